"""The polygon's face deviations from a cross-calibration, written as the polygon
workbench reads a polygon certificate (``position,deviation_arcsec``; models/polygon/
certificate_reader.py), each with its expanded uncertainty from face 1: the U the
cross-calibration's certificate states from face 1 with the same certificate details (the
comparators' stated calibration U in); without details listing a comparator with a stated U,
the header says that U leaves it out."""

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

__all__ = ["COMPARATOR_NOT_STATED", "WITHOUT_COMPARATORS", "comparator_not_stated",
           "comparators_stated", "polygon_deviation_rows",
           "polygon_deviations", "polygon_reference_csv", "write_polygon_reference"]

#: said of a U from face 1 sent or written without the comparators' calibration U (the
#: sent reference's name, the window's message; the file's header in English)
WITHOUT_COMPARATORS = QT_TR_NOOP("without the comparators' calibration U: not stated in the "
                                 "cross-calibration's certificate details")


#: the input a cross-calibration's U lacks where no comparator is listed with a stated U
#: (the certificate's inputs not stated, the JSON's uncertainty_inputs_not_stated): every
#: reading is made with the autocollimator, and its indication error is known only within
#: its certificate's U (models.crosscal.report: its budget row "Comparator calibration"),
#: whether or not a standard is listed (assessment 73 M2: with none listed the row, 69.5 %
#: of U, was dropped without a word and a pass stated on half the U)
COMPARATOR_NOT_STATED = QT_TR_NOOP("Comparator calibration (the autocollimator's: no comparator "
                                   "listed with a stated uncertainty)")


def comparator_not_stated(metadata: Any) -> list[str]:
    """[:data:`COMPARATOR_NOT_STATED`] where the certificate details ``metadata`` list no
    comparator with a stated U and no standard listed without one (which the certificate
    names as not stated itself, by its description: models.certificate.traceability
    .standards_not_stated); else []."""
    if metadata is None or comparators_stated(metadata):
        return []
    if any(std.uncertainty is None for std in metadata.standards):
        return []
    return [COMPARATOR_NOT_STATED]


def comparators_stated(metadata: Any) -> bool:
    """Whether the certificate details ``metadata`` (None: none) list a comparator with a
    stated U: an input of the certificate's U (models.crosscal.report.comparator_u_arcsec),
    without which a U from face 1 leaves the comparators' calibration out."""
    return metadata is not None and any((std.uncertainty_in("arcsec") or 0.0) > 0
                                        for std in metadata.standards)


def polygon_deviations(result: CrossCalResult) -> np.ndarray:
    """The polygon's face deviations d_i (″); ValueError when the design does not
    determine them, or their U is withheld (CrossCalResult.polygon_u_withheld)."""
    d = result.solution.polygon_deviation_arcsec
    if d is None:
        raise ValueError(message(QT_TR_NOOP("the face deviations are not determined by this "
                                            "design: nothing to send")))
    if result.polygon_u_withheld is not None:  # a reference without its U is no reference
        raise ValueError(result.polygon_u_withheld)
    return d


def polygon_deviation_rows(result: CrossCalResult, metadata: Any = None) -> list[list[str]]:
    """The polygon's face deviations as its certificate states them for the polygon
    workbench: position, deviation from face 1 (″) and its expanded U (″), the
    certificate's "U from face 1" column with the certificate details ``metadata`` (the
    comparators' stated U in), held to the laboratory's CMC for face deviations as it is."""
    d = polygon_deviations(result)  # ValueError when not determined
    u = result.polygon_u_from_face1_arcsec(metadata)
    return [[str(i + 1), f"{d[i] - d[0]:.4f}", f"{u[i]:.4f}"] for i in range(result.faces)]


def polygon_reference_csv(result: CrossCalResult, metadata: Any = None) -> str:
    rows = polygon_deviation_rows(result, metadata)  # ValueError when not determined
    s = result.solution
    largest = max(float(r[2]) for r in rows)
    out = io.StringIO()
    out.write("# AngleBench cross-calibration: the polygon's face deviations from face 1 "
              "(for the polygon workbench: Load polygon certificate)\n")
    out.write(f"# U (k = {s.coverage_factor:.2f}) from face 1 up to {largest:.4f} arcsec: "
              "enter it as the polygon standard's U stated from face 1\n")
    if comparators_stated(metadata):
        out.write("# the comparators' stated calibration U included, as on the "
                  "cross-calibration's certificate\n")
    else:  # a U that leaves an input out says so where it is read
        out.write(f"# {WITHOUT_COMPARATORS}\n")
    if result.cmc_polygon_arcsec > 0:  # (models.crosscal.analysis: CrossCalResult.u_from_first)
        out.write(f"# each U held to the laboratory's CMC for face deviations, "
                  f"{result.cmc_polygon_arcsec:g} arcsec, except at face 1 (zero by definition)"
                  "\n")
    out.write("position,deviation_arcsec,expanded_uncertainty_arcsec\n")
    for row in rows:
        out.write(",".join(row) + "\n")
    return out.getvalue()


def write_polygon_reference(result: CrossCalResult, settings: Mapping[str, Any],
                            path: str | Path, metadata: Any = None) -> str:
    """Write the file (atomically) with the certificate details ``metadata`` (None: none);
    returns what was written, for the user."""
    write_text_atomic(path, polygon_reference_csv(result, metadata))
    if comparators_stated(metadata):
        return message(QT_TR_NOOP("The polygon's face deviations (from face 1, with U)"))
    return message(QT_TR_NOOP("The polygon's face deviations (from face 1, with U; {without})"),
                   without=message(WITHOUT_COMPARATORS))
