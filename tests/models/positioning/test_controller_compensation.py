"""Controller compensation tables, each proven on an emulator of its controller.

The rig's axis (lost motion, a periodic error and drift; a full-turn rotary axis and a
linear one) is measured, the table written in the controller's format, read back by the
emulated controller (tests/controller_emulators.py, written from the manuals and not from
the writers), and the axis measured again through it: ISO 230-2 "after compensation".
At the table's points the residual is what the controller's rounding leaves; between
them, what linear interpolation leaves of the error, h²·max|e″|/8. Each lint is shown
refusing what its controller would reject or misapply, naming the rule. The emulators
themselves are checked against a second, simpler reading of each application rule.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.positioning.analysis import POSITIONING
from models.positioning.compensation import compensation_table, write_compensation
from models.positioning.controllers import CONTROLLERS, fanuc, sinumerik
from models.positioning.controllers.common import ControllerRuleError, parse_options
from models.readings.sheet import ReadingsSheet
from models.validation.positioning_rig import AxisRig
from tests import controller_emulators as emu

# -- the two axes (first principles, in the axis unit) -----------------------------------------
ARCSEC = 1 / 3600.0


def rotary_error(p):
    """Eccentricity (1/rev) and a 4/rev periodic error of a rotary table, degrees."""
    r = np.radians(p)
    return (8.0 * np.sin(r) + 3.0 * np.sin(4 * r + 0.3)) * ARCSEC


def linear_error(p):
    """Pitch error of a ball screw: a slope and a 250 mm periodic error, mm."""
    return 12e-6 * p + 3e-3 * np.sin(2 * np.pi * p / 250.0)


AXES = {
    "rotary": dict(error=rotary_error, lost=4.0 * ARCSEC, drift=0.6 * ARCSEC,
                   targets=np.arange(0.0, 360.0 + 1e-9, 15.0), unit="deg", dev="arcsec",
                   scale=3600.0, modulo="360"),
    "linear": dict(error=linear_error, lost=3e-3, drift=0.4e-3,
                   targets=np.arange(0.0, 1000.0 + 1e-9, 50.0), unit="mm", dev="um",
                   scale=1000.0, modulo=""),
}


def second_derivative_bound(error, lo, hi):
    x = np.linspace(lo, hi, 20001)
    h = x[1] - x[0]
    e = error(x)
    return float(np.max(np.abs(np.diff(e, 2)))) / h ** 2


def measure(axis, controller=None, targets=None):
    a = AXES[axis]
    rig = AxisRig(a["error"], lost_motion=a["lost"], drift_per_run=a["drift"],
                  controller=controller)
    cycle = rig.standard_cycle(a["targets"] if targets is None else targets, 5)
    rows = [[f"{t:.9g}", str(run), "+" if d > 0 else "-", f"{(x - t) * a['scale']:.9f}", ""]
            for t, run, d, x in cycle]
    settings = {"target_unit": a["unit"], "deviation_unit": a["dev"]}
    return POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)


# -- each controller: its options, its emulator, its quantum ------------------------------------
def _options(fmt, axis):
    modulo = AXES[axis]["modulo"]
    m = f"modulo={modulo}" if modulo else ""
    return {
        "sinumerik": f"axis=AX4,{m}",
        "fanuc": f"axis=4,detection_unit=0.0001,value_limit=127,{m}",
        "heidenhain": f"axis=C,values=error,{m}" if modulo else "axis=X,values=error",
        "twincat": f"name=Table1,{m}",
        "isg": f"axis_name=C,{m}",
        "mach4": "axis=X,values=correction",
    }[fmt]


ONE_TABLE = {"sinumerik", "fanuc"}  # the reversal goes to the controller's backlash setting
QUANTUM = {"sinumerik": 1e-7, "fanuc": 1e-4, "heidenhain": 1e-6, "twincat": 1e-9, "isg": 1e-4,
           "mach4": 1e-9}


def _load(fmt, path: Path, axis):
    text = path.read_text()
    if fmt == "sinumerik":
        return emu.load_sinumerik(text)
    if fmt == "fanuc":
        return emu.load_fanuc(text, reference_position=0.0, detection_unit=1e-4, value_limit=127)
    if fmt == "heidenhain":
        cma = path.with_suffix(".CMA").read_text()
        return emu.load_heidenhain(text, cma, "C" if axis == "rotary" else "X", "error",
                                   modulo=360.0 if axis == "rotary" else 0.0)
    return {"twincat": emu.load_twincat, "isg": emu.load_isg, "mach4": emu.load_mach4}[fmt](text)


CASES = [(fmt, axis) for fmt in CONTROLLERS for axis in AXES
         if not (fmt == "mach4" and axis == "rotary")]


@pytest.mark.parametrize(("fmt", "axis"), CASES)
def test_the_controller_applies_our_table_and_the_axis_reaches_its_targets(tmp_path, fmt, axis):
    a = AXES[axis]
    before = measure(axis)
    tables = "bidirectional" if fmt in ONE_TABLE else "separate"
    path = tmp_path / ("table.com" if fmt == "heidenhain" else "table.txt")
    write_compensation(str(path), before, 0.0, tables, fmt, _options(fmt, axis))
    controller = _load(fmt, path, axis)
    after = measure(axis, controller.controller)
    scale = a["scale"]
    # at the points: what rounding to the controller's quantum leaves (plus the second-order
    # look-up at the target instead of the reached position, < 0.01 of a unit here)
    at_points = (QUANTUM[fmt] / 2 + 1e-5 if axis == "rotary" else QUANTUM[fmt] / 2 + 1e-5) * scale
    if fmt in ONE_TABLE:
        left = after.iso.bidirectional_mean.copy()
        if fmt == "fanuc":  # no pitch error at the reference position (0): it is its own zero
            left -= left[0]
        assert np.max(np.abs(left)) <= at_points
        assert after.iso.figures["M"] < 0.05 * before.iso.figures["M"]
        assert after.iso.figures["B"] == pytest.approx(before.iso.figures["B"], abs=2 * at_points)
    else:
        left = np.concatenate([after.iso.forward.mean, after.iso.backward.mean])
        assert np.max(np.abs(left)) <= at_points
        assert after.iso.figures["E"] < 0.05 * before.iso.figures["E"]
        # the drift from run to run is no systematic error: it stays in R, and A keeps it
        assert after.iso.figures["A"] < 0.2 * before.iso.figures["A"]
        assert after.iso.figures["R_up"] == pytest.approx(before.iso.figures["R_up"], rel=1e-3)
    # between the points: the interpolation bound h²·max|e″|/8
    h = float(a["targets"][1] - a["targets"][0])
    bound = h ** 2 * second_derivative_bound(a["error"], a["targets"][0], a["targets"][-1]) / 8
    mids = measure(axis, controller.controller, a["targets"][:-1] + h / 2)
    means = (mids.iso.bidirectional_mean if fmt in ONE_TABLE else
             np.concatenate([mids.iso.forward.mean, mids.iso.backward.mean]))
    if fmt == "fanuc":
        means = means - after.iso.bidirectional_mean[0]
    worst = float(np.max(np.abs(means)))
    assert worst <= bound * scale + 2 * at_points
    assert worst > 0.3 * bound * scale  # the interpolation's own error is there, no more


@pytest.mark.parametrize(("fmt", "axis"), CASES)
def test_each_emulator_agrees_with_a_second_reading_of_its_rule(tmp_path, fmt, axis):
    before = measure(axis)
    tables = "bidirectional" if fmt in ONE_TABLE else "separate"
    path = tmp_path / ("t.com" if fmt == "heidenhain" else "t.txt")
    write_compensation(str(path), before, 0.0, tables, fmt, _options(fmt, axis))
    controller = _load(fmt, path, axis)
    text = path.read_text()
    t = AXES[axis]["targets"]
    rng = np.random.default_rng(7)
    span = t[-1] - t[0]
    x = np.concatenate([rng.uniform(t[0] - 0.2 * span, t[-1] + 0.2 * span, 400), t])
    for d in (1, -1):
        got = np.array([controller.offset(v, d) for v in x])
        if fmt == "sinumerik":
            want = emu.simple_sinumerik(text, x)
        elif fmt == "fanuc":
            want = emu.simple_fanuc(text, x, 0.0, 1e-4)
        elif fmt == "heidenhain":
            want = emu.simple_heidenhain(text, "C" if axis == "rotary" else "X", "error", x, d,
                                         360.0 if axis == "rotary" else 0.0)
        else:
            want = {"twincat": emu.simple_twincat, "isg": emu.simple_isg,
                    "mach4": emu.simple_mach4}[fmt](text, x, d)
        np.testing.assert_allclose(got, want, atol=1e-12)
        assert np.ptp(got) > 0  # a table that does something


def test_the_emulators_hold_the_end_values_beyond_the_range(tmp_path):
    before = measure("linear")
    path = tmp_path / "eec.ini"
    write_compensation(str(path), before, 0.0, "bidirectional", "sinumerik", "")
    c = emu.load_sinumerik(path.read_text())
    assert c.offset(1200.0, 1) == c.offset(1000.0, 1) == pytest.approx(
        -before.iso.bidirectional_mean[-1] / 1000.0, abs=1e-7)
    assert c.offset(-50.0, -1) == c.offset(0.0, 1)
    # a table for the second measuring system is not applied while the first is active
    write_compensation(str(path), before, 0.0, "bidirectional", "sinumerik", "system=2,encoders=2")
    assert emu.load_sinumerik(path.read_text()).offset(500.0, 1) == 0.0
    assert emu.load_sinumerik(path.read_text(), active_system=2).offset(500.0, 1) != 0.0


def test_fanuc_rounds_to_detection_units_times_magnification_without_accumulating(tmp_path):
    before = measure("linear")
    path = tmp_path / "pitch.txt"
    write_compensation(str(path), before, 0.0, "bidirectional", "fanuc",
                       "detection_unit=0.001,magnification=2,reference=500")
    text = path.read_text()
    assert "N3620A1P10" in text and "N3621A1P1" in text and "N3622A1P20" in text
    assert "N3623A1P2" in text and "N3624A1P50000" in text
    c = emu.load_fanuc(text, reference_position=500.0, detection_unit=0.001)
    want = -before.iso.bidirectional_mean / 1000.0
    want -= want[10]
    got = np.array([c.offset(t, 1) for t in AXES["linear"]["targets"]])
    assert np.max(np.abs(got - want)) <= 0.001  # half of 2 µm: each sum rounded once
    assert c.offset(500.0, 1) == 0.0


# -- lints: what the controller would reject or misapply ----------------------------------------
def _table(axis="rotary", step=0.0, tables="bidirectional"):
    return compensation_table(measure(axis), step, tables)


def test_lints_refuse_naming_the_rule(tmp_path):
    rotary = _table()
    with pytest.raises(ControllerRuleError, match="MD38000 MM_ENC_COMP_MAX_POINTS = 20"):
        sinumerik.write(rotary, "modulo=360,max_points=20")
    with pytest.raises(ControllerRuleError, match="measuring system .*MD30200"):
        sinumerik.write(rotary, "system=2")
    with pytest.raises(ControllerRuleError, match="the step divides the turn.*7 does not divide 360"):
        sinumerik.write(_table(step=7.0), "modulo=360")
    with pytest.raises(ControllerRuleError, match="one table per measuring system"):
        sinumerik.write(_table(tables="separate"), "")
    with pytest.raises(ControllerRuleError, match="at most 128 points per axis"):
        fanuc.write(_table("linear", step=5.0), "")
    with pytest.raises(ControllerRuleError, match="stored value is at most ±7"):
        fanuc.write(rotary, "modulo=360,detection_unit=0.00001")
    with pytest.raises(ControllerRuleError, match="reference position is a compensation point"):
        fanuc.write(_table("linear"), "reference=25")
    with pytest.raises(ControllerRuleError, match="at most 256 entries"):
        CONTROLLERS["heidenhain"].write(_table("linear", step=2.0), "values=error")
    with pytest.raises(ControllerRuleError, match="values=error or values=correction"):
        CONTROLLERS["heidenhain"].write(rotary, "")
    with pytest.raises(ControllerRuleError, match="P-COMP-00059 = 20"):
        CONTROLLERS["isg"].write(rotary, "max_points=20")
    with pytest.raises(ControllerRuleError, match="modulo=-360 is below 0"):
        sinumerik.write(rotary, "modulo=-360")
    with pytest.raises(ControllerRuleError, match="magnification=0 is below 1"):
        fanuc.write(rotary, "magnification=0")
    with pytest.raises(ControllerRuleError, match="unknown option 'axle'"):
        CONTROLLERS["mach4"].write(rotary, "axle=X")
    uneven = compensation_table(measure("linear", targets=np.array([0, 50, 120, 200.0])),
                                tables="bidirectional")
    for fmt in ("sinumerik", "fanuc", "twincat", "isg", "mach4", "heidenhain"):
        with pytest.raises(ControllerRuleError, match="equidistant"):
            CONTROLLERS[fmt].write(uneven, {"mach4": "values=correction",
                                            "heidenhain": "values=error"}.get(fmt, ""))
    # nothing written when refused
    with pytest.raises(ControllerRuleError):
        write_compensation(str(tmp_path / "no"), measure("rotary"), 0.0, "bidirectional",
                           "sinumerik", "max_points=3")
    assert not (tmp_path / "no").exists()


def test_an_unclosed_rotary_table_is_refused_by_each_lint():
    rotary = _table()
    plan = fanuc.build(rotary, "modulo=360,detection_unit=0.0001,value_limit=127")
    values = dict(plan.values)
    values[plan.reference_number + 3] += 1
    with pytest.raises(ControllerRuleError, match="values of one revolution sum to zero"):
        fanuc.lint(fanuc.Plan(**{**plan.__dict__, "values": values}))
    plan = sinumerik.build(rotary, "modulo=360")
    opened = plan.values.copy()
    opened[-1] += 1e-4
    with pytest.raises(ControllerRuleError, match="modulo table closed"):
        sinumerik.lint(sinumerik.Plan(**{**plan.__dict__, "values": opened}))
    isg = CONTROLLERS["isg"]
    plan = isg.build(rotary, "modulo=360")
    opened = plan.pos.copy()
    opened[-1] += 3
    with pytest.raises(ControllerRuleError, match="modulo table closed"):
        isg.lint(isg.Plan(**{**plan.__dict__, "pos": opened}))
    # and the emulated controllers would have refused or accumulated it
    text = fanuc.render(fanuc.Plan(**{**fanuc.build(rotary, "modulo=360,detection_unit=0.0001,"
                                                            "value_limit=127").__dict__,
                                      "values": values}))
    with pytest.raises(emu.ControllerAlarm):
        emu.load_fanuc(text, 0.0, 1e-4, value_limit=127)


def test_the_turn_is_closed_from_a_log_without_its_end_and_the_table_starts_at_zero(tmp_path):
    before = measure("rotary", targets=np.arange(0.0, 345.0 + 1e-9, 15.0))
    path = tmp_path / "eec"
    what = write_compensation(str(path), before, 0.0, "bidirectional", "sinumerik", "modulo=360")
    assert "the end of the turn, 360, takes the value at its start" in what
    text = path.read_text()
    assert "$AA_ENC_COMP_MAX[0,AX1]=360" in text and "$AA_ENC_COMP[0,24,AX1]" in text
    c = emu.load_sinumerik(text)
    assert c.offset(359.999999, 1) == pytest.approx(c.offset(0.0, 1), abs=1e-9)
    assert c.offset(370.0, 1) == pytest.approx(c.offset(10.0, 1), abs=1e-12)
    assert math.isclose(c.offset(0.0, 1), -before.iso.bidirectional_mean[0] / 3600, abs_tol=1e-7)


def test_what_a_lint_refuses_the_emulated_controller_refuses_too():
    """The lints' limits are the controllers': the same table rendered past the lint is
    refused (or would be misapplied) by the emulated controller."""
    rotary = _table()
    plan = sinumerik.build(rotary, "modulo=360,max_points=20")
    with pytest.raises(ControllerRuleError):
        sinumerik.lint(plan)
    with pytest.raises(emu.ControllerAlarm):
        emu.load_sinumerik(sinumerik.render(plan), md38000=20)
    heidenhain = CONTROLLERS["heidenhain"]
    plan = heidenhain.build(_table("linear", step=2.0), "values=error")
    with pytest.raises(ControllerRuleError):
        heidenhain.lint(plan)
    com, cma = heidenhain.render(plan, "X.COM")
    with pytest.raises(emu.ControllerAlarm, match="256"):
        emu.load_heidenhain(com, cma, "X", "error")
    isg = CONTROLLERS["isg"]
    plan = isg.build(rotary, "modulo=360,max_points=25")
    with pytest.raises(ControllerRuleError):
        isg.lint(plan)
    with pytest.raises(emu.ControllerAlarm):
        emu.load_isg(isg.render(plan), max_points=25)
    plan = fanuc.build(rotary, "modulo=360,detection_unit=0.00001,value_limit=7")
    with pytest.raises(ControllerRuleError):
        fanuc.lint(plan)
    with pytest.raises(emu.ControllerAlarm):
        emu.load_fanuc(fanuc.render(plan), 0.0, 1e-5, value_limit=7)
    # a table for the measuring system the axis lacks: refused by the lint, and the
    # controller would never apply it
    plan = sinumerik.build(rotary, "modulo=360,system=2")
    with pytest.raises(ControllerRuleError):
        sinumerik.lint(plan)
    assert emu.load_sinumerik(sinumerik.render(plan)).offset(90.0, 1) == 0.0


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=60))
@pytest.mark.slow
def test_options_text_never_crashes(text):
    """Whatever is typed as options is read or refused with a message naming the
    controller, never a crash."""
    for module in CONTROLLERS.values():
        try:
            got = parse_options(module.NAME, module.OPTIONS, text)
        except ControllerRuleError as exc:
            assert str(exc).startswith(module.NAME)
        else:
            assert set(got) == {o.key for o in module.OPTIONS}
