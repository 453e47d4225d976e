"""The reference standards and what the results are traceable through (or plainly what they
are not)."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.wording import _between, _listed, _translatable, label
from models.certificate.document import CertificateDocument, Table
from models.certificate.metadata import APPLIES_TO_NAMES, ReferenceStandard
from models.messages import QT_TR_NOOP, joined, message, separated, typed_name
from models.quantity import UNITS, Quantity
from models.uncertainty.budget import BASIS_DIVISORS
from models.uncertainty.printed_figure import printed


def draw_traceability(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, "Reference standards and traceability"))
    # a stated uncertainty's basis in both on a bilingual certificate (zh81), a lab's own
    # words once
    pdf.data_table(_standards_table(document), (50, 26, 34, 42, 22), ("LEFT",) * 5,
                   rows_in_both=True, report=document.is_test_report)
    # in Chinese, then in English on a bilingual certificate (assessment 76 L1: English only)
    pdf.paragraph_in_both(_traceability(document), 8.5)


def _standards_table(document: CertificateDocument) -> Table:
    rows = []
    for s in document.metadata.standards:
        u = "—" if s.uncertainty is None else _stated_uncertainty(s, document.reading_name)
        if s.uncertainty is None and s.certificate_no and document.stated_inputs:
            u = message(QT_TR_NOOP("as stated in the settings: {inputs}"),
                        inputs=joined(_between(", ", document.stated_inputs)))
        name = s.description or "—"
        # no reference standard: a comparator, said once (assessment 78 L7: "Photoelectric
        # autocollimator (comparator) (comparator)" where the description already says so)
        if document.traceability_basis and not name.rstrip().casefold().endswith("(comparator)"):
            name = message(QT_TR_NOOP("{standard} (comparator)"), standard=name)
        rows.append((name, s.serial or "—", s.certificate_no or "—", u, s.due_date or "—"))
    if not rows:
        rows.append((QT_TR_NOOP("not stated"), "", "", "", ""))
    return Table(QT_TR_NOOP("Reference standards"), (
        QT_TR_NOOP("Standard"), QT_TR_NOOP("Serial no."), QT_TR_NOOP("Certificate no."),
        QT_TR_NOOP("Uncertainty"), QT_TR_NOOP("Calibration due")), rows)



def _stated_uncertainty(s: ReferenceStandard, reading_name: str = APPLIES_TO_NAMES["reading"]):
    """A standard's figure as its certificate states it: as typed, with its basis and what it
    is stated per (a reading, an angle between two readings, a face from face 1: day review
    69 F2, the budget takes u/√2 a reading of one stated per angle); read from its DCC (its
    k known), U with that k to two significant digits (GUM 7.2.6), not the every digit of
    the U/k the budget takes. A reading is called ``reading_name``, the budget's word (the
    fringe's "sample")."""
    per = message(reading_name if s.applies_to == "reading" else
                  APPLIES_TO_NAMES.get(s.applies_to, s.applies_to))
    if s.coverage_factor is None:
        return message("{u} ({basis})", u=Quantity(s.uncertainty, s.uncertainty_unit),
                       basis=message(QT_TR_NOOP("{basis} per {per}"), per=per,
                                     basis=message(BASIS_DIVISORS[s.basis][0])))
    k = s.coverage_factor
    expanded = s.uncertainty * (k if s.basis == "u" else 1.0)
    return message("{u} ({basis})",
                   u=printed(expanded, UNITS[s.uncertainty_unit].written(), rounding="up"),
                   basis=message(QT_TR_NOOP("{basis} per {per}"), per=per,
                                 basis=message(QT_TR_NOOP("expanded uncertainty U (k = {k})"),
                                               k=f"{k:.2f}")))


def _traceability(document: CertificateDocument) -> str:
    """What the results are traceable through, and plainly what they are not: a standard
    with no stated uncertainty is no input of the budget, and an input of the result with
    none (document.untraceable) leaves the result untraceable, with no conformity on it."""
    standards = document.metadata.standards
    stated = document.stated_inputs
    listed = [s for s in standards if s.certificate_no and (s.uncertainty is not None
                                                             or stated)]
    names = joined(_between("; ", (
        message(QT_TR_NOOP("{standard} (certificate {certificate})"),
                standard=typed_name(s.description) or message(QT_TR_NOOP("standard")),
                certificate=s.certificate_no) if s.uncertainty is not None else
        message(QT_TR_NOOP("{standard} (certificate {certificate}; its figures enter as the "
                           "inputs stated in the settings: {inputs})"),
                standard=typed_name(s.description) or message(QT_TR_NOOP("standard")),
                certificate=s.certificate_no, inputs=joined(_between(", ", stated)))
        for s in listed)))
    if document.untraceable:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established for these "
                                    "results — {what}; no statement of conformity rests on "
                                    "them."),
                         what=joined(_between("; ", document.untraceable)))]
        if listed:
            parts += [message(QT_TR_NOOP("The standards listed with a certificate and a "
                                              "stated uncertainty: {names}."), names=names)]
    elif document.traceability_gaps:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established for these "
                                    "results — {what}."),
                         what=joined(_between("; ", document.traceability_gaps)))]
        if listed:
            parts += [message(QT_TR_NOOP("The standards listed with a certificate and a "
                                              "stated uncertainty: {names}."), names=names)]
    elif document.traceability_basis:  # a self-calibrating method: its own reference
        parts = [_translatable(document.traceability_basis)]
        if standards:  # no reference value comes from them
            parts += [message(QT_TR_NOOP("The instruments listed are comparators only; "
                                              "their calibration enters the uncertainty, not "
                                              "the reference: {names}."),
                                   names=_listed(typed_name(s.description)
                                                 or message(QT_TR_NOOP("standard"))
                                                 for s in standards))]
    elif not listed:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established on this "
                                    "document — no reference standard with a calibration "
                                    "certificate and a stated uncertainty is listed."))]
    else:
        parts = [message(QT_TR_NOOP("Metrological traceability: the results are traceable to "
                                    "the SI unit of plane angle through the reference standards "
                                    "listed, calibrated as stated in their certificates: "
                                    "{names}."), names=names)]
    for s in standards:
        if s.uncertainty is None and not (stated and s.certificate_no):
            parts += [message(QT_TR_NOOP("{standard}: no uncertainty stated, so it is no "
                                              "input of the budget and the results are not "
                                              "traceable through it."),
                                   standard=(typed_name(s.description)
                                             or message(QT_TR_NOOP("standard"))))]
    return separated(parts, " ")  # sentence after sentence
