"""Column headers as labs write them: ``theta_deg``, ``θ``, ``转角θ/°``, ``A(″)``,
``方位角 A [deg]`` … matched to a workbench's columns.

A header is normalised (case, spaces, underscores and the unit in brackets, after a
slash, or as a known unit word removed) and compared with each column's key, title,
the key without its unit suffix, and the column's aliases (English and Chinese).
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from models.readings.sheet import Column

__all__ = ["match_header", "names_of", "normalise_header"]

_BRACKETED = re.compile(r"[\[\(（【].*?[\]\)）】]")
_UNIT_WORDS = ("arcsec", "arcmin", "deg", "µrad", "urad", "rad", "mm", "µm", "um", "nm", "mv",
               "v", "″", "′", "°", '"', "'", "秒", "度")
_SEPARATORS = re.compile(r"[\s_\-:：,，.]+")


def _cjk(text: str) -> bool:
    return any("\u4e00" <= ch <= "\u9fff" for ch in text)


def normalise_header(text: str) -> str:
    t = _BRACKETED.sub("", str(text)).strip().lower()
    if "/" in t:  # 转角θ/° , theta/deg: the quantity before the unit
        t = t.split("/", 1)[0]
    t = _SEPARATORS.sub("", t)
    for unit in sorted(_UNIT_WORDS, key=len, reverse=True):
        if t.endswith(unit) and len(t) > len(unit):
            t = t[: -len(unit)]
            break
    return t


def names_of(column: Column) -> set[str]:
    """Every normalised name the column answers to."""
    raw = {column.key, column.title, column.header, *column.aliases}
    base = re.sub(r"_(deg|arcsec|arcmin|rad|urad|um|nm|mm|v)$", "", column.key)
    raw.add(base)
    return {n for n in (normalise_header(r) for r in raw) if n}


def match_header(header: Sequence[str], columns: Sequence[Column]) -> list[int | None]:
    """Return, for each column, the index of the header cell that names it, or None when
    no cell does. A cell that is exactly the column's key wins over a cell that matches only
    after normalising, and each header cell names at most one column."""
    names = [normalise_header(h) for h in header]
    exact = [str(h).strip().lower() for h in header]
    taken: set[int] = set()
    out: list[int | None] = []
    for column in columns:
        found = next((i for i, n in enumerate(exact) if n == column.key.lower()
                      and i not in taken), None)
        if found is None:
            wanted = names_of(column)
            found = next((i for i, n in enumerate(names) if n in wanted and i not in taken), None)
        if found is None:  # "方位角A", "azimuth A": a long enough name and its symbol
            long = [w for w in names_of(column) if len(w) >= (2 if _cjk(w) else 4)]
            found = next((i for i, n in enumerate(names) if i not in taken
                          and any(n.startswith(w) for w in long)), None)
        if found is not None:
            taken.add(found)
        out.append(found)
    return out
