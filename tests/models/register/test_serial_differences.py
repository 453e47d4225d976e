"""Day review 67 F6: the look-alike question says WHICH characters differ: the two serials
with the differing characters in brackets, each pair named in words ("the small letter o
and the digit 0"), since in a dialog's font "o" and "0" are barely told apart; a serial
with several certificates is named once.

The generator: a serial of random letters, digits and separators; a few of its letters or
digits, at positions drawn at random, swapped for a look-alike (another character of one
class of the table below, in either case), and the expected marks put by hand around those
positions, runs of neighbours in one pair of brackets, separators between them outside."""

from __future__ import annotations

import datetime as dt
import random

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.serial_differences import differences_sentence, serial_difference
from models.register.store import IssueRequest, LookalikeSerial, Register

#: characters that print alike (a class each); none of them in the filler alphabet
CLASSES = ["0Oo", "1lI", "8B", "5S", "2Z", "6G"]
FILLER = "ACDEFHJKMNPQRTWXY3479"
SEPARATORS = "-/ "


def _words(char: str) -> str:
    if char.isdigit():
        return f"the digit {char}"
    return f"the capital letter {char}" if char.isupper() else f"the small letter {char}"


def _marked(text: str, at: set[int]) -> str:
    out = ""
    for i, char in enumerate(text):
        out += ("[" if i in at and i - 1 not in at else "") + char + \
            ("]" if i in at and i + 1 not in at else "")
    return out


def _pair(rng: random.Random) -> tuple[str, str, set[int]]:
    """A serial, a look-alike of it and the positions changed."""
    length = rng.randint(4, 10)
    kept = [rng.choice(FILLER + SEPARATORS) if 0 < i < length - 1 else rng.choice(FILLER)
            for i in range(length)]
    places = [i for i, c in enumerate(kept) if c not in SEPARATORS]
    changed = set(rng.sample(places, rng.randint(1, min(3, len(places)))))
    typed = list(kept)
    for i in changed:  # two characters of a class that are not one letter in two cases
        one, other = rng.choice([(a, b) for c in CLASSES for a in c for b in c
                                 if a.casefold() != b.casefold()])
        kept[i], typed[i] = one, other
    return "".join(typed), "".join(kept), changed


def test_the_characters_that_differ_are_marked_and_named():
    rng = random.Random(67)
    for _ in range(400):
        typed, kept, changed = _pair(rng)
        found = serial_difference(typed, kept)
        runs = set(changed)  # a separator between two changed characters is not marked
        assert found.one_marked == _marked(typed, runs), (typed, kept)
        assert found.other_marked == _marked(kept, runs), (typed, kept)
        sentence = str(differences_sentence(typed, kept))
        assert sentence.startswith(f"{_marked(typed, runs)} vs {_marked(kept, runs)}: ")
        for i in changed:
            assert f"{_words(typed[i])} and {_words(kept[i])}" in sentence, (typed, kept)
        assert sentence.endswith(" print alike, case aside")


def test_case_and_separators_are_not_marked():
    found = serial_difference("1ra 0815", "LRA-O815")
    assert (found.one_marked, found.other_marked) == ("[1]ra [0]815", "[L]RA-[O]815")
    assert found.pairs == (("1", "L"), ("0", "O"))
    assert serial_difference("sn-11", "SN-LL").pairs == (("1", "L"),)  # each pair once
    found = serial_difference("SN-rnA7", "SN-MA7")  # of two lengths: aligned as it prints
    assert (found.one_marked, found.other_marked, found.pairs) == \
        ("SN-[rn]A7", "SN-[M]A7", (("rn", "M"),))


def test_a_cyrillic_letter_is_named_by_its_code_point():
    sentence = str(differences_sentence("LR\u0410-0815", "LRA-0B15"))
    assert "U+0410" in sentence and "the capital letter A" in sentence, sentence


@pytest.fixture
def register(register_url):
    with Register(register_url, timezone="UTC") as reg:
        reg.clock = lambda: dt.datetime(2028, 6, 1, 10, tzinfo=dt.timezone.utc)
        yield reg


def test_a_serial_of_two_certificates_is_named_once_with_both(register):
    def meta(serial, day):
        return CertificateMetadata(item_serial=serial, item_manufacturer="Acme Optics",
                                   item_description="Rotary table", customer_name="Customer X",
                                   calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                                   approver="Dr. Li")

    def issue(serial, day):
        return register.issue(IssueRequest("polygon", meta(serial, day), "{}"),
                              lambda m, head="": b"%PDF " + m.certificate_number.encode(),
                              separate_calibration="")[0]

    one, two = issue("RX-26-0815", "2026-11-20"), issue("RX-26-0815", "2026-11-21")
    with pytest.raises(LookalikeSerial) as raised:
        issue("RX-26-o815", "2026-11-22")
    said = str(raised.value)
    assert raised.value.numbers == (one.number, two.number)
    assert said.count("RX-26-0815") == 1, said  # named once, marked once
    assert f"looks like RX-26-0815 of Acme Optics ({one.number}, {two.number}). " \
        "RX-26-[o]815 vs RX-26-[0]815: the small letter o and the digit 0 print alike, " \
        "case aside." in said, said
    # the window's parts: no command-line option, a question, advice for a No
    question = raised.value
    assert "--another" not in question.facts + question.question + question.advice
    assert str(question.question) == "Is RX-26-o815 a different item from RX-26-0815?"
