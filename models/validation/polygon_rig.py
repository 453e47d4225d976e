"""An encoder test on a polygon done by 3-D geometry, from first principles.

This helper imports nothing from ``models``: it knows rotations and what an
autocollimator and an encoder read, nothing of the seed's equations or of our
correction. Frames and senses:

* Lab frame: the autocollimator (AC) looks along −x at the face whose normal
  points to +x; z is up. The AC reads a face normal n in its own basis (line of
  sight d, horizontal h, vertical u): horizontal ``atan2(n·h, n·d)``, vertical
  ``atan2(n·u, n·d)``. With no pitch and roll (d, h, u) = (x, y, z); a pitch
  turns the basis about y, then a roll turns it about its line of sight.
* ``frame = "levelled"`` (the lab's set-up): the shaft turns about z (levelled,
  like the AC); the polygon sits on it with its own axis tilted from z by ψ
  towards the azimuth ω (with the shaft at count 0): its face normals, square to
  its own axis, are the ideal ones tipped by ψ about ``[−sinω, cosω, 0]``.
* ``frame = "polygon"`` (seed 001's set-up): the polygon's own axis is z at
  count 0 and the shaft turns about ``k = [sinψ cosω, sinψ sinω, cosψ]``, so
  the AC's vertical is along the polygon's axis, not the shaft's.
* ``handedness`` = +1 when the encoder counts up for a right-handed turn about
  the shaft's axis (z or k), −1 for a left-handed one.
* ``counting`` = +1 when the encoder counts up as the face numbers rise, −1
  when it counts against the numbering.
* The AC's horizontal reading is taken in the encoder's counting sense (a
  shaft that overshoots raises it: eq (1) needs that); its vertical reading
  in either sense (``vertical_sense``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from models.validation.rotation import ARCSEC, rotate


@dataclass
class PolygonRig:
    faces: int
    encoder_error_arcsec: np.ndarray  # true error (indicated − true) at face 1…n, forward
    psi_arcsec: float = 0.0
    omega_deg: float = 0.0
    # per face (empty, the default: zeros): the true face angles − nominal, numbering sense;
    # the certificate − the true face deviation
    face_dev_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))
    certificate_error_arcsec: np.ndarray = field(default_factory=lambda: np.zeros(0))
    encoder_zero_deg: float = 123.4
    counting: int = 1
    handedness: int = 1
    vertical_sense: int = 1
    ac_zero_x_arcsec: float = 5.0
    ac_zero_y_arcsec: float = -2.0
    noise_arcsec: float = 0.0
    positioning_arcsec: float = 20.0  # the operator stops within ± this of each face
    backlash_arcsec: float | np.ndarray = 0.0  # reverse approach reads this much lower (per face)
    frame: str = "levelled"  # "levelled" or "polygon" (seed 001's), see the module's text
    ac_pitch_deg: float = 0.0  # the AC's line of sight raised by this (about y)
    ac_roll_arcsec: float = 0.0  # the AC turned about its line of sight (right-handed)
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))

    def __post_init__(self) -> None:
        n = self.faces
        self.encoder_error_arcsec = np.asarray(self.encoder_error_arcsec, dtype=float)
        self.face_dev_arcsec = (np.asarray(self.face_dev_arcsec, dtype=float)
                                if np.size(self.face_dev_arcsec) else np.zeros(n))
        self.certificate_error_arcsec = (np.asarray(self.certificate_error_arcsec, dtype=float)
                                         if np.size(self.certificate_error_arcsec) else np.zeros(n))
        if self.frame not in ("levelled", "polygon"):
            raise ValueError(f"frame: {self.frame!r}")
        psi = self.psi_arcsec * ARCSEC
        om = np.radians(self.omega_deg)
        tilted = np.array([np.sin(psi) * np.cos(om), np.sin(psi) * np.sin(om), np.cos(psi)])
        # count (deg, in the counting sense) at which face j stands square to the AC
        step = 360.0 / n
        self.face_count_deg = self.counting * (np.arange(n) * step + self.face_dev_arcsec / 3600.0)
        # face normals with the shaft at count 0: turning by the face's count brings it to +x
        beta = -self.handedness * np.radians(self.face_count_deg)
        self.normals = np.vstack([np.cos(beta), np.sin(beta), np.zeros(n)])
        if self.frame == "polygon":
            self.axis = tilted
        else:
            self.axis = np.array([0.0, 0.0, 1.0])
            self.normals = rotate(self.normals, np.array([-np.sin(om), np.cos(om), 0.0]), psi)
            assert np.allclose(self.normals.T @ tilted, 0.0, atol=1e-12)  # square to its axis
        basis = np.eye(3)  # columns: line of sight d, horizontal h, vertical u
        basis = rotate(basis, np.array([0.0, 1.0, 0.0]), -np.radians(self.ac_pitch_deg))
        self.ac_basis = rotate(basis, basis[:, 0], self.ac_roll_arcsec * ARCSEC)

    def ac_reading_arcsec(self, normal: np.ndarray) -> tuple[float, float]:
        """What the AC reads (horizontal, vertical) for a face normal, before its zero and
        senses: the normal's direction in the AC's own basis."""
        d, h, u = (normal @ self.ac_basis[:, i] for i in range(3))
        return float(np.arctan2(h, d) / ARCSEC), float(np.arctan2(u, d) / ARCSEC)

    def tilt_test_roll_arcmin(self, tilt_arcsec: float = 300.0) -> float:
        """The AC's roll as a technician measures it: tip a mirror square to the line of
        sight about the lab's horizontal axis y and watch both readings; the horizontal
        reading's change per unit change of the vertical one, as an angle (′), in the
        readings' own senses."""
        mirror = self.ac_basis[:, [0]]
        before = self.ac_reading_arcsec(mirror[:, 0])
        after = self.ac_reading_arcsec(rotate(mirror, np.array([0.0, 1.0, 0.0]),
                                              -tilt_arcsec * ARCSEC)[:, 0])
        dx = self.handedness * (after[0] - before[0])
        dy = self.vertical_sense * (after[1] - before[1])
        return float(np.arctan(dx / dy) / ARCSEC / 60.0)

    def truth_arcsec(self, zero_face: int = 1) -> np.ndarray:
        """The true encoder error at faces 1…n relative to ``zero_face`` (forward)."""
        f = self.encoder_error_arcsec
        return f - f[zero_face - 1]

    def read(self, face: int, reverse: bool, drift_x_arcsec: float = 0.0) -> tuple[float, ...]:
        """One stop at ``face`` (1-based): encoder (deg), AC x and AC y (")."""
        j = face - 1
        stop = self.rng.uniform(-self.positioning_arcsec, self.positioning_arcsec)
        count = self.face_count_deg[j] + stop / 3600.0  # the shaft's true turn, counting sense
        normal = rotate(self.normals[:, [j]], self.axis, self.handedness * np.radians(count))[:, 0]
        azimuth, elevation = self.ac_reading_arcsec(normal)
        noise = self.rng.normal(0.0, self.noise_arcsec, 2) if self.noise_arcsec else np.zeros(2)
        ac_x = self.handedness * azimuth + self.ac_zero_x_arcsec + drift_x_arcsec + noise[0]
        ac_y = self.vertical_sense * elevation + self.ac_zero_y_arcsec + noise[1]
        backlash = np.broadcast_to(np.asarray(self.backlash_arcsec, dtype=float), (self.faces,))
        error = self.encoder_error_arcsec[j] - (backlash[j] if reverse else 0.0)
        encoder = (self.encoder_zero_deg + count + error / 3600.0) % 360.0
        return float(encoder), float(ac_x), float(ac_y)

    def set_rows(self, set_id: int = 1, reverse: bool = False, start_face: int = 1,
                 closure_drift_arcsec: float = 0.0, closure: bool = True) -> list[list[str]]:
        """The rows of one set in approach order, closing on the start face again.

        Columns: position, encoder_deg, polygon_dev_arcsec (the certificate's),
        ac_x_arcsec, ac_y_arcsec, set, direction. The AC's horizontal zero drifts
        linearly by ``closure_drift_arcsec`` from the first reading to the closure.
        """
        n = self.faces
        step = -1 if reverse else 1
        order = [(start_face - 1 + step * k) % n + 1 for k in range(n)]
        if closure:
            order.append(start_face)
        rows = []
        for k, face in enumerate(order):
            a, x, y = self.read(face, reverse, closure_drift_arcsec * k / n)
            cert = self.face_dev_arcsec[face - 1] + self.certificate_error_arcsec[face - 1]
            rows.append([str(face), repr(a), repr(float(cert)), repr(x), repr(y), str(set_id),
                         "-" if reverse else "+"])
        return rows


def write_csv(path, rows: list[list[str]]) -> None:
    header = "position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction\n"
    with open(path, "w", encoding="utf-8", newline="") as handle:
        handle.write(header + "".join(",".join(r) + "\n" for r in rows))
