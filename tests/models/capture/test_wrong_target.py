"""A position read nearer another target of the plan than its own (models/capture/
wrong_target.py), and a rotary reading in its target's turn (take_cells.in_turn_of)."""

from __future__ import annotations

import math

import pytest

from models.capture.take_cells import in_turn_of
from models.capture.wrong_target import off_target

TARGETS = (0.0, 30.0, 60.0, 100.0)  # uneven: 30° then 40° between neighbours


@pytest.mark.parametrize(("reading", "target", "neighbour", "gap"), [
    (15.0001, 0.0, 30.0, 30.0),     # nearer 30 than 0
    (14.9999, 30.0, 0.0, 30.0),     # below 30: nearer 0
    (80.0001, 60.0, 100.0, 40.0),   # the 40° side: more than 20
    (-15.5, 0.0, 30.0, 30.0),       # the end target read beyond the end: its one neighbour
    (120.5, 100.0, 60.0, 40.0),
])
def test_a_reading_more_than_half_the_gap_to_its_neighbour_is_off_target(reading, target,
                                                                         neighbour, gap):
    off = off_target(reading, target, TARGETS)
    assert off is not None
    assert (off.target, off.neighbour, off.gap) == (target, neighbour, gap)
    assert off.off == pytest.approx(reading - target)


@pytest.mark.parametrize(("reading", "target"), [
    (15.0, 0.0), (45.0, 30.0), (15.0, 30.0), (79.9999, 60.0), (45.0001, 60.0),
    (-15.0, 0.0), (120.0, 100.0), (30.0, 30.0),
])
def test_a_reading_within_half_the_gap_is_not(reading, target):
    assert off_target(reading, target, TARGETS) is None


def test_nothing_to_compare_with_is_no_warning():
    assert off_target(50.0, 0.0, [0.0]) is None
    assert off_target(math.nan, 0.0, TARGETS) is None


@pytest.mark.parametrize(("value", "near", "turned"), [
    (-0.5, 0.0, -0.5), (359.5, 0.0, -0.5), (0.0004, 360.0, 360.0004),
    (-89.9997, 270.0, 270.0003), (-179.9998, 180.0, 180.0002), (180.0, 0.0, 180.0),
    (359.9996, 0.0, -0.0004), (720.0003, 720.0, 720.0003), (0.5, 720.0, 720.5),
    (12.5, 10.0, 12.5),  # within 180° of the target: as sent, never another turn
])
def test_a_reading_in_its_targets_turn_keeps_its_digits(value, near, turned):
    assert in_turn_of(value, near) == turned  # exactly: 359.9996 − 360 is −0.0004
