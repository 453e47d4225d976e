"""A theodolite run with repeated passes, simulated from first principles (numpy only,
nothing from the code it checks): the frame of ../shared/SPEC.md §1 (OZ plumb down, OX the
azimuth zero), the axis tilted by ψ towards α, the mirror normal at the axis' zero
[cos β, 0, −sin β], turned right-handed about the axis by its TRUE rotation θ − d(θ)
(Rodrigues); the theodolite reads atan2(y, x) and asin z. The axis' error has a reversal:
d + b/2 forward, d − b/2 backward. Each pass reads every θ once, forward then backward; the
runs repeat the passes. The reading error: pointing noise σ new in every reading, and the
circle's own error at each θ (standard deviation ``circle``, the same in every pass)."""

from __future__ import annotations

import math

import numpy as np

THETA = np.arange(-12.0, 12.1, 2.0)  # 13 points, θ₀ = 0 among them
PSI, ALPHA, BETA = 1.5, 65.0, -2.0  # deg


def _rotate(v: np.ndarray, axis: np.ndarray, phi: float) -> np.ndarray:
    k = axis / np.linalg.norm(axis)
    return v * math.cos(phi) + np.cross(k, v) * math.sin(phi) + k * (k @ v) * (1 - math.cos(phi))


def mirror_readings(true_rotation_deg: np.ndarray, psi_deg: float = PSI,
                    alpha_deg: float = ALPHA, beta_deg: float = BETA
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Azimuth and elevation (deg) of the mirror normal at each true rotation, noise-free,
    the axis tilted by ψ towards α and the normal at β."""
    psi, alpha, beta = np.radians([psi_deg, alpha_deg, beta_deg])
    axis = np.array([-math.sin(psi) * math.cos(alpha), -math.sin(psi) * math.sin(alpha),
                     math.cos(psi)])
    normal = np.array([math.cos(beta), 0.0, -math.sin(beta)])
    out = np.array([_rotate(normal, axis, phi) for phi in np.radians(true_rotation_deg)])
    return np.degrees(np.arctan2(out[:, 1], out[:, 0])), np.degrees(np.arcsin(out[:, 2]))


def _shown(angle_deg: float, step: float | None) -> str:
    """An angle as the theodolite's display shows it: decimal degrees, or d°m's" rounded to
    ``step`` arcsec (a CSV cell, quoted)."""
    if step is None:
        return f"{angle_deg:.9f}"
    per_second = max(1, round(1.0 / step))  # counted in whole ticks: no 59.99999″
    ticks = round(abs(angle_deg) * 3600.0 / step) * round(step * per_second)
    d, rest = divmod(ticks, 3600 * per_second)
    m, t = divmod(rest, 60 * per_second)
    decimals = len(str(per_second)) - 1
    sign = "-" if angle_deg < 0 and ticks else ""
    return f'"{sign}{d}°{m}\'{t / per_second:.{decimals}f}"""'


def passes_record(path, rng, runs: int, sigma: float, reversal: float,
                  circle: float = 0.0, axis_noise: float = 0.0,
                  directions: bool = True, circle_shape: str = "independent",
                  curve: str = "random", step: float | None = None,
                  theta: np.ndarray | None = None, curves: dict | None = None
                  ) -> dict[str, float]:
    """Write a record of ``runs`` × (forward, backward) passes to ``path``; return the true
    ISO 230-2 figures of the axis (the circle's errors are an error of the measurement, not
    the axis': they are in no truth). ``axis_noise``: the axis' own non-repeatability, a
    random error of its true rotation at every approach (in R and A, as ISO 230-2 counts
    it); ``directions`` False: no run and direction columns (θ repeated); ``circle_shape``:
    the circle's error independent at each θ, or one sine over the span (random phase,
    "sine"), or the axis' error curve turned over ("against": it flattens the measured
    curve), each of standard deviation ``circle``, or "against_2u": the axis' error curve
    turned over and scaled to ±2 ``circle`` at its extremes (it lowers the measured range by
    4 ``circle`` and flattens the whole curve), "with_2u": the axis' error curve itself so
    scaled (it raises the measured range by 4 ``circle``), or "extremes": ±2 ``circle`` (each within
    its U at k = 2) at the θ where the axis' error is highest and lowest, 0 elsewhere (it
    lowers the measured range by 4 ``circle``, the most such errors can). The theodolite
    reads the mirror's true rotation, off by the circle's error: the readings show the
    axis' error less the circle's, d − c. ``step``: the theodolite shows its
    readings to that step (arcsec), written in degrees, minutes and seconds as a user types
    them off the display; None: decimal degrees to 1e-9°. ``theta``: the θ read (sorted, 0
    among them; :data:`THETA` if None). ``curve`` also "smooth" (one slow wave and a bow,
    random phase, 2″ peak-to-peak), "rough" (the smooth curve and an independent 0.4″ at
    each θ) or "spike" (a slow 1″ wave and one θ 1.5″ off). ``curves``: a dict given is
    filled with the θ ("theta"), the axis' error d ("d") and the circle's ("c"), arcsec."""
    grid = THETA if theta is None else np.asarray(theta, dtype=float)
    t = np.radians(grid)
    span = grid[-1] - grid[0]
    x = (grid - grid[0]) / span
    if curve == "smooth":
        d = np.sin(2 * math.pi * 0.7 * x + rng.uniform(0, 2 * math.pi)) + 0.8 * (2 * x - 1) ** 2
        d *= 2.0 / float(np.ptp(d))
    elif curve == "rough":
        d = np.sin(2 * math.pi * 0.7 * x + rng.uniform(0, 2 * math.pi)) + 0.8 * (2 * x - 1) ** 2
        d = d * 2.0 / float(np.ptp(d)) + rng.normal(0.0, 0.4, grid.size)
    elif curve == "spike":
        d = 0.5 * np.sin(2 * math.pi * 0.5 * x + rng.uniform(0, 2 * math.pi))
        d[rng.integers(1, grid.size - 1)] += 1.5
    elif curve == "bow":
        d = (1.5 * np.sin(2 * math.pi * 0.8 * (grid - grid[0]) / span)
             + 0.6 * (grid / grid[-1]) ** 2)
    else:
        d = 1.2 * np.sin(5.0 * t + rng.uniform(0, 2 * math.pi)) + 0.4 * np.cos(
            11.0 * t + rng.uniform(0, 2 * math.pi))  # the axis' error, arcsec
    c = rng.normal(0.0, circle, grid.size)  # the circle's error at each θ's position
    if circle_shape == "sine":
        c = circle * math.sqrt(2.0) * np.sin(2 * math.pi * (grid - grid[0]) / span
                                             + rng.uniform(0, 2 * math.pi))
    elif circle_shape == "against":  # the readings show d − c: this flattens them
        c = circle * (d - d.mean()) / np.std(d)
    elif circle_shape == "against_2u":  # d − c: the curve flattened, ±2 circle at its ends
        c = 2.0 * circle * (d - 0.5 * (d.max() + d.min())) / (0.5 * float(np.ptp(d)))
    elif circle_shape == "with_2u":  # d − c: the curve steepened, ∓2 circle at its ends
        c = -2.0 * circle * (d - 0.5 * (d.max() + d.min())) / (0.5 * float(np.ptp(d)))
    elif circle_shape == "extremes":  # +2 circle where d is highest, −2 where lowest
        c = np.zeros(grid.size)
        c[np.argmax(d)], c[np.argmin(d)] = 2.0 * circle, -2.0 * circle
    if curves is not None:
        curves.update(theta=grid.copy(), d=d.copy(), c=c.copy())
    rows = ["theta_deg,azimuth_deg,elevation_deg" + (",run,direction" if directions else "")]
    for run in range(1, runs + 1):
        for sign, order in ((+1, grid), (-1, grid[::-1])):
            i = np.searchsorted(grid, order)
            error = d[i] + sign * 0.5 * reversal + rng.normal(0.0, axis_noise, order.size)
            az, el = mirror_readings(order - error / 3600.0)
            az = az + (c[i] + rng.normal(0.0, sigma, order.size)) / 3600.0
            el = el + rng.normal(0.0, sigma, order.size) / 3600.0
            tail = f",{run},{'+' if sign > 0 else '-'}" if directions else ""
            rows += [f"{a:.9f},{_shown(b, step)},{_shown(e, step)}{tail}"
                     for a, b, e in zip(order, az, el, strict=True)]
    path.write_text("\n".join(rows) + "\n")
    # the figures are the axis': the circle's errors (the same at a θ in every pass) are an
    # error of the measurement, in the means as part of the curve, which the interval holds
    curve = d
    e_range = float(np.ptp(np.concatenate([curve + 0.5 * reversal, curve - 0.5 * reversal])))
    s = math.hypot(sigma, axis_noise)  # one reading's scatter over the passes
    return {"E": e_range, "M": float(np.ptp(curve)), "B": abs(reversal), "B_mean": reversal,
            "R_up": 4 * s, "R_down": 4 * s, "R": 4 * s + abs(reversal),
            "E_up": float(np.ptp(curve)), "E_down": float(np.ptp(curve)),
            "A": e_range + 4 * s, "A_up": float(np.ptp(curve)) + 4 * s,
            "A_down": float(np.ptp(curve)) + 4 * s}
