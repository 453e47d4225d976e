"""A polygon encoder test whose autocollimator's zero moves between sets, simulated from first
principles (numpy only; imports nothing from models/).

Exact 3-D: the shaft turns about z; the polygon sits on it tilted by ψ towards a random
azimuth; face f's normal lies at −f·Δ in the polygon's frame, moved by the face's true
deviation from its certificate's figure and out of the plane by the face's own pyramidal
angle. The shaft (the item: an encoder with a smooth error curve) is stopped within
± ``stop_arcsec`` of each face; the autocollimator, its line of sight along x and rolled by
one unknown ρ a run, reads the normal's azimuth and elevation with noise σ each, the encoder
with noise ``sigma_enc``. Its zero: one offset a set, drawn N(0, ``jump_sd``) at the start of
every set after the first ("jumps", constant within the set, so every closure is within its
limit; ``offsets`` says how the sets' offsets relate), and/or a steady drift ``rate`` per
reading over the whole test. A set reads its faces
forward, or reverse from face 1, then face 1 again (the closure).

The encoder's error curve (``shape``): "harmonics" (4 harmonics falling as 1/k, rms
``curve_rms``), or, of true half peak-to-peak ``half_range`` at the faces, "smooth" (1st and
2nd harmonics), "rough" (ten harmonics falling as 1/k) or "spike" (one face's stop a narrow
bump of 2·``half_range`` on a flat curve, the shaft's error 0 half a degree away).

The truth: the encoder's error at faces 1…n against face 1, and half its peak-to-peak; the
polygon certificate's calibration error is one draw a run (a measurement error, not truth).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

ARCSEC = math.pi / 180.0 / 3600.0
HEADER = "position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction"


def _turn_z(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _turn_y(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


@dataclass(frozen=True)
class ZeroJumpRig:
    faces: int = 24
    sets: int = 4  # alternating forward, reverse, forward, …
    sigma: float = 0.1  # autocollimator x and y noise, a reading (″)
    sigma_enc: float = 0.1  # the encoder's own reading noise (″)
    jump_sd: float = 0.0  # the zero's offset at the start of each set after the first (″)
    # how the sets' offsets relate: "from_first" each later set's N(0, jump_sd) about set 1's
    # zero; "walk" each later set's jump added to the set before's (the zero does not come
    # back); "each" every set's own N(0, jump_sd), set 1's too (one zero about which all scatter)
    offsets: str = "from_first"
    rate: float = 0.0  # the zero's steady drift per reading (″)
    curve_rms: float = 0.8  # the encoder's error curve (4 harmonics), rms (″)
    shape: str = "harmonics"  # or "smooth", "rough", "spike" (of half range ``half_range``)
    half_range: float = 1.0  # the true half peak-to-peak at the faces of those shapes (″)
    tilt_arcsec: float = 150.0
    pyramidal_sd: float = 3.0  # each face's own angle out of the plane (″)
    roll_arcmin: float = 1.0  # the autocollimator's roll, drawn within ± this
    cert_u: float = 0.05  # u of the polygon certificate's face deviations (″)
    stop_arcsec: float = 5.0

    def run(self, rng: np.random.Generator) -> tuple[list[str], np.ndarray]:
        """(CSV lines with the header, the true error at faces 1…n against face 1)."""
        n = self.faces
        step = 2.0 * math.pi / n
        error = self._curve(rng, step)

        cert = np.round(np.concatenate(([0.0], rng.normal(0.0, 0.3, n - 1))), 2)
        true_dev = cert + np.r_[0.0, rng.normal(0.0, self.cert_u, n - 1)]
        beta = rng.normal(0.0, self.pyramidal_sd, n) * ARCSEC
        towards = rng.uniform(0.0, 2.0 * math.pi)
        seat = _turn_z(towards) @ _turn_y(self.tilt_arcsec * ARCSEC) @ _turn_z(-towards)
        rho = rng.uniform(-1.0, 1.0) * self.roll_arcmin * 60.0 * ARCSEC
        enc_zero = rng.uniform(0.0, 360.0)
        lines, t, offset = [HEADER], 0, 0.0
        for k in range(self.sets):
            forward = k % 2 == 0
            order = list(range(n)) if forward else [0] + list(range(n - 1, 0, -1))
            if self.offsets == "each" or k:
                offset = rng.normal(0.0, self.jump_sd) + (offset if self.offsets == "walk" else 0.0)
            for f in order + [order[0]]:
                g = -f * step - true_dev[f] * ARCSEC
                normal = np.array([math.cos(beta[f]) * math.cos(g),
                                   math.cos(beta[f]) * math.sin(g), math.sin(beta[f])])
                phi = f * step + rng.uniform(-1.0, 1.0) * self.stop_arcsec * ARCSEC
                v = _turn_z(phi) @ seat @ normal
                x = math.atan2(v[1], v[0])
                y = math.atan2(v[2], math.hypot(v[0], v[1]))
                x, y = x * math.cos(rho) - y * math.sin(rho), x * math.sin(rho) + y * math.cos(rho)
                ac_x = x / ARCSEC + rng.normal(0.0, self.sigma) + offset + self.rate * t
                ac_y = y / ARCSEC + rng.normal(0.0, self.sigma)
                enc = (enc_zero + math.degrees(phi)
                       + (error(phi) + rng.normal(0.0, self.sigma_enc)) / 3600.0) % 360.0
                lines.append(f"{f + 1},{enc:.9f},{cert[f]:.2f},{ac_x:.4f},{ac_y:.4f},{k + 1},"
                             f"{'+' if forward else '-'}")
                t += 1
        truth = np.array([error(f * step) for f in range(n)], dtype=float)
        return lines, truth - float(truth[0])

    def _curve(self, rng: np.random.Generator, step: float):
        """The encoder's error (″) as a function of the shaft angle (rad)."""
        if self.shape == "spike":
            at = float(rng.integers(self.faces)) * step
            width = math.radians(0.1)  # far narrower than a face's pitch, far wider than a stop

            def spike(phi: float) -> float:
                off = math.remainder(phi - at, 2.0 * math.pi)
                return 2.0 * self.half_range * math.exp(-0.5 * (off / width) ** 2)
            return spike
        if self.shape == "harmonics":
            h = np.arange(1, 5)
            a, b = rng.normal(size=4) / h, rng.normal(size=4) / h
            scale = self.curve_rms / math.sqrt(0.5 * float(np.sum(a * a + b * b)))
        else:
            h = np.arange(1, 3) if self.shape == "smooth" else np.arange(1, 11)
            amp = np.array([1.0, 0.5]) if self.shape == "smooth" else 1.0 / h
            phase = rng.uniform(0.0, 2.0 * math.pi, h.size)
            a, b = amp * np.sin(phase), amp * np.cos(phase)
            at_faces = [float(np.sum(a * np.cos(h * f * step) + b * np.sin(h * f * step)))
                        for f in range(self.faces)]
            scale = self.half_range / (0.5 * (max(at_faces) - min(at_faces)))
        a, b = a * scale, b * scale

        def error(phi: float) -> float:  # the encoder's error at shaft angle phi (″)
            return float(np.sum(a * np.cos(h * phi) + b * np.sin(h * phi)))
        return error
