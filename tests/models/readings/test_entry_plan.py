"""The entry plan: the order of a test's points, and where the next reading goes."""

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.positioning.analysis import POSITIONING
from models.readings.entry_plan import (
    EntryPlan,
    crosscal_plan,
    polygon_plan,
    positioning_plan,
    same_cell,
    targets_from,
    theodolite_plan,
)
from models.readings.sheet import ReadingsSheet

READING = ("deviation", "measured")


def _take_all(plan, deviation_of, keys=READING):
    """Rows filled as a technician would: each take goes where the plan places it."""
    rows: list[dict[str, str]] = []
    while (place := plan.placement(rows, keys)) is not None:
        row = {**place.cells, keys[0]: deviation_of(place.cells)}
        if place.row == len(rows):
            rows.append(row)
        else:
            rows[place.row].update(row)
    return rows


def test_linear_bidirectional_cycle_is_iso230_standard_cycle():
    plan = positioning_plan(targets_from(0.0, 30.0, 4), runs=2, bidirectional=True)
    got = [(p.cells["target"], p.cells["run"], p.cells["direction"]) for p in plan.points]
    expected = []
    for run in ("1", "2"):
        expected += [(t, run, "+") for t in ("0", "30", "60", "90")]
        expected += [(t, run, "-") for t in ("90", "60", "30", "0")]
    assert got == expected
    assert plan.next_text([], READING) == "next: target 0°, run 1 ↑"


def test_pilgrim_takes_every_approach_of_a_target_before_the_next():
    plan = positioning_plan([0, 120, 240], runs=3, bidirectional=True, order="pilgrim")
    got = [(float(p.cells["target"]), int(p.cells["run"]), p.cells["direction"])
           for p in plan.points]
    assert sorted(got) == sorted(itertools.product((0.0, 120.0, 240.0), (1, 2, 3), ("+", "-")))
    targets = [g[0] for g in got]
    assert targets == sorted(targets)  # one target's approaches together, rising
    assert got[:2] == [(0.0, 1, "+"), (0.0, 1, "-")]


def test_next_text_follows_the_readings_and_a_filled_row_is_never_chosen():
    plan = positioning_plan(targets_from(0.0, 30.0, 5), runs=3, bidirectional=True)
    rows = [{**p.cells, "deviation": "1.0"} for p in plan.points[:22]]
    # 22 taken: run 1 (10), run 2 (10), run 3 ↑ at 0 and 30
    assert plan.next_text(rows, READING) == "next: target 60°, run 3 ↑"
    assert plan.progress(rows, READING) == (22, 30)
    place = plan.placement(rows, READING)
    assert place.row == 22 and dict(place.cells) == {"target": "60", "run": "3", "direction": "+"}
    # a row holding the next point's cells and no reading yet is where the reading goes
    rows.append({"target": "60", "run": "3", "direction": "+", "deviation": ""})
    rows.append({"target": "", "run": "", "direction": "", "deviation": ""})
    assert plan.placement(rows, READING).row == 22
    # a blank row after the last used one is reused, not a row appended after it
    rows[22]["deviation"] = "0.5"
    assert plan.placement(rows, READING).row == 23
    assert plan.next_text(rows, READING) == "next: target 90°, run 3 ↑"


def test_numbers_and_directions_are_compared_as_meanings():
    assert same_cell("30", "30.000") and same_cell("+", "↑") and same_cell("-", "down")
    assert same_cell("0°30'", "0.5") and not same_cell("30", "31") and not same_cell("+", "-")


def test_a_log_filled_by_the_plan_is_analysed_without_refusal():
    rng = np.random.default_rng(4)
    truth = {t: rng.normal(0, 2.0) for t in (0.0, 45.0, 90.0, 135.0)}
    plan = positioning_plan(list(truth), runs=5, bidirectional=True)
    rows = _take_all(plan, lambda c: f"{truth[float(c['target'])] + rng.normal(0, 0.1):.4f}")
    assert len(rows) == 40
    table = [[r["target"], r["run"], r["direction"], r["deviation"], ""] for r in rows]
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, table).parse(), {})
    assert result.least_runs == {"up": 5, "down": 5}
    up = result.iso.forward.mean
    assert np.allclose(up, [truth[t] for t in sorted(truth)], atol=0.2)


@settings(max_examples=40, deadline=None)
@given(st.integers(2, 6), st.integers(1, 4), st.booleans(), st.sampled_from(["linear", "pilgrim"]),
       st.data())
def test_takes_follow_the_plan_whatever_rows_wait_in_between(n, runs, both, order, data):
    plan = positioning_plan(targets_from(-10.0, 7.5, n), runs=runs, bidirectional=both,
                            order=order)
    rows: list[dict[str, str]] = []
    taken = []
    for _ in range(len(plan)):
        if data.draw(st.booleans()):  # the technician pressed Return: an empty row waits
            rows.append({"target": "", "run": "", "direction": "", "deviation": ""})
        place = plan.placement(rows, READING)
        assert place is not None
        assert place.row >= len(rows) or not rows[place.row]["deviation"]
        if place.row == len(rows):
            rows.append({"deviation": ""})
        rows[place.row].update({**place.cells, "deviation": "0.1"})
        taken.append(place.point.index)
    assert taken == list(range(len(plan)))
    assert plan.placement(rows, READING) is None
    assert plan.next_text(rows, READING).startswith("plan complete")


def test_polygon_crosscal_and_theodolite_plans():
    p = polygon_plan(4, sets=2, alternate=True)
    assert [(c.cells["set"], c.cells["position"], c.cells["direction"]) for c in p.points] == [
        ("1", "1", "+"), ("1", "2", "+"), ("1", "3", "+"), ("1", "4", "+"), ("1", "1", "+"),
        ("2", "1", "-"), ("2", "4", "-"), ("2", "3", "-"), ("2", "2", "-"), ("2", "1", "-")]
    assert str(p.points[6].label) == "set 2: face 4 of 4"
    c = crosscal_plan(3)
    assert [(x.cells["mounting"], x.cells["position"]) for x in c.points] == [
        ("0", "1"), ("0", "2"), ("0", "3"), ("1", "2"), ("1", "3"), ("1", "1"),
        ("2", "3"), ("2", "1"), ("2", "2")]
    t = theodolite_plan(targets_from(-20.0, 10.0, 5), runs=2)
    assert len(t) == 10 and dict(t.points[5].cells) == {"theta_deg": "-20", "run": "2",
                                                        "direction": "+"}


def test_a_plan_is_saved_and_read_back():
    for plan in (positioning_plan([0, 90, 180], 2, False, "pilgrim"), polygon_plan(12, 3),
                 crosscal_plan(6, 3, True), theodolite_plan([-5, 0, 5])):
        again = EntryPlan.from_dict(plan.as_dict())
        assert [dict(p.cells) for p in again.points] == [dict(p.cells) for p in plan.points]
    with pytest.raises(ValueError):
        EntryPlan.from_dict({"kind": "positioning", "targets": [0], "runs": 1})
    with pytest.raises(ValueError):
        EntryPlan.from_dict({"kind": "nonsense"})
    with pytest.raises(ValueError):
        positioning_plan([0, 10], runs=0)


def test_fill_gives_readings_without_plan_cells_the_next_points_skipping_those_taken():
    """Day review 65 F3: readings pasted without θ get the plan's next points in order; a
    row holding its own plan cells keeps them (its point skipped), one holding θ alone gets
    the run and direction of the first point not taken at that θ, a row without a reading
    gets none."""
    plan = theodolite_plan([-1.0, 0.0, 1.0], runs=2)
    keys = ("azimuth_deg", "elevation_deg")

    def row(theta="", run="", direction="", reading="1.0"):
        return {"theta_deg": theta, "azimuth_deg": reading, "elevation_deg": reading,
                "run": run, "direction": direction}
    rows = [row("-1", "1", "+"), row(), row("1", "1", "+"), row(), row(reading=""),
            row("1")]
    filled = plan.fill(rows, keys, [1, 2, 3, 4, 5])
    assert [(r, dict(p.cells)) for r, p in filled] == [
        (1, {"theta_deg": "0", "run": "1", "direction": "+"}),
        (3, {"theta_deg": "-1", "run": "2", "direction": "+"}),
        (5, {"theta_deg": "1", "run": "2", "direction": "+"})]


def test_each_point_has_a_row_per_reading_when_points_are_read_several_times():
    """plan80: with n readings per point the plan's rows are each point n times over, in
    order, each labelled with its reading; the rows the averaging takes n at a time agree
    on every plan cell (models/readings/repeats.py)."""
    p = polygon_plan(12, sets=2, alternate=True, readings=2)
    assert len(p) == 2 * 2 * 13
    assert [c.cells["position"] for c in p.points[:6]] == ["1", "1", "2", "2", "3", "3"]
    assert [c.cells["position"] for c in p.points[24:28]] == ["1", "1", "1", "1"]  # closure, set 2
    assert str(p.points[5].label) == "set 1: face 3 of 12, reading 2 of 2"
    assert str(p.points[25].label) == "set 1: closure on face 1, reading 2 of 2"
    assert str(p.points[29].label) == "set 2: face 12 of 12, reading 2 of 2"
    for a, b in zip(p.points[::2], p.points[1::2], strict=True):
        assert dict(a.cells) == dict(b.cells)
    # typed one after another, face 1's second reading is face 1's, never face 2's
    rows = _take_all(p, lambda c: "10.0", keys=("encoder_deg",))
    assert [r["position"] for r in rows[:4]] == ["1", "1", "2", "2"]
    assert str(p.next_text(rows[:5], ("encoder_deg",))) == \
        "next: set 1: face 3 of 12, reading 2 of 2"
    c = positioning_plan([0, 30], runs=1, bidirectional=False, readings=3)
    assert [(x.cells["target"], str(x.label)) for x in c.points] == [
        ("0", "target 0°, run 1 ↑, reading 1 of 3"), ("0", "target 0°, run 1 ↑, reading 2 of 3"),
        ("0", "target 0°, run 1 ↑, reading 3 of 3"), ("30", "target 30°, run 1 ↑, reading 1 of 3"),
        ("30", "target 30°, run 1 ↑, reading 2 of 3"), ("30", "target 30°, run 1 ↑, reading 3 of 3")]
    t = theodolite_plan([-1, 0, 1], readings=2)
    assert [x.cells["theta_deg"] for x in t.points] == ["-1", "-1", "0", "0", "1", "1"]
    with pytest.raises(ValueError):
        polygon_plan(12, readings=0)


def test_a_plan_saved_before_readings_per_point_reads_back_as_one_reading_per_point():
    """A plan saved by the versions before plan80 (no ``readings``) means one row per point,
    as it did; a plan of one reading per point saves as they saved it."""
    saved = {"kind": "sets", "faces": 12, "sets": 2, "closure": True, "alternate": True}
    plan = EntryPlan.from_dict(saved)
    assert len(plan) == 26 and plan.as_dict() == saved
    assert [dict(p.cells) for p in plan.points] == [dict(p.cells) for p in polygon_plan(
        12, 2, alternate=True).points]
    twice = polygon_plan(12, 2, alternate=True, readings=2)
    assert twice.as_dict() == {**saved, "readings": 2}
    again = EntryPlan.from_dict(twice.as_dict())
    assert [dict(p.cells) for p in again.points] == [dict(p.cells) for p in twice.points]


def test_the_workbenches_plans_follow_their_readings_per_point():
    from models.polygon.analysis import POLYGON
    from models.theodolite.analysis import THEODOLITE

    polygon = POLYGON.entry_plan({"faces": 12, "plan_sets": 1, "readings_per_point": 2})
    assert len(polygon) == 26 and polygon.spec["readings"] == 2
    assert len(POLYGON.entry_plan({"faces": 12, "plan_sets": 1})) == 13
    positioning = POSITIONING.entry_plan({"plan_runs": 1, "plan_targets": "0:30:3",
                                          "plan_directions": "up", "readings_per_point": 3})
    assert [p.cells["target"] for p in positioning.points] == ["0"] * 3 + ["30"] * 3 + ["60"] * 3
    theodolite = THEODOLITE.entry_plan({"plan_passes": 1, "plan_thetas": "-1:1:3",
                                        "readings_per_point": 2})
    assert len(theodolite) == 6
