"""One stored reference standard that does not read (a name too long, an entry that is no
object) leaves out itself only, and says which and why; the other standards, and every other
lab default, are kept. Before, one bad entry among the lab defaults' standards made
CertificateMetadata.from_dict refuse the lab defaults as a whole, and the certificate
presenter then dropped every lab default (the standards, the lab's name …) with nothing said;
one bad entry among a workbench's stored standards dropped the whole list."""

from __future__ import annotations

import json
from unittest import mock

import pytest
from PySide6.QtCore import QSettings

from app.certificate_presenter import LAB_DEFAULTS_KEY, CertificatePresenter, CertificateView

GOOD_1 = {"description": "Photoelectric autocollimator (comparator)", "serial": "AC-17",
          "uncertainty": 0.1, "basis": "U95"}
TOO_LONG = {"description": "Electronic level " + "x" * 300, "uncertainty": 0.2}
GOOD_2 = {"description": "Second autocollimator", "serial": "AC-18", "uncertainty": 0.12}
STANDARDS = [GOOD_1, TOO_LONG, "corrupt entry", GOOD_2]


@pytest.fixture
def store(tmp_path):
    """A settings store as the window's (an INI file), holding the lab defaults with one
    too-long name and one corrupt entry among the crosscal's standards."""
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    settings.setValue(LAB_DEFAULTS_KEY, json.dumps({
        "lab_name": "Precision Angle Lab", "operator": "Wang",
        "standards_by_workbench": {"crosscal": STANDARDS}}))
    settings.sync()
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


def _presenter(store, metadata=None):
    view = mock.create_autospec(CertificateView, instance=True)
    metadata = {} if metadata is None else metadata
    return CertificatePresenter(view, store, lambda: metadata, mock.Mock()), view


def test_a_bad_lab_default_standard_leaves_out_itself_only_and_says_which(store):
    presenter, view = _presenter(store)
    details = presenter.issue_details("crosscal")
    assert [s.serial for s in details.standards] == ["AC-17", "AC-18"]
    assert details.lab_name == "Precision Angle Lab" and details.operator == "Wang"
    said = view.show_status.call_args.args[0]
    assert "reference standard 2 of the lab defaults (“Electronic level xxx" in said
    assert "200" in said and "characters" in said  # why: the name's limit
    assert "reference standard 3 of the lab defaults (—)" in said and "object" in said
    assert "left out" in said
    # read again (each redraw of the plots): said once, not again
    presenter.issue_details("crosscal")
    assert view.show_status.call_count == 1
    # the certificate dialog is given them too (not marked on a row: they are not in it)
    presenter.details("crosscal")
    assert set(presenter.problems) == {"lab_defaults.standards[2]", "lab_defaults.standards[3]"}
    # stored_details (the tolerance band's) keeps the good ones as well
    presenter._metadata()["certificates"] = {"crosscal": {"item_serial": "RX-26"}}
    assert [s.serial for s in presenter.stored_details("crosscal").standards] == ["AC-17",
                                                                                  "AC-18"]


def test_a_bad_stored_standard_of_the_workbench_leaves_out_itself_only(tmp_path):
    store = QSettings(str(tmp_path / "empty.ini"), QSettings.Format.IniFormat)
    metadata = {"certificates": {"crosscal": {"lab_name": "Lab", "standards": STANDARDS}}}
    presenter, view = _presenter(store, metadata)
    details = presenter.details("crosscal")
    assert [s.serial for s in details.standards] == ["AC-17", "AC-18"]
    assert set(presenter.problems) == {"standards[2]", "standards[3]"}
    said = view.show_status.call_args.args[0]
    assert "reference standard 2 of the stored certificate details" in said
    assert "reference standard 3 of the stored certificate details (—)" in said


@pytest.mark.slow
def test_the_window_says_it_and_draws_with_the_good_ones(window, qtbot, tmp_path):
    """The window: the lab defaults' store holds the bad entries; the cross-calibration's
    sample analysed draws its bands with the two good comparators and the status bar says
    which entries were left out and why."""
    window.certificates.store.setValue(LAB_DEFAULTS_KEY, json.dumps({
        "lab_name": "Precision Angle Lab", "standards_by_workbench": {"crosscal": STANDARDS}}))
    crosscal = window.presenter("crosscal")
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    crosscal.load_sample()
    qtbot.waitUntil(lambda: "reference standard 2 of the lab defaults"
                    in window.statusBar().currentMessage(), timeout=3000)
    assert "reference standard 3" in window.statusBar().currentMessage()
    details = window.certificates.issue_details("crosscal")
    assert [s.serial for s in details.standards] == ["AC-17", "AC-18"]
