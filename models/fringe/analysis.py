"""Fringe signal analysis as a workbench: columns, settings, result, JSON and summary."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.cancellation import checkpoint
from models.fringe import KEY, MEASURAND_STANDARDS, ROLES_STATED_ONLY, TITLE
from models.fringe.compensation_at_samples import compensation_caveat
from models.fringe.equal_steps import SIGNIFICANCE as EQUAL_STEPS_SIGNIFICANCE
from models.fringe.equal_steps import step_scatter, unequal_steps
from models.fringe.folded_orders import FoldedOrder, folded_orders
from models.fringe.model import (
    MODEL_INPUT,
    TWO_PI,
    ChannelFit,
    build_correction_table,
    fit_channel_pso,
    fit_channels,
    fit_channels_by_phase,
    fit_periods,
    fit_periods_along,
    interpolation_error_rad,
    model_signal,
    period_arcsec,
    refine_phase,
)
from models.fringe.order_separation import (
    SEPARATION_MIN,
    nearest_grid,
    order_gram,
    pair_separation,
    required_separation,
    variance_inflation,
)
from models.fringe.order_statistics import median
from models.fringe.phase import EllipseFit, fit_ellipse, unwrapped
from models.fringe.phase_consistency import (
    THETA_LIMIT_DEG,
    check_samples_follow_n,
    check_theta_rows,
    check_theta_sequence,
)
from models.fringe.result import FringeResult
from models.fringe.sampling_phase_noise import phase_noise_rad
from models.fringe.signal_quality import default_window, signal_quality
from models.fringe.unmodelled_harmonics import SIGNIFICANCE as HARMONICS_SIGNIFICANCE
from models.fringe.unmodelled_harmonics import unmodelled_harmonics
from models.messages import (
    QT_TR_NOOP,
    joined,
    lines,
    message,
    reason_of,
    separated,
)
from models.parameters import Parameter, SettingsError
from models.readings.sheet import Column, ColumnKind, ParsedReadings
from models.uncertainty.lab_scope import cmc_parameter
from models.uncertainty.rounding import fixed_places, uncertainty_decimals
from models.workbench import (
    SIGN_CONVENTION,
    IssuesCertificates,
    JudgesSignals,
    OverlaysRuns,
    ShowsHeadline,
    Workbench,
    WritesCorrectionTable,
    raw_error_u_note,
)

__all__ = ["FRINGE", "FringeResult"]

COLUMNS = (
    Column("u_sin", "u sin", "V", ColumnKind.NUMBER, help="Sine channel voltage",
           aliases=("sin", "正弦", "正弦信号", "A+")),
    Column("u_cos", "u cos", "V", ColumnKind.NUMBER, help="Cosine channel voltage",
           aliases=("cos", "余弦", "余弦信号", "B+")),
    Column("theta_deg", "θ phase", "deg", ColumnKind.ANGLE_DEG, required=False,
           help="Electrical (fringe) phase of the sample from a reference, optional: without "
                "it the phase is estimated from the signals, or taken as N equal steps a period "
                "when N is given",
           aliases=("phase", "θ", "相位", "电相位")),
)

PARAMETERS = (
    Parameter("lines_per_rev", "lines per revolution L", "int", 16384, minimum=1,
              maximum=1_000_000_000,
              help="Encoder: grating lines per revolution; errors in arcsec of shaft angle (one "
                   "period = 1296000\"/L)"),
    Parameter("period_nm", "interferometer period", "float", 0.0, "nm", 0.001, 1_000_000.0,
              zero="encoder (use L)",
              help="Interferometer: displacement per fringe (316.4 nm for λ/2 of a HeNe laser); "
                   "errors then in nm. 0: an encoder"),
    Parameter("samples_per_period", "samples per period N", "int", 0, minimum=2,
              maximum=1_000_000, zero="phase from θ or the signals",
              help="Equal steps, N samples a period. 0: the phase from the θ column or, without "
                   "one, estimated from the signals (Heydemann); a record that does not follow N "
                   "is refused, and a θ column whose phases the signals fit far better than N's "
                   "steps is used in N's place, said"),
    Parameter("max_order", "highest harmonic", "int", 5, minimum=1, maximum=31,
              help="The highest harmonic fitted to each channel"),
    Parameter("harmonics", "harmonics", "choice", "odd",
              choices=(("odd", "odd (1, 3, 5 …)"), ("all", "all")),
              help="Odd harmonics only (the model of the method's paper, Gao et al. 2013), or every "
                   "order up to the highest"),
    Parameter("method", "identification", "choice", "lsq",
              choices=(("lsq", "least squares (exact)"),
                       ("pso", "particle swarm (Gao et al. 2013)")),
              help="Exact linear least squares, or the particle swarm of the method's paper "
                   "(Gao et al. 2013; first period only, for comparison: it has no U, so no "
                   "certificate is made of it)"),
    Parameter("lut_size", "correction table size", "int", 1024, minimum=8, maximum=65536,
              help="Entries of the correction table over the measured phase"),
    Parameter("table_zero", "table zero", "choice", "mean",
              choices=(("mean", "its mean is zero"), ("phase0", "zero at phase 0")),
              help="The phase origin is arbitrary: the table is stated with its mean removed, or "
                   "with its first entry zero (said in the exported file)"),
    # the inputs of the certificate's budget that the signals cannot show (0: not stated, and
    # the certificate then says what is not traceable)
    Parameter("phase_reference_u", "phase reference u", "float", 0.0, "°", 0.0, 90.0,
              zero="not stated", decimals=4, step=0.01,
              help="Standard uncertainty of each sample's phase, in degrees of a signal period: "
                   "with N equal steps the sampling's uniformity (the timing of the samples), "
                   "with a θ column its reference's stated U / k; with an estimated phase it enters "
                   "U, but the error is not traceable however it is stated (what leaves the "
                   "Lissajous figure round is not observable). Independent from sample to "
                   "sample: it widens the decided half range's interval through the fit, "
                   "counted once with the readings' scatter (the larger of the two, not their "
                   "sum). A phase reference standard listed with its U is the same reference: "
                   "the larger enters, once (a standard's ° is shaft angle, 1/L of a "
                   "period's). 0: not stated"),
    Parameter("adc_lsb_mv", "ADC LSB", "float", 0.0, "mV", 0.0, 10_000.0, zero="not stated",
              decimals=4, step=0.01,
              help="The ADC's step (quantisation LSB/√12 per channel). 0: not stated"),
    Parameter("adc_offset_u_mv", "ADC offset u", "float", 0.0, "mV", 0.0, 10_000.0,
              zero="not stated", decimals=4, step=0.01,
              help="Standard uncertainty of each channel's ADC offset, from its calibration. "
                   "0: not stated"),
    Parameter("adc_gain_u_pct", "ADC gain ratio u", "float", 0.0, "%", 0.0, 100.0,
              zero="not stated", decimals=4, step=0.01,
              help="Standard uncertainty of the ratio of the two channels' ADC gains (a gain "
                   "common to both does not move the phase). 0: not stated"),
    Parameter("adc_linearity_mv", "ADC linearity ±", "float", 0.0, "mV", 0.0, 10_000.0,
              zero="not stated", decimals=4, step=0.01,
              help="The ADC's integral nonlinearity limit ±a per channel (rectangular). "
                   "0: not stated"),
    cmc_parameter("cmc", "laboratory's CMC (smallest U), in the errors' unit", "", "the interpolation error"),
)

#: the settings that are inputs of the certificate's budget (FringeResult.inputs)
BUDGET_INPUTS = ("phase_reference_u", "adc_lsb_mv", "adc_offset_u_mv", "adc_gain_u_pct",
                 "adc_linearity_mv")

PHASE_SOURCES = ("samples_per_period", "theta_column", "estimated")
#: Channel voltages beyond this are not a read head's signals.
SIGNAL_LIMIT_V = 1000.0
# A sample whose radius on the corrected Lissajous figure is off the mean by more than
# this share is no sample of the signal (a spike, a typed value, another unit).
MAX_OFF_RING = 0.5
#: A fit of the channels against the phase below this R² means the phase is wrong.
MIN_R_SQUARED = 0.9
OBSERVABILITY = message(QT_TR_NOOP(
    "Phase estimated from the signals (no phase reference): the offsets, the amplitude ratio "
    "and the quadrature error are identified from the Lissajous ellipse (Heydemann); the "
    "harmonics are fitted against the estimated phase, so only the part of their distortion that "
    "bends the Lissajous figure is seen — a pure phase distortion of the grating leaves the figure "
    "round and is not observable without a phase reference."))


def _settings(settings: Mapping[str, Any]) -> dict[str, Any]:
    return FRINGE.checked_settings(settings)


def _row(parsed: ParsedReadings, i: int) -> int:
    return int(parsed.row_index[i]) + 1


def _check_signals(parsed: ParsedReadings, u_sin: np.ndarray, u_cos: np.ndarray) -> None:
    """Refuse what is not a fringe signal, with the reason, before any fit."""
    largest = {}
    for key, u in (("u_sin", u_sin), ("u_cos", u_cos)):
        largest[key] = float(np.max(np.abs(u)))
        if largest[key] <= SIGNAL_LIMIT_V:  # (a NaN anywhere makes it NaN: not ≤)
            continue
        bad = np.nonzero(~np.isfinite(u) | (np.abs(u) > SIGNAL_LIMIT_V))[0]
        if bad.size:
            i = int(bad[0])
            raise ValueError(message(
                QT_TR_NOOP("row {row}, column '{key}': {u} V is not a read head's signal (beyond "
                           "±{signal_limit_v} V)"),
                row=_row(parsed, i), key=key, u=f"{u[i]:g}", signal_limit_v=f"{SIGNAL_LIMIT_V:g}"))
    # deviations from the mean, once for the spread and the correlation of both channels
    deviation = {key: u - np.mean(u) for key, u in (("u_sin", u_sin), ("u_cos", u_cos))}
    squares = {key: float(d @ d) for key, d in deviation.items()}
    for key, u in (("u_sin", u_sin), ("u_cos", u_cos)):
        if not math.sqrt(squares[key] / u.size) > 1e-9 * max(1.0, largest[key]):
            raise ValueError(message(
                QT_TR_NOOP("channel {key} is constant ({u} V): not a fringe signal"),
                key=key, u=f"{u[0]:g}"))
    corr = float(deviation["u_sin"] @ deviation["u_cos"]) / math.sqrt(squares["u_sin"]
                                                                     * squares["u_cos"])
    if abs(corr) > 0.98:
        raise ValueError(message(
            QT_TR_NOOP("the two channels are the same signal (correlation {corr}): they must be in "
                       "quadrature (sine and cosine)"),
            corr=f"{corr:+.3f}"))


#: the fewest distinct phases of the Lissajous figure that determine its ellipse: five
#: parameters and one degree of freedom
ELLIPSE_PHASES = 6
#: two samples of the Lissajous figure further apart in angle than this are two phases
PHASE_GAP_RAD = math.radians(5.0)


def _lissajous_phases(u_sin: np.ndarray, u_cos: np.ndarray,
                      centre: tuple[float, float] | None = None) -> tuple[int, float]:
    """(how many distinct phases, the widest empty angle in rad) of the Lissajous figure's
    samples about ``centre`` ((u_sin, u_cos) of the ring's centre: the fitted ellipse's
    offsets; the samples' mean if None, which a ring sampled evenly shares and an arc does
    not). Phases are clusters of angle parted by gaps above :data:`PHASE_GAP_RAD` (a sector
    count split each of 4 phases at 0°, 90°, … in two by noise); where no such gap parts
    them (the ring sampled all round) the count is the samples'. The widest gap is at most
    half a turn where a few phases spread round the period, most of it where the record
    covers an arc only (too short, not too coarsely sampled)."""
    c_sin, c_cos = centre if centre is not None else (np.mean(u_sin), np.mean(u_cos))
    angle = np.sort(np.arctan2(u_sin - c_sin, u_cos - c_cos))
    if angle.size < 2:
        return int(angle.size), TWO_PI
    gaps = np.diff(np.concatenate([angle, angle[:1] + TWO_PI]))
    parted = int(np.count_nonzero(gaps > PHASE_GAP_RAD))
    return (parted if parted else int(angle.size)), float(np.max(gaps))


def _ellipse(parsed: ParsedReadings, u_sin: np.ndarray, u_cos: np.ndarray) -> EllipseFit:
    try:
        ellipse = fit_ellipse(u_sin, u_cos)
    except ValueError as exc:
        raise ValueError(message(
            QT_TR_NOOP("not a fringe signal: {exc} in the Lissajous figure (u_sin, u_cos)"),
            exc=reason_of(exc))) \
            from None
    if abs(math.degrees(ellipse.quadrature_rad)) > 30.0:
        raise ValueError(message(
            QT_TR_NOOP("the channels are not in quadrature: their phases differ by {value}°, not about "
                       "90°"),
            value=f"{90 + math.degrees(ellipse.quadrature_rad):.1f}"))
    radius = ellipse.radius(u_sin, u_cos)
    scatter = float(np.std(radius) / np.mean(radius))
    if scatter > 0.25:
        raise ValueError(message(
            QT_TR_NOOP("not a fringe signal: the Lissajous figure is not a ring (its radius scatters by "
                       "{value} %); noise, or two unrelated channels"),
            value=f"{100 * scatter:.0f}"))
    # one sample far off the ring (a spike, a typed value, another unit) bends every fit
    # that follows: its row is named instead
    off = np.abs(radius / np.mean(radius) - 1.0)
    worst = int(np.argmax(off))
    if off[worst] > MAX_OFF_RING:
        raise ValueError(message(
            QT_TR_NOOP("row {row}: the sample (u_sin {u_sin} V, u_cos {u_cos} V) lies {value} % off "
                       "the Lissajous ring the other samples draw: not a sample of this signal; "
                       "check that row"),
            row=_row(parsed, worst), u_sin=f"{u_sin[worst]:g}", u_cos=f"{u_cos[worst]:g}",
            value=f"{100 * off[worst]:.0f}"))
    return ellipse


#: a θ column given with N is taken in N's place when the signals fitted at its phases leave
#: at most this share of the residual sum of squares they leave at N equal steps
THETA_FITS_BETTER = 0.5


def _theta_fits_better(parsed: ParsedReadings, per_period: int, warnings: list[str],
                       asked: tuple[int, ...] = (1, 3, 5)) -> bool:
    """Whether a complete θ column given with N is where the samples were and N's equal steps
    are not (cov76 F4: sampling jittered by 2° of phase, its θ column dropped for N gave a
    half range of 1.3–1.8″ for a true 0.71″): the signals say so — fitted at the θ column's
    phases they leave at most :data:`THETA_FITS_BETTER` of the residual they leave at N
    equal steps. A θ column that is only noisier than N's steps fits worse and is not used.
    Both fits are of the orders ``asked`` that N's steps resolve (below N/2): with the
    fundamental alone at N below 12, a 3rd harmonic of 2 % left in both residuals hid 1° of
    jitter (the θ column's fit left 0.58 of the steps', not used)."""
    theta_col = parsed["theta_deg"]
    if not np.all(np.isfinite(theta_col)) or np.any(np.abs(theta_col) > THETA_LIMIT_DEG):
        return False
    place = parsed.row_index - parsed.row_index[0]
    orders = tuple(k for k in asked if 2 * k < per_period) or (1,)
    channels = [parsed["u_sin"], parsed["u_cos"]]
    if not all(np.all(np.isfinite(c)) for c in channels):
        return False
    try:
        at_theta = fit_channels(np.radians(theta_col), channels, orders)
        at_steps = fit_channels(place * (TWO_PI / per_period), channels, orders)
    except ValueError:
        return False
    ss_theta = sum(f.residual_rms ** 2 for f in at_theta)
    ss_steps = sum(f.residual_rms ** 2 for f in at_steps)
    if not ss_theta < THETA_FITS_BETTER * ss_steps:
        return False
    warnings.append(message(QT_TR_NOOP(
        "The samples per period N = {n} was not used: the samples are not at equal steps — the "
        "signals fitted at the θ column's phases leave {theta} mV rms, at N equal steps "
        "{steps} mV rms; the phase is the θ column's."), n=per_period,
        theta=f"{1e3 * math.sqrt(ss_theta / 2):.3g}", steps=f"{1e3 * math.sqrt(ss_steps / 2):.3g}"))
    return True


def _phase_source(parsed: ParsedReadings, per_period: int, warnings: list[str],
                  orders: tuple[int, ...] = (1, 3, 5)) -> tuple[str, np.ndarray | None]:
    """The mode and, for a fixed sampling or a θ column, each sample's phase (rad)."""
    theta_col = parsed["theta_deg"]
    has_theta = bool(np.any(np.isfinite(theta_col)))
    if per_period and has_theta and _theta_fits_better(parsed, per_period, warnings, orders):
        per_period = 0  # the θ column's phases are where the samples were
    if per_period:
        if has_theta:
            warnings.append(message(QT_TR_NOOP("The θ column was not used: samples per period N "
                                               "was given.")))
        # a sample keeps its place: a blank or unreadable row is a gap at its phase
        place = parsed.row_index - parsed.row_index[0]
        return "samples_per_period", place * (TWO_PI / per_period)
    if has_theta:
        blank = np.nonzero(~np.isfinite(theta_col))[0]
        if blank.size:
            raise ValueError(message(
                QT_TR_NOOP("row {row}, column 'theta_deg': blank while other rows have a phase; fill it, "
                           "or clear the column to estimate the phase from the signals"),
                row=_row(parsed, int(blank[0]))))
        beyond = np.flatnonzero(np.abs(theta_col) > THETA_LIMIT_DEG)
        if beyond.size:
            i = int(beyond[0])
            raise ValueError(message(
                QT_TR_NOOP("row {row}, column 'theta_deg': {theta}° is beyond ±{limit}°: not a "
                           "sample's phase"),
                row=_row(parsed, i), theta=f"{theta_col[i]:g}", limit=f"{THETA_LIMIT_DEG:g}"))
        check_theta_sequence(theta_col, lambda i: _row(parsed, i))
        if np.ptp(theta_col) == 0:
            raise ValueError(message(
                QT_TR_NOOP("every θ is {theta_col}°: the phase did not change"),
                theta_col=f"{theta_col[0]:g}"))
        return "theta_column", np.radians(theta_col)
    return "estimated", None


#: a separation below this is exact aliasing (the orders take the same values at every
#: sampled phase), not a near one: the rounding of the phases' sines
EXACT_ALIAS = 1e-6


def _folded_phases(theta_rad: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The distinct sample phases within one period (rad), and how many samples each."""
    folded = np.sort(np.round(np.mod(theta_rad, TWO_PI), 10) % np.round(TWO_PI, 10))
    if not folded.size:
        return folded, folded
    first = np.concatenate(([True], folded[1:] != folded[:-1]))
    starts = np.flatnonzero(first)
    counts = np.diff(np.concatenate((starts, [folded.size])))
    return folded[starts], counts.astype(float)


#: a span of one period is within the phases' noise when it falls short of a period by at
#: most this many standard deviations of the span (its two ends' noise)
SPAN_NOISE_MARGIN = 4.0


def period_shortfall_allowed(theta_rad: np.ndarray, step_rad: float,
                             phase_u_rad: float = 0.0) -> float:
    """How far (rad) a record's span (first to last phase and one step) may fall short of
    one period and still be one whole period within the noise of its phases: N equal steps
    of one period span (N − 1)/N of it and one step, but a θ column's noise moves both ends.
    :data:`SPAN_NOISE_MARGIN` standard deviations of the ends' difference (√2 σ, σ the
    larger of the stated ``phase_u_rad`` and the noise the record's second differences
    show, :func:`phase_noise_rad`), never more than half a step (a record one step short
    is short); 1e-9 of a
    period for phases without noise (their rounding).

    The step from the last phase back to the first is one more step of the record, so it may
    also be as long as the longest step the record itself shows, and by the steps' own
    spread (:data:`SPAN_NOISE_MARGIN` robust standard deviations) longer (cov76 F1: one
    period of 64 phases with 0.5–1° of sampling jitter, or phases estimated from low-noise
    signals, whose steps are not even enough for :func:`phase_noise_rad`, spanned 359.2–359.6°
    and were refused in 7 of 16 records), never by a whole step: a record whose steps
    scatter that much may lack one phase of its grid, which the fit's few harmonics do not
    miss; one without scatter a step short is refused."""
    noise = max(phase_u_rad, phase_noise_rad(theta_rad))
    allowed = SPAN_NOISE_MARGIN * math.sqrt(2.0) * noise
    theta = np.asarray(theta_rad, dtype=float)
    if theta.size > 2 and np.ptp(theta) < TWO_PI:  # one period's phases in the record's order
        steps = np.abs(np.diff(theta))
        spread = median(np.abs(steps - median(steps))) / 0.6745
        allowed = max(allowed, float(np.max(steps)) - step_rad + SPAN_NOISE_MARGIN * spread)
        return max(1e-9 * TWO_PI, min(allowed, 0.999 * step_rad))
    return max(1e-9 * TWO_PI, min(allowed, 0.5 * step_rad))


def check_record_covers_a_period(theta_rad: np.ndarray, step_rad: float,
                                 phase_u_rad: float = 0.0) -> None:
    """Refuse a record whose phases span less than one period: the fit would extrapolate the
    error over the part of the period never sampled (and the correction table with it). A
    span short of a period by no more than its phases' noise is one period
    (:func:`period_shortfall_allowed`); the share stated with a refusal is rounded down, so
    that it never reads 100.0 % when refused."""
    span = float(np.ptp(theta_rad)) + step_rad
    if span < TWO_PI - period_shortfall_allowed(theta_rad, step_rad, phase_u_rad):
        share = math.floor(1000.0 * span / TWO_PI) / 10.0
        degrees = math.floor(10.0 * math.degrees(span)) / 10.0
        raise ValueError(message(QT_TR_NOOP(
            "the record covers {share} % of one period ({span}° of phase): the harmonics and "
            "the interpolation error over the whole period cannot be determined from less than "
            "one whole period; record at least one period"),
            share=f"{share:.1f}", span=f"{degrees:.1f}"))


def _where(theta_rad: np.ndarray, a: int, b: int, per_period: int) -> str:
    """" at N = …" for the message naming an aliased pair: the samples per period given, or
    the equal steps a θ column's phases lie about."""
    if per_period:
        return message(QT_TR_NOOP(" at N = {n} samples per period"), n=per_period)
    grid = nearest_grid(theta_rad, a, b)
    if grid is None:
        return ""
    n, spread = grid
    if spread * n < 1e-9:
        return message(QT_TR_NOOP(" at N = {n} phases a period"), n=n)
    return message(QT_TR_NOOP(
        " at N = {n} phases a period (the θ column's phases lie within {spread}° rms of N "
        "equal steps)"), n=n, spread=f"{math.degrees(spread):.2g}")


def _lower_to(theta_rad: np.ndarray, a: int, b: int, per_period: int,
              orders: tuple[int, ...]) -> str:
    """" to 3 (below half of N = 8)": the highest harmonic that the N the pair aliases at
    allows, for the refusal's advice; " below half the samples per period" when no N."""
    n = per_period
    if not n:
        grid = nearest_grid(theta_rad, a, b)
        n = grid[0] if grid is not None else 0
    below = [k for k in orders if 2 * k < n]
    if not below:
        return message(QT_TR_NOOP(" below half the samples per period"))
    return message(QT_TR_NOOP(" to {highest} (below half of N = {n})"), highest=max(below), n=n)


def check_orders_not_aliased(theta_rad: np.ndarray, orders: tuple[int, ...],
                             per_period: int = 0, phase_u_rad: float = 0.0) -> None:
    """Refuse harmonic orders that the sample phases cannot tell apart, naming the pair: at N
    samples a period, order k and order N − k (or k + N) take the same values at every sample
    (order N/2 has a sine that is zero at every sample, order N one that is the offset).

    Decided from the design, not from exact repetition (models.fringe.order_separation): a θ
    column jittered about N steps makes the pair distinct only by its noise, and the fit
    then printed both amplitudes as determined at many times their size. A pair (or one
    order's sine and cosine) whose separation is below what is needed
    (:func:`~models.fringe.order_separation.required_separation`, ``phase_u_rad`` the
    phases' stated standard uncertainty) is refused, and so is a design that inflates a
    parameter's variance more than 1/SEPARATION_MIN² against evenly spread phases."""
    phases, counts = _folded_phases(np.asarray(theta_rad, dtype=float))
    every = (0, *orders)
    gram = order_gram(phases, every, counts)

    def figures(a: int, b: int, separation: float) -> dict[str, Any]:
        return dict(separation=f"{100.0 * separation:.2g}",
                    required=f"{100.0 * required_separation(a, b, phase_u_rad):.2g}")

    for k in orders:
        separation = pair_separation(gram, every, k, k)
        if separation >= required_separation(k, k, phase_u_rad):
            continue
        modulo = _where(theta_rad, k, k, per_period)
        if separation <= EXACT_ALIAS:
            raise ValueError(message(QT_TR_NOOP(
                "harmonic order {k} is not determined{modulo}: its sine and cosine are not "
                "independent at the sampled phases (order N/2 or a multiple of N); lower the "
                "highest harmonic or sample more finely"), k=k, modulo=modulo))
        raise ValueError(message(QT_TR_NOOP(
            "harmonic order {k} is not determined{modulo}: at the sampled phases its sine "
            "and cosine differ only through the scatter of the phases (by {separation} % of "
            "what phases spread evenly over the period would show; at least {required} % is "
            "needed; order N/2 or a multiple of N); lower the highest harmonic or sample more "
            "finely"),
            k=k, modulo=modulo, **figures(k, k, separation)))
    for i, a in enumerate(every):
        for b in every[i + 1:]:
            separation = pair_separation(gram, every, a, b)
            if separation >= required_separation(a, b, phase_u_rad):
                continue
            named = dict(a=a if a else message(QT_TR_NOOP("0 (the offset)")), b=b,
                         modulo=_where(theta_rad, a, b, per_period),
                         advice=_lower_to(theta_rad, a, b, per_period, orders))
            if separation <= EXACT_ALIAS:
                raise ValueError(message(QT_TR_NOOP(
                    "harmonic orders {a} and {b} alias{modulo}: they take the same values at "
                    "every sampled phase, so the fit cannot tell them apart; lower the highest "
                    "harmonic{advice}, or sample more finely"),
                    **named))
            raise ValueError(message(QT_TR_NOOP(
                "harmonic orders {a} and {b} alias{modulo}: at the sampled phases a harmonic "
                "of order {b} looks almost exactly like one of order {a}, they differ only "
                "through the scatter of the phases (by {separation} % of what phases spread "
                "evenly over the period would show; at least {required} % is needed), so the "
                "fit cannot tell them apart and would print both amplitudes, and their "
                "uncertainties, as determined when they are not; lower the highest "
                "harmonic{advice}, or sample more finely"),
                **named, **figures(a, b, separation)))
    params = 1 + 2 * len(orders)
    inflation = variance_inflation(gram)
    if phases.size < params or not inflation <= 1.0 / SEPARATION_MIN ** 2:
        if phases.size < params or not math.isfinite(inflation):
            raise ValueError(message(QT_TR_NOOP(
                "{count} distinct phases cannot determine the {params} parameters of each "
                "channel (offset and harmonics {orders}); lower the highest harmonic or sample "
                "more finely"),
                count=phases.size, params=params, orders=", ".join(str(k) for k in orders)))
        raise ValueError(message(QT_TR_NOOP(
            "the sampled phases determine the {params} parameters of each channel (offset and "
            "harmonics {orders}) only poorly: the design inflates a parameter's variance "
            "{inflation}-fold against evenly spread phases (at most {most} is accepted), so the "
            "fit's uncertainties would not be determined; lower the highest harmonic or sample "
            "more finely"),
            params=params, orders=", ".join(str(k) for k in orders),
            inflation=f"{inflation:.3g}", most=f"{1.0 / SEPARATION_MIN ** 2:.0f}"))


def _amplitudes(k: int) -> str:
    """"A3 and B3": the two channels' amplitudes of order ``k`` as the summary prints them
    ("A0 and B0 (the offsets)" for the offset)."""
    if k == 0:
        return message(QT_TR_NOOP("A0 and B0 (the offsets)"))
    return message(QT_TR_NOOP("A{k} and B{k}"), k=k)


def folded_orders_warning(theta_rad: np.ndarray, folds: tuple[FoldedOrder, ...],
                          per_period: int = 0) -> str:
    """The warning naming each order not fitted that folds into a fitted amplitude at the
    sampled phases, and what that leaves undetermined ("" when none)."""
    if not folds:
        return ""
    named = separated([message(QT_TR_NOOP(
        "{amplitudes} hold any harmonic of order {order}: orders {order} and {k} alias"
        "{modulo}"), amplitudes=_amplitudes(f.into), order=f.order, k=f.into,
        modulo=_where(theta_rad, f.into, f.order, per_period)) for f in folds], "; ")
    return message(QT_TR_NOOP(
        "Harmonics the fit leaves out fold into the orders it fits at these phases: {named}. "
        "At the sampled phases such a harmonic looks exactly like the fitted one, so each "
        "amplitude named is the two together (their sum as phasors), not the fitted order "
        "alone, and its U does not hold the other; the interpolation error between the "
        "samples, and its half range over the whole period, is not determined (a decision "
        "on the half range is withheld). Sample more finely to tell them apart."),
        named=named)


def count_reversals(theta_rad: np.ndarray, hysteresis_rad: float = 0.5) -> int:
    """How often the motion turned back: a turn counts once the phase has gone
    ``hysteresis_rad`` the other way, so noise while standing still does not, nor a single
    sample off the path (the median of each three is followed)."""
    theta = np.asarray(theta_rad, dtype=float)
    if theta.size < 2:
        return 0
    theta = theta[:: max(1, theta.size // 200_000)]
    if theta.size >= 3:  # a lone sample off the path (a spike typed over it) is no turn
        a, b, c = theta[:-2], theta[1:-1], theta[2:]
        middle = np.maximum(np.minimum(a, b), np.minimum(np.maximum(a, b), c))
        theta = np.concatenate([theta[:1], middle, theta[-1:]])
    # only where the motion changes direction can a turn begin or an extreme be reached:
    # between two such samples the phase runs one way, and its end decides as all of it would
    step = np.sign(np.diff(theta))
    keep = np.concatenate([[True], step[1:] != step[:-1], [True]])
    turns, direction = 0, 0
    start = extreme = float(theta[0])
    for value in theta[keep][1:].tolist():
        if direction == 0:
            if abs(value - start) > hysteresis_rad:
                direction, extreme = (1 if value > start else -1), value
        elif direction * (value - extreme) > 0:
            extreme = value
        elif direction * (extreme - value) > hysteresis_rad:
            turns += 1
            direction, extreme = -direction, value
    return turns


def check_steps_equal(theta: np.ndarray, u_sin: np.ndarray, u_cos: np.ndarray,
                      fits: tuple[ChannelFit, ChannelFit], per_period: int,
                      stated_u_rad: float = 0.0,
                      theta_given: bool = False) -> None:
    """Refuse N equal steps that the samples were not at: they scatter along the fitted
    Lissajous figure far more than across it (models.fringe.equal_steps), the excess a
    random error of each sample's phase (sampling jitter) beyond the phase reference u
    stated. The whole analysis is refused, not only the decided figure: every error it
    would print (each sample's, their peak-to-peak, the half range, the fit's parameters
    and their U) is taken against phases the samples were not at, and carries the jitter as
    if it were interpolation error; the phases measured (a θ column) remove it
    (``theta_given``: a θ column was given, and fitted the signals no better than the
    steps, so it was not used: said)."""
    scatter = step_scatter(theta, u_sin, u_cos, fits, per_period, stated_u_rad)
    if not unequal_steps(scatter):
        return
    assert scatter is not None
    stated = (message(QT_TR_NOOP(", beyond the phase reference u of {u}° stated"),
                      u=f"{math.degrees(stated_u_rad):.3g}") if stated_u_rad > 0 else "")
    raise ValueError(message(QT_TR_NOOP(
        "the samples are not at N = {n} equal steps: about the fitted signals they scatter "
        "{tangential} mV rms along the Lissajous figure and {radial} mV rms across it, where "
        "the signals' noise moves them alike ({dof} degrees of freedom each; a chance below "
        "{risk} at equal steps). The excess is a random error of {jitter}° rms in each "
        "sample's phase (sampling jitter){stated}, which the analysis at equal steps would "
        "print as interpolation error. Give the phases measured for the samples (a θ "
        "column){theta}"),
        n=per_period, tangential=f"{1e3 * scatter.tangential_v:.3g}",
        radial=f"{1e3 * scatter.radial_v:.3g}", dof=scatter.dof,
        risk=f"{EQUAL_STEPS_SIGNIFICANCE:g}", jitter=f"{math.degrees(scatter.jitter_rad):.2g}",
        stated=stated,
        theta=message(QT_TR_NOOP("; the θ column given fits the signals no better than the "
                                 "equal steps, and is not those phases either"))
        if theta_given else ""))


def _with_unmodelled_harmonics(theta, u_sin, u_cos, fits, orders, phase_index, per_period,
                               stated_step, method, warnings, phase_u=0.0):
    """(orders, fits, orders left out): the fits again with the orders the signals hold
    beyond those asked for (models.fringe.unmodelled_harmonics), named in ``warnings``; the
    particle swarm cannot fit them, so they are returned as left out instead."""
    sin_fit, cos_fit = fits
    found = unmodelled_harmonics(theta, {"sin": (u_sin, sin_fit), "cos": (u_cos, cos_fit)},
                                 phase_index, per_period, stated_step, phase_u)
    if not found:
        return orders, fits, ()
    more = tuple(sorted({h.order for h in found}))
    heard = separated([  # each part translated when shown (a str join froze it in English)
        message(QT_TR_NOOP("order {order}, {channel} {amplitude} mV (u {u} mV)"),
                order=h.order, channel=h.channel, amplitude=f"{h.amplitude_v * 1e3:.3g}",
                u=f"{h.u_v * 1e3:.2g}") for h in found])
    if method == "pso":
        warnings.append(message(QT_TR_NOOP(
            "The signals hold harmonics of order {orders} that the particle swarm (orders 1, "
            "3, 5) leaves out ({heard}): the error between the samples is not "
            "determined, and the half range over the whole period is withheld; use "
            "least squares"), orders=", ".join(map(str, more)), heard=heard))
        return orders, fits, more
    wider = tuple(sorted(set(orders) | set(more)))
    refit = (fit_channels_by_phase(phase_index, per_period, [u_sin, u_cos], wider)
             if phase_index is not None else fit_channels(theta, [u_sin, u_cos], wider))
    warnings.append(message(QT_TR_NOOP(
        "The signals hold harmonics of order {orders} beyond the orders asked for ({asked}): "
        "their residuals show {heard}, beyond the scatter (of {tested} orders looked at on "
        "the two channels, signals that hold none have one named at a risk of {risk} %). "
        "They are fitted as well, so that the error between the samples (and its "
        "half range over the whole period) is the signals' and not a model's that "
        "leaves them out. Ask for them (harmonics: all, or a higher highest "
        "harmonic) to fit them by choice."),
        orders=", ".join(map(str, more)), asked=", ".join(map(str, orders)), heard=heard,
        tested=found[0].tested, risk=f"{100 * HARMONICS_SIGNIFICANCE:g}"))
    return wider, (refit[0], refit[1]), ()


#: the degrees of freedom the noise of the readings needs beyond the unknowns of a channel:
#: one, for its variance to be estimated at all (the coverage factor of the budget's Type A
#: rows, Student's t of n − p degrees of freedom, carries how little one tells)
NOISE_DOF = 1


def least_samples(orders: tuple[int, ...]) -> int:
    """The fewest samples a record of the harmonic ``orders`` needs: the unknowns of each
    channel (its offset, and a sine and a cosine an order) and :data:`NOISE_DOF` degrees of
    freedom for the noise. (Four times the unknowns were asked for before: 16 samples of
    two periods at N = 8, orders 1 and 3, five unknowns a channel, were refused for 20,
    cov76 F9.) A record must also cover a whole period
    (:func:`check_record_covers_a_period`), and the phases tell the orders apart
    (:func:`check_orders_not_aliased`)."""
    return 1 + 2 * len(orders) + NOISE_DOF


def check_enough_samples(count: int, orders: tuple[int, ...], per_period: int = 0) -> None:
    """Refuse a record of fewer than :func:`least_samples`; with N samples a period, orders
    that alias at N are named first, the refusal's real reason (N = 8 and orders 1, 3, 5 over
    three periods was refused as "24 samples; at least 28", cov76 F9)."""
    least = least_samples(orders)
    if count >= least:
        return
    if per_period:
        check_orders_not_aliased(np.arange(per_period) * (TWO_PI / per_period), orders,
                                 per_period)
    raise ValueError(message(QT_TR_NOOP(
        "{size} samples; at least {value} are needed: {params} unknowns for each channel "
        "(the offset and harmonics {orders}) and one degree of freedom for the noise"),
        size=count, value=least, params=least - NOISE_DOF,
        orders=", ".join(str(k) for k in orders)))


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> FringeResult:
    s = _settings(settings)
    lines, per_period = int(s["lines_per_rev"]), int(s["samples_per_period"])
    orders = harmonic_orders(int(s["max_order"]), str(s["harmonics"]))
    u_sin, u_cos = parsed["u_sin"], parsed["u_cos"]
    check_enough_samples(u_sin.size, orders, per_period)
    warnings: list[str] = []
    _check_signals(parsed, u_sin, u_cos)
    checkpoint()
    ellipse = _ellipse(parsed, u_sin, u_cos)
    checkpoint()
    source, given_theta = _phase_source(parsed, per_period, warnings, orders)
    if source == "theta_column":  # N given and the θ column taken in its place: N is unused
        per_period = 0
    stated_ellipse: EllipseFit | None = ellipse
    where = _lissajous_phases(u_sin, u_cos)[0]
    if given_theta is not None and where < ELLIPSE_PHASES:
        # an ellipse has five parameters: through 4 phases (4 steps a period) its quadrature
        # came out −2.95° where the least squares against θ gave 0.009° and 0 was true
        stated_ellipse = None
        warnings.append(message(QT_TR_NOOP(
            "The Lissajous figure holds {count} distinct phases: the ellipse "
            "(Heydemann: offsets, amplitudes, quadrature) is not determined by fewer than "
            "{least} and is not stated; the fit against the phases is."),
            count=where, least=ELLIPSE_PHASES))
    phasor: tuple[np.ndarray, np.ndarray] | None = None
    if given_theta is not None:
        theta = given_theta
    else:  # source "estimated"
        phase, sin_phase, cos_phase = ellipse.phase_and_phasor(u_sin, u_cos)
        phasor = (sin_phase, cos_phase)
        bins = np.count_nonzero(np.bincount(np.floor((phase + math.pi) / TWO_PI * 36)
                                            .astype(np.intp)))
        if bins < 27:
            centre = (ellipse.offset_sin, ellipse.offset_cos)
            distinct, widest = _lissajous_phases(u_sin, u_cos, centre)
            if 2 <= distinct < 27 and u_sin.size >= 2 * distinct and widest <= math.pi:
                # many samples at few phases: sampled too coarsely, not too short (4 a period
                # over 8 periods was refused as "17 % of a period", a tester)
                raise ValueError(message(QT_TR_NOOP(
                    "the {count} samples fall at {phases} distinct phases of the period: too "
                    "few to estimate the phase from the signals; give the phase (a θ column) "
                    "or the samples per period"), count=u_sin.size, phases=distinct))
            raise ValueError(message(
                QT_TR_NOOP("the signals cover {value} % of a period: the phase cannot be estimated from "
                           "less than three quarters of one"),
                value=f"{100 * bins / 36:.0f}"))
        theta = unwrapped(phase)
        warnings.append(OBSERVABILITY)
    # the noise of a θ column's phases: as stated, or as the record shows it if larger
    phase_u = (max(math.radians(float(s["phase_reference_u"])), phase_noise_rad(theta))
               if source == "theta_column" else 0.0)
    if source == "samples_per_period":
        check_record_covers_a_period(theta, TWO_PI / per_period)
    elif theta.size > 1:
        check_record_covers_a_period(theta, median(np.abs(np.diff(theta))), phase_u)
    pso_seconds, design = None, None
    least_squares_rms: tuple[float, ...] = ()
    phase_index = (np.rint(theta / (TWO_PI / per_period)).astype(np.intp) % per_period
                   if source == "samples_per_period" else None)
    if s["method"] == "pso":
        if orders != (1, 3, 5):
            raise SettingsError(message(
                QT_TR_NOOP("the particle swarm (the method of Gao et al. 2013) fits orders 1, "
                           "3, 5 only")))
        span = slice(0, min(u_sin.size, per_period or 64))
        ps, pc = fit_channel_pso(theta[span], u_sin[span]), fit_channel_pso(theta[span], u_cos[span])
        sin_fit, cos_fit = ps.fit, pc.fit
        for fit, u in ((sin_fit, u_sin), (cos_fit, u_cos)):  # over the whole record, as the
            # least squares' (the swarm leaves them unset: the budget's noise was NaN and the
            # certificate a traceback; R² printed "nan", assessment 76 H1)
            resid = u - model_signal(theta, fit)
            fit.residual_rms = float(np.sqrt(np.mean(resid**2)))
            centred = u - np.mean(u)
            ss_tot = float(centred @ centred)
            fit.r_squared = 1.0 - float(resid @ resid) / ss_tot if ss_tot > 0 else 0.0
        # the least squares of the same readings, over the whole record: how far the swarm
        # is from the fit it stands in for (said when a certificate of it is refused)
        least_squares_rms = tuple(f.residual_rms for f in fit_channels(theta, [u_sin, u_cos],
                                                                      orders))
        pso_seconds = ps.seconds + pc.seconds
        lsq_cost = sum(f.cost for f in fit_channels(theta[span], [u_sin[span], u_cos[span]]))
        warnings.append(message(
            QT_TR_NOOP("Particle swarm on the first period: cost {cost} V² against {lsq} V² for "
                       "least squares, {seconds} s."),
            cost=f"{ps.cost + pc.cost:.3g}", lsq=f"{lsq_cost:.3g}", seconds=f"{pso_seconds:.2f}"))
    elif source == "estimated":
        theta, (sin_fit, cos_fit), design = refine_phase(theta, u_sin, u_cos, orders,
                                                          phasor=phasor)
    elif phase_index is not None:  # N equal steps: the fit from N per-phase sums
        sin_fit, cos_fit = fit_channels_by_phase(phase_index, per_period, [u_sin, u_cos], orders)
    else:
        sin_fit, cos_fit = fit_channels(theta, [u_sin, u_cos], orders)
    if source != "estimated" and s["method"] == "lsq":
        worst = min(sin_fit.r_squared, cos_fit.r_squared)
        if not worst >= MIN_R_SQUARED:
            given = (message(QT_TR_NOOP("N = {n} samples per period"), n=per_period)
                     if source == "samples_per_period" else message(QT_TR_NOOP("the θ column")))
            raise ValueError(message(
                QT_TR_NOOP("the signals do not follow {given} (R² {r_squared} sin, {r_squared2} cos): "
                           "leave the samples per period and the θ column out to estimate the phase from "
                           "the signals"),
                given=given, r_squared=f"{sin_fit.r_squared:.4f}", r_squared2=f"{cos_fit.r_squared:.4f}"))
        # the R² gate is coarse (a wrong N by 1 in 64 fitted to R² 0.946): the phase given
        # must be the signals' period by period (N), and sample by sample (a θ column)
        if source == "samples_per_period":
            check_samples_follow_n(parsed.row_index - parsed.row_index[0], per_period,
                                   u_sin, u_cos, (sin_fit, cos_fit))
        else:
            check_theta_rows(theta, u_sin, u_cos, (sin_fit, cos_fit),
                             lambda i: _row(parsed, i))
    given_n = per_period if source == "samples_per_period" else 0  # N as stated, if it is
    if source != "estimated":  # (after the phase is known to fit: a wrong N is said first)
        check_orders_not_aliased(theta, orders, given_n, phase_u)
        lead = math.degrees((cos_fit.phase[1] - sin_fit.phase[1]) % TWO_PI)
        if abs(lead - 90.0) > 30.0:
            raise ValueError(message(
                QT_TR_NOOP("against this phase the cos channel leads the sin channel by {lead}°, not "
                           "about 90°: the channels are in the wrong order or one is inverted (check the "
                           "columns, or the sense of θ)"),
                lead=f"{lead:.0f}"))
    unmodelled: tuple[int, ...] = ()
    folds: tuple[FoldedOrder, ...] = ()
    asked = orders
    if source != "estimated":  # harmonics the signals hold beyond the orders asked for (after
        # the orders asked for are known not to alias: an order found is below half the
        # phases, so it aliases with none of them)
        orders, (sin_fit, cos_fit), unmodelled = _with_unmodelled_harmonics(
            theta, u_sin, u_cos, (sin_fit, cos_fit), orders, phase_index, per_period,
            1e-3 * float(s["adc_lsb_mv"]), str(s["method"]), warnings, phase_u)
        if unmodelled == () and len(orders) > len(asked):  # the orders found are fitted
            # too: the phases must tell them apart from the rest as well
            check_orders_not_aliased(theta, orders, given_n, phase_u)
        # orders left out that the sampled phases fold into a fitted amplitude (5 into A3
        # at N = 8): invisible here, so named, and the curve between the samples withheld
        phases, counts = _folded_phases(theta)
        folds = folded_orders(phases, orders, counts, phase_u)
        if folds:
            warnings.append(folded_orders_warning(theta, folds, given_n))
    if phase_index is not None:  # N equal steps that the samples were not at (cov76 F4)
        check_steps_equal(theta, u_sin, u_cos, (sin_fit, cos_fit), per_period,
                          math.radians(float(s["phase_reference_u"])),
                          bool(np.any(np.isfinite(parsed["theta_deg"]))))
    checkpoint()
    if s["period_nm"]:
        unit, period = "nm", float(s["period_nm"])
    else:
        unit, period = "arcsec", period_arcsec(lines)
    figure = _fitted_figure(sin_fit, cos_fit)  # (the two checks' one figure)
    _check_compensable(sin_fit, cos_fit, figure)
    table = build_correction_table(sin_fit, cos_fit, int(s["lut_size"]), zero=str(s["table_zero"]))
    _check_compensates(sin_fit, cos_fit, table, figure)
    measured = np.arctan2(u_sin, u_cos)
    to_unit = period / TWO_PI
    raw = interpolation_error_rad(measured, theta) * to_unit
    comp = interpolation_error_rad(table.compensate(measured), theta) * to_unit
    # N equal steps: the phase rises with the row by construction, and never turns back
    reversals = 0 if source == "samples_per_period" else count_reversals(theta)
    checkpoint()
    if source == "samples_per_period":
        sin_periods = fit_periods(u_sin, per_period, orders)
        cos_periods = fit_periods(u_cos, per_period, orders)
    else:
        sin_periods, cos_periods = fit_periods_along(theta, [u_sin, u_cos], orders,
                                                     stacked=design)
    return FringeResult(
        theta_rad=theta, u_sin=u_sin, u_cos=u_cos, sin_fit=sin_fit, cos_fit=cos_fit,
        raw_error=raw, compensated_error=comp, table=table, lines_per_rev=lines,
        samples_per_period=per_period, method=str(s["method"]), sin_periods=sin_periods,
        cos_periods=cos_periods, phase_source=source, unit=unit, period_length=period,
        ellipse=stated_ellipse, table_zero=str(s["table_zero"]), reversals=reversals,
        pso_seconds=pso_seconds, least_squares_residual_rms=least_squares_rms,
        warnings=warnings, unmodelled_orders=unmodelled,
        folded_orders=tuple((f.order, f.into) for f in folds),
        inputs={key: float(s[key]) for key in BUDGET_INPUTS},
    )


# The table, applied to the fitted signals themselves, must leave at most this share of
# their error (and of a period): else it does not compensate them, and is refused.
MAX_MODEL_RESIDUAL_SHARE = 0.5
MAX_MODEL_RESIDUAL_PERIOD = 0.01


def _fitted_figure(sin_fit: ChannelFit, cos_fit: ChannelFit, samples: int = 4096
                   ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(phases, the fitted sin channel, the fitted cos channel) over a period: the Lissajous
    figure the checks below judge (made once for both: ~0.5 ms of a record's analysis)."""
    dense = np.linspace(0.0, TWO_PI, samples, endpoint=False)
    return dense, model_signal(dense, sin_fit), model_signal(dense, cos_fit)


def _volts(value: float, sign: str = "") -> str:
    text = f"{value:{sign}.3f}"
    return text.replace("-0.000", "+0.000") if sign else text


def _check_compensable(sin_fit: ChannelFit, cos_fit: ChannelFit,
                       figure: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> None:
    """Refuse a compensation over the measured phase atan2(u_sin, u_cos) where that phase
    does not turn once, forward, a period: the fitted Lissajous figure must circle 0 V (an
    offset larger than the amplitude leaves the origin outside) without looping back
    (``figure``: :func:`_fitted_figure` of the fits, when made)."""
    _, model_sin, model_cos = _fitted_figure(sin_fit, cos_fit) if figure is None else figure
    measured = np.arctan2(model_sin, model_cos)
    steps = np.diff(np.concatenate([measured, measured[:1]]))
    steps = (steps + math.pi) % TWO_PI - math.pi
    turns = float(np.sum(steps)) / TWO_PI
    figures = dict(a0=_volts(sin_fit.offset, "+"), b0=_volts(cos_fit.offset, "+"),
                   a1=_volts(sin_fit.amplitude[1]), b1=_volts(cos_fit.amplitude[1]))
    if round(turns) != 1:
        raise ValueError(message(QT_TR_NOOP(
            "no compensation: the Lissajous figure does not circle 0 V (offsets A0 = {a0} V, "
            "B0 = {b0} V against amplitudes A1 = {a1} V, B1 = {b1} V; the measured phase "
            "atan2(u_sin, u_cos) turns {turns} times a period, not once), so no table over it "
            "can compensate: remove the offsets (differential signals A+ − A−, or the reference "
            "voltage) and analyse again"), turns=int(round(turns)), **figures))
    if not np.all(steps > 0):
        raise ValueError(message(QT_TR_NOOP(
            "no compensation: the measured phase atan2(u_sin, u_cos) of the fitted signals "
            "turns back within a period (the Lissajous figure loops near 0 V: offsets A0 = {a0} "
            "V, B0 = {b0} V, amplitudes A1 = {a1} V, B1 = {b1} V), so a table over it cannot "
            "compensate"), **figures))


def _check_compensates(sin_fit: ChannelFit, cos_fit: ChannelFit, table,
                       figure: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> None:
    """The proof: the table applied to the fitted signals removes their error (else refused,
    with the figures; ``figure`` as :func:`_check_compensable`'s)."""
    dense, model_sin, model_cos = _fitted_figure(sin_fit, cos_fit) if figure is None else figure
    measured = np.arctan2(model_sin, model_cos)
    before = float(np.ptp(interpolation_error_rad(measured, dense)))
    after = float(np.ptp(interpolation_error_rad(table.compensate(measured), dense)))
    if after > MAX_MODEL_RESIDUAL_SHARE * before and after > MAX_MODEL_RESIDUAL_PERIOD * TWO_PI:
        raise ValueError(message(QT_TR_NOOP(
            "no compensation: the correction table, applied to the fitted signals themselves, "
            "leaves {after} % of a period of their {before} % (peak-to-peak): it does not "
            "compensate these signals"),
            after=f"{100 * after / TWO_PI:.2f}", before=f"{100 * before / TWO_PI:.2f}"))


def harmonic_orders(max_order: int, harmonics: str) -> tuple[int, ...]:
    if max_order < 1:
        raise SettingsError(message(
            QT_TR_NOOP("max_order must be at least 1")))
    step = 2 if harmonics == "odd" else 1
    return tuple(range(1, max_order + 1, step))


def to_json(result: FringeResult) -> dict[str, Any]:
    u = result.unit
    out: dict[str, Any] = {
        "phase_source": result.phase_source,
        "sin_params": result.sin_fit.as_dict(),
        "cos_params": result.cos_fit.as_dict(),
        "r_squared": {"sin": result.sin_fit.r_squared, "cos": result.cos_fit.r_squared},
        "offsets_v": [result.sin_fit.offset, result.cos_fit.offset],
        "amplitude_ratio": result.amplitude_ratio,
        "quadrature_error_deg": result.quadrature_error_deg,
        "error_unit": u,
        f"raw_error_{u}": result.raw_error.tolist(),
        f"compensated_error_{u}": result.compensated_error.tolist(),
        f"raw_peak_to_peak_{u}": result.raw_peak_to_peak,
        f"compensated_peak_to_peak_{u}": result.compensated_peak_to_peak,
        f"period_{u}": result.period_length,
        "samples": int(result.raw_error.size),
        "reversals": result.reversals,
        "correction_table": {"size": result.table.size, "zero": result.table_zero,
                             "sha256": result.table.sha256},
        "method": result.method,
        "sign_convention": SIGN_CONVENTION,
        "warnings": result.warnings,
        # orders not fitted that the sampled phases fold into a fitted amplitude
        "folded_orders": [{"order": order, "into": into}
                          for order, into in result.folded_orders],
        # False where orders fold: the compensated error and the table hold at the sampled
        # phases only (compensation_caveat)
        "compensation_determined_between_samples": not result.folded_orders,
    }
    # the signals along the record (#45): per window of periods, in the record's units; the
    # command line's --signal-preset gives them in a preset's units, judged
    quality = signal_quality(result, periods_per_window=default_window(result))
    out["signal_quality"] = quality.windows
    out["signal_quality_units"] = quality.units
    if result.ellipse is not None:
        e = result.ellipse
        out["heydemann"] = {"offsets_v": [e.offset_sin, e.offset_cos],
                            "amplitudes_v": [e.amplitude_sin, e.amplitude_cos],
                            "amplitude_ratio": e.amplitude_ratio,
                            "quadrature_error_deg": math.degrees(e.quadrature_rad)}
    return out


def _with_u(value: float, u: float | None, signed: bool = False) -> str:
    """A fitted parameter and its standard uncertainty, u to two significant digits and
    the value to its decimal (GUM 7.2.6; the certificate rounds its U so too): "0.500000 ±
    0.000019", never a u printed as "0.0000" (day review 68 F12: "A1 = 0.5000 ± 0.0000 V"
    where the certificate printed U = 0.000038 V); without a u, four decimals. A value that
    rounds to zero is printed "0…", never "-0.0000" (day review 69 F6)."""
    spec = "+" if signed else ""
    if u is None or not (math.isfinite(u) and u > 0):
        decimals, shown_u = 4, ""
    else:
        decimals = uncertainty_decimals(u)
        shown_u = f" ± {fixed_places(u, decimals)}"
    # no sign on a zero, and never a negative one
    return f"{fixed_places(value, decimals, spec)}{shown_u}"


def _fit_line(name: str, fit: ChannelFit, u: Mapping[str, float] | None,
              no_u: Any = "") -> Any:
    """One channel's fitted parameters, each ± its standard uncertainty ``u`` (the fit's
    scatter and the ADC's stated figures: models.fringe.parameter_uncertainty): the offset and
    each order's amplitude and phase, the phase to the decimal its own u supports (day review
    69 F6: "∠ -0.0000 rad"), and the fit's R²; or without any u (None: the phase estimated from
    the signals, no u determined)."""
    def of(key: str) -> float | None:
        return None if u is None else u.get(key)

    parts = [f"{name}0 = {_with_u(fit.offset, of('A0'), signed=True)} V"]
    for k in fit.orders:
        parts.append(f"{name}{k} = {_with_u(fit.amplitude[k], of(f'A{k}'))} V "
                     f"∠ {_with_u(fit.phase[k], of(f'c{k}'), signed=True)} rad")
    if u is None:
        return joined(("  " + ", ".join(parts) + " ",
                       no_u or message(QT_TR_NOOP("(no u: the phase was estimated from the "
                                                  "signals)")),
                       f"; R² = {fit.r_squared:.8f}"))
    return joined(("  ", message(QT_TR_NOOP("{parameters} (± u, k = 1); R² = {r_squared}"),
                                 parameters=", ".join(parts), r_squared=f"{fit.r_squared:.8f}")))


_SOURCE_TEXT = {"samples_per_period": QT_TR_NOOP("phase from equal steps, {n} samples per period"),
                "theta_column": QT_TR_NOOP("phase from the θ column"),
                "estimated": QT_TR_NOOP("phase estimated from the signals")}


def summary(result: FringeResult) -> str:
    from models.fringe.parameter_uncertainty import parameter_uncertainty

    stated = parameter_uncertainty(result)
    # the swarm's parameters have no u (parameter_uncertainty.PSO_REASON), said as such
    no_u = (message(QT_TR_NOOP("(no u: identified by particle swarm, which gives no "
                               "covariance)")) if result.method == "pso" else "")
    period, sym = result.period_length, result.unit_symbol
    raw = result.raw_error
    scale = (message(QT_TR_NOOP("L = {lines} (period {period})"), lines=result.lines_per_rev,
                     period=f"{period:.2f}{sym}") if result.unit == "arcsec"
             else message(QT_TR_NOOP("period {period} nm"), period=f"{period:g}"))
    source = message(_SOURCE_TEXT[result.phase_source], n=result.samples_per_period)
    out = [
        joined((message(QT_TR_NOOP("{n} samples, {source}, {scale}, fitted by least squares")
                        if result.method == "lsq" else
                        QT_TR_NOOP("{n} samples, {source}, {scale}, fitted by PSO"),
                        n=raw.size, source=source, scale=scale),
                message(QT_TR_NOOP("; the motion reversed {count} time(s)"),
                        count=result.reversals) if result.reversals else "")),
        _fit_line("A", result.sin_fit, stated.channels.get("sin"), no_u),
        _fit_line("B", result.cos_fit, stated.channels.get("cos"), no_u),
        message(QT_TR_NOOP("Offsets {sin} / {cos} mV, amplitude ratio {ratio}, quadrature error "
                           "{quadrature}°"),
                # a figure that rounds to zero unsigned, as the window prints zero (live78:
                # "Offsets -0.00 / +0.00 mV")
                sin=fixed_places(1e3 * result.sin_fit.offset, 2, "+"),
                cos=fixed_places(1e3 * result.cos_fit.offset, 2, "+"),
                ratio=f"{result.amplitude_ratio:.4f}",
                quadrature=fixed_places(result.quadrature_error_deg, 3, "+")),
        message(QT_TR_NOOP("Interpolation error as found: {low} … {high} (peak-to-peak {ptp}, "
                           "{share} % of a period)"),
                low=f"{fixed_places(result.raw_range[0], 3, '+')}{sym}",
                high=f"{fixed_places(result.raw_range[1], 3, '+')}{sym}",
                ptp=f"{result.raw_peak_to_peak:.3f}{sym}",
                share=f"{result.raw_peak_to_peak / period * 100:.2f}"),
        message(QT_TR_NOOP("After compensation ({entries}-entry table, zero at its mean): {low} … "
                           "{high} (peak-to-peak {ptp}, {share} %)")
                if result.table_zero == "mean" else
                QT_TR_NOOP("After compensation ({entries}-entry table, zero at its phase 0): "
                           "{low} … {high} (peak-to-peak {ptp}, {share} %)"),
                entries=result.table.size, low=f"{fixed_places(result.compensated_range[0], 3, '+')}{sym}",
                high=f"{fixed_places(result.compensated_range[1], 3, '+')}{sym}",
                ptp=f"{result.compensated_peak_to_peak:.3f}{sym}",
                share=f"{result.compensated_peak_to_peak / period * 100:.2f}"),
    ]
    caveat = compensation_caveat(result)
    if caveat:
        out.append(message(QT_TR_NOOP("The compensated error holds {caveat}."), caveat=caveat))
    return lines(out)


def _correction_table(result: FringeResult, settings: Mapping[str, Any], path: str,
                      metadata: Any = None) -> str:
    from models.fringe.export import write_correction_table

    write_correction_table(path, result)
    written = message(QT_TR_NOOP("Correction table, {n} entries (C header)")
                      if str(path).endswith(".h")
                      else QT_TR_NOOP("Correction table, {n} entries (CSV)"), n=result.table.size)
    caveat = compensation_caveat(result)
    return separated([written, caveat], ", ") if caveat else written


class Fringe(Workbench[FringeResult], IssuesCertificates[FringeResult],
             WritesCorrectionTable[FringeResult], OverlaysRuns[FringeResult],
             ShowsHeadline[FringeResult], JudgesSignals[FringeResult]):
    key = KEY
    title = TITLE
    columns = COLUMNS
    parameters = PARAMETERS
    sample_file = "fringe_sample.csv"
    measurand_standards = MEASURAND_STANDARDS
    roles_stated_only = ROLES_STATED_ONLY
    standards_in_settings = True  # the ADC's figures (its report's build_certificate too)
    # each error's U column (the certificate's "U as found" is the raw error's)
    dcc_uncertainty_columns = {"raw_error": "raw_error_",
                               "compensated_error": "compensated_error_"}
    #: what the DCC says of the raw error's U (the printed "U as found"): the one rule
    dcc_column_notes = {"raw_error": raw_error_u_note(MODEL_INPUT)}
    method_reference = ("Gao X. et al., Automatic compensation of sine deviation for grating "
                        "fringe photoelectric signal, Acta Optica Sinica 33(7):0712001 (2013)")
    presenter = "widgets.fringe.presenter:FringePresenter"
    entry_column = "u_sin"
    sample_settings = {"lines_per_rev": 16384}  # the phase from the sample's θ column
    analyze = staticmethod(analyze)
    to_json = staticmethod(to_json)
    summary = staticmethod(summary)
    correction_table = staticmethod(_correction_table)

    @property
    def signal_flags(self):
        from models.fringe.signal_options import FLAGS

        return FLAGS

    def add_signal_arguments(self, parser, words):
        from models.fringe.signal_options import add_arguments

        add_arguments(parser, words)

    def signal_setup(self, args):
        from models.fringe.signal_options import setup

        return setup(args)

    def signal_results(self, args, result, setup):
        from models.fringe.signal_options import results

        return results(args, result, *setup)

    def write_signal_table(self, args, result, table):
        from models.fringe.signal_options import write_table

        return write_table(args, result, table)

    def certificate(self, result, metadata, source_name="", settings=None):
        from models.fringe.report import fringe_certificate

        return fringe_certificate(result, metadata, source_name, self.method_reference, settings)

    def certificate_refusal(self, result):
        # a particle swarm's fit: no U, no certificate whatever the details (assessment 76 H1)
        from models.fringe.report import identification_refusal

        return identification_refusal(result)

    def certified_json(self, result, metadata, settings=None):
        # each signal parameter's U beside it, at the certificate's probability, as the
        # certificate's parameters table prints it (issue 39; audit 69 finding 2)
        from models.fringe.report import (
            adc_standard_warnings,
            parameters_json,
            reference_unit_warnings,
        )

        out = parameters_json(result, float(metadata.coverage_probability))
        # a phase reference standard's "°" read as shaft angle, and the ADC's U that is no
        # input (its figures in the settings are), said as the certificate says them
        # (assessment 76 M3)
        said = [*reference_unit_warnings(result, metadata),
                *adc_standard_warnings(result, metadata)]
        if said:
            out["warnings"] = [*result.warnings, *(str(w) for w in said)]
        return out

    def inputs_not_stated(self, result, metadata):
        from models.fringe.report import not_stated

        return not_stated(result, metadata)

    def decided_errors(self, result, metadata):
        # half range: the fitted model's continuous as-found error over the whole period
        if metadata.decision_quantity == "half_range":
            if result.folded_orders:  # the curve between the samples is not determined
                return None
            from models.fringe.report import model_error_curve

            return model_error_curve(result)[1]
        return result.raw_error

    def uncertainty_array_names(self, result):
        return [f"raw_error_{result.unit}", f"compensated_error_{result.unit}"]

    def uncertainty_budgets(self, result, metadata, settings=None):
        # as found: the signals' and the stated inputs; compensated: with the fitted model
        if result.phase_source == "estimated":
            # what the estimated phase cannot see is in no budget: an audit with its own
            # signals found the per-sample U covering 15-19 % of the samples with 3rd and
            # 5th harmonics of 0.1-0.5 % (and 100 % at twenty times the deviations without):
            # the JSON's U null with the reason, as for any U the readings do not determine
            from models.fringe.report import ESTIMATED_PHASE_REASON

            raise ValueError(message(ESTIMATED_PHASE_REASON))
        from models.fringe.report import fringe_budget

        u = result.unit
        return {f"raw_error_{u}": fringe_budget(result, metadata, as_found=True, settings=settings),
                f"compensated_error_{u}": fringe_budget(result, metadata, settings=settings)}

    def error_unit(self, settings):
        """nm when an interferometer's period is set, as :func:`analyze` does; else arcsec."""
        try:
            return "nm" if float(settings.get("period_nm") or 0.0) else "arcsec"
        except (TypeError, ValueError):
            return "arcsec"

    def overlay_figure(self, result):
        from models.fringe.plots import figures  # the window's: a plot's module

        return figures(result)["errors"]

    def verdict(self, r):
        # where orders fold, the error as found is the sampled phases' too (day review 69 F1)
        said = message(
            QT_TR_NOOP("Interpolation error {ptp} peak-to-peak at the sampled phases only "
                       "({share} % of a period); {after} after compensation")
            if getattr(r, "folded_orders", ()) else
            QT_TR_NOOP("Interpolation error {ptp} peak-to-peak ({share} % of a period); {after} "
                       "after compensation"),
            ptp=f"{r.raw_peak_to_peak:.3f}{r.unit_symbol}",
            share=f"{r.raw_peak_to_peak / r.period_length * 100:.2f}",
            after=f"{r.compensated_peak_to_peak:.3f}{r.unit_symbol}")
        caveat = compensation_caveat(r)
        return separated([said, caveat], ", ") if caveat else said

    def printed_headline(self, result, printed=None):
        # the certificate's statistics print both to 0.001 (models/fringe/report.py)
        return {f"as-found peak-to-peak ({result.unit})": f"{result.raw_peak_to_peak:.3f}",
                f"compensated peak-to-peak ({result.unit})":
                    f"{result.compensated_peak_to_peak:.3f}"}

    def headline(self, r):
        return {f"as-found peak-to-peak ({r.unit})": r.raw_peak_to_peak,
                f"compensated peak-to-peak ({r.unit})": r.compensated_peak_to_peak}


FRINGE = Fringe()
