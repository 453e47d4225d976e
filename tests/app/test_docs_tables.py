"""The documentation (#44): README.md short, the generated tables of README.md and docs/
those the code declares now (``make docs``), every link inside the docs pointing at a file
and a heading that exist, and a user guide for every workbench."""

from __future__ import annotations

import re
import unicodedata
from pathlib import Path

import pytest

from app import docs_tables
from models.registry import KINDS

ROOT = Path(__file__).resolve().parents[2]
README_MAX_LINES = 300
DOCS = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md")])


def test_readme_is_at_most_300_lines():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) <= README_MAX_LINES, (
        f"README.md has {len(lines)} lines (at most {README_MAX_LINES}): move the long form "
        "into docs/ and link it")


def _read(path: str) -> str:
    return (ROOT / path).read_text(encoding="utf-8")


def test_workbench_and_settings_tables_are_current():
    """The fast half of the staleness check (the commands' help, which imports every
    command, is the slow one below)."""
    assert docs_tables.block(_read("README.md"), "workbenches") == (
        docs_tables.workbench_table()), "README.md: the workbench table is stale: run `make docs`"
    assert docs_tables.block(_read("docs/README.md"), "workbenches") == (
        docs_tables.workbench_table("user-guide/")), (
        "docs/README.md: the workbench table is stale: run `make docs`")
    assert docs_tables.block(_read("docs/command-line.md"), "settings") == (
        docs_tables.settings_tables()), (
        "docs/command-line.md: the settings tables are stale: run `make docs`")


@pytest.mark.slow
def test_command_help_is_current():
    """Every generated block of every file, the commands' help included (``make docs``)."""
    assert docs_tables.stale() == [], "generated tables are stale: run `make docs`"


def test_every_workbench_and_every_setting_is_in_the_tables():
    table = docs_tables.workbench_table()
    settings = docs_tables.settings_tables()
    for key, kind in KINDS.items():
        assert f"| `{key}` | **{kind.title}** |" in table
        assert f"`resources/samples/{kind.sample_file}`" in table
        for parameter in kind.parameters:
            assert f"(`{parameter.key}`)" in settings, (key, parameter.key)
            if parameter.cli:
                assert f"| `{parameter.flag}` |" in settings, (key, parameter.flag)


def test_a_stale_block_is_replaced_and_nothing_else():
    text = "before\n<!-- generated:x begin -->\nold\n<!-- generated:x end -->\nafter\n"
    assert docs_tables.filled(text, "x", "new") == (
        "before\n<!-- generated:x begin -->\nnew\n<!-- generated:x end -->\nafter\n")
    with pytest.raises(ValueError, match="generated:y begin"):
        docs_tables.filled(text, "y", "new", "doc.md")


def test_the_check_fails_on_a_stale_file(tmp_path, monkeypatch):
    for path in docs_tables.BLOCKS:
        (tmp_path / path).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / path).write_text((ROOT / path).read_text(encoding="utf-8"), encoding="utf-8")
    fast = {"README.md": {"workbenches": docs_tables.workbench_table}}
    monkeypatch.setattr(docs_tables, "BLOCKS", fast)
    assert docs_tables.stale(tmp_path) == []
    readme = tmp_path / "README.md"
    readme.write_text(readme.read_text(encoding="utf-8").replace("`crosscal`", "`xcal`"),
                      encoding="utf-8")
    assert docs_tables.stale(tmp_path) == ["README.md"]


@pytest.mark.parametrize("key", list(KINDS))
def test_every_workbench_has_a_user_guide(key):
    guide = ROOT / "docs" / "user-guide" / f"{key}.md"
    assert guide.exists(), f"{key}: write its user guide in docs/user-guide/{key}.md"
    assert f"docs/user-guide/{key}.md" in (ROOT / "README.md").read_text(encoding="utf-8")


def _anchor(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower().replace("`", "")
    kept = "".join(ch for ch in text if ch in " -_" or unicodedata.category(ch)[0] in "LN")
    return kept.replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.DOTALL)
    return {_anchor(h) for h in re.findall(r"^#{1,6} (.+)$", text, flags=re.MULTILINE)}


@pytest.mark.parametrize("doc", DOCS, ids=lambda p: str(p.relative_to(ROOT)))
def test_links_point_at_files_and_headings_that_exist(doc):
    text = re.sub(r"```.*?```", "", doc.read_text(encoding="utf-8"), flags=re.DOTALL)
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target):
            continue  # a web address
        file, _, anchor = target.partition("#")
        linked = (doc.parent / file).resolve() if file else doc
        assert linked.exists(), f"{doc.relative_to(ROOT)}: {target}: no such file"
        if anchor and linked.suffix == ".md":
            assert anchor in _anchors(linked), f"{doc.relative_to(ROOT)}: {target}: no such heading"
