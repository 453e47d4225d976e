"""The registry of workbench kinds, by key (``theodolite``, ``polygon``, ``fringe``)."""

from __future__ import annotations

from models.analysis_kind import AnalysisKind
from models.fringe_analysis import FRINGE
from models.polygon_analysis import POLYGON
from models.theodolite_analysis import THEODOLITE

__all__ = ["KINDS"]


KINDS: dict[str, AnalysisKind] = {k.key: k for k in (THEODOLITE, POLYGON, FRINGE)}
