"""Polygon encoder test: encoder error per face, closure, pyramidal error.

Seed 001 (Tian et al., Acta Optica Sinica 35(5) 0512003, 2015). An n-face
polygon sits on the encoder shaft; an autocollimator looks at face i after the
encoder has turned by (i − 1)·360°/n.

* Error per position (eq 1), against one common zero for every set (face z of
  the first set): ``e_i = (a_i − a_z) − (b_i − b_z) − (c_i − c_z)`` with
  ``b_i = (i − 1)·360°/n + dev_i`` (dev from the polygon's certificate), every
  angle taken in the encoder's counting sense.
* Closure drift of a set that returns to its start face s:
  ``H = (c'_s − c_s) − (a'_s − a_s)``, so a shaft that overshoots on return
  with nothing drifting gives 0.
* Pyramidal error: the encoder axis ``[sinψ cosω, sinψ sinω, cosψ]`` is tilted
  by ψ towards ω in the polygon frame. Face normal ``[cosθ, sinθ, 0]`` rotated
  about it by −θ (eqs 3–5) gives ``ε_x = atan(y'/x')`` and
  ``ε_y = atan(z'/x')`` (eqs 6–7). Eqs 3–7 turn the faces by −θ, so the
  horizontal readings, taken in eq (1)'s sense, contain −ε_x: the corrected
  error is ``e_i − (ε_x,i − ε_x,z)`` (../shared/SPEC.md §2, corrected 2026-11-27). The fitted
  ω is in the seed's frame; :func:`tilt_advice` says where the tilt is in
  terms of faces and readings.
* Which frame the autocollimator reads in (../shared/SPEC.md §2, 2026-12-01): eqs 3–7 put the
  autocollimator's vertical along the *polygon's* axis (``ac_alignment`` =
  ``"polygon"``). In a lab the autocollimator and the rotary axis are levelled
  (``"levelled"``): its vertical is along the shaft. Same coordinates, same turned
  normals, read in a basis turned from the polygon's to the shaft's by the least
  rotation; the vertical readings agree (to O(ψ³)), the horizontal ones differ by the
  cross-talk of a roll ψ·sinω (in the seed's ω) between the two bases. A measured roll
  ρ of the autocollimator (the horizontal reading's change per unit change of the
  vertical one, as a tilt test shows it) is a further turn of the reading basis about
  the line of sight. :func:`frame_readings_arcsec` does it all by 3-D rotation.

Angles in degrees, errors and tilts in arcseconds unless the name says otherwise.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from models.polygon.rounding import HorizontalRounding
    from models.readings.sheet import ParsedReadings

from models.messages import QT_TR_NOOP, Message, message

# the tilt's geometry and the closure drift (shared with the cross-calibration workbench)
from models.pyramidal import (
    AC_ALIGNMENTS,
    TiltFit,
    closure_drift_arcsec,
    fit_tilt,
    frame_readings_arcsec,
    pyramidal_correction_arcsec,
    pyramidal_readings_arcsec,
    wrap_deg,
)
from models.readings.angles import ARCSEC_PER_RAD
from models.uncertainty.error_stats import ErrorStats
from models.uncertainty.tilt_direction import NOT_DETERMINED

__all__ = ["split_sets",
    "AC_ALIGNMENTS",
    "GRADE_ACCURACY_ARCSEC",
    "LEVELLED_OWN_COEFFICIENT",
    "SHORT_FORM_COEFFICIENT",
    "WORST_CASE_COEFFICIENT",
    "HarmonicAnalysis",
    "PolygonResult",
    "PolygonSetResult",
    "TiltFit",
    "allowed_tilt_arcsec",
    "allowed_tilt_levelled_arcsec",
    "closure_drift_arcsec",
    "counting_residuals_deg",
    "face_errors_arcsec",
    "fit_tilt",
    "frame_readings_arcsec",
    "harmonic_analysis",
    "pyramidal_correction_arcsec",
    "pyramidal_readings_arcsec",
    "pyramidal_x_short_arcsec",
    "pyramidal_y_short_arcsec",
    "PolygonSetReadings",
    "direction_means",
    "evaluate_sets",
    "pooled_repeatability", "reversal_pair_noise", "sets_alike", "set_offsets_spread",
    "within_set_noise", "zero_offsets_warning",
    "tilt_advice",
    "tilt_not_identified",
    "tilt_not_identified_cause",
    "wrap_deg",
]

#: Table 1 of the seed: accuracy (±") of encoder grades 1–7.
GRADE_ACCURACY_ARCSEC = {1: 0.25, 2: 0.5, 3: 1.0, 4: 2.0, 5: 5.0, 6: 10.0, 7: 30.0}

#: The seed's ε_x/ψ² (1/arcsec): its largest over θ at ω = 90° (θ ≈ 111°).
SHORT_FORM_COEFFICIENT = 0.5337e-5

#: The largest ε_x/ψ² over every θ and ω (1/arcsec): (1 + √2)/2 rad⁻¹ = 5.852e-6,
#: at ω = 67.5°, θ = 225° (and ω = 247.5°). ω is not known before measuring, so the
#: allowed tilt is judged with this one.
WORST_CASE_COEFFICIENT = (1.0 + math.sqrt(2.0)) / 2.0 / ARCSEC_PER_RAD

#: Levelled frame: the polygon's own term is a 2θ pattern of amplitude ψ²/4 (rad), so two
#: faces differ by at most ψ²/2: 1/(2 rad) = 2.424e-6 per arcsec (tests check it by 3-D).
LEVELLED_OWN_COEFFICIENT = 0.5 / ARCSEC_PER_RAD


def allowed_tilt_arcsec(grade: int, coefficient: float = WORST_CASE_COEFFICIENT) -> float:
    """Largest pyramidal tilt ψ (") keeping the induced error under a third of the accuracy.

    ``ψ_max = sqrt((tol/3)/coefficient)``. With the seed's coefficient (ω = 90°):
    125, 177, 250, 353, 559, 790, 1369" for grades 1–7 (the seed prints 140" for
    grade 1, which its formula does not give); with the worst case over ω
    (the default): 119, 169, 239, 338, 534, 755, 1307".
    """
    tol = GRADE_ACCURACY_ARCSEC[int(grade)]
    return math.sqrt((tol / 3.0) / coefficient)


def allowed_tilt_levelled_arcsec(grade: int, roll_arcmin: float) -> float:
    """Largest tilt ψ (") of a levelled set-up keeping the induced error under a third of the
    accuracy: the polygon's own term ψ²/2 (rad) plus the unknown roll ρ times the vertical
    span 2ψ, ``ψ²/(2 rad) + 2ρψ = tol/3``. 370, 524, 741, … with no roll; 270″ for grade 3
    at a 1′ roll."""
    third = GRADE_ACCURACY_ARCSEC[int(grade)] / 3.0
    a, b = LEVELLED_OWN_COEFFICIENT, 2.0 * abs(roll_arcmin) * 60.0 / ARCSEC_PER_RAD
    return (-b + math.sqrt(b * b + 4.0 * a * third)) / (2.0 * a)


def counting_residuals_deg(encoder_deg, position_deg, counting: int) -> np.ndarray:
    """How far each encoder reading is from its face, relative to the first reading (deg).

    ``position_deg`` is each reading's nominal face angle (i − 1)·360°/n in the
    face numbering; ``counting`` = +1 when the encoder counts up with the face
    numbers, −1 when against them. Near zero for readings of a polygon test.
    """
    a = np.asarray(encoder_deg, dtype=float)
    nominal = np.asarray(position_deg, dtype=float)
    return wrap_deg((a - a[0]) - counting * (nominal - nominal[0]))


def face_errors_arcsec(encoder_deg, polygon_dev_arcsec, ac_x_arcsec, position_deg,
                       zero: tuple[float, float, float, float], counting: int = 1) -> np.ndarray:
    """Encoder error at each reading against a common zero (eq 1), arcsec.

    ``zero`` is (encoder_deg, position_deg, polygon_dev_arcsec, ac_x_arcsec) of
    the zero reading. Face angles b = nominal + dev are taken in the counting
    sense; the encoder difference is wrapped, so readings may pass 360°.
    """
    a0, p0, dev0, c0 = zero
    a = np.asarray(encoder_deg, dtype=float)
    nominal = np.asarray(position_deg, dtype=float)
    dev = np.asarray(polygon_dev_arcsec, dtype=float)
    c = np.asarray(ac_x_arcsec, dtype=float)
    da = wrap_deg((a - a0) - counting * (nominal - p0))
    return da * 3600.0 - counting * (dev - dev0) - (c - c0)


def pyramidal_x_short_arcsec(theta_deg, psi_arcsec: float, omega_deg: float):
    """Short form (12): ε_x ≈ 0.4848e-5 ψ²[sinω(1 − cosθ)cos(ω − θ) + ½ sinθ cosθ]."""
    th = np.radians(np.asarray(theta_deg, dtype=float))
    om = math.radians(omega_deg)
    bracket = math.sin(om) * (1 - np.cos(th)) * np.cos(om - th) + 0.5 * np.sin(th) * np.cos(th)
    return psi_arcsec**2 / ARCSEC_PER_RAD * bracket


def pyramidal_y_short_arcsec(theta_deg, psi_arcsec: float, omega_deg: float):
    """Short form (13): ε_y ≈ ψ[cos(ω − θ) − cosω]."""
    th = np.radians(np.asarray(theta_deg, dtype=float))
    om = math.radians(omega_deg)
    return psi_arcsec * (np.cos(om - th) - math.cos(om))


#: a set's warning when it ends without its closure reading
NO_CLOSURE_READING = QT_TR_NOOP("{set}: no closure reading (the row back on its start face): "
                                "drift not checked.")


def set_name(label: str) -> Message:
    """ "Set 2" for the set labelled "set 2", as a warning begins with it."""
    return message(QT_TR_NOOP("Set {number}"), number=label.split()[-1])


@dataclass
class HarmonicAnalysis:
    """Fourier analysis of an error over the full circle, arcsec.

    ``amplitude[k]`` and ``phase_deg[k]`` describe ``A_k cos(kθ + φ_k)``
    for k = 0…n/2 (k = 1 eccentricity, k = 2 ellipticity, …).
    """

    order: np.ndarray
    amplitude: np.ndarray
    phase_deg: np.ndarray


def harmonic_analysis(error_arcsec) -> HarmonicAnalysis:
    """DFT of an error sampled at n equally spaced positions over 360°."""
    e = np.asarray(error_arcsec, dtype=float)
    n = e.size
    spectrum = np.fft.rfft(e) / n
    amplitude = np.abs(spectrum) * 2.0
    amplitude[0] /= 2.0
    if n % 2 == 0:
        amplitude[-1] /= 2.0
    return HarmonicAnalysis(np.arange(spectrum.size), amplitude, np.degrees(np.angle(spectrum)))


def tilt_advice(tilt: TiltFit, faces: int, counting: int) -> str:
    """Where the tilt is, in what the technician sees: the faces where the vertical
    reading is highest and lowest, and how far the readings must come together.

    The fitted vertical curve ``k + ψ[cos(ω − θ) − cos ω]`` peaks at θ = ω, so the
    answer holds whichever sense the autocollimator's vertical reading has.
    """
    step = 360.0 / faces
    nominal = (counting * tilt.omega_deg) % 360.0
    high = int(round(nominal / step)) % faces + 1
    low = int(round(((nominal + 180.0) % 360.0) / step)) % faces + 1
    return message(QT_TR_NOOP("the vertical reading is highest at face {high} and lowest at "
                              "face {low} (spread 2ψ = {spread}): tilt the polygon on its seat "
                              "so that face {high} comes down and face {low} up by about {psi} "
                              "each"),
                   high=high, low=low, spread=f"{2 * tilt.psi_arcsec:.0f}\"",
                   psi=f"{tilt.psi_arcsec:.0f}\"")


@dataclass
class PolygonSetReadings:
    """One set (a turn round the polygon) as read, in approach order."""

    positions: np.ndarray  # face numbers 1…n
    encoder_deg: np.ndarray
    polygon_dev_arcsec: np.ndarray
    ac_x_arcsec: np.ndarray
    ac_y_arcsec: np.ndarray  # NaN where not read
    direction: int = 1  # +1 forward (encoder counting up), −1 reverse
    closure_encoder_deg: float | None = None  # the reading back on the start face
    closure_ac_x_arcsec: float | None = None
    label: str = "set 1"
    rows: np.ndarray | None = None  # each reading's 0-based sheet row, approach order


@dataclass
class PolygonSetResult:
    """One set's figures over positions 1…n (arcsec), against the test's common zero."""

    theta_deg: np.ndarray  # position angle in the counting sense
    error_arcsec: np.ndarray
    closure_drift_arcsec: float | None
    closure_ok: bool | None
    tilt: TiltFit | None
    pyramidal_error_arcsec: np.ndarray  # ε_x − ε_x(zero face): subtracted from the error
    corrected_error_arcsec: np.ndarray
    direction: int = 1
    start_face: int = 1
    ac_y_arcsec: np.ndarray | None = None  # position order, for the budget
    warnings: list[str] = field(default_factory=list)
    # why the tilt was not identified ("" when it was): no vertical readings, no variation
    # in them, or no degrees of freedom left for the fit (3 faces)
    tilt_not_identified: str = ""
    # position order: each position's index among the set's readings (0: its first reading,
    # the closure comes at n), for the drift carried from set to set in the budget
    reading_index: np.ndarray | None = None
    # the same cause in a few words, for the summary's line of the set ("" when identified;
    # :func:`tilt_not_identified_cause`)
    tilt_not_identified_cause: str = ""

    @property
    def closure_arcsec(self) -> float | None:
        """|closure drift|, the figure judged against the closure limit."""
        return None if self.closure_drift_arcsec is None else abs(self.closure_drift_arcsec)


#: the tilt fit's unknowns: the vertical reading's zero, ψ and ω
TILT_FIT_UNKNOWNS = 3

#: the largest tilt of the polygon on the shaft the budget assumes when the readings do not
#: identify it (the setting tilt_bound_arcsec's default, ″)
DEFAULT_TILT_BOUND_ARCSEC = 300.0


def _unidentified_because(v: np.ndarray) -> str:
    """Why readings ``v`` cannot identify the tilt, as a key: "missing" (none, or one not a
    number), "few" (no more than the fit's unknowns), "equal" (no variation); "" when they
    can."""
    read = v[np.isfinite(v)]
    if read.size == 0:
        return "missing"
    if read.size <= TILT_FIT_UNKNOWNS:
        # the faces that have one are too few: a vertical reading missing, or 3 faces
        return "missing" if read.size < v.size else "few"
    # the faces read are enough: the tilt is fitted from them (contract review 75 F9: one
    # empty cell switched the whole set's correction off), the faces missing one named
    return "equal" if np.ptp(read) == 0 else ""


def tilt_not_identified_cause(ac_y_arcsec) -> str:
    """Why one set's vertical readings cannot identify the tilt, in a few words for a line of
    the summary ("no vertical readings", "every vertical reading is 12.5\"" …); "" when they
    can. The whole reason, with what follows from it, is :func:`tilt_not_identified`'s."""
    v = np.asarray(ac_y_arcsec if ac_y_arcsec is not None else [], dtype=float)
    because = _unidentified_because(v)
    if because == "missing":
        finite = int(np.count_nonzero(np.isfinite(v)))
        return message(QT_TR_NOOP("no vertical readings")) if finite == 0 else message(
            QT_TR_NOOP("vertical readings missing on {missing} of {faces} faces"),
            missing=v.size - finite, faces=v.size)
    if because == "few":
        return message(QT_TR_NOOP("{n} faces: no degrees of freedom left for the tilt fit"),
                       n=v.size)
    if because == "equal":
        return message(QT_TR_NOOP("every vertical reading is {value}\""),
                       value=f"{v[np.isfinite(v)][0]:g}")
    return ""


def tilt_not_identified(ac_y_arcsec, label: str = "set 1") -> str:
    """Why one set's vertical readings cannot identify the tilt, naming it ("" when they can).

    A tilt ψ moves the vertical reading by 2ψ peak-to-peak over a turn: readings that are all
    equal carry no tilt to fit (and a fit through them shows no scatter, so they cannot say
    how noisy the readings are either); the fit has three unknowns (zero, ψ, ω), so 3 faces
    leave it no degrees of freedom — it passes through every reading, whatever their noise.
    """
    v = np.asarray(ac_y_arcsec, dtype=float)
    because = _unidentified_because(v)
    if because == "missing":
        return message(QT_TR_NOOP("{set}: vertical readings missing: the pyramidal tilt is not "
                                  "identified and its error not removed; the tilt bound "
                                  "enters the uncertainty."), set=set_name(label))
    if because == "few":
        return message(QT_TR_NOOP(
            "{set}: {n} faces give {n} vertical readings for the tilt fit's 3 unknowns (zero, ψ, "
            "ω): no degrees of freedom are left, so the fit would pass through every reading "
            "whatever its noise. The pyramidal tilt is not identified and its error not "
            "removed; the tilt bound enters the uncertainty."), set=set_name(label), n=v.size)
    if because == "equal":
        return message(QT_TR_NOOP(
            "{set}: every vertical reading is {value}\": no variation, while a tilt ψ moves it by "
            "2ψ over a turn. The pyramidal tilt is not identified (ψ = 0 is not a finding) and its "
            "error not removed; the tilt bound enters the uncertainty. Check that the vertical "
            "readings were read, not copied."), set=set_name(label),
            value=f"{v[np.isfinite(v)][0]:g}")
    return ""


def _fit_tilt_of_faces_read(theta: np.ndarray, ac_y: np.ndarray, ac_alignment: str,
                            roll_rad: float) -> TiltFit:
    """The tilt fitted to the faces that have a vertical reading (each face's correction
    needs only ψ, ω and its angle); its residuals over every face, NaN where none was read."""
    read = np.isfinite(ac_y)
    if np.all(read):
        return fit_tilt(theta, ac_y, ac_alignment, roll_rad)
    tilt = fit_tilt(theta[read], ac_y[read], ac_alignment, roll_rad)
    residuals = np.full(theta.size, np.nan)
    residuals[read] = tilt.residuals_arcsec
    return dataclasses.replace(tilt, residuals_arcsec=residuals)


def evaluate_sets(sets: list[PolygonSetReadings], faces: int, counting: int = 1,
                  zero_face: int = 0, closure_limit_arcsec: float = math.inf,
                  spread_drift: bool = False, ac_alignment: str = "levelled",
                  roll_rad: float = 0.0) -> list[PolygonSetResult]:
    """Error, closure drift and pyramidal correction of every set against one zero.

    The correction is the frame's (``ac_alignment``, with a measured roll ``roll_rad``;
    see :func:`frame_readings_arcsec`).

    The zero is ``zero_face`` of the first set (0: the first set's first
    reading). With ``spread_drift`` each set's closure drift is taken as
    growing linearly from its first reading to its closure and removed from
    the autocollimator's readings.
    """
    n = faces
    step = 360.0 / n
    first = sets[0]
    zero_face = zero_face or int(first.positions[0])
    prepared = []
    for s in sets:
        ac_x = np.asarray(s.ac_x_arcsec, dtype=float)
        drift = None
        if s.closure_ac_x_arcsec is not None and s.closure_encoder_deg is not None:
            drift = closure_drift_arcsec(s.encoder_deg[0], ac_x[0], s.closure_encoder_deg,
                                         s.closure_ac_x_arcsec)
            if spread_drift:
                ac_x = ac_x - drift * np.arange(ac_x.size) / n
        order = np.argsort(s.positions)
        prepared.append((s, ac_x, drift, order))
    s0, ac_x0, _, _ = prepared[0]
    z = int(np.nonzero(s0.positions == zero_face)[0][0])
    nominal_z = (zero_face - 1) * step
    zero = (float(s0.encoder_deg[z]), nominal_z, float(s0.polygon_dev_arcsec[z]), float(ac_x0[z]))
    theta_z = counting * nominal_z
    results = []
    for s, ac_x, drift, order in prepared:
        nominal = (s.positions[order] - 1) * step
        theta = counting * nominal
        error = face_errors_arcsec(s.encoder_deg[order], s.polygon_dev_arcsec[order], ac_x[order],
                                   nominal, zero, counting)
        warnings: list[str] = []
        ok = None
        if drift is not None:
            ok = bool(abs(drift) <= closure_limit_arcsec)
            drift = float(drift)
            if not ok:
                warnings.append(message(
                    QT_TR_NOOP("{set}: closure drift {drift} exceeds the limit ±{limit}: the set "
                               "is invalid; repeat it."), set=set_name(s.label),
                    drift=f"{drift:+.2f}\"", limit=f"{closure_limit_arcsec:g}\""))
        else:
            warnings.append(message(NO_CLOSURE_READING, set=set_name(s.label)))
        ac_y = np.asarray(s.ac_y_arcsec, dtype=float)[order]
        tilt = None
        pyramidal = np.zeros(n)
        unidentified = tilt_not_identified(ac_y, s.label)
        if not unidentified:
            tilt = _fit_tilt_of_faces_read(theta, ac_y, ac_alignment, roll_rad)
            if not np.all(np.isfinite(ac_y)):
                # the faces read fit the tilt; the budget's vertical change from the zero
                # face takes the fitted one where a face has no reading
                fitted = tilt.offset_arcsec + frame_readings_arcsec(
                    theta, tilt.psi_arcsec, tilt.omega_deg, ac_alignment, roll_rad)[1]
                ac_y = np.where(np.isfinite(ac_y), ac_y, fitted)
            pyramidal = pyramidal_correction_arcsec(theta, tilt.psi_arcsec, tilt.omega_deg, theta_z,
                                                    ac_alignment, roll_rad)
            if not tilt.omega_determined:
                warnings.append(message(QT_TR_NOOP("{set}: {why}"), set=set_name(s.label),
                                        why=message(NOT_DETERMINED,
                                                    tilt=f"ψ = {tilt.psi_arcsec:.3g}\"",
                                                    u=f"{tilt.u_psi_arcsec:.2g}\"",
                                                    direction="ω")))
        else:
            warnings.append(unidentified)
        results.append(PolygonSetResult(theta, error, drift, ok, tilt, pyramidal, error - pyramidal,
                                        s.direction, int(s.positions[0]),
                                        ac_y if tilt is not None else None, warnings,
                                        unidentified, np.asarray(order),
                                        tilt_not_identified_cause(ac_y) if unidentified else ""))
    return results


@dataclass
class PolygonResult:
    """A whole polygon test (one or several sets) against one common zero."""

    sets: list[PolygonSetResult]
    faces: int
    grade: int
    theta_deg: np.ndarray  # nominal face angle of positions 1…n (face numbering)
    mean_error_arcsec: np.ndarray  # bidirectional mean when both directions were run
    mean_corrected_arcsec: np.ndarray
    repeatability_arcsec: np.ndarray | None  # pooled s within each direction, per position
    reversal_arcsec: np.ndarray | None  # ē↑ − ē↓ per position: forward sets' mean error minus reverse's
    stats: ErrorStats
    raw_stats: ErrorStats
    harmonics: HarmonicAnalysis
    allowed_tilt_arcsec: float  # worst case over ω
    allowed_tilt_seed_arcsec: float  # the seed's (ω = 90°)
    accuracy_ok: bool
    tilt_verdict: str
    valid: bool
    counting: int = 1
    zero_face: int = 1
    spread_drift: bool = False
    ac_roll_arcmin: float = 1.0  # stated bound of the autocollimator's roll ρ (budget)
    ac_alignment: str = "levelled"  # the frame the horizontal readings are corrected in
    ac_roll_measured_arcmin: float | None = None  # measured roll ρ, corrected (None: not measured)
    u_ac_roll_arcmin: float = 0.0  # its standard uncertainty
    closure_rows: set[int] = field(default_factory=set)  # 0-based sheet rows
    warnings: list[str] = field(default_factory=list)
    # with n readings per point (setting readings per point): RepeatedReadings, and each
    # set's s/√n per position (sets, faces) of its encoder and autocollimator readings
    repeats: object = None
    repeat_s_mean_arcsec: np.ndarray | None = None
    incomplete: object = None  # the last unit in progress (models.readings.incomplete), left out
    # the reference polygon's face deviations as the readings give them (the first set's
    # polygon-deviation column, faces 1…n, taken from face 1); None when a face is not read
    reference_deviations_arcsec: np.ndarray | None = None
    # the rounding of the horizontal readings as typed (models.polygon.rounding; None: the
    # readings were averaged first, n a face)
    rounding: HorizontalRounding | None = None
    # the σ of a reading stated in the settings (″; 0: not stated)
    reading_noise_stated_arcsec: float = 0.0
    # the 0-based sheet row of each point of the per-set arrays (set after set, positions
    # 1…n in each): the JSON lists them in input-row order by it (None: not known)
    point_rows: np.ndarray | None = None
    # the tilt bound these readings were analysed with (the setting, ″), for the analysis'
    # JSON only; a certificate's budget takes the bound from the settings it is issued with
    # (tests/models/certificate/test_settings_reach_the_certificate.py)
    tilt_bound_analysed_arcsec: float = DEFAULT_TILT_BOUND_ARCSEC

    @property
    def mean_reversal_arcsec(self) -> float | None:
        """The mean of ē↑ − ē↓ over the positions (error sense: −B̄ of ISO 230-2, whose
        deviation is reference − indicated)."""
        return None if self.reversal_arcsec is None else float(np.mean(self.reversal_arcsec))

    @property
    def roll_corrected(self) -> bool:
        """Whether a measured roll ρ was corrected (else its bound is only in the budget)."""
        return self.ac_roll_measured_arcmin is not None


def direction_means(values: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray | None]:
    """Mean over the sets of each direction (rows of ``values``): the bidirectional mean
    and the reversal mean(forward) − mean(reverse) in the values' own sense (None unless
    both directions were run)."""
    fwd, rev = values[directions > 0], values[directions < 0]
    if fwd.size and rev.size:
        up, down = fwd.mean(axis=0), rev.mean(axis=0)
        return 0.5 * (up + down), up - down
    return values.mean(axis=0), None


def sets_alike(values: np.ndarray, directions: np.ndarray) -> bool:
    """Whether every direction measured more than once read alike at every face in all its
    sets (the same errors, bit for bit): readings shown coarser than they scatter (an
    encoder's display of 0.001° with the autocollimator nulled, a reviewer), or copied."""
    repeated = [values[directions == d] for d in (1, -1)
                if np.count_nonzero(directions == d) >= 2]
    return bool(repeated) and all(np.all(np.ptp(g, axis=0) == 0.0) for g in repeated)


def vertical_fits_noise(sets: list[PolygonSetResult], faces: int
                        ) -> tuple[float, int, bool] | None:
    """The autocollimator's reading noise from the vertical readings' tilt fits, with its
    degrees of freedom and whether it was taken between the sets; None without a fit that
    has readings left over its unknowns. With two fits or more over every face, the sets'
    residuals face by face about the face's mean over the sets: a face's own pyramidal
    error is in its vertical reading the same in every set (the polygon re-seated or not:
    the tilt is fitted set by set), and only the noise differs. About the fits alone, those
    errors were taken for noise: an audit's polygon with faces' pyramidal errors of 2″ and
    a reading noise of 0.03″, one set each way, got U 18 times too large and a decided half
    range of 0 … 0."""
    fits = [s.tilt for s in sets if s.tilt is not None]
    residuals = [t.residuals_arcsec for t in fits]
    between = len(fits) >= 2 and all(r.shape == (faces,) for r in residuals)
    complete = all(np.all(np.isfinite(r)) for r in residuals)
    if between and complete:
        stacked = np.array(residuals)
        dof = (faces - TILT_FIT_UNKNOWNS) * (len(fits) - 1)
        scatter = float(np.sum((stacked - stacked.mean(axis=0)) ** 2))
    elif between:
        # a face with no vertical reading in some set (its tilt fitted from the others):
        # between the sets over the faces every set read, when they leave degrees of freedom
        common = np.all(np.isfinite(np.array(residuals)), axis=0)
        between = int(np.count_nonzero(common)) > TILT_FIT_UNKNOWNS
        stacked = np.array(residuals)[:, common]
        dof = (int(np.count_nonzero(common)) - TILT_FIT_UNKNOWNS) * (len(fits) - 1)
        scatter = float(np.sum((stacked - stacked.mean(axis=0)) ** 2))
    if not between and complete:
        dof = (faces - TILT_FIT_UNKNOWNS) * len(residuals)  # a fitted tilt has n ≥ 4
        scatter = sum(float(np.sum(r**2)) for r in residuals)
    elif not between:
        # about each fit, over the faces it was fitted to (4 or more)
        dof = sum(int(np.count_nonzero(np.isfinite(r))) - TILT_FIT_UNKNOWNS for r in residuals)
        scatter = sum(float(np.nansum(r**2)) for r in residuals)
    if dof <= 0 or not math.sqrt(scatter / dof) > ARITHMETIC_NOISE_ARCSEC:
        return None  # no scatter beyond the arithmetic's: nothing to tell the noise from
    return float(np.sqrt(scatter / dof)), dof, between


def pooled_repeatability(values: np.ndarray, directions: np.ndarray) -> tuple[np.ndarray, int] | None:
    """Standard deviation per position pooled over the sets of each direction, about that
    direction's mean, with its degrees of freedom; None when no direction was repeated, or
    when the repeated sets read alike at every face (:func:`sets_alike`: their scatter
    cannot be told, and a repeatability of 0 took the noise out of U)."""
    squares = np.zeros(values.shape[1])
    dof = 0
    for d in (1, -1):
        group = values[directions == d]
        if group.shape[0] >= 2:
            squares += np.sum((group - group.mean(axis=0)) ** 2, axis=0)
            dof += group.shape[0] - 1
    if dof == 0 or sets_alike(values, directions):
        return None
    return np.sqrt(squares / dof), dof


def _direction_fit(group: np.ndarray, index: np.ndarray | None
                   ) -> tuple[float, int, np.ndarray]:
    """Least squares of one direction's sets (rows of ``group``, positions in columns): one
    value per position (the curve), one zero offset per set and, with ``index`` (each
    position's reading index in its set, per set), one steady drift per set along its own
    reading order. (residual sum of squares, residual degrees of freedom, residuals)."""
    m, n = group.shape
    if m * n * (n + 2 * m) > DENSE_DIRECTION_FIT_ELEMENTS:
        return _direction_fit_by_sets(group, index)
    columns = [np.kron(np.ones((m, 1)), np.eye(n)), np.kron(np.eye(m), np.ones((n, 1)))]
    if index is not None:
        centred = index - index.mean(axis=1, keepdims=True)
        columns.append(np.kron(np.eye(m), np.ones((n, 1))) * centred.reshape(-1, 1))
    design = np.hstack(columns)
    y = group.reshape(-1)
    coef, *_ = np.linalg.lstsq(design, y, rcond=None)
    residuals = y - design @ coef
    dof = int(y.size - np.linalg.matrix_rank(design))
    return float(np.sum(residuals**2)), dof, residuals.reshape(m, n)


#: the largest design (elements) :func:`_direction_fit` solves whole; a larger one (some 55
#: sets of 24 faces and more: its size grows as m², its solution as m³) is solved set by set
#: (:func:`_direction_fit_by_sets`, the same least squares: contract review 75 F11)
DENSE_DIRECTION_FIT_ELEMENTS = 200_000


def _direction_fit_by_sets(group: np.ndarray, index: np.ndarray | None
                           ) -> tuple[float, int, np.ndarray]:
    """:func:`_direction_fit` with each set's own unknowns (its offset, its drift) eliminated
    first: the set's values projected off its own columns (1 and its centred reading index,
    orthogonal), the curve from the n × n normal equations Σ P_s·curve = Σ P_s·y_s (any of
    their solutions leaves the same residuals), the rank of the design as the sets' own
    columns' plus that matrix's. Time and memory linear in the sets."""
    y = np.asarray(group, dtype=float)
    m, n = y.shape
    if index is not None:
        centred = np.asarray(index, dtype=float)
        centred = centred - centred.mean(axis=1, keepdims=True)
        norms = np.sum(centred**2, axis=1)
        unit = np.divide(centred, np.sqrt(norms)[:, None], out=np.zeros_like(centred),
                         where=norms[:, None] > 0)
    else:
        unit = np.zeros((m, n))
        norms = np.zeros(m)

    def projected(values: np.ndarray) -> np.ndarray:
        values = values - values.mean(axis=1, keepdims=True)
        return values - unit * np.sum(unit * values, axis=1, keepdims=True)

    normal = m * (np.eye(n) - np.full((n, n), 1.0 / n)) - unit.T @ unit
    curve, *_ = np.linalg.lstsq(normal, projected(y).sum(axis=0), rcond=None)
    residuals = projected(y - curve)
    rank = m + int(np.count_nonzero(norms > 0)) + int(np.linalg.matrix_rank(normal))
    return float(np.sum(residuals**2)), int(y.size - rank), residuals


def within_set_noise(values: np.ndarray, directions: np.ndarray,
                     reading_index: np.ndarray | None = None) -> tuple[float, int] | None:
    """σ of one error and its degrees of freedom from the sets of each direction measured
    twice or more, once each set's own zero offset and (``reading_index``: each position's
    reading index in its set, sets × positions) its own steady drift along its reading order
    are taken out, face by face about the direction's curve; None without a repeated
    direction or with no degrees of freedom left.

    An autocollimator whose zero moves between sets (a jump, a drift carried on) shifts a
    whole set: one unknown value per set, a systematic of the set, not the noise of a
    reading. About the direction's mean alone (:func:`pooled_repeatability`) the offsets
    were taken for noise: an audit's 24 faces, 2 sets each way, σ 0.1″ and the zero moved by
    1″ between sets, gave a noise of 1.3″, and the decided half range, that much noise's
    range excess taken off, came out 0.35″ low (interval 31/40 at 95.45 %, a failing item
    "pass" in 17/40). Here they cannot inflate it: a direction's m sets over n faces leave
    (m − 1)(n − 1) degrees of freedom, (m − 1)(n − 2) with the drifts."""
    values = np.asarray(values, dtype=float)
    directions = np.asarray(directions)
    squares, dof = 0.0, 0
    for d in (1, -1):
        rows = np.nonzero(directions == d)[0]
        if rows.size < 2:
            continue
        index = None if reading_index is None else np.asarray(reading_index, float)[rows]
        ss, df, _ = _direction_fit(values[rows], index)
        squares += ss
        dof += df
    if dof <= 0 or sets_alike(values, directions):
        return None
    return math.sqrt(squares / dof), dof


def set_offsets_spread(values: np.ndarray, directions: np.ndarray,
                       carried: np.ndarray | None = None,
                       carried_covariance: np.ndarray | None = None,
                       floor: float = 0.0, noise_share: float = 0.0
                       ) -> tuple[float, int] | None:
    """The standard deviation of one set's zero offset, from the scatter of the means over
    the positions of the sets of each direction measured twice or more, pooled, with its
    degrees of freedom (Σ (m_d − 1)); None without a repeated direction. ``carried``: each
    set's offset a steady drift carried from set to set explains (taken out first: it is
    an input of its own). That is an estimate, and its own error puts the sets apart as
    well: its share of the scatter, trace(P·C) for its covariance ``carried_covariance``
    (sets × sets) and P the centring within each direction, is taken out (counted in the
    carried drift's input, not here again). The scatter also holds the means' reading noise
    σ²/n: not taken out (a few per cent, on the safe side); ``floor`` (σ/√n; 0: none) is the
    least it is taken as once the estimate's share is out, so that offsets merely hidden in
    that noise never read 0. ``noise_share``: the variance one set's mean has from its
    readings' noise (σ²/n), taken out of the scatter instead (positive part: the offsets
    beyond the noise the repeatability's input already holds; 0: kept in). Between the
    directions the offsets cannot be told from the mean reversal."""
    values = np.asarray(values, dtype=float)
    directions = np.asarray(directions)
    means = values.mean(axis=1)
    if carried is not None:
        means = means - np.asarray(carried, dtype=float)
    squares, dof = 0.0, 0
    blocks = []
    for d in (1, -1):
        rows = np.nonzero(directions == d)[0]
        if rows.size >= 2:
            group = means[rows]
            squares += float(np.sum((group - group.mean()) ** 2))
            dof += rows.size - 1
            blocks.append(rows)
    if dof == 0:
        return None
    if carried_covariance is not None:
        # trace(P·C), P = I − 1/m_d within each direction's block: the block's trace less its
        # sum over m_d (no sets × sets product: 4000 sets took 13 s, contract review 75 F11)
        covariance = np.asarray(carried_covariance, dtype=float)
        for rows in blocks:
            block = covariance[np.ix_(rows, rows)]
            squares -= float(np.trace(block)) - float(np.sum(block)) / rows.size
    return math.sqrt(max(squares / dof - noise_share, floor**2, 0.0)), dof


#: the standard normal quantile of how unlikely the sets' offsets must be under the reading
#: noise alone to be named (1 − 0.999)
ZERO_OFFSETS_Z = 3.090


def zero_offsets_warning(values: np.ndarray, directions: np.ndarray,
                         reading_index: np.ndarray | None = None) -> str:
    """The warning that the autocollimator's zero moved between the sets ("" when the sets'
    means within each direction scatter no more than the reading noise gives them, σ²/n: ν s²
    /(σ²/n) below the chi-square's 99.9 % quantile for ν = Σ (m_d − 1), by Wilson–Hilferty,
    no scipy for a plain analysis; or when no direction was measured twice)."""
    values = np.asarray(values, dtype=float)
    within = within_set_noise(values, directions, reading_index)
    spread = set_offsets_spread(values, directions)
    if within is None or spread is None or not within[0] > 0:
        return ""
    n = values.shape[1]
    expected = within[0] / math.sqrt(n)
    nu = spread[1]
    quantile = nu * (1.0 - 2.0 / (9.0 * nu) + ZERO_OFFSETS_Z * math.sqrt(2.0 / (9.0 * nu))) ** 3
    if nu * (spread[0] / expected) ** 2 <= quantile:
        return ""
    return message(QT_TR_NOOP(
        "The autocollimator's zero moved between the sets: the sets' mean errors within a "
        "direction scatter by {spread} where the readings' noise gives {expected}. Each set's "
        "offset is taken as one unknown value of that set (in U, the same at every position), "
        "not as reading noise; check that the autocollimator was not touched between sets."),
        spread=f"{spread[0]:.2f}\"", expected=f"{expected:.2f}\"")


#: a reading noise at or below this (″) is the arithmetic's, not the readings': the errors
#: are made of angles up to 360° (1.3e6″) converted and differenced in doubles (1.3e6 ×
#: 2.2e-16 ≈ 3e-10″), and no display reads finer than 1e-4″. Readings that differ by no
#: more show no scatter at all: nothing to tell the noise from, never a noise of 0 (gui80:
#: noise-free captured readings of two sets gave "reading noise 9.76e-17″" into U)
ARITHMETIC_NOISE_ARCSEC = 1e-7


def reversal_pair_noise(values: np.ndarray, directions: np.ndarray) -> tuple[float, int] | None:
    """σ of one error from one forward and one reverse set, with its degrees of freedom:
    the encoder's own reading noise and the horizontal reading's together, which is what an
    error holds (the vertical readings hold neither). Face by face the two sets differ by the
    reversal and by the noise of two readings of each instrument, so the differences
    d_i = e↑_i − e↓_i about their mean over the faces (the mean reversal removed) scatter
    with 2σ²: σ² = Σ(d_i − d̄)²/(2(n − 1)), n − 1 degrees of freedom. A reversal that
    changes from face to face is counted as noise (on the safe side). None unless there is
    exactly one set each way, or when the differences are all equal (nothing to tell)."""
    fwd, rev = values[directions > 0], values[directions < 0]
    if fwd.shape[0] != 1 or rev.shape[0] != 1 or values.shape[1] < 2:
        return None
    d = fwd[0] - rev[0]
    dof = d.size - 1
    scatter = float(np.sum((d - d.mean()) ** 2))
    if not math.sqrt(scatter / (2.0 * dof)) > ARITHMETIC_NOISE_ARCSEC:
        return None
    return math.sqrt(scatter / (2.0 * dof)), dof


def split_sets(parsed: ParsedReadings) -> list[tuple[int, np.ndarray, int | None]]:
    """(set id, row indices in approach order, closure row index or None) per set.

    A set's closure is its last row when that row repeats the set's first face.
    """
    set_ids = np.nan_to_num(parsed["set"], nan=1.0).astype(int)
    out = []
    for set_id in dict.fromkeys(set_ids.tolist()):
        rows = np.nonzero(set_ids == set_id)[0]
        positions = parsed["position"][rows]
        closure = None
        if rows.size > 1 and positions[-1] == positions[0]:
            closure = int(rows[-1])
            rows = rows[:-1]
        out.append((set_id, rows, closure))
    return out
