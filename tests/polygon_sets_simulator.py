"""A polygon encoder test with any number of sets per direction, from first principles.

Imports nothing from ``models`` or ``app`` (numpy only): it knows rotations and what an
encoder and an autocollimator read, nothing of the workbench's equations, its budget or its
weights. It writes the readings file the workbench reads (the columns of
resources/samples/polygon_sample.csv) and the truth the analysis should find.

The bench:

* the encoder's true error ``E(θ)`` (indicated − true, ″), a few harmonics; it reads the
  shaft's true turn plus ``E`` plus its own reading noise;
* a polygon whose face k stands square to the autocollimator at the true turn
  ``(k − 1)·360°/n + dev_k`` (dev from face 1, so face 1 exact); its certificate states
  ``dev_k`` with an error drawn afresh each run, face by face (standard uncertainty
  ``u_polygon``: the certificate's U95 / 2, as a certificate "from face 1" states it; 0 at
  face 1); the polygon sits on the shaft with its own axis tilted by ψ towards ω;
* the shaft turns about the lab's z; the autocollimator (line of sight along x, levelled,
  rolled about its line of sight by a ρ drawn each run within ±``roll_bound_arcmin``) reads a
  face normal's azimuth (horizontal, rising as the shaft over-turns) and elevation
  (vertical), each with reading noise σ; its horizontal zero drifts linearly within each
  set, by ``D_s`` from the set's first reading to its closure (``D_s`` normal, σ_D, drawn per
  set, independent between sets);
* each face may have its own pyramidal error (``face_pyramidal_sd_arcsec``: its normal out of
  the polygon's plane, a fixed artefact's, the same in every set);
* the operator stops the shaft within ±20″ of each face; every set closes on its start face.

Forward sets go 1, 2, …, n, 1; reverse sets 1, n, n − 1, …, 2, 1. Every set is against the
first set's first reading (face 1), the workbench's default common zero, so the truth is
``E(θ_k) − E(0)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

ARCSEC = np.pi / 648000.0  # one arcsecond in radians
HEADER = "position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction\n"


def rotate(vectors: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """Columns of ``vectors`` turned right-handedly about the unit ``axis`` (Rodrigues)."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    v = np.asarray(vectors, dtype=float)
    cos, sin = np.cos(angle), np.sin(angle)
    # k × v component by component: the products and differences np.cross(k[:, None], v,
    # axis=0) takes, bit for bit, without its ~15 µs of moving axes (a run of 4 sets of 24
    # faces turns ~100 normals)
    cross = np.array([k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2],
                      k[0] * v[1] - k[1] * v[0]])
    return v * cos + cross * sin + k[:, None] * (k @ v)[None, :] * (1.0 - cos)


@dataclass(frozen=True)
class Bench:
    faces: int = 24
    sigma_arcsec: float = 0.10  # autocollimator reading noise, each reading (x and y)
    encoder_sigma_arcsec: float = 0.03  # the encoder's own reading noise
    drift_sigma_arcsec: float = 0.15  # σ_D of a set's drift from its first reading to closure
    u_polygon_arcsec: float = 0.10  # the polygon certificate's standard uncertainty
    psi_arcsec: float = 120.0  # the polygon's tilt on the shaft
    omega_deg: float = 50.0
    roll_bound_arcmin: float = 1.0  # the autocollimator's roll, drawn within ± this
    stop_arcsec: float = 20.0  # the operator stops within ± this of each face
    # "per set": each set's own drift D_s from its first reading, independent between sets;
    # "steady": one rate for the whole session (a lab warming steadily), D per set, drawn
    # per run, carried on from set to set; "carried": each set's own D_s, carried on to the
    # sets after it (a random walk). Neither is what the workbench's budget assumes: it takes
    # each set's drift as within ±d of its own first reading, independent between sets
    drift: str = "per set"
    # each face's own pyramidal error (its normal out of the plane square to the polygon's
    # axis, ″), standard deviation of a fixed artefact's faces; the same in every set
    face_pyramidal_sd_arcsec: float = 0.0
    # how the operator stops at a face: "anywhere" within ± stop_arcsec of it (the
    # autocollimator reads the rest); "nominal": the shaft turned until the encoder's
    # display shows the face's nominal angle from its zero (its reading typed as shown);
    # "nulled": until the autocollimator shows its zero (it reads that); "near zero": until
    # it reads within ± stop_arcsec of its zero (it reads where the shaft stopped)
    stop_at: str = "anywhere"
    # the displays' steps (0: every digit): the encoder's in degrees, the autocollimator's
    # in arcseconds; a reading is typed as its display shows it (rounded to the step)
    encoder_step_deg: float = 0.0
    ac_step_arcsec: float = 0.0
    # the encoder's reading with the shaft at 0 (None: drawn in 0 … 360° each run, so that
    # where a display's steps fall moves from run to run)
    encoder_zero_deg: float | None = 123.4
    # the encoder's true error curve, times this (1: about ±1.7″)
    error_scale: float = 1.0
    # readings taken at each stop (the setting "readings per point"): each with its own noise
    reads_per_stop: int = 1

    @property
    def theta_deg(self) -> np.ndarray:
        return np.arange(self.faces) * 360.0 / self.faces

    def encoder_error_arcsec(self, theta_deg) -> np.ndarray:
        t = np.radians(np.asarray(theta_deg, dtype=float))
        return self.error_scale * (1.2 * np.sin(t + 0.4) + 0.5 * np.sin(2.0 * t + 1.1)
                                   + 0.15 * np.sin(7.0 * t))

    def truth_arcsec(self) -> np.ndarray:
        """The true error at faces 1…n against face 1 (the common zero)."""
        e = self.encoder_error_arcsec(self.theta_deg)
        return e - e[0]

    # the polygon's true face deviations from face 1 (a fixed artefact)
    def face_dev_arcsec(self) -> np.ndarray:
        dev = np.random.default_rng(2026).normal(0.0, 0.3, self.faces)
        return dev - dev[0]

    def run_rows(self, directions: tuple[int, ...], rng: np.random.Generator) -> list[str]:
        """The readings file's rows (CSV lines, no header) of one test: a set per entry of
        ``directions`` (+1 forward, −1 reverse), in that order."""
        n = self.faces
        step = 360.0 / n
        dev = self.face_dev_arcsec()
        certificate = dev + rng.normal(0.0, self.u_polygon_arcsec, n)
        certificate[0] = dev[0]  # stated from face 1: face 1 exact (0), each other face ±u
        # face normals with the shaft at 0: turning by the face's true angle brings it to +x
        beta = -np.radians(np.arange(n) * step + dev / 3600.0)
        # each face's own pyramidal error: its normal raised out of the polygon's plane
        lift = (np.random.default_rng(2027).normal(0.0, self.face_pyramidal_sd_arcsec, n)
                * ARCSEC)
        normals = np.vstack([np.cos(beta) * np.cos(lift), np.sin(beta) * np.cos(lift),
                             np.sin(lift)])
        om = np.radians(self.omega_deg)
        normals = rotate(normals, np.array([-np.sin(om), np.cos(om), 0.0]),
                         self.psi_arcsec * ARCSEC)
        roll = rng.uniform(-1.0, 1.0) * self.roll_bound_arcmin * 60.0 * ARCSEC
        basis = rotate(np.eye(3), np.array([1.0, 0.0, 0.0]), roll)  # columns d, h, u
        encoder_zero = (self.encoder_zero_deg if self.encoder_zero_deg is not None
                        else float(rng.uniform(0.0, 360.0)))
        zero_x, zero_y = 5.0, -2.0
        rows = []
        if self.drift not in ("per set", "steady", "carried"):
            raise ValueError(f"drift: {self.drift!r}")
        steady = rng.normal(0.0, self.drift_sigma_arcsec) if self.drift == "steady" else None
        offset = 0.0  # the drift of the sets before this one, when carried on
        for s, d in enumerate(directions, start=1):
            order = [(d * k) % n for k in range(n)] + [0]  # 0-based faces, closing on face 1
            drift = rng.normal(0.0, self.drift_sigma_arcsec) if steady is None else steady
            for j, face in enumerate(order):
                if self.stop_at == "nominal":
                    # the encoder reads turn + error and shows the nominal (from its zero)
                    # wherever that lies within its display's step of it
                    error = (self.encoder_error_arcsec(face * step)
                             + rng.normal(0.0, self.encoder_sigma_arcsec))
                    shows = _shown((encoder_zero + face * step) % 360.0, self.encoder_step_deg)
                    indicated = (shows - encoder_zero + rng.uniform(-0.5, 0.5)
                                 * self.encoder_step_deg)
                    turn = indicated - error / 3600.0
                elif self.stop_at == "anywhere":
                    turn = (face * step + dev[face] / 3600.0
                            + rng.uniform(-1.0, 1.0) * self.stop_arcsec / 3600.0)
                    error = (self.encoder_error_arcsec(face * step)
                             + rng.normal(0.0, self.encoder_sigma_arcsec))
                elif self.stop_at in ("nulled", "near zero"):
                    # turned until the autocollimator shows its zero: its reading (with its
                    # noise) anywhere within its display's step of that; or only near it,
                    # within ± stop_arcsec, and then read
                    aim = (rng.uniform(-0.5, 0.5) * self.ac_step_arcsec
                           - rng.normal(0.0, self.sigma_arcsec) if self.stop_at == "nulled"
                           else rng.uniform(-1.0, 1.0) * self.stop_arcsec)
                    turn = face * step + dev[face] / 3600.0
                    for _ in range(3):  # the azimuth rises with the over-turn, ~1″ per ″
                        seen = self._azimuth(normals[:, face], turn, basis)
                        turn -= (seen + offset + drift * j / n - aim) / 3600.0
                    error = (self.encoder_error_arcsec(face * step)
                             + rng.normal(0.0, self.encoder_sigma_arcsec))
                else:
                    raise ValueError(f"stop_at: {self.stop_at!r}")
                normal = rotate(normals[:, [face]], np.array([0.0, 0.0, 1.0]),
                                np.radians(turn))[:, 0]
                ld, lh, lu = (float(normal @ basis[:, i]) for i in range(3))
                x = (np.arctan2(lh, ld) / ARCSEC + zero_x + offset + drift * j / n
                     + rng.normal(0.0, self.sigma_arcsec))
                if self.stop_at == "nulled":  # it shows its zero (where within, in the aim)
                    x = zero_x
                y = np.arctan2(lu, ld) / ARCSEC + zero_y + rng.normal(0.0, self.sigma_arcsec)
                # where the face stands, without a reading's noise (read again: new noise)
                x_seen = np.arctan2(lh, ld) / ARCSEC + offset + drift * j / n
                y_seen = np.arctan2(lu, ld) / ARCSEC
                for again in range(self.reads_per_stop):
                    if again:  # the same stop read again: each reading's own noise
                        error = (self.encoder_error_arcsec(face * step)
                                 + rng.normal(0.0, self.encoder_sigma_arcsec))
                        x = (zero_x if self.stop_at == "nulled" else
                             zero_x + x_seen + rng.normal(0.0, self.sigma_arcsec))
                        y = zero_y + y_seen + rng.normal(0.0, self.sigma_arcsec)
                    a = (encoder_zero + turn + error / 3600.0) % 360.0
                    x, y = _shown(x, self.ac_step_arcsec), _shown(y, self.ac_step_arcsec)
                    a = _shown(a, self.encoder_step_deg)
                    rows.append(f"{face + 1},{a!r},{float(certificate[face])!r},{float(x)!r},"
                                f"{float(y)!r},{s},{'+' if d > 0 else '-'}\n")
            if self.drift != "per set":
                offset += drift
        return rows

    @staticmethod
    def _azimuth(normal: np.ndarray, turn_deg: float, basis: np.ndarray) -> float:
        """The autocollimator's horizontal angle (″, from its zero) of a face normal with the
        shaft turned by ``turn_deg``."""
        n = rotate(normal[:, None], np.array([0.0, 0.0, 1.0]), np.radians(turn_deg))[:, 0]
        return float(np.arctan2(n @ basis[:, 1], n @ basis[:, 0]) / ARCSEC)

    def metadata(self) -> dict:
        """The certificate details the budget needs: the polygon standard as stated (U95 =
        2·u, from face 1). The autocollimator's calibration is not simulated, so not stated."""
        return {"standards": [{"description": "24-face polygon (deviations from face 1)",
                               "uncertainty": 2.0 * self.u_polygon_arcsec,
                               "uncertainty_unit": "arcsec", "basis": "U95",
                               "applies_to": "from face 1"}]}


def _shown(value: float, step: float) -> float:
    """A reading as a display of step ``step`` shows it (every digit: 0), to the digits a
    technician types (no binary tails such as 0.30000000000000004)."""
    if not step:
        return float(value)
    decimals = max(0, -int(np.floor(np.log10(step) + 1e-9))) + 1
    return round(round(float(value) / step) * step, decimals)


def write_readings(path, rows: list[str]) -> None:
    with open(path, "w", encoding="utf-8", newline="") as handle:
        handle.write(HEADER + "".join(rows))
