"""A theodolite run whose elevations do not identify the axis tilt, from first principles.

numpy only, nothing from models/ (the code it checks). The frame is NOT the workbench's
(../shared/SPEC.md §1 has OZ plumb down): here OZ points UP, OX at the theodolite's azimuth
zero, right-handed. The theodolite's horizontal circle counts clockwise seen from above, so
it reads A = atan2(−y, x); its vertical reading is written as the workbench takes it,
positive below the horizontal, E = −asin z. The axis under test leans from the vertical by
ψ towards the azimuth-counted direction d: its upper end is u = [sinψ cos d, −sinψ sin d,
cosψ]. It turns clockwise seen from above for increasing θ: a right-handed rotation by the
true angle about −u (Rodrigues). The mirror normal at the reference reading points at
azimuth 0 and γ above the horizontal, n₀ = [cos γ, 0, sin γ].

The axis indicates θ with its own error of indication e (indicated − true): at indicated θ
it has truly turned t = θ − e(t) (solved by fixed-point iteration). The reference reading is
the row whose θ is nearest 0, where the theodolite is zeroed; the corrected error's truth at
a row is e(t) − e(t_ref), and the decided half range's truth half its peak-to-peak.

The elevations are written as a careless record has them: all equal (their mean, copied
into every row), or read to 0.1°; either way the tilt is not identified.
"""

from __future__ import annotations

import math

import numpy as np


def rodrigues(vector: np.ndarray, axis: np.ndarray, angle_rad: float) -> np.ndarray:
    """``vector`` turned right-handedly by ``angle_rad`` about the unit ``axis``."""
    a = axis / np.linalg.norm(axis)
    return (vector * math.cos(angle_rad) + np.cross(a, vector) * math.sin(angle_rad)
            + a * float(a @ vector) * (1.0 - math.cos(angle_rad)))


def theta_grid(points: int, rng: np.random.Generator) -> np.ndarray:
    """``points`` indicated angles, unevenly spaced over −35° … +50° (0 not among them)."""
    base = np.linspace(-35.0, 50.0, points)
    jitter = rng.uniform(-0.3, 0.3, points) * (85.0 / points)
    return np.sort(base + jitter)


def axis_error_curve(theta_deg: np.ndarray, shape: str, half_range: float,
                     rng: np.random.Generator):
    """The axis' own error e(t) (″) as a function, scaled so that its half peak-to-peak at
    ``theta_deg`` is ``half_range``: ``smooth`` (two low harmonics, random phases) or
    ``rough`` (a random value at each point, linearly interpolated between them)."""
    if shape == "smooth":
        p1, p2 = rng.uniform(0.0, 2.0 * math.pi, 2)

        def raw(t):
            r = np.radians(np.asarray(t, float))
            return np.sin(3.0 * r + p1) + 0.6 * np.sin(7.0 * r + p2)
    else:
        knots = np.asarray(theta_deg, float)
        values = rng.normal(0.0, 1.0, knots.size)

        def raw(t):
            return np.interp(np.asarray(t, float), knots, values)
    scale = half_range / (0.5 * float(np.ptp(raw(theta_deg))))
    return lambda t: scale * raw(t)


def run(theta_deg: np.ndarray, error, tilt_arcsec: float, direction_deg: float,
        gamma_deg: float, sigma_arcsec: float, rng: np.random.Generator,
        elevations: str = "copied"):
    """(θ, A, E, truth) of one run: the corrected error's truth at each row (″)."""
    theta = np.asarray(theta_deg, float)
    ref = int(np.argmin(np.abs(theta)))
    true = theta.copy()
    for _ in range(8):
        true = theta - error(true) / 3600.0
    psi, d = math.radians(tilt_arcsec / 3600.0), math.radians(direction_deg)
    up = np.array([math.sin(psi) * math.cos(d), -math.sin(psi) * math.sin(d), math.cos(psi)])
    g = math.radians(gamma_deg)
    n0 = np.array([math.cos(g), 0.0, math.sin(g)])
    normals = np.array([rodrigues(n0, -up, math.radians(t - true[ref])) for t in true])
    az = (np.degrees(np.arctan2(-normals[:, 1], normals[:, 0]))
          + rng.normal(0.0, sigma_arcsec, theta.size) / 3600.0)
    clean = -np.degrees(np.arcsin(normals[:, 2]))
    # copied (their mean in every row), else read to 0.1°
    el = (np.full(theta.size, round(float(np.mean(clean)), 4)) if elevations == "copied"
          else np.round(clean, 1))
    e = error(true)
    return theta, az, el, e - e[ref]
