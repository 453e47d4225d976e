"""Identifiers that print alike are one identifier, and an identifier prints what is stored.

The principle, for a certificate number and an item's serial number (ISO/IEC 17025 7.8.2.1:
a certificate is uniquely identified; #61 and #62 reviews):

1. **Refused** (:func:`normalise_identifier`), naming the character, its code point and its
   position, before anything is checked or stored: every character that prints as nothing,
   moves the text or draws a blank, so that a certificate never prints something other
   than what the register holds: the general categories control, format, surrogate,
   private use, unassigned and line/paragraph separator; every Default_Ignorable_Code_Point
   (the Unicode property, from DerivedCoreProperties.txt: the combining grapheme joiner,
   variation selectors, Hangul fillers, soft hyphen, zero-width and bidi marks …); the
   glyphs that draw a blank (U+2800 BRAILLE PATTERN BLANK, U+1D159 MUSICAL SYMBOL NULL
   NOTEHEAD, U+16FE4 KHITAN SMALL SCRIPT FILLER); and a combining mark with no character
   before it to mark (first, or after a space).
2. **Kept** as typed otherwise, normalised: Unicode NFKC, every dash and hyphen as "-", every
   space as one " ".
3. **Compared** by a key (:func:`identifier_key`, :func:`serial_key`) in which what prints
   alike is one: NFKC; default-ignorable code points dropped (the key never depends on
   them, whatever called it); every decimal digit as its ASCII digit, by its value
   ("٠٨١٥" is 0815; "৭", seven, is 7, though it looks like 9: no bundled font prints it); the
   UTS #39 skeleton's prototypes, from confusables.txt, for every character that prints as
   a Latin letter, digit or sign (Cyrillic "А", Greek "Β", Cherokee "Ꮮ", Latin small
   capitals; :mod:`models.register._identifier_tables`, generated from Unicode's data by
   app/identifier_tables.py, no package offering the skeleton being a dependency);
   case folded; the look-alikes of digits within Latin ("O"/"o" as 0; "l", "I", "i" and
   "|" as 1) and "rn" as "m", as UTS #39 has them; zeros before a number dropped ("01" is
   "0001"). Because case is folded too, the key joins what prints alike in either case:
   "L" and "1" have one key (l ≡ 1 in print, L ≡ l by case), which only ever asks a
   question or refuses a number — never issues a second one.
   - A certificate number's separators (any run of punctuation, symbols and spaces: "-",
     "·", ",", "#", "/", ".") are one separator, none at either end ("AB·2026·0001" and
     "AB-2026-0001." are AB-2026-0001; the amendment form "-A<n>" is read from this key).
   - A serial number's separators are dropped altogether before its zeros
     ("RX260815" is "RX-26-0815"; "LRA#0815" is "LRA-0815").
4. **No serial**: an empty serial, one of separators only ("-", "—") and the words labs
   write for none ("n/a", "none", "unknown", "无" …; :func:`no_serial`) are no serial: the
   item is then the same item by its description and manufacturer, compared by
   :func:`identifier_key` (case, spaces and look-alikes aside)."""

from __future__ import annotations

import bisect
import functools
import re
import unicodedata

from models.messages import QT_TR_NOOP, message
from models.register._identifier_tables import CONFUSABLES, DEFAULT_IGNORABLE

__all__ = ["IdentifierError", "identifier_key", "no_serial", "normalise_identifier",
           "serial_key"]

#: dashes, hyphens and minus signs a word processor or a keyboard layout may put in
_DASHES = re.compile("[\u2010\u2011\u2012\u2013\u2014\u2015\u2043\u2212\u2e3a\u2e3b"
                     "\ufe58\ufe63\uff0d\u058a\u05be\u1400\u1806\u2e17\u30a0]")
_REFUSED_CATEGORIES = {"Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"}
#: glyphs that draw a blank and are not default-ignorable
_BLANK = {"\u2800", "\U0001d159", "\U00016fe4"}
_IGNORABLE_FIRST = [first for first, _last in DEFAULT_IGNORABLE]


class IdentifierError(ValueError):
    """An identifier holds a character that does not print as itself."""


def _ignorable(char: str) -> bool:
    """Whether ``char`` is a Default_Ignorable_Code_Point."""
    code = ord(char)
    at = bisect.bisect_right(_IGNORABLE_FIRST, code) - 1
    return at >= 0 and code <= DEFAULT_IGNORABLE[at][1]


def _prints_nothing(char: str) -> bool:
    return unicodedata.category(char) in _REFUSED_CATEGORIES or _ignorable(char) \
        or char in _BLANK


def _marks_nothing(text: str, i: int) -> bool:
    """Whether ``text[i]`` is (or NFKC makes it) a combining mark with no character before
    it to mark: first, after a space, or after the space NFKC gives it ("´" is " ́")."""
    kept = unicodedata.normalize("NFKC", text[i])
    return any(unicodedata.category(char).startswith("M")
               and (kept[j - 1].isspace() if j else i == 0 or text[i - 1].isspace())
               for j, char in enumerate(kept))


def normalise_identifier(text: str, what: str = "identifier") -> str:
    """``text`` as the register keeps it; IdentifierError names the first character that
    prints as nothing or marks nothing (by its code point) and where it is."""
    text = text or ""
    for i, char in enumerate(text):
        shown = text.encode("ascii", "backslashreplace").decode()
        if _prints_nothing(char):
            raise IdentifierError(message(QT_TR_NOOP(
                "{what} \"{shown}\": character {n} is U+{code:04X} ({name}), which prints as "
                "nothing or moves the text; type the {what} again without it"),
                what=what, shown=shown, n=i + 1, code=ord(char),
                name=unicodedata.name(char, "unnamed")))
        if _marks_nothing(text, i):
            raise IdentifierError(message(QT_TR_NOOP(
                "{what} \"{shown}\": character {n} is U+{code:04X} ({name}), an accent or mark "
                "with no letter before it to mark; type the {what} again without it"),
                what=what, shown=shown, n=i + 1, code=ord(char),
                name=unicodedata.name(char, "unnamed")))
    text = unicodedata.normalize("NFKC", text)
    text = _DASHES.sub("-", text)
    return " ".join(text.split())


#: Latin letters and signs UTS #39 gives as digits' look-alikes (its own "0" → "O",
#: "1" → "l", "I" → "l", "|" → "l"), read as the digits, case folded
_DIGIT_LIKE = str.maketrans("oli|", "0111")


def _is_separator(char: str) -> bool:
    return unicodedata.category(char)[0] in "PSZ"


def _printed(text: str) -> str:
    """``text`` as it prints: NFKC, no default-ignorable code point, decimal digits as
    ASCII ones, UTS #39 prototypes, case folded, digit look-alikes as digits (separators
    are left to the caller, and so is "rn", which its separators may part)."""
    kept = []
    for char in unicodedata.normalize("NFKC", text or ""):
        if _ignorable(char):
            continue
        digit = unicodedata.decimal(char, None)
        kept.append(str(digit) if digit is not None else char)
    folded = "".join(kept)
    for _ in range(2):  # a prototype's case folded may have a prototype of its own
        folded = "".join(CONFUSABLES.get(char, char) for char in folded).casefold()
    return folded.translate(_DIGIT_LIKE)


def _zeros_dropped(text: str) -> str:
    """"rn" as "m" (UTS #39), and no zero before a number."""
    return re.sub(r"[0-9]+", lambda digits: str(int(digits.group())), text.replace("rn", "m"))


@functools.lru_cache(maxsize=1 << 16)  # every record's, at each typed number
def identifier_key(text: str) -> str:
    """What makes two identifiers one: equal keys print alike (the module's principle 3)."""
    words = "".join(" " if _is_separator(char) else char for char in _printed(text)).split()
    return _zeros_dropped("-".join(words))


@functools.lru_cache(maxsize=1 << 16)
def serial_key(text: str) -> str:
    """What makes two serial numbers one item's: :func:`identifier_key` without the
    separators a serial is typed with or without ("RX260815" is "RX-26-0815"; #61
    re-check: the same item issued again got past the one-calibration check that way)."""
    return _zeros_dropped("".join(c for c in _printed(text) if not _is_separator(c)))


#: what labs write in the serial's field for an item that has none
_NO_SERIAL_WORDS = ("", "n/a", "na", "n.a.", "none", "no serial", "unknown", "nil", "null",
                    "keine", "无", "没有", "不详", "未知")
_NO_SERIAL = frozenset(serial_key(word) for word in _NO_SERIAL_WORDS)


def no_serial(text: str) -> bool:
    """Whether ``text``, in the serial number's field, says the item has none (principle
    4): empty, separators only ("-"), or a word for none ("n/a")."""
    return serial_key(text) in _NO_SERIAL
