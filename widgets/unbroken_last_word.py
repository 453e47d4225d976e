"""The end of a wrapped Chinese text kept from standing alone on its last line: Qt may break a
line between any two ideographs, and a caption ending "…少于 5 次测量：已标注" wrapped with
"标注" (flagged) alone on its third line, the "已" (already) of its word left above it (day 74
finding 13). Its last characters written without spaces (ideographs, full-width punctuation)
are joined by word joiners (U+2060, drawn as nothing, no line break on either side), six at
most, so that the last line holds them whole ("测量：已标注": with three, "测量" was broken
instead); the characters themselves are unchanged, and six take about 80 pixels, the
narrowest the caption is given, so a narrow label still wraps. A text that does not end in
such characters (English) is as it is: it breaks at its spaces."""

from __future__ import annotations

import unicodedata

from widgets.unbroken_identifiers import WORD_JOINER

__all__ = ["LAST_WORD", "unbroken_last_word"]

#: how many characters at a text's end are kept on one line: a Chinese word is mostly two
#: characters, a clause after its colon a few more ("测量：已标注")
LAST_WORD = 6


def _written_without_spaces(character: str) -> bool:
    """A wide character of a script written without spaces (Chinese ideographs, Japanese
    kana, full-width punctuation), which a line may break beside."""
    return unicodedata.east_asian_width(character) in ("W", "F") and unicodedata.category(
        character)[0] in "LP"


def unbroken_last_word(text: str, count: int = LAST_WORD) -> str:
    """``text`` with its last ``count`` wide characters joined (fewer where it ends in fewer);
    any
    joiners it held before are taken out first, so that a text extended and joined again is
    joined at its new end only."""
    text = text.replace(WORD_JOINER, "")
    end = len(text)
    start = end
    while start > 0 and end - start < count and _written_without_spaces(text[start - 1]):
        start -= 1
    if end - start < 2:
        return text
    return text[:start] + WORD_JOINER.join(text[start:end])
