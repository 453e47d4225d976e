"""The registry of workbenches: each is declared once, here, by its analysis kind.

A kind names its readings columns, settings (checked by ``check_settings``),
analysis, JSON, summary, certificate content, sample file and the dotted path
of its presenter. The command line, the project file and the main window are
built from this one list; the window imports the presenters by their path, so
the command line never imports Qt. Adding a workbench: a folder in models/,
one in widgets/, and a line here.
"""

from __future__ import annotations

import importlib
from typing import Any

from models.analysis_kind import AnalysisKind
from models.crosscal.analysis import CROSSCAL
from models.fringe.analysis import FRINGE
from models.polygon.analysis import POLYGON
from models.positioning.analysis import POSITIONING
from models.theodolite.analysis import THEODOLITE

__all__ = ["KINDS", "presenter_class"]


KINDS: dict[str, AnalysisKind] = {k.key: k for k in (THEODOLITE, POLYGON, FRINGE,
                                                           POSITIONING, CROSSCAL)}


def presenter_class(kind: AnalysisKind) -> Any:
    """The presenter class a kind names (imports its widgets module: Qt)."""
    module, _, name = kind.presenter.partition(":")
    return getattr(importlib.import_module(module), name)
