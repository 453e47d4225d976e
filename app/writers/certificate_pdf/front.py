"""The certificate's front: its title, a DRAFT, SPECIMEN or revision notice, and the details
of the certificate, the laboratory, the customer, the item and the calibration."""

from __future__ import annotations

import datetime as dt

from fpdf.enums import XPos, YPos

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.fonts import FONT
from app.writers.certificate_pdf.wording import _between, _colon, _in_both, _listed, label
from models.certificate.document import CertificateDocument
from models.certificate.metadata import (
    PLACES,
    readings_of_another_item_statement,
    revision_statement,
    separate_statement,
    withdrawn_statement,
)
from models.messages import QT_TR_NOOP, joined, message
from models.uncertainty.printed_figure import tolerance_figure


def draw_front(pdf: _CertificatePdf, document: CertificateDocument, created: dt.datetime) -> None:
    meta = document.metadata
    pdf.set_font(FONT, "B", 17)
    pdf.cell(0, 9, label(document, document.title), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    pdf.set_font(FONT, "", 11)
    # the workbench's title in both languages on a bilingual certificate, as the title above
    # (assessment 78 L9: "校准证书 Calibration certificate" over English alone)
    pdf.cell(0, 6, " ".join(pdf.say(part) for part in _in_both(document, document.kind_title)),
             new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    if document.specimen:
        pdf.paragraph(message(QT_TR_NOOP(
            "SPECIMEN — made from example details for training or demonstration; not a "
            "certificate, not recorded in any register.")), 9, (170, 30, 30))
    elif document.is_draft:
        # a test report's banner names its own number, "report number", as the page beside
        # it does (assessment 73 L2: "Missing: certificate number" beside "Report number")
        report = document.is_test_report
        pdf.paragraph(message(QT_TR_NOOP("DRAFT — not valid as a test report. Missing: "
                                         "{fields}.") if report else
                              QT_TR_NOOP("DRAFT — not valid as a certificate. Missing: "
                                         "{fields}."),
                              fields=_listed(meta.missing_fields(report))),
                      9, (170, 30, 30))
    if meta.supersedes:
        pdf.paragraph(revision_statement(meta), 9.5, (20, 60, 140))
    elif meta.separate_from:
        pdf.paragraph(separate_statement(meta), 9.5, (20, 60, 140))
    if meta.replaces_withdrawn:  # a withdrawn certificate of this calibration (hostile78 F3)
        pdf.paragraph(withdrawn_statement(meta), 9.5, (20, 60, 140))
    if meta.readings_of_another_item:  # another item's readings, said why (hostile78 F7)
        pdf.paragraph(readings_of_another_item_statement(meta), 9.5, (20, 60, 140))
    pdf.ln(1)
    pdf.key_values([
        (label(document, "Certificate number", "\n"), meta.certificate_number),
        (label(document, "Date of issue", "\n"), meta.issue_date or created.date().isoformat()),
        (label(document, "Laboratory", "\n"),
         ", ".join(p for p in (meta.lab_name, meta.lab_address) if p)),
        (label(document, "Accreditation", "\n"), meta.lab_accreditation),
        (label(document, "Customer", "\n"),
         ", ".join(p for p in (meta.customer_name, meta.customer_address) if p)),
        (label(document, "Item calibrated", "\n"), meta.item_description),
        (label(document, "Manufacturer", "\n"), meta.item_manufacturer),
        (label(document, "Model", "\n"), meta.item_model),
        (label(document, "Serial number", "\n"), meta.item_serial),
        # the program's words of a value (the tolerance, the place, the environment) in
        # Chinese, then in English on a bilingual certificate, as its label (zh81)
        (label(document, "Grade / specification", "\n"), _both_lines(document, joined(_between(
            "; ", [meta.item_grade, message(QT_TR_NOOP("tolerance ±{tolerance}"),
                                            tolerance=tolerance_figure(document.tolerance,
                                                                       document.unit))
                   if document.tolerance else ""])))),
        (label(document, "Date of calibration", "\n"), meta.calibration_date),
        (label(document, "Place of calibration", "\n"),
         _both_lines(document, _place(meta, _colon(document)))),
        (label(document, "Environment", "\n"), _both_lines(document, _environment(meta))),
        # on a bilingual certificate in Chinese, then in English, as every line of the
        # heading (day review 68 F12: English only under "原始记录 Readings")
        (label(document, "Readings", "\n"),
         joined(_between("\n", _in_both(document, document.source_name)))),
        *([(label(document, "Instrument output", "\n"),
            f"SHA-256 {document.raw_data_sha256}")] if document.raw_data_sha256 else []),
        # edits, cleared and deleted readings, rows captured again (review 62 F1: a row taken
        # again stood under "Edited after capture"), readings that cannot be checked
        # on a bilingual certificate each in Chinese, then in English (rev62day F14: English
        # only under the two-language heading)
        *([(label(document, "Changes after capture", "\n"),
            joined(_between("\n", [line for edit in document.edited_readings
                                    for line in _in_both(document, edit)])))]
          if document.edited_readings else []),
    ])


def _both_lines(document: CertificateDocument, text) -> str:
    """``text`` as a details value: on a bilingual certificate its Chinese line above its
    English (once where it has no Chinese: a lab's own words)."""
    return joined(_between("\n", _in_both(document, text))) if text else text


def _created(document: CertificateDocument) -> dt.datetime:
    meta = document.metadata
    if meta.created:
        try:
            stamp = dt.datetime.fromisoformat(meta.created)
        except ValueError:
            stamp = None
        if stamp is not None:
            return stamp if stamp.tzinfo else stamp.replace(tzinfo=dt.timezone.utc)
    if meta.issue_date:
        return dt.datetime.fromisoformat(meta.issue_date).replace(tzinfo=dt.timezone.utc)
    return dt.datetime.now(dt.timezone.utc).replace(microsecond=0)


def _place(meta, colon: str = ": ") -> str:
    """Where it was calibrated: at the laboratory, or at the customer's site (and where)."""
    place = message(PLACES.get(meta.calibration_place, PLACES["laboratory"]))
    return joined([place, colon, meta.calibration_site]) if meta.calibration_site else place


def _environment(meta) -> str:
    parts = []
    if meta.temperature_c is not None:
        parts.append(message(QT_TR_NOOP("temperature {t} °C"), t=f"{meta.temperature_c:.1f}"))
    if meta.humidity_pct is not None:
        parts.append(message(QT_TR_NOOP("relative humidity {h} %"),
                             h=f"{meta.humidity_pct:.0f}"))
    return joined(_between(", ", parts))
