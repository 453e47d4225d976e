"""What a controller table tells the one who loads it (outside review comp75): ISG's strict
SGN16 bounds. Each number is checked against the log's own figures, computed here from the
rows, not with the product's formulas."""

from __future__ import annotations

import numpy as np
import pytest

from models.positioning.analysis import POSITIONING
from models.positioning.compensation import compensation_table, write_compensation
from models.positioning.controllers import CONTROLLERS
from models.positioning.controllers.common import ControllerRuleError
from models.readings.sheet import ReadingsSheet

isg, heidenhain = CONTROLLERS["isg"], CONTROLLERS["heidenhain"]


def pitch(t):
    """A screw's error, µm (or ″ on a rotary axis): a slope and a periodic term."""
    return 0.012 * t + 3.0 * np.sin(2 * np.pi * t / 250.0)


def log_rows(targets, error=pitch, lost=6.0, runs=3, directions="+-"):
    """Rows of the standard cycle without scatter: approached +, the axis stops lost/2 below
    its error; approached −, lost/2 above (a lost motion ``lost``: x̄↑ − x̄↓ = −lost)."""
    rows = []
    for run in range(1, runs + 1):
        if "+" in directions:
            rows += [[f"{t:.9g}", str(run), "+", f"{error(t) - lost / 2:.6f}", ""] for t in targets]
        if "-" in directions:
            rows += [[f"{t:.9g}", str(run), "-", f"{error(t) + lost / 2:.6f}", ""]
                     for t in targets[::-1]]
    return rows


def analysed(rows, unit="mm", dev="um"):
    sheet = ReadingsSheet(POSITIONING.columns, rows).parse()
    return POSITIONING.analyze(sheet, {"target_unit": unit, "deviation_unit": dev})


LINEAR = np.arange(0.0, 1000.0 + 1e-9, 50.0)
OPTIONS = {"sinumerik": "", "fanuc": "", "heidenhain": "values=correction", "twincat": "",
           "isg": "", "mach4": "values=correction", "linuxcnc": "", "csv": ""}
COMMENTED = {"csv": "#", "sinumerik": ";", "isg": "#", "twincat": "(*", "mach4": ";"}


# -- F4: ISG: MIN(SGN16) < value < MAX(SGN16) -----------------------------------------------------
def test_isg_values_lie_strictly_inside_the_types_bounds():
    lo16, hi16 = int(np.iinfo(np.int16).min), int(np.iinfo(np.int16).max)  # −32768, 32767
    plan = isg.build(compensation_table(analysed(log_rows(LINEAR))), "")
    for edge, ok in ((hi16 - 1, True), (lo16 + 1, True), (hi16, False), (lo16, False)):
        pos = plan.pos.copy()
        pos[4] = edge
        candidate = isg.Plan(**{**plan.__dict__, "pos": pos})
        if ok:
            assert isg.lint(candidate) is candidate
        else:
            with pytest.raises(ControllerRuleError, match=rf"-32767…\+32766 units.*a value of {edge} "):
                isg.lint(candidate)
    lo32, hi32 = int(np.iinfo(np.int32).min), int(np.iinfo(np.int32).max)
    plan32 = isg.Plan(**{**plan.__dict__, "value_type": "sgn32"})
    for edge, ok in ((hi32 - 1, True), (hi32, False), (lo32, False)):
        pos = plan32.pos.copy()
        pos[4] = edge
        if ok:
            isg.lint(isg.Plan(**{**plan32.__dict__, "pos": pos}))
        else:
            with pytest.raises(ControllerRuleError, match="SGN32"):
                isg.lint(isg.Plan(**{**plan32.__dict__, "pos": pos}))


def test_isg_refuses_an_error_of_3_2767_mm_through_the_writer(tmp_path):
    """3276.7 µm is 32767 units of 0.1 µm = MAX(SGN16), which the kernel excludes; 3276.6 µm
    is written as 32766."""
    def at(edge):
        return lambda t: edge if t == 500.0 else 0.0

    for edge, written in ((3276.6, True), (3276.7, False)):
        result = analysed(log_rows(LINEAR, error=at(edge), lost=0.0))
        path = tmp_path / f"{edge}.txt"
        if written:
            write_compensation(str(path), result, 0.0, "separate", "isg", "")
            assert ["kw.ssfk.table[10].pos", "32766"] in [
                line.split() for line in path.read_text().splitlines()]
        else:
            with pytest.raises(ControllerRuleError, match="a value of 32767 units"):
                write_compensation(str(path), result, 0.0, "separate", "isg", "")
            assert not path.exists()
