"""scipy.optimize.least_squares, imported on first use.

Importing scipy.optimize costs about 0.3 s; the window imports every model at
start-up but fits nothing until readings arrive, so it should not pay that.
"""

from __future__ import annotations

__all__ = ["least_squares"]


def least_squares(*args, **kwargs):
    """Same arguments and result as :func:`scipy.optimize.least_squares`."""
    from scipy.optimize import least_squares as _least_squares

    return _least_squares(*args, **kwargs)
