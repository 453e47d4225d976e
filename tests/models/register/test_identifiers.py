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
