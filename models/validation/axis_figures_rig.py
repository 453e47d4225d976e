"""A rotary axis with a known systematic deviation curve, known repeatability and a known
reversal, measured by the ISO 230-2 standard test cycle — and the truth of every figure.

This helper imports nothing from ``models`` but numpy. The axis at a target P, approached
in direction d (+1 up, −1 down), stops at the deviation

    x = f(P) + d·b(P)/2 + σ_d(P)·z,   z ~ N(0, 1) independently at each approach,

f the systematic deviation curve, b the reversal (x̄↑ − x̄↓ of the true distribution: half
of it is lost each way), σ_d the repeatability (1σ) of that direction at that target.
Each run goes up through every target and back down.

The truth of each figure is defined, as ISO 230-2:2014 (and GB/T 17421.2-2016) and VDI/DGQ
3441 define the figure, on the true distribution: μ↑ = f + b/2, μ↓ = f − b/2, σ↑, σ↓ in
place of x̄↑, x̄↓, s↑, s↓ (written out here from the standards' definitions):

* E↑ = max μ↑ − min μ↑; E = max(μ↑ ∪ μ↓) − min(μ↑ ∪ μ↓);
* M = max (μ↑ + μ↓)/2 − min (μ↑ + μ↓)/2; B = max |μ↑ − μ↓|; B̄ = mean (μ↑ − μ↓);
* R↑ = 4 max σ↑; R = max over the targets of max(2σ↑ + 2σ↓ + |μ↑ − μ↓|, 4σ↑, 4σ↓);
* A↑ = max(μ↑ + 2σ↑) − min(μ↑ − 2σ↑); A the same over both directions;
* VDI/DGQ 3441: Pa = M, U_max = B, Ps_max = max 6(σ↑ + σ↓)/2,
  P = max(m + (|b| + Ps)/2) − min(m − (|b| + Ps)/2), m = (μ↑ + μ↓)/2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["SAMPLE_DOWN", "SAMPLE_UP", "SHAPES", "SIGMA_ALONG", "AxisCase", "true_figures"]

#: the bundled sample's mean deviations (″, 13 targets 0…360°, forward and backward): a real
#: axis's curve
SAMPLE_UP = (-1.38, 2.64, 5.84, 4.74, 1.80, -3.57, -6.04, -6.95, -6.69, -4.94, -5.67, -3.70,
             -0.69)
SAMPLE_DOWN = (4.55, 8.36, 10.33, 9.98, 6.73, 1.52, -1.71, -1.75, -1.54, -1.11, 0.40, 0.88,
               4.70)

SHAPES = ("smooth", "rough", "spike", "sample")

#: how σ may change along the axis beside ``varying`` (:class:`AxisCase`'s ``along``):
#: at random in 1–2 × for each target and direction, rising linearly 1 → 3 × from the first
#: target to the last, or one target (the third of the way along) at 3 ×
SIGMA_ALONG = ("random", "ramp", "one")


def _periodic(values: tuple[float, ...], angle_deg: np.ndarray) -> np.ndarray:
    """A curve given at equal steps over 0…360° (both ends given), linearly interpolated."""
    grid = np.linspace(0.0, 360.0, len(values))
    return np.interp(angle_deg, grid, np.asarray(values, dtype=float))


def _curves(shape: str, angle_deg: np.ndarray, rng: np.random.Generator
            ) -> tuple[np.ndarray, np.ndarray]:
    """(f, b) of a shape, f scaled to a peak-to-peak of 2 (″)."""
    t = np.radians(angle_deg)
    if shape == "smooth":  # pitch error: a scale error, once and twice per turn
        f = 0.3 * t / np.pi + np.sin(t) + 0.3 * np.sin(2 * t + 1.0)
        b = 0.5 + 0.2 * np.sin(t + 0.4)
    elif shape == "rough":  # every harmonic the targets resolve, amplitudes 1/k
        k = np.arange(1, max(angle_deg.size // 2, 1) + 1)
        phase = rng.uniform(0.0, 2 * np.pi, k.size)
        f = np.sum(np.sin(np.outer(t, k) + phase) / k, axis=1)
        b = 0.4 + 0.1 * rng.standard_normal(angle_deg.size)
    elif shape == "spike":  # a smooth curve and one target far off (a damaged scale line)
        f = 0.2 * np.sin(t)
        f[angle_deg.size // 3] += 1.0
        b = np.full(angle_deg.size, 0.6)
    elif shape == "sample":
        up, down = _periodic(SAMPLE_UP, angle_deg), _periodic(SAMPLE_DOWN, angle_deg)
        f, b = 0.5 * (up + down), up - down
    else:
        raise ValueError(f"unknown shape {shape}")
    scale = 2.0 / float(np.ptp(f))
    return f * scale, b * scale


@dataclass
class AxisCase:
    """One axis: ``shape`` of f, ``targets`` equally spaced over a turn, repeatability
    ``noise_ratio`` × the signal (σ = ratio × half the peak-to-peak of f), constant over the
    targets or (``varying``) changing by ±50 % along the axis, the backward direction's
    10 % larger; ``runs`` runs each way. ``along`` (one of :data:`SIGMA_ALONG`, "" for none)
    multiplies σ further along the axis: "random" by a factor drawn in 1–2 for each target
    and direction (from the case's seed, after the curve), "ramp" by 1 → 3 linearly over the
    targets, "one" the target a third of the way along by 3."""

    shape: str
    targets: int
    noise_ratio: float
    varying: bool = False
    runs: int = 5
    seed: int = 0
    along: str = ""

    def __post_init__(self) -> None:
        rng = np.random.default_rng(self.seed)
        self.angles = np.linspace(0.0, 360.0, self.targets, endpoint=False)
        self.f, self.b = _curves(self.shape, self.angles, rng)
        sigma = self.noise_ratio * 0.5 * float(np.ptp(self.f)) * np.ones(self.targets)
        if self.varying:
            sigma = sigma * (1.0 + 0.5 * np.sin(np.radians(self.angles) + 0.7))
        up, down = sigma, 1.1 * sigma
        if self.along == "random":
            up, down = up * rng.uniform(1.0, 2.0, self.targets), \
                down * rng.uniform(1.0, 2.0, self.targets)
        elif self.along == "ramp":
            ramp = np.linspace(1.0, 3.0, self.targets)
            up, down = up * ramp, down * ramp
        elif self.along == "one":
            one = np.ones(self.targets)
            one[self.targets // 3] = 3.0
            up, down = up * one, down * one
        elif self.along:
            raise ValueError(f"unknown σ along the axis {self.along}")
        self.sigma = {"up": up, "down": down}
        self.mu = {"up": self.f + 0.5 * self.b, "down": self.f - 0.5 * self.b}

    def readings(self, rng: np.random.Generator) -> list[tuple[float, int, str, float]]:
        """(target °, run, direction "+"/"-", deviation ″) in the order measured."""
        out = []
        index = np.arange(self.targets)
        for run in range(1, self.runs + 1):
            for name, sign, order in (("up", "+", index), ("down", "-", index[::-1])):
                for i in order:
                    x = self.mu[name][i] + self.sigma[name][i] * rng.standard_normal()
                    out.append((float(self.angles[i]), run, sign, float(x)))
        return out

    def truth(self) -> dict[str, float]:
        return true_figures(self.mu["up"], self.mu["down"], self.sigma["up"],
                            self.sigma["down"])


def true_figures(mu_up: np.ndarray, mu_down: np.ndarray, sigma_up: np.ndarray,
                 sigma_down: np.ndarray) -> dict[str, float]:
    """Every figure of the true distribution (see the module's docstring)."""
    out: dict[str, float] = {}
    for name, mu, sigma in (("up", mu_up, sigma_up), ("down", mu_down, sigma_down)):
        out[f"E_{name}"] = float(mu.max() - mu.min())
        out[f"R_{name}"] = float(4.0 * sigma.max())
        out[f"A_{name}"] = float((mu + 2 * sigma).max() - (mu - 2 * sigma).min())
    rev = mu_up - mu_down
    mid = 0.5 * (mu_up + mu_down)
    both = np.concatenate([mu_up, mu_down])
    out["E"] = float(both.max() - both.min())
    out["M"] = out["Pa"] = float(mid.max() - mid.min())
    out["B"] = out["U_max"] = float(np.abs(rev).max())
    out["B_mean"] = float(rev.mean())
    per_target = np.maximum.reduce([2 * sigma_up + 2 * sigma_down + np.abs(rev),
                                    4 * sigma_up, 4 * sigma_down])
    out["R"] = float(per_target.max())
    top = np.concatenate([mu_up + 2 * sigma_up, mu_down + 2 * sigma_down])
    bottom = np.concatenate([mu_up - 2 * sigma_up, mu_down - 2 * sigma_down])
    out["A"] = float(top.max() - bottom.min())
    scatter = 3.0 * (sigma_up + sigma_down)
    half = 0.5 * (np.abs(rev) + scatter)
    out["Ps_max"] = float(scatter.max())
    out["P"] = float((mid + half).max() - (mid - half).min())
    return out
