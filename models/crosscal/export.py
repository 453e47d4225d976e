"""The polygon's face deviations from a cross-calibration, written as the polygon
workbench reads a polygon certificate (``position,deviation_arcsec``; models/polygon/
certificate_reader.py), each with its expanded uncertainty from face 1."""

from __future__ import annotations

import io
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from models.messages import QT_TR_NOOP, message
from models.project.atomic_write import write_text_atomic

if TYPE_CHECKING:
    import numpy as np

    from models.crosscal.analysis import CrossCalResult

__all__ = ["polygon_deviation_rows", "polygon_deviations", "polygon_reference_csv", "write_polygon_reference"]


def polygon_deviations(result: CrossCalResult) -> np.ndarray:
    """The polygon's face deviations d_i (″); ValueError when the design does not
    determine them."""
    d = result.solution.polygon_deviation_arcsec
    if d is None:
        raise ValueError(message(QT_TR_NOOP("the face deviations are not determined by this "
                                            "design: nothing to send")))
    return d


def polygon_deviation_rows(result: CrossCalResult) -> list[list[str]]:
    """The polygon's face deviations as its certificate states them for the polygon
    workbench: position, deviation from face 1 (″) and its expanded U (″), held to the
    laboratory's CMC for face deviations as the certificate's column is."""
    d = polygon_deviations(result)  # ValueError when not determined
    u = result.polygon_u_from_face1_arcsec()
    return [[str(i + 1), f"{d[i] - d[0]:.4f}", f"{u[i]:.4f}"] for i in range(result.faces)]


def polygon_reference_csv(result: CrossCalResult) -> str:
    rows = polygon_deviation_rows(result)  # ValueError when not determined
    s = result.solution
    largest = max(float(r[2]) for r in rows)
    out = io.StringIO()
    out.write("# AngleBench cross-calibration: the polygon's face deviations from face 1 "
              "(for the polygon workbench: Load polygon certificate)\n")
    out.write(f"# U (k = {s.coverage_factor:.2f}) from face 1 up to {largest:.4f} arcsec: "
              "enter it as the polygon standard's U stated from face 1\n")
    if result.cmc_polygon_arcsec > 0:  # (models.crosscal.analysis: CrossCalResult.u_from_first)
        out.write(f"# each U held to the laboratory's CMC for face deviations, "
                  f"{result.cmc_polygon_arcsec:g} arcsec, except at face 1 (zero by definition)"
                  "\n")
    out.write("position,deviation_arcsec,expanded_uncertainty_arcsec\n")
    for row in rows:
        out.write(",".join(row) + "\n")
    return out.getvalue()


def write_polygon_reference(result: CrossCalResult, settings: Mapping[str, Any],
                            path: str | Path) -> str:
    """Write the file (atomically); returns what was written, for the user."""
    write_text_atomic(path, polygon_reference_csv(result))
    return message(QT_TR_NOOP("The polygon's face deviations (from face 1, with U)"))
