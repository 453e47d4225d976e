"""Whether a certificate's reference standards fit the workbench they are to enter the
budget of (#41: the lab's defaults carried the theodolite's standard, u 0.5″, into a fringe
budget — U = 1.00″ against 0.003″ of noise — and raised a polygon certificate's U from
0.30″ to 1.44″, with nothing said).

* A standard whose uncertainty is not a quantity of the kind of the workbench's errors (an
  angle standard in a length budget) is **refused**: it cannot enter the budget.
* A standard whose stated uncertainty is as large as the certificate's tolerance or larger
  is **warned** of: with it no conformity can be shown, and it is most likely the standard
  of another test.

Also: the lab's saved defaults keep the standards **per workbench**
(:func:`standards_for`)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from models.certificate.metadata import CertificateMetadata, MetadataError
from models.messages import QT_TR_NOOP, message
from models.quantity import UNITS, Quantity, UnitError

__all__ = ["STANDARDS_BY_WORKBENCH", "standards_fit", "standards_for", "with_workbench_standards"]

#: the lab defaults' key of the standards per workbench (beside the older ``standards``)
STANDARDS_BY_WORKBENCH = "standards_by_workbench"


def standards_fit(meta: CertificateMetadata, error_unit: str) -> tuple[list[str], list[str]]:
    """(refusals, warnings) for the standards of ``meta`` entering a budget in
    ``error_unit`` (a key of models.quantity.UNITS); each a models.messages.Message."""
    refusals: list[str] = []
    warnings: list[str] = []
    tolerance = None
    if meta.tolerance is not None:
        try:
            tolerance = float(Quantity(meta.tolerance, meta.tolerance_unit).in_unit(error_unit))
        except UnitError:
            tolerance = None  # the tolerance's own unit is refused where it is checked
    for index, standard in enumerate(meta.standards):
        name = standard.description or f"#{index + 1}"
        try:
            u = standard.uncertainty_in(error_unit)
        except MetadataError:
            refusals.append(message(QT_TR_NOOP(
                "reference standard '{name}': its uncertainty is in {given}, a quantity of "
                "another kind than this workbench's errors ({unit}); it cannot enter this "
                "budget"), name=name, given=UNITS[standard.uncertainty_unit].symbol,
                unit=UNITS[error_unit].symbol))
            continue
        if u is not None and tolerance is not None and u >= tolerance:
            warnings.append(message(QT_TR_NOOP(
                "reference standard '{name}': its uncertainty {u} is not smaller than the "
                "tolerance ±{t}: with it no conformity can be shown (is it the standard of "
                "another test?)"), name=name, u=f"{u:g}{UNITS[error_unit].symbol}",
                t=f"{tolerance:g}{UNITS[error_unit].symbol}"))
    return refusals, warnings


def standards_for(defaults: Mapping[str, Any], workbench: str) -> list[Any] | None:
    """The standards the lab's defaults give ``workbench``: its own list when one was saved
    from it; else the older lab-wide ``standards`` only while no workbench has a list of its
    own (defaults saved before standards were kept per workbench); else none (None)."""
    own = defaults.get(STANDARDS_BY_WORKBENCH)
    if isinstance(own, Mapping) and own:
        listed = own.get(workbench)
        return list(listed) if isinstance(listed, list) else None
    shared = defaults.get("standards")
    return list(shared) if isinstance(shared, list) else None


def with_workbench_standards(stored: Mapping[str, Any], saved: Mapping[str, Any],
                             workbench: str) -> dict[str, Any]:
    """The lab's defaults after ``saved`` (a certificate dialog's lab fields) was saved from
    ``workbench``: its standards become that workbench's own. A lab-wide ``standards`` list
    saved before is kept as it was (its meaning unchanged for what reads it), and is no
    longer offered to any workbench once one has a list of its own (:func:`standards_for`)."""
    out = {**dict(stored), **{k: v for k, v in saved.items() if k != "standards"}}
    own = dict(out.get(STANDARDS_BY_WORKBENCH) or {})
    own[workbench] = list(saved.get("standards") or [])
    out[STANDARDS_BY_WORKBENCH] = own
    return out
