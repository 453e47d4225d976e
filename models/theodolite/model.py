"""Theodolite run: limited-rotation axis measured with an autocollimating theodolite.

Seed 000 (Tian et al., Acta Photonica Sinica 46(11) 1112005, 2017). Frame O-XYZ
of the theodolite, OZ plumb down, OX the azimuth zero. Axis under test
``P = [-sinψ cosα, -sinψ sinα, cosψ]``, mirror normal at the reference pose
``n = [cosβ, 0, -sinβ]``. Rotating ``n`` about ``P`` by θ (right-handed
Rodrigues formula; the seed's eq (1) prints the (1,3) element with the wrong
sign, eqs (2)–(4) use the standard one) gives ``n'``; the theodolite reads
``A = atan2(y', x')`` and ``E = asin(z')``. The set-up induced error is
``ζ(θ) = A(θ) − θ``.

Identification from the elevations: ``z'(θ) = a + b cosθ + c sinθ`` exactly,
so ``sin E`` is linear in (1, cosθ, sinθ). Linear least squares gives a, b, c
without a starting guess; (ψ, α, β) follow in closed form (two roots, one near
ψ = 90°); the admissible one is polished by nonlinear least squares on E.

Angles are in degrees at the interface, errors in arcseconds.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from models.damped_least_squares import polish
from models.lazy_optimize import least_squares
from models.messages import QT_TR_NOOP, joined, message
from models.parameters import SettingsError
from models.readings.angles import ARCSEC_PER_RAD
from models.uncertainty.error_stats import ErrorStats, error_stats
from models.uncertainty.iso230 import Iso230Result, iso230_evaluate
from models.uncertainty.tilt_direction import NOT_DETERMINED, direction_determined

#: the budget's name of the set-up model's error (the run's budget and the passes' means)
MODEL_INPUT = QT_TR_NOOP("Set-up model ζ (ψ, α, β)")
#: the budget's name of a tilt the elevations do not identify: not removed, its bound's effect
TILT_BOUND_INPUT = QT_TR_NOOP("Axis tilt, not identified (bound)")
#: both set-up inputs: what the JSON's model error carries, and not the raw error
SETUP_INPUTS = (MODEL_INPUT, TILT_BOUND_INPUT)

#: the largest axis tilt the budget assumes when the elevations do not identify it (the
#: setting tilt_bound_arcsec's default, ″; the polygon workbench's figure)
DEFAULT_TILT_BOUND_ARCSEC = 300.0
#: the elevation fit's unknowns (ψ, α, β)
ELEVATION_FIT_UNKNOWNS = 3

__all__ = [
    "Identification",
    "SetupParameters",
    "TheodoliteResult",
    "analyze_run",
    "check_corrected",
    "check_fit",
    "elevation_coefficients",
    "forward_readings",
    "identify_from_azimuth",
    "identify_from_elevations",
    "induced_error_arcsec",
    "tilt_bound_effect_arcsec",
    "tilt_half_range_change",
    "tilt_not_identified",
    "model_error_modes",
    "rotated_normal",
    "setups_from_coefficients",
    "simulate_readings",
]

D2R = math.pi / 180.0



@dataclass(frozen=True)
class SetupParameters:
    """Set-up misalignment: axis tilt ψ, tilt direction α, mirror normal β (degrees).

    (ψ, α) and (−ψ, α + 180°) describe the same axis; :meth:`canonical` gives
    ψ ≥ 0 and α in [0°, 360°).
    """

    psi_deg: float
    alpha_deg: float
    beta_deg: float

    def canonical(self) -> SetupParameters:
        psi, alpha = self.psi_deg, self.alpha_deg
        if psi < 0:
            psi, alpha = -psi, alpha + 180.0
        return SetupParameters(float(psi), float(alpha % 360.0), float(self.beta_deg))

    def as_array(self) -> np.ndarray:
        return np.array([self.psi_deg, self.alpha_deg, self.beta_deg])



def _zenith_hint(elevation_deg: np.ndarray) -> str:
    """What to say after an elevation fit's refusal when every elevation is 45° … 135°:
    such readings are a vertical circle's zenith angles V (≈ 90° towards a mirror near the
    horizontal), read as elevations (contract75 F13: a ``zenith_deg`` or ``V`` column, taken
    by its place, was refused without a word of --zenith); "" otherwise."""
    finite = elevation_deg[np.isfinite(elevation_deg)]
    if finite.size == 0 or not np.all((finite > 45.0) & (finite < 135.0)):
        return ""
    return message(QT_TR_NOOP(
        "; the vertical readings are all near 90°, as zenith angles V are: if the vertical "
        "circle reads V, set the vertical reading to zenith (--zenith; E = V − 90°)"))

def _cos_sin_deg(angle_deg) -> tuple:
    """cos and sin of angles in degrees by ``math.cos`` and ``math.sin`` (the C library's): a
    float each for a scalar, as a single set-up has always had them, else arrays of the
    angles' shape, each element the same as its scalar's (numpy's own are not promised to
    agree with them in the last bit)."""
    if np.ndim(angle_deg) == 0:
        rad = angle_deg * D2R
        return math.cos(rad), math.sin(rad)
    rad = np.asarray(angle_deg, dtype=float) * D2R
    flat = rad.ravel().tolist()
    return (np.fromiter(map(math.cos, flat), float, len(flat)).reshape(rad.shape),
            np.fromiter(map(math.sin, flat), float, len(flat)).reshape(rad.shape))


def _vectors(components: tuple, shape: tuple[int, ...]) -> np.ndarray:
    """Three components (floats or arrays broadcasting to ``shape``) as vectors, shape + (3,),
    each vector's three in a row."""
    vectors = np.empty(shape + (3,))
    for k, component in enumerate(components):
        vectors[..., k] = component
    return vectors


def rotated_normal(theta_deg, psi_deg: float | np.ndarray, alpha_deg: float | np.ndarray,
                   beta_deg: float | np.ndarray) -> np.ndarray:
    """Mirror normal after rotating the axis by θ, (x', y', z') on the first axis.

    θ is a row of N angles. ψ, α and β broadcast against one another to a shape S, ``()``
    when all three are scalars: the result is (3,) + S + (N,), θ on the last axis, so scalars
    give (3, N) and an α of shape (m,) gives (3, m, N). Each set-up's curve is bit for bit
    the one its own scalar (ψ, α, β) gives.
    """
    th = np.asarray(theta_deg, dtype=float) * D2R
    (cos_psi, sin_psi), (cos_alpha, sin_alpha), (cos_beta, sin_beta) = (
        _cos_sin_deg(psi_deg), _cos_sin_deg(alpha_deg), _cos_sin_deg(beta_deg))
    p = (-sin_psi * cos_alpha, -sin_psi * sin_alpha, cos_psi)
    n = (cos_beta, 0.0, -sin_beta)
    # P × n, the products and differences numpy's cross takes
    cross = (p[1] * n[2] - p[2] * n[1], p[2] * n[0] - p[0] * n[2], p[0] * n[1] - p[1] * n[0])
    shape = np.broadcast(*p, *n).shape
    p_vectors, n_vectors = _vectors(p, shape), _vectors(n, shape)
    # P · n of each set-up as a 1×3 by 3×1 product: one BLAS dot each, the call a single
    # set-up's ``P @ n`` always made (the sum written out differs from the BLAS dot in the
    # last bit for about a quarter of random set-ups: 0.8.21's copy in
    # tilt_half_range_change wrote it out and so differed from this in a few results)
    dot = np.matmul(p_vectors[..., None, :], n_vectors[..., :, None])[..., 0, 0]
    # the components first and θ last, (3,) + S + (1,), in that order in memory (numpy's
    # loops then run along θ)
    first = (len(shape),) + tuple(range(len(shape)))
    n_rows, cross_rows, along_rows = (
        np.ascontiguousarray(v.transpose(first))[..., None]
        for v in (n_vectors, _vectors(cross, shape), p_vectors * dot[..., None]))
    c, s = np.cos(th), np.sin(th)
    # n cos θ + (P × n) sin θ + P (P · n)(1 − cos θ), summed in that order in place
    normal = n_rows * c
    normal += cross_rows * s
    normal += along_rows * (1.0 - c)
    return normal


def forward_readings(theta_deg, psi_deg: float, alpha_deg: float, beta_deg: float):
    """Theodolite azimuth A and elevation E (degrees) at axis angles θ (eqs 2–6).

    A is unwrapped to lie within ±180° of θ.
    """
    theta = np.asarray(theta_deg, dtype=float)
    x, y, z = rotated_normal(theta, psi_deg, alpha_deg, beta_deg)
    azimuth = np.degrees(np.arctan2(y, x))
    azimuth = theta + (azimuth - theta + 180.0) % 360.0 - 180.0
    elevation = np.degrees(np.arcsin(np.clip(z, -1.0, 1.0)))
    return azimuth, elevation


def induced_error_arcsec(theta_deg, psi_deg: float | np.ndarray, alpha_deg: float | np.ndarray,
                         beta_deg: float | np.ndarray) -> np.ndarray:
    """Set-up induced error ζ(θ) = A(θ) − θ in arcsec (eq 7): S + (N,), ψ, α and β broadcast
    to S and θ (N angles) on the last axis as in :func:`rotated_normal`; scalars give (N,)."""
    theta = np.asarray(theta_deg, dtype=float)
    x, y, _ = rotated_normal(theta, psi_deg, alpha_deg, beta_deg)
    th = theta * D2R
    # atan2 of the normal rotated back by θ: A − θ without cancellation
    diff = np.arctan2(y * np.cos(th) - x * np.sin(th), x * np.cos(th) + y * np.sin(th))
    return diff * ARCSEC_PER_RAD


def elevation_coefficients(psi_deg: float, alpha_deg: float, beta_deg: float):
    """(a, b, c) with z'(θ) = a + b cosθ + c sinθ = sin E(θ)."""
    psi, alpha, beta = psi_deg * D2R, alpha_deg * D2R, beta_deg * D2R
    a = -math.cos(psi) * math.sin(psi) * math.cos(alpha) * math.cos(beta) - math.cos(
        psi
    ) ** 2 * math.sin(beta)
    b = -math.sin(beta) - a
    c = math.sin(psi) * math.sin(alpha) * math.cos(beta)
    return a, b, c


def setups_from_coefficients(a: float, b: float, c: float) -> list[SetupParameters]:
    """Every set-up (ψ ≥ 0, |ψ| < 90°) whose elevation curve has coefficients (a, b, c).

    sinβ = −(a + b); sinψ sinα = c / cosβ; with u = cos²ψ the remaining
    equation becomes u² + u(2a sinβ − (1 − q²)cos²β) + a² = 0. Each admissible
    root u gives one set-up. With noisy coefficients whose roots turn complex,
    the double root (the closest real solution) is returned.
    """
    sin_beta = float(np.clip(-(a + b), -1.0, 1.0))
    beta = math.asin(sin_beta)
    cos_beta = math.cos(beta)
    if cos_beta < 1e-12:
        return []
    q = float(np.clip(c / cos_beta, -1.0, 1.0))
    lin = 2.0 * a * sin_beta - (1.0 - q * q) * cos_beta**2
    disc = lin * lin - 4.0 * a * a
    if disc < 0:
        roots = [-lin / 2.0]
    else:
        r = math.sqrt(disc)
        roots = [(-lin + r) / 2.0, (-lin - r) / 2.0]
    out: list[SetupParameters] = []
    for u in roots:
        if not 0.0 < u <= 1.0 + 1e-12:
            continue
        u = min(u, 1.0)
        cpsi = math.sqrt(u)
        s = -(a + u * sin_beta) / (cpsi * cos_beta)  # sinψ cosα
        spsi = math.hypot(s, q)
        psi = math.atan2(spsi, cpsi)
        alpha = math.atan2(q, s) if spsi > 0 else 0.0
        out.append(SetupParameters(math.degrees(psi), math.degrees(alpha), math.degrees(beta)))
    return [p.canonical() for p in out]


def _elevation_model(params_rad: np.ndarray, theta_rad: np.ndarray,
                     cos_sin: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """The elevations (rad) of the set-up ``params_rad`` (ψ, α, β) at ``theta_rad``;
    ``cos_sin``: cos θ and sin θ when the caller has them (a fit calls this for one θ a
    dozen times: the same values)."""
    psi, alpha, beta = params_rad
    cp, sp, ca, sa, cb, sb = (
        math.cos(psi), math.sin(psi), math.cos(alpha), math.sin(alpha),
        math.cos(beta), math.sin(beta),
    )
    ct, st = (np.cos(theta_rad), np.sin(theta_rad)) if cos_sin is None else cos_sin
    a = -cp * sp * ca * cb - cp * cp * sb
    z = a + (-sb - a) * ct + sp * sa * cb * st
    return np.arcsin(np.clip(z, -1.0, 1.0))


def _elevation_jacobian(params_rad: np.ndarray, theta_rad: np.ndarray,
                        cos_sin: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """d(elevation)/d(ψ, α, β) at ``theta_rad`` (``cos_sin`` as :func:`_elevation_model`)."""
    psi, alpha, beta = params_rad
    cp, sp, ca, sa, cb, sb = (
        math.cos(psi), math.sin(psi), math.cos(alpha), math.sin(alpha),
        math.cos(beta), math.sin(beta),
    )
    da = np.array([
        -math.cos(2 * psi) * ca * cb + math.sin(2 * psi) * sb,
        cp * sp * sa * cb,
        cp * sp * ca * sb - cp * cp * cb,
    ])
    db = -da + np.array([0.0, 0.0, -cb])
    dc = np.array([cp * sa * cb, sp * ca * cb, -sp * sa * sb])
    ct, st = (np.cos(theta_rad), np.sin(theta_rad)) if cos_sin is None else cos_sin
    a = -cp * sp * ca * cb - cp * cp * sb
    z = a + (-sb - a) * ct + sp * sa * cb * st
    cos_e = np.sqrt(np.clip(1.0 - z * z, 1e-300, None))
    dz = da[None, :] + ct[:, None] * db[None, :] + st[:, None] * dc[None, :]
    return dz / cos_e[:, None]


@dataclass
class Identification:
    """Identified set-up with its standard uncertainties and fit quality.

    ``covariance_deg2`` is the 3×3 covariance of (ψ, α, β) in deg².
    ``residuals_arcsec`` are observed minus fitted values of the fitted
    quantity (elevation, or azimuth error for that route).
    """

    setup: SetupParameters
    covariance_deg2: np.ndarray
    residuals_arcsec: np.ndarray
    r_squared: float
    residual_rms_arcsec: float
    method: str
    candidates: list[SetupParameters] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    # why the readings do not identify the tilt ("" when they do): ψ = 0 is then no finding,
    # nothing is removed, and a tilt up to ``tilt_bound_arcsec`` enters the uncertainty
    tilt_not_identified: str = ""
    tilt_bound_arcsec: float = 0.0
    # a reading's σ when the readings show no scatter to evaluate it (the accuracy setting)
    reading_noise_arcsec: float = 0.0

    @property
    def tilt_identified(self) -> bool:
        return not self.tilt_not_identified

    @property
    def uncertainty_deg(self) -> np.ndarray:
        return np.sqrt(np.clip(np.diag(self.covariance_deg2), 0.0, None))

    @property
    def alpha_determined(self) -> bool:
        """Whether the tilt direction α is determined: the tilt identified and ψ told from 0
        by its u (models.uncertainty.tilt_direction)."""
        return self.tilt_identified and direction_determined(
            self.setup.psi_deg, float(self.uncertainty_deg[0]))

    @property
    def correlation(self) -> np.ndarray:
        u = self.uncertainty_deg
        with np.errstate(invalid="ignore", divide="ignore"):
            return self.covariance_deg2 / np.outer(u, u)


PARAMETER_NAMES = ("ψ", "α", "β")


def _covariance(jac_rad: np.ndarray, residuals_rad: np.ndarray) -> np.ndarray:
    n, p = jac_rad.shape
    dof = max(n - p, 1)
    sigma2 = float(residuals_rad @ residuals_rad) / dof
    try:
        cov = np.linalg.pinv(jac_rad.T @ jac_rad) * sigma2
    except np.linalg.LinAlgError:
        cov = np.full((p, p), np.inf)
    return cov * (180.0 / math.pi) ** 2


def _r_squared(observed: np.ndarray, residuals: np.ndarray) -> float:
    ss_tot = float(np.sum((observed - observed.mean()) ** 2))
    ss_res = float(residuals @ residuals)
    return 1.0 - ss_res / ss_tot if ss_tot > 0 else float("nan")


def _within(p: SetupParameters, psi_max_deg: float, beta_max_deg: float) -> bool:
    return p.psi_deg <= psi_max_deg + 1e-9 and abs(p.beta_deg) <= beta_max_deg + 1e-9


def tilt_not_identified(theta_deg, elevation_deg) -> str:
    """Why the elevations cannot identify the axis tilt, naming it ("" when they can).

    A tilt ψ of the axis moves the elevation as the mirror turns (sin E = a + b cos θ +
    c sin θ, b and c of order ψ): elevations that are all equal carry no tilt to fit, and a
    fit through them shows no scatter, so they cannot say how noisy they are either (its
    u would be 0); two distinct values are too few for the fit's three unknowns (ψ, α, β);
    no more distinct θ than unknowns leaves no degrees of freedom.
    """
    theta = np.asarray(theta_deg, dtype=float)
    elev = np.asarray(elevation_deg, dtype=float)
    points = _distinct(np.round(theta, 6)).size
    if points <= ELEVATION_FIT_UNKNOWNS:
        return message(QT_TR_NOOP(
            "{n} distinct θ give the elevation fit's 3 unknowns (ψ, α, β) no degrees of freedom: "
            "it would pass through every reading whatever its noise. The axis tilt and its "
            "direction are not identified and the set-up's error not removed; the tilt bound "
            "enters the uncertainty."), n=points)
    values = _distinct(np.round(elev, 9))
    if values.size == 1:
        return message(QT_TR_NOOP(
            "every elevation is {value}°: no variation, while a tilt of the axis moves it as the "
            "mirror turns. The axis tilt and its direction are not identified (ψ = 0 is not a "
            "finding, nor is a perfect fit) and the set-up's error not removed; the tilt bound "
            "enters the uncertainty. Check that the elevations were read, not copied."),
            value=f"{values[0]:g}")
    if values.size < ELEVATION_FIT_UNKNOWNS:
        return message(QT_TR_NOOP(
            "the elevations take only {n} distinct values ({values}°): too few for the fit's 3 "
            "unknowns (ψ, α, β), a tilt within their resolution. The axis tilt and its direction "
            "are not identified and the set-up's error not removed; the tilt bound enters the "
            "uncertainty. Read the elevations to a finer digit to identify it."),
            n=values.size, values=", ".join(f"{v:g}" for v in values))
    return ""


def tilt_bound_effect_arcsec(rotation_deg, beta_deg: float, bound_arcsec: float) -> np.ndarray:
    """The largest |ζ(θ)| a tilt of ``bound_arcsec`` gives at each rotation from the reference
    (where ζ = 0), over every tilt direction α (1° steps) and the tilt up to the bound (the
    effect is first order in ψ tan β, second in ψ², so its largest is at the bound)."""
    rotation = np.asarray(rotation_deg, dtype=float)
    worst = np.zeros(rotation.shape)
    if not bound_arcsec > 0:
        return worst
    for psi in (0.5 * bound_arcsec, bound_arcsec):
        if rotation.ndim == 1:  # a row of rotations (the analysis'): every α at once, (α, θ),
            # each α's curve bit for bit its own scalar's (:func:`rotated_normal`) and the
            # largest the same in any order (one call instead of 360, ~16 → 0.7 ms a run)
            zeta = induced_error_arcsec(rotation, psi / 3600.0, np.arange(360.0), beta_deg)
            worst = np.maximum(worst, np.max(np.abs(zeta), axis=0))
            continue
        for alpha in np.arange(360.0):
            worst = np.maximum(worst, np.abs(induced_error_arcsec(
                rotation, psi / 3600.0, float(alpha), beta_deg)))
    return worst


def tilt_half_range_change(rotation_deg, beta_deg: float, bound_arcsec: float) -> float:
    """The largest change (″) a tilt up to ``bound_arcsec`` not identified and not removed
    can make to the half range of the errors at these rotations from the reference: the
    largest half peak-to-peak of its effect ζ(θ) over every tilt direction α and magnitude
    up to the bound (half the range is half a seminorm: |h(f + ζ) − h(f)| ≤ h(ζ) for any
    curve f, reached for some). α on a 1° grid at eight magnitudes, the best refined to
    0.01°; ζ is smooth in α, so what the grid misses is of order (0.005°)² of it. β is
    known from elevations that a tilt moves by up to 2ψ over a turn (copied, or read to a
    coarse digit, they may be any of them): ζ, first order in ψ tan β, is taken at β and at
    β ± twice the bound, the largest."""
    rotation = np.asarray(rotation_deg, dtype=float)
    if not bound_arcsec > 0 or rotation.size < 2:
        return 0.0

    return max(_tilt_half_range_at(rotation, beta_deg + k * 2.0 * bound_arcsec / 3600.0,
                                   bound_arcsec) for k in (-1, 0, 1))


def _tilt_half_range_at(rotation_deg: np.ndarray, beta_deg: float, bound_arcsec: float) -> float:
    """:func:`tilt_half_range_change` at one β."""

    def half_ranges(psi_arcsec: float, alpha_deg: np.ndarray) -> np.ndarray:
        # every α at once: ζ is (α, θ)
        zeta = induced_error_arcsec(rotation_deg, psi_arcsec / 3600.0, alpha_deg, beta_deg)
        return 0.5 * np.ptp(zeta, axis=-1)

    best, best_psi, best_alpha = 0.0, bound_arcsec, 0.0
    for psi in bound_arcsec * np.arange(1, 9) / 8.0:
        h = half_ranges(float(psi), np.arange(360.0))
        if float(h.max()) > best:
            best, best_psi, best_alpha = float(h.max()), float(psi), float(np.argmax(h))
    best = max(best, float(half_ranges(best_psi, best_alpha + np.arange(-100, 101) / 100.0).max()))
    return best


def _unidentified(theta_rel_deg: np.ndarray, elevation_deg: np.ndarray, reference_index: int,
                  reason: str, bound_arcsec: float, accuracy_arcsec: float | None
                  ) -> Identification:
    """The set-up when the elevations do not identify the tilt: ψ = 0 (nothing removed, not a
    finding), β from the reference reading (E₀ = −β whatever the tilt), no fit statistics.
    Readings without variation show no noise either: the accuracy setting is a reading's σ,
    and without it the run is refused (ValueError) rather than its noise taken as 0."""
    if not (accuracy_arcsec and accuracy_arcsec > 0):
        raise ValueError(message(QT_TR_NOOP(
            "{why} Nor do these elevations show the readings' noise: state the theodolite "
            "accuracy (1σ) to evaluate the run"), why=reason))
    if not bound_arcsec > 0:
        # 0 would claim an axis with no tilt at all, which no set-up achieves and these
        # elevations cannot show: the run's error would then be taken as the axis' own
        # (audit 73 finding 1: a true 120″ tilt, covered 14/40, 3 false passes)
        # the refusal and what to do first, then why (day 74 finding 10: it began with the
        # warning's own "… the tilt bound enters the uncertainty")
        raise SettingsError(message(QT_TR_NOOP(
            "A tilt bound of 0\" is refused: state the largest axis tilt ψ the set-up can have "
            "(the setting \"largest axis tilt ψ, when not identified\", --tilt-bound-arcsec), "
            "or read elevations that identify the tilt. 0 would claim that the axis has no "
            "tilt at all, which no set-up achieves and these elevations cannot show: {why}"),
            why=reason), key="tilt_bound_arcsec")
    beta = -float(elevation_deg[reference_index])
    residuals = (np.asarray(elevation_deg, dtype=float) + beta) * 3600.0
    return Identification(
        setup=SetupParameters(0.0, 0.0, beta),
        covariance_deg2=np.zeros((3, 3)),
        residuals_arcsec=residuals,
        r_squared=float("nan"),
        residual_rms_arcsec=float(np.sqrt(np.mean(residuals ** 2))),
        method="elevation",
        warnings=[reason],
        tilt_not_identified=reason,
        tilt_bound_arcsec=float(bound_arcsec),
        reading_noise_arcsec=float(accuracy_arcsec),
    )


def identify_from_elevations(
    theta_deg,
    elevation_deg,
    psi_max_deg: float = 45.0,
    beta_max_deg: float = 45.0,
) -> Identification:
    """Identify (ψ, α, β) from the elevation readings, with no starting guess.

    Parameters
    ----------
    theta_deg, elevation_deg : array
        Axis angle relative to the reference pose and theodolite elevation
        (degrees, OZ down), at least 3 points.
    psi_max_deg, beta_max_deg : float
        Admissible bounds: the root with |ψ| near 90° is rejected by them.

    Raises
    ------
    ValueError
        If there are fewer than 4 points or no admissible set-up exists.
    """
    return _identification(_elevation_fit(theta_deg, elevation_deg, psi_max_deg, beta_max_deg))


@dataclass(frozen=True)
class _ElevationFit:
    """The set-up fitted to the elevations (:func:`_elevation_fit`), before its covariance,
    residuals and warnings are worked out (:func:`_identification`)."""

    setup: SetupParameters
    theta_rad: np.ndarray
    cos_sin: tuple[np.ndarray, np.ndarray]
    elevation_rad: np.ndarray
    candidates: list[SetupParameters]


def _elevation_fit(theta_deg, elevation_deg, psi_max_deg: float = 45.0,
                   beta_max_deg: float = 45.0) -> _ElevationFit:
    """The set-up of :func:`identify_from_elevations` (its refusals the same), without the
    identification's covariance and warnings: the run's iteration on the true rotation
    (:func:`analyze_run`) needs only the set-up of each step but the last."""
    theta = np.asarray(theta_deg, dtype=float)
    elev = np.asarray(elevation_deg, dtype=float)
    if theta.size < 4:
        raise ValueError(message(
            QT_TR_NOOP("at least 4 readings are needed to identify ψ, α, β")))
    th = theta * D2R
    e_rad = elev * D2R
    cos_sin = (np.cos(th), np.sin(th))
    design = np.column_stack([np.ones_like(th), *cos_sin])
    (a, b, c), *_ = np.linalg.lstsq(design, np.sin(e_rad), rcond=None)
    candidates = setups_from_coefficients(a, b, c)
    starts = [p for p in candidates if _within(p, psi_max_deg, beta_max_deg)]
    if not starts:
        starts = candidates[-1:] if candidates else []
    if not starts:
        raise ValueError(joined((message(
            QT_TR_NOOP("the elevations fit no set-up (sin E is not of the form a + b cos θ + c sin θ "
                       "with |a|, |b|, |c| ≤ 1): check the elevation column")), _zenith_hint(elev))))

    best = None
    for start in starts:
        fit = polish(lambda x: _elevation_model(x, th, cos_sin) - e_rad,
                     lambda x: _elevation_jacobian(x, th, cos_sin), np.radians(start.as_array()))
        if not fit.converged:  # MINPACK's LM from the same start (imports scipy.optimize)
            fit = least_squares(
                lambda x: _elevation_model(x, th, cos_sin) - e_rad,
                np.radians(start.as_array()),
                jac=lambda x: _elevation_jacobian(x, th, cos_sin),
                method="lm",
                xtol=1e-15,
                ftol=1e-15,
                gtol=1e-15,
            )
        polished = SetupParameters(*np.degrees(fit.x)).canonical()
        cost = float(fit.fun @ fit.fun)
        if not _within(polished, psi_max_deg, beta_max_deg):
            continue
        if best is None or cost < best[0] * (1 - 1e-9) - 1e-30:
            best = (cost, polished, fit)
    if best is None:
        raise ValueError(joined((
            message(
            QT_TR_NOOP("no set-up with ψ ≤ {psi_max_deg}° and |β| ≤ {beta_max_deg}° fits the elevations"),
            psi_max_deg=f"{psi_max_deg:g}", beta_max_deg=f"{beta_max_deg:g}"),
            _zenith_hint(elev))))
    return _ElevationFit(best[1], th, cos_sin, e_rad, candidates)


def _identification(fitted: _ElevationFit) -> Identification:
    """The identification of a set-up fitted to the elevations: its covariance, residuals,
    fit quality and warnings."""
    setup, th, e_rad = fitted.setup, fitted.theta_rad, fitted.elevation_rad
    jac = _elevation_jacobian(np.radians(setup.as_array()), th, fitted.cos_sin)
    residuals = _elevation_model(np.radians(setup.as_array()), th, fitted.cos_sin) - e_rad
    cov = _covariance(jac, residuals)
    ident = Identification(
        setup=setup,
        covariance_deg2=cov,
        residuals_arcsec=-residuals * ARCSEC_PER_RAD,
        r_squared=_r_squared(e_rad, residuals),
        residual_rms_arcsec=float(np.sqrt(np.mean(residuals**2))) * ARCSEC_PER_RAD,
        method="elevation",
        candidates=fitted.candidates,
    )
    ident.warnings.extend(_separation_warnings(ident))
    return ident


def _azimuth_residuals(x_rad: np.ndarray, theta_deg: np.ndarray, zeta_arcsec: np.ndarray):
    psi, alpha, beta = np.degrees(x_rad)
    return (induced_error_arcsec(theta_deg, psi, alpha, beta) - zeta_arcsec) / ARCSEC_PER_RAD


def identify_from_azimuth(
    theta_deg,
    raw_error_arcsec,
    psi_max_deg: float = 45.0,
    beta_max_deg: float = 45.0,
    start: SetupParameters | None = None,
) -> Identification:
    """Identify (ψ, α, β) from the azimuth errors ζ'_i = A_i − θ_i (the seed's second route).

    This route absorbs any part of the axis' own error that looks like the
    model (a scale error, say); the result carries that warning. Without a
    ``start`` a coarse grid over (ψ, α, β) seeds the nonlinear fit.
    """
    theta = np.asarray(theta_deg, dtype=float)
    zeta = np.asarray(raw_error_arcsec, dtype=float)
    if theta.size < 4:
        raise ValueError(message(
            QT_TR_NOOP("at least 4 readings are needed to identify ψ, α, β")))
    grid_starts: list[np.ndarray] = []
    if start is not None:
        grid_starts.append(np.radians(start.as_array()))
    psis = np.linspace(0.5, min(psi_max_deg, 15.0), 6)
    for psi in psis:
        for alpha in np.arange(0.0, 360.0, 30.0):
            for beta in (-5.0, 0.0, 5.0):
                grid_starts.append(np.radians([psi, alpha, beta]))
    costs = [float(np.sum(_azimuth_residuals(x, theta, zeta) ** 2)) for x in grid_starts]
    order = np.argsort(costs)[:8]
    best = None
    for idx in order:
        fit = least_squares(_azimuth_residuals, grid_starts[idx], args=(theta, zeta), method="lm",
                            x_scale=np.array([0.05, 1.0, 0.05]))
        polished = SetupParameters(*np.degrees(fit.x)).canonical()
        if not _within(polished, psi_max_deg, beta_max_deg):
            continue
        cost = float(fit.fun @ fit.fun)
        if best is None or cost < best[0]:
            best = (cost, polished, fit)
    if best is None:
        raise ValueError(message(
            QT_TR_NOOP("no admissible set-up fits the azimuth errors")))
    _, setup, fit = best
    residuals = fit.fun
    cov = _covariance(fit.jac, residuals)
    ident = Identification(
        setup=setup,
        covariance_deg2=cov,
        residuals_arcsec=-residuals * ARCSEC_PER_RAD,
        r_squared=_r_squared(zeta / ARCSEC_PER_RAD, residuals),
        residual_rms_arcsec=float(np.sqrt(np.mean(residuals**2))) * ARCSEC_PER_RAD,
        method="azimuth",
    )
    ident.warnings.append(message(QT_TR_NOOP(
        "Identified from the azimuth errors: any part of the axis' own error that looks like "
        "the set-up model (a scale error, say) is absorbed and removed from the result.")))
    ident.warnings.extend(_separation_warnings(ident))
    return ident


def _separation_warnings(ident: Identification, limit: float = 0.999) -> list[str]:
    corr = ident.correlation
    out: list[str] = []
    for i in range(3):
        for j in range(i + 1, 3):
            r = corr[i, j]
            if np.isfinite(r) and abs(r) > limit:
                out.append(message(
                    QT_TR_NOOP("{first} and {second} cannot be separated on this range "
                               "(correlation {r}); widen the range of θ."),
                    first=PARAMETER_NAMES[i], second=PARAMETER_NAMES[j], r=f"{r:+.4f}")
                )
    if not np.all(np.isfinite(ident.uncertainty_deg)):
        out.append(message(QT_TR_NOOP("Some parameters are not determined by these readings "
                                      "(singular fit).")))
    return out


@dataclass
class TheodoliteResult:
    """Everything the workbench, the CLI and the certificate show (arrays over used rows).

    Errors are errors of indication, indicated − reference: the raw error is
    (θ − θ₀) − (A − A₀), the negative of the seed's ζ' = A − θ (which is the
    correction); ``model_error_arcsec`` = −ζ(θ) is the set-up's share of it.
    """

    theta_deg: np.ndarray
    raw_error_arcsec: np.ndarray
    model_error_arcsec: np.ndarray
    model_uncertainty_arcsec: np.ndarray
    corrected_error_arcsec: np.ndarray
    identification: Identification
    elevation_residuals_arcsec: np.ndarray
    raw_stats: ErrorStats
    corrected_stats: ErrorStats
    reference_theta_deg: float
    reference_index: int = 0  # the row where the theodolite was zeroed (its error is 0)
    iso230: Iso230Result | None = None
    warnings: list[str] = field(default_factory=list)
    runs: np.ndarray | None = None  # per used row, when the readings name their runs
    directions: np.ndarray | None = None  # ±1 per used row, when stated
    repeats: object = None  # RepeatedReadings when each point is the mean of n readings
    incomplete: object = None  # the last unit in progress (models.readings.incomplete), left out


def model_error_modes(rotation_deg: np.ndarray, ident: Identification) -> np.ndarray:
    """The set-up model's error at each rotation as modes, (n, 3) arcsec: the error of ζ(θ)
    from the parameters' errors is modes @ z, z ~ N(0, I₃) (first order: ζ's gradient in
    ψ, α, β times a square root of their covariance). Its rows' norms are ζ's standard
    uncertainty; the modes keep how it is correlated from θ to θ (one set of parameters for
    the whole run). A tilt not identified: its bound's effect, rectangular (÷ √3), as one
    mode, the same unknown tilt at every θ."""
    if not ident.tilt_identified:
        modes = np.zeros((np.size(rotation_deg), 3))
        modes[:, 0] = tilt_bound_effect_arcsec(rotation_deg, ident.setup.beta_deg,
                                               ident.tilt_bound_arcsec) / math.sqrt(3.0)
        return modes
    p = ident.setup.as_array()
    steps = np.array([1e-6, 1e-5, 1e-6])
    grads = []
    for k in range(3):
        hi, lo = p.copy(), p.copy()
        hi[k] += steps[k]
        lo[k] -= steps[k]
        grads.append((induced_error_arcsec(rotation_deg, *hi)
                      - induced_error_arcsec(rotation_deg, *lo)) / (2 * steps[k]))
    g = np.array(grads).T  # (n, 3) in arcsec/deg
    cov = np.where(np.isfinite(ident.covariance_deg2), ident.covariance_deg2, 0.0)
    values, vectors = np.linalg.eigh(0.5 * (cov + cov.T))
    return g @ (vectors * np.sqrt(np.clip(values, 0.0, None)))


def _model_uncertainty(theta_deg: np.ndarray, ident: Identification) -> np.ndarray:
    """Standard uncertainty of ζ(θ) from the parameters' covariance (first order)."""
    return np.sqrt(np.sum(model_error_modes(theta_deg, ident) ** 2, axis=1))


_TRUE_ROTATION_MAX_ITERATIONS = 8


def _row_of(index: int, row_numbers) -> int:
    """The sheet row of reading ``index`` (1-based), for messages."""
    return int(row_numbers[index]) if row_numbers is not None else index + 1


def true_rotation_deg(azimuth_deg, setup: SetupParameters, iterations: int = 4) -> np.ndarray:
    """Axis rotation that makes the theodolite read ``azimuth_deg``: solves A(t) = A_i.

    Fixed-point iteration t ← A_i − ζ(t); |dζ/dθ| is of order ψ², so it
    converges to 1e-12" in a few steps for any admissible set-up.
    """
    az = np.asarray(azimuth_deg, dtype=float)
    rotation = az.copy()
    for _ in range(iterations):
        rotation = az - induced_error_arcsec(rotation, *setup.as_array()) / 3600.0
    return rotation


def _distinct(values: np.ndarray) -> np.ndarray:
    """The distinct values among finite ``values``, sorted: ``np.unique(values)`` without its
    check for a masked array, which imports numpy.ma (a tenth of the command line's start-up,
    tests/benchmarks/test_cli_startup.py)."""
    ordered = np.sort(np.ravel(values))
    return ordered[np.concatenate(([True], ordered[1:] != ordered[:-1]))] if ordered.size else ordered


def check_run(theta_deg, azimuth_deg, elevation_deg, reference_index: int | None = None,
              row_numbers=None) -> None:
    """Refuse readings that cannot identify a set-up, before any fit (ValueError, one line).

    Angles must be finite and physically possible (|E| ≤ 90°, |θ| and |A| within two
    turns); at least 4 distinct θ; the design (1, cos θ, sin θ) well conditioned.
    """
    theta = np.asarray(theta_deg, dtype=float)
    for name, values, limit in (("theta_deg", theta, 720.0), ("azimuth_deg", azimuth_deg, 720.0),
                                ("elevation_deg", elevation_deg, 90.0)):
        values = np.asarray(values, dtype=float)
        bad = np.nonzero(~np.isfinite(values) | (np.abs(values) > limit))[0]
        if bad.size:
            i = int(bad[0])
            raise ValueError(joined((message(
                QT_TR_NOOP("row {value}, column '{name}': {values}° is beyond ±{limit}° and cannot "
                           "be a reading of this test"),
                value=_row_of(i, row_numbers), name=name, values=f"{values[i]:g}", limit=f"{limit:g}"),
                _zenith_hint(values) if name == "elevation_deg" else "")))
    distinct = _distinct(np.round(theta, 6))
    if distinct.size == 1:
        raise ValueError(message(
            QT_TR_NOOP("all θ are equal ({theta}°): the set-up cannot be identified; the axis must turn "
                       "between readings"),
            theta=f"{theta[0]:g}"))
    if distinct.size < 4:
        raise ValueError(message(
            QT_TR_NOOP("{size} distinct θ; at least 4 are needed to identify ψ, α, β"),
            size=distinct.size))
    th = np.radians(distinct)
    design = np.column_stack([np.ones_like(th), np.cos(th), np.sin(th)])
    singular = np.linalg.svd(design / np.linalg.norm(design, axis=0), compute_uv=False)
    if not singular[-1] > 1e-8:
        raise ValueError(message(
            QT_TR_NOOP("θ spans only {ptp}°: too little rotation to identify the set-up"),
            ptp=f"{np.ptp(distinct):.3g}"))


# The identification gates the result. The fitted quantity's residuals are the reading
# noise when the set-up model holds (RMS ≈ the theodolite's accuracy σ; an axis' wobble
# adds a few σ, hence the warning at 3σ). Refused: an RMS beyond ``RESIDUAL_REFUSED`` σ
# whatever the R² (no reading error of the instrument makes that), and an RMS beyond
# ``RESIDUAL_UNEXPLAINED`` σ when the model explains less than ``MIN_R_SQUARED`` of the
# readings' variation (a small set-up leaves the elevations flat: a low R² with residuals
# at σ is noise, not a failure). σ = 0 turns the check off, as it does the warning.
RESIDUAL_WARNED = 3.0
#: the warning of a residual RMS beyond RESIDUAL_WARNED times the accuracy setting (a
#: certificate judges it again on its stated standards' u: models.theodolite.accuracy_check)
RESIDUAL_ABOVE_ACCURACY = QT_TR_NOOP("Residual RMS {rms} is more than three times the "
                                     "theodolite accuracy {accuracy}: check the readings and "
                                     "the set-up.")
RESIDUAL_REFUSED = 100.0
RESIDUAL_UNEXPLAINED = 10.0
MIN_R_SQUARED = 0.99
# A corrected error (the axis' own error of indication) beyond this is not an axis' error
# but θ and A of one row that disagree: a typed or shifted cell, another unit.
MAX_AXIS_ERROR_ARCSEC = 3600.0


def check_fit(ident: Identification, accuracy_arcsec: float | None, row_numbers=None) -> None:
    """Refuse an identification whose fit the set-up model does not explain (ValueError,
    one line with the figures and the row of the largest residual)."""
    if not accuracy_arcsec:
        return
    rms, r2 = ident.residual_rms_arcsec, ident.r_squared
    ratio = rms / accuracy_arcsec
    unexplained = not (r2 >= MIN_R_SQUARED)  # a NaN R² (flat readings) is not an explanation
    if not (ratio > RESIDUAL_REFUSED or (ratio > RESIDUAL_UNEXPLAINED and unexplained)):
        return
    worst = int(np.argmax(np.abs(ident.residuals_arcsec)))
    # the column as the sheet heads it, not its key (rev62 F14: "elevation_deg" in a message)
    column = "E / V [°]" if ident.method == "elevation" else "A [°]"
    raise ValueError(message(
        QT_TR_NOOP("no set-up explains the {column} readings: residual RMS {rms} is {ratio}× the "
                   "theodolite accuracy {accuracy} (refused beyond {far}×, or beyond {near}× with "
                   "R² below {min_r2}), R² = {r2}; the largest residual, {largest}, is at row "
                   "{row}: check that row's readings, the columns and the accuracy setting"),
        column=column, rms=f"{rms:.3g}\"", ratio=f"{ratio:.0f}",
        accuracy=f"{accuracy_arcsec:g}\"", far=f"{RESIDUAL_REFUSED:g}",
        near=f"{RESIDUAL_UNEXPLAINED:g}", min_r2=f"{MIN_R_SQUARED:g}", r2=f"{r2:.4f}",
        largest=f"{ident.residuals_arcsec[worst]:+.4g}\"", row=_row_of(worst, row_numbers)))


def check_corrected(corrected_arcsec, theta_deg, azimuth_deg, reference_index: int,
                    row_numbers=None) -> None:
    """Refuse a corrected error no axis has (beyond ±MAX_AXIS_ERROR_ARCSEC), naming the row
    (ValueError, one line)."""
    corrected = np.asarray(corrected_arcsec, dtype=float)
    worst = int(np.argmax(np.abs(corrected)))
    if not abs(corrected[worst]) > MAX_AXIS_ERROR_ARCSEC:
        return
    bad = int(np.count_nonzero(np.abs(corrected) > MAX_AXIS_ERROR_ARCSEC))
    if bad > corrected.size // 2:  # every row off by as much: the zero row is the odd one
        zero = int(reference_index)
        raise ValueError(message(
            QT_TR_NOOP("row {row}, where the theodolite was zeroed (θ = {theta}°, A = {azimuth}°), "
                       "disagrees with {bad} of the other {n} rows by more than ±{limit}: check "
                       "columns 'theta_deg' and 'azimuth_deg' of that row, or the reference row"),
            row=_row_of(zero, row_numbers), theta=f"{theta_deg[zero]:.6g}",
            azimuth=f"{azimuth_deg[zero]:.6g}", bad=bad, n=corrected.size - 1,
            limit=f"{MAX_AXIS_ERROR_ARCSEC:g}\""))
    raise ValueError(message(
        QT_TR_NOOP("row {row}: θ = {theta}° and A = {azimuth}° disagree by {error} after the "
                   "set-up's share is removed ({bad} of {n} rows beyond ±{limit}; the zero is at "
                   "row {zero}): no axis errs by that much: check columns 'theta_deg' and "
                   "'azimuth_deg' of that row"),
        row=_row_of(worst, row_numbers), theta=f"{theta_deg[worst]:.6g}",
        azimuth=f"{azimuth_deg[worst]:.6g}", error=f"{corrected[worst]:+.0f}\"", bad=bad,
        n=corrected.size, limit=f"{MAX_AXIS_ERROR_ARCSEC:g}\"",
        zero=_row_of(int(reference_index), row_numbers)))


def analyze_run(
    theta_deg,
    azimuth_deg,
    elevation_deg,
    reference_index: int | None = None,
    method: str = "elevation",
    psi_max_deg: float = 45.0,
    beta_max_deg: float = 45.0,
    accuracy_arcsec: float | None = None,
    directions=None,
    row_numbers=None,
    tilt_bound_arcsec: float = DEFAULT_TILT_BOUND_ARCSEC,
) -> TheodoliteResult:
    """Analyse one theodolite run.

    Parameters
    ----------
    theta_deg, azimuth_deg, elevation_deg : array
        Indicated axis angle, theodolite azimuth and elevation (degrees).
    reference_index : int, optional
        Row where the theodolite was zeroed on the mirror; θ and A are taken
        relative to it. Default: the row with θ closest to 0.
    method : {"elevation", "azimuth"}
        Identification route.
    accuracy_arcsec : float, optional
        Theodolite accuracy (1σ); residuals far above it raise a warning.
    directions : array of ±1, optional
        Approach direction per row; with repeated θ gives the ISO 230-2 figures.
    row_numbers : array of int, optional
        The sheet row of each reading, for the messages of a refusal (default 1, 2, …).
    tilt_bound_arcsec : float
        The largest axis tilt (″) when the elevations do not identify it
        (:func:`tilt_not_identified`): nothing is removed and its effect enters the
        uncertainty.

    Raises
    ------
    ValueError
        Readings that identify no set-up, a fit the set-up model does not explain
        (:func:`check_fit`), or a corrected error no axis has (:func:`check_corrected`).
    """
    theta = np.asarray(theta_deg, dtype=float)
    az = np.asarray(azimuth_deg, dtype=float)
    elev = np.asarray(elevation_deg, dtype=float)
    check_run(theta, az, elev, row_numbers=row_numbers)
    if reference_index is None:
        reference_index = int(np.argmin(np.abs(theta)))
    if not 0 <= reference_index < theta.size:
        raise ValueError(message(
            QT_TR_NOOP("reference row {value} is outside the {size} readings"),
            value=reference_index + 1, size=theta.size))
    theta_rel = theta - theta[reference_index]
    az_rel = az - az[reference_index]
    raw = (az_rel - theta_rel + 180.0) % 360.0 - 180.0
    raw_arcsec = raw * 3600.0
    unidentified = tilt_not_identified(theta_rel, elev) if method == "elevation" else ""
    if unidentified:
        ident = _unidentified(theta_rel, elev, reference_index, unidentified, tilt_bound_arcsec,
                              accuracy_arcsec)
        rotation = az_rel  # ψ = 0: the azimuth is the rotation
        elev_res = ident.residuals_arcsec
    elif method == "elevation":
        # The elevations were read where the axis truly was, θ_true = θ + e, not at the
        # indicated θ; fitting them against θ lets the axis' own error leak into the
        # set-up. Iterate: identify, recover θ_true from the azimuths, identify again.
        # (each step's set-up only; the identification, its covariance and warnings, of the
        # last: a fifth of a run's analysis was spent on those of the steps before it)
        rotation = theta_rel
        for _ in range(_TRUE_ROTATION_MAX_ITERATIONS):
            fitted = _elevation_fit(rotation, elev, psi_max_deg, beta_max_deg)
            previous, rotation = rotation, true_rotation_deg(az_rel, fitted.setup)
            if np.max(np.abs(rotation - previous)) < 1e-10:  # deg, i.e. 4e-7"
                break
        ident = _identification(fitted)
        elev_res = ident.residuals_arcsec
    elif method == "azimuth":
        start = None
        try:
            start = identify_from_elevations(theta_rel, elev, psi_max_deg, beta_max_deg).setup
        except ValueError:
            start = None
        ident = identify_from_azimuth(theta_rel, raw_arcsec, psi_max_deg, beta_max_deg, start)
        rotation = true_rotation_deg(az_rel, ident.setup)
        _, e_model = forward_readings(rotation, *ident.setup.as_array())
        elev_res = (elev - e_model) * 3600.0
    else:
        raise ValueError(message(
            QT_TR_NOOP("unknown identification method '{method}'"),
            method=method))
    if not unidentified:
        check_fit(ident, accuracy_arcsec, row_numbers)
    # a tilt not identified: nothing removed (not ψ = 0's ζ, zero but for rounding)
    zeta = (np.zeros(rotation.shape) if unidentified
            else induced_error_arcsec(rotation, *ident.setup.as_array()))
    # The seed's ζ' = A − θ is reference − indicated (a correction); the error of indication
    # is its negative, and the set-up's share of it is −ζ.
    raw_error = -raw_arcsec
    model = -zeta
    corrected = raw_error - model
    check_corrected(corrected, theta, az, reference_index, row_numbers)
    warnings = list(ident.warnings)
    if ident.tilt_identified and not ident.alpha_determined:
        warnings.append(message(NOT_DETERMINED, tilt=f"ψ = {ident.setup.psi_deg * 3600.0:.2f}\"",
                                u=f"{ident.uncertainty_deg[0] * 3600.0:.2f}\"", direction="α"))
    if (accuracy_arcsec and not unidentified
            and ident.residual_rms_arcsec > RESIDUAL_WARNED * accuracy_arcsec):
        warnings.append(message(
            RESIDUAL_ABOVE_ACCURACY,
            rms=f"{ident.residual_rms_arcsec:.2f}\"", accuracy=f"{accuracy_arcsec:g}\""))
    iso = None
    if directions is not None or _distinct(np.round(theta, 6)).size < theta.size:
        iso = iso230_evaluate(theta, corrected, directions)
    return TheodoliteResult(
        theta_deg=theta,
        raw_error_arcsec=raw_error,
        model_error_arcsec=model,
        model_uncertainty_arcsec=_model_uncertainty(rotation, ident),
        corrected_error_arcsec=corrected,
        identification=ident,
        elevation_residuals_arcsec=elev_res,
        raw_stats=error_stats(raw_error),
        corrected_stats=error_stats(corrected),
        reference_theta_deg=float(theta[reference_index]),
        reference_index=int(reference_index),
        iso230=iso,
        warnings=warnings,
    )


def simulate_readings(
    theta_deg,
    setup: SetupParameters,
    true_error_arcsec=None,
    noise_arcsec: float = 0.0,
    rng: np.random.Generator | None = None,
):
    """Readings (A, E in degrees) of a run with the given set-up.

    The axis indicates θ_i with the error of indication e_i (``true_error_arcsec``,
    indicated − true): it truly turns θ_i − e_i. The theodolite sees that true
    rotation, plus Gaussian reading noise.
    """
    theta = np.asarray(theta_deg, dtype=float)
    true_rot = theta - (0.0 if true_error_arcsec is None else np.asarray(true_error_arcsec) / 3600)
    az, el = forward_readings(true_rot, *setup.as_array())
    if noise_arcsec:
        rng = rng or np.random.default_rng()
        az = az + rng.normal(0.0, noise_arcsec, theta.shape) / 3600.0
        el = el + rng.normal(0.0, noise_arcsec, theta.shape) / 3600.0
    return az, el
