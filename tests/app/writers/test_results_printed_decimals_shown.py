"""The XLSX's printed tables (*Statistics*, *Parameters*, *Uncertainty budget*) hold each
figure as a number that shows the decimals the certificate prints it to, and their column
headers read as headers (assessment 72 L6: a U of 7.0 µrad was the number 7 in a General
cell, which shows 7; the polygon's *Statistics* header read "Value (to | second | U−)").

An expanded uncertainty is printed with two significant digits (GUM 7.2.6): the cell must
show both. The samples' certificates, read in µrad (the theodolite sample's largest U is
1.436″, 6.96 µrad, printed 7.0 µrad)."""

from __future__ import annotations

import io
import json
import math

import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata
from models.display_units import ANGLE_UNITS
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # two analyses, four workbooks


def _document(samples_dir, key: str, language: str = "en"):
    kind = KINDS[key]
    sample = samples_dir / f"{key}_sample.csv"
    parsed = ReadingsSheet(kind.columns, map_columns(read_table(str(sample)), kind.columns)).parse()
    settings = kind.settings_with_defaults({})
    details = json.loads((samples_dir / f"certificate_{key}.json").read_text("utf-8"))
    return kind.certificate_document(kind.analyze(parsed, settings),
                                     CertificateMetadata.from_dict(details | {"language": language}),
                                     sample.name, settings)


def _shown(value: float, number_format: str) -> str:
    """A number as a spreadsheet shows it in the formats the sheets use ("General", "0",
    "0.000"): General shows the number's shortest digits (7.0 as 7)."""
    if number_format == "General":
        return repr(float(value)).removesuffix(".0")
    decimals = len(number_format.split(".")[1]) if "." in number_format else 0
    return f"{value:.{decimals}f}"


def _significant(text: str) -> int:
    digits = text.lstrip("+-").replace(".", "").lstrip("0")
    return len(digits)


def test_u_cells_show_two_significant_digits_and_every_figure_its_decimals(samples_dir):
    book = load_workbook(io.BytesIO(results_xlsx_bytes(_document(samples_dir, "theodolite"),
                                                       ANGLE_UNITS["urad"])))
    rows = {row[0].value: row for row in book["Statistics"].iter_rows()}
    u_cell = next(row[1] for name, row in rows.items()
                  if str(name).startswith("Expanded uncertainty U (p"))
    u = 1.436 * math.pi / 648000 * 1e6  # the sample's largest U, about 6.96 µrad
    assert float(u_cell.value) == pytest.approx(round(u + 0.05, 1), abs=1e-9)  # 7.0
    assert _shown(u_cell.value, u_cell.number_format) == "7.0", u_cell.number_format
    for title in ("Statistics", "Parameters", "Uncertainty budget"):
        for row in book[title].iter_rows(min_row=2):
            name = str(row[0].value)
            for cell in row[1:]:
                if isinstance(cell.value, bool) or not isinstance(cell.value, int | float):
                    continue
                shown = _shown(cell.value, cell.number_format)
                # the number stored is the number shown: no digit hidden by the format
                assert float(shown) == pytest.approx(cell.value, abs=1e-12), (title, name)
                if name.startswith("Expanded uncertainty U"):
                    assert _significant(shown) == 2, (title, name, shown)


@pytest.mark.parametrize("language", ["en", "zh", "zh+en"])
def test_polygon_statistics_headers_read_as_headers(samples_dir, language):
    book = load_workbook(io.BytesIO(results_xlsx_bytes(_document(samples_dir, "polygon",
                                                                 language))))
    header = [c.value for c in next(book["Statistics"].iter_rows(max_row=1)) if c.value]
    assert not any("|" in h for h in header), header
    # the column holding the end of a range, the second of a pair and the U below a value
    # names the three
    said = {"en": ("to", "second", "U−"), "zh": ("止", "第二个", "U−"),
            "zh+en": ("止", "第二个", "U−", "to", "second")}[language]
    assert any(all(word in h for word in said) for h in header), header
