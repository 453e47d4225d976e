"""U in the command line's JSON (``anglebench analyze KIND FILE --json``).

Beside each reported error array ``NAME`` (for example ``corrected_error_arcsec``) the
JSON gets ``expanded_uncertainty_NAME`` (U per point, same order, same unit; 0 at a
reference point, where the error is zero by definition) and ``coverage_factor_NAME`` (k
per point, or one number when every point has the same k), and at the top level the
``coverage_probability``. When a tolerance is set, ``decided_quantity`` states the figure
the conformity decision is made on — ``value``, ``interval_low``, ``interval_high``,
``coverage_probability``, ``unit``, ``verdict`` (null when no statement of conformity may
be made, with the ``reason``), ``rule``, ``compared_with_tolerance`` (the value a simple or
non-binary rule compares with T itself, rounded as ASTM E29 §6.4 does: its ``value``,
``unit`` and ``decimals``) — always with numbers where the readings give them
(a withheld interval: both ends and its ``coverage_probability`` null).
``uncertainty_inputs_not_stated`` lists the inputs the certificate names as not stated, so
not in U (empty when U holds every input; no statement of conformity while one is).

Each workbench says which budget belongs to which array
(:meth:`models.workbench.IssuesCertificates.uncertainty_budgets`); this module writes them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np

from models.uncertainty.budget import UncertaintyBudget
from models.uncertainty.conformity import Conformity

__all__ = ["PointUncertainty", "budget_arrays", "certified_json", "decided_quantity_json",
           "merge_json",
           "uncertainty_json", "workbench_uncertainty_json"]


@dataclass(frozen=True)
class PointUncertainty:
    """U and k per point of an array whose U is not one budget's (a part of a budget's
    points, or a budget's points repeated)."""

    expanded: np.ndarray
    coverage_factors: np.ndarray
    # the points whose U was raised to the laboratory's CMC (None: none was, or no CMC
    # holds these points' U) and that CMC (0: none holds them)
    below_floor: np.ndarray | None = None
    floor: float = 0.0

    @classmethod
    def part(cls, budget: UncertaintyBudget, points: slice) -> PointUncertainty:
        return cls(np.asarray(budget.expanded)[points], np.asarray(budget.coverage_factors)[points],
                   np.asarray(budget.below_floor)[points], float(budget.floor))

    @classmethod
    def repeated(cls, budget: UncertaintyBudget, times: int) -> PointUncertainty:
        return cls(np.tile(budget.expanded, times), np.tile(budget.coverage_factors, times),
                   np.tile(budget.below_floor, times), float(budget.floor))


def in_json_order(budgets: Mapping[str, UncertaintyBudget | PointUncertainty | None],
                  orders: Mapping[str, np.ndarray]
                  ) -> dict[str, UncertaintyBudget | PointUncertainty | None]:
    """``budgets`` with the points of each array named in ``orders`` taken in that order
    (the order the workbench lists the array's values in the JSON)."""
    out = dict(budgets)
    for name, order in orders.items():
        budget = out.get(name)
        if budget is None or np.size(budget.expanded) != np.size(order):
            continue
        below = getattr(budget, "below_floor", None)
        out[name] = PointUncertainty(
            np.asarray(budget.expanded, dtype=float)[order],
            np.asarray(budget.coverage_factors, dtype=float)[order],
            None if below is None else np.asarray(below)[order], float(budget.floor))
    return out


def _number(x: float) -> float | None:
    x = float(x)
    return x if math.isfinite(x) else None


def budget_arrays(name: str, budget: UncertaintyBudget | PointUncertainty | None,
                  cmc_set: bool = False) -> dict[str, Any]:
    """``expanded_uncertainty_NAME`` and ``coverage_factor_NAME`` of one error array (None
    for both when its U is not determined); with ``cmc_set`` (the laboratory's CMC is set for
    the workbench) also ``uncertainty_raised_to_cmc_NAME``: per point, whether its U is the
    CMC because the budget gave less (false where it did not, or where the CMC does not hold
    this array's U; null with a U not determined)."""
    if budget is None:
        return {f"expanded_uncertainty_{name}": None, f"coverage_factor_{name}": None,
                **({f"uncertainty_raised_to_cmc_{name}": None} if cmc_set else {})}
    u = np.asarray(budget.expanded, dtype=float)
    k = np.asarray(budget.coverage_factors, dtype=float)
    finite = k[np.isfinite(k)]
    factor: Any = ([_number(v) for v in k] if finite.size and np.ptp(finite) > 0 or
                   finite.size != k.size else (_number(finite[0]) if finite.size else None))
    out = {f"expanded_uncertainty_{name}": [_number(v) for v in u],
           f"coverage_factor_{name}": factor}
    if cmc_set:
        out[f"uncertainty_raised_to_cmc_{name}"] = [bool(r) for r in _raised(budget, u.size)]
    return out


def _raised(budget: UncertaintyBudget | PointUncertainty, size: int) -> np.ndarray:
    """Per point, whether ``budget``'s U was raised to the laboratory's CMC."""
    raised = budget.below_floor if budget.floor > 0 else None
    return np.zeros(size, dtype=bool) if raised is None else np.asarray(raised, dtype=bool)


def _floor(budget: UncertaintyBudget | PointUncertainty | None) -> float:
    return float(getattr(budget, "floor", 0.0) or 0.0) if budget is not None else 0.0


def tolerance_stated_json(tolerance: Any) -> dict[str, Any] | None:
    """The tolerance as the customer stated it (assessment 73 M4: the JSON gave only its
    conversion to the errors' unit, from which a simple or conditional verdict cannot be
    redone): ``value`` the number (a JSON number), ``decimals`` the places it was typed to
    (trailing zeros kept: "4.600" is 3; the last place ASTM E29 rounds a value compared
    with it to), ``text`` the number as typed ("4.600") and ``unit`` its unit's key; None
    where the tolerance decided is not one the details state (a polygon's grade)."""
    stated = getattr(tolerance, "stated", None)
    if stated is None:
        return None
    from models.uncertainty.rounding import stated_decimals

    number, key = stated
    decimals = stated_decimals(number)
    return {"value": _number(float(number)), "decimals": decimals,
            "text": f"{float(number):.{decimals}f}", "unit": str(key)}


def decided_quantity_json(conformity: Conformity, tolerance: float | None) -> dict[str, Any] | None:
    """The decided quantity as the JSON states it; None without a tolerance."""
    if tolerance is None:
        return None
    stated = conformity.verdict != "not assessed"
    out: dict[str, Any] = {
        "value": _number(conformity.value),
        # the measured figure the value was estimated from (half the measured peak-to-peak:
        # noise widens it, so it lies above the value)
        "measured": _number(conformity.measured),
        "interval_low": _number(conformity.interval_low),
        "interval_high": _number(conformity.interval_high),
        # the Monte Carlo the interval came from (seeded from the readings: rerun, the same)
        "monte_carlo_trials": getattr(conformity.monte_carlo, "trials", None) or None,
        # as a decimal string: a seed made from the readings' hash reaches 2⁶⁴ (positioning's
        # 10712984201263442809), beyond an int64 reader and beyond the 2⁵³ a double holds
        # exactly (RFC 8259 6), where a number would overflow or be silently rounded and
        # name another seed; the draws are unchanged (until 0.8.18 a JSON number)
        "monte_carlo_seed": (str(int(conformity.monte_carlo.seed))
                             if conformity.monte_carlo is not None
                             and getattr(conformity.monte_carlo, "trials", None) else None),
        "coverage_probability": _number(conformity.probability),
        "unit": conformity.unit,
        "tolerance": _number(tolerance),
        "verdict": conformity.verdict if stated else None,
        "rule": conformity.rule_key,
        # agreed with the customer (ISO/IEC 17025 7.1.3), as the details say; false: the rule
        # requested, no agreement recorded (the certificate's "Decision rule" says which)
        "rule_agreed": conformity.rule_agreed,
        # stated only with a statement of conformity: where none may be made (U incomplete,
        # U ≥ T, the error untraceable) a probability of conformity would rest on that U
        "probability_conforming": _number(conformity.conforming_probability) if stated else None,
        # false acceptance after a pass, false rejection after a fail (JCGM 106 specific risk)
        "decision_risk": _number(conformity.decision_risk) if stated else None,
        # whether the two are bounds (every point deciding, two points or more: Boole's
        # inequality): decision_risk then at most the figure, probability_conforming at
        # least it after a pass and at most it after a fail (assessment 73 M6: a bound of
        # 1.0 read as a certain false acceptance); the figures keep their keys and meaning
        "decision_risk_is_bound": bool(conformity.risk_is_bound) if stated else None,
    }
    said = tolerance_stated_json(tolerance)
    if said is not None:
        out["tolerance_stated"] = said
    if not stated:
        out["reason"] = str(conformity.reason or conformity.statement)
    compared = conformity.compared
    if stated and compared is not None and conformity.rule_key in ("simple", "guarded"):
        # the value the rule compares with T itself, rounded as ASTM E29 §6.4 does: to the
        # finer of U's digit and T's last place as stated, in T's unit
        out["compared_with_tolerance"] = {"value": compared.value, "unit": compared.unit_key,
                                          "decimals": compared.decimals}
    raised = conformity.raised_to_cmc
    if raised is not None:  # (lower, upper) half-width held to the laboratory's CMC
        out["raised_to_cmc"] = {"low": bool(raised[0]), "high": bool(raised[1])}
    return out


def uncertainty_json(budgets: Mapping[str, UncertaintyBudget | PointUncertainty | None], probability: float,
                     conformity: Conformity | None = None,
                     tolerance: float | None = None, withheld: str = "",
                     cmcs: list[dict[str, Any]] | None = None) -> dict[str, Any]:
    """The keys to add to a workbench's JSON: U and k beside each array of ``budgets``
    (a key ``a/b`` places them in the object ``a`` of the JSON, beside its array ``b``),
    ``coverage_probability``, and ``decided_quantity`` when a tolerance is set.
    ``withheld``: why U is not given (the arrays whose U is not given null). ``cmcs``: the laboratory's
    CMCs set for the workbench (:func:`laboratory_cmcs`): with one, every U array gets its
    ``uncertainty_raised_to_cmc_`` flags and the JSON ``laboratory_cmc``."""
    out: dict[str, Any] = {"coverage_probability": _number(probability)}
    for key, budget in budgets.items():
        *path, name = key.split("/")
        target = out
        for part in path:
            target = target.setdefault(part, {})
        target.update(budget_arrays(name, budget, bool(cmcs)))
    if cmcs:
        out["laboratory_cmc"] = dict(cmcs[0])
        if len(cmcs) > 1:  # a cross-calibration's second item
            out["laboratory_cmc"]["other_quantities"] = [dict(c) for c in cmcs[1:]]
    if withheld:
        out["uncertainty_withheld"] = withheld
    if conformity is not None:
        decided = decided_quantity_json(conformity, tolerance)
        if decided is not None:
            out["decided_quantity"] = decided
    return out


def merge_json(data: dict[str, Any], extra: Mapping[str, Any]) -> dict[str, Any]:
    """``extra`` merged into ``data`` (objects merged key by key; existing keys keep their
    values: new keys go beside them)."""
    for key, value in extra.items():
        if isinstance(value, Mapping) and isinstance(data.get(key), dict):
            merge_json(data[key], value)
        elif key not in data:
            data[key] = value
    return data


#: what a budget or a decision raises when the readings do not determine it (a degenerate
#: record): the JSON then says why, and still prints every figure it has
_NOT_DETERMINED = (ValueError, ArithmeticError, IndexError, np.linalg.LinAlgError)


def workbench_uncertainty_json(kind: Any, result: Any, metadata: Any,
                               settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """The U keys of ``kind``'s JSON for ``result`` with the certificate details
    ``metadata`` (the standards and their U, the tolerance, the decision rule and quantity):
    the budgets the workbench names for its arrays, the decision its certificate makes."""
    from models.messages import reason_of

    probability = float(metadata.coverage_probability)
    withheld = ""
    try:
        budgets = kind.uncertainty_budgets(result, metadata, settings)
    except _NOT_DETERMINED as exc:  # U not determined: the arrays' U null
        names = getattr(kind, "uncertainty_array_names", lambda r: ())(result)
        budgets, withheld = dict.fromkeys(names), str(reason_of(exc))
    budgets = in_json_order(budgets, getattr(kind, "json_point_order", lambda r: {})(result))
    conformity, tolerance, why = None, None, ""
    if metadata.tolerance is not None or getattr(kind, "tolerance_in_settings", False):
        try:  # the decision as the certificate makes it
            document = kind.certificate(result, metadata, settings=settings)
            conformity, tolerance = document.conformity, document.tolerance
        except _NOT_DETERMINED as exc:
            why = str(reason_of(exc))
            conformity, tolerance = _interval_despite(kind, result, metadata, settings)
    # some arrays' U null by the workbench's own rule (a cross-calibration's encoder without
    # closure readings or a drift bound): said here too, as docs/command-line.md says
    withheld = withheld or str(getattr(kind, "uncertainty_withheld", lambda _r: "")(result) or "")
    out = uncertainty_json(budgets, probability, conformity, tolerance, withheld,
                           laboratory_cmcs(kind, budgets, settings))
    # the inputs the certificate names as not stated: U does not hold them (the list empty
    # when U is complete), so a lab's system can tell an incomplete U from a complete one
    # (a standard listed with no stated U among them, as the certificate names it under its
    # budget: models.certificate.builder.build_certificate)
    out["uncertainty_inputs_not_stated"] = [str(name) for name in
                                            inputs_not_stated(kind, result, metadata)]
    if why and "decided_quantity" in out:  # the certificate refused: no statement, its reason
        out["decided_quantity"].update(verdict=None, probability_conforming=None,
                                       decision_risk=None, reason=why)
    if conformity is None:
        unit = kind.error_unit(kind.settings_with_defaults(settings))
        try:
            tolerance = kind.decided_tolerance(result, metadata, unit)
        except ValueError:  # a tolerance in a unit of another kind: no figure to state
            tolerance = None
        if tolerance is not None:
            measured = _measured_figure(kind, result, metadata)
            out["decided_quantity"] = {
                # no interval: the value is the figure as measured (the key as elsewhere)
                "value": measured, "measured": measured,
                "interval_low": None, "interval_high": None,
                "coverage_probability": None, "unit": unit,
                "tolerance": _number(tolerance), "verdict": None,
                "rule": metadata.decision_rule,
                "rule_agreed": bool(metadata.decision_rule_agreed), "reason": why}
            given = getattr(metadata, "tolerance_quantity", None)
            said = None if given is None else tolerance_stated_json(
                SimpleNamespace(stated=(given.value, given.unit.key)))
            if said is not None:
                out["decided_quantity"]["tolerance_stated"] = said
    else:  # the figure is always stated, even where the decision could not compute it
        decided = out.get("decided_quantity")
        if decided is not None and decided["value"] is None:
            # the figure the decision measured (the means' half range of passes), else the
            # workbench's own
            decided["value"] = (decided["measured"] if decided.get("measured") is not None
                                else _measured_figure(kind, result, metadata))
    decided = out.get("decided_quantity")
    if decided is not None and decided["interval_low"] is None and decided["interval_high"] is None:
        # no interval, no probability of one (as positioning's figures state a withheld one)
        decided["coverage_probability"] = None
    return out


def inputs_not_stated(kind: Any, result: Any, metadata: Any) -> list[str]:
    """The inputs ``kind``'s certificate of ``result`` names as not stated, so not in U
    (untranslated): the workbench's own, and each standard listed with no stated U
    (:func:`models.certificate.traceability.standards_not_stated`) unless the workbench
    takes a listed standard's figures as inputs of its settings and names those itself
    (``standards_in_settings``: the fringe's ADC)."""
    from models.certificate.traceability import standards_not_stated

    named = list(kind.inputs_not_stated(result, metadata))
    if not getattr(kind, "standards_in_settings", False):
        named += [name for name in standards_not_stated(metadata) if name not in named]
    return named


def laboratory_cmcs(kind: Any, budgets: Mapping[str, Any],
                    settings: Mapping[str, Any] | None) -> list[dict[str, Any]]:
    """The laboratory's CMCs set for ``kind`` (its settings of
    :func:`models.uncertainty.lab_scope.cmc_parameter` that are not 0), each as the JSON's
    ``laboratory_cmc`` states it: ``value``, ``unit`` (the errors'), ``quantity`` (what it
    is the CMC of), ``setting`` (its key) and ``arrays``, the names of the JSON's arrays whose
    U it holds; the one that holds the most arrays first. Empty: none set."""
    from models.uncertainty.lab_scope import cmc_quantity

    full = kind.settings_with_defaults(settings)
    unit = kind.error_unit(full)
    out = []
    for parameter in kind.parameters:
        quantity = cmc_quantity(parameter)
        value = float(full.get(parameter.key, 0.0) or 0.0) if quantity else 0.0
        if not value > 0:
            continue
        arrays = [key.replace("/", ".") for key, budget in budgets.items()
                  if _floor(budget) == value]
        out.append({"value": value, "unit": unit, "quantity": quantity,
                    "setting": parameter.key, "arrays": arrays})
    # the certified item's CMC first (a cross-calibration's encoder certificate gave the
    # polygon's, which held as many arrays: assessment 70 L7), then the one holding the most
    primary = getattr(kind, "certified_cmc_setting", lambda _s: "")(settings) or ""
    out.sort(key=lambda c: (c["setting"] != primary, -len(c["arrays"])))
    return out


def _interval_despite(kind: Any, result: Any, metadata: Any,
                      settings: Mapping[str, Any] | None) -> tuple[Any, Any]:
    """The decided figure's interval when the certificate refused the details (they state an
    item grade or a tolerance the workbench's settings contradict): the interval does not
    depend on the tolerance, so it is computed with the contradicting details left out
    (the item grade, then the tolerance too, the workbench's own then deciding); no
    statement is made on it (the caller withholds the verdict with the refusal's reason).
    (None, None) where it still cannot be computed."""
    import dataclasses

    for cleared in ({"item_grade": ""}, {"item_grade": "", "tolerance": None}):
        try:
            document = kind.certificate(result, dataclasses.replace(metadata, **cleared),
                                        settings=settings)
        except _NOT_DETERMINED:
            continue
        if document.tolerance is not None and math.isfinite(document.conformity.value):
            return document.conformity, document.tolerance
    return None, None


def _measured_figure(kind: Any, result: Any, metadata: Any) -> float | None:
    """The decided figure as measured, when the certificate cannot give its interval (no
    honest U for these readings — a polygon without an identified tilt and no stated σ of
    a reading — or the certificate refused): half the peak-to-peak of the curve the decision
    is made on, or its largest |error| when every point decides. The interval is then not
    stated (null, with the reason): an interval without the reading noise would take the
    noise as 0, which no coverage can be claimed for. None only where the readings do not
    determine the curve itself (a cross-calibration design that leaves harmonics unseen)."""
    try:
        errors = kind.decided_errors(result, metadata)
    except _NOT_DETERMINED:
        return None
    if errors is None:
        return None
    e = np.asarray(errors, dtype=float)
    e = e[np.isfinite(e)]
    if not e.size:
        return None
    if metadata.decision_quantity == "points":
        return float(np.max(np.abs(e)))
    return 0.5 * float(np.ptp(e))


def certified_json(kind: Any, result: Any, metadata: Any,
                   settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """The keys of ``kind``'s JSON that the certificate details change (positioning's figure
    intervals with the reference standards' U, as the certificate prints them): they
    replace ``to_json``'s (:meth:`models.workbench.IssuesCertificates.certified_json`);
    none where the readings do not determine them."""
    hook = getattr(kind, "certified_json", None)
    if hook is None:
        return {}
    try:
        return dict(hook(result, metadata, settings))
    except _NOT_DETERMINED:
        return {}
