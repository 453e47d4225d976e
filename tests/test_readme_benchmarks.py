"""The docs' performance figures are those of the last benchmark run.

`make bench` writes the headlines into BENCHMARKS.md and between the markers of
docs/benchmarks.md (the README's until #44 moved them there); this checks that nobody
edited one without the other.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BEGIN, END = "<!-- bench:headlines begin -->", "<!-- bench:headlines end -->"


def _readme_headlines() -> list[str]:
    text = (ROOT / "docs" / "benchmarks.md").read_text(encoding="utf-8")
    start, end = text.index(BEGIN), text.index(END)
    return [line for line in text[start + len(BEGIN):end].splitlines() if line.strip()]


def _benchmark_headlines() -> list[str]:
    lines = (ROOT / "BENCHMARKS.md").read_text(encoding="utf-8").splitlines()
    start = lines.index("## Headlines") + 1
    out = []
    for line in lines[start:]:
        if line.startswith(("## ", "<!-- bench:section")):  # the first section
            break
        if line.strip():
            out.append(line)
    return out


def test_readme_figures_are_the_last_benchmark_run():
    readme = _readme_headlines()
    assert readme, "docs/benchmarks.md's benchmark block is empty: run `make bench`"
    assert readme == _benchmark_headlines()


def test_theodolite_headline_compares_with_what_a_user_would_do():
    theodolite = next(line for line in _readme_headlines() if line.startswith("* Theodolite"))
    assert "one random start" in theodolite and "best of three" in theodolite
    assert "1000 random starts" not in theodolite  # the seed's route is the robustness check
