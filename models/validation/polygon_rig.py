"""An encoder test on a polygon done by 3-D geometry, from first principles.

This helper imports nothing from ``models``: it knows rotations and what an
autocollimator and an encoder read, nothing of the seed's equations or of our
correction. Frames and senses:

* Lab frame: the autocollimator (AC) looks along −x at the face whose normal
  points to +x; z is up. The AC's horizontal reading is the azimuth of the
  face normal, its vertical reading the normal's elevation.
* The shaft turns about ``k = [sinψ cosω, sinψ sinω, cosψ]``: the polygon's
  own axis (z when the shaft is at its zero) is tilted against the rotation
  axis by ψ. ``handedness`` = +1 when the encoder counts up for a right-handed
  turn about +k, −1 for a left-handed one.
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
    face_dev_arcsec: np.ndarray | None = None  # true face angles − nominal, numbering sense
    certificate_error_arcsec: np.ndarray | None = None  # certificate − true face deviation
    encoder_zero_deg: float = 123.4
    counting: int = 1
    handedness: int = 1
    vertical_sense: int = 1
    ac_zero_x_arcsec: float = 5.0
    ac_zero_y_arcsec: float = -2.0
    noise_arcsec: float = 0.0
    positioning_arcsec: float = 20.0  # the operator stops within ± this of each face
    backlash_arcsec: float | np.ndarray = 0.0  # reverse approach reads this much lower (per face)
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))

    def __post_init__(self) -> None:
        n = self.faces
        self.encoder_error_arcsec = np.asarray(self.encoder_error_arcsec, dtype=float)
        self.face_dev_arcsec = (np.zeros(n) if self.face_dev_arcsec is None
                                else np.asarray(self.face_dev_arcsec, dtype=float))
        self.certificate_error_arcsec = (np.zeros(n) if self.certificate_error_arcsec is None
                                         else np.asarray(self.certificate_error_arcsec, float))
        psi = self.psi_arcsec * ARCSEC
        om = np.radians(self.omega_deg)
        self.axis = np.array([np.sin(psi) * np.cos(om), np.sin(psi) * np.sin(om), np.cos(psi)])
        # count (deg, in the counting sense) at which face j stands square to the AC
        step = 360.0 / n
        self.face_count_deg = self.counting * (np.arange(n) * step + self.face_dev_arcsec / 3600.0)
        # face normals with the shaft at count 0: turning by the face's count brings it to +x
        beta = -self.handedness * np.radians(self.face_count_deg)
        self.normals = np.vstack([np.cos(beta), np.sin(beta), np.zeros(n)])

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
        azimuth = np.arctan2(normal[1], normal[0]) / ARCSEC
        elevation = np.arctan2(normal[2], np.hypot(normal[0], normal[1])) / ARCSEC
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
