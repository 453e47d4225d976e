"""#39 (trust): the presenter keeps with each result the readings it was analysed from
(``result_state``), and says whether the result shown is the analysis of the readings and
settings it holds now (``analysis_pending``). An edit made while a worker analyses never
reaches the readings that analysis parses, so a certificate can never pair the figures
with other readings."""

from __future__ import annotations

import pytest

from tests.widgets.test_presenters import _delete_presenters_at_teardown, load, make  # noqa: F401
from widgets.theodolite.presenter import TheodolitePresenter
from widgets.theodolite.view import TheodoliteView


class HeldWorkers:
    """The application's workers, whose analyses wait until the test runs them: the GUI
    thread's edits can then be put exactly between an analysis's start and its parse."""

    def __init__(self, workers) -> None:
        self.workers, self.tasks = workers, []

    def start(self, task) -> None:
        self.tasks.append(task)

    def __getattr__(self, name):
        return getattr(self.workers, name)


@pytest.fixture
def theodolite(qtbot, samples_dir):
    presenter, _ = make(TheodolitePresenter, TheodoliteView, qtbot)
    load(presenter, samples_dir)
    presenter.workers = HeldWorkers(presenter.workers)
    return presenter


def _azimuth_seconds(presenter) -> float:
    """The azimuth reading of θ = −15° (row 5) the result shown was analysed with: its
    arc seconds past −14°55′ (the sample's −14°54′50.7″ reads 9.3)."""
    parsed = presenter.parsed
    at = list(parsed["theta_deg"]).index(-15.0)
    return float(parsed["azimuth_deg"][at]) * 3600.0 + (14 * 3600 + 55 * 60)


def test_an_edit_during_the_analysis_stays_out_of_its_readings(theodolite, qtbot):
    presenter = theodolite
    assert not presenter.analysis_pending and presenter.result is not None
    sample_row = list(presenter.state().rows[5])
    assert sample_row[1] == "-14°54'50.7\""  # the sample's reading of θ = −15°
    presenter.set_capturing(True)  # analysed on a worker from now on
    presenter.refresh()
    assert presenter.analysis_pending  # started, its result not yet shown
    (task,) = presenter.workers.tasks
    presenter.table_model.set_cells([(5, 1, "-14°55'00.7\"")])  # typed while it runs
    task.run()  # the analysis parses now: after the edit
    # its result is shown, of the readings at its start: the edit is in neither
    assert _azimuth_seconds(presenter) == pytest.approx(9.3, abs=1e-6)
    analysed = presenter.result_state()
    assert analysed.rows[5] == sample_row and analysed.settings == presenter.settings
    assert presenter.sheet.text(5, 1) == "-14°55'00.7\""
    assert presenter.analysis_pending  # the edit still waits for its analysis
    assert not presenter.analyse_if_due()  # started now, on its worker
    presenter.workers.tasks.pop().run()
    assert not presenter.analysis_pending and presenter.analyse_if_due()
    assert _azimuth_seconds(presenter) == pytest.approx(-0.7, abs=1e-6)
    assert presenter.result_state().rows[5][1] == "-14°55'00.7\""
    assert presenter.result_state().rows == presenter.state().rows


def test_a_superseded_result_is_not_shown_and_the_newer_one_is_awaited(theodolite):
    presenter = theodolite
    before = presenter.result
    presenter.set_capturing(True)
    presenter.table_model.set_cells([(5, 1, "-14°55'00.7\"")])
    presenter.refresh()
    presenter.table_model.set_cells([(5, 1, "-14°55'10.7\"")])
    presenter.refresh()
    older, newer = presenter.workers.tasks
    newer.run()
    older.run()  # cancelled at its first checkpoint, or finished late: never shown
    assert presenter.result is not before and not presenter.analysis_pending
    assert _azimuth_seconds(presenter) == pytest.approx(-10.7, abs=1e-6)
    assert presenter.result_state().rows[5][1] == "-14°55'10.7\""


def test_a_settings_edit_waits_for_its_analysis_too(theodolite):
    presenter = theodolite
    presenter.view.settings_values.return_value = {"cmc_arcsec": 0.7}
    presenter.settings_edited()
    assert presenter.analysis_pending and presenter.result_state().settings["cmc_arcsec"] == 0.0
    assert presenter.analyse_if_due()  # a small sheet, not capturing: analysed at once
    assert presenter.result_state().settings["cmc_arcsec"] == 0.7


def test_details_changed_redraw_without_a_new_analysis(theodolite, qtbot):
    presenter = theodolite
    shown = presenter.result
    presenter.schedule_redraw()
    qtbot.wait(20)
    assert presenter.result is shown and not presenter.analysis_pending
    assert presenter.workers.tasks == []
