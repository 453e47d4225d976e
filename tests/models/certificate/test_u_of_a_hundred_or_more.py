"""A U of 100 or more in the errors' unit is printed with two significant digits, rounded
up, and every figure beside it to the same place (GUM 7.2.6, JJF 1059.1; assessment 76 M1:
until 0.8.24 the decimals stopped at the unit, and a linear axis in nm printed U 168, 222 nm,
s 151 nm and "A 2245 nm, 1556 … 3719 nm"). Every expected figure is recomputed here from the
analysis' full-precision arrays with this file's own rounding (not the code's helpers)."""

from __future__ import annotations

import json
import math
from decimal import ROUND_CEILING, ROUND_FLOOR, ROUND_HALF_EVEN, Decimal
from pathlib import Path

import numpy as np
import pytest

from models.certificate.document import budget_table
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget

SETTINGS = {"target_unit": "mm", "deviation_unit": "nm", "misalignment_u": 30,
            "reference_resolution": 10, "temperature_u": 20}


def _step(u: float) -> Decimal:
    """The place of a U's second significant digit after rounding it up (168 → 10, 99.6 →
    10 as it is 100, 1081 → 100, 1.436 → 0.1)."""
    exponent = math.floor(math.log10(u)) - 1
    step = Decimal(1).scaleb(exponent)
    if Decimal(repr(u)).quantize(step, rounding=ROUND_CEILING) >= 100 * step:
        step *= 10
    return step


def _text(value: float | Decimal, step: Decimal, rounding=ROUND_HALF_EVEN, sign: bool = False
          ) -> str:
    shown = Decimal(repr(float(value))).quantize(step, rounding=rounding)
    if shown == 0:
        return str(abs(shown).quantize(step))  # a zero unsigned
    text = f"{shown:f}"
    return f"+{text}" if sign and shown > 0 else text


def _up(u: float) -> str:
    return _text(u, _step(u), ROUND_CEILING)


@pytest.fixture(scope="module")
def linear_nm(tmp_path_factory):
    return nm_axis(tmp_path_factory.mktemp("nm"))


def nm_axis(folder: Path):
    """(result, certificate document) of the bundled positioning sample as a linear axis read
    in nm (targets /10 in mm, the deviations ×100): the assessor's pos_nm.csv, ±1500 nm."""
    kind = KINDS["positioning"]
    lines = Path("resources/samples/positioning_sample.csv").read_text("utf-8").splitlines()
    rows = [lines[0]]
    for line in lines[1:]:
        target, run, direction, deviation = line.split(",")
        rows.append(f"{float(target) / 10:g},{run},{direction},{float(deviation) * 100:g}")
    path = folder / "pos_nm.csv"
    path.write_text("\n".join(rows) + "\n", "utf-8")
    parsed = ReadingsSheet(kind.columns, map_columns(read_table(str(path)),
                                                     kind.columns)).parse()
    settings = kind.settings_with_defaults(SETTINGS)
    result = kind.analyze(parsed, settings)
    details = json.loads(Path("resources/samples/certificate_positioning.json").read_text("utf-8"))
    details.update(language="en", tolerance=1500, tolerance_unit="nm", decision_rule="guarded",
                   decision_quantity="points",
                   standards=[{"description": "Laser interferometer", "serial": "XL-80",
                               "certificate_no": "NIM-2026-2000", "uncertainty": 100,
                               "uncertainty_unit": "nm", "basis": "U95",
                               "role": "reference"}])
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         settings=settings)
    return result, document


def test_the_results_table_in_nm_states_u_s_and_the_means_with_two_digits(linear_nm):
    result, document = linear_nm
    table = document.results
    col = {h: i for i, h in enumerate(table.header)}
    points = dict(document.point_columns)
    n = len(table.rows)
    u_up, u_down = points["expanded_uncertainty_nm"][:n], points["expanded_uncertainty_nm"][n:]
    assert float(np.min(points["expanded_uncertainty_nm"])) > 100  # every U in the hundreds
    for i, row in enumerate(table.rows):
        for name, u, mean, s in (("↑", u_up[i], result.iso.forward.mean[i],
                                  result.iso.forward.std[i]),
                                 ("↓", u_down[i], result.iso.backward.mean[i],
                                  result.iso.backward.std[i])):
            assert row[col[f"U{name}"]] == _up(float(u)), (i, row)
            assert row[col[f"x̄{name}"]] == _text(mean, _step(float(u)), sign=True), (i, row)
            assert row[col[f"s{name}"]] == _text(s, Decimal(1).scaleb(
                math.floor(math.log10(s)) - 1)), (i, row)
    # the assessor's figures: U↑ 168 → 170 nm, U↓ 222 → 230 nm (rounded up), s↓ 151 → 150 nm
    assert table.rows[0][col["U↑"]] == "170" and table.rows[3][col["U↓"]] == "230"
    assert table.rows[3][col["s↓"]] == "150" and table.rows[3][col["x̄↓"]] == "+1000"


def test_the_figures_of_the_axis_in_nm_to_two_digits_of_their_half_width(linear_nm):
    from models.positioning.report import figure_uncertainties

    result, document = linear_nm
    intervals = figure_uncertainties(result, document.budget)
    rows = {str(row[0]).split(":")[0]: row for row in document.statistics.rows}
    iv = intervals["A"]
    step = _step((iv.high - iv.low) / 2.0)
    assert step == 100  # a half-width of 1081 nm
    assert rows["A"][1] == f"{_text(result.iso.figures['A'], step)} nm" == "2200 nm"
    assert rows["A"][2] == (f"{_text(iv.low, step, ROUND_FLOOR)} nm … "
                            f"{_text(iv.high, step, ROUND_CEILING)} nm") == "1500 nm … 3800 nm"


def test_the_statement_and_the_largest_u_in_nm(linear_nm):
    _, document = linear_nm
    statement = str(document.conformity.statement)
    assert "|e| = 1000 nm, U = 230 nm" in statement  # 998 nm ± 222 nm until 0.8.24
    zones = str(document.conformity.zones)
    assert "pass ≤ 1270 nm (T − w)" in zones and "≤ 1730 nm (T + w)" in zones
    rows = {str(row[0]): row for row in document.statistics.rows}
    largest = next(row for name, row in rows.items() if name.startswith("Expanded"))
    assert largest[1] == f"{_up(float(np.max(document.budget.expanded)))} nm" == "230 nm"


def test_the_budget_shows_why_k_uc_just_above_a_step_is_rounded_up():
    """k·u_c = 360.000001″ (a 180″ input and small ones in quadrature, the assessor's fringe
    f_full) is stated U = 370″, two significant digits rounded up; the line before rounding
    shows the digits that make it so, not "360.000" above "370"."""
    budget = UncertaintyBudget((BudgetComponent("big", "B", "normal", 180.0, 1.0, 1.0, math.inf),
                                BudgetComponent("small", "B", "normal", 0.011, 1.0, 1.0,
                                                math.inf)), 1)
    k_uc = budget.coverage_factor * float(budget.combined[0])
    assert 360.0 < k_uc < 360.000001
    rows = {str(row[0]): row for row in budget_table(budget, "the point").rows}
    before = next(row for name, row in rows.items() if "before rounding" in name)[7]
    stated = next(row for name, row in rows.items() if name.startswith("U stated"))[7]
    assert stated == "370" and float(before) > 360.0 and before == f"{k_uc:.6f}"
