"""Serial numbers, certificate numbers and dates kept on one line in a wrapped text (a
message box's question): Qt breaks a line after a hyphen or a slash, and a serial broken
there reads as two ("RX-2[G]-" / "[0]815", day review 68 F11). A word joiner (U+2060, drawn
as nothing) after each such character inside a word, and a no-break space for a space inside
a serial named, keep them whole; the characters themselves are unchanged. (Rich text's
``<nobr>`` and ``white-space: nowrap`` do not: Qt still breaks after the hyphen.)"""

from __future__ import annotations

import re
from collections.abc import Iterable

__all__ = ["WORD_JOINER", "unbroken"]

#: U+2060 WORD JOINER: no line break on either side of it, drawn as nothing
WORD_JOINER = "\u2060"
#: a hyphen, dash or slash between two characters of a word (a line may break after it)
_BREAK_AFTER = re.compile(r"(?<=\S)([-\u2010\u2013/])(?=\S)")


def _joined(identifier: str) -> str:
    return _BREAK_AFTER.sub(r"\1" + WORD_JOINER, identifier).replace(" ", "\u00a0")


def unbroken(text: str, identifiers: Iterable[str] = ()) -> str:
    """``text`` with no line break after a hyphen, dash or slash inside a word, nor at a
    space inside one of ``identifiers`` (serials as typed or marked: "12/W I")."""
    for identifier in sorted({i for i in identifiers if " " in i}, key=len, reverse=True):
        text = text.replace(identifier, identifier.replace(" ", "\u00a0"))
    return _BREAK_AFTER.sub(r"\1" + WORD_JOINER, text)
