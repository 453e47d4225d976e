"""A cross-calibration (polygon turned on an encoder's shaft) done by geometry.

Imports nothing from the code it checks (only numpy and ``rotation``). The bench:

* Lab frame: the autocollimator (AC) looks along −x at the face whose normal
  points to +x; z is up, the shaft's axis (levelled). The AC's horizontal
  reading of a face normal n is its azimuth ``atan2(n_y, n_x)`` — it rises when
  the shaft turns on (right-handed about z) past the face.
* The encoder counts up for a right-handed turn: it indicates
  ``zero + θ + E(θ)``, θ the shaft's true turn, E(θ) = Σ A_h sin(hθ + φ_h) its
  periodic error (indicated − true).
* The polygon: face i's normal, in the polygon's own frame, is at azimuth
  −((i − 1)·360°/n + d_i), d_i its true deviation (faces numbered in the
  counting sense). Mounting j seats the polygon turned by j·360°/n + μ_j on the
  shaft (μ_j the mounting error, up to ±20″); optionally tilted by ψ_j towards
  ω_j (a small pyramidal tilt: its horizontal effect is second order).
* Mounting j: the shaft starts where the encoder reads its start, then the
  operator turns it so each face in turn stands within ±15″ of the AC's null
  (faces j+1, j+2, … as the encoder counts its steps), and finally a full turn
  back to the first face (the closure reading). The AC's zero drifts linearly
  in time within each mounting; every reading has Gaussian noise.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from models.validation.rotation import ARCSEC, rotate


@dataclass
class CrossCalRig:
    faces: int
    harmonics: dict[int, tuple[float, float]]  # h -> (amplitude ″, phase rad) of E(θ)
    face_dev_arcsec: np.ndarray
    mounting_error_arcsec: float = 20.0  # μ_j uniform within ±
    stop_arcsec: float = 15.0  # the operator stops within ± this of null
    drift_arcsec: float = 0.0  # each mounting's AC drift over its n steps, uniform within ±
    noise_arcsec: float = 0.0
    tilt_arcsec: float = 0.0  # each mounting's polygon tilt, uniform within 0 … this
    encoder_zero_deg: float = 211.7
    ac_zero_arcsec: float = 3.0
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))

    def __post_init__(self) -> None:
        self.face_dev_arcsec = np.asarray(self.face_dev_arcsec, dtype=float)

    def encoder_error(self, theta_deg) -> np.ndarray:
        th = np.radians(np.asarray(theta_deg, dtype=float))
        return sum(a * np.sin(h * th + ph) for h, (a, ph) in self.harmonics.items()) + 0.0 * th

    def indicated_deg(self, theta_deg: float) -> float:
        return float((self.encoder_zero_deg + theta_deg + self.encoder_error(theta_deg) / 3600.0) % 360)

    def true_angle_at(self, indicated_offset_deg: float) -> float:
        """The shaft's true turn θ at which the encoder reads zero + offset (fixed point)."""
        theta = indicated_offset_deg
        for _ in range(20):
            theta = indicated_offset_deg - float(self.encoder_error(theta)) / 3600.0
        return theta

    def truth(self) -> tuple[np.ndarray, np.ndarray]:
        """True E at the encoder's steps (from the start reading at θ_start = the first
        reading's θ) and true d, each about its mean (the closure convention)."""
        n = self.faces
        start = self.start_offset_deg + float(self.encoder_error(self.start_offset_deg)) / 3600.0
        e = np.array([self.encoder_error(self.true_angle_at(start + k * 360.0 / n))
                      for k in range(n)], dtype=float)
        return e - e.mean(), self.face_dev_arcsec - self.face_dev_arcsec.mean()

    def _normals(self, tilt: tuple[float, float]) -> np.ndarray:
        """Face normals (3 × n) in the polygon's frame as seated (tilted), before any turn."""
        n = self.faces
        body = -np.radians(np.arange(n) * 360.0 / n + self.face_dev_arcsec / 3600.0)
        v = np.vstack([np.cos(body), np.sin(body), np.zeros(n)])
        psi, omega = tilt
        if psi:
            v = rotate(v, np.array([-np.sin(omega), np.cos(omega), 0.0]), psi * ARCSEC)
        return v

    @staticmethod
    def _turned(v: np.ndarray, angle_deg: np.ndarray) -> np.ndarray:
        """Each column of v turned right-handed about z (the shaft) by its own angle."""
        ca, sa = np.cos(np.radians(angle_deg)), np.sin(np.radians(angle_deg))
        return np.vstack([ca * v[0] - sa * v[1], sa * v[0] + ca * v[1], v[2]])

    def rows(self, mountings, closure: bool = True) -> list[tuple[int, int, float, float]]:
        """(mounting, face, encoder_deg, ac_x_arcsec) in the order measured."""
        n = self.faces
        step = 360.0 / n
        out = []
        self.drifts_arcsec = []  # each mounting's AC drift over its n steps (to its closure)
        for q, j in enumerate(mountings):
            mount = j * step + self.rng.uniform(-1, 1) * self.mounting_error_arcsec / 3600.0
            tilt = (self.rng.uniform(0, self.tilt_arcsec), self.rng.uniform(0, 2 * np.pi))
            drift = self.rng.uniform(-1, 1) * self.drift_arcsec
            self.drifts_arcsec.append(drift)
            faces = np.array([(j + k) % n + 1 for k in range(n)] + ([j + 1] if closure else []))
            t = np.arange(faces.size)
            v = self._normals(tilt)[:, faces - 1]
            # the turn that brings each face to the AC's null (its normal along +x), near t steps
            at_mount = self._turned(v, np.full(faces.size, mount))
            null = -np.degrees(np.arctan2(at_mount[1], at_mount[0]))
            null = null + 360.0 * np.round((t * step - null) / 360.0)
            theta = null + self.rng.uniform(-1, 1, faces.size) * self.stop_arcsec / 3600.0
            if q == 0:  # every mounting starts where the encoder read the first reading
                self.start_offset_deg = float(theta[0])
            nv = self._turned(v, mount + theta)
            azimuth = np.arctan2(nv[1], nv[0]) / ARCSEC
            ac = (azimuth + self.ac_zero_arcsec + drift * t / n
                  + self.rng.normal(0, 1, faces.size) * self.noise_arcsec)
            for face, th, reading in zip(faces, theta, ac, strict=True):
                out.append((int(j), int(face), self.indicated_deg(th), float(reading)))
        return out
