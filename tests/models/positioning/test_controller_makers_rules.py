"""The makers' rules the tables had missed (issue 42): HEIDENHAIN's equidistant linear table
and the TNC 407's power-of-two spacing, ISG's SGN16/SGN32 pos/neg, FANUC's Q1 on 30i tapes,
LinuxCNC's unwrapped rotary joint, SINUMERIK's zero at the reference point and Mach4's sign
as an option. Each measured on the same rig as the controllers' proof (an axis simulated
from its error curve, measured in the standard cycle)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from models.positioning.compensation import compensation_table, write_compensation
from models.positioning.controllers import CONTROLLERS, fanuc, sinumerik
from models.positioning.controllers.common import ControllerRuleError
from tests import controller_emulators as emu
from tests.models.positioning.test_controller_compensation import AXES, measure

heidenhain, isg, mach4 = CONTROLLERS["heidenhain"], CONTROLLERS["isg"], CONTROLLERS["mach4"]


def _uneven_linear():
    return measure("linear", targets=np.array([0.0, 40.0, 120.0, 160.0, 240.0, 320.0]))


def test_heidenhain_refuses_a_linear_table_at_unequal_steps_and_names_the_step():
    table = compensation_table(_uneven_linear(), tables="bidirectional")
    with pytest.raises(ControllerRuleError, match=r"equidistant points \(MANUALplus 620.*spaced "
                                                  r"40…80: resample .* e\.g\. 40"):
        heidenhain.write(table, "values=error")
    # resampled at that step, it is written, and the controller reads it
    table = compensation_table(_uneven_linear(), step=40.0, tables="bidirectional")
    files, _ = heidenhain.write(table, "values=error")
    com, cma = files[0][1], files[1][1]
    assert emu.load_heidenhain(com, cma, "X", "error").offset(80.0, 1) == pytest.approx(
        table.forward[2] / 1000.0, abs=1e-6)


def test_heidenhain_refusal_through_the_command_line(tmp_path, capsys):
    log = tmp_path / "uneven.csv"
    rows = ["target,run,direction,deviation"]
    for run in range(1, 6):
        for t in (0, 40, 120, 160, 240, 320):
            rows.append(f"{t},{run},+,{1.5 * np.sin(t / 50) + 0.01 * run:.4f}")
        for t in (320, 240, 160, 120, 40, 0):
            rows.append(f"{t},{run},-,{1.5 * np.sin(t / 50) - 0.8:.4f}")
    log.write_text("\n".join(rows) + "\n")
    out = tmp_path / "X.COM"
    code = main(["analyze", "positioning", str(log), "--target-unit", "mm", "--deviation-unit", "um",
                 "--table", str(out), "--compensation-format", "heidenhain",
                 "--compensation-controller-options", "values=error"])
    assert code != 0 and not out.exists()
    assert "equidistant points" in capsys.readouterr().err


def test_tnc407_spacing_is_a_power_of_two_of_0_1_um():
    table = compensation_table(measure("linear"), step=50.0, tables="bidirectional")
    with pytest.raises(ControllerRuleError, match=r"2\^n × 0\.1 µm.*50 mm .*choose 26\.2144 mm or "
                                                  r"52\.4288 mm"):
        heidenhain.write(table, "values=error,control=tnc407")
    # the manual's example: 2^16 × 0.1 µm = 6.5536 mm
    table = compensation_table(measure("linear"), step=6.5536 * 8, tables="bidirectional")
    files, _ = heidenhain.write(table, "values=error,control=tnc407")
    assert "+52.42880" in files[0][1]
    with pytest.raises(ControllerRuleError, match="control=tnc999"):
        heidenhain.write(table, "values=error,control=tnc999")


def test_isg_refuses_a_value_beyond_its_type():
    rotary = compensation_table(measure("rotary"), tables="bidirectional")
    plan = isg.build(rotary, "modulo=360")
    big = plan.pos.copy()
    big[3] = 40000  # 4 mm in 0.1 µm: the audit's case
    with pytest.raises(ControllerRuleError, match=r"SGN16: MIN\(SGN16\) < value < MAX\(SGN16\), "
                                                  r"-32767…\+32766 units.*40000 units.*sgn32"):
        isg.lint(isg.Plan(**{**plan.__dict__, "pos": big}))
    plan32 = isg.build(rotary, "modulo=360,value_type=sgn32")
    assert isg.lint(isg.Plan(**{**plan32.__dict__, "pos": big})).value_type == "sgn32"
    with pytest.raises(ControllerRuleError, match="value_type=sgn8"):
        isg.build(rotary, "value_type=sgn8")


def test_fanuc_30i_tapes_carry_q1_and_the_controller_reads_them_alike():
    table = compensation_table(measure("rotary"), tables="bidirectional")
    options = "modulo=360,detection_unit=0.0001,value_limit=127"
    [(_, old)], _ = fanuc.write(table, options)
    [(_, new)], _ = fanuc.write(table, options + ",series=30i")
    assert "N3620A1P0" in old and "Q1" not in old
    assert "N03620Q1A1P0" in new and "N10001Q1P" in new
    a = emu.load_fanuc(old, 0.0, 1e-4, value_limit=127)
    b = emu.load_fanuc(new, 0.0, 1e-4, value_limit=127)
    x = np.linspace(0, 359, 50)
    assert [a.offset(v, 1) for v in x] == [b.offset(v, 1) for v in x]


def _linuxcnc_lookup(text: str, x: float, direction: int) -> float:
    """LinuxCNC's rule for COMP_FILE_TYPE 0 as its manual states it: linear between the lines,
    the first/last line's value held beyond them (no wrap)."""
    rows = np.array([[float(v) for v in ln.split()] for ln in text.splitlines()])
    nominal, actual = rows[:, 0], rows[:, 1 if direction > 0 else 2]
    return float(np.interp(x, nominal, actual - nominal))


def test_linuxcnc_rotary_joint_written_over_its_travel(tmp_path):
    before = measure("rotary")
    plain = tmp_path / "plain.comp"
    what = write_compensation(str(plain), before, 0.0, "separate", "linuxcnc")
    assert "does not wrap" in what and "at 370" in what
    travelled = tmp_path / "travel.comp"
    what = write_compensation(str(travelled), before, 0.0, "separate", "linuxcnc",
                              "modulo=360,travel_min=-720,travel_max=720")
    assert "over the joint's travel -720…720" in what
    text = travelled.read_text()
    lines = text.splitlines()
    assert float(lines[0].split()[0]) == -720 and float(lines[-1].split()[0]) == 720
    # at 370° the value of 10°, at −350° too: the table repeats
    for x in (10.0, 370.0, -350.0, 710.0):
        assert _linuxcnc_lookup(text, x, 1) == pytest.approx(
            _linuxcnc_lookup(text, x % 360, 1), abs=1e-9)
    # and within the first turn it is what the plain table says
    assert _linuxcnc_lookup(text, 100.0, -1) == pytest.approx(
        _linuxcnc_lookup(plain.read_text(), 100.0, -1), abs=1e-9)
    with pytest.raises(ControllerRuleError, match="at most 256 lines"):
        write_compensation(str(tmp_path / "x"), before, 0.0, "separate", "linuxcnc",
                           "modulo=360,travel_min=-36000,travel_max=36000")


def test_sinumerik_zero_at_the_reference_point():
    table = compensation_table(measure("rotary"), tables="bidirectional")
    [(_, measured)], what = sinumerik.write(table, "modulo=360")
    assert "recommends zero compensation at the reference point" in what
    [(_, zeroed)], what = sinumerik.write(table, "modulo=360,reference=90")
    shift = sinumerik.build(table, "modulo=360,reference=90").reference_shift
    assert f"{shift:.6g}" in what and "MD34090" in what
    a, b = emu.load_sinumerik(measured), emu.load_sinumerik(zeroed)
    assert b.offset(90.0, 1) == pytest.approx(0.0, abs=1e-7)
    for x in (0.0, 45.0, 200.0):
        assert b.offset(x, 1) == pytest.approx(a.offset(x, 1) + shift, abs=1e-7)  # offset = −value
    with pytest.raises(ControllerRuleError, match="outside the table"):
        sinumerik.write(compensation_table(measure("linear"), tables="bidirectional"),
                        "reference=2000")


def test_mach4_sign_is_an_option_without_a_default():
    table = compensation_table(measure("linear"), tables="separate")
    with pytest.raises(ControllerRuleError, match="values=correction or values=error must be given") \
            as refused:
        mach4.write(table, "axis=X")
    # the refusal points at the page that explains the two signs (not at "README")
    guide = re.search(r"docs/user-guide/\w+\.md", str(refused.value))
    assert guide is not None, str(refused.value)
    text = (Path(__file__).resolve().parents[3] / guide.group()).read_text(encoding="utf-8")
    assert "## Compensation tables" in text and "values=correction" in text
    [(_, corr)], _ = mach4.write(table, "axis=X,values=correction")
    [(_, err)], _ = mach4.write(table, "axis=X,values=error")
    assert "expected - actual (values=correction)" in corr
    assert "actual - expected (values=error)" in err
    c = [float(r.split(",")[2]) for r in corr.splitlines()[6:]]
    e = [float(r.split(",")[2]) for r in err.splitlines()[6:]]
    assert np.allclose(c, -np.array(e)) and np.allclose(c, table.forward / AXES["linear"]["scale"])
