"""theodolite."""
