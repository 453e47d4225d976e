"""An entry plan: the order in which a test's points are taken, so that entry follows the run.

A plan is the list of the test's points in the order they are measured; each point names
the cells the plan itself fills (positioning: target, run and direction; polygon: face,
set and direction; cross-calibration: mounting and face; theodolite: θ, run and
direction). The readings of a point (the deviation, the encoder and autocollimator
readings, the theodolite's azimuth and elevation) are what the technician types or the
instrument sends; the plan never writes them.

API (plain Python, no Qt; the window's readings table and the capture panel both use it)::

    plan = positioning_plan(targets_from(0.0, 30.0, 13), runs=5, bidirectional=True)
    place = plan.placement(rows, reading_keys=("deviation", "measured"))
    # place.row:   the table row the next reading goes to (an existing row holding this
    #              point's plan cells and no reading yet, else the first row after the last
    #              filled one; == len(rows) means "append a row")
    # place.cells: {column key: text} the plan writes into that row (target, run, dir)
    # place.point: the PlanPoint (place.point.label: "target 120°, run 3 ↓")
    plan.fill(rows, reading_keys, [6, 7])  # readings pasted without the plan's cells: their
    #                                        points, in order ([(row, PlanPoint), …])
    plan.next_text(rows, reading_keys)   # "next: target 120°, run 3 ↓" / "plan complete"
    plan.progress(rows, reading_keys)    # (points taken, points in the plan)
    plan.as_dict() / EntryPlan.from_dict(d)   # saved with the lab defaults / project

With n readings per point (the workbench's ``readings_per_point``, averaged n rows at a
time by models/readings/repeats.py) each point is n rows with the same plan cells, one
after another, each labelled with its reading ("set 1: face 3 of 12, reading 2 of 2"): a
plan of one row per point put a face's second reading in the next face's row (plan80).

``rows`` is the table as a list of {column key: cell text}. A row *takes* a plan point
when its plan cells equal the point's (numbers compared as numbers, "+"/"↑"/"up" as one
direction) and at least one of ``reading_keys`` is filled. ``placement`` returns None when
every point of the plan is taken.

Each point's ``cells`` are exactly the texts to write; ``label`` is a
:class:`~models.messages.Message` (translated by the window).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from models.messages import QT_TR_NOOP, Message, message
from models.readings.angles import AngleParseError, parse_angle_deg

__all__ = ["PLAN_MAKERS", "EntryPlan", "Placement", "PlanPoint", "crosscal_plan", "polygon_plan",
           "positioning_plan", "same_cell", "targets_from", "targets_from_text",
           "theodolite_plan"]

_UP = ("+", "↑", "up")
_DOWN = ("-", "−", "↓", "down")


def same_cell(a: str, b: str) -> bool:
    """Whether two cell texts mean the same plan value: numbers as numbers (30 = 30.0),
    directions as directions (+ = ↑ = up), other text as text."""
    a, b = str(a).strip(), str(b).strip()
    if a == b:
        return True
    for group in (_UP, _DOWN):
        if a.lower() in group and b.lower() in group:
            return True
    try:
        x, y = parse_angle_deg(a), parse_angle_deg(b)  # plain numbers, or D°M'S" in the cell
    except (AngleParseError, ValueError):
        return False
    return math.isfinite(x) and math.isfinite(y) and abs(x - y) <= 1e-9 * max(1.0, abs(x))


@dataclass(frozen=True)
class PlanPoint:
    """One point of a plan: its place in the order, the cells the plan fills and a label."""

    index: int
    cells: Mapping[str, str]
    label: Message

    def taken_by(self, row: Mapping[str, str]) -> bool:
        """Whether ``row`` holds this point's plan cells (whatever its readings)."""
        return all(same_cell(row.get(k, ""), v) for k, v in self.cells.items())


@dataclass(frozen=True)
class Placement:
    """Where the next reading goes: ``row`` (``len(rows)``: a new row) and the plan's cells."""

    row: int
    cells: Mapping[str, str]
    point: PlanPoint


def _filled(row: Mapping[str, str], keys: Sequence[str]) -> bool:
    return any(str(row.get(k, "")).strip() for k in keys)


def _blank(row: Mapping[str, str]) -> bool:
    return not any(str(v).strip() for v in row.values())


@dataclass(frozen=True)
class EntryPlan:
    """The points of a test in the order they are taken; ``kind`` names the plan's maker
    (``cycle``: positioning's ISO 230-2 test cycle, ``sets``: a polygon test's sets,
    ``mountings``: a cross-calibration's, ``passes``: a theodolite run's) and ``spec`` its
    inputs (what :meth:`as_dict` saves)."""

    kind: str
    spec: Mapping[str, Any]
    points: tuple[PlanPoint, ...]

    def __len__(self) -> int:
        return len(self.points)

    def taken(self, rows: Sequence[Mapping[str, str]], reading_keys: Sequence[str]) -> list[bool]:
        """For each plan point, whether a row with a reading takes it."""
        used = [False] * len(rows)
        out = []
        for point in self.points:
            hit = next((i for i, r in enumerate(rows)
                        if not used[i] and _filled(r, reading_keys) and point.taken_by(r)), None)
            if hit is not None:
                used[hit] = True
            out.append(hit is not None)
        return out

    def progress(self, rows: Sequence[Mapping[str, str]],
                 reading_keys: Sequence[str]) -> tuple[int, int]:
        """(points taken, points in the plan)."""
        return sum(self.taken(rows, reading_keys)), len(self.points)

    def next_point(self, rows: Sequence[Mapping[str, str]],
                   reading_keys: Sequence[str]) -> PlanPoint | None:
        """The first point of the plan no row has taken; None when all are."""
        taken = self.taken(rows, reading_keys)
        return next((p for p, t in zip(self.points, taken, strict=True) if not t), None)

    def placement(self, rows: Sequence[Mapping[str, str]],
                  reading_keys: Sequence[str]) -> Placement | None:
        """Where the next reading goes (see the module's docstring); None: plan complete.
        A filled row is never chosen."""
        point = self.next_point(rows, reading_keys)
        if point is None:
            return None
        waiting = next((i for i, r in enumerate(rows)
                        if not _filled(r, reading_keys) and point.taken_by(r)), None)
        if waiting is not None:
            return Placement(waiting, dict(point.cells), point)
        last = max((i for i, r in enumerate(rows) if not _blank(r)), default=-1)
        row = last + 1
        # an empty row directly after the last used one is reused; otherwise append
        return Placement(row if row < len(rows) else len(rows), dict(point.cells), point)

    def fill(self, rows: Sequence[Mapping[str, str]], reading_keys: Sequence[str],
             candidates: Sequence[int]) -> list[tuple[int, PlanPoint]]:
        """The plan's points for the rows ``candidates`` (in that order) that hold a reading
        and not all of the plan's cells (readings pasted in the plan's rows): each the first
        point no row has taken that agrees with the plan cells the row holds — with none,
        the next point, as if the rows had been typed one by one. A row holding all its
        plan cells keeps them (its point is skipped); a row whose cells no point left
        agrees with gets none. (row, point) of each row given a point; the caller writes
        the point's cells the row does not hold."""
        keys = sorted({k for p in self.points for k in p.cells})
        table: list[dict[str, str]] = [dict(r) for r in rows]
        out: list[tuple[int, PlanPoint]] = []
        for r in candidates:
            if not (0 <= r < len(table)) or not _filled(table[r], reading_keys):
                continue
            have = {k: str(table[r].get(k, "")).strip() for k in keys}
            have = {k: v for k, v in have.items() if v}
            if len(have) == len(keys):
                continue
            taken = self.taken(table, reading_keys)
            point = next((p for p, t in zip(self.points, taken, strict=True) if not t and
                          all(same_cell(v, p.cells.get(k, "")) for k, v in have.items())),
                         None)
            if point is None:
                continue
            table[r].update(point.cells)
            out.append((r, point))
        return out

    def next_text(self, rows: Sequence[Mapping[str, str]],
                  reading_keys: Sequence[str]) -> Message:
        """"next: target 120°, run 3 ↓" (the label of the next point), or "plan complete"."""
        point = self.next_point(rows, reading_keys)
        if point is None:
            return message(QT_TR_NOOP("plan complete ({n} points)"), n=len(self.points))
        return message(QT_TR_NOOP("next: {point}"), point=point.label)

    def as_dict(self) -> dict[str, Any]:
        """What the lab defaults and the project file keep (the maker and its inputs)."""
        return {"kind": self.kind, **dict(self.spec)}

    @staticmethod
    def from_dict(data: Mapping[str, Any]) -> EntryPlan:
        """The plan :meth:`as_dict` saved (ValueError naming what is wrong)."""
        if not isinstance(data, Mapping) or data.get("kind") not in PLAN_MAKERS:
            raise ValueError(message(QT_TR_NOOP("not an entry plan: {data}"),
                                     data=str(data)[:80]))
        spec = {k: v for k, v in data.items() if k != "kind"}
        try:
            return PLAN_MAKERS[data["kind"]](**spec)
        except TypeError as exc:
            raise ValueError(message(QT_TR_NOOP("entry plan: {reason}"), reason=str(exc))) \
                from None


def _number(value: float) -> str:
    """A plan value as the cell shows it: the shortest text of the number (30, 7.5)."""
    return f"{float(value):.10g}"


def targets_from(start: float, step: float, count: int) -> list[float]:
    """``count`` targets from ``start`` in steps of ``step`` (ISO 230-2's target positions)."""
    if not (isinstance(count, int) and count >= 2):
        raise ValueError(message(QT_TR_NOOP("a test plan needs at least 2 targets, not {count}"),
                                 count=count))
    if not (math.isfinite(start) and math.isfinite(step) and step != 0):
        raise ValueError(message(QT_TR_NOOP("a test plan needs a finite, non-zero step")))
    return [start + k * step for k in range(count)]


def targets_from_text(text: str) -> list[float]:
    """Targets written as ``start:step:count`` ("0:30:13") or as a list ("0, 30, 60"; D°M′S″
    allowed); ValueError naming what is wrong."""
    text = str(text).strip()
    if ":" in text and "°" not in text and text.count(":") == 2:
        start, step, count = (part.strip() for part in text.split(":"))
        try:
            return targets_from(float(start), float(step), int(count))
        except ValueError as exc:
            if isinstance(exc.args[0] if exc.args else None, Message):
                raise
            raise ValueError(message(QT_TR_NOOP("test plan targets '{text}': write start:step:"
                                                "count (0:30:13) or a list (0, 30, 60)"),
                                     text=text)) from None
    parts = [p for p in text.replace(";", ",").split(",") if p.strip()]
    try:
        targets = [parse_angle_deg(p) for p in parts]
        if len(targets) < 2:
            raise ValueError("one target")
        return targets
    except (AngleParseError, ValueError):
        raise ValueError(message(QT_TR_NOOP("test plan targets '{text}': write start:step:count "
                                            "(0:30:13) or a list (0, 30, 60)"), text=text)) \
            from None


def _check_count(name: str, value: Any, least: int = 1) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or value < least:
        raise ValueError(message(QT_TR_NOOP("a test plan needs {name} ≥ {least}, not {value}"),
                                 name=name, least=least, value=value))
    return value


def positioning_plan(targets: Sequence[float], runs: int = 5, bidirectional: bool = True,
                     order: str = "linear", unit: str = "°", readings: int = 1) -> EntryPlan:
    """ISO 230-2's test cycle over ``targets`` (in the target unit, ``unit`` its symbol).

    ``linear`` (ISO 230-2 standard test cycle): run 1 forward over the targets in rising
    order, then (bidirectional) backward in falling order, then run 2, …
    ``pilgrim`` (the pilgrim-step cycle): every approach of one target before the next
    target: at each target in rising order, run 1 ↑ (and ↓), run 2 ↑ (and ↓), …
    Fills ``target``, ``run`` and ``direction`` (+ forward, − backward); each approach is
    ``readings`` rows, one per reading of the point (the workbench's readings per point).
    """
    targets = [float(t) for t in targets]
    if len(targets) < 2 or not all(math.isfinite(t) for t in targets):
        raise ValueError(message(QT_TR_NOOP("a test plan needs at least 2 finite targets")))
    if len({round(t, 9) for t in targets}) != len(targets):
        raise ValueError(message(QT_TR_NOOP("a test plan lists a target twice")))
    _check_count("runs", runs)
    _check_count("readings", readings)
    if order not in ("linear", "pilgrim"):
        raise ValueError(message(QT_TR_NOOP("test plan order '{order}': linear or pilgrim"),
                                 order=order))
    rising = sorted(targets)
    approaches: list[tuple[float, int, int]] = []
    if order == "linear":
        for run in range(1, runs + 1):
            approaches += [(t, run, 1) for t in rising]
            if bidirectional:
                approaches += [(t, run, -1) for t in reversed(rising)]
    else:
        for t in rising:
            for run in range(1, runs + 1):
                approaches.append((t, run, 1))
                if bidirectional:
                    approaches.append((t, run, -1))
    rows = [row for t, run, d in approaches for row in _readings_of(
        {"target": _number(t), "run": str(run), "direction": "+" if d > 0 else "-"},
        message(QT_TR_NOOP("target {target}, run {run} {arrow}"), target=f"{_number(t)}{unit}",
                run=run, arrow="↑" if d > 0 else "↓"), readings)]
    points = tuple(PlanPoint(i, cells, label) for i, (cells, label) in enumerate(rows))
    return EntryPlan("cycle", _with_readings({"targets": targets, "runs": runs,
                                              "bidirectional": bool(bidirectional),
                                              "order": order, "unit": unit}, readings), points)


def _readings_of(cells: Mapping[str, str], label: Message,
                 readings: int) -> list[tuple[Mapping[str, str], Message]]:
    """A point's ``readings`` rows (the workbench's readings per point n, taken one after
    another, averaged by models/readings/repeats.py): its cells on each, its label saying
    which reading of the point it is when there is more than one."""
    if readings == 1:
        return [(cells, label)]
    return [(cells, message(QT_TR_NOOP("{point}, reading {k} of {n}"), point=label, k=k,
                            n=readings)) for k in range(1, readings + 1)]


def _with_readings(spec: dict[str, Any], readings: int) -> dict[str, Any]:
    """A plan's inputs as saved: ``readings`` only when more than one, so a plan of one
    reading per point saves as the versions before it did (they had no such input; a
    saved plan without it is one reading per point)."""
    return {**spec, "readings": readings} if readings > 1 else spec


def polygon_plan(faces: int, sets: int = 1, closure: bool = True,
                 alternate: bool = False, readings: int = 1) -> EntryPlan:
    """A polygon test: each set reads faces 1…n in order (a reverse set, with
    ``alternate`` every second one: 1, n, n − 1, …, 2), then face 1 again for the closure.
    Each face (and the closure) is ``readings`` rows, one per reading of the face (the
    workbench's readings per point). Fills ``position``, ``set`` and ``direction``."""
    _check_count("faces", faces, 3)
    _check_count("sets", sets)
    _check_count("readings", readings)
    points: list[PlanPoint] = []
    for s in range(1, sets + 1):
        reverse = alternate and s % 2 == 0
        order = [1] + (list(range(faces, 1, -1)) if reverse else list(range(2, faces + 1)))
        if closure:
            order.append(1)
        for q, face in enumerate(order):
            label = (message(QT_TR_NOOP("set {set}: closure on face {face}"), set=s, face=face)
                     if closure and q == len(order) - 1 else
                     message(QT_TR_NOOP("set {set}: face {face} of {faces}"), set=s, face=face,
                             faces=faces))
            cells = {"position": str(face), "set": str(s), "direction": "-" if reverse else "+"}
            points += [PlanPoint(len(points) + k, c, text)
                       for k, (c, text) in enumerate(_readings_of(cells, label, readings))]
    return EntryPlan("sets", _with_readings({"faces": faces, "sets": sets,
                                             "closure": bool(closure),
                                             "alternate": bool(alternate)}, readings),
                     tuple(points))


def crosscal_plan(faces: int, mountings: int | None = None, closure: bool = False) -> EntryPlan:
    """A cross-calibration: mounting j (0, 1, …) reads every face from face j + 1 (the face
    it brings to the encoder's first step) round to face j, then (``closure``) face j + 1
    again. Fills ``mounting`` and ``position``."""
    _check_count("faces", faces, 3)
    mountings = faces if mountings is None else _check_count("mountings", mountings, 2)
    if mountings > faces:
        raise ValueError(message(QT_TR_NOOP("a test plan of {faces} faces has at most {faces} "
                                            "mountings, not {mountings}"),
                                 faces=faces, mountings=mountings))
    points: list[PlanPoint] = []
    for j in range(mountings):
        order = [(j + q) % faces + 1 for q in range(faces)] + ([j + 1] if closure else [])
        for q, face in enumerate(order):
            label = (message(QT_TR_NOOP("mounting {mounting}: closure on face {face}"),
                             mounting=j, face=face) if closure and q == faces else
                     message(QT_TR_NOOP("mounting {mounting}: face {face} ({k} of {faces})"),
                             mounting=j, face=face, k=q + 1, faces=faces))
            points.append(PlanPoint(len(points), {"mounting": str(j), "position": str(face)},
                                    label))
    return EntryPlan("mountings", {"faces": faces, "mountings": mountings,
                                  "closure": bool(closure)}, tuple(points))


def theodolite_plan(thetas: Sequence[float], runs: int = 1,
                    bidirectional: bool = False, readings: int = 1) -> EntryPlan:
    """A theodolite run over the θ steps: pass 1 forward (and backward), pass 2, …
    Fills ``theta_deg``, and ``run`` and ``direction`` when there is more than one pass;
    each θ is ``readings`` rows, one per reading of the point (readings per point)."""
    thetas = [float(t) for t in thetas]
    if len(thetas) < 3 or not all(math.isfinite(t) for t in thetas):
        raise ValueError(message(QT_TR_NOOP("a theodolite plan needs at least 3 finite θ")))
    _check_count("runs", runs)
    _check_count("readings", readings)
    several = runs > 1 or bidirectional
    points: list[PlanPoint] = []
    for run in range(1, runs + 1):
        passes = [(thetas, 1)] + ([(thetas[::-1], -1)] if bidirectional else [])
        for steps, d in passes:
            for t in steps:
                cells = {"theta_deg": _number(t)}
                if several:
                    cells.update(run=str(run), direction="+" if d > 0 else "-")
                label = (message(QT_TR_NOOP("θ = {theta}, pass {run} {arrow}"),
                                 theta=f"{_number(t)}°", run=run, arrow="↑" if d > 0 else "↓")
                         if several else message(QT_TR_NOOP("θ = {theta}"),
                                                 theta=f"{_number(t)}°"))
                points += [PlanPoint(len(points) + k, c, text)
                           for k, (c, text) in enumerate(_readings_of(cells, label, readings))]
    return EntryPlan("passes", _with_readings({"thetas": thetas, "runs": runs,
                                               "bidirectional": bool(bidirectional)}, readings),
                     tuple(points))


#: each plan's maker by its kind (EntryPlan.from_dict)
PLAN_MAKERS: dict[str, Callable[..., EntryPlan]] = {
    "cycle": positioning_plan, "sets": polygon_plan, "mountings": crosscal_plan,
    "passes": theodolite_plan}
