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
3. **Compared** by four keys, never chained (:func:`same_identifier`, :func:`same_serial`):
   the UTS #39 skeleton, case-sensitive as UTS #39 defines it (:func:`identifier_key`,
   :func:`serial_key`), and the text case folded with nothing else made alike
   (:func:`folded_identifier_key`, :func:`folded_serial_key`). Both: NFKC;
   default-ignorable code points dropped (the key never depends on them, whatever called
   it); every decimal digit as its ASCII digit, by its value ("٠٨١٥" is 0815; "৭", seven,
   is 7, though it looks like 9: no bundled font prints it); zeros before a number dropped
   ("01" is "0001"). The skeleton, on NFD (so that "Ӧ", Cyrillic О and a diaeresis, meets
   "Ö"; rev63 F3): the prototypes, from confusables.txt, for every character that prints
   as a Latin letter, digit or sign (Cyrillic "А", Greek "Β", Cherokee "Ꮮ", Latin small
   capitals; :mod:`models.register._identifier_tables`, generated from Unicode's data by
   app/identifier_tables.py, no package offering the skeleton being a dependency); the
   look-alikes of digits within Latin ("O" as 0; "l", "I" and "|" as 1) and "rn" as "m",
   as UTS #39 has them; "rn" only as typed, case kept, in every key before it is case
   folded and never after (rev65 F8: folded first, the capitals "RN-05" were the serial
   "M-05"). Case is not folded in the skeleton: "L" prints otherwise than "I" and "i"
   otherwise than "1" (rev63 F10: case folded before the look-alikes made
   "SN-L5" one with "SN-I5"). Case and look-alikes at once (#64 review F4) by two keys
   more (:func:`identifier_keys`, :func:`serial_keys`): the skeleton case folded
   ("ab-2026-OOO1"), and the prototypes without the digit look-alikes case folded
   ("lrа-0815", a Cyrillic "а"); a letter read as a digit is never folded, so "SN-L5" is
   neither "SN-I5" nor "SN-15". And a fifth (stop 65, :func:`_digits_in_numbers_folded`):
   the digit look-alikes read only where a run of them touches a digit, a capital that
   prints as "I" read as "I", then case folded ("lra-O815" is LRA-0815, "lrІ-0815" with a
   capital Cyrillic "І" is LRI-0815); it reads a letter as a digit only where the skeleton
   does and folds only afterwards, so of two serials in one case it joins none the skeleton
   keeps apart, and "SN-L5" stays apart from "SN-15". The dash stand-ins of CJK input methods ("一", "ー",
   "ㅡ") between letters or digits of other scripts are "-" in every key
   (:func:`_cjk_dashes`). A key only ever asks a question or refuses a number — never
   issues a second one, and never lets a change through (what prints otherwise is
   compared as printed, :func:`as_printed`; rev63 F2). What the keys keep apart but a
   reader who does not mind the case would take for one — every letter or digit read as
   the digit a case of it prints like, however many ("1ra-o815" for LRA-0815, "sn-11" for
   SN-LL; :func:`lookalike_serial_key`) — is asked about, never joined
   (:func:`serial_lookalike`; stop 67).
   - A certificate number's separators (any run of punctuation, symbols and spaces: "-",
     "·", ",", "#", "/", ".") are one separator, none at either end ("AB·2026·0001" and
     "AB-2026-0001." are AB-2026-0001; the amendment form "-A<n>" ("A<n>", "-Amendment n",
     "-Rev n" …) is read from these keys with marks dropped and any dash as "-", a separator
     or none between "A" and n, and is refused only as an amendment of a number in the
     register: :func:`reads_as_amendment_of`; rev65 F5, F6).
   - A serial number's separators are dropped altogether before its zeros
     ("RX260815" is "RX-26-0815"; "LRA#0815" is "LRA-0815").
4. **No serial**: an empty serial, one of separators only ("-", "—") and the words labs
   write for none ("n/a", "none", "unknown", "无" …; :func:`no_serial`) are no serial: the
   item is then the same item by its description and manufacturer, compared by
   :func:`identifier_key` (case, spaces and look-alikes aside). The register asks about an
   item of no serial beside a certificate of that day's item of its description and maker
   with one, and the other way round (store.SerialLeftOut; stop 67)."""

from __future__ import annotations

import bisect
import functools
import re
import unicodedata

from models.messages import QT_TR_NOOP, message
from models.register._identifier_tables import CONFUSABLES, DEFAULT_IGNORABLE

__all__ = ["IdentifierError", "amendment_form_keys", "amendment_stems", "as_printed",
           "folded_identifier_key", "folded_serial_key", "identifier_key", "identifier_keys",
           "lookalike_character_class", "lookalike_serial_key", "no_serial",
           "normalise_identifier", "printed_search_keys", "reads_as_amendment",
           "reads_as_amendment_of",
           "refuse_unprinted", "same_identifier", "same_name",
           "same_serial", "serial_key", "serial_keys", "serial_lookalike"]

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


#: what a name or description may hold that prints as no character of its own: a line
#: break or a tab prints as a space
_TEXT_SPACES = frozenset("\t\n\r")


def refuse_unprinted(text: str, what: str) -> None:
    """IdentifierError, worded as :func:`normalise_identifier`'s, naming ``what`` (the
    field: "customer", "manufacturer" …) and the first character of ``text`` that prints as
    nothing or moves the text (principle 1, line breaks and tabs aside), by its code point
    and position: a name or description prints on a certificate and is stored as typed, so
    "ACME\u200b Ltd" would print as "ACME Ltd" but be another text in the register
    (#63 regkeys). Nothing else is changed or checked: it is not an identifier."""
    text = text or ""
    for i, char in enumerate(text):
        if char not in _TEXT_SPACES and _prints_nothing(char):
            raise IdentifierError(message(QT_TR_NOOP(
                "{what} \"{shown}\": character {n} is U+{code:04X} ({name}), which prints as "
                "nothing or moves the text; type the {what} again without it"),
                what=what, shown=text.encode("ascii", "backslashreplace").decode(), n=i + 1,
                code=ord(char), name=unicodedata.name(char, "unnamed")))


#: ASCII letters and signs UTS #39 gives as digits' look-alikes (its own "0" → "O",
#: "1" → "l", "I" → "l", "|" → "l"), read as the digits: case-sensitive, as the skeleton
#: is ("L", "i" and "o" print otherwise: rev63 F10, "SN-L5" is not "SN-I5")
_DIGIT_LIKE = str.maketrans("OlI|", "0111")


def _is_separator(char: str) -> bool:
    return unicodedata.category(char)[0] in "PSZ"


#: what Chinese, Japanese and Korean input methods give for "-" (as NFKC keeps them): the
#: ideograph one "一" (and the Kangxi radical "⼀"), the prolonged sound mark "ー" (and the
#: half-width "ｰ"), the Hangul vowel "ㅡ" (NFKC: U+1173)
_DASH_STAND_INS = frozenset("\u4e00\u30fc\u1173")
_CJK_NAMES = ("CJK ", "HIRAGANA", "KATAKANA", "HANGUL", "BOPOMOFO", "IDEOGRAPHIC", "KANGXI",
              "HALFWIDTH KATAKANA", "HALFWIDTH HANGUL")


def _stands_in_a_word(char: str) -> bool:
    """Whether ``char`` is a letter or digit of a script other than Chinese, Japanese or
    Korean (a dash stand-in between two of them is a dash)."""
    return unicodedata.category(char)[0] in "LN" and char not in _DASH_STAND_INS \
        and not unicodedata.name(char, "").startswith(_CJK_NAMES)


def _cjk_dashes(text: str) -> str:
    """``text`` with every run of dash stand-ins (:data:`_DASH_STAND_INS`) that stands
    between two letters or digits of other scripts as "-" (#64 review F4: "LRA一0815" is
    LRA-0815); between or beside Chinese, Japanese or Korean characters, or at either end,
    each is the character it is ("一" is one in "第一", "ー" lengthens "センサー")."""
    if not _DASH_STAND_INS.intersection(text):
        return text
    out, i = [], 0
    while i < len(text):
        j = i
        while j < len(text) and text[j] in _DASH_STAND_INS:
            j += 1
        if j == i:
            out.append(text[i])
            i += 1
            continue
        between = i > 0 and j < len(text) and _stands_in_a_word(text[i - 1]) \
            and _stands_in_a_word(text[j])
        out.append("-" if between else text[i:j])
        i = j
    return "".join(out)


def _digits(text: str) -> str:
    """NFKC, no default-ignorable code point, decimal digits as ASCII ones, the dash
    stand-ins of CJK input methods between letters or digits of other scripts as "-"."""
    kept = []
    for char in unicodedata.normalize("NFKC", text or ""):
        if _ignorable(char):
            continue
        digit = unicodedata.decimal(char, None)
        kept.append(str(digit) if digit is not None else char)
    return _cjk_dashes("".join(kept))


def _prototypes(text: str) -> str:
    """``text`` (as :func:`_digits` gives it) in NFD with every character that prints as a
    Latin letter, digit or sign as its UTS #39 prototype: NFD, so that a composed Cyrillic
    or Greek letter meets its Latin look-alike ("Ӧ" is "О" and a diaeresis, "Ö" is "O" and
    one; rev63 F3)."""
    return "".join(CONFUSABLES.get(char, char)
                   for char in unicodedata.normalize("NFD", _digits(text)))


def _skeleton(text: str) -> str:
    """``text``'s UTS #39 skeleton, case-sensitive as UTS #39 defines it: the prototypes,
    the digit look-alikes as digits, then NFC again (separators and "rn" are left to the
    caller)."""
    return unicodedata.normalize("NFC", _prototypes(text).translate(_DIGIT_LIKE))


def _folded(text: str) -> str:
    """``text`` case folded, and nothing else made alike (no prototype, no digit
    look-alike: a chain of the two made "L" one with "I"; rev63 F10)."""
    return unicodedata.normalize("NFC", _digits(text).casefold())


def _skeleton_folded(text: str) -> str:
    """The skeleton, then case folded (#64 review F4: "ab-2026-OOO1" is AB-2026-0001, and
    "sn-IO5" is SN-105, which neither key alone joined). Folded after the digit
    look-alikes, so "I" is still "1" and "L" still "l": "SN-I5" is not "SN-L5"."""
    return unicodedata.normalize("NFC", _skeleton(text).casefold())


def _prototypes_folded(text: str) -> str:
    """The prototypes without the digit look-alikes, then case folded (#64 review F4:
    "lrа-0815", with a Cyrillic "а", is LRA-0815; the skeleton reads its lower-case "l"
    as "1", the upper-case "L" as itself, so the skeleton folded kept them apart). No
    digit look-alike: "SN-L5" (folded "sn-l5") is neither "SN-I5" ("sn-i5") nor "SN-15"."""
    return unicodedata.normalize("NFC", unicodedata.normalize("NFC", _prototypes(text))
                                 .casefold())


#: the digit look-alikes (:data:`_DIGIT_LIKE`) in a run that touches a digit
_DIGIT_LIKE_RUN = re.compile(r"(?<=[0-9])[OlI|]+|[OlI|]+(?=[0-9])")


def _capital_i(char: str, prototype: str) -> str:
    """A capital letter whose prototype is "l" is a capital I look-alike (Cyrillic "І",
    Greek "Ι", Cyrillic "Ӏ"): read as "I", which case folds to "i" as the letter's own
    lower case does (Cyrillic "і"), not to "l" (UTS #39 gives "I" itself the prototype "l",
    which this module reads only as a digit)."""
    return "I" if prototype == "l" and unicodedata.category(char) == "Lu" else prototype


def _digits_in_numbers_folded(text: str) -> str:
    """The fifth key (stop 65): the prototypes (a capital I look-alike as "I"), the digit
    look-alikes as digits only where a run of them touches a digit ("lra-O815": the "O"
    before "815" is 0, the "l" before "ra" stays a letter), then case folded. Case and a
    letter for a digit at once are one serial ("lra-O815" is LRA-0815), and a capital
    Cyrillic "І" is "I" ("lrІ-0815" is LRI-0815). Folded after the digit look-alikes and
    reading them case-sensitively, as the skeleton does, so "L" is never "l" and never "1":
    "SN-L5" is neither "SN-15" nor "SN-I5" (rev63 F10). "rn" is "m" before the folding
    (:func:`_rn_as_m`)."""
    prototypes = "".join(_capital_i(char, CONFUSABLES.get(char, char))
                         for char in unicodedata.normalize("NFD", _digits(text)))
    prototypes = unicodedata.normalize("NFC", prototypes)
    digits = _DIGIT_LIKE_RUN.sub(lambda run: run.group().translate(_DIGIT_LIKE), prototypes)
    return _fold(_rn_as_m(digits))


def _fold(text: str) -> str:
    return unicodedata.normalize("NFC", text.casefold())


def _rn_as_m(text: str) -> str:
    """"rn" as "m" (UTS #39's one look-alike of two letters), in the text as typed, case
    kept: only small "rn" prints like "m". Never applied to a case folded text, where the
    capitals "RN" (which print nothing like "M") are small letters already (rev65 F8:
    "RN-05" was the serial "M-05", "KERN-12" was "KEM-12")."""
    return text.replace("rn", "m")


def _zeros_dropped(text: str) -> str:
    """No zero before a number."""
    # not int(): it refuses more than 4,300 digits (rev63 M4)
    return re.sub(r"[0-9]+", lambda digits: digits.group().lstrip("0") or "0", text)


def _case_kept_and_folded(text: str) -> tuple[str, str, str, str, str]:
    """The five texts an identifier's keys are made of (principle 3): the skeleton, the text
    case folded, the skeleton case folded, the prototypes case folded and the fifth key's
    text; "rn" read as "m" before any folding (:func:`_rn_as_m`), never after."""
    skeleton = _rn_as_m(_skeleton(text))
    prototypes = _rn_as_m(unicodedata.normalize("NFC", _prototypes(text)))
    return (skeleton, _folded(text), _fold(skeleton), _fold(prototypes),
            _digits_in_numbers_folded(text))


def _number_key(printed: str) -> str:
    words = "".join(" " if _is_separator(char) else char for char in printed).split()
    return _zeros_dropped("-".join(words))


def _serial_key(printed: str) -> str:
    return _zeros_dropped("".join(c for c in printed if not _is_separator(c)))


@functools.lru_cache(maxsize=1 << 16)  # every record's, at each typed number
def identifier_key(text: str) -> str:
    """The identifier's skeleton key (the module's principle 3): equal keys print alike,
    case aside. :func:`same_identifier` also joins what differs only by case."""
    return _number_key(_rn_as_m(_skeleton(text)))


@functools.lru_cache(maxsize=1 << 16)
def folded_identifier_key(text: str) -> str:
    """The identifier's key case folded (no look-alikes): "ab-2026-0001" is AB-2026-0001."""
    return _number_key(_folded(text))


@functools.lru_cache(maxsize=1 << 16)
def identifier_keys(text: str) -> tuple[str, str, str, str, str]:
    """Every key an identifier is compared by (the module's principle 3), each to the same
    key of another: the skeleton, the case folded text, the skeleton case folded, the
    prototypes case folded, and the digit look-alikes read in numbers only, case folded
    (:func:`same_identifier`)."""
    skeleton, folded, skeleton_folded, prototypes, fifth = _case_kept_and_folded(text)
    return (_number_key(skeleton), _number_key(folded), _number_key(skeleton_folded),
            _number_key(prototypes), _number_key(fifth))


@functools.lru_cache(maxsize=1 << 16)
def printed_search_keys(text: str) -> frozenset[str]:
    """What a search compares by besides the text as typed: the skeleton case folded of the
    text, of its capitals and of its small letters (so "lra" finds "LRA" as "LRA-098O" finds
    LRA-0980 and "Acme" finds "Аcme" with a Cyrillic "А"); separators and zeros kept, so a
    part of a number or a name is found as a part (Register.list)."""
    return frozenset(_fold(_rn_as_m(_skeleton(t))) for t in {text, text.upper(), text.lower()}
                     if t)


def same_identifier(one: str, other: str) -> bool:
    """Whether two identifiers are one: one of their keys (:func:`identifier_keys`) is
    equal; never a chain of two keys (rev63 F10)."""
    return any(a == b for a, b in zip(identifier_keys(one), identifier_keys(other),
                                      strict=True))


@functools.lru_cache(maxsize=1 << 16)
def serial_key(text: str) -> str:
    """What makes two serial numbers one item's, case aside: the skeleton key without the
    separators a serial is typed with or without ("RX260815" is "RX-26-0815"; #61
    re-check: the same item issued again got past the one-calibration check that way).
    :func:`same_serial` also joins what differs only by case."""
    return _serial_key(_rn_as_m(_skeleton(text)))


@functools.lru_cache(maxsize=1 << 16)
def folded_serial_key(text: str) -> str:
    """The serial's key case folded (no look-alikes): "lra-0815" is LRA-0815."""
    return _serial_key(_folded(text))


@functools.lru_cache(maxsize=1 << 16)
def serial_keys(text: str) -> tuple[str, str, str, str, str]:
    """Every key a serial number is compared by, as :func:`identifier_keys` (separators
    dropped: :func:`serial_key`)."""
    skeleton, folded, skeleton_folded, prototypes, fifth = _case_kept_and_folded(text)
    return (_serial_key(skeleton), _serial_key(folded), _serial_key(skeleton_folded),
            _serial_key(prototypes), _serial_key(fifth))


def same_serial(one: str, other: str) -> bool:
    """Whether two serial numbers are one item's: one of their keys (:func:`serial_keys`)
    is equal; never a chain of two keys (rev63 F10: "SN-L5" and "SN-I5" are two items)."""
    return any(a == b for a, b in zip(serial_keys(one), serial_keys(other), strict=True))


def _one_look_alike_apart(one: str, other: str) -> bool:
    """Whether two characters of a key are one look-alike substitution apart, case aside:
    a case of one and a case of the other have one skeleton ("l" and "1": "L" folded is
    "l", whose skeleton is "1"; "0" and "o": "O" is "0"), by the skeleton's own tables."""
    return not {_skeleton(c) for c in (one, one.upper(), one.lower())}.isdisjoint(
        _skeleton(c) for c in (other, other.upper(), other.lower()))


#: capital letters that engraved, etched and stamped serials (and a technician's note of
#: one) print like a digit though UTS #39 does not list them (day review 67 F6: "RX-26-0B15"
#: beside RX-26-0815 was not asked): B and 8, S and 5, Z and 2, G and 6 — the pairs that
#: human-read codes leave out for that reason. Only ever asked about (:func:`serial_lookalike`),
#: never a key. U and V are not: two letters, not a letter and a digit, drawn apart (a round
#: and a pointed base) in every face serials are marked and printed in, and no key reads a
#: letter as another letter but small "rn" as "m".
_LETTERS_LIKE_DIGITS = {"B": "8", "S": "5", "Z": "2", "G": "6"}


@functools.lru_cache(maxsize=1 << 12)
def _lookalike_class(char: str) -> str:
    """What ``char`` (a character of :func:`_prototypes`' text, decomposed) is, case and
    look-alikes aside at once: the digit that one of its cases prints like ("l", "L", "I",
    "i", "|" are 1; "O", "o" are 0: the skeleton's own tables, :data:`_DIGIT_LIKE`; "B",
    "b" are 8, "S", "s" 5, "Z", "z" 2, "G", "g" 6: :data:`_LETTERS_LIKE_DIGITS`), else
    the character case folded. Only ever compared, to ask (:func:`serial_lookalike`)."""
    skeletons = {_skeleton(case) for case in {char, char.upper(), char.lower()}}
    digits = sorted({s for s in skeletons if len(s) == 1 and s in "0123456789"}
                    | {_LETTERS_LIKE_DIGITS[s] for s in skeletons if s in _LETTERS_LIKE_DIGITS})
    return digits[0] if digits else min(_fold(s) for s in skeletons)


def lookalike_character_class(char: str) -> str:
    """What one character of a serial as typed prints like, case and look-alikes aside
    (:func:`_lookalike_class` of its prototype): "o", "O" and "0" are "0"; only ever
    compared, to show where two serials differ (models.register.serial_differences)."""
    prototypes = unicodedata.normalize("NFD", _prototypes(char))
    return "".join(_lookalike_class(c) for c in prototypes)


@functools.lru_cache(maxsize=1 << 16)
def lookalike_serial_key(text: str) -> str:
    """The serial as it looks, case and look-alikes aside at once: the prototypes, small
    "rn" as "m" as typed (case kept, rev65 F8), each character as its look-alike class
    (:func:`_lookalike_class`: "1ra-o815", "LRA-0815", "lra-O8I5" are all "1ra815"),
    separators and zeros before a number dropped. Never a key that joins two serials (it
    would make "SN-1A" one item with "SN-LA"): equal by it and not one serial
    (:func:`same_serial`) is a look-alike the register asks about
    (:func:`serial_lookalike`; stop 67: "LRA-o815", a small "o" for the zero, and
    "1ra-o815", two substitutions and the case, issued unasked beside LRA-0815)."""
    prototypes = _rn_as_m(unicodedata.normalize("NFC", _prototypes(text)))
    classes = "".join(_lookalike_class(char)
                      for char in unicodedata.normalize("NFD", prototypes))
    return _serial_key(unicodedata.normalize("NFC", classes))


def serial_lookalike(one: str, other: str) -> bool:
    """Whether two serial numbers that are not one (:func:`same_serial`) would be if each
    letter or digit that prints like another were read as it, case aside (rev65 F7:
    "1ra-0815", a digit for a letter and a change of case at once, is LRA-0815 by none of
    the keys; stop 67: so are "LRA-o815", a small "o" for the zero, "1ra-o815" and "sn-11"
    beside SN-LL, two substitutions): their :func:`lookalike_serial_key` is one, or by one
    of their keys (:func:`serial_keys`), each to the same key of the other, they differ in
    one character only whose cases have one skeleton (a letter and the digit it prints
    like). Never joins them: folding this into a key would make "SN-1A" one with "SN-LA",
    two items; the register asks instead (store.LookalikeSerial)."""
    if same_serial(one, other):
        return False
    if lookalike_serial_key(one) == lookalike_serial_key(other):
        return True
    for mine, theirs in zip(serial_keys(one), serial_keys(other), strict=True):
        if len(mine) != len(theirs):
            continue
        differ = [(a, b) for a, b in zip(mine, theirs, strict=True) if a != b]
        if len(differ) == 1 and _one_look_alike_apart(*differ[0]):
            return True
    return False


#: letters and signs drawn as a dash that are no punctuation (so no separator by their
#: category), read as "-" where the amendment form is read (rev65 F5: "AB-2026-0001ᐨA1"):
#: modifier letters (macron, low macron, minus), Canadian syllabics' short stroke, Coptic
#: dialect-p ni, the CJK dash stand-ins (:data:`_DASH_STAND_INS`, and the Kangxi "⼀"), box
#: drawing lines, the horizontal line extension and heavy minus
_DASH_DRAWN = frozenset("\u02c9\u02cd\u02d7\u1428\u2cba\u2cbb\u30fc\uff70\u4e00\u2f00"
                        "\u1173\u3161\uffda\u2500\u2501\u23af\u2796\u2212\u06d4")
#: a Latin letter with a mark that Unicode does not decompose ("Ⱥ", "Ø"): its letter
_LATIN_WITH = re.compile(r"LATIN (CAPITAL|SMALL) LETTER ([A-Z]) WITH ")
#: what follows a number in an amendment's number, as a key gives it (separators "-", zeros
#: dropped, any case): "-A", "A", "-Amd", "-Amendment", "-Rev" …, a separator or none, "No"
#: or "Nr" or none, a count
_AMENDMENT_SUFFIX = re.compile(
    r"-?(?:a|amd|amdt|amend|amendment|rev|revision)-?(?:(?:no|nr|number)-?)?[0-9]+",
    re.IGNORECASE)


def _form_text(text: str) -> str:
    """``text`` as the amendment form is read from it (rev65 F5): every combining mark
    dropped ("Ạ", "A̲", "Â", "Ḁ" are "A"), a Latin letter with a mark Unicode does not
    decompose as its letter ("Ⱥ"), every dash (Unicode's Pd) and every letter or sign drawn
    as one (:data:`_DASH_DRAWN`, the skeleton's: what UTS #39 gives as "-") as "-"."""
    kept = []
    for char in unicodedata.normalize("NFD", _digits(text)):
        category = unicodedata.category(char)
        if category.startswith("M"):
            continue
        if category == "Pd" or char in _DASH_DRAWN or CONFUSABLES.get(char) == "-":
            kept.append("-")
            continue
        base = _LATIN_WITH.match(unicodedata.name(char, ""))
        if base:
            char = base.group(2) if base.group(1) == "CAPITAL" else base.group(2).lower()
        kept.append(char)
    return unicodedata.normalize("NFC", "".join(kept))


@functools.lru_cache(maxsize=1 << 16)
def amendment_form_keys(number: str) -> tuple[str, str, str, str, str]:
    """The keys (:func:`identifier_keys`) of ``number`` with its marks dropped and its dashes
    read as :func:`_form_text` reads them: what an amendment's stem is compared with."""
    return identifier_keys(_form_text(number))


@functools.lru_cache(maxsize=1 << 16)
def amendment_stems(number: str) -> tuple[frozenset[str], ...]:
    """For each of :func:`amendment_form_keys`, every number ``number`` reads as an
    amendment of: what precedes an amendment-like suffix (:data:`_AMENDMENT_SUFFIX`),
    and the stems of those stems ("X-A1-A2" reads as an amendment of X-A1 and of X).
    Empty sets: ``number`` has no amendment's form."""
    stems = []
    for key in amendment_form_keys(number):
        found: set[str] = set()
        todo = [key]
        while todo:
            text = todo.pop()
            for at in range(1, len(text)):
                stem = text[:at].rstrip("-")
                if stem and stem not in found and _AMENDMENT_SUFFIX.fullmatch(text, at):
                    found.add(stem)
                    todo.append(stem)
        stems.append(frozenset(found))
    return tuple(stems)


def reads_as_amendment(number: str) -> bool:
    """Whether certificate number ``number`` has an amendment's form: a number, then "-A",
    "A", "-Amd", "-Amendment", "-Rev" … and a count, by any key it is compared by, its
    separators, case, marks, look-alikes and zeros aside (:func:`amendment_stems`). The form
    alone refuses nothing (rev65 F6: "KAL-2026-A17", "2026-A-0001", "D-K-15070-A-17" are
    numbering schemes): :func:`reads_as_amendment_of` says of which number."""
    return any(amendment_stems(number))


def reads_as_amendment_of(number: str, other: str) -> bool:
    """Whether ``number`` reads to a customer as an amendment of ``other``: a stem of it
    (:func:`amendment_stems`) equals ``other`` by one of the keys the commit's check compares
    by, each to the same key, marks dropped and dashes read as :func:`_form_text` reads
    them ("AB-2026-0001A1", "AB-2026-0001-Amendment 1", "AB-2026-0001-Ạ1", "AB-2026-0001ᐨA1",
    "AB-2026-0001-Â1" of AB-2026-0001; rev65 F5). The register refuses such a number for an
    original or a replacement when ``other`` is in the register, and ``other`` when such a
    number is."""
    return any(key in stems for key, stems in zip(amendment_form_keys(other),
                                                  amendment_stems(number), strict=True))


def as_printed(text: str) -> str:
    """``text`` as a certificate prints it, for telling whether it changed: NFC, outer
    spaces trimmed (rev63 F2: a serial that prints otherwise is a corrected one, though it
    shares a key)."""
    return unicodedata.normalize("NFC", text or "").strip()


#: what labs write in the serial's field for an item that has none
_NO_SERIAL_WORDS = ("", "n/a", "na", "n.a.", "none", "no serial", "unknown", "nil", "null",
                    "keine", "无", "没有", "不详", "未知")
_NO_SERIAL = frozenset(key for word in _NO_SERIAL_WORDS for key in serial_keys(word))


def no_serial(text: str) -> bool:
    """Whether ``text``, in the serial number's field, says the item has none (principle
    4): empty, separators only ("-"), or a word for none ("n/a")."""
    return not _NO_SERIAL.isdisjoint(serial_keys(text))


def _name_keys(text: str) -> tuple[str, ...]:
    spaced = " ".join(_digits(text).split())
    return (_skeleton(spaced), _folded(spaced), _skeleton_folded(spaced),
            _prototypes_folded(spaced))


def same_name(one: str, other: str) -> bool:
    """Whether two people's names print alike: spaces collapsed, one of the keys of
    :func:`identifier_keys` equal, punctuation and zeros kept as typed (#64 review F10: an
    operator "Dr. Lі", with a Cyrillic "і", approved the calibration of approver "Dr. Li")."""
    return any(a == b for a, b in zip(_name_keys(one), _name_keys(other), strict=True))
