"""What a certificate changes of what decides its result, against an earlier certificate of
the same calibration: the tolerance, the decision rule, the decided quantity, the coverage
probability, the item's grade and resolution, the document asked for, the laboratory and its
accreditation, the reference standards, the readings and the analysis settings, each
compared with the project state recorded with the earlier one.

An amendment says what it changes (ISO/IEC 17025 7.8.8.2). The register stated a corrected
serial, date, maker, customer or description, and otherwise only the note typed: an
amendment of a "conditional pass" at ±1″ issued with ±3″ and the simple rule read "pass"
and "Changed: typo in the address" (hostile78 F1). These changes are stated unasked, before
the note, by :meth:`models.register.store.Register.issue`; an original issued in place of a
withdrawn certificate of the same calibration states them too (hostile78 F3)."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

from models.messages import QT_TR_NOOP, Message, message

__all__ = ["basis_changes", "same_readings"]

#: the details that decide a result, each with how its change is said
_DECIDING: tuple[tuple[str, str], ...] = (
    ("decision_rule", QT_TR_NOOP("decision rule changed from {old} (on {number}) to {new}")),
    ("decision_quantity", QT_TR_NOOP("decided quantity changed from {old} (on {number}) to "
                                     "{new}")),
    ("coverage_probability_pct", QT_TR_NOOP("coverage probability changed from {old} % (on "
                                            "{number}) to {new} %")),
    ("item_grade", QT_TR_NOOP("grade / specification changed from {old} (on {number}) to "
                              "{new}")),
    ("document_type", QT_TR_NOOP("document asked for changed from {old} (on {number}) to "
                                 "{new}")),
    # who certifies it: the laboratory and its accreditation
    ("lab_name", QT_TR_NOOP("laboratory changed from {old} (on {number}) to {new}")),
    ("lab_accreditation", QT_TR_NOOP("accreditation changed from {old} (on {number}) to "
                                     "{new}")),
)


def _state(project_json: str, workbench: str) -> tuple[list, dict, dict]:
    """The readings' rows, the settings and the certificate details ``project_json`` holds
    for ``workbench`` (empty where it holds none, or is no project)."""
    try:
        data = json.loads(project_json or "{}")
    except ValueError:
        return [], {}, {}
    if not isinstance(data, dict):
        return [], {}, {}
    bench = (data.get("workbenches") or {}).get(workbench) or {}
    details = ((data.get("metadata") or {}).get("certificates") or {}).get(workbench) or {}
    rows = bench.get("rows") if isinstance(bench, dict) else None
    settings = bench.get("settings") if isinstance(bench, dict) else None
    return (rows if isinstance(rows, list) else [],
            settings if isinstance(settings, dict) else {},
            details if isinstance(details, dict) else {})


def _filled(rows: Sequence[Any]) -> list[tuple[str, ...]]:
    """The rows that hold a reading, each cell as typed less the spaces about it and the
    empty cells at its end (a sheet pads its rows; the command line does not)."""
    out = []
    for row in rows:
        cells = [str(c).strip() if c is not None else "" for c in
                 (row if isinstance(row, list | tuple) else [row])]
        while cells and not cells[-1]:
            cells.pop()
        if cells:
            out.append(tuple(cells))
    return out


def same_readings(project_a: str, project_b: str, workbench: str) -> bool:
    """Whether two project states hold the same readings for ``workbench`` (as typed, the
    rows that hold one, spaces about a cell aside) — and some."""
    a = _filled(_state(project_a, workbench)[0])
    return bool(a) and a == _filled(_state(project_b, workbench)[0])


def _shown(value: Any) -> str:
    if value is None or value == "":
        return "—"
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def _symbol(unit: Any) -> str:
    """A unit key's symbol as the certificate prints it (models.quantity.UNITS); the key
    itself when it is none of them."""
    from models.quantity import UNITS

    known = UNITS.get(unit) if isinstance(unit, str) else None
    return getattr(known, "symbol", "") or str(unit or "")


def _with_unit(value: Any, unit: Any) -> str:
    symbol = _symbol(unit)
    gap = "" if symbol in ('"', "″", "°", "′", "'") else " "
    return f"{_shown(value)}{gap}{symbol}".strip()


def _tolerance(details: Mapping[str, Any]) -> str:
    value = details.get("tolerance")
    if value in (None, "", 0, 0.0):
        return "—"
    return "±" + _with_unit(value, details.get("tolerance_unit"))


def _resolution(details: Mapping[str, Any]) -> str:
    value = details.get("item_resolution")
    if value in (None, ""):
        return "—"
    return _with_unit(value, details.get("item_resolution_unit"))


def _standard(entry: Any) -> str:
    if not isinstance(entry, dict):
        return str(entry)
    figure = "" if entry.get("uncertainty") in (None, "") else (
        f"{_with_unit(entry.get('uncertainty'), entry.get('uncertainty_unit'))} "
        f"{entry.get('basis') or ''}").strip()
    parts = [entry.get("description") or "", entry.get("serial") or "",
             entry.get("certificate_no") or "", figure,
             entry.get("applies_to") or "", entry.get("due_date") or ""]
    return " ".join(str(p) for p in parts if p)


def _rows_changed(old: list[tuple[str, ...]], new: list[tuple[str, ...]]) -> list[int]:
    """The rows (0-based) that differ, the longer list's extra rows counted."""
    return [i for i in range(max(len(old), len(new)))
            if i >= len(old) or i >= len(new) or old[i] != new[i]]


def basis_changes(original_project: str, project: str, workbench: str, number: str
                  ) -> tuple[Message, ...]:
    """What ``project`` (a certificate's project state, its details final) changes against
    ``original_project``, the one recorded with certificate ``number``, of what decides the
    result: each said as "tolerance changed from ±1 arcsec (on N) to ±3 arcsec"; () when
    nothing, or when the original recorded no project state to compare."""
    from models.certificate.readings_origin import row_spans

    old_rows, old_settings, old = _state(original_project, workbench)
    new_rows, new_settings, new = _state(project, workbench)
    if not old and not old_rows:
        return ()
    said: list[Message] = []
    if _tolerance(old) != _tolerance(new):
        said.append(message(QT_TR_NOOP("tolerance changed from {old} (on {number}) to {new}"),
                            old=_tolerance(old), number=number, new=_tolerance(new)))
    for key, template in _DECIDING:
        if _shown(old.get(key)) != _shown(new.get(key)):
            said.append(message(template, old=_shown(old.get(key)), number=number,
                                new=_shown(new.get(key))))
    if _resolution(old) != _resolution(new):
        said.append(message(QT_TR_NOOP("item's resolution changed from {old} (on {number}) "
                                       "to {new}"),
                            old=_resolution(old), number=number, new=_resolution(new)))
    old_standards = [_standard(s) for s in old.get("standards") or []]
    new_standards = [_standard(s) for s in new.get("standards") or []]
    if old_standards != new_standards:
        said.append(message(QT_TR_NOOP("reference standards changed from {old} (on {number}) "
                                       "to {new}"),
                            old="; ".join(old_standards) or "—", number=number,
                            new="; ".join(new_standards) or "—"))
    before, now = _filled(old_rows), _filled(new_rows)
    changed = _rows_changed(before, now)
    if changed:
        said.append(message(QT_TR_NOOP("readings changed from those of {number}: row(s) "
                                       "{rows} ({old} rows there, {new} here)"),
                            number=number, rows=row_spans(changed), old=len(before),
                            new=len(now)))
    settings = [f"{key} {_shown(old_settings.get(key))} → {_shown(new_settings.get(key))}"
                for key in sorted(set(old_settings) | set(new_settings))
                if _setting_changed(key, old_settings, new_settings)]
    if settings:
        said.append(message(QT_TR_NOOP("analysis settings changed from those of {number}: "
                                       "{settings}"),
                            number=number, settings=", ".join(settings)))
    return tuple(said)


def _setting_changed(key: str, old: Mapping[str, Any], new: Mapping[str, Any]) -> bool:
    """A setting set on both sides to other values, or on one side only to a value that
    sets something (a key one side's version did not write, at its empty value, is not a
    change)."""
    if key in old and key in new:
        return json.dumps(old[key], sort_keys=True) != json.dumps(new[key], sort_keys=True)
    value = old.get(key) if key in old else new.get(key)
    return value not in (None, "", 0, 0.0, False, [], {})
