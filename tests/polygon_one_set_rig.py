"""One set of a polygon encoder test, from first principles, with faces that are not at one
tilt (the known defect of issue 39: one set, no σ of a reading stated).

Imports nothing from ``models`` or ``app`` (numpy only). What it knows is geometry and what
the instruments read:

* a polygon of n faces; face k's outward normal, in the polygon's own frame, lies at azimuth
  −(k·360°/n + d_k), d_k the face's true angle error (d_1 = 0: the deviations are from face
  1), and is raised out of the polygon's plane by its own pyramidal error p_k (a fixed
  artefact: ground faces are not exactly square to the axis);
* the polygon sits on the shaft with its axis tilted by ψ towards ω: every normal is turned
  by ψ about the horizontal axis (−sin ω, cos ω, 0);
* the shaft turns by φ about the lab's vertical z; the encoder under test indicates
  φ + E(φ) + its own reading noise (σ_enc), E a known error curve;
* a levelled autocollimator looks along −x at the faces (its line of sight along +x from the
  polygon) and reads the normal's azimuth atan2(n_y, n_x) (horizontal x, rising as the shaft
  over-turns) and its elevation atan2(n_z, √(n_x² + n_y²)) (vertical y), each with its own
  reading noise σ_ac and an arbitrary zero;
* the operator stops within ±20″ of each face, forward 1, 2, …, n, and closes on face 1.

The polygon's certificate states d_k exactly, so the error the workbench should find at face
k against face 1 is E(θ_k) − E(0) (θ_k the nominal), and the decided quantity's truth is half
its peak-to-peak.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

ARCSEC = np.pi / 648000.0
COLUMNS = ["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec", "ac_y_arcsec", "set",
           "direction"]


def _turn(vectors: np.ndarray, axis, angle: float) -> np.ndarray:
    """Rotation of the columns of ``vectors`` by ``angle`` (rad) about the unit ``axis``, as a
    rotation matrix (Rodrigues' formula written out)."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    k = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    r = np.eye(3) + np.sin(angle) * k + (1.0 - np.cos(angle)) * (k @ k)
    return r @ vectors


@dataclass
class OneSetBench:
    faces: int = 12
    sigma_enc_arcsec: float = 0.08  # the encoder's own reading noise
    sigma_ac_arcsec: float = 0.05  # the autocollimator's, on x and on y
    face_pyramidal_sd_arcsec: float = 1.5  # the faces' own pyramidal errors (sd)
    psi_arcsec: float = 120.0
    omega_deg: float = 35.0
    error_half_range: float = 1.0  # scale of E (″)
    seed: int = 0  # the artefact: face errors and pyramidal errors
    face_dev_arcsec: np.ndarray = field(init=False)
    face_pyramidal_arcsec: np.ndarray = field(init=False)

    def __post_init__(self) -> None:
        art = np.random.default_rng(1000 + self.seed)
        dev = art.normal(0.0, 0.4, self.faces)
        self.face_dev_arcsec = dev - dev[0]
        self.face_pyramidal_arcsec = art.normal(0.0, self.face_pyramidal_sd_arcsec, self.faces)

    @property
    def nominal_deg(self) -> np.ndarray:
        return np.arange(self.faces) * 360.0 / self.faces

    def encoder_error_arcsec(self, phi_deg) -> np.ndarray:
        t = np.radians(np.asarray(phi_deg, dtype=float))
        return self.error_half_range * (0.8 * np.cos(t - 0.7) + 0.3 * np.sin(3.0 * t + 0.2))

    def truth_arcsec(self) -> np.ndarray:
        e = self.encoder_error_arcsec(self.nominal_deg)
        return e - e[0]

    def truth_half_range(self) -> float:
        return 0.5 * float(np.ptp(self.truth_arcsec()))

    def rows(self, rng: np.random.Generator) -> list[list[str]]:
        """The readings sheet of one forward set closing on face 1 (one row a reading)."""
        n = self.faces
        az = -np.radians(self.nominal_deg + self.face_dev_arcsec / 3600.0)
        el = self.face_pyramidal_arcsec * ARCSEC
        normals = np.vstack([np.cos(az) * np.cos(el), np.sin(az) * np.cos(el), np.sin(el)])
        om = np.radians(self.omega_deg)
        normals = _turn(normals, (-np.sin(om), np.cos(om), 0.0), self.psi_arcsec * ARCSEC)
        encoder_zero, x0, y0 = 217.25, 3.0, -4.0
        out = []
        for face in [*range(n), 0]:
            phi = self.nominal_deg[face] + self.face_dev_arcsec[face] / 3600.0 \
                + rng.uniform(-20.0, 20.0) / 3600.0
            nrm = _turn(normals[:, [face]], (0.0, 0.0, 1.0), np.radians(phi))[:, 0]
            x = np.arctan2(nrm[1], nrm[0]) / ARCSEC + x0 + rng.normal(0.0, self.sigma_ac_arcsec)
            y = (np.arctan2(nrm[2], np.hypot(nrm[0], nrm[1])) / ARCSEC + y0
                 + rng.normal(0.0, self.sigma_ac_arcsec))
            indicated = (phi + (self.encoder_error_arcsec(phi)
                                + rng.normal(0.0, self.sigma_enc_arcsec)) / 3600.0)
            a = (encoder_zero + indicated) % 360.0
            out.append([str(face + 1), repr(float(a)), repr(float(self.face_dev_arcsec[face])),
                        repr(float(x)), repr(float(y)), "1", "+"])
        return out


def write_csv(path, rows: list[list[str]]) -> None:
    with open(path, "w", encoding="utf-8", newline="") as handle:
        handle.write(",".join(COLUMNS) + "\n" + "".join(",".join(r) + "\n" for r in rows))
