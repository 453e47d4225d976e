"""The same readings with their text and choice columns typed otherwise are the same readings
(ident80b; the hostile pass of ident80): the positioning's direction "+" re-typed as "up" or
"↑" (the column's choices, one meaning), the run numbers and directions added where the
analysis derives the same ones (the k-th approach to a target in a direction is run k; a
blank direction from the order of the targets), or left out where it would. The register
compares the cells as the analysis reads them (Workbench.read_cells, through the analysis's
own functions); the stored identities of records issued before keep their meaning (the
stored layout is of the cells as typed, the candidates found by their anchor)."""

from __future__ import annotations

import pytest

from models.positioning.analysis import DOWN, POSITIONING, UP
from models.readings.sheet import ReadingsSheet
from models.register.readings_identity import readings_identity
from models.register.store import (
    NotASeparateCalibration,
    ReadingsOfAnotherItem,
    Register,
    SameReadingsIssued,
)
from tests.models.register.test_readings_retyped import _issue, _positioning_rows, _project

SPELLINGS = {"+": UP, "-": DOWN}


def _spelled(rows):
    """The directions in every spelling of their choice, row after row (+, ↑, up, UP …)."""
    out = []
    for i, (t, run, d, x) in enumerate(rows):
        choices = SPELLINGS[d]
        spelling = choices[i % len(choices)]
        out.append([t, run, spelling.upper() if i % 7 == 3 else spelling, x])
    return out


def _without(rows, run: bool, direction: bool):
    return [[t, "" if run else r, "" if direction else d, x] for t, r, d, x in rows]


def _routes():
    rows = _positioning_rows()
    return [
        ("direction as up, ↑, down, ↓, −", rows, _spelled(rows)),
        ("runs and directions left out", rows, _without(rows, True, True)),
        ("directions left out", rows, _without(rows, False, True)),
        ("runs left out", rows, _without(rows, True, False)),
        ("runs and directions added", _without(rows, True, True), rows),
        ("runs added, directions spelled", _without(rows, True, False), _spelled(rows)),
    ]


ROUTES = _routes()


def test_the_sample_derives_its_own_runs_and_directions():
    """The routes' premise: the sample's runs and directions are those the analysis derives
    (else leaving them out would be other readings)."""
    rows = _positioning_rows()
    parsed = ReadingsSheet(POSITIONING.columns, _without(rows, True, True)).parse()
    read = POSITIONING.read_cells(parsed, POSITIONING.default_settings)
    assert read["run"] == [int(r[1]) for r in rows]
    assert read["direction"] == [r[2] for r in rows]
    assert set(read["direction"]) == {"+", "-"}


@pytest.mark.parametrize("route", ROUTES, ids=[r[0] for r in ROUTES])
def test_cells_read_alike_are_the_readings_of_another_item(tmp_path, route):
    _, rows, retyped = route
    assert retyped != rows
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "positioning", "LRA-0815", rows)
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "positioning", "LRA-0900", retyped)
        assert refused.value.numbers == (first.number,)
        assert [r.number for r in register.list()] == [first.number]


@pytest.mark.parametrize("route", ROUTES, ids=[r[0] for r in ROUTES])
def test_cells_read_alike_are_the_calibration_issued_again(tmp_path, route):
    _, rows, retyped = route
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "positioning", "LRA-0815", rows)
        with pytest.raises(NotASeparateCalibration) as refused:
            _issue(register, "positioning", "LRA-0815", retyped,
                   separate="as left after adjustment")
        assert refused.value.numbers == (first.number,)
        with pytest.raises(SameReadingsIssued) as redated:
            _issue(register, "positioning", "LRA-0815", retyped, date="2026-11-21")
        assert redated.value.numbers == (first.number,)


def test_directions_the_other_way_are_other_readings(tmp_path):
    """Every direction typed the other way (the forward and backward tables swapped): the
    analysis reads other readings, and so does the register."""
    rows = _positioning_rows()
    swapped = [[t, r, "-" if d == "+" else "+", x] for t, r, d, x in rows]
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "positioning", "LRA-0815", rows)
        other = _issue(register, "positioning", "LRA-0900", swapped)
        assert other.number != first.number


def test_the_stored_layout_is_of_the_cells_as_typed():
    """What records store (and chain) keeps its meaning: the layout of the cells as typed
    (records issued before ident80b verify as they are); the cells as the analysis reads
    them are compared (shape), made again from the project state."""
    rows = _positioning_rows()
    typed = readings_identity(_project("positioning", rows), "positioning")
    spelled = readings_identity(_project("positioning", _spelled(rows)), "positioning")
    blank = readings_identity(_project("positioning", _without(rows, True, True)), "positioning")
    assert typed is not None and spelled is not None and blank is not None
    assert len({typed.layout, spelled.layout, blank.layout}) == 3
    assert typed.shape == spelled.shape == blank.shape
    assert typed.stored[1:] == spelled.stored[1:] == blank.stored[1:]


def _polygon_rows() -> list[list[str]]:
    import csv

    from tests.models.register.test_readings_retyped import SAMPLES

    with open(SAMPLES / "polygon_sample.csv", newline="", encoding="utf-8") as handle:
        return [list(r) for r in csv.reader(handle)][1:]


def _polygon_without(rows, set_: bool = False, direction: bool = False, later: bool = False):
    """The polygon rows with the set or the direction left out (``later``: the direction
    left out but in each set's first row)."""
    out, seen = [], set()
    for r in rows:
        first = r[5] not in seen
        seen.add(r[5])
        out.append([*r[:5], "" if set_ else r[5],
                    "" if direction or (later and not first) else r[6]])
    return out


def _polygon_routes():
    rows = _polygon_rows()
    one_set = [r for r in rows if r[5] == "1"]
    return [
        ("directions from the encoder's steps", rows, _polygon_without(rows, direction=True)),
        ("directions in each set's first row", rows, _polygon_without(rows, later=True)),
        ("set 1 left out", one_set, _polygon_without(one_set, set_=True)),
        ("set and direction left out", _polygon_without(one_set, True, True), one_set),
    ]


POLYGON_ROUTES = _polygon_routes()


@pytest.mark.parametrize("route", POLYGON_ROUTES, ids=[r[0] for r in POLYGON_ROUTES])
def test_polygon_sets_and_directions_read_alike_are_the_same_readings(tmp_path, route):
    """The polygon's set, blank, is set 1 (split_sets), and a set's direction its first
    stated, else the encoder's steps' (_direction): typed or left out, the same readings."""
    _, rows, retyped = route
    assert retyped != rows
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "polygon", "PG-0815", rows)
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "polygon", "PG-0900", retyped)
        assert refused.value.numbers == (first.number,)
        with pytest.raises(SameReadingsIssued) as redated:
            _issue(register, "polygon", "PG-0815", retyped, date="2026-11-21")
        assert redated.value.numbers == (first.number,)


def test_a_polygon_set_turned_the_other_way_is_other_readings(tmp_path):
    """Set 2 stated forward, against its encoder's steps: the analysis reads it forward
    (the stated direction), other readings than the sample's."""
    rows = _polygon_rows()
    turned = [[*r[:6], "+"] for r in rows]
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "polygon", "PG-0815", rows)
        other = _issue(register, "polygon", "PG-0900", turned)
        assert other.number != first.number


def test_theodolite_blank_directions_beside_stated_ones_are_forward(tmp_path):
    """The theodolite's direction, stated in some rows, is forward in the blank ones
    (pass_directions): "+" typed there is the same readings; "-" there is not."""
    from tests.own_readings import theodolite_sample_rows

    rows = theodolite_sample_rows()
    blank = [[*r[:3], "", "-" if i % 10 == 9 else ""] for i, r in enumerate(rows)]
    typed = [[*r[:3], "", "-" if i % 10 == 9 else "+"] for i, r in enumerate(rows)]
    other = [[*r[:3], "", "-" if i % 10 == 9 or i == 4 else "+"] for i, r in enumerate(rows)]
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}") as register:
        first = _issue(register, "theodolite", "LRA-0815", blank)
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "theodolite", "LRA-0900", typed)
        assert refused.value.numbers == (first.number,)
        assert _issue(register, "theodolite", "LRA-0901", other).number != first.number
