"""The item's manufacturer is called one thing in Chinese: the certificate's label is the
register's column (day review 67 F9: `register list --language zh_CN` headed it 制造商,
the certificate printed 制造单位)."""

from __future__ import annotations

import pytest

from app.register_listing import HEADERS
from models.messages import translator
from tests.pdf_text import pdf_text


def _register_manufacturer() -> str:
    """The Chinese heading of the register list's manufacturer column."""
    assert "Manufacturer" in HEADERS
    return translator("zh_CN")("Manufacturer")


@pytest.mark.parametrize("language", ["zh", "zh+en"])
def test_the_certificate_calls_the_manufacturer_as_the_register_does(language,
                                                                      sample_certificates):
    heading = _register_manufacturer()
    assert heading != "Manufacturer"
    # the polygon's sample certificate in ``language`` (printed once a run: tests/conftest.py)
    text = pdf_text(sample_certificates("polygon", language)[0])
    assert heading in text and "制造单位" not in text, (heading, text[:800])
