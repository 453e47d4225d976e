"""Parse and format angles: decimal degrees and degrees-minutes-seconds strings.

Accepted spellings (a leading sign applies to the whole angle)::

    12.5           -0.25        +3          12,5 (decimal comma)
    12°34'56.7"    12 34 56.7   12:34:56.7  12d34m56.7s
    -0°00'12.5"    12°30.5'     12°         12度34分56.7秒
    １２°３４′５６．７″  (full-width digits and primes)
    138°24'05,15"  138 24 05,15  (a decimal comma in the last part, as Europe writes it)

Minutes and seconds must be below 60; degrees must be whole when minutes
follow, and minutes whole when seconds follow. A decimal comma is read in one
number only (never with a point): ``12,34,56`` is not an angle.
"""

from __future__ import annotations

import math
import re
import unicodedata

from models.messages import QT_TR_NOOP, message

ARCSEC_PER_DEG = 3600.0
ARCSEC_PER_RAD = 180.0 * 3600.0 / math.pi

__all__ = [
    "ARCSEC_PER_DEG",
    "ARCSEC_PER_RAD",
    "AngleParseError",
    "arcsec_to_deg",
    "deg_to_arcsec",
    "format_dms",
    "parse_angle_deg",
]


class AngleParseError(ValueError):
    """An angle string could not be read; the message says why."""


def deg_to_arcsec(value_deg):
    """Degrees to arcseconds (works on floats and numpy arrays)."""
    return value_deg * ARCSEC_PER_DEG


def arcsec_to_deg(value_arcsec):
    """Arcseconds to degrees (works on floats and numpy arrays)."""
    return value_arcsec / ARCSEC_PER_DEG


_NUMBER = r"(\d+(?:\.\d*)?|\.\d+|\d+,\d+)"  # 05,15: a decimal comma
_SEP_DEG = r"(?:°|d|度|\s+|:)"
_SEP_MIN = r"(?:'|m|分|\s+|:)"
_SEP_SEC = r"(?:\"|s|秒)"
_DMS = re.compile(
    rf"^{_NUMBER}\s*{_SEP_DEG}\s*"
    rf"(?:{_NUMBER}\s*(?:{_SEP_MIN}\s*(?:{_NUMBER}\s*{_SEP_SEC}?)?)?)?$"
)
_DECIMAL = re.compile(r"^(\d+(?:\.\d*)?|\.\d+)(?:e[+-]?\d+)?$")


#: the spellings read as the plain ones, replaced in this order
_REPLACEMENTS = {
    "\u2212": "-",  # minus sign
    "\u2013": "-",
    "\u2032\u2032": '"',  # NFKC turns the double prime into two primes
    "\u2033": '"',
    "\u2032": "'",
    "\u2019\u2019": '"',
    "\u201d": '"',
    "\u2019": "'",
    "''": '"',
    "º": "°",
    "˚": "°",
}
#: any text of :data:`_REPLACEMENTS` (a replacement makes one only where this finds one)
_REPLACED = re.compile("|".join(re.escape(k) for k in _REPLACEMENTS))


def _normalise(text: str) -> str:
    s = unicodedata.normalize("NFKC", text).strip().lower()
    if _REPLACED.search(s) is None:
        return s  # nothing to replace (most cells: one search, not eleven replaces)
    for old, new in _REPLACEMENTS.items():
        s = s.replace(old, new)
    return s


def parse_angle_deg(text: str) -> float:
    """Read an angle in degrees from decimal or D°M'S" text.

    Parameters
    ----------
    text : str
        The cell text, e.g. ``"12°34'56.7\\""``, ``"12 34 56.7"`` or ``"-0.25"``.

    Returns
    -------
    float
        The angle in decimal degrees.

    Raises
    ------
    AngleParseError
        With a message naming what is wrong (empty, minutes out of range, ...).
    """
    if not isinstance(text, str):
        raise AngleParseError(f"expected text, got {type(text).__name__}")
    s = _normalise(text)
    if not s:
        raise AngleParseError(message(QT_TR_NOOP("empty")))
    sign = 1.0
    if s[0] in "+-":
        sign = -1.0 if s[0] == "-" else 1.0
        s = s[1:].lstrip()
    if s.count(",") == 1 and "." not in s and _DECIMAL.match(s.replace(",", ".")):
        s = s.replace(",", ".")
    if _DECIMAL.match(s):
        value = float(s)
        if not math.isfinite(value):
            raise AngleParseError(message(QT_TR_NOOP("'{text}' is not a finite angle"),
                                          text=text.strip()))
        return sign * value
    match = _DMS.match(s) if s.count(",") <= 1 and not ("," in s and "." in s) else None
    if match is None:
        raise AngleParseError(message(QT_TR_NOOP(
            "'{text}' is not an angle; write decimal degrees (12.5) or D°M'S\" (12°34'56.7\", "
            "12 34 56.7, 12:34:56.7)"), text=text.strip()))
    _, min_s, sec_s = (None if g is None else g.replace(",", ".") for g in match.groups())
    degrees = float(match.group(1).replace(",", "."))  # a match always has its degrees
    minutes = float(min_s) if min_s is not None else 0.0
    seconds = float(sec_s) if sec_s is not None else 0.0
    if min_s is not None and not degrees.is_integer():
        raise AngleParseError(message(QT_TR_NOOP("'{text}': degrees must be whole when minutes "
                                                 "follow"), text=text.strip()))
    if sec_s is not None and not minutes.is_integer():
        raise AngleParseError(message(QT_TR_NOOP("'{text}': minutes must be whole when seconds "
                                                 "follow"), text=text.strip()))
    if minutes >= 60:
        raise AngleParseError(message(QT_TR_NOOP("'{text}': minutes {minutes} out of range (0 "
                                                 "to 59)"), text=text.strip(), minutes=min_s))
    if seconds >= 60:
        raise AngleParseError(message(QT_TR_NOOP("'{text}': seconds {seconds} out of range (0 "
                                                 "to below 60)"), text=text.strip(),
                                      seconds=sec_s))
    return sign * (degrees + minutes / 60.0 + seconds / 3600.0)


def format_dms(value_deg: float, places: int = 1) -> str:
    """Format decimal degrees as ``-12°34'56.7"`` with ``places`` decimals of seconds.

    Rounding carries into minutes and degrees, so 59.96" never shows as 60.0".
    """
    if not math.isfinite(value_deg):
        return "—"
    sign = "-" if value_deg < 0 else ""
    scale = 10**places
    total = round(abs(value_deg) * 3600.0 * scale)  # integer count of 10^-places arcsec
    if total == 0:
        sign = ""
    deg, rest = divmod(total, 3600 * scale)
    minutes, sec_scaled = divmod(rest, 60 * scale)
    if places > 0:
        whole, frac = divmod(sec_scaled, scale)
        sec_text = f"{whole:02d}.{frac:0{places}d}"
    else:
        sec_text = f"{sec_scaled:02d}"
    return f"{sign}{deg}°{minutes:02d}'{sec_text}\""
