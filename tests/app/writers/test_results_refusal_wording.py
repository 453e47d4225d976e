"""A refused export of results says what was refused, the results, not a certificate (day
review 67 F9: an export of results of a run with one approach per target was refused with
"… no certificate is issued", although no certificate was asked for)."""

from __future__ import annotations


def test_a_refused_export_of_results_says_no_results_were_written(window, tmp_path, qtbot,
                                                                   samples_dir):
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.import_file(samples_dir / polygon.kind.sample_file, sample=True)
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    assert window.send_to_positioning(), window.told
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    path = tmp_path / "results.xlsx"
    window.certificates.view.choose_save_path = lambda title, suggested, kinds: str(path)
    window.told.clear()
    # one forward approach per target: its repeatability, part of U, is unknown
    assert not window.export_results()
    assert not path.exists()
    said = " ".join(window.told)
    assert "approached fewer than twice" in said, said
    assert "certificate" not in said, said
    assert str(path) in said and "No results were written" in said, said
