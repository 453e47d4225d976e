"""Every reference case of the method validation report (``anglebench validate``): each
workbench's own (``models/<kind>/validation_cases.py``'s ``validation_cases(trials)`` and its
Workbench's ``validation_cases``), in the order of the registry, then the shared ones.

This is the one module of models/validation that reaches every workbench (through the
registry, by name): the cases themselves import only the shared machinery of
models.validation.cases, so no workbench imports back into this module.
"""

from __future__ import annotations

import importlib
import importlib.util

from models.registry import KINDS, LOCATIONS
from models.validation.cases import ValidationCase, uncertainty_cases

__all__ = ["run_validation", "workbench_cases"]


def workbench_cases(key: str, trials: int) -> list[ValidationCase]:
    """A workbench's reference cases: those of ``validation_cases.py`` in the package of its
    object (models.registry.LOCATIONS), when it has one, then its ``validation_cases``."""
    package = LOCATIONS[key].partition(":")[0].rpartition(".")[0]
    cases: list[ValidationCase] = []
    if importlib.util.find_spec(f"{package}.validation_cases") is not None:
        cases += importlib.import_module(f"{package}.validation_cases").validation_cases(trials)
    return cases + list(KINDS[key].validation_cases(trials))


def run_validation(trials: int = 200) -> list[ValidationCase]:
    """Every reference case; ``trials`` Monte Carlo runs for each budget comparison."""
    from models.validation.degenerate import degenerate_design_cases
    from models.validation.half_range import half_range_cases

    return ([case for key in KINDS for case in workbench_cases(key, trials)]
            + uncertainty_cases() + half_range_cases(trials) + degenerate_design_cases(trials))
