"""A certificate number of a scheme is its fields, not its separators.

The register steps over a number issued before whatever the separators, case, marks and
zero padding of its scheme (models/register/identifiers.py: "AB-2026-6" is AB-2026-0006,
"AB_2026_0009" is AB-2026-0009), each digit run read as a number. A scheme without
separators runs its fields together: ``AB{year}{seq:04d}`` prints AB20260001, one run of
digits that no key of AB-2026-0001 meets, and the register issued it beside AB-2026-0001
(reg72 #11). The scheme says where its fields are: :func:`number_pattern` matches every
number that prints the same fields — the same year, month, day and sequence, the same
letters and digits of its text, case aside — with any separators (or none) between them and
any zero padding, so that the number is skipped as issued.

Why the fields and not a refusal of the scheme: a lab moving to a scheme without separators
(or back) is a legitimate change, and refusing it would stop issuing; skipping the numbers
whose fields were issued keeps every printed number one certificate's.
"""

from __future__ import annotations

import re
import unicodedata
from collections.abc import Iterable

__all__ = ["fields_issued", "number_pattern"]

#: the fields a scheme fills in (models/certificate/metadata.format_certificate_number)
_FIELD = re.compile(r"\{(year|month|day|seq)(?::0?\d+d)?\}")
#: what may stand between two fields or letters: anything that is no letter or digit
_SEP = r"[\W_]*"


def _literal(text: str) -> list[str]:
    """The letters and digits of the scheme's text between fields, each matched case aside
    (separators are what lies between them)."""
    return [re.escape(c) for c in unicodedata.normalize("NFKC", text) if c.isalnum()]


def number_pattern(scheme: str, sequence: int, year: int, month: int, day: int
                   ) -> re.Pattern[str]:
    """A pattern matching every number that prints the fields ``scheme`` gives with
    ``sequence`` on that date, whatever its separators (or none), case and zero padding."""
    values = {"year": year, "month": month, "day": day, "seq": sequence}
    tokens: list[str] = []
    at = 0
    for field in _FIELD.finditer(scheme):
        tokens += _literal(scheme[at:field.start()])
        tokens.append(f"0*{values[field.group(1)]}")
        at = field.end()
    tokens += _literal(scheme[at:])
    return re.compile(_SEP + _SEP.join(tokens) + _SEP, re.IGNORECASE)


def fields_issued(pattern: re.Pattern[str], issued: Iterable[str]) -> str | None:
    """The first of the ``issued`` numbers that prints the fields ``pattern`` stands for
    (:func:`number_pattern`); None when none does."""
    for number in issued:
        if pattern.fullmatch(unicodedata.normalize("NFKC", number)):
            return number
    return None
