"""Fringe signal analysis: harmonic identification and interpolation-error compensation.

Seed 003 (Gao et al., Acta Optica Sinica 33(7) 0712001, 2013). Each channel of
the grating signal is ``u(θ) = A0 + Σ_k A_k sin(kθ + c_k)`` (k = 1, 3, 5 by
default), θ the electrical (fringe) phase. The model is linear in
``(1, sin kθ, cos kθ)``: an exact least-squares solve identifies it, with no
start and no iterations (the seed used particle-swarm optimisation, kept here
as :func:`fit_channel_pso` for comparison).

Interpolation error (eq 5): ``Δθ = atan2(u_sin, u_cos) − θ``, mean removed,
shown in arcsec of shaft angle: ``Δθ/2π · 1296000"/L`` for L lines per
revolution. Compensation (eq 6): a look-up table of the modelled error over
the *measured* phase, subtracted from the measured phase.
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from models.cancellation import checkpoint
from models.fringe.harmonic_basis import BLOCK, BasisBlocks, blocks, phasor_of
from models.messages import QT_TR_NOOP, message

#: the budget's name of the fitted model's error (the correction table's)
MODEL_INPUT = QT_TR_NOOP("Fitted model (correction table)")

__all__ = [
    "ChannelFit",
    "CorrectionTable",
    "PsoFit",
    "build_correction_table",
    "channel_cost",
    "fit_channel",
    "fit_channels",
    "fit_channel_pso",
    "fit_design",
    "fit_periods",
    "fit_periods_along",
    "refine_phase",
    "interpolation_error_arcsec",
    "interpolation_error_rad",
    "model_signal",
    "model_slope",
    "model_signal_std",
    "period_arcsec",
    "phase_error_about_its_mean",
    "phase_of_samples",
]

TWO_PI = 2.0 * math.pi


def period_arcsec(lines_per_rev: int) -> float:
    """Shaft angle of one grating period: 1296000"/L (79.1" for L = 16384)."""
    return 1_296_000.0 / lines_per_rev


def phase_of_samples(count: int, samples_per_period: int) -> np.ndarray:
    """Electrical phase (rad) of equally spaced samples, N per period, starting at 0."""
    return np.arange(count) * (TWO_PI / samples_per_period)


def _wrap(angle_rad):
    """Angles into [−π, π) (rad). By the nearest whole turn, not np.remainder: a quarter
    of the time on a million samples."""
    angle = np.asarray(angle_rad, dtype=float)
    turns = np.rint(angle * (1.0 / TWO_PI))
    turns *= TWO_PI
    wrapped = angle - turns
    wrapped[wrapped >= math.pi] -= TWO_PI
    return wrapped


@dataclass
class ChannelFit:
    """One channel's model ``A0 + Σ A_k sin(kθ + c_k)`` in canonical form.

    Amplitudes ≥ 0 (V), phases in (−π, π] (rad); ``u_*`` are standard
    uncertainties from the least-squares covariance.
    """

    orders: tuple[int, ...]
    offset: float
    amplitude: dict[int, float]
    phase: dict[int, float]
    u_offset: float = 0.0
    u_amplitude: dict[int, float] = field(default_factory=dict)
    u_phase: dict[int, float] = field(default_factory=dict)
    r_squared: float = float("nan")
    residual_rms: float = float("nan")
    cost: float = float("nan")
    #: each sample's residual (V) when the fit was made from samples (the plots read it)
    residuals: np.ndarray | None = field(default=None, repr=False, compare=False)

    @classmethod
    def from_parameters(cls, offset: float, terms: dict[int, tuple[float, float]]) -> ChannelFit:
        """Build from (amplitude, phase) pairs that may be negative or unwrapped."""
        amplitude, phase = {}, {}
        for k, (a, c) in terms.items():
            if a < 0:
                a, c = -a, c + math.pi
            c = math.remainder(float(c), 2.0 * math.pi)  # into [−π, π]
            if c == -math.pi:
                c = math.pi
            amplitude[k], phase[k] = float(a), c
        return cls(tuple(terms), float(offset), amplitude, phase)

    def as_dict(self) -> dict[str, float]:
        """``{"A0": …, "A1": …, "c1": …, "A3": …}`` as in the seed's Table 1."""
        out = {"A0": self.offset}
        for k in self.orders:
            out[f"A{k}"] = self.amplitude[k]
            out[f"c{k}"] = self.phase[k]
        return out


def model_signal(theta_rad, fit: ChannelFit) -> np.ndarray:
    theta = np.asarray(theta_rad, dtype=float)
    u = np.full_like(theta, fit.offset)
    for k in fit.orders:
        u += fit.amplitude[k] * np.sin(k * theta + fit.phase[k])
    return u


def model_slope(theta_rad, fit: ChannelFit) -> np.ndarray:
    """dU/dθ of the model (V/rad)."""
    theta = np.asarray(theta_rad, dtype=float)
    du = np.zeros_like(theta)
    for k in fit.orders:
        du += k * fit.amplitude[k] * np.cos(k * theta + fit.phase[k])
    return du


def channel_cost(theta_rad, u, fit: ChannelFit) -> float:
    """The seed's cost (11): sum of squared signal residuals (V²)."""
    r = np.asarray(u, dtype=float) - model_signal(theta_rad, fit)
    return float(r @ r)


def _design(theta: np.ndarray, orders: tuple[int, ...]) -> np.ndarray:
    """Columns 1, sin kθ, cos kθ for k in ``orders``. Ascending orders come from powers
    of e^{iθ} (one complex exponential for all orders instead of two per order)."""
    x = np.empty((theta.size, 1 + 2 * len(orders)))
    x[:, 0] = 1.0
    z = np.exp(1j * theta)
    zk: complex | np.ndarray = 1.0
    power = 0
    for i, k in enumerate(orders):
        if power <= k <= power + 8:
            while power < k:
                zk = zk * z
                power += 1
            column = zk
        else:
            column = np.exp(1j * k * theta)
        x[:, 1 + 2 * i] = column.imag
        x[:, 2 + 2 * i] = column.real
    return x


def fit_design(theta_rad, orders: tuple[int, ...]) -> np.ndarray:
    """The fits' design at ``theta_rad``: columns 1, sin kθ, cos kθ for k in ``orders``."""
    return _design(np.asarray(theta_rad, dtype=float), orders)


def model_signal_std(theta_fit_rad, residual_std: float, orders: tuple[int, ...],
                     theta_rad) -> np.ndarray:
    """Standard uncertainty (V) of a fitted channel's model at ``theta_rad``.

    Linear least squares: u²(θ) = σ² x(θ)ᵀ (XᵀX)⁻¹ x(θ), with X the design of
    the fit's samples ``theta_fit_rad`` and σ the residual standard deviation.
    """
    _, inv = _solver(np.asarray(theta_fit_rad, dtype=float), orders)
    x = _design(np.asarray(theta_rad, dtype=float), orders)
    return residual_std * np.sqrt(np.clip(np.einsum("ij,jk,ik->i", x, inv, x), 0.0, None))


def model_signal_modes(theta_fit_rad, orders: tuple[int, ...], theta_rad) -> np.ndarray:
    """(len(theta_rad), p) changes of a fitted channel's model at ``theta_rad`` per unit
    residual standard deviation, one column per independent direction of its parameters'
    covariance (the eigenvectors of (XᵀX)⁻¹ scaled by the root of their eigenvalue): a
    draw ξ ~ N(0, I) of p values gives one model the data allow, σ·(modes @ ξ); the row
    norms are :func:`model_signal_std` / σ."""
    _, inv = _solver(np.asarray(theta_fit_rad, dtype=float), orders)
    values, vectors = np.linalg.eigh(0.5 * (inv + inv.T))
    x = _design(np.asarray(theta_rad, dtype=float), orders)
    return x @ (vectors * np.sqrt(np.clip(values, 0.0, None)))


def fit_channel(theta_rad, u, orders: tuple[int, ...] = (1, 3, 5)) -> ChannelFit:
    """Exact least squares for ``A0 + Σ A_k sin(kθ + c_k)``; global, no start.

    Raises ValueError when there are fewer samples than parameters.
    """
    return fit_channels(theta_rad, [u], orders)[0]


def fit_channels(theta_rad, channels, orders: tuple[int, ...] = (1, 3, 5)) -> list[ChannelFit]:
    """:func:`fit_channel` for several channels sampled at the same phases: one design
    matrix and one factorisation of the normal equations serve them all.

    The normal equations are well conditioned here (sines and cosines of distinct
    orders are near-orthogonal over whole periods); a rank-deficient design
    (e.g. too few distinct phases) falls back to the pseudo-inverse.
    """
    theta = np.asarray(theta_rad, dtype=float)
    n_par = 1 + 2 * len(orders)
    if theta.size < n_par + 1:
        raise ValueError(message(
            QT_TR_NOOP("{size} samples; at least {value} are needed for orders {join}"),
            size=theta.size, value=n_par + 1, join=', '.join(map(str, orders))))
    if theta.size <= _CACHED_DESIGN_MAX:  # a period's phases recur: reuse its factorisation
        x, inv = _small_solver(theta.tobytes(), orders)
    else:
        x, inv = _solver(theta, orders)
    return _fits(x, inv, np.asarray(channels, dtype=float).T, orders)


def _fits(x: np.ndarray, inv: np.ndarray, ys: np.ndarray, orders: tuple[int, ...]
          ) -> list[ChannelFit]:
    """The channels ``ys`` (samples, channels) fitted on the design ``x`` with (XᵀX)⁻¹."""
    coefs = inv @ (x.T @ ys)  # (n_par, channels)
    resid = ys - x @ coefs
    dof = max(x.shape[0] - x.shape[1], 1)
    return [_channel_fit(coefs[:, j], resid[:, j], ys[:, j], inv, dof, orders)
            for j in range(ys.shape[1])]


def _inverse(gram: np.ndarray) -> np.ndarray:
    """(XᵀX)⁻¹, the pseudo-inverse when X is rank-deficient."""
    n_par = gram.shape[0]
    try:
        inv = np.linalg.inv(gram)
        check = gram @ inv
        check.flat[:: n_par + 1] -= 1.0
        if not np.abs(check).max() < 1e-6:  # near-singular: a poor inverse
            raise np.linalg.LinAlgError
    except np.linalg.LinAlgError:
        inv = np.linalg.pinv(gram)
    return inv


#: a variance inflation beyond this is a singular design (the rounding of its inverse)
SINGULAR_INFLATION = 1e10


def _parameter_names(orders: tuple[int, ...]) -> list[str]:
    return ["A0", *(f"{part} {k}θ" for k in orders for part in ("sin", "cos"))]


def _determined_inverse(gram: np.ndarray, orders: tuple[int, ...]) -> np.ndarray:
    """(XᵀX)⁻¹ of the fit at an estimated phase, or a refusal naming what the phases cannot
    tell apart: a design that inflates a fitted parameter's variance more than
    1/SEPARATION_MIN² against evenly spread phases (the rule a θ column's phases are held
    to, analysis.check_orders_not_aliased) is not solved (a pseudo-inverse printed a
    minimum-norm answer as the signals' harmonics, or a refusal for a reason not theirs).
    ``gram``: XᵀX over the samples, columns 1, sin kθ, cos kθ for k in ``orders``."""
    from models.fringe.order_separation import SEPARATION_MIN, least_separation

    count = float(gram[0, 0])  # the samples: the offset's column is 1
    scale = np.array([1.0] + [math.sqrt(2.0)] * (gram.shape[0] - 1))
    scaled = gram * np.outer(scale, scale) / max(count, 1.0)
    most = 1.0 / SEPARATION_MIN ** 2
    try:
        inflation = float(np.max(np.diag(np.linalg.inv(scaled))))
    except np.linalg.LinAlgError:
        inflation = math.inf
    if math.isfinite(inflation) and 0.0 < inflation <= most:
        return np.linalg.inv(gram)
    every = (0, *orders)
    # one order's sine and cosine first (order N/2: its sine is nothing but noise), as the
    # θ column's check names them; then the least separated pair
    separations = least_separation(scaled, every)
    singles = [p for p in separations if p.a == p.b and p.separation < SEPARATION_MIN]
    worst = singles[0] if singles else separations[0]
    what: Any
    if worst.separation < SEPARATION_MIN:
        what = (message(QT_TR_NOOP("the sine and cosine of order {k}"), k=worst.a)
                if worst.a == worst.b else
                message(QT_TR_NOOP("the offset and order {k}"), k=worst.b) if worst.a == 0 else
                message(QT_TR_NOOP("orders {a} and {b}"), a=worst.a, b=worst.b))
    else:  # no pair alone: the parameters of the design's weakest direction
        _, vectors = np.linalg.eigh(0.5 * (scaled + scaled.T))
        weakest = np.abs(vectors[:, 0])
        names = _parameter_names(orders)
        what = ", ".join(names[i] for i in np.flatnonzero(weakest >= 0.3 * weakest.max()))
    if not math.isfinite(inflation) or not 0.0 < inflation <= SINGULAR_INFLATION:
        raise ValueError(message(QT_TR_NOOP(
            "the harmonics asked for are not determined at the phase estimated from the "
            "signals: at the estimated phases {what} take the same values, so the data cannot "
            "tell them apart ({params} parameters a channel); lower the highest harmonic, or "
            "give the phase (a θ column) or the samples per period"),
            what=what, params=gram.shape[0]))
    raise ValueError(message(QT_TR_NOOP(
        "the harmonics asked for are determined only poorly at the phase estimated from the "
        "signals: at the estimated phases the data can hardly tell {what} apart (the design "
        "inflates a fitted parameter's variance {inflation}-fold against evenly spread "
        "phases; at most {most} is accepted); lower the highest harmonic, or give the phase "
        "(a θ column) or the samples per period"),
        what=what, inflation=f"{inflation:.3g}", most=f"{most:.0f}"))


def refine_phase(theta_rad, u_sin, u_cos, orders: tuple[int, ...] = (1, 3, 5),
                 iterations: int = 3, phasor: tuple[np.ndarray, np.ndarray] | None = None
                 ) -> tuple[np.ndarray, list[ChannelFit], np.ndarray]:
    """An estimated phase refined against the channels' own harmonics: both channels are
    fitted at the phase, then each sample's phase moves to the nearest point of the fitted
    curve (one Gauss–Newton step), repeated ``iterations`` times; then the final fit.

    ``phasor``: (sin θ, cos θ) of the phase given, if at hand (the corrected signals over
    their norm, for a phase that is their atan2). Returns (phase, [sin fit, cos fit], the
    rows of the design at that phase with the two channels below them: what
    :func:`fit_periods_along` needs). A pass is one sweep over the record a block at a time
    (:mod:`models.fringe.harmonic_basis`): each block steps its phase with the last fit
    (the values and slopes from the block's rows: dU/dθ has the coefficients of U mapped
    by the derivative), rotates its phasor, and adds its rows at the new phase to the
    normal equations of the next fit.
    """
    theta = np.array(theta_rad, dtype=float)  # refined in place: a copy
    ys = np.vstack([np.asarray(u_sin, dtype=float), np.asarray(u_cos, dtype=float)])
    n_par = 1 + 2 * len(orders)
    if theta.size < n_par + 1:
        raise ValueError(message(
            QT_TR_NOOP("{size} samples; at least {value} are needed for orders {join}"),
            size=theta.size, value=n_par + 1, join=', '.join(map(str, orders))))
    sin, cos = phasor_of(theta) if phasor is None else (
        np.array(phasor[0], dtype=float), np.array(phasor[1], dtype=float))
    derivative = np.zeros((n_par, n_par))
    for i, k in enumerate(orders):  # d/dθ (s sin kθ + c cos kθ) = −k c sin kθ + k s cos kθ
        derivative[1 + 2 * i, 2 + 2 * i] = -k
        derivative[2 + 2 * i, 1 + 2 * i] = k
    basis = BasisBlocks(orders)
    curve = np.empty((4, BLOCK))  # U_sin, U_cos and their slopes at a block's samples
    curve_of = None  # (4, n_par): the last fit's U_sin, U_cos and slopes by basis row
    for _ in range(iterations + 1):
        checkpoint()
        gram, rhs = np.zeros((n_par, n_par)), np.zeros((n_par, 2))
        for start, stop in blocks(theta.size):
            s, c, y = sin[start:stop], cos[start:stop], ys[:, start:stop]
            if curve_of is not None:
                values = curve[:, :stop - start]
                np.matmul(curve_of, basis.rows(s, c), out=values)
                rs, rc, ds, dc = values
                rs -= y[0]
                rc -= y[1]
                rs *= ds
                rc *= dc
                rs += rc  # the residual along the curve's tangent …
                np.multiply(ds, ds, out=ds)
                np.multiply(dc, dc, out=dc)
                ds += dc
                np.maximum(ds, 1e-30, out=ds)  # … over the tangent's squared length
                np.divide(rs, ds, out=ds)
                theta[start:stop] -= ds
                basis.rotate(s, c, ds)
            block_gram, block_rhs = basis.normal_sums(s, c, y)
            gram += block_gram
            rhs += block_rhs
        gram = np.triu(gram) + np.triu(gram, 1).T  # symmetric to the bit
        inv = _determined_inverse(gram, orders)
        coefs = inv @ rhs
        curve_of = np.vstack([coefs.T, (derivative @ coefs).T])
    checkpoint()
    stacked = np.empty((n_par + 2, theta.size))  # the design's rows, the channels below
    stacked[n_par:] = ys
    resid = ys  # the channels' copy becomes their residuals
    for start, stop in blocks(theta.size):
        rows = basis.rows(sin[start:stop], cos[start:stop], out=stacked[:n_par, start:stop])
        resid[:, start:stop] -= coefs.T @ rows
    dof = max(theta.size - n_par, 1)
    fits = [_channel_fit(coefs[:, j], resid[j], stacked[n_par + j], inv, dof, orders)
            for j in range(2)]
    return theta, fits, stacked


def fit_channels_by_phase(phase_index, samples_per_period: int, channels,
                          orders: tuple[int, ...] = (1, 3, 5)) -> list[ChannelFit]:
    """:func:`fit_channels` for samples at N equal steps a period (sample i at phase
    ``phase_index[i]`` · 2π/N): the same fit from N per-phase sums. The normal equations
    are Xₙᵀ W Xₙ (Xₙ the design at the N phases, W the samples per phase) and Xₙᵀ S (S the
    per-phase sums), so a million samples cost N-sized sums and a 7×7 solve instead of a
    million-row design; the residuals are then one gather of the N model values."""
    index = np.asarray(phase_index, dtype=np.intp)
    n = int(samples_per_period)
    n_par = 1 + 2 * len(orders)
    if index.size < n_par + 1:
        raise ValueError(message(
            QT_TR_NOOP("{size} samples; at least {value} are needed for orders {join}"),
            size=index.size, value=n_par + 1, join=', '.join(map(str, orders))))
    counts = np.bincount(index, minlength=n).astype(float)
    x = _design(np.arange(n) * (TWO_PI / n), orders)
    gram = x.T @ (x * counts[:, None])
    try:
        inv = np.linalg.inv(gram)
        check = gram @ inv
        check.flat[:: n_par + 1] -= 1.0
        if not np.abs(check).max() < 1e-6:
            raise np.linalg.LinAlgError
    except np.linalg.LinAlgError:
        inv = np.linalg.pinv(gram)
    dof = max(index.size - n_par, 1)
    fits = []
    for u in channels:
        y = np.asarray(u, dtype=float)
        coef = inv @ (x.T @ np.bincount(index, weights=y, minlength=n))
        resid = y - (x @ coef)[index]
        fits.append(_channel_fit(coef, resid, y, inv, dof, orders))
    return fits


_CACHED_DESIGN_MAX = 4096


def _solver(theta: np.ndarray, orders: tuple[int, ...]) -> tuple[np.ndarray, np.ndarray]:
    """Design matrix and (XᵀX)⁻¹ (the pseudo-inverse if X is rank-deficient)."""
    x = _design(theta, orders)
    return x, _inverse(x.T @ x)


@functools.lru_cache(maxsize=16)
def _small_solver(theta_bytes: bytes, orders: tuple[int, ...]) -> tuple[np.ndarray, np.ndarray]:
    x, inv = _solver(np.frombuffer(theta_bytes, dtype=float), orders)
    x.flags.writeable = False
    inv.flags.writeable = False
    return x, inv


def _channel_fit(coef, resid, y, inv, dof: int, orders: tuple[int, ...]) -> ChannelFit:
    cost = float(resid @ resid)
    cov = inv * (cost / dof)
    terms, u_amp, u_ph = {}, {}, {}
    for i, k in enumerate(orders):
        s, c = float(coef[1 + 2 * i]), float(coef[2 + 2 * i])
        amp = math.hypot(s, c)
        terms[k] = (amp, math.atan2(c, s))
        v_ss, v_sc, v_cc = cov[1 + 2 * i, 1 + 2 * i], cov[1 + 2 * i, 2 + 2 * i], cov[2 + 2 * i,
                                                                                    2 + 2 * i]
        if amp > 0:
            # gradients of the amplitude (s, c)/A and of the phase (−c, s)/A²
            var_a = (s * s * v_ss + 2 * s * c * v_sc + c * c * v_cc) / amp**2
            var_p = (c * c * v_ss - 2 * s * c * v_sc + s * s * v_cc) / amp**4
            u_amp[k], u_ph[k] = math.sqrt(max(var_a, 0.0)), math.sqrt(max(var_p, 0.0))
        else:
            u_amp[k], u_ph[k] = math.sqrt(max(v_ss, 0.0)), math.inf
    fit = ChannelFit.from_parameters(float(coef[0]), terms)
    fit.u_offset = float(math.sqrt(max(cov[0, 0], 0.0)))
    fit.u_amplitude, fit.u_phase = u_amp, u_ph
    total = float(y.sum())
    ss_tot = float(y @ y) - total * total / y.size
    fit.cost = cost
    fit.r_squared = 1.0 - cost / ss_tot if ss_tot > 0 else float("nan")
    fit.residual_rms = math.sqrt(cost / y.size)
    fit.residuals = resid
    return fit


def fit_periods(u, samples_per_period: int, orders: tuple[int, ...] = (1, 3, 5)) -> np.ndarray:
    """Fit every whole period separately (one solve for all): array (periods, 1 + 2·len(orders))
    of ``[A0, A_k, c_k …]`` in canonical form, to show how the parameters drift."""
    y = np.asarray(u, dtype=float)
    periods = y.size // samples_per_period
    if periods == 0:
        return np.empty((0, 1 + 2 * len(orders)))
    block = y[: periods * samples_per_period].reshape(periods, samples_per_period)
    x = _design(phase_of_samples(samples_per_period, samples_per_period), orders)
    coef = np.linalg.pinv(x) @ block.T  # (n_par, periods)
    out = np.empty((periods, 1 + 2 * len(orders)))
    out[:, 0] = coef[0]
    for i in range(len(orders)):
        s, c = coef[1 + 2 * i], coef[2 + 2 * i]
        out[:, 1 + 2 * i] = np.hypot(s, c)
        out[:, 2 + 2 * i] = np.arctan2(c, s)
    return out


def interpolation_error_rad(measured_phase_rad, theta_rad) -> np.ndarray:
    """Eq (5): measured phase − θ, wrapped, mean removed (rad of electrical phase)."""
    return phase_error_about_its_mean(np.asarray(measured_phase_rad, dtype=float)
                                      - np.asarray(theta_rad, dtype=float))[0]


def phase_error_about_its_mean(delta_rad) -> tuple[np.ndarray, float]:
    """(δ − c wrapped into [−π, π), c): a phase difference about its circular mean c.

    The phase's origin is arbitrary: where the signals' phase at θ = 0 is near ±π (a record
    whose first sample is near 180°), δ wrapped on its own straddles the ±π cut, half its
    values near −π and half near +π. Wrapped about its mean it is the small error it is
    (before, its mean was taken out without wrapping again: the error spanned a whole
    period, and its table was refused as not compensating)."""
    delta = _wrap(np.asarray(delta_rad, dtype=float))
    centre = _circular_mean(delta)
    return _wrap(delta - centre), centre


def interpolation_error_arcsec(u_sin, u_cos, theta_rad, lines_per_rev: int) -> np.ndarray:
    """Eq (5): ``atan2(u_sin, u_cos) − θ``, wrapped, mean removed, in arcsec of shaft angle."""
    return (interpolation_error_rad(np.arctan2(u_sin, u_cos), theta_rad) / TWO_PI
            * period_arcsec(lines_per_rev))


def fit_periods_along(theta_rad, channels, orders: tuple[int, ...] = (1, 3, 5),
                      max_segments: int = 4000, stacked: np.ndarray | None = None
                      ) -> list[np.ndarray]:
    """:func:`fit_periods` along the actual phase, for each of ``channels``: a segment per
    period of travel (forward or back), or per block of periods when there are more than
    ``max_segments``; a segment that does not cover three quarters of a period (6 of its
    8 octants) is left out. ``stacked``: the rows of the design at ``theta_rad`` with
    the channels below them, if at hand (:func:`refine_phase` returns them).

    Each segment is a least-squares fit of its own; they are solved together from their
    normal equations (a 7×7 system a segment), a segment whose equations are near
    singular by the SVD of its samples."""
    theta = np.asarray(theta_rad, dtype=float)
    ys = np.atleast_2d(np.asarray(channels, dtype=float))  # (channels, samples)
    n_par = 1 + 2 * len(orders)
    empty = [np.empty((0, n_par)) for _ in range(ys.shape[0])]
    if theta.size < 2 * n_par:
        return empty
    travel = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(theta)))])
    periods = int(travel[-1] // TWO_PI)
    width = TWO_PI * max(1, -(-periods // max_segments))
    segment = np.floor(travel / width).astype(np.intp)
    starts = np.flatnonzero(np.diff(segment, prepend=segment[0] - 1))
    ends = np.append(starts[1:], theta.size)
    turns = theta * (1.0 / TWO_PI)
    octant = ((turns - np.floor(turns)) * 8.0).astype(np.intp)  # 0…8
    # the octants seen under each segment number (a number a jump of travel skipped is empty)
    octant += segment * 9
    seen = np.bincount(octant, minlength=(int(segment[-1]) + 1) * 9).reshape(-1, 9)
    seen = seen[segment[starts]]
    keep = np.flatnonzero((ends - starts >= 2 * n_par) & (np.count_nonzero(seen, axis=1) >= 6))
    if keep.size == 0:
        return empty
    if stacked is None:  # a segment's normal equations are then one product of its columns
        stacked = np.empty((n_par + ys.shape[0], theta.size))
        stacked[n_par:] = ys
        sin, cos = phasor_of(theta)
        basis = BasisBlocks(orders)
        for a, b in blocks(theta.size):
            basis.rows(sin[a:b], cos[a:b], out=stacked[:n_par, a:b])
    elif stacked.shape != (n_par + ys.shape[0], theta.size):
        raise ValueError(f"a design of {stacked.shape} for {ys.shape[0]} channels of "
                         f"{theta.size} samples and {n_par} parameters")
    x = stacked[:n_par].T
    sums = np.empty((keep.size, stacked.shape[0], stacked.shape[0]))
    for j, (a, b) in enumerate(zip(starts[keep].tolist(), ends[keep].tolist(), strict=True)):
        if j % 1024 == 0:
            checkpoint()
        part = stacked[:, a:b]
        np.matmul(part, part.T, out=sums[j])
    gram, rhs = sums[:, :n_par, :n_par], sums[:, :n_par, n_par:]
    coef = np.empty_like(rhs)
    scale = np.sqrt(np.einsum("sii->si", gram))  # equilibrated, the condition is the design's
    with np.errstate(divide="ignore", invalid="ignore"):
        scaled = gram / (scale[:, :, None] * scale[:, None, :])
        good = np.all(scale > 0, axis=1)
        eigen = np.linalg.eigvalsh(scaled[good])  # ascending: the condition is the ratio
        good[good] = (eigen[:, 0] > 0) & (eigen[:, -1] < 1e10 * eigen[:, 0])
    if np.any(good):
        coef[good] = np.linalg.solve(scaled[good], rhs[good] / scale[good][:, :, None]
                                     ) / scale[good][:, :, None]
    for j in np.flatnonzero(~good).tolist():  # rank-deficient: the minimum-norm solution
        a, b = int(starts[keep[j]]), int(ends[keep[j]])
        coef[j] = np.linalg.lstsq(x[a:b], ys[:, a:b].T, rcond=None)[0]
    out = []
    for c in range(ys.shape[0]):
        rows = np.empty((keep.size, n_par))
        rows[:, 0] = coef[:, 0, c]
        s_, c_ = coef[:, 1::2, c], coef[:, 2::2, c]
        rows[:, 1::2], rows[:, 2::2] = np.hypot(s_, c_), np.arctan2(c_, s_)
        out.append(rows)
    return out


def _circular_mean(angle_rad: np.ndarray) -> float:
    """The mean of wrapped angles: their arithmetic mean when they span less than π (they
    cannot straddle the ±π cut), otherwise the circular mean."""
    if angle_rad.size and float(np.ptp(angle_rad)) < math.pi:
        return float(np.mean(angle_rad))
    return float(np.angle(np.mean(np.exp(1j * angle_rad))))


#: the grid the table's checksum takes its values on: 1e-9 rad of phase, 1.6e-10 of a
#: period (far below what a table's 9 digits or a processor's float32 hold of it), and some
#: thousand times what a fit's last bits move them (the chance that a value lying at a step's
#: edge crosses it between two machines: about 1e-6 an entry)
CHECKSUM_GRID_RAD = 1e-9


@dataclass
class CorrectionTable:
    """Eq (6) as a look-up table: ``correction_rad[j]`` at measured phase ``2πj/size``.

    The compensated phase is ``φ_measured − correction(φ_measured)`` with
    periodic linear interpolation.
    """

    correction_rad: np.ndarray
    zero: str = "mean"  # "mean": the table's mean is zero; "phase0": its first entry is

    @property
    def size(self) -> int:
        return int(self.correction_rad.size)

    @property
    def sha256(self) -> str:
        """Checksum of the table: the certificate names the table the lab states it loaded
        into the encoder by it. Of its values on a grid of :data:`CHECKSUM_GRID_RAD` (as
        little-endian int64), not of their float64 bits: a fit's last bits differ between
        processors (the bundled sample's table had another checksum on another machine),
        and a checksum of them refused, on the computer that issued the certificate, the
        table exported from the same readings on the one at the bench."""
        import hashlib

        steps = np.rint(np.asarray(self.correction_rad, dtype=float) / CHECKSUM_GRID_RAD)
        data = np.ascontiguousarray(steps, dtype="<i8").tobytes()
        return hashlib.sha256(data).hexdigest()

    def correction_at(self, measured_phase_rad) -> np.ndarray:
        # the same operations as low + (table[j + 1] − low)·fraction, in two buffers (a
        # million samples' temporaries cost as much as their arithmetic)
        pos = np.asarray(measured_phase_rad, dtype=float) * (self.size / TWO_PI)
        work = pos * (1.0 / self.size)
        np.floor(work, out=work)
        work *= self.size
        pos -= work  # one turn: [0, size]
        j = pos.astype(np.intp)  # pos ≥ 0: the integer part is the floor
        np.minimum(j, self.size - 1, out=j)  # a phase a rounding below 2π
        pos -= j  # the fraction of the way to the next entry
        table = np.append(self.correction_rad, self.correction_rad[0])  # periodic
        low = table[j]
        j += 1
        np.take(table, j, out=work)
        work -= low
        work *= pos
        work += low
        return work

    def compensate(self, measured_phase_rad) -> np.ndarray:
        correction = self.correction_at(measured_phase_rad)
        return np.subtract(np.asarray(measured_phase_rad), correction, out=correction)


def build_correction_table(sin_fit: ChannelFit, cos_fit: ChannelFit,
                           size: int = 1024, zero: str = "mean") -> CorrectionTable:
    """Tabulate the modelled error over the measured phase (eq 6).

    The model is evaluated on a dense grid of true phase θ; the measured phase
    φ(θ) = atan2(u_sin, u_cos) is monotonic for realistic distortion, so the
    error Δ(θ) = φ − θ is re-sampled onto an even grid of φ. The phase's origin
    is arbitrary, so a constant in the table would only shift the fine track:
    ``zero`` = "mean" removes the table's mean, "phase0" makes its first entry
    (measured phase 0) zero.
    """
    if size < 8:
        raise ValueError(message(
            QT_TR_NOOP("the correction table needs at least 8 entries")))
    dense = np.linspace(0.0, TWO_PI, 16 * size, endpoint=False)
    measured = np.arctan2(model_signal(dense, sin_fit), model_signal(dense, cos_fit))
    error = _wrap(measured - dense)
    if float(np.ptp(error)) >= math.pi:  # about ±π (the phase's origin near half a period):
        centred, centre = phase_error_about_its_mean(error)  # whole about its mean
        error = centred + centre
    phi = np.mod(dense + error, TWO_PI)
    order = np.argsort(phi)
    phi, error = phi[order], error[order]
    grid = np.arange(size) * (TWO_PI / size)
    table = np.interp(grid, phi, error, period=TWO_PI)
    table = table - (table[0] if zero == "phase0" else float(np.mean(table)))
    return CorrectionTable(table, zero)


@dataclass
class PsoFit:
    fit: ChannelFit
    cost: float
    iterations: int
    seconds: float
    history: np.ndarray


def fit_channel_pso(theta_rad, u, particles: int = 40, max_iterations: int = 2000, stall: int = 200,
                    seed: int = 0, tolerance: float = 1e-12) -> PsoFit:
    """The seed's particle-swarm identification of the 7 parameters (eqs 11–15).

    Velocity update (12) with c1 = c2 = 2, position update (13), velocity
    limits [−1, 1.8] (14) and the inertia weight adapted in [0.4, 0.9] to each
    particle's distance l from the global best and the iteration k (15). Stops
    after ``max_iterations`` or when the best cost changes by less than
    ``tolerance`` (relative) over ``stall`` iterations. Kept for comparison: the
    least-squares fit reaches the global optimum exactly and much faster.
    """
    start = time.perf_counter()
    theta = np.asarray(theta_rad, dtype=float)
    y = np.asarray(u, dtype=float)
    scale = float(np.max(np.abs(y))) or 1.0
    lo = np.array([-0.2 * scale, 0.0, -math.pi, -0.1 * scale, -math.pi, -0.1 * scale, -math.pi])
    hi = np.array([0.2 * scale, 1.5 * scale, math.pi, 0.1 * scale, math.pi, 0.1 * scale, math.pi])
    rng = np.random.default_rng(seed)
    x = lo + rng.random((particles, 7)) * (hi - lo)
    v = rng.uniform(-1.0, 1.8, (particles, 7)) * 0.1 * (hi - lo)
    s1, s3, s5 = np.sin(theta), np.sin(3 * theta), np.sin(5 * theta)
    c1t, c3t, c5t = np.cos(theta), np.cos(3 * theta), np.cos(5 * theta)

    def costs(p: np.ndarray) -> np.ndarray:
        # A sin(kθ + c) = A cos c · sin kθ + A sin c · cos kθ, evaluated for all particles
        model = (p[:, [0]]
                 + (p[:, [1]] * np.cos(p[:, [2]])) * s1 + (p[:, [1]] * np.sin(p[:, [2]])) * c1t
                 + (p[:, [3]] * np.cos(p[:, [4]])) * s3 + (p[:, [3]] * np.sin(p[:, [4]])) * c3t
                 + (p[:, [5]] * np.cos(p[:, [6]])) * s5 + (p[:, [5]] * np.sin(p[:, [6]])) * c5t)
        r = y[None, :] - model
        return np.einsum("ij,ij->i", r, r)

    cost = costs(x)
    pbest, pcost = x.copy(), cost.copy()
    g = int(np.argmin(pcost))
    gbest, gcost = pbest[g].copy(), float(pcost[g])
    diag = float(np.linalg.norm(hi - lo))
    l_min, l_max, w_min, w_max = 0.01 * diag, 0.5 * diag, 0.4, 0.9
    vmin, vmax = -1.0, 1.8
    history = [gcost]
    k = 0
    for k in range(1, max_iterations + 1):  # noqa: B007 - k is used after the loop
        dist = np.linalg.norm(x - gbest, axis=1)
        w = w_max - (dist - l_min) * (w_max - w_min) * k / ((l_max - l_min) * max_iterations)
        w = np.where(dist < l_min, w_min, np.where(dist > l_max, w_max, w))[:, None]
        r1, r2 = rng.random((particles, 7)), rng.random((particles, 7))
        v = w * v + 2.0 * r1 * (pbest - x) + 2.0 * r2 * (gbest - x)
        v = np.clip(v, vmin, vmax)
        x = np.clip(x + v, lo, hi)
        cost = costs(x)
        better = cost < pcost
        pbest[better], pcost[better] = x[better], cost[better]
        g = int(np.argmin(pcost))
        if pcost[g] < gcost:
            gbest, gcost = pbest[g].copy(), float(pcost[g])
        history.append(gcost)
        if k > stall and history[-stall - 1] - gcost <= tolerance * max(history[-stall - 1], 1e-300):
            break
    fit = ChannelFit.from_parameters(
        gbest[0], {1: (gbest[1], gbest[2]), 3: (gbest[3], gbest[4]), 5: (gbest[5], gbest[6])})
    fit.cost = gcost
    return PsoFit(fit, gcost, k, time.perf_counter() - start, np.array(history))
