"""Polygon encoder test: encoder error per face, closure, pyramidal error.

Seed 001 (Tian et al., Acta Optica Sinica 35(5) 0512003, 2015). An n-face
polygon sits on the encoder shaft; an autocollimator looks at face i after the
encoder has turned by (i − 1)·360°/n.

* Error per position (eq 1): ``e_i = (a_i − a_1) − (b_i − b_1) − (c_i − c_1)``
  with ``b_i = (i − 1)·360°/n + dev_i`` (dev from the polygon's certificate).
* Closure ``H = |c'_1 − c_1|``.
* Pyramidal error: the encoder axis ``[sinψ cosω, sinψ sinω, cosψ]`` is tilted
  by ψ towards ω in the polygon frame. Face normal ``[cosθ, sinθ, 0]`` rotated
  about it by −θ (eqs 3–5) gives the autocollimator readings
  ``ε_x = atan(y'/x')`` (horizontal, the induced error) and
  ``ε_y = atan(z'/x')`` (vertical) (eqs 6–7).

Angles in degrees, errors and tilts in arcseconds unless the name says otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from models.angles import ARCSEC_PER_RAD
from models.error_stats import ErrorStats
from models.lazy_optimize import least_squares

__all__ = [
    "GRADE_ACCURACY_ARCSEC",
    "SHORT_FORM_COEFFICIENT",
    "HarmonicAnalysis",
    "TiltFit",
    "allowed_tilt_arcsec",
    "face_errors_arcsec",
    "fit_tilt",
    "harmonic_analysis",
    "pyramidal_readings_arcsec",
    "pyramidal_x_short_arcsec",
    "pyramidal_y_short_arcsec",
]

#: Table 1 of the seed: accuracy (±") of encoder grades 1–7.
GRADE_ACCURACY_ARCSEC = {1: 0.25, 2: 0.5, 3: 1.0, 4: 2.0, 5: 5.0, 6: 10.0, 7: 30.0}

#: Largest ε_x/ψ² over θ and ω (at ω = 90°, θ ≈ 111°), in 1/arcsec.
SHORT_FORM_COEFFICIENT = 0.5337e-5



def allowed_tilt_arcsec(grade: int) -> float:
    """Largest pyramidal tilt ψ (") keeping the induced error under a third of the accuracy.

    ``ψ_max = sqrt((tol/3)/0.5337e-5)``: 125, 177, 250, 353, 559, 790, 1369" for
    grades 1–7. (The seed prints 140" for grade 1, which its formula does not give.)
    """
    tol = GRADE_ACCURACY_ARCSEC[int(grade)]
    return math.sqrt((tol / 3.0) / SHORT_FORM_COEFFICIENT)


def face_errors_arcsec(encoder_deg, polygon_dev_arcsec, ac_x_arcsec, faces: int) -> np.ndarray:
    """Encoder error at each position (eq 1), arcsec; position i = index + 1.

    The encoder difference is taken modulo 360° so a reading that wraps past
    360° still compares with its nominal angle.
    """
    a = np.asarray(encoder_deg, dtype=float)
    dev = np.asarray(polygon_dev_arcsec, dtype=float)
    c = np.asarray(ac_x_arcsec, dtype=float)
    nominal = np.arange(a.size) * 360.0 / faces
    da = (a - a[0]) - nominal
    da = (da + 180.0) % 360.0 - 180.0
    return da * 3600.0 - (dev - dev[0]) - (c - c[0])


def pyramidal_readings_arcsec(theta_deg, psi_arcsec: float, omega_deg: float):
    """Exact autocollimator readings (ε_x, ε_y) in arcsec at face angles θ (eqs 3–7)."""
    th = np.radians(np.asarray(theta_deg, dtype=float))
    psi = psi_arcsec / ARCSEC_PER_RAD
    om = math.radians(omega_deg)
    axis = np.array([math.sin(psi) * math.cos(om), math.sin(psi) * math.sin(om), math.cos(psi)])
    normal = np.array([np.cos(th), np.sin(th), np.zeros_like(th)])
    phi = -th
    cos_p, sin_p = np.cos(phi), np.sin(phi)
    cross = np.cross(axis[:, None], normal, axis=0)
    dot = axis @ normal
    rotated = normal * cos_p + cross * sin_p + axis[:, None] * dot * (1.0 - cos_p)
    x, y, z = rotated
    return np.arctan(y / x) * ARCSEC_PER_RAD, np.arctan(z / x) * ARCSEC_PER_RAD


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


@dataclass
class TiltFit:
    """Pyramidal tilt identified from the vertical readings.

    ``offset_arcsec`` is the vertical zero of the autocollimator; uncertainties
    are standard (k = 1) from the fit's Jacobian.
    """

    psi_arcsec: float
    omega_deg: float
    offset_arcsec: float
    u_psi_arcsec: float
    u_omega_deg: float
    residuals_arcsec: np.ndarray
    residual_rms_arcsec: float


def fit_tilt(theta_deg, ac_y_arcsec) -> TiltFit:
    """Identify ψ, ω from vertical readings: linear fit on (1, cosθ − 1, sinθ), exact polish."""
    theta = np.asarray(theta_deg, dtype=float)
    v = np.asarray(ac_y_arcsec, dtype=float)
    if theta.size < 4:
        raise ValueError("at least 4 vertical readings are needed to identify the tilt")
    th = np.radians(theta)
    design = np.column_stack([np.ones_like(th), np.cos(th) - 1.0, np.sin(th)])
    (k, p, q), *_ = np.linalg.lstsq(design, v, rcond=None)
    start = np.array([k, math.hypot(p, q), math.degrees(math.atan2(q, p))])

    def residuals(x):
        return x[0] + pyramidal_readings_arcsec(theta, x[1], x[2])[1] - v

    fit = least_squares(residuals, start, method="lm", x_scale=np.array([1.0, 1.0, 1.0]))
    k, psi, omega = fit.x
    if psi < 0:
        psi, omega = -psi, omega + 180.0
        fit.jac[:, 1] *= -1
    dof = max(theta.size - 3, 1)
    sigma2 = float(fit.fun @ fit.fun) / dof
    cov = np.linalg.pinv(fit.jac.T @ fit.jac) * sigma2
    u = np.sqrt(np.clip(np.diag(cov), 0, None))
    return TiltFit(float(psi), float(omega % 360.0), float(k), float(u[1]), float(u[2]),
                   -fit.fun, float(np.sqrt(np.mean(fit.fun**2))))


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


@dataclass
class PolygonSetResult:
    """One set (a turn round the polygon) of readings, arcsec over positions 1…n."""

    theta_deg: np.ndarray
    error_arcsec: np.ndarray
    closure_arcsec: float | None
    closure_ok: bool | None
    tilt: TiltFit | None
    pyramidal_error_arcsec: np.ndarray
    corrected_error_arcsec: np.ndarray
    direction: int = 1
    warnings: list[str] = field(default_factory=list)


def analyze_set(encoder_deg, polygon_dev_arcsec, ac_x_arcsec, ac_y_arcsec, faces: int,
                closure_ac_x_arcsec: float | None, closure_limit_arcsec: float,
                direction: int = 1) -> PolygonSetResult:
    """Error, closure and pyramidal correction of one set of n readings."""
    theta = np.arange(len(encoder_deg)) * 360.0 / faces
    error = face_errors_arcsec(encoder_deg, polygon_dev_arcsec, ac_x_arcsec, faces)
    warnings: list[str] = []
    closure = ok = None
    if closure_ac_x_arcsec is not None:
        closure = abs(closure_ac_x_arcsec - float(np.asarray(ac_x_arcsec)[0]))
        ok = closure <= closure_limit_arcsec
        if not ok:
            warnings.append(f"Closure {closure:.2f}\" exceeds the limit {closure_limit_arcsec:g}\": "
                            "this set is invalid; repeat the measurement.")
    else:
        warnings.append("No closure reading (the row back on position 1): closure not checked.")
    ac_y = np.asarray(ac_y_arcsec, dtype=float)
    tilt = None
    pyramidal = np.zeros_like(error)
    if np.all(np.isfinite(ac_y)) and ac_y.size >= 4:
        tilt = fit_tilt(theta, ac_y)
        eps_x, _ = pyramidal_readings_arcsec(theta, tilt.psi_arcsec, tilt.omega_deg)
        pyramidal = eps_x - eps_x[0]
    elif ac_y.size:
        warnings.append("Vertical readings missing: pyramidal error not identified or removed.")
    return PolygonSetResult(theta, error, closure, ok, tilt, pyramidal, error + pyramidal,
                            direction, warnings)


@dataclass
class PolygonResult:
    """A whole polygon test (one or several sets)."""

    sets: list[PolygonSetResult]
    faces: int
    grade: int
    theta_deg: np.ndarray
    mean_error_arcsec: np.ndarray
    mean_corrected_arcsec: np.ndarray
    repeatability_arcsec: np.ndarray | None
    reversal_arcsec: np.ndarray | None
    stats: ErrorStats
    raw_stats: ErrorStats
    harmonics: HarmonicAnalysis
    allowed_tilt_arcsec: float
    accuracy_ok: bool
    tilt_verdict: str
    valid: bool
    closure_rows: set[int] = field(default_factory=set)  # 0-based sheet rows
    warnings: list[str] = field(default_factory=list)


@dataclass
class SimulatedPolygonSet:
    """Readings of one simulated set: encoder (deg), certificate deviations and AC readings (")."""

    encoder_deg: np.ndarray
    polygon_dev_arcsec: np.ndarray
    ac_x_arcsec: np.ndarray
    ac_y_arcsec: np.ndarray
    closure_ac_x_arcsec: float


def simulate_set(faces: int, encoder_error_arcsec, psi_arcsec: float = 0.0, omega_deg: float = 0.0,
                 polygon_dev_arcsec=None, noise_arcsec: float = 0.0,
                 rng: np.random.Generator | None = None, closure_drift_arcsec: float = 0.0,
                 positioning_arcsec: float = 20.0) -> SimulatedPolygonSet:
    """Readings of a polygon test whose encoder error is ``encoder_error_arcsec`` (n values).

    The shaft stops near each face (± ``positioning_arcsec``); the encoder reads
    the true rotation plus its error; the autocollimator sees the face's
    offset, the pyramidal ε_x and ε_y, fixed zero offsets and noise.
    """
    rng = rng or np.random.default_rng()
    n = faces
    nominal = np.arange(n) * 360.0 / n
    dev = np.zeros(n) if polygon_dev_arcsec is None else np.asarray(polygon_dev_arcsec, float)
    stop = rng.uniform(-positioning_arcsec, positioning_arcsec, n)  # shaft rotation − nominal
    f = np.asarray(encoder_error_arcsec, dtype=float)
    eps_x, eps_y = pyramidal_readings_arcsec(nominal, psi_arcsec, omega_deg)
    encoder = 123.4 + nominal + (stop + f) / 3600.0
    ac_x = 5.0 + (stop - dev) + eps_x + rng.normal(0, noise_arcsec, n) if noise_arcsec else \
        5.0 + (stop - dev) + eps_x
    ac_y = -2.0 + eps_y + (rng.normal(0, noise_arcsec, n) if noise_arcsec else 0.0)
    closure = float(ac_x[0] + closure_drift_arcsec)
    return SimulatedPolygonSet(encoder % 360.0, dev, ac_x, ac_y, closure)
