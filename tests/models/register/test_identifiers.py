"""#40: identifiers that print alike are one identifier (hypothesis): normalising is
idempotent, unifies every dash and space, keeps what prints as itself, and refuses a
character that prints as nothing wherever it stands."""

from __future__ import annotations

import unicodedata

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.register.identifiers import IdentifierError, normalise_identifier

DASHES = "\u2010\u2011\u2012\u2013\u2014\u2015\u2212\ufe58\ufe63\uff0d"
SPACES = "\u00a0\u2002\u2003\u2009\u202f\u3000 "
INVISIBLE = "\u200b\u200c\u200d\u2060\ufeff\u00ad\u202e\u2066\u061c\x00\x1f\u2028"
PLAIN = st.text(alphabet="ABCDEFGHJKLMNPQRSTUVWXYZ0123456789/._", min_size=1, max_size=12)


@settings(max_examples=200, deadline=None)
@given(st.lists(PLAIN, min_size=1, max_size=4), st.data())
def test_dashes_and_spaces_print_alike_and_normalise_alike(parts, data):
    plain = "-".join(parts)
    dashed = "".join(p + (data.draw(st.sampled_from(DASHES)) if i < len(parts) - 1 else "")
                     for i, p in enumerate(parts))
    padded = data.draw(st.sampled_from(SPACES)) + dashed + data.draw(st.sampled_from(SPACES))
    assert normalise_identifier(padded) == normalise_identifier(plain) == plain


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=30))
def test_normalising_is_idempotent_and_leaves_nothing_invisible(text):
    try:
        once = normalise_identifier(text)
    except IdentifierError:
        return
    assert normalise_identifier(once) == once
    assert once == once.strip() and "  " not in once
    assert not any(unicodedata.category(c) in {"Cc", "Cf", "Co", "Cn", "Zl", "Zp"}
                   for c in once)
    assert not any(c in DASHES for c in once)


@settings(max_examples=200, deadline=None)
@given(PLAIN, st.sampled_from(INVISIBLE), st.integers(0, 12))
def test_an_invisible_character_anywhere_is_refused_by_its_code_point(plain, char, at):
    at = min(at, len(plain))
    with pytest.raises(IdentifierError, match=f"U\\+{ord(char):04X}"):
        normalise_identifier(plain[:at] + char + plain[at:])


def test_full_width_and_compatibility_forms_are_their_plain_letters():
    assert normalise_identifier("ＡＢ－２０２６－０００１") == "AB-2026-0001"
    assert normalise_identifier("AB‐2026‐0001") == "AB-2026-0001"  # U+2010, as Word pastes
    assert normalise_identifier("RX\u00a0 26") == "RX 26"


# -- #62 review: what prints as nothing or as a Latin letter, digit or separator -------------
from models.register._identifier_tables import CONFUSABLES, DEFAULT_IGNORABLE  # noqa: E402
from models.register.identifiers import (  # noqa: E402
    folded_identifier_key,
    folded_serial_key,
    identifier_key,
    no_serial,
    same_identifier,
    same_serial,
    serial_key,
    serial_keys,
)

#: every assigned default-ignorable code point (Python's own Unicode data), the blanks
IGNORABLE = [chr(c) for first, last in DEFAULT_IGNORABLE for c in range(first, last + 1)
             if unicodedata.category(chr(c)) != "Cn"]
BLANKS = ["\u2800", "\U0001d159", "\U00016fe4"]
#: each ASCII letter or digit's look-alikes of other scripts (UTS #39, as generated)
ALIKE: dict[str, list[str]] = {}
for _source, _prototype in CONFUSABLES.items():
    # a digit of another script is its value ("৭", seven, looks like 9 but is 7)
    if len(_prototype) == 1 and _prototype.isalnum() \
            and unicodedata.decimal(_source, None) is None:
        ALIKE.setdefault(_prototype, []).append(_source)
ALIKE["0"] = ["O", *ALIKE.get("O", [])]
ALIKE["1"] = ["l", "I", "|", *ALIKE.get("l", []), *ALIKE.get("I", [])]
SEPARATORS = "-‐–—·,.#/_:; \u00a0\u30fb\uff0c"
SERIAL = st.text(alphabet="ABCDEFGHJKLNPQRSTUVWXYZ0123456789-", min_size=1, max_size=14)


def test_the_tables_are_unicodes():
    """The default-ignorable code points are the property's, not a hand list (Python's own
    data agrees on every format character it knows), and the look-alikes are UTS #39's."""
    assert len(IGNORABLE) > 300 and "\u034f" in IGNORABLE and "\ufe0f" in IGNORABLE
    assert {"\u3164", "\u1160", "\uffa0", "\u00ad", "\u200b", "\u202e"} <= set(IGNORABLE)
    for code in range(0x110000):
        char = chr(code)
        if unicodedata.category(char) == "Cf" and char not in IGNORABLE:
            assert code in (0x0600, 0x0601, 0x0602, 0x0603, 0x0604, 0x0605, 0x06DD, 0x070F,
                            0x0890, 0x0891, 0x08E2, 0x110BD, 0x110CD, 0xFFF9, 0xFFFA,
                            0xFFFB) or 0x13430 <= code <= 0x1343F, hex(code)
    assert CONFUSABLES["\u13de"] == "L" and CONFUSABLES["\u0410"] == "A"  # Cherokee, Cyrillic
    assert CONFUSABLES["\u1d00"] == "A"  # small capital (by its name)


@settings(max_examples=300, deadline=None)
@given(SERIAL, st.data())
def test_look_alikes_case_and_invisible_characters_give_the_same_keys(plain, data):
    """Any identifier and its variants that print alike (each letter or digit swapped for a
    look-alike, default-ignorable code points anywhere) have one key; its variants in the
    other case have one folded key. Both are one identifier (same_identifier)."""
    alike, cased = [], []
    for char in plain:
        alike.append(data.draw(st.sampled_from([char, *ALIKE.get(char, [])])))
        cased.append(data.draw(st.sampled_from([char, char.lower()])))
        if data.draw(st.booleans()):
            alike.append(data.draw(st.sampled_from(IGNORABLE)))
            cased.append(data.draw(st.sampled_from(IGNORABLE)))
    alike_text, cased_text = "".join(alike), "".join(cased)
    assert identifier_key(alike_text) == identifier_key(plain), ascii(alike_text)
    assert serial_key(alike_text) == serial_key(plain), ascii(alike_text)
    assert folded_identifier_key(cased_text) == folded_identifier_key(plain), ascii(cased_text)
    assert folded_serial_key(cased_text) == folded_serial_key(plain), ascii(cased_text)
    for text in (alike_text, cased_text):
        assert same_identifier(text, plain) and same_serial(text, plain), ascii(text)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.text(alphabet="ABCDEFGHJKNPRSTUVWXYZ23456789", min_size=1, max_size=5),
                min_size=1, max_size=4), st.data())
def test_separators_are_one_in_numbers_and_none_in_serials(parts, data):
    """"AB·2026·0001", "AB-2026-0001." and "AB#2026#0001" are AB-2026-0001; a serial is
    the same typed with or without its separators, and with zeros before its numbers."""
    dashed = "-".join(parts)
    other = "".join(p + (data.draw(st.sampled_from(SEPARATORS)) if i < len(parts) - 1 else "")
                    for i, p in enumerate(parts))
    other += data.draw(st.sampled_from(["", ".", ",", " #"]))
    assert identifier_key(other) == identifier_key(dashed)
    assert serial_key(other) == serial_key("".join(parts)) == serial_key(dashed)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="ABCDEFGHJKNPQRSTUVWXYZ", min_size=1, max_size=4),
       st.integers(1, 10**6), st.text(alphabet="ABCDEFGHJKNPQRSTUVWXYZ", min_size=1, max_size=4),
       st.integers(1, 10**6))
def test_distinct_serials_stay_distinct(letters, number, other_letters, other_number):
    """Real serials that differ in a letter or a digit have different keys (M aside, which
    UTS #39 gives as "rn"; I, L and O, which print as digits)."""
    one, two = f"{letters}-{number:05d}", f"{other_letters}-{other_number:05d}"
    if (letters, number) != (other_letters, other_number):
        assert serial_key(one) != serial_key(two)
        assert identifier_key(one) != identifier_key(two)


@pytest.mark.parametrize("char", sorted({*(chr(first) for first, _ in DEFAULT_IGNORABLE),
                                          "\u034f", "\ufe0f", "\u3164", "\u1160", "\uffa0",
                                          "\U000e0100", "\u200b", "\u202e", *BLANKS}))
def test_every_default_ignorable_and_blank_is_refused_naming_it(char):
    with pytest.raises(IdentifierError, match=f"character 9 is U\\+{ord(char):04X} "):
        normalise_identifier("LRA-0815" + char + "7")


def test_a_combining_mark_with_nothing_to_mark_is_refused():
    with pytest.raises(IdentifierError, match="character 1 is U\\+0301"):
        normalise_identifier("\u0301LRA-0815")
    with pytest.raises(IdentifierError, match="character 5 is U\\+20DD.*no letter before it"):
        normalise_identifier("LRA \u20dd0815")
    assert normalise_identifier("Me\u0301tre") == "Métre"  # a mark on its letter is kept
    with pytest.raises(IdentifierError, match="character 3 is U\\+00B4"):
        normalise_identifier("RX\u00b41")  # NFKC: a space and a combining acute


@pytest.mark.parametrize(("typed", "alike"), [
    ("LRA-0815", "\u13de\u13a1\u13aa-0815"), ("LRA-0815", "LRA-O815"),
    ("LRA-0815", "LRA·0815"), ("LRA-0815", "LRA,0815"), ("LRA-0815", "LRA#0815"),
    ("LRA-0815", "\u029f\u0280\u1d00-0815"), ("LRA-0815", "𝐋𝐑𝐀-0815"),
    ("LRA-0815", "LRA-\u0660\u0668\u0661\u0665"), ("RX-26-0815", "RX260815"),
    ("SN 1I0l", "SN-1101"), ("LRA-0815", "lra-0815")])
def test_serials_the_review_issued_twice_have_one_key(typed, alike):
    assert same_serial(alike, typed)


@pytest.mark.parametrize("alike", ["\u13aa\u13f4-2026-0001", "AB-2026-OOO1", "AB·2026·0001",
                                   "A\u0299-2026-0001", "AB-2026-0001.", "AB#2026#0001",
                                   "AB-2026-01", "ab-2026-0001"])
def test_numbers_the_review_issued_twice_have_one_key(alike):
    assert same_identifier(alike, "AB-2026-0001")
    assert "AB-2026-1" in (identifier_key(alike), folded_identifier_key(alike).upper())


def test_the_amendment_form_is_read_from_the_key():
    for typed in ("AB-2026-0001-A1.", "AB-2026-0001-\u04101", "AB-2026-0001·A1",
                  "AB-2026-0001-Al", "AB-2026-0001 a1"):
        assert any(key(typed).upper().endswith("-A1")
                   for key in (identifier_key, folded_identifier_key)), typed


@pytest.mark.parametrize(("serial", "none"), [
    ("", True), ("-", True), ("—", True), ("n/a", True), ("N/A", True), ("n.a.", True),
    ("none", True), ("无", True), ("unknown", True), ("NA-1", False), ("0", False),
    ("RX-1", False)])
def test_what_says_there_is_no_serial(serial, none):
    assert no_serial(serial) is none


# -- stop 65: case and a letter for a digit at once; a capital Cyrillic "І" ------------------
@pytest.mark.parametrize(("typed", "alike"), [
    ("LRA-0815", "lra-O815"), ("LRA-0815", "Lra-O815"),
    ("LRA-0815", "lr\u0430-O815"),  # a Cyrillic "а" as well
    ("LRI-0815", "LR\u0406-0815"), ("LRI-0815", "lr\u0406-0815"),  # capital Cyrillic "І"
    ("lri-0815", "LR\u0406-O815"), ("AB-2026-0001", "ab-2026-OOO1"),
    ("SN-105", "sn-I05")])
def test_case_and_a_letter_for_a_digit_at_once_are_one_serial(typed, alike):
    """Each was another serial before (stop 63's note: "lra-O815", case, a Cyrillic letter
    and a letter for a digit at once; a capital Cyrillic "І" for the "i" of "lri")."""
    assert same_serial(alike, typed) and same_identifier(alike, typed)


@pytest.mark.parametrize(("one", "other"), [
    ("SN-L5", "SN-15"), ("SN-L5", "SN-I5"), ("sn-L5", "SN-15"), ("SN-L5", "sn-15"),
    ("LRA-0815", "LRA-L815"), ("AL-15", "A1-15"), ("Ai55", "A155"), ("SN-Ч5", "SN-45")])
def test_a_letter_that_prints_otherwise_than_a_digit_stays_a_letter(one, other):
    """rev63 F10: the naive join (case folded, then the digit look-alikes) made "SN-L5" one
    with "SN-15"; the fifth key reads the look-alikes before folding and only in numbers."""
    assert not same_serial(one, other) and not same_identifier(one, other)


def test_the_fifth_key_joins_no_serials_in_one_case_the_skeleton_keeps_apart():
    """Every 4-character serial of capitals (or of small letters), the letters that print
    like digits and digits:
    two that the fifth key joins, the skeleton joins too (what it adds is only case and a
    letter for a digit at once)."""
    import itertools

    from models.register.identifiers import serial_keys

    for alphabet in ("LIOA01", "lioa01"):  # capitals and digits; small letters and digits
        by_key: dict[str, set[str]] = {}
        for chars in itertools.product(alphabet, repeat=4):
            serial = "".join(chars)
            by_key.setdefault(serial_keys(serial)[4], set()).add(serial)
        for serials in by_key.values():
            assert len({serial_key(s) for s in serials}) == 1, serials


@pytest.mark.parametrize(("one", "other"), [("RN-05", "M-05"), ("KERN-12", "KEM-12"),
                                            ("TURN-5", "TUM-5"), ("Rn-05", "m-05")])
def test_capital_rn_is_not_m(one, other):
    """rev65 F8: "rn" read as "m" after case folding made the capitals "RN-05" the serial
    "M-05" (histories merged, one item's interval replaced the other's)."""
    assert not same_serial(one, other) and not same_identifier(one, other)
    assert not set(serial_keys(one)) & set(serial_keys(other))


@pytest.mark.parametrize(("one", "other"), [("rn-05", "m-05"), ("kern-12", "kem-12"),
                                            ("kern-12", "KEM-12"), ("TURN-5", "TURN-5")])
def test_small_rn_typed_is_still_m(one, other):
    assert same_serial(one, other) and same_identifier(one, other)
