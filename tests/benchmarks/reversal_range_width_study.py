"""The narrowest correct interval of B, E↑ and E against ours (#39's "not more than 1.6× what a
correct interval needs"; width81b, the sibling of least_favourable_width_study.py's
narrowest section for R↑ and A↑, which are made of σ: B and the ranges E↑, E are maxima and
ranges of the MEANS, and their bias comes from the curve as much as from σ).

The rig: per target and direction x̄ ~ N(μ, σ²/n) and s ~ σ √(χ²_ν/ν), 12 targets, 5 runs each
way (ν = 4), numpy only, seeded. σ = 1 at the quiet targets; a mean's standard error
se = σ/√n, a reversal's se_b = σ √(2/n).

Patterns (each figure's own grid; every one with σ alike, the pattern's first target's σ
× 2 or × 3, or a quiet target's (the last) × 3, both directions):

* B = max |μ↑ − μ↓|: the reversal even, β0 = 0, 1, 3 or 10 se_b at every target (a flat
  reversal, where the measured B is biased high by the noise), or one, two or three targets
  Δ = 1, 2, 3, 4, 6, 10 se_b above an even β0 of 0 or 10 se_b;
* E↑ = range of μ↑: the curve flat, or one target Δ se above the rest (a crest), a crest and
  a trough (one target Δ below), two or three crest targets and the trough, Δ as B's;
* E = range of μ↑ and μ↓ together: E↑'s curves with the reversal 0 or an even 10 se_b.

"Narrowest correct": the narrowest member of a simple family whose miss on each side is at
most the tail of the probability PRINTED beside the figure (B 95.45 %; E↑ 92 %, E 92.5 %:
models.uncertainty.figure_intervals.ACHIEVED) in EVERY pattern, on NARROW_N draws a pattern:

* B: upper end max_i(|b_i| + z_u u_i), u_i = √((s↑² + s↓²)/n); lower end the larger of
  max_i(|b_i| − z_l u_i) and the mean reversal's |b̄| − z_m u(b̄) (z_m = ∞: none), as the
  product's lower end is made. Each target's error is Studentised by its own u_i, so σ
  scaled at a target moves only which target makes the maximum: no Cochran switch;
* E↑, E: upper end max(x̄ + z_u u) − min(x̄ − z_u u), lower end max(x̄ − z_l u) − min(x̄ +
  z_l u) (at least 0), u = s/√n of each mean, over the figure's 12 (24) means;
* each end also with a shifted pivot, the measured figure ± c × the pooled u (the upper end
  the lower of the two, the lower end the higher; c = ∞: not used);
* E↑, E: each end may switch on Cochran's C of the figure's u (ISO 5725-2; critical values
  from alike σ at level 0.05 or 0.2): where C rejects, the unswitched design narrowest on a
  flat curve with one target's σ × 3, where it accepts a pivot factor and own factor of its
  own (both branches' misses counted together).

The narrowest at each evaluation pattern is the feasible design (each end its own) whose
mean end there is nearest the value.

An end misses where its factor is below the draw's root (the factor at which the end equals
the truth: closed forms over the targets or their pairs), so each pattern's least factor is
a quantile of its roots: the narrowest is chosen on the draws it passes (a bound from below
of the narrowest correct width); its worst miss is estimated again on VERIFY_N fresh draws.

"Ours": the product's interval, models.uncertainty.figure_intervals.figure_intervals called
as models.positioning.report.figure_uncertainties calls it for readings with no Type B inputs
(seeded from the readings), on OURS_TESTS draws of each evaluation pattern: the flat curve
and even reversal (β0 = 0 and 5 se_b) with σ alike and with one target's σ × 3, and one
target (B: its reversal; E↑, E: a crest, with a trough) standing 3 and 10 se clear. Widths:
ours' mean over its tests, the narrowest's mean over EVAL_N draws, each ÷ the oracle spread
(2 z × the standard deviation of measured − truth over EVAL_N draws of the pattern, z the
normal factor of the printed tail). Ours' mean width has a relative Monte Carlo standard
deviation of about 1–3 % at 200 tests.

    nice -n 10 python tests/benchmarks/reversal_range_width_study.py

About 6–7 min at nice 10 on the shared 2-core machine (346–429 s at a load of 3.6+; ours' 1200
analyses about 100 s of it).
"""

from __future__ import annotations

import itertools
import math
import sys
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np
from scipy.special import ndtr, ndtri

from models.uncertainty.figure_intervals import (
    ACHIEVED,
    figure_intervals,
    readings_seed,
    world_truth,
)
from tests.benchmarks.least_favourable_width_study import cochran_c

M, RUNS = 12, 5
NU = RUNS - 1
SE = 1.0 / math.sqrt(RUNS)
SE_B = math.sqrt(2.0 / RUNS)
#: the probability the analysis asks for (the budget's: k = 2)
ASKED = float(ndtr(2.0) - ndtr(-2.0))
#: the probability printed beside each figure (its interval at ASKED reaches this one)
PRINTED = {"B": 0.9545, "E_up": ACHIEVED["E_up"], "E": ACHIEVED["E"]}
FIGURE_NAMES = {"B": "B", "E_up": "E↑", "E": "E"}
NARROW_N, VERIFY_N, EVAL_N, OURS_TESTS = 100_000, 100_000, 20_000, 200
CHUNK = 12_500
DELTAS = (1.0, 2.0, 3.0, 4.0, 6.0, 10.0)
#: σ along the axis: (name, target, factor)
SIGMA_PATTERNS = (("alike", 0, 1.0), ("first x 2", 0, 2.0), ("first x 3", 0, 3.0),
                  ("quiet x 3", M - 1, 3.0))
#: B's mean-reversal factors (inf: no mean bound)
MEAN_FACTORS = (math.inf, 2.5)


@dataclass(frozen=True)
class Pattern:
    name: str
    mu_up: np.ndarray
    mu_down: np.ndarray
    sigma: np.ndarray  # both directions

    def truth(self, figure: str) -> float:
        if figure == "B":
            return float(np.max(np.abs(self.mu_up - self.mu_down)))
        if figure == "E_up":
            return float(np.ptp(self.mu_up))
        both = np.concatenate([self.mu_up, self.mu_down])
        return float(np.ptp(both))


def sigma_along(target: int, factor: float) -> np.ndarray:
    sigma = np.ones(M)
    sigma[target] = factor
    return sigma


def curve(shape: str, delta: float) -> np.ndarray:
    """E's curves in se: flat, a crest, a crest and a trough, two or three crests and the
    trough."""
    c = np.zeros(M)
    if shape == "flat":
        return c
    tops = {"crest": 1, "crest+trough": 1, "two": 2, "three": 3}[shape]
    c[:tops] = delta * SE
    if shape != "crest":
        c[M // 2] = -delta * SE
    return c


def reversal(shape: str, base: float, delta: float) -> np.ndarray:
    """B's reversals in se_b: even (base), or one, two or three targets delta above it."""
    b = np.full(M, base * SE_B)
    tops = {"even": 0, "one": 1, "two": 2, "three": 3}[shape]
    b[:tops] += delta * SE_B
    return b


def curves(figure: str) -> Iterator[tuple[str, np.ndarray, np.ndarray]]:
    """(name, μ↑, μ↓) of every curve of a figure's grid."""
    if figure == "B":
        for base in (0.0, 1.0, 3.0, 10.0):
            b = reversal("even", base, 0.0)
            yield f"even {base:g}", 0.5 * b, -0.5 * b
        for shape in ("one", "two", "three"):
            for base in (0.0, 10.0):
                for delta in DELTAS:
                    b = reversal(shape, base, delta)
                    yield f"{shape} {delta:g} above {base:g}", 0.5 * b, -0.5 * b
        return
    shapes = [("flat", 0.0)] + [(s, d) for s in ("crest", "crest+trough", "two", "three")
                                 for d in DELTAS]
    for rev in ((0.0,) if figure == "E_up" else (0.0, 10.0)):
        for shape, delta in shapes:
            c = curve(shape, delta)
            yield (f"{shape} {delta:g}" + (f", reversal {rev:g}" if rev else ""),
                   c + 0.5 * rev * SE_B, c - 0.5 * rev * SE_B)


def grid(figure: str) -> Iterator[Pattern]:
    for name, up, down in curves(figure):
        for sname, target, factor in SIGMA_PATTERNS:
            yield Pattern(f"{name}, {sname}", up, down, sigma_along(target, factor))


def evaluation_patterns() -> list[tuple[str, Pattern]]:
    """The patterns ours is measured on (each gives B, E↑ and E at once)."""
    out = []
    for label, base, target, factor, delta in (
            ("flat, σ alike", 0.0, 0, 1.0, 0.0), ("flat, one σ x 3", 0.0, 0, 3.0, 0.0),
            ("even reversal 5, σ alike", 5.0, 0, 1.0, 0.0),
            ("even reversal 5, one σ x 3", 5.0, 0, 3.0, 0.0),
            ("one 3 se clear, σ alike", 5.0, 0, 1.0, 3.0),
            ("one 10 se clear, σ alike", 5.0, 0, 1.0, 10.0)):
        c = curve("crest+trough", delta) if delta else curve("flat", 0.0)
        b = reversal("one", base, delta)
        out.append((label, Pattern(label, c + 0.5 * b, c - 0.5 * b,
                                   sigma_along(target, factor))))
    return out


@dataclass
class Draws:
    """Standardised draws: x̄ = μ + z σ, s = w σ (z ~ N(0, 1/n), w ~ √(χ²_ν/ν))."""

    z_up: np.ndarray
    z_down: np.ndarray
    w_up: np.ndarray
    w_down: np.ndarray

    @classmethod
    def make(cls, rng: np.random.Generator, count: int) -> Draws:
        def z():
            return (rng.standard_normal((count, M)) * SE).astype(np.float32)

        def w():
            return np.sqrt(rng.chisquare(NU, (count, M)) / NU).astype(np.float32)

        return cls(z(), z(), w(), w())

    def at(self, p: Pattern, rows: slice = slice(None)):
        """x̄↑, x̄↓, s↑, s↓ of the pattern."""
        sig = p.sigma.astype(np.float32)
        return (p.mu_up.astype(np.float32) + self.z_up[rows] * sig,
                p.mu_down.astype(np.float32) + self.z_down[rows] * sig,
                self.w_up[rows] * sig, self.w_down[rows] * sig)

    @property
    def count(self) -> int:
        return self.z_up.shape[0]


def figure_terms(figure: str, x_up, x_down, s_up, s_down):
    """(values, u, s for Cochran's C) of the figure's means (E↑: the 12 up; E: the 24)."""
    if figure == "E_up":
        return x_up, s_up * np.float32(SE), s_up
    values = np.concatenate([x_up, x_down], axis=1)
    s = np.concatenate([s_up, s_down], axis=1)
    return values, s * np.float32(SE), s


def roots(figure: str, p: Pattern, draws: Draws) -> dict[str, np.ndarray]:
    """Per draw and component of an end (:data:`COMPONENTS`), the factor at which that
    component equals the truth: a component whose factor is below its root misses (an upper
    end's below the truth, a lower end's above it)."""
    truth = np.float32(p.truth(figure))
    parts: dict[str, list[np.ndarray]] = {}
    for start in range(0, draws.count, CHUNK):
        x_up, x_down, s_up, s_down = draws.at(p, slice(start, start + CHUNK))
        value = measured(figure, x_up, x_down)
        if figure == "B":
            b = np.abs(x_up - x_down)
            u = np.sqrt((s_up**2 + s_down**2) / RUNS)
            pooled = np.sqrt(np.mean(s_up**2 + s_down**2, axis=1) / RUNS)
            got = {"up own": np.min((truth - b) / u, axis=1),
                   "low own": np.max((b - truth) / u, axis=1),
                   "low mean": (np.abs(np.mean(x_up - x_down, axis=1)) - truth)
                   / (pooled / math.sqrt(M))}
        else:
            v, u, _ = figure_terms(figure, x_up, x_down, s_up, s_down)
            diff = v[:, :, None] - v[:, None, :]
            pair = u[:, :, None] + u[:, None, :]
            pooled = np.sqrt(np.mean(u**2, axis=1))
            got = {"up own": np.min((truth - diff) / pair, axis=(1, 2)),
                   "low own": np.max((diff - truth) / pair, axis=(1, 2)),
                   "c": cochran_c(u)}
        got["up pivot"] = (truth - value) / pooled
        got["low pivot"] = (value - truth) / pooled
        for key, part in got.items():
            parts.setdefault(key, []).append(part)
    return {key: np.concatenate(part) for key, part in parts.items()}


def least_factor(r: np.ndarray, allowed: int) -> float:
    """The least factor that misses in at most ``allowed`` draws (miss: factor < root)."""
    if allowed >= r.size:
        return -math.inf
    return float(np.partition(r, r.size - 1 - allowed)[r.size - 1 - allowed])


#: an end's components after its own bound (max_i(|b_i| ± z u_i), max(x̄ ± z u) − min(x̄ ∓
#: z u)), each with the factors searched (inf: the component not used): the measured
#: figure ± c × the pooled standard uncertainty (a shifted pivot; the upper end the lower
#: of the two, the lower end the higher) and B's mean-reversal bound |b̄| − z_m u(b̄)
PIVOT_UP = (math.inf,) + tuple(np.arange(0.5, 8.01, 0.5))
PIVOT_LOW = (math.inf,) + tuple(np.arange(1.0, 12.01, 0.5))
COMPONENTS = {"up": (("pivot", PIVOT_UP),),
              "low": (("pivot", PIVOT_LOW),)}
B_LOW = (("pivot", PIVOT_LOW), ("mean", MEAN_FACTORS))


@dataclass(frozen=True)
class Design:
    """An end: its own bound's factor and the other components' ({name: factor})."""

    own: float
    others: tuple[tuple[str, float], ...] = ()

    def text(self) -> str:
        return f"{self.own:.3f}" + "".join(f", {name} {f:.2f}" for name, f in self.others
                                           if math.isfinite(f))

    def misses(self, r: dict[str, np.ndarray], side: str) -> np.ndarray:
        missed = self.own < r[f"{side} own"]
        for name, f in self.others:
            if math.isfinite(f):
                missed = missed | (f < r[f"{side} {name}"])
        return missed


@dataclass(frozen=True)
class Gated:
    """An end that switches on Cochran's C of the figure's s: ``accept`` where C is at most
    ``crit`` (level ``level`` where σ is alike), ``reject`` above it."""

    accept: Design
    reject: Design
    crit: float
    level: float

    def text(self) -> str:
        return (f"{self.accept.text()} where C accepts (level {self.level:g}), "
                f"{self.reject.text()} where it rejects")

    def misses(self, r: dict[str, np.ndarray], side: str) -> np.ndarray:
        return np.where(r["c"] > self.crit, self.reject.misses(r, side),
                        self.accept.misses(r, side))


#: Cochran's C levels of the gated designs (E↑, E)
LEVELS = (0.05, 0.2)


def gated_candidates(side: str, stored, allowed: int, fallback: Design, crits
                     ) -> list[Gated]:
    """Designs that take ``fallback`` where C rejects and, where it accepts, a pivot factor
    of the grid with the least own factor that keeps every pattern's misses (both branches
    together) within ``allowed``."""
    out = []
    pivots = PIVOT_UP if side == "up" else PIVOT_LOW
    for level, crit in crits:
        for f in pivots:
            need = -math.inf
            for r in stored:
                rejected = r["c"] > crit
                missed = (rejected & fallback.misses(r, side)) | (
                    ~rejected & (f < r[f"{side} pivot"]))
                budget = allowed - int(np.sum(missed))
                if budget < 0:
                    need = math.inf
                    break
                need = max(need, least_factor(r[f"{side} own"][~rejected & ~missed],
                                              budget))
            if math.isfinite(need):
                out.append(Gated(Design(need, (("pivot", f),)), fallback, crit, level))
    return out


def candidates(figure: str, side: str, stored, allowed: int) -> list[Design]:
    """Every feasible design of an end: for each choice of the other components' factors,
    the least own factor whose end misses in at most ``allowed`` draws of every pattern."""
    comps = B_LOW if (figure, side) == ("B", "low") else COMPONENTS[side]
    out = []
    for factors in itertools.product(*(grid_ for _, grid_ in comps)):
        need = -math.inf
        for r in stored:
            missed = np.zeros(r[f"{side} own"].shape, bool)
            for (name, _), f in zip(comps, factors, strict=True):
                if math.isfinite(f):
                    missed |= f < r[f"{side} {name}"]
            budget = allowed - int(np.sum(missed))
            if budget < 0:
                need = math.inf
                break
            need = max(need, least_factor(r[f"{side} own"][~missed], budget))
        if math.isfinite(need):
            out.append(Design(need, tuple((name, f) for (name, _), f
                                          in zip(comps, factors, strict=True))))
    return out


def end_values(figure: str, draws: Draws, p: Pattern, side: str, design: Design | Gated
               ) -> np.ndarray:
    """An end of a design on the draws of a pattern."""
    x_up, x_down, s_up, s_down = draws.at(p)
    if isinstance(design, Gated):
        u = figure_terms(figure, x_up, x_down, s_up, s_down)[1]
        return np.where(cochran_c(u) > design.crit,
                        end_values(figure, draws, p, side, design.reject),
                        end_values(figure, draws, p, side, design.accept))
    value = measured(figure, x_up, x_down)
    sign = 1.0 if side == "up" else -1.0
    if figure == "B":
        b = np.abs(x_up - x_down)
        u = np.sqrt((s_up**2 + s_down**2) / RUNS)
        pooled = np.sqrt(np.mean(s_up**2 + s_down**2, axis=1) / RUNS)
        end = np.max(b + sign * design.own * u, axis=1)
    else:
        v, u, _ = figure_terms(figure, x_up, x_down, s_up, s_down)
        pooled = np.sqrt(np.mean(u**2, axis=1))
        end = (np.max(v + sign * design.own * u, axis=1)
               - np.min(v - sign * design.own * u, axis=1))
    for name, f in design.others:
        if not math.isfinite(f):
            continue
        if name == "pivot":
            other = value + sign * f * pooled
        else:  # B's mean reversal
            other = np.abs(np.mean(x_up - x_down, axis=1)) - f * pooled / math.sqrt(M)
        end = np.minimum(end, other) if side == "up" else np.maximum(end, other)
    return np.maximum(end, 0.0)


def measured(figure: str, x_up, x_down) -> np.ndarray:
    if figure == "B":
        return np.max(np.abs(x_up - x_down), axis=-1)
    if figure == "E_up":
        return np.ptp(x_up, axis=-1)
    return np.ptp(np.concatenate([x_up, x_down], axis=-1), axis=-1)


def tail_of(figure: str) -> float:
    return 0.5 * (1.0 - PRINTED[figure])


def narrowest(figure: str, draws: Draws, eval_draws: Draws | None = None
              ) -> tuple[dict[str, list], list]:
    """Every feasible design per end over the figure's grid, on ``draws``; the grid's
    (pattern, roots). E↑, E with ``eval_draws``: also the gated designs whose branch where C
    rejects is the ungated design narrowest where one σ is × 3 on a flat curve."""
    allowed = math.floor(tail_of(figure) * draws.count)
    stored = [(p, roots(figure, p, draws)) for p in grid(figure)]
    designs: dict[str, list] = {side: candidates(figure, side, [r for _, r in stored], allowed)
                                for side in ("up", "low")}
    if figure != "B" and eval_draws is not None:
        alike = cochran_c(np.sqrt(np.random.default_rng([81, 3]).chisquare(
            NU, (draws.count, M if figure == "E_up" else 2 * M)) / NU))
        crits = [(level, float(np.quantile(alike, 1.0 - level))) for level in LEVELS]
        noisy = dict(evaluation_patterns())["flat, one σ x 3"]
        for side in ("up", "low"):
            values = [(float(np.mean(end_values(figure, eval_draws, noisy, side, d))), d)
                      for d in designs[side]]
            fallback = (min(values, key=lambda t: t[0]) if side == "up"
                        else max(values, key=lambda t: t[0]))[1]
            designs[side] += gated_candidates(side, [r for _, r in stored], allowed, fallback,
                                              crits)
    return designs, stored


def best_at(figure: str, draws: Draws, p: Pattern, designs: dict[str, list]
            ) -> tuple[Design | Gated, Design | Gated, float]:
    """The feasible designs' narrowest at a pattern (each end its own: the upper end's
    lowest mean, the lower end's highest), and its mean width."""
    chosen = []
    for side in ("up", "low"):
        values = [(float(np.mean(end_values(figure, draws, p, side, d))), d)
                  for d in designs[side]]
        chosen.append(min(values, key=lambda t: t[0]) if side == "up"
                      else max(values, key=lambda t: t[0]))
    return chosen[0][1], chosen[1][1], chosen[0][0] - chosen[1][0]


def worst_misses(figure: str, stored, designs: list) -> list[tuple[str, float, str, float]]:
    """Each design's (upper, lower) worst miss above and below over the grid ((pattern,
    roots) of it)."""
    names = [["", ""] for _ in designs]
    shares = [[0.0, 0.0] for _ in designs]
    for p, r in stored:
        for name, share, (up, low) in zip(names, shares, designs, strict=True):
            for at, (side, design) in enumerate((("up", up), ("low", low))):
                got = float(np.mean(design.misses(r, side)))
                if got > share[at]:
                    name[at], share[at] = p.name, got
    return [(n[0], s[0], n[1], s[1]) for n, s in zip(names, shares, strict=True)]


def ours_widths(patterns: list[tuple[str, Pattern]], tests: int, rng: np.random.Generator
                ) -> dict[str, dict[str, tuple[float, int, int]]]:
    """Per pattern and figure: ours' mean width, misses below and above (the product's
    interval on ``tests`` draws of the pattern)."""
    out: dict[str, dict[str, tuple[float, int, int]]] = {}
    runs = {"up": np.full(M, float(RUNS)), "down": np.full(M, float(RUNS))}
    for label, p in patterns:
        draws = Draws.make(rng, tests)
        x_up, x_down, s_up, s_down = (np.asarray(a, float) for a in draws.at(p))
        widths: dict[str, list[float]] = {k: [] for k in PRINTED}
        missed = {k: [0, 0] for k in PRINTED}
        for i in range(tests):
            x = {"up": x_up[i], "down": x_down[i]}
            s = {"up": s_up[i], "down": s_down[i]}
            got = figure_intervals(x, s, runs, ASKED, None,
                                   readings_seed(x_up[i], x_down[i], s_up[i], s_down[i]),
                                   figures=world_truth(x, s), pair_envelope=True,
                                   pair_bias_level=True)
            for key in PRINTED:
                iv, truth = got[key], p.truth(key)
                widths[key].append(iv.high - iv.low)
                missed[key][0] += int(iv.low > truth)
                missed[key][1] += int(iv.high < truth)
        out[label] = {k: (float(np.mean(widths[k])), missed[k][0], missed[k][1])
                      for k in PRINTED}
    return out


def oracle_spread(figure: str, p: Pattern, draws: Draws) -> float:
    x_up, x_down, _, _ = draws.at(p)
    err = measured(figure, x_up, x_down) - p.truth(figure)
    return 2.0 * float(ndtri(1.0 - tail_of(figure))) * float(np.std(err, ddof=1))


def study(narrow_n: int = NARROW_N, verify_n: int = VERIFY_N, eval_n: int = EVAL_N,
          tests: int = OURS_TESTS, seed: int = 81, figures=tuple(PRINTED),
          only: tuple[str, ...] | None = None):
    """Per figure: (patterns searched, rows), rows per evaluation pattern: (label,
    ours/oracle, narrowest/oracle, ours/narrowest, ours' misses below and above of
    ``tests``, the narrowest's designs (upper, lower), their worst misses on the search's
    draws and on ``verify_n`` fresh ones). ``tests`` 0: ours not run (nan); ``only``: those
    evaluation patterns alone (by label)."""
    rng = np.random.default_rng(seed)
    search = Draws.make(rng, narrow_n)
    evaluation = Draws.make(rng, eval_n)
    patterns = [(label, p) for label, p in evaluation_patterns()
                if only is None or label in only]
    ours = ours_widths(patterns, tests, np.random.default_rng([seed, 1])) if tests else {}
    fresh = Draws.make(np.random.default_rng([seed, 2]), verify_n) if verify_n else None
    out = {}
    for figure in figures:
        designs, stored = narrowest(figure, search, evaluation)
        rows: list[list] = []
        for label, p in patterns:
            spread = oracle_spread(figure, p, evaluation)
            up, low, width = best_at(figure, evaluation, p, designs)
            mine, below, above = (ours[label][figure] if label in ours
                                  else (math.nan, 0, 0))
            rows.append([label, mine / spread, width / spread, mine / width, below, above,
                         (up, low)])
        chosen = list(dict.fromkeys(row[-1] for row in rows))
        found = dict(zip(chosen, worst_misses(figure, stored, chosen), strict=True))
        del stored
        again: dict = {}
        if fresh is not None:
            again = dict(zip(chosen, worst_misses(
                figure, [(p, roots(figure, p, fresh)) for p in grid(figure)], chosen),
                strict=True))
        out[figure] = (sum(1 for _ in grid(figure)),
                       [tuple(row) + (found[row[-1]], again.get(row[-1])) for row in rows])
    return out


def main(out=sys.stdout) -> None:
    for figure, (count, rows) in study().items():
        tail = tail_of(figure)
        out.write(f"{FIGURE_NAMES[figure]} (printed {100 * PRINTED[figure]:g} %, tail "
                  f"{tail:.5f}; {count} patterns, {NARROW_N} draws each, a miss's Monte Carlo "
                  f"sd {math.sqrt(tail * (1 - tail) / NARROW_N):.5f})\n")
        for label, mine, narrow, ratio, below, above, (up, low), found, again in rows:
            out.write(f"  {label:28s} ours/oracle {mine:5.2f}  narrowest/oracle {narrow:5.2f}"
                      f"  ours/narrowest {ratio:5.2f}  (ours missed below {below}, above "
                      f"{above} of {OURS_TESTS})\n")
            out.write(f"      narrowest: upper {up.text()}; lower {low.text()}; worst miss "
                      f"above {found[1]:.4f} ({found[0]}), below {found[3]:.4f} ({found[2]})")
            if again is not None:
                out.write(f"; fresh above {again[1]:.4f} ({again[0]}), below {again[3]:.4f} "
                          f"({again[2]})")
            out.write("\n")


if __name__ == "__main__":
    main()
