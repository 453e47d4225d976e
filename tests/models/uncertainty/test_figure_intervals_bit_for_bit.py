"""The figure intervals' Monte Carlo made faster without a figure changing: the figures of
many tests (``axis_figures``, taken in blocks, targets first) and the triple-goal world's EM
(``_ensemble``, its steps' changes compared a batch at a time) are, bit for bit, what the
plain computation written here gives: numpy's reductions along each test's row of targets,
and the EM of Laird (1978) one step after the other, each step's change tested as it is
made. Their processor time against the plain computation's is a benchmark
(tests/benchmarks/test_figure_intervals_speed.py), not a test here."""

from __future__ import annotations

import numpy as np
import pytest

from models.uncertainty.figure_intervals import _ensemble, axis_figures

pytestmark = pytest.mark.slow  # the plain EM makes its 3000 steps in Python


def _plain_figures(stats: dict[str, tuple[np.ndarray, np.ndarray]]) -> dict[str, np.ndarray]:
    """ISO 230-2 and VDI/DGQ 3441's figures of each test (its row of targets, the last
    axis), each a largest or smallest value along the row or the mean reversal."""
    out = {}
    for name, (mean, s) in stats.items():
        out[f"E_{name}"] = mean.max(axis=-1) - mean.min(axis=-1)
        out[f"R_{name}"] = (4.0 * s).max(axis=-1)
        out[f"A_{name}"] = (mean + 2 * s).max(axis=-1) - (mean - 2 * s).min(axis=-1)
    if len(stats) == 1:
        (name, (mean, s)), = stats.items()
        out["Pa"] = out[f"E_{name}"]
        out["Ps_max"] = (6.0 * s).max(axis=-1)
        return out
    (up, s_up), (down, s_down) = stats["up"], stats["down"]
    both = np.concatenate([up, down], axis=-1)
    out["E"] = both.max(axis=-1) - both.min(axis=-1)
    middle = 0.5 * (up + down)
    out["M"] = out["Pa"] = middle.max(axis=-1) - middle.min(axis=-1)
    size = np.abs(up - down)
    out["B"] = out["U_max"] = size.max(axis=-1)
    out["B_mean"] = np.mean(up - down, axis=-1)
    out["R"] = np.maximum(np.maximum(2 * s_up + 2 * s_down + size, 4 * s_up),
                          4 * s_down).max(axis=-1)
    ends = np.concatenate([up + 2 * s_up, down + 2 * s_down], axis=-1).max(axis=-1)
    starts = np.concatenate([up - 2 * s_up, down - 2 * s_down], axis=-1).min(axis=-1)
    out["A"] = ends - starts
    scatter = 6.0 * 0.5 * (s_up + s_down)
    half = 0.5 * (size + scatter)
    out["P"] = (middle + half).max(axis=-1) - (middle - half).min(axis=-1)
    out["Ps_max"] = scatter.max(axis=-1)
    return out


def _draws(shape: tuple[int, ...], m: int, seed: int) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Tests drawn as the bootstrap draws them (single precision): a bow and a backlash
    in the means, s from a chi-square with 4 degrees of freedom; a far-off target in some."""
    rng = np.random.default_rng(seed)
    bow = np.sin(np.linspace(0.0, np.pi, m)).astype(np.float32)
    out = {}
    for name, shift in (("up", 0.15), ("down", -0.15)):
        mean = bow + shift + 0.3 * rng.standard_normal(shape + (m,), dtype=np.float32)
        mean.reshape(-1, m)[::7, m // 3] += np.float32(4.0)
        s = np.float32(0.2) * np.sqrt(rng.standard_gamma(2.0, shape + (m,), dtype=np.float32))
        out[name] = (mean, s)
    return out


@pytest.mark.parametrize(("shape", "m"), [((2000,), 12), ((2000,), 72), ((300,), 600),
                                          ((25, 40), 12), ((25, 40), 72), ((3,), 1)])
def test_the_figures_in_blocks_are_each_rows_own_bit_for_bit(shape, m):
    """Many blocks (600 targets: 55 tests a block), one (12), 3-D draws and one target."""
    stats = _draws(shape, m, seed=m)
    for directions in (("up", "down"), ("up",), ("down",)):
        given = {d: stats[d] for d in directions}
        got, plain = axis_figures(given), _plain_figures(given)
        assert set(got) == set(plain)
        for key, value in plain.items():
            assert got[key].shape == shape and got[key].dtype == value.dtype, key
            assert got[key].tobytes() == value.tobytes(), (key, directions)


def test_one_test_given_as_a_row_keeps_its_figures_as_numbers():
    stats = {k: (v[0][0], v[1][0]) for k, v in _draws((1,), 12, seed=3).items()}
    got, plain = axis_figures(stats), _plain_figures(stats)
    for key, value in plain.items():
        assert np.ndim(got[key]) == 0 and got[key] == value, key


def _plain_ensemble(values: np.ndarray, se2: np.ndarray, grid_size: int = 80,
                    steps: int = 3000) -> tuple[np.ndarray, int]:
    """Shen & Louis's triple-goal estimates, the true values' distribution by Laird's EM on
    a grid over the measured span from the uniform, each step's change tested as it is
    made (stop below 1e-9), and the steps made."""
    v = np.asarray(values, dtype=float)
    se2 = np.maximum(np.broadcast_to(se2, v.shape), 1e-150)
    if not v.max() > v.min():
        return v.copy(), 0
    grid = np.linspace(v.min(), v.max(), grid_size)
    d = (v[:, None] - grid[None, :]) ** 2 / se2[:, None]
    likelihood = np.exp(-0.5 * (d - np.min(d, axis=1, keepdims=True)))
    weights = np.full(grid.size, 1.0 / grid.size)
    made = 0
    for made in range(1, steps + 1):  # noqa: B007 (the steps made are returned)
        new = weights * (likelihood.T @ (1.0 / (likelihood @ weights)))
        new /= v.size
        change = np.abs(new - weights).max()
        weights = new
        if change < 1e-9:
            break
    cdf = np.cumsum(weights)
    ranks = np.argsort(np.argsort(v, kind="stable"), kind="stable")
    return grid[np.minimum(np.searchsorted(cdf, (ranks + 0.5) / v.size), grid.size - 1)], made


def _ensemble_cases():
    """(values, se2): smooth curves with noise at 12, 36 and 72 targets, a spike, two
    targets, values measured far more precisely than they differ (the EM stops early,
    inside a batch of steps), every value alike."""
    rng = np.random.default_rng(11)
    cases = []
    for m in (12, 36, 72):
        curve = np.sin(np.linspace(0.0, 2 * np.pi, m)) + 0.3 * rng.standard_normal(m)
        cases.append((curve, np.full(m, 0.09)))
        cases.append((curve, rng.uniform(0.01, 0.3, m)))
    spike = 0.2 * rng.standard_normal(24)
    spike[5] += 3.0
    cases.append((spike, np.full(24, 0.04)))
    cases.append((np.array([0.0, 1.0]), np.array([0.5, 0.5])))
    cases.append((np.array([0.0, 0.0, 1.0, 1.0, 2.0]), np.full(5, 1e-6)))
    cases.append((np.linspace(-1.0, 1.0, 9), np.full(9, 1e-4)))
    cases.append((np.full(6, 0.25), np.full(6, 0.01)))
    return cases


def test_the_triple_goal_world_is_the_plain_ems_bit_for_bit():
    made = []
    for values, se2 in _ensemble_cases():
        expected, steps = _plain_ensemble(values, se2)
        made.append(steps)
        got = _ensemble(values, se2)
        assert got.dtype == expected.dtype and got.tobytes() == expected.tobytes(), values
    # the cases reach every way out: all the steps, an early stop off a batch's end, none
    assert 3000 in made and 0 in made and any(0 < n < 3000 and n % 64 for n in made), made
