"""The registry of workbench kinds, by key (``theodolite``, ``polygon``, ``fringe``)."""

from __future__ import annotations

from models.analysis_kind import AnalysisKind
from models.theodolite_analysis import THEODOLITE

__all__ = ["KINDS"]


def _registry() -> dict[str, AnalysisKind]:
    kinds = [THEODOLITE]
    try:
        from models.fringe_analysis import FRINGE
        from models.polygon_analysis import POLYGON
    except ImportError:  # workbenches not built yet
        pass
    else:
        kinds += [POLYGON, FRINGE]
    return {k.key: k for k in kinds}


KINDS: dict[str, AnalysisKind] = _registry()
