"""Sending a workbench's result to another as its reference standard (File › Send as
reference): the cross-calibration's polygon face deviations, from face 1 with their U, into
the polygon workbench's reference column, and the polygon's U into its certificate details:
the U its own certificate states, with its certificate details (the comparators' stated
calibration U in); without details listing a comparator with a stated U, the standard's name
and the message say that U leaves it out.

The sender and the receiver are found by capability (models.workbench.SendsReference /
AcceptsReference, matched by the kind of reference), never by key."""

from __future__ import annotations

import dataclasses
from typing import Any

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.messages import JOINS
from models.workbench import AcceptsReference, SendsReference
from widgets.i18n import declared, explained, tr, translated

__all__ = ["SENT_REFERENCES", "check_sent_references", "receiver_of", "send_reference",
           "sent_reference_source", "watch_sent_references"]

#: the project metadata's record of each reference sent, by the receiver's key: the
#: sender's key, what was sent and its digest (models.workbench.SentReference.digest), so
#: that a reference whose source has changed since is said, in the session and on load
SENT_REFERENCES = "sent_references"


def receiver_of(window: Any, source: Any) -> Any:
    """The presenter whose workbench accepts what ``source``'s sends (None: none)."""
    if not isinstance(source.kind, SendsReference):
        return None
    return next((p for p in window.presenters if p is not source
                 and isinstance(p.kind, AcceptsReference)
                 and p.kind.accepted_reference == source.kind.reference_kind), None)


def send_reference(window: Any) -> bool:
    """The current workbench's reference into the workbench that accepts it (one undo step
    there), its largest U as the reference standard's (stated from face 1) in that
    workbench's certificate details, replacing one sent before; its U as the sender's
    certificate states it with the sender's certificate details."""
    source = window.current
    target = receiver_of(window, source)
    if target is None:
        window.tell(tr("Cannot send"), tr("{workbench} has no reference to send.").format(
            workbench=declared(source.kind.title)))
        return False
    if not window.result_is_current(source, sending=True):  # never a result older than
        return False  # the readings it stands for
    if source.result is None:
        problem = (translated(source.problem) if source.problem else
                       tr("no readings have been analysed yet"))
        window.tell(tr("Nothing to send"), tr("{workbench}: {problem}.").format(
                workbench=declared(source.kind.title), problem=problem))
        return False
    try:
        # the details its certificate would be issued with now: never a smaller U than it states
        details = window.certificates.issue_details(source.kind.key)
        reference = source.kind.sent_reference(source.result, details)
        # the budget takes one figure per standard: the largest standard u of d_i − d_1
        standard = ReferenceStandard(description=translated(reference.standard_name),
                                     uncertainty=round(reference.largest_standard_uncertainty, 6),
                                     basis="u", applies_to="from face 1",
                                     uncertainty_unit=reference.unit)
        meta = window.certificates.details(target.kind.key)
        kept = tuple(s for s in meta.standards if s.applies_to != "from face 1")
        meta = dataclasses.replace(meta, standards=(*kept, standard))
        # stored details read back leniently: a standard that does not read (a name too
        # long) would drop every standard unseen, the sent U with them; refused here instead
        CertificateMetadata.from_dict(meta.to_dict())
        cells = target.accept_reference(reference)
    except ValueError as exc:
        window.tell(tr("Nothing to send"), tr("{workbench}: {problem}").format(
            workbench=declared(source.kind.title), problem=explained(exc)))
        return False
    window.certificates.store_details(target.kind.key, meta)
    sent = window.projects.metadata.get(SENT_REFERENCES)
    sent = dict(sent) if isinstance(sent, dict) else {}
    sent[target.kind.key] = {"source": source.kind.key, "kind": str(reference.kind),
                             "digest": reference.digest(),
                             "values": {str(k): v for k, v in reference.values.items()}}
    window.projects.metadata[SENT_REFERENCES] = sent  # saved with the project
    target.view.reference_notice.clear()
    target.refresh()
    window.tabs.setCurrentIndex(window.presenters.index(target))
    said = tr("{workbench}: {cells} reference values sent to {target} with their U (largest "
              "u = {u}); Edit › Undo there restores the column").format(
        workbench=declared(source.kind.title), cells=cells, target=declared(target.kind.title),
        u=f"{reference.largest_standard_uncertainty:.4f}\"")
    if reference.left_out:  # said where it is read, not only in the standard's name
        said = tr(JOINS["; "]).format(first=said, second=translated(reference.left_out))
    window.statusBar().showMessage(said, 15000 if reference.left_out else 8000)
    return True


def _now(window: Any, source: Any) -> tuple[str, str]:
    """(the digest of what ``source`` would send now, "") or ("", why it would send none)."""
    if source.result is None:
        return "", source.problem or tr("no readings have been analysed yet")
    try:
        details = window.certificates.issue_details(source.kind.key)
        return source.kind.sent_reference(source.result, details).digest(), ""
    except ValueError as exc:
        return "", explained(exc)


def _still_held(target: Any, record: dict) -> bool:
    """Whether ``target``'s reference column still holds the values sent (to 1e-6, as they
    were written)."""
    sent = record.get("values")
    if not isinstance(sent, dict):
        return True  # (a record without them: the column is taken as the sent one)
    held = target.held_reference()
    try:
        return all(abs(held[int(k)] - float(v)) <= 1e-6 for k, v in sent.items())
    except (KeyError, TypeError, ValueError):
        return False


def check_sent_references(window: Any) -> None:
    """Each workbench that holds a sent reference says so when its source would not send the
    same now (its readings, settings or certificate details changed since, in this session
    or before the project was saved: the digests differ), and offers to send it again; the
    notice goes when it is current again or nothing sent is held."""
    sent = window.projects.metadata.get(SENT_REFERENCES)
    sent = sent if isinstance(sent, dict) else {}
    for target in window.presenters:
        if not isinstance(target.kind, AcceptsReference):
            continue
        notice = target.view.reference_notice
        record = sent.get(target.kind.key)
        source = next((p for p in window.presenters if isinstance(record, dict)
                       and p.kind.key == record.get("source")
                       and isinstance(p.kind, SendsReference)), None)
        if source is None or not _still_held(target, record):
            notice.clear()  # nothing sent, or the column holds something else now (undone,
            continue  # a certificate loaded, typed over): not the sent reference to check
        digest, why = _now(window, source)
        if digest and digest == record.get("digest"):
            notice.clear()
        elif why:
            notice.show_stale(tr(
                "The {what} in the reference column were sent from {source}, which has no "
                "result now ({why}): they cannot be checked against it.").format(
                what=translated(record.get("kind", "")), source=declared(source.kind.title),
                why=why), can_resend=False)
        else:
            notice.show_stale(tr(
                "The {what} in the reference column were sent from {source}, which has "
                "changed since (its readings, settings or certificate details): the column "
                "and the reference standard's U are not what it sends now. Send them "
                "again.").format(what=translated(record.get("kind", "")),
                                 source=declared(source.kind.title)))


def sent_reference_source(window: Any, target: Any) -> Any:
    """The presenter ``target``'s sent reference came from (None: nothing sent to it)."""
    if not isinstance(target.kind, AcceptsReference):
        return None
    sent = window.projects.metadata.get(SENT_REFERENCES)
    record = sent.get(target.kind.key) if isinstance(sent, dict) else None
    return next((p for p in window.presenters if isinstance(record, dict)
                 and p.kind.key == record.get("source")), None)


def _send_again(window: Any, target: Any) -> None:
    """The notice's *Send again*: the reference sent from its source once more."""
    source = sent_reference_source(window, target)
    if source is None:
        return
    window.tabs.setCurrentIndex(window.presenters.index(source))
    send_reference(window)


def watch_sent_references(window: Any) -> None:
    """Check the sent references whenever a workbench that sends or receives one shows a
    result (a new analysis, its details or the lab defaults changed, a project opened), and
    connect each receiver's *Send again*."""
    for presenter in window.presenters:
        if isinstance(presenter.kind, SendsReference | AcceptsReference):
            presenter.analysed.connect(lambda: check_sent_references(window))
        if isinstance(presenter.kind, AcceptsReference):
            presenter.view.reference_notice.resend.connect(
                lambda p=presenter: _send_again(window, p))
