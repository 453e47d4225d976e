"""A polygon encoder test with an encoder reversal, from first principles, for the tests of
the reversal's U (issue 39): numpy only, nothing from the code it checks.

The encoder's true error e(θ) is the same both ways round but its reading lags by b/2 each
way (a reversal b_k at face k: forward sets read θ + e + b/2, reverse sets θ + e − b/2), so
the reversal ē↑ − ē↓ that the workbench reports per face is b_k, its truth. A polygon (face
k's normal at azimuth −φ_k, φ_k = (k − 1)·360°/n + dev_k, its own elevation γ_k) sits on the
shaft with its axis tilted by ψ towards ω; the shaft turns about the lab's z to within
± ``stop`` of each face; the autocollimator looks along x, levelled, rolled by ρ about its line
of sight, and reads the normal's azimuth and elevation in its rolled frame, each with noise σ;
its zero may drift steadily (``drift_arcsec`` per set, carried on from set to set). Forward
sets go 1, 2, …, n, 1; reverse sets 1, n, …, 2, 1.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

ARCSEC = np.pi / 648000.0
HEADER = ["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec", "ac_y_arcsec", "set",
          "direction"]


def _turn(axis, angle: float) -> np.ndarray:
    """The rotation matrix about the unit ``axis`` by ``angle`` (Rodrigues)."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    cross = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(angle) * cross + (1.0 - np.cos(angle)) * cross @ cross


@dataclass
class ReversalRig:
    faces: int = 12
    sigma_arcsec: float = 0.1  # the autocollimator's noise, each reading (x and y)
    psi_arcsec: float = 120.0
    omega_deg: float = 200.0
    roll_arcmin: float = 0.0
    drift_arcsec: float = 0.0  # the zero's steady drift per set (a set's closure)
    stop_arcsec: float = 8.0
    seed: int = 3  # the artefact: error curve, reversal, face deviations and elevations
    error: np.ndarray = field(init=False)
    reversal: np.ndarray = field(init=False)
    dev: np.ndarray = field(init=False)
    gamma: np.ndarray = field(init=False)

    def __post_init__(self) -> None:
        r = np.random.default_rng(self.seed)
        n = self.faces
        t = np.radians(np.arange(n) * 360.0 / n)
        self.error = np.sin(t + 0.3) + 0.4 * r.standard_normal(n)
        self.reversal = 0.3 + 0.2 * np.cos(t) + 0.1 * r.standard_normal(n)
        self.dev = np.round(0.3 * r.standard_normal(n), 2)
        self.dev[0] = 0.0
        self.gamma = 2.0 * r.standard_normal(n)

    def rows(self, directions: tuple[int, ...], rng: np.random.Generator) -> list[list[str]]:
        n = self.faces
        roll = np.radians(self.roll_arcmin / 60.0)
        omega = np.radians(self.omega_deg)
        tilt = _turn([-np.sin(omega), np.cos(omega), 0.0], self.psi_arcsec * ARCSEC)
        out, count = [], 0
        for number, d in enumerate(directions, 1):
            order = list(range(n)) + [0] if d > 0 else [0] + list(range(n - 1, -1, -1))
            for j, k in enumerate(order):
                phi = np.radians(k * 360.0 / n) + self.dev[k] * ARCSEC
                g = self.gamma[k] * ARCSEC
                normal = np.array([np.cos(phi) * np.cos(g), -np.sin(phi) * np.cos(g), np.sin(g)])
                theta = np.radians(k * 360.0 / n) + self.stop_arcsec * ARCSEC * rng.standard_normal()
                v = _turn([0.0, 0.0, 1.0], theta) @ tilt @ normal
                azimuth = np.arctan2(v[1], v[0])
                elevation = np.arctan2(v[2], np.hypot(v[0], v[1]))
                x = ((azimuth * np.cos(roll) + elevation * np.sin(roll)) / ARCSEC
                     + self.sigma_arcsec * rng.standard_normal() + self.drift_arcsec * count / n)
                y = ((-azimuth * np.sin(roll) + elevation * np.cos(roll)) / ARCSEC
                     + self.sigma_arcsec * rng.standard_normal())
                count += 1
                lag = 0.5 * self.reversal[k] * d
                turns = 360.0 if (d > 0 and j == len(order) - 1) else 0.0
                reading = (123.4 + np.degrees(theta) + turns + (self.error[k] + lag) / 3600.0) % 360.0
                out.append([str(k + 1), f"{reading:.8f}", f"{self.dev[k]:.2f}", f"{x:.3f}",
                            f"{y:.3f}", str(number), "+" if d > 0 else "-"])
        return out
