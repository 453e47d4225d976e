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

Face pyramidal errors (:func:`fit_tilts_and_faces`): a real polygon's face normals are
not square to its axis — face i's normal stands at its own elevation β_i, fixed to the
polygon's body, the same in every mounting. Each mounting's vertical readings are then
``k_j + ε_y(θ_i; ψ_j, ω_j, β_i)``: the faces' β pattern is fitted once, shared by all
mountings, with every mounting's tilt. Two parts of β cannot be told from the rest: its
mean over the faces from each mounting's vertical zero k_j, and its first harmonic over
the faces (β_i = a·cos θ_i + b·sin θ_i, a plane tipped against the axis) from a tilt common
to all mountings. β is therefore stated with its mean and first harmonic removed — each
face's pyramidal error relative to the faces' mean plane (the best-fit plane of the face
normals' elevations); what was removed stays in the tilts and zeros (the tilts are the
mean plane's tilts). Its horizontal effect is exact: the elevated normals are read through
each mounting's tilt.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from models.pyramidal import AC_ALIGNMENTS, TiltFit, fit_tilt
from models.readings.angles import ARCSEC_PER_RAD

__all__ = ["FacePyramidalFit", "face_pyramidal_projector", "fit_tilts", "fit_tilts_and_faces",
           "frame_readings_batch", "pyramidal_corrections"]


def _rotations(axis: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """(m, 3, 3) rotations about unit axes (m, 3) by angles (m,) rad (Rodrigues)."""
    kx, ky, kz = axis.T
    zero = np.zeros_like(kx)
    cross = np.stack([np.stack([zero, -kz, ky], -1), np.stack([kz, zero, -kx], -1),
                      np.stack([-ky, kx, zero], -1)], -2)
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return np.eye(3) + s * cross + (1.0 - c) * (cross @ cross)


def frame_readings_batch(theta_deg, psi_arcsec, omega_deg, ac_alignment: str = "polygon",
                         roll_rad: float = 0.0, elevation_arcsec=None) -> tuple[np.ndarray, np.ndarray]:
    """:func:`models.pyramidal.frame_readings_arcsec` for m tilts at once: θ (m, n) deg,
    ψ (m,) arcsec, ω (m,) deg -> (ε_x, ε_y), each (m, n) arcsec. ``elevation_arcsec``
    (broadcast to θ; None: 0): each face normal's own elevation β above the polygon's
    plane, ``[cosβ cosθ, cosβ sinθ, sinβ]`` (a face pyramidal error)."""
    if ac_alignment not in AC_ALIGNMENTS:
        raise ValueError(f"ac_alignment must be one of {AC_ALIGNMENTS}, not {ac_alignment!r}")
    th = np.radians(np.asarray(theta_deg, dtype=float))
    psi = np.asarray(psi_arcsec, dtype=float) / ARCSEC_PER_RAD
    om = np.radians(np.asarray(omega_deg, dtype=float))
    ax, ay, az = np.sin(psi) * np.cos(om), np.sin(psi) * np.sin(om), np.cos(psi)
    nx, ny = np.cos(th), np.sin(th)
    cos_p, sin_p = np.cos(-th), np.sin(-th)
    ax, ay, az = ax[:, None], ay[:, None], az[:, None]
    if elevation_arcsec is None:
        dot = ax * nx + ay * ny
        # normal turned by −θ about the axis (eqs 3–5); normal_z = 0
        rotated = np.stack([
            nx * cos_p + (-az * ny) * sin_p + ax * dot * (1.0 - cos_p),
            ny * cos_p + (az * nx) * sin_p + ay * dot * (1.0 - cos_p),
            (ax * ny - ay * nx) * sin_p + az * dot * (1.0 - cos_p)], 1)
    else:  # the same rotation (Rodrigues) of an elevated normal
        beta = np.broadcast_to(np.asarray(elevation_arcsec, dtype=float), th.shape) / ARCSEC_PER_RAD
        nx, ny, nz = nx * np.cos(beta), ny * np.cos(beta), np.sin(beta)
        dot = ax * nx + ay * ny + az * nz
        rotated = np.stack([
            nx * cos_p + (ay * nz - az * ny) * sin_p + ax * dot * (1.0 - cos_p),
            ny * cos_p + (az * nx - ax * nz) * sin_p + ay * dot * (1.0 - cos_p),
            nz * cos_p + (ax * ny - ay * nx) * sin_p + az * dot * (1.0 - cos_p)], 1)
    ax, ay, az = ax[:, 0], ay[:, 0], az[:, 0]
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
              iterations: int = 30, elevation_arcsec=None) -> list[TiltFit]:
    """:func:`models.pyramidal.fit_tilt` for each row of θ (m, n) and its vertical
    readings (m, n), at once; ``elevation_arcsec`` (m, n): the faces' own elevations β,
    known (see :func:`fit_tilts_and_faces`), read through each tilt exactly."""
    theta = np.atleast_2d(np.asarray(theta_deg, dtype=float))
    v = np.atleast_2d(np.asarray(ac_y_arcsec, dtype=float))
    m, n = theta.shape
    beta = None
    if elevation_arcsec is not None and np.any(elevation_arcsec):
        beta = np.broadcast_to(np.asarray(elevation_arcsec, dtype=float), theta.shape)
    level = v if beta is None else v - beta  # β adds to the vertical readings (first order)
    if n < 4:
        return [fit_tilt(theta[q], level[q], ac_alignment, roll_rad) for q in range(m)]
    th = np.radians(theta)
    design = np.stack([np.ones_like(th), np.cos(th) - 1.0, np.sin(th)], -1)  # (m, n, 3)
    k, p, q = np.moveaxis((np.linalg.pinv(design) @ level[..., None])[..., 0], 1, 0)
    x = np.stack([k, np.hypot(p, q), np.degrees(np.arctan2(q, p))], -1)  # (m, 3)

    def residuals(x, rows=slice(None)):
        return (x[:, [0]] + frame_readings_batch(theta[rows], x[:, 1], x[:, 2], ac_alignment, roll_rad,
                                                 None if beta is None else beta[rows])[1] - v[rows])

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
            out.append(fit_tilt(theta[q], level[q], ac_alignment, roll_rad))
            continue
        kq, psi, omega = x[q]
        if flip[q]:
            psi, omega = -psi, omega + 180.0
        u = np.sqrt(np.clip(np.diag(cov[q]), 0, None))
        out.append(TiltFit(float(psi), float(omega % 360.0), float(kq), float(u[1]), float(u[2]),
                           -fun[q], float(np.sqrt(np.mean(fun[q] ** 2))), cov[q, 1:, 1:]))
    return out


def pyramidal_corrections(tilts: list[TiltFit], faces: int, ac_alignment: str,
                          roll_rad: float = 0.0, elevation_arcsec=None) -> np.ndarray:
    """(m, n): each tilt's ε_x at faces 1 … n (θ = (i − 1)·360°/n) less its ε_x at face 1 —
    :func:`models.pyramidal.pyramidal_correction_arcsec` with face 1 the zero;
    ``elevation_arcsec`` (n,): the faces' own elevations β (None: 0)."""
    theta = np.broadcast_to(np.arange(faces) * 360.0 / faces, (len(tilts), faces))
    eps_x = frame_readings_batch(theta, [t.psi_arcsec for t in tilts], [t.omega_deg for t in tilts],
                                 ac_alignment, roll_rad, elevation_arcsec)[0]
    return eps_x - eps_x[:, [0]]


def face_pyramidal_projector(faces: int) -> np.ndarray:
    """n × n: removes the mean and the first harmonic over the faces (θ_i = (i − 1)·360°/n)
    — the part of the face elevations β that a vertical zero and a common tilt cannot take."""
    th = np.radians(np.arange(faces) * 360.0 / faces)
    q, _ = np.linalg.qr(np.column_stack([np.ones(faces), np.cos(th), np.sin(th)]))
    return np.eye(faces) - q @ q.T


@dataclass(frozen=True)
class FacePyramidalFit:
    """The faces' own elevations β_i (face 1 first), arcsec, in the sense of the vertical
    reading, relative to the faces' mean plane (mean and first harmonic over the faces
    removed: they cannot be told from the vertical zero and a common tilt); their standard
    uncertainty (k = 1), the vertical readings' σ and its ν (m·n − 3m − (n − 3)).

    ``scatter_arcsec`` (m,): each mounting's RMS about its own tilt and the faces' β taken
    as the median over the mountings (not the mean: one mounting's slipped readings would
    spread a third of themselves into every other mounting's residuals with three
    mountings); what a vertical reading that follows no tilt is judged by."""

    elevation_arcsec: np.ndarray
    u_arcsec: np.ndarray
    sigma_arcsec: float
    dof: int
    scatter_arcsec: np.ndarray


def fit_tilts_and_faces(face_index, faces: int, ac_y_arcsec, ac_alignment: str = "polygon",
                        roll_rad: float = 0.0, iterations: int = 8
                        ) -> tuple[list[TiltFit], FacePyramidalFit | None]:
    """Each mounting's tilt (ψ_j, ω_j, zero k_j) and the faces' own elevations β, shared by
    all mountings, from the vertical readings (m, n) of faces ``face_index`` (m, n; 0-based,
    each mounting reads each face once). β is constrained to the faces' mean plane (module
    text): no mean, no first harmonic over the faces. In the linear model that subspace is
    orthogonal to every mounting's (1, cos θ, sin θ), so the joint least squares separates:
    β is the projected mean over the mountings of the tilt fits' residuals; it is refined
    with the exact 3-D readings until it moves by less than 1e-7″. The TiltFits' residuals
    are those left after both. With fewer than 2 mountings or 4 faces no β is fitted (None).
    """
    idx = np.atleast_2d(np.asarray(face_index, dtype=int))
    v = np.atleast_2d(np.asarray(ac_y_arcsec, dtype=float))
    m, n = idx.shape
    theta = idx * 360.0 / faces
    fits = fit_tilts(theta, v, ac_alignment, roll_rad)
    if m < 2 or faces < 4 or n != faces:
        return fits, None
    keep = face_pyramidal_projector(faces)
    beta = np.zeros(faces)
    for _ in range(iterations):
        total = np.zeros(faces)
        np.add.at(total, idx, np.array([f.residuals_arcsec for f in fits]))
        change = keep @ (total / m)
        beta += change
        fits = fit_tilts(theta, v, ac_alignment, roll_rad, elevation_arcsec=beta[idx])
        if np.abs(change).max() < 1e-7:
            break
    dof = m * faces - 3 * m - (faces - 3)
    scatter = float(sum(f.residuals_arcsec @ f.residuals_arcsec for f in fits))
    sigma = float(np.sqrt(scatter / dof)) if dof > 0 else float("nan")
    u = sigma * np.sqrt(np.clip(np.diag(keep), 0.0, None) / m)
    pattern = np.zeros((m, faces))  # v less each tilt, β left in, face order
    np.put_along_axis(pattern, idx, np.array([f.residuals_arcsec for f in fits]) + beta[idx], 1)
    # about the median β and each mounting's own tilt (linear: P removes 1, cos θ, sin θ)
    left = (pattern - np.median(pattern, axis=0)) @ keep
    scatter = np.sqrt(np.mean(left**2, axis=1))
    return fits, FacePyramidalFit(beta, u, sigma, int(dof), scatter)
