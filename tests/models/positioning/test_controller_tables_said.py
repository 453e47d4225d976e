"""What a controller table tells the one who loads it (outside review comp75, F1–F8): the
files it names are the files written, where they are; that its positions are machine
coordinates; a table from one approach direction; ISG's strict SGN16 bounds; SINUMERIK's
modulo table from 0°, the reversal for MD32450 and the sign of the reference shift; the unit
an inch control needs; a table that ends before the last target. Each number is checked
against the log's own figures, computed here from the rows, not with the product's
formulas."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from models.positioning.analysis import POSITIONING
from models.positioning.compensation import compensation_table, write_compensation
from models.positioning.controllers import CONTROLLERS, fanuc, sinumerik
from models.positioning.controllers.common import ControllerRuleError
from models.readings.sheet import ReadingsSheet
from tests import controller_emulators as emu

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


# -- F1: HEIDENHAIN's files are *.COM, named inside as on disk, both paths said ----------------
def test_heidenhain_refuses_a_table_not_named_com_and_writes_nothing(tmp_path):
    result = analysed(log_rows(LINEAR))
    with pytest.raises(ControllerRuleError, match=r"\*\.COM files, named in the \.CMA .*No such "
                                                  r"compensation table.*'OUT\.txt' would not be "
                                                  r"loaded: name it OUT\.COM"):
        write_compensation(str(tmp_path / "OUT.txt"), result, 0.0, "separate", "heidenhain",
                           "values=correction")
    assert os.listdir(tmp_path) == []
    with pytest.raises(ControllerRuleError, match="name it X.COM"):
        write_compensation(str(tmp_path / "X"), result, 0.0, "separate", "heidenhain",
                           "values=correction")


@pytest.mark.parametrize("name", ["x_axis.com", "X_AXIS.COM", "Table.Com"])
def test_heidenhain_names_inside_are_the_files_written_and_both_paths_are_said(tmp_path, name):
    result = analysed(log_rows(LINEAR))
    path = tmp_path / name
    what = write_compensation(str(path), result, 0.0, "separate", "heidenhain", "values=correction")
    on_disk = sorted(os.listdir(tmp_path))
    cma_file = name.rsplit(".", 1)[0] + ".CMA"
    assert on_disk == sorted([name, cma_file])
    com, cma = path.read_text(), (tmp_path / cma_file).read_text()
    assert com.splitlines()[0] == f"BEGIN {name} MM"
    assert cma.splitlines()[0] == f"BEGIN {cma_file}"
    active = [line.split() for line in cma.splitlines() if "*" in line]
    assert active == [["0", "*", name]]  # the .COM the control will look for: the one on disk
    assert active[0][2] in on_disk
    head = what.splitlines()[0]
    assert str(tmp_path / cma_file) in head and name in head
    # and the control as read loads it and applies the correction at a target
    c = emu.load_heidenhain(com, cma, "X", "correction")
    assert c.offset(250.0, 1) == pytest.approx(-(pitch(250.0) - 3.0) / 1000, abs=1e-6)


def test_the_command_line_names_both_files_and_says_the_notes_on_their_own_lines(tmp_path,
                                                                                 capsys):
    log = tmp_path / "log.csv"
    log.write_text("target,run,direction,deviation\n" + "\n".join(
        ",".join(r[:4]) for r in log_rows(LINEAR)) + "\n")
    common = ["analyze", "positioning", str(log), "--target-unit", "mm", "--deviation-unit", "um",
              "--compensation-format", "heidenhain", "--compensation-tables", "separate",
              "--compensation-controller-options", "values=correction"]
    capsys.readouterr()
    assert main([*common, "--table", str(tmp_path / "OUT.txt")]) == 2
    assert "name it OUT.COM" in capsys.readouterr().err
    assert not (tmp_path / "OUT.txt").exists() and not (tmp_path / "OUT.CMA").exists()
    assert main([*common, "--table", str(tmp_path / "x.com")]) == 0
    err = capsys.readouterr().err.splitlines()
    said = [line for line in err if line.startswith("HEIDENHAIN")]
    assert len(said) == 1
    assert f"in {tmp_path / 'x.CMA'}" in said[0] and said[0].endswith(f"written to {tmp_path / 'x.com'}")
    following = err[err.index(said[0]) + 1]
    assert following.startswith("the positions are the log's targets, taken as machine coordinates")


# -- F2: the positions are machine coordinates: said with every format, in every header that can
@pytest.mark.parametrize("fmt", list(OPTIONS))
def test_every_table_says_its_positions_are_machine_coordinates(tmp_path, fmt):
    result = analysed(log_rows(LINEAR))
    tables = "bidirectional" if fmt in ("sinumerik", "fanuc") else "separate"
    path = tmp_path / ("t.COM" if fmt == "heidenhain" else "t.txt")
    what = write_compensation(str(path), result, 0.0, tables, fmt, OPTIONS[fmt])
    assert "taken as machine coordinates (from the machine datum): a log taken in a work offset " \
           "gives a table shifted by that offset" in what
    if fmt in COMMENTED:
        said = [line for line in path.read_text().splitlines() if "machine coordinates" in line]
        assert len(said) == 1 and said[0].startswith(COMMENTED[fmt])


def test_the_headers_leave_the_tables_readable_by_the_controllers(tmp_path):
    """The comment lines added are comments to each controller as read: the tables load and
    give the same correction as without them."""
    result = analysed(log_rows(LINEAR))
    for fmt, load in (("sinumerik", emu.load_sinumerik), ("isg", emu.load_isg),
                      ("twincat", emu.load_twincat), ("mach4", emu.load_mach4)):
        tables = "bidirectional" if fmt == "sinumerik" else "separate"
        path = tmp_path / f"{fmt}.txt"
        write_compensation(str(path), result, 0.0, tables, fmt, OPTIONS[fmt])
        c = load(path.read_text())
        want = -(pitch(300.0) - (0 if tables == "bidirectional" else 3.0)) / 1000
        assert c.offset(300.0, 1) == pytest.approx(want, abs=1e-4 if fmt == "isg" else 1e-6), fmt


# -- F3: one approach direction measured ---------------------------------------------------------
@pytest.mark.parametrize("fmt", ["twincat", "isg", "sinumerik", "heidenhain", "mach4", "csv"])
def test_a_backward_only_log_says_its_one_table_serves_both_directions(tmp_path, fmt):
    result = analysed(log_rows(LINEAR, directions="-"))
    path = tmp_path / ("b.COM" if fmt == "heidenhain" else "b.txt")
    what = write_compensation(str(path), result, 0.0, "separate", fmt, OPTIONS[fmt])
    said = ("only the backward (−) approach was measured: this one table is applied to both "
            "directions, and approached forward (+) the axis is left off by the reversal "
            "(not measured)")
    assert said in what
    if fmt in COMMENTED:
        assert said in path.read_text()
    forward = write_compensation(str(tmp_path / "f.txt"), analysed(log_rows(LINEAR, directions="+")),
                                 0.0, "separate", "twincat", "")
    assert "only the forward (+) approach was measured" in forward
    both = write_compensation(str(tmp_path / "s.txt"), analysed(log_rows(LINEAR)), 0.0, "separate",
                              "twincat", "")
    assert "approach was measured" not in both


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


# -- F5: SINUMERIK ---------------------------------------------------------------------------------
def rotary_error(t):
    """″: eccentricity and a 4/rev term; periodic in 360°."""
    r = np.radians(t)
    return 8.0 * np.sin(r) + 3.0 * np.sin(4 * r + 0.3)


def test_sinumerik_writes_a_turn_measured_from_minus_180_from_0_with_the_same_values():
    targets = np.arange(-180.0, 180.0 + 1e-9, 30.0)
    table = compensation_table(analysed(log_rows(targets, error=rotary_error, lost=5.0),
                                        "deg", "arcsec"), tables="bidirectional")
    [(_, text)], what = sinumerik.write(table, "modulo=360")
    assert "$AA_ENC_COMP_MIN[0,AX1]=0\n" in text and "$AA_ENC_COMP_MAX[0,AX1]=360\n" in text
    assert "the turn is written from 0" in what
    c = emu.load_sinumerik(text)
    for t in targets[1:-1]:  # the log's own means (the bidirectional mean is the error)
        assert c.offset(float(t) % 360, 1) == pytest.approx(-rotary_error(t) / 3600, abs=1e-7), t
    # ±180 measured twice: the mean of both ends
    assert c.offset(180.0, 1) == pytest.approx(-rotary_error(180.0) / 3600, abs=1e-7)
    # a turn whose points miss 0 is written from its first point, and said so
    shifted = np.arange(5.0, 365.0 + 1e-9, 30.0)
    table = compensation_table(analysed(log_rows(shifted, error=rotary_error, lost=5.0),
                                        "deg", "arcsec"), tables="bidirectional")
    [(_, text)], what = sinumerik.write(table, "modulo=360")
    assert "$AA_ENC_COMP_MIN[0,AX1]=5\n" in text
    assert "the turn is written 5…365: 0 is not one of its points" in what


@pytest.mark.parametrize("lost, sense", [(6.0, "positive: the axis stops short on reversal"),
                                         (-4.0, "negative: the axis overshoots on reversal")])
def test_refused_separate_tables_state_the_mean_reversal_for_the_backlash_setting(lost, sense):
    rows = log_rows(LINEAR, lost=lost)
    # the log's own reversal: per target, mean of the + rows minus mean of the − rows
    dev = {(r[0], r[2]): [] for r in rows}
    for r in rows:
        dev[(r[0], r[2])].append(float(r[3]))
    reversal = np.mean([np.mean(dev[(t, "+")]) - np.mean(dev[(t, "-")])
                        for t in {r[0] for r in rows}])
    assert reversal == pytest.approx(-lost)
    table = compensation_table(analysed(rows), tables="separate")
    with pytest.raises(ControllerRuleError) as refused:
        sinumerik.write(table, "")
    said = str(refused.value)
    assert f"mean(x̄↑ − x̄↓), is {reversal:+.4g} um" in said
    assert f"MD32450 = {-reversal / 1000:+.6g} mm ({sense}" in said
    with pytest.raises(ControllerRuleError) as refused:
        fanuc.write(table, "detection_unit=0.0005")
    said = str(refused.value)
    assert "parameter 1851" in said and f"is {reversal:+.4g} um" in said
    assert f"{-reversal / 1000 / 0.0005:+.4g} detection units of 0.0005 ({sense}" in said


# -- F6: the reference shift: which way it leaves the axis -------------------------------------
def test_sinumerik_reference_shift_says_which_way_the_axis_is_left_and_what_a_wrong_sign_gives():
    targets = np.arange(-200.0, 600.0 + 1e-9, 50.0)
    result = analysed(log_rows(targets))
    table = compensation_table(result, tables="bidirectional")
    [(_, text)], what = sinumerik.write(table, "reference=300")
    c = emu.load_sinumerik(text)
    # through the table the axis stands at target + x̄(t) + offset(t): the same everywhere
    left = {t: pitch(t) / 1000 + c.offset(t, 1) for t in targets}
    assert np.ptp(list(left.values())) < 1e-6
    shift = pitch(300.0) / 1000  # the log's error at the reference point, mm
    assert left[0.0] == pytest.approx(shift, abs=1e-6)
    assert f"left {shift:+.6g} (axis unit) off at every position (actual − target)" in what
    assert "MD34090 REFP_MOVE_DIST_CORR" in what and "not verified" in what
    assert f"{2 * shift:+.6g} means the sign was wrong" in what
    assert f"left {shift:+.6g} (axis unit) off" in text


# -- F7: inch controls ---------------------------------------------------------------------------
def test_sinumerik_says_its_table_is_metric_and_what_an_inch_control_needs():
    table = compensation_table(analysed(log_rows(LINEAR)), tables="bidirectional")
    [(_, text)], what = sinumerik.write(table, "")
    said = ("positions and values in mm: a control with MD10240 SCALING_SYSTEM_IS_METRIC = 0 reads "
            "them in inches (25.4 times too large): for it, divide the positions, the step and the "
            "values by 25.4")
    assert said in what and f"; {said}" in text
    rotary = compensation_table(analysed(log_rows(np.arange(0.0, 360.0 + 1e-9, 30.0),
                                                  error=rotary_error), "deg", "arcsec"),
                                tables="bidirectional")
    [(_, text)], what = sinumerik.write(rotary, "modulo=360")
    assert "positions and values in degrees" in what and "MD10240" not in text


def test_fanuc_says_the_detection_unit_is_in_mm_and_an_inch_machine_gives_it_so():
    inch = 25.4
    targets = np.arange(0.0, 40 * inch + 1e-9, 2 * inch)  # every 2 in over 40 in
    result = analysed(log_rows(targets, lost=0.0))
    table = compensation_table(result, tables="bidirectional")
    [(_, tape)], what = fanuc.write(table, "detection_unit=0.00254")  # 0.0001 in
    assert ("values and 3624 in detection units of 0.00254 mm (the table is metric): on an inch "
            "machine give detection_unit in mm, e.g. 0.0001 in = 0.00254") in what
    assert "N3624A1P20000\n" in tape  # 2 in / 0.0001 in
    # each increment in 0.0001 in, from the log's errors in inches
    compensation_in = -pitch(targets) / 1000 / inch
    counts = np.round((compensation_in - compensation_in[0]) / 0.0001).astype(int)
    want = np.diff(counts)
    got = [int(line.split("P")[1]) for line in tape.splitlines() if line.startswith("N1")]
    assert got == list(want)
    option = next(o for o in fanuc.OPTIONS if o.key == "detection_unit")
    assert "detection unit in mm or degrees" in option.help
    assert "(an inch machine's in mm: 0.00254)" in option.help


# -- F8: a step that does not divide the span --------------------------------------------------
@pytest.mark.parametrize("fmt", ["twincat", "csv", "sinumerik"])
def test_a_table_that_ends_before_the_last_target_says_where_and_what_holds_beyond(tmp_path, fmt):
    result = analysed(log_rows(LINEAR))
    tables = "bidirectional" if fmt == "sinumerik" else "separate"
    end = math.floor(1000 / 70) * 70  # 980
    what = write_compensation(str(tmp_path / "t.txt"), result, 70.0, tables, fmt, OPTIONS[fmt])
    said = (f"the table ends at {end}, {1000 - end} before the last target 1000 (the step does not "
            f"divide the targets' span): beyond {end} the controller applies the value at {end}")
    assert said in what and said in (tmp_path / "t.txt").read_text()
    what = write_compensation(str(tmp_path / "u.txt"), result, 50.0, tables, fmt, OPTIONS[fmt])
    assert "the table ends at" not in what


def test_the_guide_says_machine_coordinates_and_inch_controls():
    guide = (Path(__file__).resolve().parents[3] / "docs" / "user-guide" / "positioning.md").read_text(
        encoding="utf-8")
    section = guide[guide.index("## Compensation tables"):guide.index("## Before and after")]
    assert "machine coordinates" in section and "work offset" in section
    assert "MD10240" in section and "0.00254" in section
    assert "−32767…+32766" in section and "*.COM" in section
