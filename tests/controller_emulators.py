"""Controllers that read our compensation files as the machine would, and apply them.

Written from the controllers' manuals (the rules the writers cite, read again here), not
from the writers: this helper imports nothing from ``models``. Each ``load_*`` parses the
file text the way the controller does — refusing what the controller would refuse, with
the alarm it would raise — and returns an :class:`Emulated` axis whose ``offset(target,
direction)`` is what the controller adds to a commanded position (in the axis unit). The
rig's axis is driven through it: commanded = target + offset.

The compensation is looked up at the commanded target (a controller that corrects its
measuring system looks it up at the position it reads; the two differ by the slope of the
table times the compensation, second order and far below the tolerances used).

Each controller also has a second, simpler reading of the same application rule
(``simple_*``: vectorised with numpy.interp, sums with numpy.cumsum) that checks the
emulator itself.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np


class ControllerAlarm(Exception):
    """The controller refuses the table (what its alarm would say)."""


@dataclass
class Emulated:
    """``rule(position, direction) -> offset``; an axis the controller drives."""

    rule: Callable[[float, int], float]

    def offset(self, target: float, direction: int) -> float:
        return float(self.rule(float(target), int(direction)))

    def controller(self, target: float, direction: int) -> float:
        return target + self.offset(target, direction)


def _segment(x: float, grid_start: float, step: float, values: list[float]) -> float:
    """Linear interpolation by hand on an equidistant grid, the ends held beyond it."""
    last = len(values) - 1
    u = (x - grid_start) / step
    if u <= 0:
        return values[0]
    if u >= last:
        return values[last]
    i = int(np.floor(u))
    f = u - i
    return values[i] * (1.0 - f) + values[i + 1] * f


def _wrap(x: float, start: float, period: float) -> float:
    return start + (x - start) % period


# -- SINUMERIK 840D -------------------------------------------------------------------------
def load_sinumerik(text: str, active_system: int = 1, md38000: int = 10_000) -> Emulated:
    lines = [ln.strip() for ln in text.splitlines() if ln.strip() and not ln.startswith(";")]
    if lines[0] != "%_N_AX_EEC_INI" or lines[-1] != "M17":
        raise ControllerAlarm("not an EEC file")
    values: dict[int, float] = {}
    scalars: dict[str, float] = {}
    system = None
    for ln in lines[1:-1]:
        m = re.fullmatch(r"\$AA_ENC_COMP\[(\d+),(\d+),(\w+)\]=(\S+)", ln)
        if m:
            system = int(m.group(1))
            values[int(m.group(2))] = float(m.group(4))
            continue
        m = re.fullmatch(r"\$AA_ENC_COMP_(STEP|MIN|MAX|IS_MODULO)\[(\d+),(\w+)\]=(\S+)", ln)
        if m:
            scalars[m.group(1)] = float(m.group(4))
    if system != active_system - 1:  # a table of the other measuring system is not applied
        return Emulated(lambda x, d: 0.0)
    step, lo, hi = scalars["STEP"], scalars["MIN"], scalars["MAX"]
    count = round((hi - lo) / step) + 1
    if count > md38000 or sorted(values) != list(range(count)):
        raise ControllerAlarm("table does not fit MD38000 or has gaps")
    table = [values[i] for i in range(count)]
    modulo = scalars.get("IS_MODULO", 0) == 1
    if modulo and table[0] != table[-1]:
        raise ControllerAlarm("modulo table: 0 and 360 disagree")

    def rule(x: float, d: int) -> float:
        if modulo:
            x = _wrap(x, lo, hi - lo)
        return -_segment(x, lo, step, table)  # a positive value moves the axis negative

    return Emulated(rule)


def simple_sinumerik(text: str, x: np.ndarray) -> np.ndarray:
    v = np.array([float(m) for m in re.findall(r"\$AA_ENC_COMP\[\d+,\d+,\w+\]=(\S+)", text)])
    lo = float(re.search(r"_MIN\[.*\]=(\S+)", text).group(1))
    hi = float(re.search(r"_MAX\[.*\]=(\S+)", text).group(1))
    grid = np.linspace(lo, hi, v.size)
    if re.search(r"IS_MODULO\[.*\]=1", text):
        x = lo + np.mod(x - lo, hi - lo)
    return -np.interp(x, grid, v)


# -- FANUC ----------------------------------------------------------------------------------
def _fanuc_parse(text: str) -> tuple[dict[int, int], dict[int, int]]:
    params, data = {}, {}
    for ln in text.split():
        m = re.fullmatch(r"N(\d+)(?:Q1)?(?:A\d+)?P(-?\d+)", ln)
        if not m:
            continue
        number, value = int(m.group(1)), int(m.group(2))
        (data if number >= 10000 else params)[number % 10000 if number >= 10000 else number] = value
    return params, data


def load_fanuc(text: str, reference_position: float, detection_unit: float,
               value_limit: int = 7) -> Emulated:
    p, data = _fanuc_parse(text)
    ref, neg, pos, mag, interval = p[3620], p[3621], p[3622], p[3623], p[3624]
    unit = detection_unit * mag
    h = interval * detection_unit
    if any(abs(data.get(n, 0)) > value_limit for n in range(neg, pos + 1)):
        raise ControllerAlarm("compensation value out of range")
    rotary = 3625 in p
    absolute = {ref: 0}
    for n in range(ref + 1, pos + 1):  # the value at n is output between n-1 and n
        absolute[n] = absolute[n - 1] + data.get(n, 0)
    for n in range(ref, neg - 1, -1):
        absolute[n - 1] = absolute[n] - data.get(n, 0)
    if rotary:
        if neg != ref or absolute[pos] != 0:
            raise ControllerAlarm("rotary: the sum over one revolution is not zero")
        lowest = ref
    else:
        lowest = neg - 1
    numbers = list(range(lowest, pos + 1))
    table = [absolute[n] * unit for n in numbers]
    start = reference_position + (lowest - ref) * h

    def rule(x: float, d: int) -> float:
        if rotary:
            x = _wrap(x, reference_position, p[3625] * detection_unit)
        return _segment(x, start, h, table)  # a positive value moves the axis positive

    return Emulated(rule)


def simple_fanuc(text: str, x: np.ndarray, reference_position: float,
                 detection_unit: float) -> np.ndarray:
    p, data = _fanuc_parse(text)
    numbers = np.arange(p[3621], p[3622] + 1)
    inc = np.array([data.get(int(n), 0) for n in numbers])
    if 3625 in p:
        inc[0] = 0  # the reference point's own value repeats the last one: one turn from 0
        x = reference_position + np.mod(x - reference_position, p[3625] * detection_unit)
        ends = numbers
    else:
        ends = np.concatenate([[numbers[0] - 1], numbers])
        inc = np.concatenate([[0], inc])
    total = np.cumsum(inc)
    total = total - total[list(ends).index(p[3620])]
    where = reference_position + (ends - p[3620]) * p[3624] * detection_unit
    return np.interp(x, where, total * detection_unit * p[3623])


# -- HEIDENHAIN -----------------------------------------------------------------------------
def _tnc_table(text: str) -> tuple[list[str], list[list[str]]]:
    lines = [ln for ln in text.splitlines() if ln.strip()]
    if not lines[0].startswith("BEGIN") or lines[-1].strip() != "[END]":
        raise ControllerAlarm("not a table")
    return lines[1].split(), [ln.split() for ln in lines[2:-1]]


def load_heidenhain(com: str, cma: str, axis: str, values: str, modulo: float = 0.0) -> Emulated:
    head, rows = _tnc_table(cma)
    active = [r for r in rows if "*" in r]
    if len(active) != 1:
        raise ControllerAlarm("one active line")
    name = active[0][head.index(axis)]
    if not com.startswith(f"BEGIN {name}"):
        raise ControllerAlarm(f"no such compensation table {name}")
    head, rows = _tnc_table(com)
    if len(rows) > 256:
        raise ControllerAlarm("more than 256 entries")
    where = [float(r[head.index("AXISPOS")]) for r in rows]
    fwd = [float(r[head.index(axis)]) for r in rows]
    back = [float(r[head.index("BACKLASH")]) for r in rows] if "BACKLASH" in head else fwd
    sign = -1.0 if values == "error" else 1.0
    step = where[1] - where[0]

    def rule(x: float, d: int) -> float:
        if modulo:
            x = _wrap(x, 0.0, modulo)
        return sign * _segment(x, where[0], step, fwd if d > 0 else back)

    return Emulated(rule)


def simple_heidenhain(com: str, axis: str, values: str, x: np.ndarray, direction: int,
                      modulo: float = 0.0) -> np.ndarray:
    head, rows = _tnc_table(com)
    table = np.array(rows, dtype=float)
    column = head.index("BACKLASH") if direction < 0 and "BACKLASH" in head else head.index(axis)
    if modulo:
        x = np.mod(x, modulo)
    out = np.interp(x, table[:, head.index("AXISPOS")], table[:, column])
    return -out if values == "error" else out


# -- TwinCAT (Tc2_MC2) ----------------------------------------------------------------------
def _twincat_tables(text: str) -> list[tuple[dict[str, str], list[tuple[float, float]]]]:
    out = []
    for m in re.finditer(r"ST_PositionCompensationTableParameter := \((.*?)\);.*?:= \[(.*?)\];",
                         text, re.S):
        params = dict(re.findall(r"(\w+) := ([^,]+)", m.group(1)))
        elements = [(float(a), float(b)) for a, b in re.findall(
            r"\(Position := (\S+), Compensation := (\S+)\)", m.group(2))]
        out.append((params, elements))
    return out


def load_twincat(text: str) -> Emulated:
    tables = {}
    for params, elements in _twincat_tables(text):
        if int(params["NoOfTableElements"]) != len(elements):
            raise ControllerAlarm("table size")
        where = [e[0] for e in elements]
        steps = np.diff(where)
        if np.any(steps <= 0) or np.ptp(steps) > 1e-9 * steps[0]:
            raise ControllerAlarm("not equidistant and monotonic")
        tables[params["Direction"]] = (params, elements)

    def rule(x: float, d: int) -> float:
        key = "WorkDirectionBoth" if "WorkDirectionBoth" in tables else (
            "WorkDirectionPositive" if d > 0 else "WorkDirectionNegative")
        params, elements = tables[key]
        lo, hi = float(params["MinPosition"]), float(params["MaxPosition"])
        if params["Modulo"] == "TRUE":
            x = _wrap(x, lo, hi - lo)
        return _segment(x, lo, elements[1][0] - elements[0][0], [e[1] for e in elements])

    return Emulated(rule)


def simple_twincat(text: str, x: np.ndarray, direction: int) -> np.ndarray:
    tables = {p["Direction"]: (p, np.array(e)) for p, e in _twincat_tables(text)}
    params, e = tables.get("WorkDirectionBoth") or tables[
        "WorkDirectionPositive" if direction > 0 else "WorkDirectionNegative"]
    if params["Modulo"] == "TRUE":
        x = e[0, 0] + np.mod(x - e[0, 0], e[-1, 0] - e[0, 0])
    return np.interp(x, e[:, 0], e[:, 1])


# -- ISG kernel -----------------------------------------------------------------------------
def _isg_list(text: str) -> dict[str, str]:
    out = {}
    for ln in text.splitlines():
        if ln.startswith("#") or not ln.strip():
            continue
        key, value = ln.split(None, 1)
        out[key] = value.strip()
    return out


def load_isg(text: str, max_points: int = 1500) -> Emulated:
    kv = _isg_list(text)
    n = int(kv["kw.ssfk.kw_nr_max"])
    if n >= max_points:
        raise ControllerAlarm("kw_nr_max >= P-COMP-00059")
    unit = 1e-4 if kv["kw.ssfk.unit"] == "1" else None
    if unit is None:
        raise ControllerAlarm("increments need the encoder resolution")
    start, interval = float(kv["kw.ssfk.kw_startpos"]) * unit, float(kv["kw.ssfk.interval"]) * unit
    pos = [int(kv[f"kw.ssfk.table[{i}].pos"]) * unit for i in range(n)]
    neg = [int(kv[f"kw.ssfk.table[{i}].neg"]) * unit for i in range(n)] if \
        kv["kw.ssfk.bilateral"] == "1" else pos
    modulo = kv.get("kw.ssfk.modulo") == "1"

    def rule(x: float, d: int) -> float:
        if modulo:
            x = _wrap(x, start, interval * (n - 1))
        return -_segment(x, start, interval, pos if d > 0 else neg)  # the error is subtracted

    return Emulated(rule)


def simple_isg(text: str, x: np.ndarray, direction: int) -> np.ndarray:
    kv = _isg_list(text)
    column = "neg" if direction < 0 and kv["kw.ssfk.bilateral"] == "1" else "pos"
    keys = sorted((int(re.search(r"\[(\d+)\]", k).group(1)), float(v)) for k, v in kv.items()
                  if k.endswith(f"].{column}"))
    v = np.array([val for _, val in keys]) * 1e-4
    grid = (float(kv["kw.ssfk.kw_startpos"]) + float(kv["kw.ssfk.interval"]) * np.arange(v.size)) * 1e-4
    if kv.get("kw.ssfk.modulo") == "1":
        x = grid[0] + np.mod(x - grid[0], grid[-1] - grid[0])
    return -np.interp(x, grid, v)


# -- Mach4 ----------------------------------------------------------------------------------
def _mach4(text: str) -> tuple[dict[str, str], list[list[str]], list[str]]:
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith(";")]
    kv = dict(ln.split("=", 1) for ln in lines if "=" in ln)
    rows = [ln.split(",") for ln in lines if "," in ln]
    return kv, rows[1:], rows[0]


def load_mach4(text: str) -> Emulated:
    kv, rows, head = _mach4(text)
    start, length, points = float(kv["Start"]), float(kv["Length"]), int(kv["Points"])
    if len(rows) != points:
        raise ControllerAlarm("number of points")
    step = length / (points - 1)  # points = intervals + 1
    if "Error" in head:
        plus = minus = [float(r[head.index("Error")]) for r in rows]
    else:
        plus = [float(r[head.index("PositiveError")]) for r in rows]
        minus = [float(r[head.index("NegativeError")]) for r in rows]

    def rule(x: float, d: int) -> float:  # expected − actual: added to the command
        return _segment(x, start, step, plus if d > 0 else minus)

    return Emulated(rule)


def simple_mach4(text: str, x: np.ndarray, direction: int) -> np.ndarray:
    kv, rows, head = _mach4(text)
    table = np.array(rows, dtype=float)
    column = head.index("Error") if "Error" in head else head.index(
        "PositiveError" if direction > 0 else "NegativeError")
    grid = float(kv["Start"]) + np.linspace(0.0, float(kv["Length"]), int(kv["Points"]))
    return np.interp(x, grid, table[:, column])
