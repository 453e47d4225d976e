"""The positioning test plan (ISO 230-2 test cycle): targets from start, step and count or
a list, runs, uni- or bidirectional, linear or pilgrim-step order; it fills target, run
and direction as readings arrive. The plan object and its API ("next point to fill",
``placement``) are shared by every workbench: see :mod:`models.readings.entry_plan`."""

from __future__ import annotations

from models.readings.entry_plan import EntryPlan, Placement, PlanPoint, positioning_plan, targets_from

__all__ = ["EntryPlan", "Placement", "PlanPoint", "positioning_plan", "targets_from"]
