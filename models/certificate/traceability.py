"""Whether a certificate may state metrological traceability, and when it is a test report.

A calibration certificate states traceability to the SI only where every standard that
carries the measurand is listed with its calibration certificate and a stated uncertainty
(ISO/IEC 17025 6.5, 7.8.4.1; ILAC-P14). Otherwise the document is a test report and its
title and statements say so, naming what is missing.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from models.messages import QT_TR_NOOP, message, separated

if TYPE_CHECKING:  # the details' module is loaded by whoever hands them (not a plain analyze)
    from models.certificate.metadata import CertificateMetadata

__all__ = ["expired_standards", "expired_withheld", "test_report_statement", "traceability_gaps"]


def expired_standards(metadata: CertificateMetadata) -> list:
    """The standards listed whose calibration was due before the date of calibration (their
    due date stated): the U their certificates state no longer holds for this calibration."""
    if not metadata.calibration_date:
        return []
    return [s for s in metadata.standards
            if s.due_date and s.due_date < metadata.calibration_date]


def expired_withheld(metadata: CertificateMetadata):
    """Why no statement of conformity may be made with the standards listed ("" when it may):
    a standard whose calibration had expired leaves the U of every result it carries
    without a basis (ILAC-G8:09/2019 4.2: a decision rests on the measurement uncertainty;
    ISO/IEC 17025 6.4.7, 7.8.6.1), so the decision is withheld as when U is incomplete."""
    expired = expired_standards(metadata)
    if not expired:
        return ""
    names = separated((message(QT_TR_NOOP("{standard} (due {due})"),
                               standard=s.description or message(QT_TR_NOOP("standard")),
                               due=s.due_date) for s in expired), "; ")
    return message(QT_TR_NOOP("the calibration of a standard had expired before the date of "
                              "calibration, so the uncertainty it states does not hold: {names}"),
                   names=names)


def traceability_gaps(metadata: CertificateMetadata, roles: tuple[str, ...],
                      stated_inputs: tuple[str, ...] = ()) -> list[str]:
    """Why the standards listed do not make the results traceable (empty: they do, or none is
    listed yet — a draft, which says so). ``roles``: the standards that carry the measurand
    (QT_TR_NOOP texts, e.g. the polygon and the autocollimator); each needs a standard listed
    with a calibration certificate and a stated U — a U in the table, or, for one standard
    listed with its certificate and no U, the inputs stated in the settings (the ADC's
    figures). Every standard listed needs both, or the results are not traceable through it;
    and a standard whose calibration was due before the date of calibration (its due date
    stated) had expired: the results are not traceable through it either (the same rule as
    a missing certificate: the document is a test report naming it)."""
    standards = metadata.standards
    if not standards:
        return []
    gaps: list[str] = []
    with_u = [s for s in standards if s.certificate_no and s.uncertainty is not None]
    by_settings = [s for s in standards if s.certificate_no and s.uncertainty is None
                   and stated_inputs]
    # the inputs stated in the settings, by the standard they come from ("Phase reference",
    # "ADC offset", "ADC gain ratio" …: two standards), one listed standard each at most
    families = {str(name).split()[0] for name in stated_inputs if str(name).strip()}
    carried = len(with_u) + min(len(by_settings), len(families))
    if carried < len(roles):
        # a list of none is not printed as "0 listed so" (day review 69 F6)
        gaps.append(message(QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; {count} listed so")
            if carried else QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; none of them is listed so"),
            roles=separated((message(r) for r in roles), "; "), count=carried))
    expired = expired_standards(metadata)
    for std in standards:
        name = std.description or message(QT_TR_NOOP("standard"))
        if std in expired:
            gaps.append(message(QT_TR_NOOP(
                "{standard}: its calibration was due on {due}, before the date of calibration "
                "{date}: it had expired"), standard=name, due=std.due_date,
                date=metadata.calibration_date))
        if std.uncertainty is None and not (stated_inputs and std.certificate_no):
            gaps.append(message(QT_TR_NOOP("{standard} has no stated uncertainty"), standard=name))
        elif not std.certificate_no:
            gaps.append(message(QT_TR_NOOP("{standard} has no calibration certificate stated"),
                                standard=name))
    return gaps


def test_report_statement(document) -> str:
    """Why a document asked for as a calibration certificate is a test report ("" when it is
    not, or was asked for as one)."""
    if document.metadata.document_type == "test" or not document.is_test_report:
        return ""
    why = list(document.untraceable) + list(document.traceability_gaps)
    return message(QT_TR_NOOP(
        "This document is a test report, not a calibration certificate: metrological "
        "traceability of its results is not established ({why})."),
        why=separated(why, "; "))
