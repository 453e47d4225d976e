"""A polygon's pyramidal tilt on a shaft as an autocollimator reads it, and the closure
drift of a turn: the geometry the polygon and cross-calibration workbenches share.

Seed 001 (Tian et al., Acta Optica Sinica 35(5) 0512003, 2015), eqs 3–7: the encoder
axis ``[sinψ cosω, sinψ sinω, cosψ]`` is tilted by ψ towards ω in the polygon frame;
face normal ``[cosθ, sinθ, 0]`` rotated about it by −θ gives ``ε_x = atan(y'/x')`` and
``ε_y = atan(z'/x')``. Which frame the autocollimator reads in (../shared/SPEC.md §2, 2026-12-01):
``"polygon"`` (eqs 3–7: its vertical along the polygon's axis) or ``"levelled"`` (the
lab's set-up: its vertical along the shaft), same turned normals read in a basis turned
by the least rotation; a measured roll ρ turns the reading basis about the line of
sight. :func:`fit_tilt` identifies ψ, ω from the vertical readings,
:func:`pyramidal_correction_arcsec` gives what the tilt adds to the horizontal ones.

Moved here unchanged from ``models.polygon.model`` (which still offers every name) so
that two workbenches use one copy without importing each other.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.damped_least_squares import difference_jacobian, polish
from models.lazy_optimize import least_squares
from models.messages import QT_TR_NOOP, message
from models.readings.angles import ARCSEC_PER_RAD
from models.uncertainty.tilt_direction import direction_determined

__all__ = ["AC_ALIGNMENTS", "TiltFit", "closure_drift_arcsec", "fit_tilt", "frame_readings_arcsec",
           "pyramidal_correction_arcsec", "pyramidal_readings_arcsec", "wrap_deg"]

#: The set-ups the horizontal readings may be taken in: ``levelled`` (autocollimator and
#: rotary axis levelled, the usual lab set-up) and ``polygon`` (seed 001's frame: the
#: autocollimator's vertical along the polygon's axis).
AC_ALIGNMENTS = ("levelled", "polygon")

def wrap_deg(angle_deg):
    """Angle(s) wrapped into [−180°, 180°)."""
    return (np.asarray(angle_deg, dtype=float) + 180.0) % 360.0 - 180.0


def closure_drift_arcsec(start_encoder_deg: float, start_ac_x_arcsec: float,
                         closure_encoder_deg: float, closure_ac_x_arcsec: float) -> float:
    """Drift over a set: ``(c' − c) − (a' − a)`` on its start face, arcsec.

    An autocollimator that drifted by d gives d; an encoder whose zero moved by
    d gives −d; a shaft that stops a little further on return gives 0.
    """
    da = float(wrap_deg(closure_encoder_deg - start_encoder_deg)) * 3600.0
    return (closure_ac_x_arcsec - start_ac_x_arcsec) - da


def _axis_cross(axis: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """``np.cross(axis[:, None], normal, axis=0)``: the axis (3,) crossed with each column of
    ``normal`` (3, m), each component the same two products and difference numpy's cross
    makes (a₁b₂ − a₂b₁, a₂b₀ − a₀b₂, a₀b₁ − a₁b₀), bit for bit, without its broadcasting and
    axis moves (half of a frame's readings' time: a polygon's tilt fit makes ~130 of them)."""
    a0, a1, a2 = axis
    b0, b1, b2 = normal
    return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])


def pyramidal_readings_arcsec(theta_deg, psi_arcsec: float, omega_deg: float):
    """Exact autocollimator readings (ε_x, ε_y) in arcsec at face angles θ (eqs 3–7)."""
    th = np.radians(np.asarray(theta_deg, dtype=float))
    psi = psi_arcsec / ARCSEC_PER_RAD
    om = math.radians(omega_deg)
    axis = np.array([math.sin(psi) * math.cos(om), math.sin(psi) * math.sin(om), math.cos(psi)])
    normal = np.array([np.cos(th), np.sin(th), np.zeros_like(th)])
    phi = -th
    cos_p, sin_p = np.cos(phi), np.sin(phi)
    cross = _axis_cross(axis, normal)
    dot = axis @ normal
    rotated = normal * cos_p + cross * sin_p + axis[:, None] * dot * (1.0 - cos_p)
    x, y, z = rotated
    return np.arctan(y / x) * ARCSEC_PER_RAD, np.arctan(z / x) * ARCSEC_PER_RAD


def _turned_normals(theta_deg, psi_arcsec: float, omega_deg: float):
    """Face normals [cosθ, sinθ, 0] turned by −θ about the tilted axis (eqs 3–5), and
    the axis: (3, m) and (3,), in the seed's polygon coordinates."""
    th = np.radians(np.asarray(theta_deg, dtype=float))
    psi = psi_arcsec / ARCSEC_PER_RAD
    om = math.radians(omega_deg)
    axis = np.array([math.sin(psi) * math.cos(om), math.sin(psi) * math.sin(om), math.cos(psi)])
    normal = np.array([np.cos(th), np.sin(th), np.zeros_like(th)])
    cos_p, sin_p = np.cos(-th), np.sin(-th)
    cross = _axis_cross(axis, normal)
    dot = axis @ normal
    return normal * cos_p + cross * sin_p + axis[:, None] * dot * (1.0 - cos_p), axis


def _rotation(axis, angle_rad: float) -> np.ndarray:
    """Rotation matrix about a unit axis (Rodrigues)."""
    kx, ky, kz = axis
    cross = np.array([[0.0, -kz, ky], [kz, 0.0, -kx], [-ky, kx, 0.0]])
    return np.eye(3) + math.sin(angle_rad) * cross + (1.0 - math.cos(angle_rad)) * (cross @ cross)


def frame_readings_arcsec(theta_deg, psi_arcsec: float, omega_deg: float,
                          ac_alignment: str = "polygon", roll_rad: float = 0.0):
    """Exact readings (ε_x, ε_y) in arcsec of an autocollimator in the chosen frame.

    The normals are turned as in eqs 3–5 (seed's coordinates, ψ, ω as fitted). The
    reading basis (line of sight, horizontal, vertical) is the polygon's (X, Y, Z) for
    ``"polygon"`` (eqs 6–7) and, for ``"levelled"``, that basis turned by the least
    rotation taking Z to the shaft's axis (vertical along the shaft, line of sight square
    to it). ``roll_rad`` is the autocollimator's measured roll ρ: the horizontal reading
    as read (eq 1's sense, which carries −ε_x) changes by ρ per unit change of the
    vertical reading; the basis is turned about the line of sight by −ρ.
    """
    if ac_alignment not in AC_ALIGNMENTS:
        raise ValueError(f"ac_alignment must be one of {AC_ALIGNMENTS}, not {ac_alignment!r}")
    rotated, axis = _turned_normals(theta_deg, psi_arcsec, omega_deg)
    basis = np.eye(3)  # rows: line of sight, horizontal, vertical
    if ac_alignment == "levelled":
        hinge = np.array([-axis[1], axis[0], 0.0])  # Z × axis
        size = float(np.hypot(hinge[0], hinge[1]))
        if size > 0.0:
            turn = _rotation(hinge / size, math.atan2(size, axis[2]))
            basis = (turn @ basis.T).T
    if roll_rad:
        basis = (_rotation(basis[0], -roll_rad) @ basis.T).T
    along, across, up = basis @ rotated
    return (np.arctan2(across, along) * ARCSEC_PER_RAD,
            np.arctan2(up, along) * ARCSEC_PER_RAD)


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
    cov_psi_omega: np.ndarray | None = None  # covariance of (ψ ″, ω °) from the fit

    @property
    def omega_determined(self) -> bool:
        """Whether the tilt direction ω is determined: ψ told from 0 by its u
        (models.uncertainty.tilt_direction)."""
        return direction_determined(self.psi_arcsec, self.u_psi_arcsec)


def fit_tilt(theta_deg, ac_y_arcsec, ac_alignment: str = "polygon",
             roll_rad: float = 0.0) -> TiltFit:
    """Identify ψ, ω from vertical readings: linear fit on (1, cosθ − 1, sinθ), then an exact
    polish with the chosen frame's vertical readings (:func:`frame_readings_arcsec`)."""
    theta = np.asarray(theta_deg, dtype=float)
    v = np.asarray(ac_y_arcsec, dtype=float)
    if theta.size < 4:
        raise ValueError(message(
            QT_TR_NOOP("at least 4 vertical readings are needed to identify the tilt")))
    th = np.radians(theta)
    design = np.column_stack([np.ones_like(th), np.cos(th) - 1.0, np.sin(th)])
    (k, p, q), *_ = np.linalg.lstsq(design, v, rcond=None)
    start = np.array([k, math.hypot(p, q), math.degrees(math.atan2(q, p))])

    def residuals(x):
        if ac_alignment == "polygon" and not roll_rad:
            return x[0] + pyramidal_readings_arcsec(theta, x[1], x[2])[1] - v
        return x[0] + frame_readings_arcsec(theta, x[1], x[2], ac_alignment, roll_rad)[1] - v

    # k, ψ in arcsec and ω in degrees: 1e-10 of them is far below any reading
    fit = polish(residuals, lambda x: difference_jacobian(residuals, x, central=True), start,
                 xtol=1e-10)
    if not fit.converged:  # MINPACK's LM from the same start (imports scipy.optimize)
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
                   -fit.fun, float(np.sqrt(np.mean(fit.fun**2))), cov[1:, 1:])


def pyramidal_correction_arcsec(theta_deg, psi_arcsec: float, omega_deg: float,
                                zero_theta_deg: float, ac_alignment: str = "polygon",
                                roll_rad: float = 0.0) -> np.ndarray:
    """``ε_x(θ) − ε_x(θ_z)``: what the tilt adds to each error against the zero face, in the
    chosen frame (and with a measured roll ρ, see :func:`frame_readings_arcsec`).

    θ is the position angle in the counting sense (the one the tilt was fitted
    on). The corrected error is the error minus this.
    """
    theta = np.append(np.asarray(theta_deg, dtype=float), zero_theta_deg)
    eps_x = frame_readings_arcsec(theta, psi_arcsec, omega_deg, ac_alignment, roll_rad)[0]
    return eps_x[:-1] - eps_x[-1]
