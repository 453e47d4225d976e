"""True error curves for the coverage study of the decided quantity (half the peak-to-peak).

The shapes that occur on an axis, a polygon test or a grating, made from their physics and
from the bundled samples, with no use of the estimator they check
(:mod:`models.uncertainty.conformity`): a smooth curve (eccentricity and ellipticity, the
1st and 2nd harmonics of a circle's graduation), a rough one (ten harmonics falling as
1/k, as a graduation's short-period errors), a single spike (one bad line or face on a flat
curve), a flat curve (a perfect axis) and the real curves of the bundled samples
(theodolite, polygon and fringe runs as analysed by their workbenches).
"""

from __future__ import annotations

import numpy as np

__all__ = ["SHAPES", "sample_curves", "true_curve"]

SHAPES = ("smooth", "rough", "spike", "sample")


def _harmonics(theta: np.ndarray, amplitudes, phases) -> np.ndarray:
    return sum(a * np.sin((k + 1) * theta + p)
               for k, (a, p) in enumerate(zip(amplitudes, phases, strict=True)))


def sample_curves() -> dict[str, np.ndarray]:
    """The corrected (theodolite, polygon) and as-found (fringe, its first period) error
    curves of the bundled samples, as their workbenches analyse them."""
    from pathlib import Path

    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    folder = Path(__file__).resolve().parent.parent.parent / "resources" / "samples"

    out = {}
    for key, attribute in (("theodolite", "corrected_error_arcsec"),
                           ("polygon", "mean_corrected_arcsec"), ("fringe", "raw_error")):
        kind = KINDS[key]
        table = read_table(folder / kind.sample_file)
        parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
        result = kind.analyze(parsed, kind.settings_with_defaults({}))
        curve = np.asarray(getattr(result, attribute), dtype=float)
        if key == "fringe":
            curve = curve[:result.samples_per_period or 64]
        out[key] = curve
    return out


def true_curve(shape: str, points: int, variant: int = 0,
               samples: dict[str, np.ndarray] | None = None) -> np.ndarray:
    """A true error curve of ``points`` points and half peak-to-peak 1 (0 for "flat").

    ``variant`` picks the random phases of "rough" and where the spike falls, and for
    "sample" which bundled curve (theodolite, polygon, fringe in turn), resampled to
    ``points`` points along its abscissa."""
    theta = np.arange(points) * 2.0 * np.pi / points
    rng = np.random.default_rng(1000 + variant)
    if shape == "flat":
        return np.zeros(points)
    if shape == "smooth":
        curve = _harmonics(theta, (1.0, 0.5), rng.uniform(0, 2 * np.pi, 2))
    elif shape == "rough":
        curve = _harmonics(theta, 1.0 / np.arange(1, 11), rng.uniform(0, 2 * np.pi, 10))
    elif shape == "spike":
        curve = np.zeros(points)
        curve[int(rng.integers(points))] = 2.0
    elif shape == "sample":
        samples = samples if samples is not None else sample_curves()
        real = list(samples.values())[variant % len(samples)]
        curve = np.interp(np.linspace(0.0, 1.0, points), np.linspace(0.0, 1.0, real.size), real)
    else:
        raise ValueError(f"unknown shape {shape!r}")
    return curve / (0.5 * float(np.ptp(curve)))
