"""The XLSX 'Statistics' sheet in µrad or mdeg prints no figure to more digits than its
interval supports (day 69's check of the theodolite and positioning windows): the
certificate prints each figure to its interval's decimal (R = 3″ beside 0″ … 30″), and the
sheet in another unit carries that resolution over, 10^-d″ becoming the first decimal of
the unit at least as fine. It added digits to make three significant ones, so a figure
and its interval's ends came out to different decimals: R = 0.833 mdeg beside
0.0 … 8.33 mdeg, 14.5 µrad beside 0 … 145 µrad.

The runs come from first principles (tests/repeatability_rig.py: a mirror on a tilted
axis read with pointing noise, an axis approached run by run), nothing from models/; the
units' factors are worked out here."""

from __future__ import annotations

import io
import math
import re
from decimal import Decimal

import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata
from models.display_units import ANGLE_UNITS
from tests.models.test_summary_intervals_in_unit import _positioning as positioning_run
from tests.models.test_summary_intervals_in_unit import _theodolite as theodolite_run

pytestmark = pytest.mark.slow  # (two certificates, four workbooks)

META = CertificateMetadata.from_dict({"certificate_number": "X", "lab_name": "L"})
#: one arcsecond in each unit: π/648000 rad, 1/3600°
PER_ARCSEC = {"urad": math.pi / 648000 * 1e6, "mdeg": 1000 / 3600}
SYMBOL = {"urad": "µrad", "mdeg": "mdeg"}
ARCSEC_FIGURE = re.compile(r"[-+−]?\d+(?:\.(\d+))?\s*[\"″]")


def _theodolite():
    kind, result = theodolite_run()
    return kind.certificate(result, META)


def _positioning():
    kind, result = positioning_run()
    return kind.certificate(result, META)


def _decimals(value: float) -> int:
    return max(0, -Decimal(repr(value)).normalize().as_tuple().exponent)


@pytest.mark.parametrize("make", [_theodolite, _positioning], ids=["theodolite", "positioning"])
def test_statistics_in_another_unit_keep_each_figures_printed_resolution(make):
    document = make()
    printed = list(document.statistics.rows)
    checked = 0
    for key, per_arcsec in PER_ARCSEC.items():
        sheet = load_workbook(io.BytesIO(results_xlsx_bytes(document, ANGLE_UNITS[key])))[
            "Statistics"]
        header, *rows = list(sheet.iter_rows(values_only=True))
        symbol = SYMBOL[key]
        unit_column = next((j for j, h in enumerate(header) if h == "Value: unit"), None)
        for row, cells in zip(rows, printed, strict=False):
            found = [m.group(1) or "" for cell in cells for m in ARCSEC_FIGURE.finditer(str(cell))]
            if not found:
                continue
            # the decimals the arcsecond figure's resolution takes in the unit
            allowed = max(map(len, found)) + max(0, math.ceil(-math.log10(per_arcsec)))
            for j, value in enumerate(row):
                name = str(header[j] or "")
                angle = f"({symbol})" in name or (
                    name.startswith("Value") and unit_column is not None
                    and row[unit_column] == symbol)
                if angle and isinstance(value, float | int) and not isinstance(value, bool):
                    checked += 1
                    assert _decimals(value) <= allowed, (key, row[0], name, value, cells)
    assert checked >= 20  # (the figures and their intervals' ends, in both units)
