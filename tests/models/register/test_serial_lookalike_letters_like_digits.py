"""Day review 67 F6: letters that engraved and stamped serials print like digits, beyond
UTS #39's own, are asked about: B and 8, S and 5, Z and 2, G and 6 ("RX-26-0B15" beside
RX-26-0815 was issued unasked as another item). U and V are not (two letters, drawn apart).
Asked, never merged: the two serials stay two items.

The rule, stated here on its own: each character prints like the digit of its class, case
aside ("B", "b", "8" are 8; "S", "s", "5" are 5; "Z", "z", "2" are 2; "G", "g", "6" are 6;
"O", "o", "0" are 0); a letter with no digit look-alike is itself, case aside. Exhaustive
over every serial "SN-xy" of those characters and a few others."""

from __future__ import annotations

import datetime as dt
import itertools

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register.identifiers import same_serial, serial_lookalike
from models.register.store import IssueRequest, LookalikeSerial, Register

#: what each character prints like, case aside (the rule above)
PRINTS_LIKE = {"B": "8", "b": "8", "8": "8", "S": "5", "s": "5", "5": "5",
               "Z": "2", "z": "2", "2": "2", "G": "6", "g": "6", "6": "6",
               "O": "0", "o": "0", "0": "0", "U": "u", "u": "u", "V": "v", "v": "v",
               "A": "a", "a": "a", "3": "3"}


def _looks_alike(one: str, other: str) -> bool:
    return len(one) == len(other) and all(PRINTS_LIKE.get(a, a) == PRINTS_LIKE.get(b, b)
                                          for a, b in zip(one, other, strict=True))


def test_every_serial_that_looks_alike_is_one_or_asked_and_no_other_is_asked():
    serials = ["SN-" + "".join(chars) for chars in itertools.product(PRINTS_LIKE, repeat=2)]
    passed, asked_otherwise = [], []
    for one, other in itertools.combinations(serials, 2):
        one_item, asked = same_serial(one, other), serial_lookalike(one, other)
        assert not (one_item and asked), (one, other)  # asked is never merged
        if _looks_alike(one, other) and not (one_item or asked):
            passed.append((one, other))
        if asked and not _looks_alike(one, other):
            asked_otherwise.append((one, other))
    assert passed == [], f"{len(passed)} pairs passed unasked, e.g. {passed[:5]}"
    assert asked_otherwise == [], f"{len(asked_otherwise)} asked, e.g. {asked_otherwise[:5]}"


@pytest.mark.parametrize("letter,digit", [("B", "8"), ("S", "5"), ("Z", "2"), ("G", "6")])
def test_each_letter_like_a_digit_is_asked_in_either_case(letter, digit):
    kept = f"RX-26-0{digit}15"
    for typed in (f"RX-26-0{letter}15", f"rx-26-0{letter.lower()}15"):
        assert serial_lookalike(typed, kept) and not same_serial(typed, kept), typed


def test_u_and_v_are_two_letters_unasked():
    for one, other in (("SN-U5", "SN-V5"), ("uv-100", "UU-100"), ("SN-VU", "SN-UV")):
        assert not serial_lookalike(one, other) and not same_serial(one, other), (one, other)


def test_the_register_asks_about_a_b_for_an_8_and_keeps_two_items(register_url):
    def meta(serial, day):
        return CertificateMetadata(item_serial=serial, item_manufacturer="Acme Optics",
                                   item_description="Rotary table", customer_name="Customer X",
                                   calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                                   approver="Dr. Li")

    def issue(register, serial, day, **options):
        return register.issue(IssueRequest("polygon", meta(serial, day), "{}"),
                              lambda m, head="": b"%PDF " + m.certificate_number.encode(),
                              separate_calibration="", **options)[0]

    with Register(register_url, timezone="UTC") as register:
        register.clock = lambda: dt.datetime(2028, 6, 1, 10, tzinfo=dt.timezone.utc)
        first = issue(register, "RX-26-0815", "2026-11-20")
        with pytest.raises(LookalikeSerial) as raised:
            issue(register, "RX-26-0B15", "2027-01-15")
        assert raised.value.numbers == (first.number,)
        second = issue(register, "RX-26-0B15", "2027-01-15", another_lookalike_item=True)
        assert [r.number for r in register.history("RX-26-0815", "Acme Optics")] == \
            [first.number]
        assert [r.number for r in register.history("RX-26-0B15", "Acme Optics")] == \
            [second.number]
        assert register.audit() == []
