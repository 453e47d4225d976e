"""The window shows the figures its certificate prints, as it prints them (review 62, F2): the
headline, the summary, the figures table and the positioning's per-target table, for every
workbench's sample with the sample's certificate details, read against the certificate
document made of the same result."""

from __future__ import annotations

import json

import pytest

from models.certificate.metadata import CertificateMetadata
from widgets.crosscal.presenter import CrossCalPresenter
from widgets.fringe.presenter import FringePresenter
from widgets.polygon.presenter import PolygonPresenter
from widgets.positioning.presenter import PositioningPresenter
from widgets.theodolite.presenter import TheodolitePresenter

pytestmark = pytest.mark.slow  # a sample analysed and its certificate made (seconds each)

#: the reviewer's amended polygon (review 62, F2): peak-to-peak 2.594997…″, the ends
#: printed −2.12″ and +0.48″, so the certificate prints 2.60″ and the window said 2.59″
AMENDED_POLYGON = [
    ["1", "0.00004", "0.0", "-0.10", "0.85", "1", "+"],
    ["2", "30.00001", "0.12", "-0.51", "3.12", "1", "+"],
    ["3", "60.00002", "-0.08", "-0.52", "3.96", "1", "+"],
    ["4", "90.00003", "0.21", "-0.48", "3.27", "1", "+"],
    ["5", "120.00002", "-0.15", "-0.45", "1.13", "1", "+"],
    ["6", "150.00004", "0.05", "-0.50", "-1.84", "1", "+"],
    ["7", "180", "0.18", "-0.09", "-4.89", "1", "+"],
    ["8", "210.00003", "-0.22", "0.70", "-7.11", "1", "+"],
    ["9", "240", "0.09", "1.54", "-7.98", "1", "+"],
    ["10", "269.99999", "-0.04", "1.89", "-7.26", "1", "+"],
    ["11", "299.99999", "0.11", "1.50", "-5.13", "1", "+"],
    ["12", "329.99999", "-0.27", "0.71", "-2.11", "1", "+"],
    ["1", "-0.00001", "0.0", "-0.09", "0.88", "1", "+"],
    ["1", "0", "0.0", "-0.09", "0.88", "2", "-"],
    ["12", "330.00002", "-0.27", "0.71", "-2.13", "2", "-"],
    ["11", "300.00002", "0.11", "1.55", "-5.12", "2", "-"],
    ["10", "270", "-0.04", "1.90", "-7.27", "2", "-"],
    ["9", "239.99999", "0.09", "1.57", "-7.99", "2", "-"],
    ["8", "209.99994", "-0.22", "0.68", "-7.12", "2", "-"],
    ["7", "179.99998", "0.18", "-0.08", "-4.87", "2", "-"],
    ["6", "150.00004", "0.05", "-0.49", "-1.86", "2", "-"],
    ["5", "120.00002", "-0.15", "-0.55", "1.11", "2", "-"],
    ["4", "90", "0.21", "-0.50", "3.28", "2", "-"],
    ["3", "59.99999", "-0.08", "-0.51", "4.01", "2", "-"],
    ["2", "29.99997", "0.12", "-0.52", "3.12", "2", "-"],
    ["1", "0.00001", "0.0", "-0.11", "0.92", "2", "-"],
]


def _shown(qtbot, presenter, samples_dir, key: str, rows=None, settings=None):
    """The presenter with the sample's certificate details, its readings analysed; and the
    certificate document of the result shown."""
    qtbot.addWidget(presenter.view)
    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / f"certificate_{key}.json").read_text(encoding="utf-8")))
    presenter.certificate_details = lambda: details
    if rows is None:
        presenter.load_sample()
    else:
        presenter.set_settings(settings or {})
        presenter.table_model.replace_all(rows, "readings")
    qtbot.waitUntil(lambda: presenter.result is not None and presenter.analyse_if_due(),
                    timeout=60000)
    document = presenter.kind.certificate_document(presenter.result, details, "",
                                                   presenter.result_settings)
    return presenter.view, document


def _statistics(document) -> dict[str, tuple[str, ...]]:
    return {str(row[0]): tuple(str(cell) for cell in row[1:]) for row in document.statistics.rows}


def _figures(view) -> dict[str, str]:
    table = view.figures
    return {table.item(r, 0).text(): table.item(r, 1).text() for r in range(table.rowCount())}


def _ptp(note: str) -> str:
    """"2.60″" of "peak-to-peak 2.60″, RMS 0.8″"."""
    return note.split("peak-to-peak ")[1].split(",")[0].split(" ")[0]


def test_polygon_headline_is_the_certificates_peak_to_peak(qtbot, samples_dir):
    """The reviewer's readings: the certificate prints the ends −2.12″ and +0.48″ and the
    peak-to-peak 2.60″ (their difference as printed); the verdict, the summary and the figures
    table said 2.59″ / 2.595 (the unrounded 2.594997…″ rounded)."""
    settings = {"faces": 12, "grade": 3, "closure_drift": "report", "cmc_arcsec": 0.3,
                "plan_sets": 2}
    view, document = _shown(qtbot, PolygonPresenter(), samples_dir, "polygon",
                            AMENDED_POLYGON, settings)
    span, note = _statistics(document)["Corrected error"]
    ptp = _ptp(note)
    assert (span, ptp) == ("-2.12\" … +0.48\"", "2.60\"")
    assert f"peak-to-peak {ptp}" in view.verdict.text()
    assert f"Corrected error {span} (peak-to-peak {ptp})" in view.summary.toPlainText()
    assert f"division error {ptp}" in view.summary.toPlainText()
    assert _figures(view)["corrected peak-to-peak (\")"] == ptp.rstrip("\"")


def test_polygon_sample_figures_table_as_printed(qtbot, samples_dir):
    view, document = _shown(qtbot, PolygonPresenter(), samples_dir, "polygon")
    span, note = _statistics(document)["Corrected error"]
    assert _figures(view)["corrected peak-to-peak (\")"] == _ptp(note).rstrip("\"")  # not 0.9835
    assert f"Corrected error {span} (peak-to-peak {_ptp(note)})" in view.summary.toPlainText()


def test_theodolite_ranges_to_the_certificates_decimal(qtbot, samples_dir):
    """U = 1.4″: the certificate prints the corrected error −1.6″ … +1.3″, peak-to-peak 2.9″,
    RMS 0.8″; the window said −1.58″ … +1.30″ (peak-to-peak 2.88″, RMS 0.81″)."""
    view, document = _shown(qtbot, TheodolitePresenter(), samples_dir, "theodolite")
    stats = _statistics(document)
    raw_span, raw_note = stats["Raw error"]
    span, note = stats["Corrected error"]
    assert (span, note) == ("-1.6\" … +1.3\"", "peak-to-peak 2.9\", RMS 0.8\"")
    summary = view.summary.toPlainText()
    assert f"Raw error        {raw_span} ({raw_note})" in summary
    assert f"Corrected error  {span} ({note})" in summary
    assert view.verdict.text().startswith(f"Corrected error {span} (peak-to-peak {_ptp(note)})")
    figures = _figures(view)
    assert figures["corrected peak-to-peak (\")"] == "2.9"
    assert figures["raw peak-to-peak (\")"] == _ptp(raw_note).rstrip("\"")


def test_positioning_figures_and_per_target_table_as_printed(qtbot, samples_dir):
    """With the sample's reference standard (U 1″) the certificate prints M = 12.4″ and the
    per-target means to U's decimal (x̄↑ −1.4″ at 0°); the window said M = 12.43″, A 22.45 in
    its figures table and −1.375 in its per-target table."""
    view, document = _shown(qtbot, PositioningPresenter(), samples_dir, "positioning")
    printed = {name.split(":")[0]: cells[0] for name, cells in _statistics(document).items()
               if ":" in name}
    summary, verdict, figures = view.summary.toPlainText(), view.verdict.text(), _figures(view)
    assert printed["M"] == "12.4\""
    for key in ("A", "R", "B", "B_mean", "E", "M", "P", "Ps_max", "Pa", "U_max"):
        assert f"{key} = {printed[key]}" in summary, key
    for key in ("A", "R", "B"):
        assert f"{key} = {printed[key]}" in verdict, key
    for key in ("A", "R", "B", "A_up", "A_down", "R_up", "R_down"):
        assert figures[f"{key} (\")"] == printed[key].rstrip("\""), key
    results = document.results
    table = view.per_target
    shown_header = [table.horizontalHeaderItem(c).text().split(" (")[0]
                    for c in range(table.columnCount())]
    for column, header in enumerate(results.header):
        if header in ("x̄↑", "s↑", "x̄↓", "s↓", "B_i", "M_i"):
            shown = shown_header.index(header)
            assert [table.item(r, shown).text() for r in range(table.rowCount())] == [
                str(row[column]) for row in results.rows], header
    assert table.item(0, shown_header.index("x̄↑")).text() == "-1.4"


def test_crosscal_states_the_certificates_u_and_range(qtbot, samples_dir):
    """The certificate of the faces states U 0.033″ (the comparators' U in it); the window
    said "U up to 0.018″", the readings' scatter alone."""
    view, document = _shown(qtbot, CrossCalPresenter(), samples_dir, "crosscal")
    stats = _statistics(document)
    span, note = stats["Deviation"]
    u = next(cells[0] for name, cells in stats.items() if name.startswith("Expanded"))
    assert u == "0.033\""
    assert f"Face deviations {span} (about their mean), U up to {u}" in \
        view.summary.toPlainText()
    assert f"face deviations {span} (U ≤ {u})" in view.verdict.text()
    assert _figures(view)["face deviation peak-to-peak (\")"] == _ptp(note).rstrip("\"")


def test_fringe_figures_table_as_printed(qtbot, samples_dir):
    """The certificate prints the peak-to-peaks to 0.001″ (0.991″, 0.038″); the figures table
    said 0.9909 and 0.03812."""
    view, document = _shown(qtbot, FringePresenter(), samples_dir, "fringe")
    stats = _statistics(document)
    found = _ptp(stats["Interpolation error as found"][1])
    left = _ptp(stats["After compensation (not applied to the item)"][1])
    assert (found, left) == ("0.991\"", "0.038\"")
    figures = _figures(view)
    assert figures["as-found peak-to-peak (\")"] == found.rstrip("\"")
    assert figures["compensated peak-to-peak (\")"] == left.rstrip("\"")
    assert f"Interpolation error {found} peak-to-peak" in view.verdict.text()
