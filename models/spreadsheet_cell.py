"""A text cell of a CSV that a spreadsheet shows and never runs: formula (CSV) injection.

A spreadsheet runs a cell that starts with ``=``, ``+``, ``-`` or ``@`` (and, after a tab
or a line break, also one that starts with those) as a formula: ``=HYPERLINK(…)``,
``+cmd|' /C calc'!A0``, ``@SUM(…)``. Such a cell gets an apostrophe in front, which the
spreadsheet takes as "this is text" and does not show (OWASP's advice). Full-width
``＝ ＋ － ＠`` (as a Chinese input method types them) are treated alike.

Numbers and angles are data, not formulas: a cell that is, whole, a number (``-0.5``,
``+3``, ``-1.2e-5``, with a unit such as ``-0.12"`` or ``12 arcsec``) or an angle as the
readings write it (``-19°52'57.0"``, ``-0 00 12.5``) stays as it is, so a spreadsheet
still reads it as the number it is. Nothing a spreadsheet can run has that form.
"""

from __future__ import annotations

import re

__all__ = ["FORMULA_STARTS", "is_number_or_angle", "spreadsheet_safe"]

#: what a spreadsheet takes as the start of a formula (or, tab and line breaks, as the
#: start of a cell whose next character is read as one)
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r", "\n", "\uff1d", "\uff0b", "\uff0d", "\uff20")

_NUM = r"(?:\d+(?:\.\d*)?|\.\d+)"
_UNIT = r"(?:\"|″|°|'|′|%|µrad|μrad|urad|mrad|mdeg|arcsec|deg|rad|mV|V|nm|µm|μm|um|mm)"
_NUMBER = re.compile(rf"[+\-]?{_NUM}(?:[eE][+\-]?\d+)?(?:\s?{_UNIT})?")
# D°M'S" (each part optional after the degrees; ' or ′, " or ″ or '') and D M S
_ANGLE = re.compile(
    rf"[+\-]?{_NUM}°(?:\s*{_NUM}['′](?:\s*{_NUM}(?:\"|″|'')?)?)?"
    rf"|[+\-]?\d+\s+\d+(?:\s+{_NUM})?")


def is_number_or_angle(text: str) -> bool:
    """Whether ``text`` is, whole, a number (perhaps signed, with a unit) or an angle."""
    return bool(_NUMBER.fullmatch(text) or _ANGLE.fullmatch(text))


def spreadsheet_safe(value: object) -> str:
    """``value`` as the text of a CSV cell that no spreadsheet runs: an apostrophe in front
    of a cell that starts (after spaces) like a formula, unless it is a number or an
    angle."""
    text = "" if value is None else str(value)
    if not text.lstrip(" ").startswith(FORMULA_STARTS) or is_number_or_angle(text):
        return text
    return "'" + text
