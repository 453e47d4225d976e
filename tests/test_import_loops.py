"""No import loops in models/ (#44), measured on the import graph grimp builds from the code:
every import counts, those inside functions too; only those under ``if TYPE_CHECKING:``
(which never run) are left out. Checked at two grains: modules, and the units the layers of
pyproject.toml's import-linter contracts are made of (each package of models/ is one unit,
except models/validation, whose modules are the shared machinery below the workbenches and
the cross-workbench studies above them, each its own unit)."""

from __future__ import annotations

import grimp
import pytest


@pytest.fixture(scope="module")
def graph():
    return grimp.build_graph("models", include_external_packages=False,
                             exclude_type_checking_imports=True)


def unit(module: str) -> str:
    """The layer unit of a module: models.X (a package or a top-level module), or the module
    itself inside models.validation."""
    parts = module.split(".")
    return module if parts[:2] == ["models", "validation"] and len(parts) > 2 else ".".join(parts[:2])


def loops(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one node (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []
    for root in sorted(edges):
        if root in index:
            continue
        work = [(root, iter(sorted(edges.get(root, ()))))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, children = work[-1]
            for child in children:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(edges.get(child, ())))))
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return found


def test_the_loop_finder_finds_a_loop():
    assert loops({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert loops({"a": {"b"}, "b": {"c"}, "c": set()}) == []


def test_the_graph_sees_imports_inside_functions(graph):
    # models.validation.run imports the cross-workbench studies inside run_validation
    assert "models.validation.half_range" in graph.find_modules_directly_imported_by(
        "models.validation.run")


def _why(graph, component: list[str]) -> list[str]:
    return [f"{a} -> {b} (line {d['line_number']}: {d['line_contents']})"
            for a in component for b in component
            for d in graph.get_import_details(importer=a, imported=b)]


def test_no_import_loop_between_modules_of_models(graph):
    edges = {m: set(graph.find_modules_directly_imported_by(m)) for m in graph.modules}
    found = loops(edges)
    assert not found, "\n".join(line for c in found for line in _why(graph, c))


def test_no_import_loop_between_the_layer_units_of_models(graph):
    edges: dict[str, set[str]] = {}
    for module in graph.modules:
        for imported in graph.find_modules_directly_imported_by(module):
            if unit(module) != unit(imported):
                edges.setdefault(unit(module), set()).add(unit(imported))
    found = loops(edges)
    detail = [f"{m} -> {i}" for c in found for m in graph.modules if unit(m) in c
              for i in graph.find_modules_directly_imported_by(m)
              if unit(i) in c and unit(i) != unit(m)]
    assert not found, f"{found}\n" + "\n".join(sorted(detail))


def test_every_workbench_is_in_the_import_contracts():
    """A workbench left out of pyproject's import-linter contracts would escape them."""
    from pathlib import Path

    from models.registry import LOCATIONS

    tomllib = pytest.importorskip("tomllib")  # Python 3.11 on
    config = tomllib.loads((Path(__file__).resolve().parents[1] / "pyproject.toml").read_text("utf-8"))
    contracts = {c["name"]: c for c in config["tool"]["importlinter"]["contracts"]}
    models = contracts["the workbenches' models are independent of each other"]["modules"]
    views = contracts["the workbenches' views are independent of each other"]["modules"]
    layers = " | ".join(contracts["models/: the cross-workbench code above the workbenches above "
                                 "the shared code"]["layers"])
    for key in LOCATIONS:
        assert f"models.{key}" in models and f"widgets.{key}" in views, (
            f"{key}: add models.{key} and widgets.{key} to the independence contracts of "
            "pyproject.toml [tool.importlinter]")
        assert f"| {key}" in layers or f"{key} |" in layers, (
            f"{key}: add it to the workbenches' layer of pyproject.toml's models/ contract")
