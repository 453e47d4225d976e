"""The polygon's set-up statement (certificate, summary, window) joins its three sentences
as a translation punctuates them: in Chinese no space after "。" (cert77: a plain " " put
"。 " between them), in English as before."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from models.messages import in_language, translator
from models.polygon.setup_statement import setup_statement

ZH = translator("zh_CN")


@pytest.mark.parametrize("alignment, corrected", [("levelled", False), ("tilted", True)])
def test_the_set_up_statement_has_no_space_between_its_chinese_sentences(alignment, corrected):
    result = SimpleNamespace(ac_alignment=alignment, roll_corrected=corrected,
                             ac_roll_measured_arcmin=1.5, u_ac_roll_arcmin=0.2,
                             ac_roll_arcmin=5.0)
    said = setup_statement(result)
    assert said.count(". ") >= 2 and said.startswith("Set-up assumed: ")
    assert (" corrected. To tell which set-up" in said if corrected else
            " in the uncertainty. To tell which set-up" in said)
    chinese = in_language(said, ZH)
    assert chinese.count("。") >= 3 and "。 " not in chinese, chinese
    assert ("+1.5′" if corrected else "±5′") in chinese
