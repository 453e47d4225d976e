"""The readings table's cell marks as a project file keeps them (``cell_marks`` of a
workbench, optional: absent in a file written before it existed, which opens with no
marks): a take's reading at another face or target than its row's (app/capture/panel.py),
marked while its cell holds the text the take wrote (gui77: save, reopen, and the marks
were gone).

Each mark is ``{"row": 1-based row, "column": the column's key, "text": the cell's text
when marked, "note": what is said of it}``; the note is ``{"template": English source,
"figures": {name: text}}`` — said again in the language of the window that opens it — or,
for a text of no known source, the text as it was shown. A mark that cannot be read is left
out (a project is never refused for one: its cells are what count, and they are kept).
"""

from __future__ import annotations

from typing import Any

from models.messages import Message

__all__ = ["CellMark", "mark_from_json", "mark_to_json", "marks_from_json"]

#: (row 0-based, column key, the cell's text when marked, the note: a Message or a text)
CellMark = tuple[int, str, str, str]


def mark_to_json(row: int, column: str, text: str, note: Any) -> dict[str, Any]:
    """One mark as the file keeps it. ``note``: a :class:`Message` (its template and
    figures), a text that remembers its source (``spelt``: (source, figures), the window's
    ``tr(…).format(…)``), or a plain text."""
    spelt = getattr(note, "spelt", None)
    if isinstance(note, Message) and not note.parts:
        kept: Any = {"template": note.template,
                     "figures": {k: str(v) for k, v in note.figures.items()}}
    elif spelt is not None:
        kept = {"template": str(spelt[0]), "figures": {k: str(v) for k, v in spelt[1].items()}}
    else:
        kept = str(note)
    return {"row": int(row) + 1, "column": str(column), "text": str(text), "note": kept}


def mark_from_json(raw: Any) -> CellMark | None:
    """One mark read back (None: not a mark this version can read)."""
    if not isinstance(raw, dict):
        return None
    row, column, text, note = (raw.get(k) for k in ("row", "column", "text", "note"))
    if not (isinstance(row, int) and not isinstance(row, bool) and row >= 1
            and isinstance(column, str) and isinstance(text, str)):
        return None
    if isinstance(note, dict):
        template, figures = note.get("template"), note.get("figures", {})
        if not isinstance(template, str) or not isinstance(figures, dict) \
                or not all(isinstance(k, str) and isinstance(v, str) for k, v in figures.items()):
            return None
        try:
            note = Message(template, figures)
        except (KeyError, IndexError, ValueError):  # a template its figures do not fill
            return None
    elif not isinstance(note, str):
        return None
    return row - 1, column, text, note


def marks_from_json(raw: Any) -> list[CellMark]:
    """The marks a workbench's ``cell_marks`` holds, those that can be read."""
    if not isinstance(raw, list):
        return []
    return [mark for mark in map(mark_from_json, raw) if mark is not None]
