"""A cross-calibration bench done by geometry: a polygon turned on an encoder's shaft.

Imports nothing from ``models`` (numpy only, its own rotations): it knows what a shaft,
an encoder and an autocollimator do, nothing of the least squares, the closure
constraints or the polygon workbench's tilt equations. Frames and senses:

* Lab frame: the autocollimator (AC) looks along −x at the face whose normal points to
  +x; z is up. Its horizontal reading of a normal v is ``atan2(v·y, v·x)`` (it rises
  when the shaft turns on, right-handed, past the face), its vertical reading
  ``atan2(v·z, v·x)``.
* The encoder counts up for a right-handed turn: it indicates ``zero + θ + E(θ)``, θ
  the shaft's true turn from where the first mounting started, E(θ) = Σ A_h sin(hθ + φ_h)
  its periodic error (indicated − true).
* The polygon: face i's normal, in the polygon's own frame (face 1 on +x), lies at the
  azimuth −((i − 1)·360°/n + d_i), d_i its true deviation (faces numbered in the
  counting sense). Mounting j seats it turned on the shaft by j·360°/n + μ_j (μ_j the
  mounting error, uniform within ±``mounting_error_arcsec``).
* Face pyramidal errors: face i's normal stands at its own elevation β_i
  (``face_elevation_arcsec``, positive towards the polygon's own axis direction +z) above
  the polygon's plane, ``[cosβ cos az, cosβ sin az, sinβ]`` in the polygon's frame — fixed to
  the polygon, so the same in every mounting (zero unless given).
* Tilt: in each mounting the polygon sits with its own axis at ψ_j from the shaft's,
  towards ω_j (in the polygon's frame). ``frame = "levelled"``: the shaft is vertical
  (z, levelled like the AC) and the face normals are tipped by ψ_j about
  ``[−sin ω_j, cos ω_j, 0]`` before the polygon is turned. ``frame = "polygon"`` (seed
  001's set-up): the AC's vertical is along the polygon's own axis as it stands with
  face 1 at the AC; the shaft's axis is tilted from it, ``[sinψ cosω, sinψ sinω, cosψ]``,
  and every turn is about that axis.
* Each mounting starts where the encoder read the first mounting's start; the operator
  turns the shaft so each face in turn stands within ±``stop_arcsec`` of the AC's null
  (faces j+1, j+2, … as the encoder counts its steps), and, with ``closure``, once more to
  the first face after a full turn. The AC's zero drifts linearly in time within each
  mounting (by up to ±``drift_arcsec`` over its n steps, drawn for each mounting on its own;
  with ``drift_common`` the same drift in every mounting; ``drifts_arcsec`` sets a mounting's
  drift over its n steps outright), the closure reading carrying n/n of it; both readings
  have Gaussian
  noise σ = ``noise_arcsec``. The AC's horizontal scale may be off by ``ac_scale`` (relative):
  it then indicates (1 + s) times the face normal's angle from its null.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

ARCSEC = np.pi / 648000.0


def rotation(axis, angle_rad: float) -> np.ndarray:
    """Right-handed rotation about a unit axis (Rodrigues)."""
    kx, ky, kz = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    cross = np.array([[0.0, -kz, ky], [kz, 0.0, -kx], [-ky, kx, 0.0]])
    return np.eye(3) + np.sin(angle_rad) * cross + (1.0 - np.cos(angle_rad)) * (cross @ cross)


@dataclass
class Bench:
    faces: int
    harmonics: dict[int, tuple[float, float]]  # h -> (amplitude ″, phase rad) of E(θ)
    face_dev_arcsec: np.ndarray
    mounting_error_arcsec: float = 20.0
    stop_arcsec: float = 15.0
    drift_arcsec: float = 0.0
    noise_arcsec: float = 0.0
    tilt_arcsec: float = 0.0  # each mounting's ψ_j uniform within 0 … this, ω_j any
    frame: str = "levelled"
    encoder_zero_deg: float = 97.3
    ac_zero_x_arcsec: float = -4.0
    ac_zero_y_arcsec: float = 7.0
    face_elevation_arcsec: np.ndarray | None = None  # β_i per face (1 … n), ″; None: square faces
    ac_scale: float = 0.0  # the AC's relative scale error: it indicates (1 + s)·(angle from its null)
    ac_roll_arcmin: float = 0.0  # the AC's axes rolled about its line of sight (x) by this
    #: the AC's zero drifts the same in every mounting (thermal drift the same way all day):
    #: one drift over a mounting, uniform within ±drift_arcsec, drawn for the whole run
    drift_common: bool = False
    #: mounting j -> its drift over its n steps, ″, as given (the draw above still made, so the
    #: other draws stay those of the same seed): mountings drifting each their own way
    drifts_arcsec: dict[int, float] | None = None
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))

    def __post_init__(self) -> None:
        self.face_dev_arcsec = np.asarray(self.face_dev_arcsec, dtype=float)
        self.start_deg = float(self.rng.uniform(-0.002, 0.002))  # where mounting 0 starts (true θ)
        self.mounts: list[dict] = []
        self.common_drift_arcsec = float(self.rng.uniform(-1, 1) * self.drift_arcsec) \
            if self.drift_common else 0.0

    def encoder_error(self, theta_deg) -> np.ndarray:
        th = np.radians(np.asarray(theta_deg, dtype=float))
        return sum(a * np.sin(h * th + ph) for h, (a, ph) in self.harmonics.items()) + 0.0 * th

    def indicated_deg(self, theta_deg) -> np.ndarray:
        return (self.encoder_zero_deg + theta_deg + self.encoder_error(theta_deg) / 3600.0) % 360.0

    def theta_where_encoder_reads(self, indicated_offset_deg: float) -> float:
        """The true turn θ at which the encoder reads its zero + this (by iteration)."""
        theta = indicated_offset_deg
        for _ in range(30):
            theta = indicated_offset_deg - float(self.encoder_error(theta)) / 3600.0
        return theta

    def truth(self) -> tuple[np.ndarray, np.ndarray]:
        """True E at the encoder's steps from the start reading, and true d, each about
        its mean (both close at 360°)."""
        n = self.faces
        start = self.start_deg + float(self.encoder_error(self.start_deg)) / 3600.0
        e = np.array([float(self.encoder_error(self.theta_where_encoder_reads(start + k * 360.0 / n)))
                      for k in range(n)])
        return e - e.mean(), self.face_dev_arcsec - self.face_dev_arcsec.mean()

    def _normals(self) -> np.ndarray:
        n = self.faces
        az = -np.radians(np.arange(n) * 360.0 / n + self.face_dev_arcsec / 3600.0)
        beta = (np.zeros(n) if self.face_elevation_arcsec is None
                else np.asarray(self.face_elevation_arcsec, dtype=float) * ARCSEC)
        return np.vstack([np.cos(beta) * np.cos(az), np.cos(beta) * np.sin(az), np.sin(beta)])

    def _face_normals(self, faces, turn_deg, psi: float, omega: float) -> np.ndarray:
        """The faces' normals (3, m) in the lab with the polygon turned by ``turn_deg`` (its
        seat on the shaft plus the shaft's turn, one angle per face) about the shaft's axis."""
        v = self._normals()[:, np.asarray(faces) - 1]
        if self.frame == "levelled":
            if psi:
                v = rotation([-np.sin(omega), np.cos(omega), 0.0], psi * ARCSEC) @ v
            axis = np.array([0.0, 0.0, 1.0])
        else:
            axis = np.array([np.sin(psi * ARCSEC) * np.cos(omega), np.sin(psi * ARCSEC) * np.sin(omega),
                             np.cos(psi * ARCSEC)])
        # each column turned about the axis by its own angle (Rodrigues, column by column)
        angle = np.radians(np.asarray(turn_deg, dtype=float))
        along = axis[:, None] * (axis @ v)
        return (along + (v - along) * np.cos(angle) + np.cross(axis, v, axis=0) * np.sin(angle))

    def _null_turns(self, faces, seat_deg: float, guess_deg, psi, omega) -> np.ndarray:
        """The shaft's turns near ``guess_deg`` at which each face's horizontal reading is
        zero (Newton on the exact geometry)."""
        theta = np.asarray(guess_deg, dtype=float).copy()
        for _ in range(8):
            v = self._face_normals(faces, seat_deg + theta, psi, omega)
            theta -= np.degrees(np.arctan2(v[1], v[0]))
        return theta

    def rows(self, mountings, closure=True, vertical: bool = False) -> list[tuple]:
        """(mounting, face, encoder_deg, ac_x_arcsec[, ac_y_arcsec]) in the order measured;
        ``closure``: every mounting ends with its closure reading (True), none (False), or the
        mountings named (a collection of mounting numbers)."""
        n = self.faces
        step = 360.0 / n
        out = []
        self.mounts = []
        for j in mountings:
            seat = j * step + self.rng.uniform(-1, 1) * self.mounting_error_arcsec / 3600.0
            psi = float(self.rng.uniform(0.0, self.tilt_arcsec))
            omega = float(self.rng.uniform(0.0, 2 * np.pi))
            drift = float(self.rng.uniform(-1, 1) * self.drift_arcsec)
            if self.drift_common:
                drift = self.common_drift_arcsec
            if self.drifts_arcsec is not None and j in self.drifts_arcsec:
                drift = float(self.drifts_arcsec[j])
            self.mounts.append({"mounting": j, "seat_deg": seat, "psi_arcsec": psi,
                                "omega_rad": omega, "drift_arcsec": drift})
            closed = closure if isinstance(closure, bool) else j in closure
            faces = np.array([(j + k) % n + 1 for k in range(n)] + ([j + 1] if closed else []))
            t = np.arange(faces.size)
            theta = self._null_turns(faces, seat, t * step, psi, omega)
            theta += self.rng.uniform(-1, 1, faces.size) * self.stop_arcsec / 3600.0
            theta[0] = self.start_deg  # every mounting starts where the first did
            v = self._face_normals(faces, seat + theta, psi, omega)
            if self.ac_roll_arcmin:  # the normals in the AC's rolled axes
                v = rotation([1.0, 0.0, 0.0], -self.ac_roll_arcmin * 60.0 * ARCSEC) @ v
            noise = self.rng.normal(0.0, self.noise_arcsec, (2, faces.size))
            ac_x = ((1.0 + self.ac_scale) * np.arctan2(v[1], v[0]) / ARCSEC + self.ac_zero_x_arcsec
                    + drift * t / n + noise[0])
            ac_y = np.arctan2(v[2], v[0]) / ARCSEC + self.ac_zero_y_arcsec + noise[1]
            encoder = self.indicated_deg(theta)
            for q in range(faces.size):
                row = (int(j), int(faces[q]), float(encoder[q]), float(ac_x[q]))
                out.append(row + ((float(ac_y[q]),) if vertical else ()))
        return out
