"""Whether a certificate may state metrological traceability, and when it is a test report.

A calibration certificate states traceability to the SI only where every standard that
carries the measurand is listed with its calibration certificate and a stated uncertainty
(ISO/IEC 17025 6.5, 7.8.4.1; ILAC-P14). Otherwise the document is a test report and its
title and statements say so, naming what is missing.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from models.messages import QT_TR_NOOP, listed, message, separated, typed_name

if TYPE_CHECKING:  # the details' module is loaded by whoever hands them (not a plain analyze)
    from models.certificate.metadata import CertificateMetadata

#: the role of a standard that stands behind inputs stated in the settings, by the first word
#: of their budget names (the fringe's "Phase reference", "ADC offset" …)
_FAMILY_ROLES = {"Phase": "reference", "ADC": "adc"}

__all__ = ["expired_standards", "expired_withheld", "standards_not_stated", "test_report_statement",
           "traceability_gaps", "traceability_withheld"]


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
                               standard=(typed_name(s.description)
                                         or message(QT_TR_NOOP("standard"))),
                               due=s.due_date) for s in expired), "; ")
    return message(QT_TR_NOOP("the calibration of a standard had expired before the date of "
                              "calibration, so the uncertainty it states does not hold: {names}"),
                   names=names)


def standards_not_stated(metadata: CertificateMetadata, stated_inputs: tuple[str, ...] = ()
                         ) -> list[str]:
    """The standards listed with no stated uncertainty (their descriptions): inputs of every
    result they take part in whose uncertainty is not stated, so not in U — the readings'
    scatter cannot stand in for a standard's calibration (GUM 7.2.7; ILAC-P14). A standard
    listed with its certificate and no U in the table while inputs are stated in the settings
    (the fringe's ADC figures, ``stated_inputs``) stands behind those inputs: it is not one
    (the same rule as :func:`traceability_gaps`' "has no stated uncertainty")."""
    return [typed_name(s.description) or QT_TR_NOOP("standard") for s in metadata.standards
            if s.uncertainty is None and not (stated_inputs and s.certificate_no)]


def traceability_withheld(metadata: CertificateMetadata, roles: tuple[tuple[str, str], ...],
                          stated_inputs: tuple[str, ...] = (),
                          roles_stated_only: tuple[str, ...] = ()) -> str:
    """Why no statement of conformity may be made while traceability is not established
    ("" when it is): a decision rule rests on the result's uncertainty (ISO/IEC 17025 7.1.3,
    7.8.6.1; ILAC-G8:09/2019), and a result not traceable to the reference has no U that
    relates it to the specification. With no standard listed at all and ``roles`` named, U
    holds no standard's calibration, whatever inputs are typed in the settings: no statement
    either (audit 71 finding 2; the cross-calibration names no roles and keeps its verdicts). An expired
    standard is left to :func:`expired_withheld` (its own reason). ``roles_stated_only``:
    as :func:`traceability_gaps`."""
    gaps = _gaps(metadata, roles, stated_inputs, expired=False,
                 roles_stated_only=roles_stated_only)
    if not gaps:
        return ""
    return message(QT_TR_NOOP("metrological traceability of the results is not established: "
                              "{gaps}"), gaps=separated(gaps, "; "))


def traceability_gaps(metadata: CertificateMetadata, roles: tuple[tuple[str, str], ...],
                      stated_inputs: tuple[str, ...] = (),
                      roles_stated_only: tuple[str, ...] = ()) -> list[str]:
    """Why the standards listed do not make the results traceable (empty: they do; none
    listed where ``roles`` are named is a gap too: assessment 72 M3). ``roles``: the
    standards that carry the measurand, each (its role, its name: a QT_TR_NOOP text, e.g.
    ("reference", the polygon) and ("autocollimator", the autocollimator)); each needs a
    standard listed with a calibration certificate and a stated U — a U in the table, or,
    for one standard listed with its certificate and no U, the inputs stated in the settings
    (the ADC's figures); a role not filled is named where the standards' roles are stated
    or told (:func:`_told_role`). Every standard listed needs both, or the results are not
    traceable through it;
    and a standard whose calibration was due before the date of calibration (its due date
    stated) had expired: the results are not traceable through it either (the same rule as
    a missing certificate: the document is a test report naming it).

    ``roles_stated_only``: the roles only a standard stating its role carries (the fringe's
    phase or angle reference: a standard listed with a U and no role may be another
    instrument's certificate, such as the ADC's, and was taken as the phase reference, the
    document a traceable calibration certificate: assessment 78 H1); one whose role is not
    told fills none of them, and the reason names the role to state."""
    return _gaps(metadata, roles, stated_inputs, expired=True,
                 roles_stated_only=roles_stated_only)


def _told_role(standard, roles: dict[str, str], families: set[str]) -> str:
    """The role a standard listed without one carries, where its other fields tell it (""
    where they do not): the only one the measurand has; the polygon's for one whose figure
    applies to each face's deviation from face 1 (a polygon's certificate); for one listed
    with its certificate and no U behind inputs stated in the settings, the role of those
    inputs where they are one standard's (the ADC's figures alone, or the phase reference's)."""
    if len(roles) == 1:
        return next(iter(roles))
    if standard.applies_to == "from face 1" and "reference" in roles:
        return "reference"
    if standard.uncertainty is None and len(families) == 1:
        return _FAMILY_ROLES.get(next(iter(families)), "")
    return ""


def _names(standards) -> object:
    """The standards' descriptions as a list ("standard" for one without)."""
    return listed(typed_name(s.description) or message(QT_TR_NOOP("standard"))
                  for s in standards)


#: a role only a standard stating it carries, not filled by a standard of no role stated
#: (:func:`traceability_gaps`' ``roles_stated_only``): what is missing and the role to state
ROLE_TO_STATE = QT_TR_NOOP(
    "the standards that carry the measurand are {roles}, each to be listed with a calibration "
    "certificate and a stated uncertainty; {count} listed so ({listed}): none is listed for "
    "{missing}, as no role is stated for {unnamed} and only a standard whose role says so is "
    "taken as {missing} (one with no role may be another instrument's, such as the ADC's): "
    "state the role {role} of the one that is")


def _gaps(metadata: CertificateMetadata, roles: tuple[tuple[str, str], ...],
          stated_inputs: tuple[str, ...], expired: bool,
          roles_stated_only: tuple[str, ...] = ()) -> list[str]:
    """:func:`traceability_gaps`, an expired standard among them or not (``expired``)."""
    standards = metadata.standards
    if not standards:
        # none listed and ``roles`` named: U holds no standard's calibration, whatever inputs
        # are typed in the settings (audit 71 finding 2), and the document is a test report,
        # a draft or a specimen too (assessment 72 M3: titled a calibration certificate while
        # it said traceability was not established); the cross-calibration names no roles
        return [] if not roles else [message(QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; none is listed, so the "
            "uncertainty holds no standard's calibration"),
            roles=separated((message(name) for _, name in roles), "; "))]
    gaps: list[str] = []
    with_u = [s for s in standards if s.certificate_no and s.uncertainty is not None]
    by_settings = [s for s in standards if s.certificate_no and s.uncertainty is None
                   and stated_inputs]
    # the inputs stated in the settings, by the standard they come from ("Phase reference",
    # "ADC offset", "ADC gain ratio" …: two standards), one listed standard each at most
    families = {str(name).split()[0] for name in stated_inputs if str(name).strip()}
    counted = with_u + by_settings[:len(families)]
    names = dict(roles)
    # each counted standard by the role it carries: stated, or told by its other fields;
    # one whose role is not told fills a role no standard of a known role fills (as every
    # standard did until 0.8.21: files without roles are judged as they were)
    known: dict[str, object] = {}
    unknown = []
    for std in counted:
        role = std.role or _told_role(std, names, families)
        if role in names:
            known.setdefault(role, std)
        elif not role:
            unknown.append(std)
        # a role this measurand does not use (an autocollimator listed for a fringe): it
        # carries none of its standards
    free = [role for role in names if role not in known]
    listed_ones = [*known.values(), *unknown]
    # a role only a standard stating it carries (the fringe's phase or angle reference): a
    # standard of no role stated does not fill it (assessment 78 H1); said, with the role to
    # state, and the other roles judged as before
    to_state = [role for role in free if role in roles_stated_only] if unknown else []
    if to_state:
        gaps.append(message(
            ROLE_TO_STATE, roles=separated((message(name) for _, name in roles), "; "),
            count=len(listed_ones), listed=_names(listed_ones), unnamed=_names(unknown),
            missing=listed(message(names[r]) for r in to_state),
            role=listed(f'"{r}"' for r in to_state)))
        free = [role for role in free if role not in to_state]
    missing = len(free) - min(len(unknown), len(free))
    if missing:
        # a list of none is not printed as "0 listed so" (day review 69 F6); some: the ones
        # listed named, and the ones not listed named by their role where the roles of those
        # listed are told (assessment 72 L2: "the standard for the other one is not listed");
        # where they are not, which one is missing is said to be unknown, and how to tell it
        template = (QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; none of them is listed so")
            if not listed_ones else QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; {count} listed so ({listed}): "
            "none is listed for {missing}") if not unknown else QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; {count} listed so ({listed}), "
            "no role stated for {unnamed}: the standard for {choices} is not listed, and the "
            "details do not say which (state each standard's role)") if missing == 1 else
            QT_TR_NOOP(
            "the standards that carry the measurand are {roles}, each to be listed with a "
            "calibration certificate and a stated uncertainty; {count} listed so ({listed}), "
            "no role stated for {unnamed}: the standards for {count_missing} of {choices} are "
            "not listed, and the details do not say which (state each standard's role)"))
        role_names = [message(names[r]) for r in free]
        gaps.append(message(
            template, roles=separated((message(name) for _, name in roles), "; "),
            count=len(listed_ones), listed=_names(listed_ones), unnamed=_names(unknown),
            missing=listed(role_names), count_missing=missing,
            choices=(message(QT_TR_NOOP("{items} or {item}"), items=listed(role_names[:-1]),
                             item=role_names[-1]) if missing == 1 and len(role_names) > 1
                     else listed(role_names))))
    expired_ones = expired_standards(metadata) if expired else []
    for std in standards:
        name = typed_name(std.description) or message(QT_TR_NOOP("standard"))
        if std in expired_ones:
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
