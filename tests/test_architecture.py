"""The house rules, checked on the code's own imports (an import contract, as napari's
import-linter does): Qt only in widgets/ and app/, models/ free of widgets/ and app/,
no workbench importing another, every workbench complete in the registry."""

from __future__ import annotations

import ast
import inspect
from pathlib import Path

import pytest

from models.registry import KINDS, presenter_class

ROOT = Path(__file__).resolve().parents[1]
QT = ("PySide6", "shiboken6", "pyqtgraph", "PyQt5", "PyQt6")
WORKBENCHES = tuple(KINDS)


def imports(path: Path) -> set[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.add(node.module)
        elif isinstance(node, ast.Import):
            out.update(alias.name for alias in node.names)
    return out


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
    # the validation cases exercise every workbench on purpose; nothing else may reach in
    assert files_touching(kind) == {"models/registry.py", "models/validation/cases.py"}


@pytest.mark.parametrize("key", WORKBENCHES)
def test_every_registered_workbench_is_complete(key):
    from widgets.workbench_presenter import WorkbenchPresenter

    kind = KINDS[key]
    assert kind.key == key and kind.title and kind.columns and kind.parameters
    for part in ("analyze", "to_json", "summary", "certificate"):
        assert callable(getattr(kind, part)), part
    for p in kind.parameters:  # every setting declared whole, its default passing its check
        assert p.label and p.help and p.check(p.default) == p.default, p.key
    assert (ROOT / "resources" / "samples" / kind.sample_file).is_file()
    assert kind.method_reference
    cls = presenter_class(kind)
    assert inspect.isclass(cls) and issubclass(cls, WorkbenchPresenter)
    assert Path(inspect.getfile(cls)).parent.name == key
    assert kind.checked_settings({}) is not None  # the defaults pass their own check


@pytest.mark.parametrize("path", [f"widgets/{k}/presenter.py" for k in WORKBENCHES]
                         + ["widgets/workbench_presenter.py", "app/certificate_presenter.py",
                            "app/register_presenter.py"])
def test_presenters_hold_no_widgets_and_open_no_dialogs(path):
    """A presenter decides and asks its view; it builds no widget, draws nothing itself."""
    bad = {m for m in imports(ROOT / path) if m.startswith(("PySide6.QtWidgets", "pyqtgraph"))}
    assert not bad, f"{path} imports {bad}"
