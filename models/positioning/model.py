"""Positioning of an axis (rotary or linear) against a reference: the readings as logged,
ISO 230-2:2014 and VDI/DGQ 3441 figures.

A reading is one approach of the axis to a target: the target position P_j, the run,
the approach direction and the positional deviation x_ij = P_ij − P_j (actual
position reached minus target, the ISO 230-2 sense: indicated − reference when the
axis's own scale is what positioned it). The ISO 230-2 figures come from
models.uncertainty.iso230; VDI/DGQ 3441 (1977) is evaluated here from the same
per-target statistics:

* mean position deviation  x̄_j = (x̄_j↑ + x̄_j↓) / 2,
* reversal span            U_j = |x̄_j↑ − x̄_j↓|,              U_max = max U_j,
* position scatter         Ps_j = 6 s̄_j, s̄_j = (s_j↑ + s_j↓) / 2,  Ps_max = max Ps_j,
* position deviation       Pa = max x̄_j − min x̄_j,
* position uncertainty     P = max (x̄_j + (U_j + Ps_j)/2) − min (x̄_j − (U_j + Ps_j)/2).

VDI/DGQ 3441 is a bidirectional test: with one direction only U and P cannot be
determined and are not given (x̄_j and s̄_j are then that direction's own).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.readings.resolution import coarse
from models.uncertainty.iso230 import Iso230Result, iso230_evaluate
from models.uncertainty.rounding import fixed_places

__all__ = ["DEVIATION_UNITS", "MIN_RUNS", "SIGN_CONVENTION", "SIGN_CONVENTION_TEXT", "STANDARDS",
           "TARGET_UNITS", "PositioningResult", "Vdi3441Result", "evaluate", "figure_text",
           "infer_directions",
           "vdi3441_evaluate"]

#: ISO 230-2's sign: x = actual − target. The axis's own scale indicates the target when it
#: stops and the reference reads the actual position, so x = reference − indicated: the
#: negative of an error of indication (the other workbenches' sign).
SIGN_CONVENTION = "actual_minus_target"
SIGN_CONVENTION_TEXT = QT_TR_NOOP("positional deviation x = actual position − target (ISO "
                                  "230-2), i.e. reference − indicated: the negative of an "
                                  "error of indication; compensation = −x")

#: ISO 230-2:2014 (and VDI/DGQ 3441): at least five runs in each direction at every target.
MIN_RUNS = 5

#: target unit → its symbol
TARGET_UNITS: dict[str, str] = {"deg": "°", "mm": " mm"}

#: deviation unit → (target unit it belongs to, deviation units per target unit, symbol)
DEVIATION_UNITS: dict[str, tuple[str, float, str]] = {
    "arcsec": ("deg", 3600.0, "\""),
    "urad": ("deg", math.pi / 180.0 * 1e6, " µrad"),
    "um": ("mm", 1e3, " µm"),
    "nm": ("mm", 1e6, " nm"),
}

#: the standard applied → its title on the certificate
STANDARDS: dict[str, str] = {
    "iso230-2": "ISO 230-2:2014",
    "vdi3441": "VDI/DGQ 3441:1977",
    "gb17421.2": QT_TR_NOOP("GB/T 17421.2-2016 (identical to ISO 230-2:2014)"),
}


def figure_text(value: float | None, symbol: str, decimals: int = 3) -> str:
    """A figure as the summary and the certificate print it (to ``decimals``: those of its
    coverage interval where it has one, models.uncertainty.conformity.interval_decimals);
    "not evaluated" when the readings could not determine it."""
    if value is None or not math.isfinite(value):
        return message(QT_TR_NOOP("not evaluated"))
    return f"{fixed_places(value, decimals)}{symbol}"


def infer_directions(targets: np.ndarray) -> np.ndarray:
    """The approach direction of each reading from the order of the targets alone.

    A reading approached a target from below (+1) when its target is above the
    previous one, from above (−1) when below; a target repeated at once is the turn
    of a bidirectional run (the axis overtravels and comes back), so the direction
    flips. The first reading takes the direction of the first step.
    """
    t = np.asarray(targets, dtype=float)
    out = np.ones(t.size)
    if t.size < 2:
        return out
    steps = np.sign(np.diff(t))
    nonzero = steps[steps != 0]
    out[0] = nonzero[0] if nonzero.size else 1.0
    for k in range(1, t.size):
        out[k] = steps[k - 1] if steps[k - 1] != 0 else -out[k - 1]
    return out


#: the pooled s, in steps of the readings as entered, up to which readings alike at a
#: target may be the rounding's chance (five readings: about 1e-4 of targets at 3 steps)
ALIKE_BY_CHANCE = 3.0

@dataclass(frozen=True)
class Vdi3441Result:
    """VDI/DGQ 3441 per target (x̄_j, U_j, Ps_j) and for the axis; ``None`` where the
    readings cannot determine a figure (U and P need both directions, Ps two runs)."""

    mean: np.ndarray
    reversal: np.ndarray | None
    scatter: np.ndarray | None
    P: float | None
    Ps_max: float | None
    Pa: float
    U_max: float | None

    def as_dict(self) -> dict[str, float | None]:
        return {"P": self.P, "Ps_max": self.Ps_max, "Pa": self.Pa, "U_max": self.U_max}


def _finite_or_none(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def vdi3441_evaluate(iso: Iso230Result) -> Vdi3441Result:
    """VDI/DGQ 3441 from the per-target statistics of an ISO 230-2 evaluation."""
    both = iso.forward is not None and iso.backward is not None
    if both:
        up, down = iso.forward, iso.backward
        mean = 0.5 * (up.mean + down.mean)
        reversal = np.abs(up.mean - down.mean)
        s_bar = 0.5 * (up.std + down.std)
    else:
        one = iso.forward if iso.forward is not None else iso.backward
        mean, reversal, s_bar = one.mean, None, one.std
    scatter = 6.0 * s_bar if np.any(np.isfinite(s_bar)) else None
    if not np.any(np.isfinite(mean)):  # no target approached both ways
        return Vdi3441Result(mean, None, None, None, None, float("nan"), None)
    pa = float(np.nanmax(mean) - np.nanmin(mean))
    p = None
    if reversal is not None and scatter is not None:
        half = 0.5 * (reversal + scatter)
        p = _finite_or_none(float(np.nanmax(mean + half) - np.nanmin(mean - half)))
    return Vdi3441Result(
        mean, reversal, scatter, p,
        None if scatter is None else _finite_or_none(float(np.nanmax(scatter))), pa,
        None if reversal is None else _finite_or_none(float(np.nanmax(reversal))))


@dataclass
class PositioningResult:
    """Readings in approach order and their evaluation; deviations in ``deviation_unit``,
    targets in ``target_unit``."""

    targets: np.ndarray  # per reading
    runs: np.ndarray
    directions: np.ndarray  # ±1 per reading
    deviations: np.ndarray
    rows: np.ndarray  # the sheet row (0-based) of each reading
    iso: Iso230Result
    vdi: Vdi3441Result
    target_unit: str
    deviation_unit: str
    standard: str
    least_runs: dict[str, int]  # direction ("up"/"down") → fewest runs at any target
    warnings: list[str] = field(default_factory=list)
    # RepeatedReadings when each reading is the mean of n (setting readings per point), with
    # each averaged reading's s/√n in the deviation unit as repeat_s_mean
    repeats: object = None
    repeat_s_mean: np.ndarray | None = None
    # the budget's inputs the readings cannot show (analysis.BUDGET_INPUTS; 0: not stated)
    inputs: dict[str, float] = field(default_factory=dict)
    incomplete: object = None  # the last unit in progress (models.readings.incomplete), left out
    # the step of the readings as entered, in the deviation unit (models.readings.resolution);
    # None when they lie on no grid of six decimals
    readings_step: float | None = None
    # the sheet rows (0-based) of readings left out for a deviation beyond the limit (a
    # reading at another position than its target's: analysis._beyond_limit)
    left_out: tuple[int, ...] = ()

    @property
    def positions(self) -> np.ndarray:
        return self.iso.positions

    @property
    def symbol(self) -> str:
        return DEVIATION_UNITS[self.deviation_unit][2]

    @property
    def target_symbol(self) -> str:
        return TARGET_UNITS[self.target_unit]

    @property
    def bidirectional(self) -> bool:
        return self.iso.forward is not None and self.iso.backward is not None

    @property
    def minimum_runs_met(self) -> bool:
        return all(n >= MIN_RUNS for n in self.least_runs.values())

    def per_target_table(self, printed: dict[str, list[str]] | None = None
                         ) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
        """(header, rows) of the per-target statistics as the window lists them; ``printed``:
        the certificate's cells by its header (models.positioning.report.printed_per_target),
        shown for x̄, s, B_i and M_i as printed there (without: to 0.001)."""
        printed = printed or {}
        sym = self.symbol.strip()
        header = ["target (" + self.target_symbol.strip() + ")"]
        present = self.directions_present()
        for name, _, _ in present:
            arrow = "↑" if name == "up" else "↓"
            header += [f"x̄{arrow} ({sym})", f"s{arrow} ({sym})", f"n{arrow}"]
        if self.bidirectional:
            header += [f"B_i ({sym})", f"M_i ({sym})", f"R_i ({sym})"]

        def cell(value: float, signed: bool = True) -> str:
            # a zero unsigned, as the certificate prints it (models/uncertainty/rounding.py)
            return "—" if not np.isfinite(value) else fixed_places(float(value), 3,
                                                                    "+" if signed else "")
        rows = []
        def shown(key: str, i: int, value: float, signed: bool = True) -> str:
            cells = printed.get(key)
            return cell(value, signed) if cells is None else cells[i]

        for i, target in enumerate(self.positions):
            row = [f"{target:g}"]
            for name, _, stats in present:
                arrow = "↑" if name == "up" else "↓"
                row += [shown(f"x̄{arrow}", i, stats.mean[i]),
                        shown(f"s{arrow}", i, stats.std[i], False), str(stats.runs[i])]
            if self.bidirectional:
                rbi = self.iso.bidirectional_repeatability
                row += [shown("B_i", i, self.iso.reversal[i]),
                        shown("M_i", i, self.iso.bidirectional_mean[i]),
                        "—" if rbi is None else cell(rbi[i], False)]
            rows.append(tuple(row))
        return tuple(header), rows

    def pooled_s(self) -> float:
        """The standard deviation of the runs pooled over every target and direction
        approached at least twice (nan when none was)."""
        nu = np.concatenate([stats.runs - 1.0 for _, _, stats in self.directions_present()])
        s = np.concatenate([stats.std for _, _, stats in self.directions_present()])
        used = (nu > 0) & np.isfinite(s)
        return (float(np.sqrt(np.sum(nu[used] * s[used] ** 2) / np.sum(nu[used])))
                if np.any(used) else math.nan)

    @property
    def coarse_readings(self) -> bool:
        """Whether the readings were entered coarser than they scatter (models.readings
        .resolution.coarse): each mean then carries a rounding error its s does not show."""
        return self.without_scatter or coarse(self.readings_step, self.pooled_s())

    @property
    def without_scatter(self) -> bool:
        """Whether every target's readings came out alike in every direction (s = 0 at every
        target approached more than once): the readings show no scatter at all."""
        return self.pooled_s() == 0.0

    def alike_targets(self, stats) -> np.ndarray:
        """Where the runs of one direction (``stats``) read alike at a target approached
        at least twice (s = 0) while the readings elsewhere scatter and are not entered
        coarser than they do: readings that do not vary at one target are copied or
        rounded apart from the rest, not a repeatability of 0 (an audit: one such target
        among targets scattering by 0.25–1.1, its U the smallest of all, the non-repeatable
        inputs' alone). A boolean mask over the targets."""
        pooled = self.pooled_s()
        if not (pooled > 0.0) or self.coarse_readings:
            return np.zeros(stats.std.shape, dtype=bool)
        return (stats.runs >= 2) & (stats.std == 0.0)

    def alike_unexplained(self, stats) -> np.ndarray:
        """:meth:`alike_targets` where the rounding of the readings as entered cannot explain
        it: no step found, or a pooled s above :data:`ALIKE_BY_CHANCE` steps. Five readings
        to 0.1″ scattering by 0.1″ come out alike at a target by chance (13 % of directions
        of 13 targets, a reviewer's simulation; 27 % at 0.8 step): U still takes the pooled
        s there, but only these are named in a warning."""
        step = self.readings_step
        if step is not None and self.pooled_s() <= ALIKE_BY_CHANCE * step:
            return np.zeros(stats.std.shape, dtype=bool)
        return self.alike_targets(stats)

    def repeatability(self, stats) -> np.ndarray:
        """The runs' s at each target in one direction as U counts it: the s pooled over
        every target and direction where :meth:`alike_targets` (a warning says so)."""
        return np.where(self.alike_targets(stats), self.pooled_s(), stats.std)

    def directions_present(self) -> list[tuple[str, int, object]]:
        """("up", +1, stats) and/or ("down", −1, stats) for the directions measured."""
        out = []
        if self.iso.forward is not None:
            out.append(("up", 1, self.iso.forward))
        if self.iso.backward is not None:
            out.append(("down", -1, self.iso.backward))
        return out


def evaluate(targets: np.ndarray, runs: np.ndarray, directions: np.ndarray,
             deviations: np.ndarray, rows: np.ndarray, target_unit: str, deviation_unit: str,
             standard: str, warnings: list[str]) -> PositioningResult:
    """ISO 230-2 and VDI/DGQ 3441 of checked readings (see analysis.py for the checks)."""
    iso = iso230_evaluate(targets, deviations, directions, decimals=9)
    least = {}
    for name, stats in (("up", iso.forward), ("down", iso.backward)):
        if stats is None:
            continue
        least[name] = int(np.min(stats.runs))
    return PositioningResult(targets, runs, directions, deviations, rows, iso,
                             vdi3441_evaluate(iso), target_unit, deviation_unit, standard,
                             least, warnings)
