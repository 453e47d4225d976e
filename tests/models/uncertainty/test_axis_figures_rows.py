"""The ISO 230-2 and VDI/DGQ 3441 figures of many tests at once (``axis_figures``, through
which every bootstrap trial of a figure's interval passes) are each test's figures as the
standards define them, computed here target by target in plain Python: for tests in rows
and in chunks of rows (the calibration's inner draws), one direction or both, with ties and
with a target's mean far off at either end (the bidirectional figures are made from each
direction's extremes, not from the directions' values joined)."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from models.uncertainty.figure_intervals import axis_figures


def _standard_figures(up: list[float], s_up: list[float], down: list[float] | None = None,
                      s_down: list[float] | None = None) -> dict[str, float]:
    """One test's figures from its targets' means and s, ISO 230-2 (E, M, B, R, A and
    their one-way forms) and VDI/DGQ 3441 (Pa, Ps, U, P)."""
    out = {"E_up": max(up) - min(up), "R_up": max(4 * s for s in s_up),
           "A_up": max(x + 2 * s for x, s in zip(up, s_up, strict=True))
           - min(x - 2 * s for x, s in zip(up, s_up, strict=True))}
    if down is None:
        out["Pa"] = out["E_up"]
        out["Ps_max"] = max(6 * s for s in s_up)
        return out
    out.update({"E_down": max(down) - min(down), "R_down": max(4 * s for s in s_down),
                "A_down": max(x + 2 * s for x, s in zip(down, s_down, strict=True))
                - min(x - 2 * s for x, s in zip(down, s_down, strict=True))})
    pairs = list(zip(up, s_up, down, s_down, strict=True))
    middle = [(u + d) / 2 for u, _, d, _ in pairs]
    reversal = [u - d for u, _, d, _ in pairs]
    out["E"] = max(up + down) - min(up + down)
    out["M"] = max(middle) - min(middle)
    out["B"] = max(abs(b) for b in reversal)
    out["B_mean"] = sum(reversal) / len(reversal)
    out["R"] = max(max(2 * su + 2 * sd + abs(u - d), 4 * su, 4 * sd) for u, su, d, sd in pairs)
    out["A"] = (max(x + 2 * s for x, s in zip(up + down, s_up + s_down, strict=True))
                - min(x - 2 * s for x, s in zip(up + down, s_up + s_down, strict=True)))
    scatter = [6 * (su + sd) / 2 for _, su, _, sd in pairs]
    out["Pa"] = out["M"]
    out["Ps_max"] = max(scatter)
    out["U_max"] = out["B"]
    out["P"] = (max(m + (abs(b) + p) / 2 for m, b, p in zip(middle, reversal, scatter, strict=True))
                - min(m - (abs(b) + p) / 2 for m, b, p in zip(middle, reversal, scatter, strict=True)))
    return out


def _tests(rng: np.random.Generator, shape: tuple[int, ...], m: int) -> dict[str, tuple]:
    """Both directions' means and s of tests ``shape``: a bow, a backlash, noise; in some
    tests one target far off above or below in one direction only, in some ties."""
    bow = np.sin(np.linspace(0.0, np.pi, m))
    up = bow + 0.2 * rng.standard_normal(shape + (m,))
    down = bow - 0.3 + 0.2 * rng.standard_normal(shape + (m,))
    flat = up.reshape(-1, m)
    flat[0::3, m // 2] += 5.0  # far off above, going up
    down.reshape(-1, m)[1::3, 0] -= 5.0  # far off below, coming down
    flat[2::3, :] = flat[2::3, :1]  # every target alike
    s_up, s_down = (rng.uniform(0.0, 0.4, shape + (m,)) for _ in range(2))
    return {"up": (up, s_up), "down": (down, s_down)}


@pytest.mark.parametrize("shape, m", [((40,), 7), ((6, 5), 13), ((1,), 2)])
def test_every_tests_figures_are_the_standards(shape, m):
    stats = _tests(np.random.default_rng(m), shape, m)
    for directions in (("up", "down"), ("up",)):
        given = {d: stats[d] for d in directions}
        figures = axis_figures(given)
        for index in itertools.product(*(range(n) for n in shape)):
            row = [list(map(float, given[d][k][index])) for d in directions for k in (0, 1)]
            expected = _standard_figures(*row)
            assert set(figures) == set(expected)
            for key, value in expected.items():
                assert figures[key].shape == shape
                assert figures[key][index] == pytest.approx(value, rel=1e-12, abs=1e-12), (
                    key, index, directions)


def test_single_precision_draws_give_single_precision_figures():
    """The bootstrap draws in float32; its figures stay float32, each the standard's of the
    float32 values."""
    stats = {d: (a.astype(np.float32), s.astype(np.float32))
             for d, (a, s) in _tests(np.random.default_rng(3), (25, 4), 9).items()}
    figures = axis_figures(stats)
    for key, values in figures.items():
        assert values.dtype == np.float32, key
    index = (7, 2)
    expected = _standard_figures(*(list(map(float, stats[d][k][index]))
                                   for d in ("up", "down") for k in (0, 1)))
    for key, value in expected.items():
        assert float(figures[key][index]) == pytest.approx(value, rel=1e-6, abs=1e-6), key
