"""Positioning workbench: ISO 230-2 and VDI/DGQ 3441 figures against an independent
evaluation written here from the standards' definitions (plain loops, nothing imported
from models/), round trips through the axis rig (first principles), the checks a log must
pass, and the compensation table closed through the rig's controller."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.positioning.analysis import POSITIONING
from models.positioning.compensation import (
    LINUXCNC_MAX_POINTS,
    compensation_table,
    write_compensation,
)
from models.readings.sheet import ReadingsSheet
from models.validation.positioning_rig import AxisRig


def parse(rows):
    return ReadingsSheet(POSITIONING.columns, rows).parse()


def analyze(rows, **settings):
    return POSITIONING.analyze(parse(rows), settings)


def rows_of(cycle, scale=3600.0, blank_direction=False, with_run=True):
    return [[f"{t:.9g}", str(run) if with_run else "", "" if blank_direction else
             ("+" if d > 0 else "-"), f"{(reading - t) * scale:.9f}", ""]
            for t, run, d, reading in cycle]


# -- an independent evaluation, from the standards' text -------------------------------------
def reference_figures(readings: list[tuple[float, int, float]]) -> dict[str, float]:
    """ISO 230-2:2014 clause 2 and VDI/DGQ 3441 with loops: (target, direction, x)."""
    targets = sorted({t for t, _, _ in readings})
    stats = {}
    for t in targets:
        for d in (1, -1):
            xs = [x for tt, dd, x in readings if tt == t and dd == d]
            n = len(xs)
            mean = sum(xs) / n
            s = math.sqrt(sum((x - mean) ** 2 for x in xs) / (n - 1))
            stats[t, d] = (mean, s)
    out = {}
    b = {t: stats[t, 1][0] - stats[t, -1][0] for t in targets}
    out["B"] = max(abs(v) for v in b.values())
    out["B_mean"] = sum(b.values()) / len(targets)
    for d, name in ((1, "up"), (-1, "down")):
        means = [stats[t, d][0] for t in targets]
        out[f"E_{name}"] = max(means) - min(means)
        out[f"R_{name}"] = max(4 * stats[t, d][1] for t in targets)
        out[f"A_{name}"] = (max(stats[t, d][0] + 2 * stats[t, d][1] for t in targets)
                            - min(stats[t, d][0] - 2 * stats[t, d][1] for t in targets))
    every = [stats[key][0] for key in stats]
    out["E"] = max(every) - min(every)
    m = [(stats[t, 1][0] + stats[t, -1][0]) / 2 for t in targets]
    out["M"] = max(m) - min(m)
    out["R"] = max(max(2 * stats[t, 1][1] + 2 * stats[t, -1][1] + abs(b[t]), 4 * stats[t, 1][1],
                       4 * stats[t, -1][1]) for t in targets)
    out["A"] = (max(stats[key][0] + 2 * stats[key][1] for key in stats)
                - min(stats[key][0] - 2 * stats[key][1] for key in stats))
    # VDI/DGQ 3441
    half = {t: (abs(b[t]) + 6 * (stats[t, 1][1] + stats[t, -1][1]) / 2) / 2 for t in targets}
    xbar = {t: (stats[t, 1][0] + stats[t, -1][0]) / 2 for t in targets}
    out["P"] = max(xbar[t] + half[t] for t in targets) - min(xbar[t] - half[t] for t in targets)
    out["Ps_max"] = max(6 * (stats[t, 1][1] + stats[t, -1][1]) / 2 for t in targets)
    out["Pa"] = max(xbar.values()) - min(xbar.values())
    out["U_max"] = max(abs(v) for v in b.values())
    return out


def table_error_deg(theta_deg):
    th = np.radians(theta_deg)
    return (6.0 * np.sin(th + 0.5) + 2.0 * np.sin(2 * th - 1.1)) / 3600.0


@settings(max_examples=40, deadline=None)
@given(st.integers(2, 7), st.integers(2, 6), st.integers(0, 2**32 - 1))
@pytest.mark.slow
def test_figures_agree_with_an_independent_evaluation(n_targets, runs, seed):
    rng = np.random.default_rng(seed)
    targets = np.sort(rng.choice(np.arange(0, 3600, 5) / 10.0, n_targets, replace=False))
    rig = AxisRig(table_error_deg, lost_motion=rng.uniform(0, 10) / 3600,
                  drift_per_run=rng.uniform(-1, 1) / 3600, noise=rng.uniform(0.1, 2) / 3600,
                  rng=rng)
    cycle = rig.standard_cycle(targets, runs)
    rows = rows_of(cycle)
    result = analyze(rows)
    x = [(float(r[0]), 1 if r[2] == "+" else -1, float(r[3])) for r in rows]
    expected = reference_figures(x)
    got = {**result.iso.figures, **result.vdi.as_dict()}
    for key, value in expected.items():
        assert got[key] == pytest.approx(value, abs=1e-9), key


def test_a_rotary_table_is_measured_to_its_truth():
    """Five bidirectional runs on a table with 5" lost motion, 0.3" drift a run and 0.8"
    scatter: each mean deviation lies within 4 standard errors of the truth, and the
    reversal is the lost motion (the axis lags: B̄ = −5")."""
    rng = np.random.default_rng(7)
    noise = 0.8
    rig = AxisRig(table_error_deg, lost_motion=5 / 3600, drift_per_run=0.3 / 3600,
                  noise=noise / 3600, rng=rng)
    targets = np.arange(0, 361, 30.0)
    result = analyze(rows_of(rig.standard_cycle(targets, 5)))
    for name, d, stats in result.directions_present():
        truth = np.array([rig.true_mean_deviation(t, d, 5) for t in targets]) * 3600
        assert np.max(np.abs(stats.mean - truth)) < 4 * noise / math.sqrt(5), name
    assert result.iso.figures["B_mean"] == pytest.approx(-5.0, abs=4 * noise / math.sqrt(5 * 13))
    assert result.minimum_runs_met and not result.warnings


def test_directions_and_runs_taken_from_the_order_when_not_logged():
    rig = AxisRig(table_error_deg, lost_motion=4 / 3600, noise=0.5 / 3600,
                  rng=np.random.default_rng(3))
    cycle = rig.standard_cycle(np.arange(0, 181, 45.0), 5)
    stated = analyze(rows_of(cycle))
    inferred = analyze(rows_of(cycle, blank_direction=True, with_run=False))
    assert inferred.iso.figures == pytest.approx(stated.iso.figures)
    np.testing.assert_array_equal(inferred.directions, stated.directions)
    assert any("taken from the order of the targets" in w for w in inferred.warnings)


def test_a_linear_axis_from_measured_positions_in_mm():
    """An interferometer log of measured positions (mm), deviations in µm: the same figures
    as the deviations typed directly."""
    rng = np.random.default_rng(11)
    rig = AxisRig(lambda p: 2e-5 * p + 3e-3 * np.sin(p / 40.0), lost_motion=0.004,
                  noise=0.0008, rng=rng)
    cycle = rig.standard_cycle(np.arange(0, 501, 50.0), 5)
    by_measured = [[f"{t:g}", str(run), "up" if d > 0 else "down", "", f"{reading:.7f}"]
                   for t, run, d, reading in cycle]
    by_deviation = [[f"{t:g}", str(run), "↑" if d > 0 else "↓",
                     f"{(round(reading, 7) - t) * 1e3:.4f}", ""] for t, run, d, reading in cycle]
    a = analyze(by_measured, target_unit="mm", deviation_unit="um")
    b = analyze(by_deviation, target_unit="mm", deviation_unit="um")
    assert a.iso.figures == pytest.approx(b.iso.figures, abs=1e-3)
    assert a.iso.figures["B"] == pytest.approx(4.0, abs=2.0)  # µm; the lost motion
    assert a.symbol == " µm"


def test_one_direction_gives_the_unidirectional_figures_only():
    rig = AxisRig(table_error_deg, noise=0.5 / 3600, rng=np.random.default_rng(5))
    result = analyze(rows_of(rig.standard_cycle(np.arange(0, 361, 90.0), 5, directions=(1,))))
    data = POSITIONING.to_json(result)
    assert data["iso230_2"]["E_up"] is not None and data["iso230_2"]["R_up"] is not None
    for key in ("A", "R", "B", "B_mean", "M", "E", "A_down"):
        assert data["iso230_2"][key] is None, key
    assert data["vdi3441"]["P"] is None and data["vdi3441"]["U_max"] is None
    assert data["vdi3441"]["Pa"] is not None
    assert any("One approach direction only" in w for w in result.warnings)


def test_fewer_than_five_runs_are_evaluated_and_flagged():
    rig = AxisRig(table_error_deg, noise=0.5 / 3600, rng=np.random.default_rng(5))
    result = analyze(rows_of(rig.standard_cycle(np.arange(0, 361, 90.0), 3)))
    data = POSITIONING.to_json(result)
    assert data["minimum_runs_met"] is False and data["least_runs"] == {"up": 3, "down": 3}
    assert data["iso230_2"]["A"] is not None
    assert any("Fewer runs than ISO 230-2 asks" in w for w in result.warnings)
    assert "fewer than 5 runs: flagged" in POSITIONING.summary(result)


def test_runs_of_one_approach_do_not_pretend_a_repeatability():
    rows = [["0", "1", "+", "1.0", ""], ["10", "1", "+", "2.0", ""],
            ["10", "1", "-", "3.0", ""], ["0", "1", "-", "1.5", ""]]
    data = POSITIONING.to_json(analyze(rows))
    assert data["iso230_2"]["R"] is None and data["iso230_2"]["A"] is None
    assert data["iso230_2"]["B"] == pytest.approx(1.0)
    assert data["vdi3441"]["Ps_max"] is None and data["vdi3441"]["P"] is None


@pytest.mark.parametrize("rows, settings_, message", [
    ([["0", "1", "+", "", ""], ["1", "1", "+", "2", ""]], {}, "row 1: neither a deviation"),
    ([["0", "1", "+", "1", ""], ["1", "1", "+", "2", "1.0001"]], {},
     "row 2: deviation 2 but measured − target = 0.3600"),
    ([["0", "1", "+", "1", ""], ["0", "1", "+", "2", ""], ["1", "1", "+", "2", ""]], {},
     "rows 1 and 2: target 0, run 1, direction + twice"),
    ([["0", "1", "+", "1", ""], ["1", "", "+", "2", ""]], {}, "row 2: no run number"),
    ([["0", "1", "+", "1", ""], ["0", "2", "+", "2", ""]], {}, "at least two targets"),
    ([["0", "1", "+", "1", ""], ["1", "1", "+", "4000", ""]], {}, "row 2: a deviation of 4000"),
    ([["0", "1", "+", "1", ""], ["1", "1", "+", "20000", ""]],
     {"target_unit": "mm", "deviation_unit": "um"}, "beyond 10000 µm"),
    ([["0", "1", "+", "1", ""], ["1e308", "1", "+", "2", ""]], {},
     "row 2: target 1e+308 deg is beyond ±36000 deg"),
])
def test_logs_that_cannot_be_a_positioning_test_are_refused(rows, settings_, message):
    with pytest.raises(ValueError, match=message.replace("+", r"\+").replace("(", r"\(")):
        analyze(rows, **settings_)


def _two_runs_measured():
    """2 runs × 4 targets ↑↓ (16 rows), each a measured position 1–5″ off its target."""
    rows = []
    for run in (1, 2):
        for direction, targets in (("+", (0, 15, 30, 45)), ("-", (45, 30, 15, 0))):
            rows += [[str(t), str(run), direction, "",
                      f"{t + (run + (2 if direction == '-' else 0)) / 3600:.6f}"]
                     for t in targets]
    return rows


def test_a_reading_at_another_position_is_left_out_and_named_the_rest_kept():
    """Day review live76 F7: after a missed point row 7 (target 15°) got a measured 0°; the
    whole result was withheld ("row 7: a deviation of -54000 arcsec is beyond 3600 arcsec (1
    deg): … or whether a position was typed as a deviation"), nothing having been typed.
    The row is left out and named, with the units' symbols; the other 15 readings stay."""
    rows = _two_runs_measured()
    rows[6][4] = "0.0001"
    result = analyze(rows)
    assert result.left_out == (6,)
    assert 6 not in result.rows.tolist() and len(result.deviations) == 15
    said = [str(w) for w in result.warnings]
    assert said[0] == ('Row 7: measured 0.0001° at target 15°, a deviation of -53999.6" beyond '
                       '3600" (1°): left out of the analysis (a reading at another position '
                       "than its target's?)"), said
    assert result.iso.backward is not None  # the rest of the work stays
    assert analyze(_two_runs_measured()).left_out == ()


def test_most_readings_beyond_the_limit_are_a_unit_refused_with_symbols():
    rows = _two_runs_measured()
    for row in rows:  # positions (in arcseconds) typed into the deviation column
        row[3], row[4] = f"{float(row[4]) * 3600:.1f}", ""
    with pytest.raises(ValueError) as refused:
        analyze(rows)
    assert str(refused.value) == ('row 2: a deviation of 54001" is beyond 3600" (1°), as are '
                                  "12 of the 16 readings: check the deviation unit")

    with pytest.raises(ValueError, match="deviation_unit um is for an axis in mm"):
        POSITIONING.checked_settings({"target_unit": "deg", "deviation_unit": "um"})


@settings(max_examples=60, deadline=None)
@given(st.lists(st.sampled_from(["+", "-", "−", "↑", "↓", "up", "down", "UP", "Down", ""]),
                min_size=2, max_size=12))
@pytest.mark.slow
def test_every_spelling_of_a_direction_reads_as_its_sign(spellings):
    rows = [[str(i), "", s, "0.5", ""] for i, s in enumerate(spellings)]
    result = analyze(rows)
    for s, d in zip(spellings, result.directions, strict=True):
        if s:
            assert d == (1 if s.lower() in ("+", "↑", "up") else -1)


# -- compensation ---------------------------------------------------------------------------
def read_csv_table(path):
    lines = [ln for ln in path.read_text().splitlines() if not ln.startswith("#")]
    values = np.array([[float(v) for v in ln.split(",")] for ln in lines[1:]])
    return lines[0].split(","), values


def test_the_compensation_table_corrects_the_axis_it_was_measured_on(tmp_path):
    """The CSV written, read back and loaded into the rig's controller (commanded = target +
    compensation of that approach direction): the axis then reaches its targets."""
    rig = AxisRig(table_error_deg, lost_motion=5 / 3600)
    targets = np.arange(0, 361, 30.0)
    result = analyze(rows_of(rig.standard_cycle(targets, 5)))
    path = tmp_path / "comp.csv"
    write_compensation(str(path), result)
    header, values = read_csv_table(path)
    assert header == ["position_deg", "forward_compensation_arcsec",
                      "backward_compensation_arcsec"]

    def controller(target, direction):
        column = 1 if direction > 0 else 2
        return target + np.interp(target, values[:, 0], values[:, column]) / 3600.0

    after = AxisRig(table_error_deg, lost_motion=5 / 3600, controller=controller)
    left = analyze(rows_of(after.standard_cycle(targets, 5)))
    assert np.max(np.abs(left.iso.forward.mean)) < 0.01
    assert np.max(np.abs(left.iso.backward.mean)) < 0.01
    assert result.iso.figures["A"] > 15 and left.iso.figures["A"] < 0.02


def test_linuxcnc_file_holds_actual_positions_that_a_controller_inverts(tmp_path):
    """LinuxCNC COMP_FILE_TYPE 0 lists nominal, actual forward, actual reverse (machine units).
    A controller that inverts those maps reaches targets between the table's points to
    within what linear interpolation leaves of a smooth error."""
    rig = AxisRig(table_error_deg, lost_motion=5 / 3600)
    result = analyze(rows_of(rig.standard_cycle(np.arange(0, 361, 15.0), 5)))
    path = tmp_path / "x.comp"
    write_compensation(str(path), result, fmt="linuxcnc")
    table = np.loadtxt(path)
    assert np.all(np.diff(table[:, 0]) > 0) and table.shape == (25, 3)

    def controller(target, direction):  # the nominal whose actual position is the target
        actual = table[:, 1] if direction > 0 else table[:, 2]
        return float(np.interp(target, actual, table[:, 0]))

    after = AxisRig(table_error_deg, lost_motion=5 / 3600, controller=controller)
    left = analyze(rows_of(after.standard_cycle(np.arange(7.5, 353, 15.0), 5)))
    # linear interpolation leaves at most h²/8 · max|e''|; e'' ≤ 6 + 2·2² = 14"/rad²
    bound = math.radians(15.0) ** 2 / 8 * 14.0
    worst = np.max(np.abs(np.concatenate([left.iso.forward.mean, left.iso.backward.mean])))
    assert 0.5 * bound < worst <= bound + 1e-3  # the interpolation's own error, no more
    assert result.iso.figures["A"] > 15


def test_table_options_and_their_refusals(tmp_path):
    rig = AxisRig(table_error_deg, lost_motion=5 / 3600)
    result = analyze(rows_of(rig.standard_cycle(np.arange(0, 361, 30.0), 5)))
    uniform = compensation_table(result, step=10.0)
    assert uniform.positions.size == 37 and uniform.positions[-1] == pytest.approx(360.0)
    both = compensation_table(result, tables="bidirectional")
    np.testing.assert_allclose(both.forward, -result.iso.bidirectional_mean)
    with pytest.raises(ValueError, match="export separate tables"):
        write_compensation(str(tmp_path / "a"), result, tables="bidirectional", fmt="linuxcnc")
    with pytest.raises(ValueError, match=f"at most {LINUXCNC_MAX_POINTS}"):
        write_compensation(str(tmp_path / "b"), result, step=1.0, fmt="linuxcnc")
    with pytest.raises(ValueError, match="fewer than two points"):
        compensation_table(result, step=400.0)
    assert not (tmp_path / "a").exists() and not (tmp_path / "b").exists()
    one = analyze(rows_of(rig.standard_cycle(np.arange(0, 361, 30.0), 5, directions=(-1,))))
    with pytest.raises(ValueError, match="needs both approach directions"):
        compensation_table(one, tables="bidirectional")
    assert compensation_table(one).form == "backward only"


def test_a_target_whose_runs_read_alike_among_scattering_ones_is_not_given_zero_repeatability(
        tmp_path, capsys):
    """12 targets, 5 runs each way, scatter 0.5″; at one target every run was entered alike
    (copied): its s is 0, and U there held only the non-repeatable inputs, the smallest of
    all (an audit). U there now takes the s pooled over the targets, with a warning naming
    the target; the other targets' U is unchanged, and the s reported is still as read."""
    import json

    from app.main import main

    rng = np.random.default_rng(21)
    targets = np.arange(0.0, 360.0, 30.0)
    curve = 2.0 * np.sin(np.radians(targets))
    rows = ["target,run,direction,deviation"]
    for run in range(1, 6):
        for sign, order in (("+", targets), ("-", targets[::-1])):
            for t in order:
                x = curve[int(t // 30)] + (0.3 if sign == "+" else -0.3)
                x = x if t == 90.0 else x + rng.normal(0.0, 0.5)
                rows.append(f"{t:g},{run},{sign},{x:.4f}")
    path = tmp_path / "alike.csv"
    path.write_text("\n".join(rows) + "\n")
    assert main(["analyze", "positioning", str(path), "--json", "--language", "en"]) == 0
    data = json.loads(capsys.readouterr().out)
    per = data["per_target"]
    at = per["target"].index(90.0)
    assert per["s_up"][at] == 0.0 and per["s_down"][at] == 0.0
    u = np.asarray(per["expanded_uncertainty_mean_up"])
    others = np.delete(u, at)
    assert u[at] >= 0.8 * np.median(others), (u[at], others)
    assert any("read alike at target(s) 90 " in w for w in data["warnings"])



def test_a_direction_read_alike_in_every_run_gets_no_figure_intervals(tmp_path, capsys):
    """Every forward run entered alike (values like −1.66 that numpy's mean leaves 2e-16
    from themselves), the backward runs scattering: R↑ was 2e-15 with an interval of
    width 3e-15, and two targets escaped the check for runs read alike. Now s is exactly 0
    where the readings are alike, every target is named, U takes the pooled s, and no
    figure has an interval (the reason says why)."""
    import json

    from app.main import main

    rng = np.random.default_rng(22)
    targets = np.arange(0.0, 390.0, 30.0)
    curve = np.round(1.7 * np.sin(np.radians(targets)) - 0.01, 2)
    rows = ["target,run,direction,deviation"]
    for run in range(1, 6):
        rows += [f"{t:g},{run},+,{x:.2f}" for t, x in zip(targets, curve, strict=True)]
        rows += [f"{t:g},{run},-,{x + rng.normal(0.0, 0.5):.2f}"
                 for t, x in zip(targets[::-1], curve[::-1], strict=True)]
    path = tmp_path / "forward_alike.csv"
    path.write_text("\n".join(rows) + "\n")
    assert main(["analyze", "positioning", str(path), "--json", "--language", "en"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["per_target"]["s_up"] == [0.0] * targets.size
    assert "read alike at every target" in data["figure_intervals_reason"]
    assert all(f["interval_low"] is None for f in data["iso230_2_figures"].values())
    alike = [w for w in data["warnings"] if "Every forward run read alike" in w]
    assert alike and all(f"{t:g}" in alike[0] for t in targets)


def test_readings_alike_by_the_rounding_s_chance_are_not_called_copied(tmp_path, capsys):
    """Deviations typed to 0.1″ scattering by about 0.1″: five runs at a target come out
    alike by chance (13 % of directions of 13 targets, a reviewer). U there still takes the
    pooled s (0 is no repeatability), said in the budget's note, but no warning suggests a
    copy; the same readings typed to 0.0001″ (the rounding cannot explain them) are named."""
    import json

    from app.main import main

    rng = np.random.default_rng(8)
    targets = np.arange(0.0, 390.0, 30.0)

    def record(decimals: int, name: str):
        rows = ["target,run,direction,deviation"]
        for run in range(1, 6):
            for sign, order in (("+", targets), ("-", targets[::-1])):
                for t in order:
                    x = 0.4 * np.sin(np.radians(t)) + (0.0 if t == 90.0 else
                                                      rng.normal(0.0, 0.1))
                    rows.append(f"{t:g},{run},{sign},{round(x, decimals):.{decimals}f}")
        path = tmp_path / name
        path.write_text("\n".join(rows) + "\n")
        assert main(["analyze", "positioning", str(path), "--json", "--language", "en"]) == 0
        return json.loads(capsys.readouterr().out)

    coarse = record(1, "tenths.csv")
    at = coarse["per_target"]["target"].index(90.0)
    assert coarse["per_target"]["s_up"][at] == 0.0
    assert not any("read alike" in w for w in coarse["warnings"])
    u = np.asarray(coarse["per_target"]["expanded_uncertainty_mean_up"])
    assert u[at] >= 0.8 * np.median(np.delete(u, at))
    fine = record(4, "fine.csv")
    assert any("read alike at target(s) 90 " in w for w in fine["warnings"])
