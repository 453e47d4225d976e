"""Assessment 78 L2: with every point deciding and U ≥ T, the statement ended "…so no result
could be shown to lie within it. (at θ = -20.0000°)": the place dangled after the full stop,
its angle with a hyphen-minus. The place is said inside the sentence, beside the U it is
of, its angle with the certificate's minus sign "−" and to the decimals of the results
table (the point's own name: "θ = −20.0000°")."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from models.messages import in_language, translator
from models.uncertainty.conformity import decide_conformity
from tests.models.uncertainty.test_conformity_chinese import _budget


def test_the_place_of_the_largest_u_is_inside_the_sentence_with_its_minus_sign():
    e = np.array([-0.4, 0.2, 0.5, -0.1])
    names = ["θ = -20.0000°", "θ = -10.0000°", "θ = 0.0000°", "θ = 10.0000°"]
    c = decide_conformity(e, _budget(2.0, e.size), 3.0, "guarded", "points", point_names=names)
    assert c.verdict == "not assessed"
    statement = str(c.statement)
    assert statement.startswith("No statement of conformity is possible: the expanded "
                                "uncertainty U = ")
    assert " (at θ = −20.0000°) is not smaller than the tolerance T = 3\"" in statement, statement
    assert statement.endswith("so no result could be shown to lie within it."), statement
    assert "-20" not in statement and ". (at" not in statement
    assert names[0] == "θ = -20.0000°"  # the names given are not changed


def test_in_chinese_the_place_is_inside_the_sentence_too():
    e = np.array([-0.4, 0.2])
    c = decide_conformity(e, _budget(2.0, e.size), 3.0, "guarded", "points",
                          point_names=["θ = -20.0000°", "θ = 20.0000°"])
    zh = in_language(c.statement, translator("zh_CN"))
    assert "（在 θ = −20.0000°）不小于允差 T = 3\"" in zh, zh
    assert zh.endswith("任何结果都不能证明在其范围以内。"), zh


@pytest.mark.slow
def test_the_theodolite_certificate_names_the_point_as_its_results_table(tmp_path):
    from app.writers.certificate_pdf import certificate_pdf_bytes
    from tests.models.certificate.test_certificate_statements import _sample
    from tests.models.certificate.test_certificate_uncertainty import META
    from tests.pdf_text import pdf_text

    kind, result = _sample("theodolite")
    meta = replace(META, decision_quantity="points", tolerance=1.5)
    document = kind.certificate_document(result, meta)
    assert document.conformity.verdict == "not assessed"
    worst = int(np.argmax(document.budget.expanded))
    shown = f"{result.theta_deg[worst]:.4f}"  # the results table's θ cell
    assert document.results.rows[worst][0] == shown
    place = f"(at θ = {shown.replace('-', '−')}°) is not smaller than the tolerance"
    assert place in str(document.conformity.statement), document.conformity.statement
    text = pdf_text(certificate_pdf_bytes(document))
    assert place in text and "within it. (at" not in text
