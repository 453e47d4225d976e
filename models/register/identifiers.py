"""Identifiers that print alike are one identifier: a certificate number or a serial is
normalised (Unicode NFKC; every dash and hyphen as "-", every space as one " ") and refused
when it holds a character that prints as nothing or moves text (format, control,
private-use, unassigned, line and paragraph separators), before any uniqueness check.

Uniqueness goes further (:func:`identifier_key`): letters of other scripts that print as
Latin ones (Cyrillic "АВ" for "AB"; UTS #39's confusables, those keyboards give), case, a
full stop or comma after it, and zeros before a number ("01" for "0001") do not make another
identifier (#61 review: "АВ-2026-0001", "ab-2026-0001", "AB-2026-0001." and "AB-2026-01"
were issued beside AB-2026-0001)."""

from __future__ import annotations

import re
import unicodedata

from models.messages import QT_TR_NOOP, message

__all__ = ["IdentifierError", "identifier_key", "normalise_identifier", "serial_key"]

#: dashes, hyphens and minus signs a word processor or a keyboard layout may put in
_DASHES = re.compile("[\u2010\u2011\u2012\u2013\u2014\u2015\u2043\u2212\u2e3a\u2e3b"
                     "\ufe58\ufe63\uff0d\u058a\u05be\u1400\u1806\u2e17\u30a0]")
_REFUSED_CATEGORIES = {"Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"}


class IdentifierError(ValueError):
    """An identifier holds a character that does not print as itself."""


def normalise_identifier(text: str, what: str = "identifier") -> str:
    """``text`` as the register keeps it; IdentifierError names the first character that
    prints as nothing (by its code point) and where it is."""
    text = text or ""
    for i, char in enumerate(text):
        if unicodedata.category(char) in _REFUSED_CATEGORIES:
            raise IdentifierError(message(QT_TR_NOOP(
                "{what} \"{shown}\": character {n} is U+{code:04X} ({name}), which prints as "
                "nothing or moves the text; type the {what} again without it"),
                what=what, shown=text.encode("ascii", "backslashreplace").decode(), n=i + 1,
                code=ord(char), name=unicodedata.name(char, "unnamed")))
    text = unicodedata.normalize("NFKC", text)
    text = _DASHES.sub("-", text)
    return " ".join(text.split())


#: Cyrillic and Greek letters that print as Latin ones (Unicode's confusables.txt, UTS #39)
_LOOKALIKES = str.maketrans(
    "АВЕЅІЈКМНОРСТХУаеѕіјорсхуԁһԛԝ" "ΑΒΕΖΗΙΚΜΝΟΡΤΥΧοϲνρ",
    "ABESIJKMHOPCTXYaesijopcxydhqw" "ABEZHIKMNOPTYXocvp")
_TRAILING = ".,;:。，、"
_DIGITS = re.compile(r"\d+")


def identifier_key(text: str) -> str:
    """What makes two identifiers (as :func:`normalise_identifier` keeps them) one: equal
    keys print alike."""
    key = (text or "").translate(_LOOKALIKES).casefold().rstrip(_TRAILING).rstrip()
    return _DIGITS.sub(lambda digits: str(int(digits.group())), key)


_SEPARATORS = re.compile(r"[\s\-_/.:]+")


def serial_key(text: str) -> str:
    """What makes two serial numbers one item's: :func:`identifier_key` without the
    separators a serial is typed with or without ("RX260815" is "RX-26-0815"; #61
    re-check: the same item issued again got past the one-calibration check that way)."""
    return _SEPARATORS.sub("", identifier_key(text))
