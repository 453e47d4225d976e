"""The long form of tests/app/writers/test_certificate_chinese.py (#44): every workbench's sample
certificate in every variant (as issued, judged per point, simple acceptance, guard band, a
draft of an amendment, a replacement) printed in Chinese and in English, 30 pairs (~70 s of
CPU); the suite prints 15 of them (every workbench as issued and in two other variants, each
variant for two workbenches)."""

from __future__ import annotations

import pytest

from models.registry import KINDS
from tests.app.writers.test_certificate_chinese import (  # noqa: F401 - the module's fixture
    VARIANTS,
    analysed,
    check_chinese_certificate,
)


@pytest.mark.parametrize("key", sorted(KINDS))
@pytest.mark.parametrize("variant", list(VARIANTS))
def test_a_chinese_certificate_has_every_figure_and_no_english_of_ours(analysed, key, variant):  # noqa: F811
    check_chinese_certificate(analysed, key, variant)
