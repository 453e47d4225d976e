"""A manufacturer's name as people write it: one maker however its name is spelt.

The one-calibration check and an item's history compare the maker as well as the serial (a
serial is unique only within its maker). People write one maker's name in many ways (rev65
F1: "Moeller-Wedel" and "Moller-Wedel" for "Möller-Wedel", "GmbH" dropped or "& Co. KG"
added, the hyphen dropped), so two names are one maker when their maker keys are equal
(:func:`maker_key`) or they print alike, case aside (identifiers.same_identifier):

- NFKC, then the letters that print as Latin ones (Cyrillic "А" …) as those, case folded;
- ß as "ss", æ/œ as "ae"/"oe", ø as "o", ł as "l", đ as "d"; NFKD, combining marks dropped
  (ö is o); then "ae", "oe", "ue" as "a", "o", "u" (so "Moeller", "Möller" and "Moller" are one);
- the legal form at the end dropped, as often as one is there ("GmbH & Co. KG", "Ltd", "Inc",
  "S.p.A.", "B.V.", "Oy", "有限公司" …), never the whole name;
- everything that is not a letter or a digit dropped (spaces, hyphens, "&", dots).

A key only ever joins names: two makers whose keys are equal are one maker to the register
(an original of the same serial and date of calibration is then a second certificate of one
calibration); names whose keys differ are not thereby two makers — with the same serial the
register asks (store.AnotherMakersItem).
"""

from __future__ import annotations

import functools
import re
import unicodedata

from models.register._identifier_tables import CONFUSABLES

__all__ = ["maker_key", "same_maker_name"]

#: letters NFKD does not decompose into a base letter and a mark
_LETTERS = str.maketrans({"ß": "ss", "ẞ": "ss", "æ": "ae", "œ": "oe", "ø": "o", "ł": "l",
                          "đ": "d", "ð": "d", "þ": "th", "ı": "i"})
#: the umlauts written out: both ways, so "oe" and "ö" meet at "o"
_UMLAUTS_WRITTEN = re.compile("(?<=[a-z])([aou])e")
#: legal forms, as the words they are written in (dots and "&" are separators): dropped
#: from the end of a name
_LEGAL_FORMS = tuple(tuple(form.split()) for form in (
    "gmbh", "mbh", "ag", "kg", "kgaa", "ohg", "ug", "se", "co", "and co", "und co", "ltd",
    "limited", "inc", "incorporated", "llc", "llp", "lp", "plc", "corp", "corporation",
    "company", "s a", "sa", "s p a", "spa", "s r l", "srl", "s a r l", "sarl", "s a s", "sas",
    "b v", "bv", "n v", "nv", "oy", "oyj", "ab", "a s", "as", "aps", "asa", "k k", "kk",
    "pty", "pte", "e k", "ek", "e v", "ev", "sp z o o", "s r o", "sro", "a g", "gesmbh",
    "holding", "group"))
#: legal forms of Chinese and Japanese names, written without spaces: dropped from the end
#: (株式会社 from either end)
_CJK_FORMS = ("股份有限公司", "有限责任公司", "有限責任公司", "有限公司", "集团", "集團", "公司",
              "株式会社", "有限会社", "合同会社")


@functools.lru_cache(maxsize=1 << 14)
def maker_key(name: str) -> str:
    """The key a manufacturer's name is compared by ("" for a blank one): see the module."""
    text = unicodedata.normalize("NFKC", name or "").casefold()
    text = "".join(CONFUSABLES.get(char, char) for char in unicodedata.normalize("NFD", text))
    text = unicodedata.normalize("NFKD", text.casefold().translate(_LETTERS))
    text = "".join(c for c in text if not unicodedata.combining(c))
    words = [w for w in re.split(r"[^\w]+|_", text) if w]
    words = [_UMLAUTS_WRITTEN.sub(r"\1", w) if w.isascii() else w for w in words]
    while True:
        form = next((f for f in _LEGAL_FORMS if len(words) > len(f)
                     and tuple(words[-len(f):]) == f), None)
        if form is None:
            break
        del words[-len(form):]
    joined = "".join(words)
    stripped = True
    while stripped:
        stripped = False
        for suffix in _CJK_FORMS:
            if joined.endswith(suffix) and len(joined) > len(suffix):
                joined, stripped = joined[:-len(suffix)], True
            elif suffix == "株式会社" and joined.startswith(suffix) and len(joined) > len(suffix):
                joined, stripped = joined[len(suffix):], True
    return joined


def same_maker_name(one: str, other: str) -> bool:
    """Whether two named makers are one maker: equal maker keys, or printing alike, case
    aside (identifiers.same_identifier). Either blank: False (the caller decides what a
    name not given means)."""
    from models.register.identifiers import same_identifier

    if not (one or "").strip() or not (other or "").strip():
        return False
    return maker_key(one) == maker_key(other) or same_identifier(one, other)
