"""No in-house name for the source papers in what a customer or technician reads (assessor):
"the seed" is what the developers call the papers a method comes from (../shared/seeds/);
a certificate, a setting's help, the command line's --help, a validation case or a page of
the manual names the paper instead (Tian et al. 2017, Tian et al. 2015, Gao et al. 2013,
cited in full as the certificate's method reference). "seed" as the Monte Carlo's random
seed ("seed 1234", "seeded from the readings") is right and stays.

The printed sample certificates are checked in tests/app/writers/test_certificate_chinese.py
(they are printed there once for every workbench, in English and Chinese)."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from models.registry import KINDS

ROOT = Path(__file__).resolve().parents[2]
TS = ROOT / "resources" / "translations" / "anglebench_zh_CN.ts"

#: the papers by their in-house name: "the seed's …", "the seeds' …", "the seed", "seed 001",
#: "(seed)", "seed paper"; and in Chinese "种子 001" (not the Monte Carlo's "随机种子 {seed}")
IN_HOUSE = re.compile(r"\bseed's|\bseeds'|\bthe seeds?\b(?!ed)|\bseed 0\d\d\b|\(seed\)|"
                      r"\bseed paper|种子\s*0\d\d", re.IGNORECASE)

#: the pages of the manual (F1) and the README (BENCHMARKS.md, `make bench`'s full report for
#: the developers, keeps the name below its headlines)
PAGES = sorted([*ROOT.glob("docs/user-guide/*.md"), *ROOT.glob("docs/zh_CN/user-guide/*.md"),
                *(ROOT / "docs" / name for name in ("certificates-and-register.md",
                                                    "zh_CN/certificates-and-register.md",
                                                    "command-line.md", "benchmarks.md")),
                ROOT / "README.md"])


def test_the_pattern_finds_the_in_house_name_and_not_the_random_seed():
    for jargon in ("the negative of the seed's A − θ", "Table 1 of the seed: the accuracy",
                   "3-D simulation in seed 001's frame", "particle swarm (seed)",
                   "the seeds' check figures", "种子 001 坐标系下的三维仿真"):
        assert IN_HOUSE.search(jargon), jargon
    for random_seed in ("5000 trials, seed 20261202", "seeded from the readings",
                        "the seeded runs", "随机种子 {seed}", "two seeds", "400 次给定种子的运行"):
        assert not IN_HOUSE.search(random_seed), random_seed


def test_no_text_of_the_window_certificate_or_validation_report_names_a_paper_the_seed():
    """Every translated text (the window's, the certificate's, the validation report's, the
    command line's), in English and in Chinese."""
    found = [text for message in ET.parse(TS).getroot().iter("message")
             for tag in ("source", "translation")
             if (text := message.findtext(tag) or "") and IN_HOUSE.search(text)]
    assert found == []


@pytest.mark.parametrize("key", sorted(KINDS))
def test_no_setting_says_seed_for_the_paper(key):
    """A setting's label, help (the window's tooltip and the command line's --help) and each
    choice as the certificate's analysis settings list it."""
    texts = [text for p in KINDS[key].parameters
             for text in (p.label, p.help, *(p.text(value) for value, _ in p.choices or ()))]
    assert [t for t in texts if IN_HOUSE.search(t)] == []


@pytest.mark.parametrize("page", PAGES, ids=[str(p.relative_to(ROOT)) for p in PAGES])
def test_no_page_of_the_manual_says_seed_for_the_paper(page):
    lines = [line for line in page.read_text("utf-8").splitlines() if IN_HOUSE.search(line)]
    assert lines == []
