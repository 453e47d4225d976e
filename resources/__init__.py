"""Bundled data: sample readings (``samples/``) and the certificate fonts (``fonts/``)."""
