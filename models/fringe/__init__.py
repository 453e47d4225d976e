"""fringe."""
