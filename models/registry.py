"""The registry of workbenches: each is listed once, here.

A workbench (see :mod:`models.workbench`) names its readings columns, settings,
analysis, JSON, summary, sample file, the dotted path of its presenter and the
capabilities it has (certificates, a correction table, …). The command line, the
project file and the main window are built from this one list; the window imports
the presenters by their path, so the command line never imports Qt. Adding a
workbench: ``make new-workbench NAME=…`` writes a folder in models/, one in widgets/,
a sample, the manual pages and its line here; tests/test_workbench_contract.py says
what else it needs.

Each workbench is named by where its object is (``module:NAME``) and its module is
imported when the workbench is first asked for: ``anglebench analyze theodolite …``
loads the theodolite's models and no other workbench's (the positioning's alone would
bring in scipy.special); ``KINDS.values()`` and ``KINDS.items()`` load them all.
"""

from __future__ import annotations

import importlib
from collections.abc import Iterator, Mapping
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from models.workbench import Workbench

__all__ = ["KINDS", "LOCATIONS", "presenter_class"]


#: each workbench's key and its object's ``module:NAME``, in the order of the window's tabs
LOCATIONS: dict[str, str] = {
    "theodolite": "models.theodolite.analysis:THEODOLITE",
    "polygon": "models.polygon.analysis:POLYGON",
    "fringe": "models.fringe.analysis:FRINGE",
    "positioning": "models.positioning.analysis:POSITIONING",
    "crosscal": "models.crosscal.analysis:CROSSCAL",
}


class Workbenches(Mapping[str, "Workbench[Any]"]):
    """The workbenches by key, each module imported on its first use (keys, ``in`` and
    ``len`` import nothing)."""

    def __init__(self, locations: Mapping[str, str]) -> None:
        self._locations = dict(locations)
        self._loaded: dict[str, Workbench[Any]] = {}

    def __getitem__(self, key: str) -> Workbench[Any]:
        try:
            return self._loaded[key]
        except KeyError:
            pass
        module, _, name = self._locations[key].partition(":")  # KeyError: no such workbench
        workbench = getattr(importlib.import_module(module), name)
        if workbench.key != key:
            raise LookupError(f"models/registry.py lists {module}:{name} as {key!r}, but its "
                              f"key is {workbench.key!r}")
        self._loaded[key] = workbench
        return workbench

    def __contains__(self, key: object) -> bool:
        return key in self._locations

    def __iter__(self) -> Iterator[str]:
        return iter(self._locations)

    def __len__(self) -> int:
        return len(self._locations)

    def __repr__(self) -> str:
        return f"Workbenches({list(self._locations)})"


#: the workbenches in the order of the window's tabs
KINDS: Mapping[str, Workbench[Any]] = Workbenches(LOCATIONS)


def presenter_class(kind: Workbench[Any]) -> Any:
    """The presenter class a workbench names (imports its widgets module: Qt)."""
    module, _, name = kind.presenter.partition(":")
    return getattr(importlib.import_module(module), name)
