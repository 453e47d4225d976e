"""Guided acquisition: what the technician does next, said by the workbench.

A workbench that can guide has the capability ``GuidesAcquisition`` (models/workbench.py):
``acquisition_guide(rows, current, settings, step)``, where ``rows`` are the sheet's rows
above the row the next reading goes to, each a mapping of column key to the text typed,
``current`` that row's
cells (a nominal may be filled in already), ``settings`` the workbench's settings and
``step`` the table's nominal step (0: none). It answers a :class:`NextReading`: the
words to show ("go to face 7 (encoder ≈ 105°)", "θ = 12°"), the cells that say which
point the reading is of (filled when blank, with the reading, as one undo step), and
which of the point's n readings it is — the first reading of a point waits for the
instrument to move there, the others are taken where it is.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

__all__ = ["NextReading", "degrees_text", "point_groups", "used_rows"]


@dataclass(frozen=True)
class NextReading:
    #: what to do next (a models.messages.Message: English, translatable)
    text: str
    #: column key -> text, the cells saying which point this is (filled only when blank)
    fill: dict[str, str] = field(default_factory=dict)
    #: this is reading ``reading`` of the point's ``of``
    reading: int = 1
    of: int = 1
    #: column key -> the reading expected there from the plan (degrees; the polygon's and the
    #: cross-calibration's encoder at the face: the set's or mounting's first reading plus
    #: the steps of 360°/N), written into a blank cell at a take when no instrument fills
    #: that column; empty where the workbench does not know it
    nominal: dict[str, float] = field(default_factory=dict)
    #: the angle between two neighbouring points (360°/N of the polygon's N faces; 0: not
    #: known): a reading more than half of it from its :attr:`nominal` is nearer another
    #: point than the one the plan expects (the window warns of it at the take)
    pitch_deg: float = 0.0
    #: column key -> the readings the plan would take there when it cannot say which one
    #: (the polygon's second face of a set: its first reading ± the steps of 360°/N, the way
    #: the encoder counts not known yet); a reading more than half the pitch from every one
    #: of them is nearer another point (warned of at the take, as a :attr:`nominal`)
    near: dict[str, tuple[float, ...]] = field(default_factory=dict)

    @property
    def new_point(self) -> bool:
        return self.reading == 1


def used_rows(rows: Sequence[Mapping[str, str]]) -> list[Mapping[str, str]]:
    """The rows with at least one cell typed."""
    return [r for r in rows if any(str(v).strip() for v in r.values())]


def point_groups(rows: Sequence[Mapping[str, str]], keys: Sequence[str]
                 ) -> list[tuple[tuple[str, ...], list[Mapping[str, str]]]]:
    """Consecutive rows that say the same in ``keys`` (one point's readings), in order."""
    groups: list[tuple[tuple[str, ...], list[Mapping[str, str]]]] = []
    for row in rows:
        key = tuple(str(row.get(k, "")).strip() for k in keys)
        if groups and groups[-1][0] == key:
            groups[-1][1].append(row)
        else:
            groups.append((key, [row]))
    return groups


def degrees_text(value: float) -> str:
    """An approximate angle for the operator: one decimal, none when it is whole."""
    text = f"{value:.1f}"
    return text[:-2] if text.endswith(".0") else text
