"""#39 (trust): a certificate is never issued from a result older than the readings it
records. A reading that came after the analysis began (typed, or taken from an instrument
while capturing, when every analysis runs on a worker) is in the sheet but not in the
figures: the window then analyses a waiting edit first, refuses while an analysis still
runs (nothing asked, written or recorded), and the register records the readings the
certificate's figures were computed from.

The check of a record: its readings, analysed again with its settings, give the figures it
states (``headline``) — the register holds no readings that do not give the certificate's
numbers."""

from __future__ import annotations

import pytest
from pypdf import PdfReader

from models.certificate.metadata import CertificateMetadata
from models.project.file import project_from_json
from models.readings.sheet import ReadingsSheet
from widgets import workbench_presenter

pytestmark = pytest.mark.slow  # a window and a certificate: ~1-3 s each

STILL_ANALYSED = ("The latest readings are still being analysed; export again when their "
                  "result is shown.")

DETAILS = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Turntable",
    "item_serial": "T-1", "calibration_date": "2026-11-20", "issue_date": "2026-11-24",
    "operator": "Wang", "approver": "Dr. Li",
    "standards": [{"description": "Theodolite", "certificate_no": "N-1",
                   "uncertainty": 0.5}]})

# one more point (θ = 21°), its azimuth ~10″ off the sample's trend: with it the figures are
# clearly not the sample's
NEW_ROW = ["21", "20°54'57.8\"", "1°11'42.0\""]


@pytest.fixture
def bench(window, samples_dir, tmp_path):
    """The theodolite in front with its sample analysed; the certificate's details and file
    answered (``asked``: the details dialogs opened, ``paths``: the files asked for)."""
    presenter = window.presenter("theodolite")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.import_file(samples_dir / presenter.kind.sample_file)
    assert presenter.result is not None and not presenter.analysis_pending
    asked: list = []
    paths: list = []
    window.certificates.edit_details = lambda shown: asked.append(shown) or DETAILS
    window.certificates.view.confirm_standards = lambda warnings: True
    window.certificates.view.choose_save_path = (
        lambda title, suggested, kinds: paths.append(suggested)
        or str(tmp_path / ("cert.pdf" if suggested.endswith(".pdf") else "results.csv")))
    return presenter, asked, paths


def _records(window) -> list:
    with window.certificates.open_register() as register:
        return register.list()


def _figures_of(kind, rows, settings) -> dict:
    """The headline figures the readings give, analysed afresh from their text."""
    sheet = ReadingsSheet(kind.columns, rows)
    return kind.headline_figures(kind.analyze_as_far_as_it_goes(sheet.parse(), settings))


def _assert_record_gives_its_figures(record, kind) -> list[list[str]]:
    state = project_from_json(record.project_json).workbenches[kind.key]
    again = _figures_of(kind, state.rows, state.settings)
    stated = record.headline
    assert set(again) == set(stated)
    for name, value in stated.items():
        assert again[name] == pytest.approx(value, rel=1e-9, abs=1e-12), name
    return [list(r) for r in state.rows]


def test_a_reading_taken_while_capturing_is_certified_only_with_its_analysis(window, bench,
                                                                          qtbot, tmp_path):
    presenter, asked, paths = bench
    sample_figures = presenter.kind.headline_figures(presenter.result)
    presenter.set_capturing(True)  # every analysis now runs on a worker
    row = presenter.sheet.row_count
    presenter.table_model.set_cells([(row, c, t) for c, t in enumerate(NEW_ROW)])
    assert presenter.analysis_pending  # the take's analysis not even started yet
    # asked at once: the waiting edit is analysed now, on its worker: not yet done
    assert not window.export_certificate()
    assert window.told == [STILL_ANALYSED]
    assert not window.export_results()
    assert window.told == [STILL_ANALYSED] * 2
    assert asked == [] and paths == []  # no dialog opened
    assert _records(window) == [] and list(tmp_path.glob("*.pdf")) == []
    assert list(tmp_path.glob("results*")) == []
    # the sheet and its undo history are as they were: nothing lost
    assert presenter.sheet.text(row, 1) == NEW_ROW[1] and presenter.undo_stack.count() == 2

    qtbot.waitUntil(lambda: not presenter.analysis_pending, timeout=5000)
    assert window.export_certificate(), (window.told, presenter.problem)
    (record,) = _records(window)
    rows = _assert_record_gives_its_figures(record, presenter.kind)
    assert rows[-1][:3] == NEW_ROW and len(rows) == row + 1
    assert record.headline != pytest.approx(sample_figures)  # the take is in the figures
    text = "\n".join(p.extract_text() for p in PdfReader(tmp_path / "cert.pdf").pages)
    assert record.number in text
    assert window.export_results(), window.told
    assert (tmp_path / "results.csv").exists()


def test_an_edit_waiting_for_its_analysis_is_analysed_before_the_certificate(window, bench,
                                                                            qtbot):
    """A small sheet is analysed on the GUI thread: the edit's analysis runs at once and the
    certificate is issued from it (no refusal where none is needed)."""
    presenter, asked, _ = bench
    before = presenter.result
    sample_figures = presenter.kind.headline_figures(before)
    presenter.table_model.set_cells([(5, 1, "-14°55'00.0\"")])  # a reading retyped
    assert presenter.analysis_pending and presenter.result is before
    assert window.export_certificate()
    assert window.told == [] and len(asked) == 1
    assert presenter.result is not before and not presenter.analysis_pending
    (record,) = _records(window)
    rows = _assert_record_gives_its_figures(record, presenter.kind)
    assert rows[5][1] == "-14°55'00.0\""
    assert record.headline != pytest.approx(sample_figures)


def test_a_large_sheet_edited_is_refused_until_its_worker_is_done(window, bench, qtbot,
                                                                 monkeypatch):
    presenter, asked, paths = bench
    monkeypatch.setattr(workbench_presenter, "THREAD_THRESHOLD_ROWS", 10)  # 41 rows: "large"
    presenter.table_model.set_cells([(5, 1, "-14°55'00.0\"")])
    assert not window.export_certificate()
    assert window.told == [STILL_ANALYSED] and asked == [] and paths == []
    assert _records(window) == []
    qtbot.waitUntil(lambda: not presenter.analysis_pending and not presenter.busy,
                    timeout=5000)
    assert window.export_certificate()
    (record,) = _records(window)
    assert _assert_record_gives_its_figures(record, presenter.kind)[5][1] == "-14°55'00.0\""


def test_a_file_still_being_read_is_not_exported_from_the_readings_it_replaces(
        window, bench, qtbot, monkeypatch, samples_dir, tmp_path):
    presenter, _, paths = bench
    monkeypatch.setattr(workbench_presenter, "THREAD_THRESHOLD_BYTES", 0)  # read on a worker
    presenter.start_import(samples_dir / presenter.kind.sample_file)
    assert presenter.reading_file
    assert not window.export_results()
    assert window.told == ["The readings are still being read from the file; export again "
                           "when their result is shown."]
    assert paths == []
    qtbot.waitUntil(lambda: not presenter.reading_file and not presenter.analysis_pending,
                    timeout=5000)
    assert window.export_results()
    assert (tmp_path / "results.csv").stat().st_size > 0


def test_a_run_still_being_analysed_is_not_sent_to_positioning(window, bench, qtbot):
    """Send to positioning takes the result's run: while a reading taken is still being
    analysed it would send the run without it. Refused and said, the positioning readings
    untouched; once the analysis is shown, sent with the new point."""
    presenter, _, _ = bench
    positioning = window.presenter("positioning")
    before = [list(r) for r in positioning.state().rows]
    presenter.set_capturing(True)
    row = presenter.sheet.row_count
    presenter.table_model.set_cells([(row, c, t) for c, t in enumerate(NEW_ROW)])
    assert not window.send_to_positioning()
    assert window.told == ["The latest readings are still being analysed; send again when "
                           "their result is shown."]
    assert [list(r) for r in positioning.state().rows] == before
    qtbot.waitUntil(lambda: not presenter.analysis_pending, timeout=5000)
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    assert window.send_to_positioning(), window.told
    sent = presenter.kind.run_rows(presenter.result)
    assert len(sent) == len(presenter.kind.run_rows(presenter.result))
    assert positioning.sheet.row_count == len(sent) and len(sent) > 0
    assert presenter.result.theta_deg.size == row + 1  # the new point is in what was sent
