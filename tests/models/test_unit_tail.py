"""models.messages.unit_tail: the fast path (no closing parenthesis, answers kept) gives what
the pattern alone gives, for every text."""

from hypothesis import given
from hypothesis import strategies as st

from models.messages import _UNIT_TAIL, unit_tail

UNITS = ["\"", "″", "µrad", "mdeg", "arcsec", "deg", "°", "V", "mV", "nm", "µm", "mm", "%",
         "°C", "V, log10", "V, log", "s", "rad"]


def _by_the_pattern(source: str) -> tuple[str, str]:
    found = _UNIT_TAIL.match(source)
    return (found.group(1), found.group(2)) if found else (source, "")


@given(st.text(max_size=60), st.sampled_from(["", " ", "  "]), st.sampled_from(UNITS),
       st.sampled_from(["", ")", " ", ")x", "))"]))
def test_unit_tail_is_the_patterns_answer(head, space, unit, after):
    for source in (head, f"{head}{space}({unit}{after}", f"{head}{space}({unit})"):
        assert unit_tail(source) == _by_the_pattern(source)


def test_unit_tail_figures():
    assert unit_tail("error (µrad)") == ("error", " (µrad)")
    assert unit_tail("signal (V, log10)") == ("signal", " (V, log10)")
    assert unit_tail("error (s)") == ("error (s)", "")
    assert unit_tail("error") == ("error", "")
