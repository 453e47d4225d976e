"""AngleBench numerics: pure numpy/scipy, no Qt (a test checks this)."""

__version__ = "0.8.30"
