"""make new-workbench refuses a key another thing already has (#44): a workbench, an
instrument of capture, a command, a folder of models/ or widgets/; nothing is written."""

from __future__ import annotations

import re

import pytest

from app import new_workbench
from app.capture.instruments import INSTRUMENTS
from app.main import COMMANDS
from models.registry import LOCATIONS


def _tree(root):
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("*")
                  if "__pycache__" not in p.parts and ".venv" not in p.parts)


@pytest.mark.parametrize(("key", "what"), [("theodolite", "a workbench"),
                                           ("crosscal", "a workbench"),
                                           ("autocollimator", "an instrument of capture"),
                                           ("signals", "an instrument of capture"),
                                           ("validate", "a command"),
                                           ("register", "a command"),
                                           ("validation", "a module of models/"),
                                           ("pyramidal", "a module of models/"),
                                           ("error_plot", "a module of widgets/")])
def test_a_taken_key_is_refused_and_nothing_written(key, what):
    before = {p: p.read_bytes() for p in (new_workbench.ROOT / "models" / "registry.py",
                                          new_workbench.ROOT / "docs" / "user-guide" / "index.md",
                                          new_workbench.ROOT / "resources" / "manual" / "index.html")}
    with pytest.raises(SystemExit, match=rf"'{key}' is taken: it is {re.escape(what)}"):
        new_workbench.new_workbench(key, "Title", "标题")
    assert {p: p.read_bytes() for p in before} == before


def test_every_workbench_instrument_and_command_is_taken():
    taken = new_workbench.taken_names()
    assert set(LOCATIONS) | set(INSTRUMENTS) | set(COMMANDS) <= set(taken)
    assert "autocollimator_test" not in taken  # a free key stays free


def test_the_commands_are_those_main_dispatches():
    source = (new_workbench.ROOT / "app" / "main.py").read_text("utf-8")
    assert set(re.findall(r'argv\[0\] == "(\w+)"', source)) == set(COMMANDS)


def test_the_written_workbench_keeps_its_cases_and_draws_through_its_view(tmp_path, monkeypatch):
    """The files written into a copy of the files the generator edits: the validation cases
    in the workbench's own folder (importing only the shared machinery of
    models/validation/cases.py, so no import loop), a presenter that calls view methods and
    the autospec'd-view test of it; every written module compiles."""
    import ast
    import shutil

    root = new_workbench.ROOT
    for rel in ("models/registry.py", "pyproject.toml", "docs/user-guide/index.md",
                "docs/zh_CN/user-guide/index.md", "resources/translations/anglebench_zh_CN.ts"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(root / rel, tmp_path / rel)
    (tmp_path / "widgets").mkdir()
    monkeypatch.setattr(new_workbench, "ROOT", tmp_path)
    written = {p.relative_to(tmp_path).as_posix() for p in new_workbench.new_workbench(
        "tilt_table", "Tilt table", "倾斜台")}
    assert {"models/tilt_table/validation_cases.py",
            "tests/widgets/tilt_table/test_tilt_table_presenter.py"} <= written
    for rel in written:
        if rel.endswith(".py"):
            ast.parse((tmp_path / rel).read_text("utf-8"), rel)
    cases = (tmp_path / "models/tilt_table/validation_cases.py").read_text("utf-8")
    assert "def validation_cases(trials: int)" in cases
    assert "from models.validation.cases import EXACT_SIMULATION, ValidationCase" in cases
    analysis = (tmp_path / "models/tilt_table/analysis.py").read_text("utf-8")
    assert "validation_cases" not in analysis
    # the typed seam (#44): generic over its result, every capability naming it
    assert ("class TiltTable(\n        Workbench[TiltTableResult], OverlaysRuns[TiltTableResult], "
            "ShowsHeadline[TiltTableResult]):") in analysis
    assert "def headline(self, result: TiltTableResult) -> dict[str, float]:" in analysis
    presenter = (tmp_path / "widgets/tilt_table/presenter.py").read_text("utf-8")
    assert not re.search(r"self\.view\.\w+\.", presenter), presenter  # no reaching into the view
    assert "self.view.show_errors(" in presenter
    assert "def show_errors(self, figure)" in (tmp_path / "widgets/tilt_table/view.py").read_text("utf-8")
    test = (tmp_path / "tests/widgets/tilt_table/test_tilt_table_presenter.py").read_text("utf-8")
    assert "mock.create_autospec(TiltTableView, instance=True)" in test
    assert '"tilt_table": "models.tilt_table.analysis:TILT_TABLE"' in (
        tmp_path / "models/registry.py").read_text("utf-8")
    # appended after the last workbench there is (not a fixed one: the test holds for any
    # number of workbenches)
    from models.registry import LOCATIONS

    keys = list(LOCATIONS)
    contracts = (tmp_path / "pyproject.toml").read_text("utf-8")
    assert f'"models.{keys[-1]}", "models.tilt_table"]' in contracts
    assert f'"widgets.{keys[-1]}", "widgets.tilt_table"]' in contracts
    assert '"' + " | ".join([*keys, "tilt_table"]) + '"' in contracts


def test_the_written_workbench_has_its_user_guide_in_both_languages_linked_and_in_the_manual(
        tmp_path, monkeypatch):
    """The user guide in docs/user-guide/ and docs/zh_CN/user-guide/ (the same sections, the
    setting and the plot tab named as each window names them), each linked from its
    language's index.md after the last workbench, and the window's manual pages (the guide's
    and the index's) made from them as `make docs` makes them."""
    import shutil

    from app import manual_pages

    root = new_workbench.ROOT
    for rel in ("models/registry.py", "pyproject.toml", "docs/user-guide/index.md",
                "docs/zh_CN/user-guide/index.md", "resources/translations/anglebench_zh_CN.ts"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(root / rel, tmp_path / rel)
    (tmp_path / "widgets").mkdir()
    monkeypatch.setattr(new_workbench, "ROOT", tmp_path)
    written = {p.relative_to(tmp_path).as_posix() for p in new_workbench.new_workbench(
        "tilt_table", "Tilt table", "倾斜台")}
    assert {"docs/user-guide/tilt_table.md", "docs/zh_CN/user-guide/tilt_table.md",
            "resources/manual/tilt_table.html", "resources/manual/tilt_table.zh_CN.html",
            "resources/manual/index.html", "resources/manual/index.zh_CN.html"} <= written
    en = (tmp_path / "docs/user-guide/tilt_table.md").read_text("utf-8")
    zh = (tmp_path / "docs/zh_CN/user-guide/tilt_table.md").read_text("utf-8")
    assert en.startswith("# Tilt table\n") and zh.startswith("# 倾斜台\n")
    assert "**Zero**" in en and "**Error curves**" in en  # the setting and the plot tab
    assert "**零点**" in zh and "**误差曲线**" in zh
    assert re.findall(r"^#+ ", en, flags=re.MULTILINE) == re.findall(r"^#+ ", zh, flags=re.MULTILINE)
    for folder, title in (("docs/user-guide", "Tilt table"), ("docs/zh_CN/user-guide", "倾斜台")):
        index = (tmp_path / folder / "index.md").read_text("utf-8")
        before = (root / folder / "index.md").read_text("utf-8")
        last = re.findall(r"^\* \[[^\]]+\]\(\w+\.md\).*$", before.split("\n## ")[0],
                          flags=re.MULTILINE)[-1]
        assert f"{last}\n* [{title}](tilt_table.md) — " in index  # after the last workbench
    for name, heading in (("tilt_table.html", "Tilt table"), ("tilt_table.zh_CN.html", "倾斜台")):
        page = (tmp_path / "resources/manual" / name).read_text("utf-8")
        assert f">{heading}</h1>" in page
    assert 'href="tilt_table.html"' in (tmp_path / "resources/manual/index.html").read_text("utf-8")
    assert 'href="tilt_table.zh_CN.html"' in (
        tmp_path / "resources/manual/index.zh_CN.html").read_text("utf-8")
    assert manual_pages.stale(tmp_path) == []  # what `make docs` would make
