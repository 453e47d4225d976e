"""The harmonic basis of a long fringe record, a block of samples at a time, from each
sample's phasor (sin θ, cos θ) rather than from θ.

A fit of ``A0 + Σ (s_k sin kθ + c_k cos kθ)`` needs the rows 1, sin kθ, cos kθ of
every sample. On a million samples three things cost more than the arithmetic:

* ``np.sin`` and ``np.cos`` of float64 (measured: BENCHMARKS.md, Notes). The orders
  come from the phasor by the Chebyshev recurrence
  sin (k+1)θ = 2 cos θ · sin kθ − sin (k−1)θ, and a phase that moves by δ moves its
  phasor by a rotation whose sin δ and cos δ come from their Taylor series, as many
  terms as the largest |δ| of the block needs for double precision. The
  phase of a record without a phase reference starts as atan2 of the corrected
  signals, so its phasor is those signals over their norm: no sine is ever taken.
  The phasor is also the exact one: θ of a long record is unwrapped to ~1e5 rad,
  where a float64 holds the phase only to ~1e-11 rad.
* Arrays of the record's size that do not fit in the cache: each step streams them
  from memory. A block of :data:`BLOCK` samples keeps its rows in the cache while they
  are used.
* The normal equations of a long, narrow design: XᵀX of 7 × n by n × 7 in one BLAS
  call ran at a third of the speed of the same sums a block of 8192 samples at a time.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

__all__ = ["BLOCK", "BasisBlocks", "blocks", "phasor_of"]

#: samples a block: few enough for its rows and scratch to stay in the cache, enough for few calls
BLOCK = 16384
#: samples a product of the normal sums (OpenBLAS runs a 7 × m by m × 9 product at a third
#: of its speed from m = 16384 on)
_PRODUCT = 8192

_SIN = [(-1) ** j / math.factorial(2 * j + 1) for j in range(12)]
_COS = [(-1) ** j / math.factorial(2 * j) for j in range(12)]
#: the largest |δ| rotated by the series; a block with a larger step takes np.sin, np.cos
_SERIES_LIMIT = 0.5


def _series_terms(largest: float) -> int | None:
    """How many terms of the series of sin δ and of cos δ leave out less than 1e-17 for
    |δ| ≤ ``largest`` (the first term left out of cos δ, the larger); None beyond
    :data:`_SERIES_LIMIT`."""
    if not largest <= _SERIES_LIMIT:
        return None
    terms = 1
    while largest ** (2 * terms) / math.factorial(2 * terms) > 1e-17:
        terms += 1
    return terms


def blocks(size: int) -> Iterator[tuple[int, int]]:
    """(start, stop) of each block of a record of ``size`` samples."""
    for start in range(0, size, BLOCK):
        yield start, min(size, start + BLOCK)


def phasor_of(theta_rad) -> tuple[np.ndarray, np.ndarray]:
    """(sin θ, cos θ) of a phase given as angles."""
    theta = np.asarray(theta_rad, dtype=float)
    return np.sin(theta), np.cos(theta)


class BasisBlocks:
    """Buffers for one block's rows 1, sin kθ, cos kθ (k in ``orders``, ascending) with
    ``channels`` rows of signals below them, and the scratch of a rotation, made once for
    a whole record."""

    def __init__(self, orders: tuple[int, ...], channels: int = 2, size: int = BLOCK) -> None:
        if not orders or list(orders) != sorted(set(orders)) or orders[0] < 1:
            raise ValueError(f"orders must ascend from 1: {orders}")
        self.orders = tuple(orders)
        self.n_par = 1 + 2 * len(orders)
        self._stacked = np.empty((self.n_par + channels, size))
        self._stacked[0] = 1.0
        self._chain = np.empty((6, size))  # the orders between rows: two live, two made
        self._two_cos = np.empty(size)
        self._rotation = np.empty((4, size))
        self._plan = self._recurrence_plan()

    def _recurrence_plan(self) -> list[tuple[int, int, int, int, tuple[int, int] | None]]:
        """The recurrence as (sin out, cos out, sin k, cos k, (sin k−1, cos k−1) or None
        where k−1 is order 0) buffer numbers, one an order from 2: rows are 0…n_par−1, the
        chain n_par…n_par+5, the phasor given n_par+6 (sin) and n_par+7 (cos); an order is
        written in its rows when it has them, otherwise in a chain buffer that neither order
        k nor k − 1 holds."""
        place = {k: (1 + 2 * i, 2 + 2 * i) for i, k in enumerate(self.orders)}
        phasor = (self.n_par + 6, self.n_par + 7)
        plan: list[tuple[int, int, int, int, tuple[int, int] | None]] = []
        before: tuple[int, int] | None = None
        now = phasor
        for k in range(2, max(self.orders) + 1):
            if k in place:
                out = place[k]
            else:
                free = [self.n_par + j for j in range(6) if self.n_par + j not in (*now, *(before or ()))]
                out = (free[0], free[1])
            plan.append((*out, *now, before))
            before, now = now, out
        return plan

    def rows(self, sin: np.ndarray, cos: np.ndarray, out: np.ndarray | None = None
             ) -> np.ndarray:
        """Xᵀ of the samples whose phasor is (``sin``, ``cos``): (1 + 2·orders, samples),
        written in ``out`` if given, else in the buffer (a view, valid until the next
        call; at most a block of samples)."""
        m = sin.size
        n_par = self.n_par
        if out is None:
            rows = self._stacked[:n_par, :m]
        else:
            rows = out
            rows[0] = 1.0
        buffers = [*rows, *(part[:m] for part in self._chain), sin, cos]
        two_cos = self._two_cos[:m]
        np.multiply(cos, 2.0, out=two_cos)
        if self.orders[0] == 1:
            buffers[1][...] = sin
            buffers[2][...] = cos
        for s_out, c_out, s_now, c_now, before in self._plan:
            np.multiply(two_cos, buffers[s_now], out=buffers[s_out])
            np.multiply(two_cos, buffers[c_now], out=buffers[c_out])
            if before is None:  # order 2: sin 0 = 0, cos 0 = 1
                buffers[c_out] -= 1.0
            else:
                s_before, c_before = before
                buffers[s_out] -= buffers[s_before]
                buffers[c_out] -= buffers[c_before]
        return rows

    def normal_sums(self, sin: np.ndarray, cos: np.ndarray, channels: np.ndarray
                    ) -> tuple[np.ndarray, np.ndarray]:
        """The block's XᵀX and Xᵀy of each of ``channels`` (a row each) at the phasor
        (``sin``, ``cos``): one product of the rows and the rows with the channels."""
        m = sin.size
        rows = self.rows(sin, cos)
        stacked = self._stacked[:self.n_par + channels.shape[0], :m]
        stacked[self.n_par:] = channels
        sums = rows[:, :_PRODUCT] @ stacked[:, :_PRODUCT].T
        for start in range(_PRODUCT, m, _PRODUCT):
            sums += rows[:, start:start + _PRODUCT] @ stacked[:, start:start + _PRODUCT].T
        return sums[:, :self.n_par], sums[:, self.n_par:]

    def rotate(self, sin: np.ndarray, cos: np.ndarray, delta: np.ndarray) -> None:
        """The phasor (``sin``, ``cos``) of θ made that of θ − δ, in place."""
        m = sin.size
        square, sin_d, cos_d, spare = (part[:m] for part in self._rotation)
        terms = _series_terms(max(float(np.max(delta)), -float(np.min(delta))))
        if terms is None:
            np.sin(delta, out=sin_d)
            np.cos(delta, out=cos_d)
        else:  # Horner in δ²
            np.multiply(delta, delta, out=square)
            sin_d.fill(_SIN[terms - 1])
            cos_d.fill(_COS[terms - 1])
            for j in range(terms - 2, -1, -1):
                sin_d *= square
                sin_d += _SIN[j]
                cos_d *= square
                cos_d += _COS[j]
            sin_d *= delta
        # sin(θ − δ) = sin θ cos δ − cos θ sin δ;  cos(θ − δ) = cos θ cos δ + sin θ sin δ
        np.multiply(cos, sin_d, out=spare)
        np.multiply(sin, sin_d, out=sin_d)
        sin *= cos_d
        sin -= spare
        cos *= cos_d
        cos += sin_d
