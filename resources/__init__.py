"""Bundled data: sample readings (``samples/``)."""
