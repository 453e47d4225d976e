"""Each mounting's pyramidal tilt, fitted on all mountings at once.

The polygon workbench fits one set's tilt with :func:`models.pyramidal.fit_tilt`
(a linear start, then an exact Levenberg–Marquardt polish on
:func:`models.pyramidal.frame_readings_arcsec`). A cross-calibration has one tilt
per mounting — 72 of them for a 72-face full rosette — so here the same exact 3-D
readings are evaluated for every mounting in one array (:func:`frame_readings_batch`,
the polygon model's frames and roll, checked against it to 1e-9″ in the tests) and the
same fit is done for all mountings together (Gauss–Newton from the same linear start;
a mounting it does not settle is handed to ``fit_tilt`` itself). The results are the
polygon model's :class:`~models.pyramidal.TiltFit`, with the same figures.
"""

from __future__ import annotations

import numpy as np

from models.pyramidal import AC_ALIGNMENTS, TiltFit, fit_tilt
from models.readings.angles import ARCSEC_PER_RAD

__all__ = ["fit_tilts", "frame_readings_batch", "pyramidal_corrections"]


def _rotations(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """(m, 3, 3) rotations about unit axes (m, 3) by angles (m,) rad (Rodrigues)."""
    kx, ky, kz = axis.T
    zero = np.zeros_like(kx)
    cross = np.stack([np.stack([zero, -kz, ky], -1), np.stack([kz, zero, -kx], -1),
                      np.stack([-ky, kx, zero], -1)], -2)
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return np.eye(3) + s * cross + (1.0 - c) * (cross @ cross)


def frame_readings_batch(theta_deg, psi_arcsec, omega_deg, ac_alignment: str = "polygon",
                         roll_rad: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`models.pyramidal.frame_readings_arcsec` for m tilts at once: θ (m, n) deg,
    ψ (m,) arcsec, ω (m,) deg -> (ε_x, ε_y), each (m, n) arcsec."""
    if ac_alignment not in AC_ALIGNMENTS:
        raise ValueError(f"ac_alignment must be one of {AC_ALIGNMENTS}, not {ac_alignment!r}")
    th = np.radians(np.asarray(theta_deg, dtype=float))
    psi = np.asarray(psi_arcsec, dtype=float) / ARCSEC_PER_RAD
    om = np.radians(np.asarray(omega_deg, dtype=float))
    ax, ay, az = np.sin(psi) * np.cos(om), np.sin(psi) * np.sin(om), np.cos(psi)
    nx, ny = np.cos(th), np.sin(th)
    cos_p, sin_p = np.cos(-th), np.sin(-th)
    dot = ax[:, None] * nx + ay[:, None] * ny
    # normal turned by −θ about the axis (eqs 3–5); normal_z = 0
    rotated = np.stack([
        nx * cos_p + (-az[:, None] * ny) * sin_p + ax[:, None] * dot * (1.0 - cos_p),
        ny * cos_p + (az[:, None] * nx) * sin_p + ay[:, None] * dot * (1.0 - cos_p),
        (ax[:, None] * ny - ay[:, None] * nx) * sin_p + az[:, None] * dot * (1.0 - cos_p)], 1)
    basis = np.broadcast_to(np.eye(3), (psi.size, 3, 3)).copy()  # rows: sight, horizontal, up
    if ac_alignment == "levelled":
        size = np.hypot(ax, ay)
        tilted = size > 0.0
        if np.any(tilted):
            hinge = np.stack([-ay[tilted], ax[tilted], np.zeros(int(tilted.sum()))], -1)
            turn = _rotations(hinge / size[tilted, None], np.arctan2(size[tilted], az[tilted]))
            basis[tilted] = np.swapaxes(turn, 1, 2)
    if roll_rad:
        roll = _rotations(basis[:, 0, :], np.full(psi.size, -roll_rad))
        basis = np.swapaxes(roll @ np.swapaxes(basis, 1, 2), 1, 2)
    along, across, up = np.moveaxis(basis @ rotated, 1, 0)
    return (np.arctan2(across, along) * ARCSEC_PER_RAD, np.arctan2(up, along) * ARCSEC_PER_RAD)


def fit_tilts(theta_deg, ac_y_arcsec, ac_alignment: str = "polygon", roll_rad: float = 0.0,
              iterations: int = 30) -> list[TiltFit]:
    """:func:`models.pyramidal.fit_tilt` for each row of θ (m, n) and its vertical
    readings (m, n), at once."""
    theta = np.atleast_2d(np.asarray(theta_deg, dtype=float))
    v = np.atleast_2d(np.asarray(ac_y_arcsec, dtype=float))
    m, n = theta.shape
    if n < 4:
        return [fit_tilt(theta[q], v[q], ac_alignment, roll_rad) for q in range(m)]
    th = np.radians(theta)
    design = np.stack([np.ones_like(th), np.cos(th) - 1.0, np.sin(th)], -1)  # (m, n, 3)
    k, p, q = np.moveaxis((np.linalg.pinv(design) @ v[..., None])[..., 0], 1, 0)
    x = np.stack([k, np.hypot(p, q), np.degrees(np.arctan2(q, p))], -1)  # (m, 3)

    def residuals(x, rows=slice(None)):
        return (x[:, [0]] + frame_readings_batch(theta[rows], x[:, 1], x[:, 2], ac_alignment,
                                                 roll_rad)[1] - v[rows])

    def jacobian(x, rows=slice(None)):
        """Central differences in ψ and ω (fit_tilt's); the offset's column is 1."""
        h = np.finfo(float).eps ** (1 / 3) * np.maximum(1.0, np.abs(x))
        cols = [np.ones(theta[rows].shape)]
        for i in (1, 2):
            up, down = x.copy(), x.copy()
            up[:, i] += h[:, i]
            down[:, i] -= h[:, i]
            cols.append((residuals(up, rows) - residuals(down, rows)) / (2 * h[:, [i]]))
        return np.stack(cols, -1)  # (m, n, 3)

    settled = np.zeros(m, dtype=bool)
    for _ in range(iterations):
        active = np.flatnonzero(~settled)
        xa = x[active]
        step = -(np.linalg.pinv(jacobian(xa, active), rcond=1e-12)
                 @ residuals(xa, active)[..., None])[..., 0]
        x[active] = xa + step
        # ω's step counts by what it moves the readings, ψ·Δω (ω is free when ψ = 0)
        moved = np.stack([step[:, 0], step[:, 1], np.radians(step[:, 2]) * x[active, 1]], -1)
        size = np.abs(x[active, 0]) + np.abs(x[active, 1]) + 1.0
        settled[active] = np.linalg.norm(moved, axis=1) <= 1e-10 * size
        if settled.all():
            break
    fun, jac = residuals(x), jacobian(x)
    flip = x[:, 1] < 0
    jac[flip, :, 1] *= -1
    cov = np.linalg.pinv(np.swapaxes(jac, 1, 2) @ jac) * (np.sum(fun**2, axis=1)
                                                           / max(n - 3, 1))[:, None, None]
    out: list[TiltFit] = []
    for q in range(m):
        if not (settled[q] and np.all(np.isfinite(fun[q]))):
            out.append(fit_tilt(theta[q], v[q], ac_alignment, roll_rad))
            continue
        kq, psi, omega = x[q]
        if flip[q]:
            psi, omega = -psi, omega + 180.0
        u = np.sqrt(np.clip(np.diag(cov[q]), 0, None))
        out.append(TiltFit(float(psi), float(omega % 360.0), float(kq), float(u[1]), float(u[2]),
                           -fun[q], float(np.sqrt(np.mean(fun[q] ** 2))), cov[q, 1:, 1:]))
    return out


def pyramidal_corrections(tilts: list[TiltFit], faces: int, ac_alignment: str,
                          roll_rad: float = 0.0) -> np.ndarray:
    """(m, n): each tilt's ε_x at faces 1 … n (θ = (i − 1)·360°/n) less its ε_x at face 1 —
    :func:`models.pyramidal.pyramidal_correction_arcsec` with face 1 the zero."""
    theta = np.broadcast_to(np.arange(faces) * 360.0 / faces, (len(tilts), faces))
    eps_x = frame_readings_batch(theta, [t.psi_arcsec for t in tilts], [t.omega_deg for t in tilts],
                                 ac_alignment, roll_rad)[0]
    return eps_x - eps_x[:, [0]]
