"""The certificate's method statement for the figures' coverage intervals names which figure
comes from which method (day review 68 F1, F6).

Since 0.8.17 A, A↑, A↓ and P (the theodolite's A, A↑, A↓) take bounds from each target's own
readings (the noncentral t, Owen 1968 / ISO 16269-6), as R, R↑, R↓ and Ps take chi-square
bounds; the certificate still said every figure's interval was the bootstrap's, united for
"(E, M, B, R, A, P)" with the measured means' (the Chinese theodolite certificate
"区间由轴系模型对指标误差作参数自助法得到 … R、R↑ 和 R↓ 的区间不用自助法区间"), and said
nothing of why those intervals are wide at few runs. Read back with pdftotext, English and
Chinese; the theodolite's passes are simulated from first principles
(tests/repeatability_rig.py)."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from app.main import main
from tests.app.writers.test_decided_row_probability import _readings

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"

#: what each certificate said that was false: every figure's interval the bootstrap's
OLD_CLAIMS = {
    "positioning": ("For the figures of the mean deviations (E, M, B, R, A, P) it is united",
                    "对平均偏差的指标（E、M、B、R、A、P），该区间与以测得平均值为真值求得的区间取并集"),
    "theodolite": ("It is a parametric bootstrap of the figure's error from a model",
                   "可能位于所给数值之下。区间由轴系模型对指标误差作参数自助法得到",
                   "R、R↑ 和 R↓ 的区间不用自助法区间"),
}
#: what the English statement now says of A's interval and of the width at few runs
SAID = {
    "positioning": ("The interval of A, A↑, A↓ and P is the bounds from each target's own mean "
                    "and standard deviation",
                    "at 3 runs each σ has 2 degrees of freedom"),
    "theodolite": ("The interval of A, A↑ and A↓ is the bounds from each θ's own mean and "
                   "standard deviation",
                   "at 3 passes each σ has 2 degrees of freedom"),
}


def _text(kind: str, language: str, tmp_path: Path, capsys) -> str:
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    details = json.loads((SAMPLES / f"certificate_{kind}.json").read_text("utf-8"))
    details.pop("certificate_number", None)  # the register allocates one
    details["language"] = language
    meta = tmp_path / f"meta_{language}.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    pdf = tmp_path / "c.pdf"
    assert main(["analyze", kind, str(_readings(kind, tmp_path)), "--metadata", str(meta),
                 "--certificate", str(pdf)]) == 0
    capsys.readouterr()
    text = subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True,
                          text=True, encoding="utf-8", check=True).stdout
    # a paragraph broken over lines and pages: the pages' running heads and feet out
    furniture = re.compile(r"shall not be reproduced|不得部分复制|SPECIMEN-|Page \d+ of \d+|"
                           r"第\s*\d+\s*页|Precision Angle Lab")
    kept = [line for line in text.splitlines() if not furniture.search(line)]
    return re.sub(r"\s+", " ", " ".join(kept))


@pytest.mark.parametrize("kind", ["positioning", "theodolite"])
@pytest.mark.parametrize("language", ["en", "zh"])
def test_the_method_names_where_each_figures_interval_comes_from(kind, language, tmp_path,
                                                                  capsys):
    text = _text(kind, language, tmp_path, capsys)
    # Chinese runs on over a line break with no space: looked for with no white space at all
    bare = re.sub(r"\s+", "", text)
    for claim in OLD_CLAIMS[kind]:
        assert claim not in text and re.sub(r"\s+", "", claim) not in bare, claim
    # the noncentral t bounds cited, as an assessor needs them to reproduce A's interval
    # (the same citations in either language)
    assert "Owen 1968" in text and "ISO 16269-6" in text
    assert "Berger 1982" in text and "Šidák" in text
    if language == "en":
        for said in SAID[kind]:
            assert said in text, said
