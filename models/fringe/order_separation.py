"""How well the sampled phases tell harmonic orders apart: the separation of two orders'
columns of the fit's design, decided from the design itself, not from exact repetition.

At N equal steps a period, order k and order N − k (or k + N) take the same values at every
sample: their columns sin kθ, cos kθ span the same plane, and the fit cannot tell them apart.
A θ column that carries its reference's noise (a jitter of hundredths of a degree about the N
steps) makes every phase distinct and the design of full rank, but the two orders then differ
only by what the jitter makes, about (k + j)·δ: the least squares separate them through the
noise of θ alone and print both amplitudes as determined at many times their size (an audit:
N = 8, orders 1, 3, 5, 0.05° of jitter: A3 and A5 at 6–35 times their true size, and nothing
said). The errors of θ are not in the fit's model, so the covariance cannot show it.

The separation of orders a and b is the least singular value of their columns over the
samples, each column scaled by the size it has over evenly spread phases (√(n/2), √n for the
offset): 1 when the orders are orthogonal (whole periods, or many random phases), 0 when they
alias exactly, about (a + b)·δ/√2 when they alias at N steps jittered by δ. Its inverse square
is the factor by which the pair's dependence inflates the variance of a fitted parameter. Two
orders are told apart when their separation is at least :data:`SEPARATION_MIN` and at least
what a phase noise of the stated reference's u could make (:data:`NOISE_MARGIN` times
(a + b)·u/√2).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

__all__ = ["NOISE_MARGIN", "SEPARATION_MIN", "PairSeparation", "least_separation",
           "nearest_grid", "order_gram", "pair_separation", "pair_separations",
           "required_separation", "separated_up_to", "variance_inflation"]

TWO_PI = 2.0 * math.pi

#: the least separation of two orders' columns: below it the pair's dependence inflates a
#: fitted parameter's variance more than 100-fold, and the fit is near-singular
SEPARATION_MIN = 0.1
#: a separation must stand this many times above what the phase reference's noise makes
NOISE_MARGIN = 3.0
#: the highest separation the noise rule asks for (a noisy reference does not make orders
#: that are orthogonal at the phases inseparable: their separation is ~1 whatever the noise)
NOISE_REQUIRED_MAX = 0.5
#: samples a block when the design's products are summed
_BLOCK = 65536


def _moments(theta: np.ndarray, weights: np.ndarray | None, highest: int
             ) -> tuple[np.ndarray, float]:
    """(Σ w·e^{imθ} for m = 0 … ``highest``, Σ w): the powers of e^{iθ} by repeated
    products, a block of samples at a time (one complex exponential a sample, not one sine
    and cosine a column: a million samples and 31 orders in a fraction of a second)."""
    moments = np.zeros(highest + 1, dtype=complex)
    total = 0.0
    for start in range(0, theta.size, _BLOCK):
        z = np.exp(1j * theta[start:start + _BLOCK])
        w = (np.ones(z.size) if weights is None
             else np.asarray(weights[start:start + _BLOCK], dtype=float))
        total += float(np.sum(w))
        power = w.astype(complex)
        moments[0] += power.sum()
        for m in range(1, highest + 1):
            power *= z
            moments[m] += power.sum()
    return moments, total


def order_gram(theta_rad: np.ndarray, orders: tuple[int, ...],
               weights: np.ndarray | None = None) -> np.ndarray:
    """XᵀX / n of the design's columns 1, sin kθ, cos kθ (k in ``orders``, order 0 the
    offset alone) over the samples, each column scaled to unit size over evenly spread
    phases (√2 sin kθ, √2 cos kθ): the identity for evenly spread phases. ``weights``:
    samples at each phase, when ``theta_rad`` are distinct phases. From the circular
    moments M(m) = Σ e^{imθ}: 2 cos aθ cos bθ = cos (a − b)θ + cos (a + b)θ and its
    kin."""
    theta = np.asarray(theta_rad, dtype=float)
    moments, total = _moments(theta, weights, 2 * max(orders, default=0))
    moments = moments / max(total, 1.0)

    # the products 2 cos aθ cos bθ = cos (a − b)θ + cos (a + b)θ and their kin, every pair of
    # columns at once: M(−m) is M(m)'s conjugate (the same sums and differences of the same
    # moments as term by term, bit for bit; ~0.5 ms a fringe analysis's 33 columns in Python)
    kinds, of_order = [], []  # 0: the offset, 1: sin kθ, 2: cos kθ
    for k in orders:
        kinds += [0] if k == 0 else [1, 2]
        of_order += [0] if k == 0 else [k, k]
    kind, order = np.array(kinds), np.array(of_order)
    top = moments.size - 1
    signed = np.concatenate([np.conj(moments[:0:-1]), moments])  # M(m) at m + top
    diff = signed[order[:, None] - order[None, :] + top]
    both = signed[order[:, None] + order[None, :] + top]
    single = signed[order + top]
    f, g = kind[:, None], kind[None, :]
    gram = np.select(
        [(f == 0) & (g == 0), f == 0, g == 0,
         (f == 2) & (g == 2), (f == 1) & (g == 1), f == 1],
        [np.ones_like(diff.real),
         np.where(g == 1, math.sqrt(2.0) * single.imag[None, :],
                  math.sqrt(2.0) * single.real[None, :]),
         np.where(f == 1, math.sqrt(2.0) * single.imag[:, None],
                  math.sqrt(2.0) * single.real[:, None]),
         diff.real + both.real, diff.real - both.real, both.imag + diff.imag],
        both.imag - diff.imag)
    # the upper triangle mirrored (each product as the pair (i ≤ j) takes it)
    upper = np.triu(np.ones(gram.shape, dtype=bool))
    gram = np.where(upper, gram, gram.T)
    return gram


def _slices(orders: tuple[int, ...]) -> dict[int, slice]:
    at, out = 0, {}
    for k in orders:
        width = 1 if k == 0 else 2
        out[k] = slice(at, at + width)
        at += width
    return out


@dataclass(frozen=True)
class PairSeparation:
    """The separation of orders ``a`` and ``b`` (``a == b``: of one order's sine and cosine)."""

    a: int
    b: int
    separation: float


def pair_separation(gram: np.ndarray, orders: tuple[int, ...], a: int, b: int) -> float:
    """The least singular value of the columns of orders ``a`` and ``b`` (of order ``a``
    alone when ``a == b``) from :func:`order_gram` over ``orders``."""
    return pair_separations(gram, orders, [(a, b)])[0]


def pair_separations(gram: np.ndarray, orders: tuple[int, ...],
                     pairs: list[tuple[int, int]]) -> list[float]:
    """:func:`pair_separation` of each of ``pairs`` (a, b), in their order: the blocks of a
    size stacked and their eigenvalues taken in one call (LAPACK takes each block as it
    would alone: the same values bit for bit; a fringe analysis takes ~160 pairs, each
    alone ~90 µs of Python around a 4×4 block)."""
    where = _slices(orders)
    out = [0.0] * len(pairs)
    by_size: dict[int, tuple[list[int], list[list[int]]]] = {}
    for n, (a, b) in enumerate(pairs):
        index = list(range(where[a].start, where[a].stop))
        if a != b:
            index += range(where[b].start, where[b].stop)
        at, indices = by_size.setdefault(len(index), ([], []))
        at.append(n)
        indices.append(index)
    for at, indices in by_size.values():
        rows = np.array(indices)
        # the same rows and columns as gram[np.ix_(index, index)] for each pair
        blocks = gram[rows[:, :, None], rows[:, None, :]]
        values = np.linalg.eigvalsh(0.5 * (blocks + np.swapaxes(blocks, 1, 2)))
        for n, least in zip(at, values[:, 0].tolist(), strict=True):
            out[n] = math.sqrt(max(least, 0.0))
    return out


def least_separation(gram: np.ndarray, orders: tuple[int, ...]) -> list[PairSeparation]:
    """Every single order (k ≥ 1: its sine against its cosine) and every pair of
    ``orders`` with its separation, the least first."""
    pairs = [(k, k) for k in orders if k]
    for i, a in enumerate(orders):
        pairs += [(a, b) for b in orders[i + 1:]]
    return sorted((PairSeparation(a, b, separation) for (a, b), separation
                   in zip(pairs, pair_separations(gram, orders, pairs), strict=True)),
                  key=lambda p: p.separation)


def variance_inflation(gram: np.ndarray) -> float:
    """The largest factor by which the design inflates a fitted parameter's variance
    against evenly spread phases (the diagonal of the scaled (XᵀX/n)⁻¹, 1 there; not
    normalised by the design's own diagonal, which hides a column that is small at every
    sample, order N/2's sine); ∞ when singular."""
    try:
        inverse = np.linalg.inv(gram)
    except np.linalg.LinAlgError:
        return math.inf
    worst = float(np.max(np.diag(inverse)))
    return worst if math.isfinite(worst) and worst > 0 else math.inf


def required_separation(a: int, b: int, phase_u_rad: float) -> float:
    """The least separation orders ``a`` and ``b`` need to be told apart by the design and
    not by the noise of the phases (standard uncertainty ``phase_u_rad`` each)."""
    noise = NOISE_MARGIN * (a + b) * phase_u_rad / math.sqrt(2.0)
    return max(SEPARATION_MIN, min(NOISE_REQUIRED_MAX, noise))


def nearest_grid(theta_rad: np.ndarray, a: int, b: int, largest: int = 1_000_000
                 ) -> tuple[int, float] | None:
    """(N, rms distance of the phases from the nearest of N equal steps, rad) for the
    fewest equal steps a period at which orders ``a`` and ``b`` alias (a ≡ ±b mod N) and
    about which the phases cluster (their N-th circular moment above 0.9, a spread of
    N·δ ≲ 0.46 rad); None when no such N."""
    theta = np.asarray(theta_rad, dtype=float)
    candidates = set()
    for m in (a + b, abs(a - b)):
        for n in range(2, min(m, largest) + 1):
            if m % n == 0:
                candidates.add(n)
    for n in sorted(candidates):
        moment = abs(complex(np.mean(np.exp(1j * n * theta))))
        if moment > 0.9:
            return n, math.sqrt(-2.0 * math.log(moment)) / n
    return None


def separated_up_to(theta_rad: np.ndarray, highest: int, phase_u_rad: float = 0.0,
                    weights: np.ndarray | None = None) -> int:
    """The highest order h ≤ ``highest`` such that the offset and every order 1 … h are told
    apart at the phases ``theta_rad`` (each single order and pair at least its
    :func:`required_separation`, the design's :func:`variance_inflation` at most
    1/SEPARATION_MIN²); 0 when not even order 1 is. ``weights``: samples at each phase,
    when ``theta_rad`` are distinct phases.

    Up to :data:`KEPT_PHASES` phases, the answer is kept for the phases, weights and u last
    asked about (:func:`_kept_separated_up_to`): N equal steps are the same N phases in every
    record of a design, and their answer, worked out again, took a fifth of a record's
    analysis (the same answer: it is made from those figures alone)."""
    theta = np.asarray(theta_rad, dtype=float)
    w = None if weights is None else np.asarray(weights, dtype=float)
    if theta.size > KEPT_PHASES or (w is not None and w.size > KEPT_PHASES):
        return _separated_up_to(theta, highest, phase_u_rad, w)
    return _kept_separated_up_to(theta.tobytes(), theta.shape, highest, phase_u_rad,
                                 None if w is None else (w.tobytes(), w.shape))


#: the most phases whose :func:`separated_up_to` is kept (32 kB of key)
KEPT_PHASES = 4096


@functools.lru_cache(maxsize=64)
def _kept_separated_up_to(theta: bytes, shape: tuple[int, ...], highest: int,
                          phase_u_rad: float, weights: tuple[bytes, tuple[int, ...]] | None
                          ) -> int:
    """:func:`_separated_up_to` of the phases (and weights) given as their bytes."""
    return _separated_up_to(
        np.frombuffer(theta).reshape(shape), highest, phase_u_rad,
        None if weights is None else np.frombuffer(weights[0]).reshape(weights[1]))


def _separated_up_to(theta_rad: np.ndarray, highest: int, phase_u_rad: float,
                     weights: np.ndarray | None) -> int:
    """:func:`separated_up_to`, worked out."""
    orders = tuple(range(highest + 1))
    gram = order_gram(theta_rad, orders, weights)
    for top in range(highest, 0, -1):
        sub = gram[:1 + 2 * top, :1 + 2 * top]
        every = orders[:top + 1]
        if variance_inflation(sub) > 1.0 / SEPARATION_MIN ** 2:
            continue
        pairs = [(a, b) for i, a in enumerate(every) for b in every[i:] if a or b]
        if all(separation >= required_separation(a, b, phase_u_rad) for (a, b), separation
               in zip(pairs, pair_separations(sub, every, pairs), strict=True)):
            return top
    return 0
