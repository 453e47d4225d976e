"""Where a line of certificate text may break: between words, between Chinese characters,
never inside a figure or before a closing mark; and how a table's cells are wrapped."""

from __future__ import annotations

import re


def _wrapmode(cells) -> str:
    """How a table's cells are wrapped: between words when every cell is Latin; between
    characters when one holds CJK text (fpdf2's word wrap dropped a word at a line's end
    with the fallback font, and Chinese breaks anywhere)."""
    return "CHAR" if any(_CJK.search(str(cell or "")) for cell in cells) else "WORD"


_CJK = re.compile("[\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef\uac00-\ud7af]")


def _mostly_cjk(text: str) -> bool:
    """Chinese prose (a Chinese certificate's paragraphs): more CJK characters than spaces."""
    cjk = sum(1 for ch in text if "\u3000" <= ch <= "\u9fff" or "\uff00" <= ch <= "\uffef")
    return cjk > text.count(" ")


def _long_word(text: str) -> bool:
    """A word no line can hold (a sha256 of 64 digits still fits whole on a line)."""
    return any(len(word) > 90 for word in text.split())


_CLOSING = set("。，、；：？！）》」』】”’…%\"″′°")
_OPENING = set("（《「『【“‘")
_OPERATORS = set("+−-=≤≥<>±×≈")


def _units(text: str) -> list[str]:
    """``text`` cut where a line may break: after a space, and between two characters of
    which one is Chinese — but never before a closing mark ("。", "）") or after an opening
    one, and never inside a Latin word or a figure."""
    units, current, previous = [], "", ""
    for ch, nxt in zip(text, text[1:] + " ", strict=False):  # "" (a blank line): no unit
        current += ch
        if (ch.isspace() and previous not in _OPERATORS and nxt not in _OPERATORS
                and nxt not in _CLOSING):  # "95.45 %" is kept whole too
            units.append(current)  # "T + w", "k = 2" are kept on one line
            current = ""
        elif (not ch.isspace() and not nxt.isspace() and nxt not in _CLOSING
              and ch not in _OPENING and (_CJK.match(ch) or _CJK.match(nxt))):
            units.append(current)
            current = ""
        previous = ch if not ch.isspace() else previous
    return [*units, current] if current else units
