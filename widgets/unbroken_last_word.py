"""The end of a wrapped Chinese text kept from standing alone on its last line: Qt may break a
line between any two ideographs, and a caption ending "…少于 5 次测量：已标注" wrapped with
"标注" (flagged) alone on its third line, the "已" (already) of its word left above it (day 74
finding 13). Its last ideographs are joined by word joiners (U+2060, drawn as nothing, no line
break on either side), so that the last line holds at least that many of them; the characters
themselves are unchanged, and only a few are joined, so a narrow label still wraps. A text
that does not end in ideographs (English) is as it is: it breaks at its spaces."""

from __future__ import annotations

import unicodedata

from widgets.unbroken_identifiers import WORD_JOINER

__all__ = ["LAST_WORD", "unbroken_last_word"]

#: how many ideographs at a text's end are kept on one line (a Chinese word is mostly two
#: characters; three keep a word with the character before it, "已标注")
LAST_WORD = 3


def _ideograph(character: str) -> bool:
    """A character of a script written without spaces (Chinese, Japanese kana), which a line
    may break on either side of."""
    return unicodedata.category(character) == "Lo" and unicodedata.east_asian_width(
        character) in ("W", "F")


def unbroken_last_word(text: str, count: int = LAST_WORD) -> str:
    """``text`` with its last ``count`` ideographs joined (fewer where it ends in fewer); any
    joiners it held before are taken out first, so that a text extended and joined again is
    joined at its new end only."""
    text = text.replace(WORD_JOINER, "")
    end = len(text)
    start = end
    while start > 0 and end - start < count and _ideograph(text[start - 1]):
        start -= 1
    if end - start < 2:
        return text
    return text[:start] + WORD_JOINER.join(text[start:end])
