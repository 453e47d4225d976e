import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.readings.angles import AngleParseError, format_dms, parse_angle_deg


@pytest.mark.parametrize(
    "text, expected",
    [
        ("12.5", 12.5),
        ("-0.25", -0.25),
        ("+3", 3.0),
        ("12,5", 12.5),
        ("12°34'56.7\"", 12 + 34 / 60 + 56.7 / 3600),
        ("12 34 56.7", 12 + 34 / 60 + 56.7 / 3600),
        ("12:34:56.7", 12 + 34 / 60 + 56.7 / 3600),
        ("12d34m56.7s", 12 + 34 / 60 + 56.7 / 3600),
        ("-0°00'12.5\"", -12.5 / 3600),
        ("−0°00′12.5″", -12.5 / 3600),
        ("１２°３４′５６．７″", 12 + 34 / 60 + 56.7 / 3600),
        ("12度34分56.7秒", 12 + 34 / 60 + 56.7 / 3600),
        ("12°30.5'", 12 + 30.5 / 60),
        ("12°", 12.0),
        ("359°59'59.9\"", 360 - 0.1 / 3600),
        ("  45 ", 45.0),
        ("12°34'56.7''", 12 + 34 / 60 + 56.7 / 3600),
        ("138°24'05,15\"", 138 + 24 / 60 + 5.15 / 3600),
        ("-138°24′05,15″", -(138 + 24 / 60 + 5.15 / 3600)),
        ("１３８°２４′０５，１５″", 138 + 24 / 60 + 5.15 / 3600),
        ("138 24 05,15", 138 + 24 / 60 + 5.15 / 3600),
        ("138:24:05,15", 138 + 24 / 60 + 5.15 / 3600),
        ("138度24分05,15秒", 138 + 24 / 60 + 5.15 / 3600),
        ("12°30,5'", 12 + 30.5 / 60),
        ("12,5°", 12.5),
    ],
)
def test_parses_usual_spellings(text, expected):
    assert parse_angle_deg(text) == pytest.approx(expected, abs=1e-12)


@pytest.mark.parametrize(
    "text, reason",
    [
        ("1°61'00\"", "minutes 61 out of range"),
        ("1°00'60\"", "seconds 60 out of range"),
        ("1.5°30'", "degrees must be whole"),
        ("1°30.5'10\"", "minutes must be whole"),
        ("", "empty"),
        ("abc", "is not an angle"),
        ("12°34'56.7\"x", "is not an angle"),
        ("inf", "is not an angle"),
        ("12,34,56", "is not an angle"),
        ("12°34'5,6.7\"", "is not an angle"),
        ("12°30,5'10\"", "minutes must be whole"),
        ("1°00'60,0\"", "seconds 60.0 out of range"),
    ],
)
def test_rejects_with_reason(text, reason):
    with pytest.raises(AngleParseError, match=reason):
        parse_angle_deg(text)


def test_format_carries_rounding():
    assert format_dms(59.99999, 1) == "60°00'00.0\""
    assert format_dms(-12.5 / 3600) == "-0°00'12.5\""
    assert format_dms(-0.00001 / 3600) == "0°00'00.0\""
    assert format_dms(12 + 34 / 60 + 56.7 / 3600, 2) == "12°34'56.70\""


@given(st.floats(-720, 720, allow_nan=False), st.integers(0, 4))
def test_format_parse_round_trip(value, places):
    text = format_dms(value, places)
    back = parse_angle_deg(text)
    assert abs(back - value) * 3600 <= 0.5 * 10**-places + 1e-9


@given(
    st.integers(0, 359), st.integers(0, 59), st.decimals(0, "59.999", places=3),
    st.booleans(), st.sampled_from(["{d}°{m}'{s}\"", "{d} {m} {s}", "{d}:{m}:{s}"]),
)
@pytest.mark.slow
def test_dms_components_round_trip(d, m, s, negative, pattern):
    text = ("-" if negative else "") + pattern.format(d=d, m=m, s=s)
    expected = (d + m / 60 + float(s) / 3600) * (-1 if negative else 1)
    assert math.isclose(parse_angle_deg(text), expected, abs_tol=1e-12)


@pytest.mark.slow
@given(st.text(max_size=20))
def test_never_raises_anything_but_parse_error(text):
    try:
        value = parse_angle_deg(text)
    except AngleParseError:
        return
    assert math.isfinite(value)


def _full_width(text: str) -> str:
    """Digits, sign, point and comma as a Chinese or Japanese input method types them."""
    return "".join(chr(ord(c) + 0xFEE0) if c.isdigit() or c in ".,-" else c for c in text)


SPELLINGS = {
    "symbols": "{sign}{d}°{m:02d}'{s}\"",
    "primes": "{sign}{d}°{m:02d}′{s}″",
    "two apostrophes": "{sign}{d}°{m:02d}'{s}''",
    "spaces": "{sign}{d} {m:02d} {s}",
    "colons": "{sign}{d}:{m:02d}:{s}",
    "letters": "{sign}{d}d{m:02d}m{s}s",
    "Chinese": "{sign}{d}度{m:02d}分{s}秒",
    "minus sign": "{minus}{d}°{m:02d}′{s}″",
}


@given(st.floats(-720, 720, allow_nan=False), st.integers(0, 4), st.sampled_from(sorted(SPELLINGS)),
       st.booleans(), st.booleans())
def test_format_parse_round_trip_in_every_spelling(value, places, spelling, comma, full_width):
    """format_dms → each accepted spelling (decimal point or comma, ASCII or full-width) →
    parse_angle_deg gives the angle back to the seconds' last place."""
    text = format_dms(value, places)
    sign = "-" if text.startswith("-") else ""
    d, rest = text.lstrip("-").split("°")
    m, s = rest.rstrip('"').split("'")
    if comma:
        s = s.replace(".", ",")
    text = SPELLINGS[spelling].format(sign=sign, minus="\u2212" if sign else "", d=int(d),
                                      m=int(m), s=s)
    if full_width:
        text = _full_width(text)
    back = parse_angle_deg(text)
    assert abs(back - value) * 3600 <= 0.5 * 10**-places + 1e-9, text


@given(st.floats(-720, 720, allow_nan=False), st.integers(1, 8), st.booleans())
def test_decimal_degrees_with_a_comma_round_trip(value, places, full_width):
    text = f"{value:.{places}f}".replace(".", ",")
    if full_width:
        text = _full_width(text)
    assert math.isclose(parse_angle_deg(text), float(f"{value:.{places}f}"), abs_tol=1e-12)


@given(st.integers(0, 359), st.integers(0, 59), st.integers(0, 59), st.integers(0, 99),
       st.integers(0, 99))
def test_two_commas_or_a_comma_with_a_point_are_never_read(d, m, s, f1, f2):
    for text in (f"{d}°{m}'{s},{f1},{f2}\"", f"{d},{m}'{s}.{f1}\"", f"{d},{m},{s}"):
        with pytest.raises(AngleParseError):
            parse_angle_deg(text)
