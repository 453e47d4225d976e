"""The registry of workbenches: each is listed once, here.

A workbench (see :mod:`models.workbench`) names its readings columns, settings,
analysis, JSON, summary, sample file, the dotted path of its presenter and the
capabilities it has (certificates, a correction table, …). The command line, the
project file and the main window are built from this one list; the window imports
the presenters by their path, so the command line never imports Qt. Adding a
workbench: ``make new-workbench NAME=…`` writes a folder in models/, one in widgets/,
a sample, the manual pages and its line here; tests/test_workbench_contract.py says
what else it needs.
"""

from __future__ import annotations

import importlib
from typing import Any

from models.fringe.analysis import FRINGE
from models.polygon.analysis import POLYGON
from models.positioning.analysis import POSITIONING
from models.theodolite.analysis import THEODOLITE
from models.workbench import Workbench

__all__ = ["KINDS", "presenter_class"]


#: the workbenches in the order of the window's tabs
KINDS: dict[str, Workbench] = {k.key: k for k in (
    THEODOLITE,
    POLYGON,
    FRINGE,
    POSITIONING,
)}


def presenter_class(kind: Workbench) -> Any:
    """The presenter class a workbench names (imports its widgets module: Qt)."""
    module, _, name = kind.presenter.partition(":")
    return getattr(importlib.import_module(module), name)
