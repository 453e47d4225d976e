"""The window's figures as the certificate prints them (review 62, F2) cost the GUI thread
little: the positioning's bootstrap of the readings without the reference standards' U is
drawn once for the summary's intervals and the certificate's (which unites them with its
own: each was drawn again, four bootstraps an edit), the cross-calibration's tilt effect is
worked out once for every budget (five times an edit), and where the readings are analysed
on a worker (a take while capturing, a large sheet) the figures as printed are made there
too, never on the GUI thread. Each edit blocked the window 0.25–0.37 s on the samples."""

from __future__ import annotations

import gc
import json
import threading
import weakref

import pytest

import models.pyramidal
import models.uncertainty.figure_intervals
from models.certificate.metadata import CertificateMetadata
from models.display_units import ANGLE_UNITS
from tests.widgets.test_readings_table_gui import type_cell
from tests.widgets.test_screen_as_printed import _figures, _statistics
from widgets.crosscal.presenter import CrossCalPresenter
from widgets.positioning.presenter import PositioningPresenter

pytestmark = pytest.mark.slow  # a sample analysed with its certificate details (seconds)


def _sample(qtbot, presenter, samples_dir, key: str):
    """``presenter`` shown, with the sample's readings and its certificate details."""
    qtbot.addWidget(presenter.view)
    presenter.view.show()
    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / f"certificate_{key}.json").read_text(encoding="utf-8")))
    presenter.certificate_details = lambda: details
    presenter.load_sample()
    assert presenter.result is not None and presenter.analyse_if_due()
    return details


def _counted(monkeypatch, module, name: str) -> list[str]:
    """Calls of ``module.name`` from now on, each by the name of the thread that made it."""
    calls: list[str] = []
    original = getattr(module, name)

    def spy(*args, **kwargs):
        calls.append(threading.current_thread().name)
        return original(*args, **kwargs)

    monkeypatch.setattr(module, name, spy)
    return calls


def _typed(qtbot, presenter, row: int, column: str, text: str) -> None:
    """``text`` typed into a cell of the readings table, and its analysis shown."""
    before = presenter.result
    keys = [c.key for c in presenter.kind.columns]
    type_cell(qtbot, presenter.view.table, row, keys.index(column), text)
    qtbot.waitUntil(lambda: presenter.result is not before and presenter.analyse_if_due(),
                    timeout=60000)


def _printed_figures_shown(presenter, details) -> None:
    """The window's figures table shows what the certificate of its result prints."""
    document = presenter.kind.certificate_document(presenter.result, details, "",
                                                   presenter.result_settings)
    printed = {name.split(":")[0]: cells[0] for name, cells in _statistics(document).items()
               if ":" in name}
    figures = _figures(presenter.view)
    for key in ("A", "R", "B"):
        assert figures[f"{key} (\")"] == printed[key].rstrip("\""), key


def test_a_positioning_edit_draws_two_bootstraps_not_four(qtbot, monkeypatch, samples_dir):
    """The readings' own (the summary's intervals) and the certificate's with its reference
    standard's U; the certificate's part without that U is the readings' own, drawn once."""
    presenter = PositioningPresenter()
    details = _sample(qtbot, presenter, samples_dir, "positioning")
    drawn = _counted(monkeypatch, models.uncertainty.figure_intervals, "_ensemble")
    _typed(qtbot, presenter, 0, "deviation", "-1.55")
    assert presenter.result.deviations[0] == pytest.approx(-1.55)
    assert len(drawn) == 2  # one _ensemble world per bootstrap
    _printed_figures_shown(presenter, details)
    presenter.set_angle_unit(ANGLE_UNITS["urad"])  # shown again: nothing drawn again
    presenter.set_angle_unit(ANGLE_UNITS["arcsec"])
    assert len(drawn) == 2
    _printed_figures_shown(presenter, details)


def test_a_crosscal_edit_works_out_the_tilt_effect_once(qtbot, monkeypatch, samples_dir):
    """Each budget (the encoder's and the faces', with and without the certificate details,
    the faces' from face 1) took the unmeasured tilt's effect again: 72 directions of every
    mounting, 4320 evaluations of models.pyramidal, ~0.05 s each time."""
    presenter = CrossCalPresenter()
    details = _sample(qtbot, presenter, samples_dir, "crosscal")
    evaluated = _counted(monkeypatch, models.pyramidal, "pyramidal_correction_arcsec")
    shown_u = presenter.view.verdict.text()
    _typed(qtbot, presenter, 0, "ac_x_arcsec", "4.265")
    solution = presenter.result.solution
    assert solution.tilts is None or all(t is None for t in solution.tilts)
    assert len(evaluated) == 72 * len(solution.mountings)
    presenter.set_angle_unit(ANGLE_UNITS["urad"])  # shown again: no budget worked out again
    presenter.set_angle_unit(ANGLE_UNITS["arcsec"])
    assert len(evaluated) == 72 * len(solution.mountings)
    document = presenter.kind.certificate_document(presenter.result, details, "",
                                                   presenter.result_settings)
    u = next(cells[0] for name, cells in _statistics(document).items()
             if name.startswith("Expanded"))
    assert f"(U ≤ {u})" in presenter.view.verdict.text()
    assert shown_u != presenter.view.verdict.text()  # the edit's figures, not the sample's


def test_a_take_is_shown_as_printed_with_no_bootstrap_on_the_gui_thread(
        qtbot, monkeypatch, samples_dir):
    """While capturing every take is analysed on a worker; the certificate's rounding (its
    intervals with the reference standard's U, a bootstrap) was then made on the GUI thread,
    which paused for it at every take."""
    presenter = PositioningPresenter()
    details = _sample(qtbot, presenter, samples_dir, "positioning")
    rounded = _counted(monkeypatch, presenter.kind, "printed_rounding")
    drawn = _counted(monkeypatch, models.uncertainty.figure_intervals, "_ensemble")
    presenter.set_capturing(True)
    try:
        _typed(qtbot, presenter, 1, "deviation", "2.96")
    finally:
        presenter.set_capturing(False)
    assert presenter.result.deviations[1] == pytest.approx(2.96)
    gui = threading.main_thread().name
    assert rounded and gui not in rounded, rounded
    assert drawn and gui not in drawn, drawn
    _printed_figures_shown(presenter, details)


def test_the_kept_texts_hold_no_result_once_the_readings_give_none(qtbot, samples_dir):
    """The texts as printed are kept with their result (a new unit shows them again); once
    the readings give no result, they hold the last one no longer (a million-sample fringe
    result would be kept for nothing)."""
    presenter = PositioningPresenter()
    _sample(qtbot, presenter, samples_dir, "positioning")
    earlier = weakref.ref(presenter.result)
    presenter.table_model.replace_all([], "cleared")
    presenter.refresh()
    assert presenter.result is None and presenter.problem
    gc.collect()
    assert earlier() is None
