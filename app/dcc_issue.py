"""The DCC beside the PDF: built from the certificate as printed and the PDF's own bytes,
validated against the laboratory's schema folder when one is set, refused when invalid.

One function, :func:`render_dcc`, makes the document; the command line and the window call
it with the PDF they issue (or write as a specimen), so the DCC's number and embedded PDF are
the PDF's. When the register renders the DCC itself (``Register.issue``), this is the one
place to wire.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

from models.certificate.document import CertificateDocument
from models.dcc.schema import validate
from models.dcc.writer import DccError, build_dcc
from models.messages import QT_TR_NOOP, message

__all__ = ["DCC_SCHEMA_ENV", "DccError", "DccInvalid", "dcc_schema_dir", "render_dcc"]

#: the environment's schema folder (beside the setting ``dcc_schema_dir`` and --dcc-schema)
DCC_SCHEMA_ENV = "ANGLEBENCH_DCC_SCHEMA"


class DccInvalid(DccError):
    """The DCC fails the schema: not issued; the message names each element and why."""


def dcc_schema_dir(explicit: str = "", configured: str = "") -> str:
    """The schema folder: the option, else the environment, else the setting ("" none)."""
    return (explicit or os.environ.get(DCC_SCHEMA_ENV, "") or configured).strip()


def render_dcc(kind: Any, result: Any, document: CertificateDocument, pdf_bytes: bytes,
               pdf_name: str, schema_dir: str = "",
               settings: Mapping[str, Any] | None = None) -> bytes:
    """The DCC of ``document`` with ``pdf_bytes`` embedded; validated against
    ``schema_dir`` when given (DccInvalid naming the element path and the schema's reason).
    DccError when the certificate lacks what the schema requires. Its budgets are made with
    the ``settings`` ``result`` was analysed with (those the certificate was made with), so
    the DCC's U is the PDF's."""
    try:
        budgets = kind.uncertainty_budgets(result, document.metadata, settings)
    except (ValueError, ArithmeticError, IndexError):  # U not determined: the table's own U
        budgets = {}
    budgets = {**budgets, **kind.dcc_point_uncertainties(result, document.metadata, settings)}
    xml = build_dcc(document, pdf_bytes, pdf_name, budgets,
                    uncertainty_columns=kind.dcc_uncertainty_columns,
                    face_deviations_column=kind.dcc_face_deviations_column,
                    column_notes=kind.dcc_column_notes,
                    reference_face_deviations=kind.dcc_reference_face_deviations(
                        result, document.metadata))
    if schema_dir:
        problems = validate(xml, schema_dir)
        if problems:
            raise DccInvalid(message(QT_TR_NOOP(
                "the DCC fails the schema in {folder} and was not issued: {problems}"),
                folder=schema_dir, problems="; ".join(problems[:5])))
    return xml
