"""The long form of tests/app/writers/test_certificate_fonts.py (#44): every workbench's sample
certificate in every language with every lab name, 45 certificates read back by poppler's
pdftotext (~80 s of CPU); the suite prints the 15 of its Latin square (every workbench with
every language and lab name, every language with every lab name)."""

from __future__ import annotations

import pytest

from models.registry import KINDS
from tests.app.writers.test_certificate_fonts import (  # noqa: F401 - the module's fixture
    LAB_NAMES,
    LANGUAGES,
    analysed,
    check_fonts_and_lab,
)


@pytest.mark.parametrize("lab", list(LAB_NAMES))
@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("key", sorted(KINDS))
def test_every_run_has_a_font_and_every_page_the_lab(analysed, key, language, lab, tmp_path):  # noqa: F811
    check_fonts_and_lab(analysed, key, language, lab, tmp_path)
