"""Which characters of two serial numbers that look alike differ, marked for the question.

The register asks about a serial that is no item's but looks like one that is
(identifiers.serial_lookalike; store.LookalikeSerial). The question is only worth asking if
the technician can see *where* the two differ: in a dialog's font "o" and "0" are barely
told apart, so the two serials are shown with the differing characters in brackets, and
each pair is named in words ("RX-26-[o]815 vs RX-26-[0]815: the small letter o and the
digit 0 print alike"; day review 67 F6).

Characters are compared case aside (a serial is one serial in either case: identifiers'
folded keys), separators aside (a serial's separators are dropped before it is compared),
each as typed (NFC): what differs in print, even where a key reads it as one (a capital
"O" for a zero), is marked. The alignment is difflib's on the remaining characters."""

from __future__ import annotations

import dataclasses
import difflib
import unicodedata
from collections.abc import Sequence
from typing import Any

from models.messages import QT_TR_NOOP, Message, listed, message

__all__ = ["SerialDifference", "character_words", "differences_named", "differences_sentence",
           "serial_difference"]

#: the marks put around a run of differing characters
OPEN, CLOSE = "[", "]"


@dataclasses.dataclass(frozen=True)
class SerialDifference:
    """Two serials with their differing characters marked, and the differing runs:
    ``pairs`` (the run of ``one``, the run of ``other``), each once, in order; a run is
    "" where the other serial has characters that this one has not."""

    one_marked: str
    other_marked: str
    pairs: tuple[tuple[str, str], ...]


def _compared(text: str) -> tuple[list[int], list[str]]:
    """The positions of ``text``'s characters that are compared (no separator: punctuation,
    symbol or space) and each one case folded."""
    at = [i for i, char in enumerate(text) if unicodedata.category(char)[0] not in "PSZ"]
    return at, [unicodedata.normalize("NFC", text[i].casefold()) for i in at]


def _marked(text: str, marked: set[int]) -> str:
    """``text`` with each run of positions in ``marked`` in brackets."""
    out = []
    for i, char in enumerate(text):
        if i in marked and i - 1 not in marked:
            out.append(OPEN)
        out.append(char)
        if i in marked and i + 1 not in marked:
            out.append(CLOSE)
    return "".join(out)


def _differing_runs(one: str, at_one: list[int], keys_one: list[str], other: str,
                    at_other: list[int], keys_other: list[str]
                    ) -> list[tuple[int, int, int, int]]:
    """The runs (i1, i2, j1, j2) of compared characters where the two differ: character by
    character when both have as many (a look-alike is a substitution); else aligned by
    what each character prints like (identifiers' look-alike classes, so that a digit is
    not matched with the same digit elsewhere: "12/W I" against "lZ/W 1"), each aligned
    block then compared character by character, what is left over a run ("rn" for "m")."""
    from models.register.identifiers import lookalike_character_class

    if len(keys_one) == len(keys_other):
        blocks = [(0, 0, len(keys_one))]
        runs: list[tuple[int, int, int, int]] = []
    else:
        classes_one = [lookalike_character_class(one[i]) for i in at_one]
        classes_other = [lookalike_character_class(other[j]) for j in at_other]
        matcher = difflib.SequenceMatcher(None, classes_one, classes_other, autojunk=False)
        blocks = [(a, b, size) for a, b, size in matcher.get_matching_blocks() if size]
        runs = [(i1, i2, j1, j2) for tag, i1, i2, j1, j2 in matcher.get_opcodes()
                if tag != "equal"]
    for a, b, size in blocks:
        for k in range(size):
            if keys_one[a + k] != keys_other[b + k]:
                runs.append((a + k, a + k + 1, b + k, b + k + 1))
    return sorted(runs)


def serial_difference(one: str, other: str) -> SerialDifference:
    """``one`` and ``other`` (NFC) with the characters where they differ, case and
    separators aside, marked; a run of one length on both sides is paired character by
    character ("11" for "LL" is the pair 1 and L once), one of another length as a whole
    ("rn" for "m")."""
    one, other = unicodedata.normalize("NFC", one), unicodedata.normalize("NFC", other)
    at_one, keys_one = _compared(one)
    at_other, keys_other = _compared(other)
    marked_one: set[int] = set()
    marked_other: set[int] = set()
    pairs: list[tuple[str, str]] = []
    for i1, i2, j1, j2 in _differing_runs(one, at_one, keys_one, other, at_other, keys_other):
        marked_one.update(at_one[i1:i2])
        marked_other.update(at_other[j1:j2])
        mine = [one[i] for i in at_one[i1:i2]]
        theirs = [other[j] for j in at_other[j1:j2]]
        found = list(zip(mine, theirs, strict=True)) if len(mine) == len(theirs) \
            else [("".join(mine), "".join(theirs))]
        for pair in found:
            if pair not in pairs:
                pairs.append(pair)
    return SerialDifference(_marked(one, marked_one), _marked(other, marked_other),
                            tuple(pairs))


def character_words(text: str) -> Message | str:
    """A character (or a run of them) in words, so that it is told from its look-alike
    whatever the font: "the digit 0", "the capital letter O", "the small letter o"; another
    script's letter by its Unicode name and code point ("а (CYRILLIC SMALL LETTER A,
    U+0430)"); a run as it is, in quotes."""
    if len(text) != 1:
        return message(QT_TR_NOOP("\u201c{text}\u201d"), text=text)
    if text in "0123456789":
        return message(QT_TR_NOOP("the digit {char}"), char=text)
    if "A" <= text <= "Z":
        return message(QT_TR_NOOP("the capital letter {char}"), char=text)
    if "a" <= text <= "z":
        return message(QT_TR_NOOP("the small letter {char}"), char=text)
    if text == "|":
        return message(QT_TR_NOOP("the vertical bar {char}"), char=text)
    return message(QT_TR_NOOP("{char} ({name}, U+{code:04X})"), char=text,
                   name=unicodedata.name(text, "unnamed"), code=ord(text))


def _pair_words(one: str, other: str, seen: set[tuple[str, str]] | None = None
                ) -> tuple[list[Message], list[Message]]:
    """The differing runs of ``one`` and ``other`` in words: the pairs that print alike
    ("the small letter o and the digit 0"), and the runs only one of them has; with ``seen``
    (the runs already named, updated here), each run named once over several ``other``."""
    alike: list[Message] = []
    alone: list[Message] = []
    for mine, theirs in serial_difference(one, other).pairs:
        if seen is not None:
            key = (mine, theirs) if mine and theirs else (mine, theirs + "\0" + other)
            if key in seen:
                continue
            seen.add(key)
        if mine and theirs:
            alike.append(message(QT_TR_NOOP("{one} and {other}"), one=character_words(mine),
                                 other=character_words(theirs)))
        else:
            alone.append(message(QT_TR_NOOP("{chars} only in {serial}"),
                                 chars=character_words(mine or theirs),
                                 serial=one if mine else other))
    return alike, alone


def _said(alike: list[Message], alone: list[Message]) -> Any:
    """The pairs that print alike in one clause, then the runs only one serial has."""
    said = [message(QT_TR_NOOP("{pairs} print alike, case aside"), pairs=listed(alike))] \
        if alike else []
    return listed([*said, *alone])


def differences_named(one: str, others: Sequence[str]) -> Any:
    """What differs between ``one`` and each of ``others`` in words, each pair once, for a
    list of look-alike serials marked in brackets (day review 68 F11: with three look-alikes
    the question compared the serial with each in turn, "the small letter o and the digit 0"
    three times, a paragraph of 16 lines): "the small letter o and the digit 0, the digit 6
    and the capital letter G print alike, case aside"; a run only one serial has is named as
    such; "" where nothing differs."""
    alike: list[Message] = []
    alone: list[Message] = []
    seen: set[tuple[str, str]] = set()
    for other in others:
        more_alike, more_alone = _pair_words(one, other, seen)
        alike += more_alike
        alone += more_alone
    return _said(alike, alone)


def differences_sentence(one: str, other: str) -> Message:
    """The two serials, marked, and what differs in words: "RX-26-[o]815 vs RX-26-[0]815:
    the small letter o and the digit 0 print alike, case aside"; a run only ``one`` or only
    ``other`` has is named as such."""
    found = serial_difference(one, other)
    return message(QT_TR_NOOP("{one} vs {other}: {differences}"), one=found.one_marked,
                   other=found.other_marked, differences=_said(*_pair_words(one, other)))
