"""When two certificates hold the same readings: the readings as they decide the result,
compared by their values, not by the bytes they were typed or saved in.

No two calibrations repeat every reading to the last digit: one item's readings issued as
another item's certificate (hostile78 F7: 41 readings to 0.1″ issued for LRA-0815, LRA-0900,
… each an original, nothing said) is refused unless the user says why
(:meth:`models.register.store.Register.issue`, ``readings_of_another_item``), and an
original of a withdrawn certificate's readings, of its item, names it even with the date of
calibration moved (hostile78 F3's route left open by a day)."""

from __future__ import annotations

import hashlib
import json
import math
from typing import Any

__all__ = ["readings_key"]

#: significant digits a value is compared to: far below any reading's last digit (20° to
#: 10 digits is 4e-5″; a reading of 0.1″ resolution has 7), far above the float noise of
#: one value written two ways ("12.5" and "12°30'00.0\"" parse within 1e-15 of each other)
#: or an angle re-typed in decimal degrees to 12 places
_DIGITS = 10


def _value(value: Any) -> str:
    """One cell's value as compared: a number to :data:`_DIGITS` significant digits (-0 as
    0), a blank optional cell as "", a text as it parses (a choice in its listed case)."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value.strip()
    number = float(value)
    if math.isnan(number):
        return ""
    text = f"{number:.{_DIGITS}g}"
    return "0" if float(text) == 0 else text


def readings_key(project_json: str, workbench: str) -> str:
    """The identity of the readings that ``project_json`` (a certificate's project state, as
    the register records it) holds for ``workbench``: "" when it holds none that parse (no
    project, no rows, a workbench unknown to this version), else a SHA-256 of exactly this:

    - the rows the analysis reads: each row of the workbench's sheet parsed by the
      workbench's columns (:class:`models.readings.sheet.ReadingsSheet`), blank rows and
      rows of an unreadable cell left out, as the analysis leaves them out;
    - each cell by its value, under its column's key: an angle typed 12°30'00.0" is the
      angle typed 12.5, 12.50 is 12.5, "+1" is 1 (numbers to 10 significant digits, a blank
      optional cell as empty, a text as it parses);
    - the rows as a set with their repeats, their order aside.

    So a re-typed, re-saved or re-ordered file (columns, or rows) of the same values is the
    same readings, and one reading changed in its last digit is not. What is not compared:
    the settings (a unit chosen, a run's layout), the certificate's details, the file's
    name or bytes, the instrument's raw capture."""
    from models.readings.sheet import ReadingsSheet
    from models.registry import KINDS

    try:
        data = json.loads(project_json or "{}")
        bench = (data.get("workbenches") or {}).get(workbench) or {}
        rows = bench.get("rows") if isinstance(bench, dict) else None
        if not isinstance(rows, list) or not rows or workbench not in KINDS:
            return ""
        columns = KINDS[workbench].columns
        parsed = ReadingsSheet(columns, [r if isinstance(r, list) else [r] for r in rows]
                               ).parse()
    except (ValueError, TypeError, AttributeError, LookupError):
        return ""  # no project state this version reads: nothing to compare
    if parsed.n == 0:
        return ""
    keys = [c.key for c in columns]
    table = sorted(tuple(_value(parsed.values[k][i]) for k in keys) for i in range(parsed.n))
    return hashlib.sha256(json.dumps([keys, table], ensure_ascii=False).encode()).hexdigest()
