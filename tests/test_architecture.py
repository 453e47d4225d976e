"""The house rules, checked on the code's own imports (an import contract, as napari's
import-linter does): Qt only in widgets/ and app/, models/ free of widgets/ and app/,
no workbench importing another, and shared code naming no workbench (it asks the registry
and the capabilities). What each workbench must have: tests/test_workbench_contract.py."""

from __future__ import annotations

import ast
import functools
from pathlib import Path

import pytest

from models.registry import KINDS

ROOT = Path(__file__).resolve().parents[1]
QT = ("PySide6", "shiboken6", "pyqtgraph", "PyQt5", "PyQt6")
WORKBENCHES = tuple(KINDS)


@functools.cache  # each file parsed once a process: the checks below read every file again
def imports(path: Path) -> frozenset[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module)
        elif isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
    if path == ROOT / "models" / "registry.py":  # it imports each workbench by its path, lazily
        from models.registry import LOCATIONS

        out.update(location.partition(":")[0] for location in LOCATIONS.values())
    return frozenset(out)


def python_files(*folders: str) -> list[Path]:
    return [p for folder in folders for p in (ROOT / folder).rglob("*.py")]


@pytest.mark.slow
def test_only_widgets_and_app_import_qt():
    for path in python_files("models", "resources"):
        bad = {m for m in imports(path) if m.split(".")[0] in QT}
        assert not bad, f"{path.relative_to(ROOT)} imports {bad}"


@pytest.mark.slow
def test_models_import_nothing_from_widgets_or_app():
    for path in python_files("models"):
        bad = {m for m in imports(path) if m.split(".")[0] in ("widgets", "app")}
        assert not bad, f"{path.relative_to(ROOT)} imports {bad}"


@pytest.mark.slow
def test_widgets_import_nothing_from_app():
    for path in python_files("widgets"):
        bad = {m for m in imports(path) if m.split(".")[0] == "app"}
        assert not bad, f"{path.relative_to(ROOT)} imports {bad}"


@pytest.mark.parametrize("kind", WORKBENCHES)
@pytest.mark.slow
def test_no_workbench_imports_another(kind):
    others = [k for k in WORKBENCHES if k != kind]
    for path in python_files(f"models/{kind}", f"widgets/{kind}"):
        bad = {m for m in imports(path)
               if any(m.startswith((f"models.{o}", f"widgets.{o}")) for o in others)}
        assert not bad, f"{path.relative_to(ROOT)} imports {bad}"


def files_touching(kind: str) -> set[str]:
    """Every source file outside the workbench's two folders that imports from them."""
    own = (f"models.{kind}", f"widgets.{kind}")
    found = set()
    for path in python_files("app", "models", "widgets"):
        rel = path.relative_to(ROOT).as_posix()
        if rel.startswith((f"models/{kind}/", f"widgets/{kind}/")):
            continue
        if any(m.startswith(own) for m in imports(path)):
            found.add(rel)
    return found


@pytest.mark.slow
@pytest.mark.parametrize("kind", WORKBENCHES)
def test_a_workbench_is_its_two_folders_and_one_registry_line(kind):
    # every workbench keeps its validation cases in its folder (models/<kind>/
    # validation_cases.py, gathered by the registry's name); nothing else may reach in
    touching = files_touching(kind)
    assert "models/registry.py" in touching
    # the shared validation studies of #39 (the decided quantity's coverage through the first
    # three workbenches, the degenerate designs) are validation cases of the same kind
    # (its own reference cases are in its folder, models/<kind>/validation_cases.py, #44)
    assert touching <= {"models/registry.py",
                        "models/validation/half_range.py", "models/validation/degenerate.py"}, touching


@pytest.mark.parametrize("path", [f"widgets/{k}/presenter.py" for k in WORKBENCHES]
                         + ["widgets/workbench_presenter.py", "app/certificate_presenter.py",
                            "app/register_presenter.py", "app/project_presenter.py"])
def test_presenters_hold_no_widgets_and_open_no_dialogs(path):
    """A presenter decides and asks its view; it builds no widget, draws nothing itself."""
    bad = {m for m in imports(ROOT / path) if m.startswith(("PySide6.QtWidgets", "pyqtgraph"))}
    assert not bad, f"{path} imports {bad}"


#: shared code that names workbenches on purpose, and why
NAMES_WORKBENCHES_ON_PURPOSE = {
    "models/validation/": "the validation cases exercise each workbench by its own rig",
    "app/validation_report.py": "the report's end-to-end cases run chosen workbenches' samples",
    "app/capture/": "'theodolite' there is an instrument (Leica GeoCOM), not the workbench",
    "models/pyramidal.py": "'polygon' there is a frame (the polygon's own axis, seed 001's "
                           "ac_alignment), not the workbench",
    "models/crosscal/": "the same frame name (a workbench folder once crosscal is registered)",
}


def shared_files() -> list[Path]:
    """Every source file outside the workbenches' own folders and the registry."""
    own = tuple(f"{top}/{key}/" for key in WORKBENCHES for top in ("models", "widgets"))
    return [path for path in python_files("app", "models", "widgets")
            if not path.relative_to(ROOT).as_posix().startswith(
                own + tuple(NAMES_WORKBENCHES_ON_PURPOSE))
            and path.relative_to(ROOT).as_posix() != "models/registry.py"]


@pytest.mark.slow
def test_shared_code_names_no_workbench():
    """Shared code finds a workbench through the registry and its capabilities
    (models/workbench.py), never by its key: a fifth workbench needs no edit there."""
    found = []
    for path in shared_files():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Constant) and node.value in WORKBENCHES:
                found.append(f"{path.relative_to(ROOT)}:{node.lineno} {node.value!r}")
    assert not found, ("shared code names a workbench by its key; ask the registry "
                       "(models.registry.KINDS) or a capability (models.workbench) instead:\n"
                       + "\n".join(found))


@pytest.mark.slow
def test_workbenches_are_told_apart_by_capability():
    """No shared code tests a workbench's key (``kind.key == …``) or one of its own
    methods' presence (``kind.x is None``): it asks ``isinstance(kind, Capability)``."""
    found = []
    for path in shared_files():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Compare) and any(
                    isinstance(side, ast.Attribute) and side.attr == "key"
                    and isinstance(other, ast.Constant) and isinstance(other.value, str)
                    for side, other in ((node.left, node.comparators[0]),
                                        (node.comparators[0], node.left))):
                found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    assert not found, "a key compared with a literal:\n" + "\n".join(found)
