"""The status line after a change of language (View › Language): its message is said again
in the new language, from its source text and arguments, for the time it had left. Before,
it kept the language it was shown in ("Imported polygon_sample.csv: 50 row(s) …" in the
Chinese window) until the next message."""

from __future__ import annotations

import re

import pytest
from PySide6.QtCore import Qt

from models.messages import QT_TR_NOOP, message
from widgets import status_line
from widgets.i18n import tr, translated

HAN = re.compile(r"[\u4e00-\u9fff]")


def choose_language(window, key: str) -> None:
    """View › Language › ``key``, as the user picks it."""
    action = next(a for a in window.menus.language_actions.actions() if a.data() == key)
    action.trigger()


@pytest.fixture
def switched_back(window, monkeypatch):
    """The window, its language set back to English after the test; the status line's clock
    held still (a loaded machine's retranslation of every workbench may take longer than a
    message's seconds: the message is then cleared, as its time is up)."""
    now = status_line._clock()
    monkeypatch.setattr(status_line, "_clock", lambda: now)
    yield window
    choose_language(window, "en")


def test_a_message_is_said_again_in_the_language_chosen(switched_back, samples_dir):
    window = switched_back
    window.tabs.setCurrentIndex(1)
    assert window.import_file(samples_dir / "polygon_sample.csv")  # File › Import, as typed
    said = window.statusBar().currentMessage()
    assert said.startswith(f"Imported {samples_dir / 'polygon_sample.csv'} (Edit › Undo")
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert chinese == f"已导入 {samples_dir / 'polygon_sample.csv'}（编辑 › 撤销 可恢复原读数）", chinese
    choose_language(window, "en")
    assert window.statusBar().currentMessage() == said  # and back, the same figures


def test_a_message_of_translated_parts_is_said_again_whole(switched_back):
    """A model's message as an argument, and a second text joined to the first (the
    certificate's "…; its DCC written to …")."""
    window = switched_back
    what = translated(message(QT_TR_NOOP("Readings")))
    window.statusBar().showMessage(tr("{what} written").format(what=what)
                                   + tr("; its DCC (validated) written to {path}").format(path="/tmp/a.xml"),
                                   8000)
    assert window.statusBar().currentMessage() == ("Readings written; its DCC (validated) written "
                                                   "to /tmp/a.xml")
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert chinese.endswith("/tmp/a.xml") and "written" not in chinese, chinese
    assert not re.search(r"[A-Za-z]{4,}", chinese.replace("/tmp/a.xml", "")), chinese
    assert HAN.search(chinese), chinese


def test_the_message_keeps_the_time_it_had_left(switched_back, qtbot):
    window = switched_back
    window.load_all_samples()
    assert window.statusBar().currentMessage() == "Bundled samples loaded in every workbench"
    choose_language(window, "zh_CN")
    assert window.statusBar().currentMessage() == "已在每个工作台载入自带示例"
    window.statusBar().showMessage(tr("Printed"), 4000)
    choose_language(window, "en")
    assert window.statusBar().currentMessage() == "Printed"
    # then gone when its time is up (not made a message that stays)
    qtbot.waitUntil(lambda: window.statusBar().currentMessage() == "", timeout=15000)



def test_a_message_whose_time_is_up_goes_with_the_language_it_was_shown_in(window, monkeypatch):
    """Its seconds over while the window was busy (the event loop not yet run to take it
    away): a change of language clears it, never leaves it in the old language."""
    window.statusBar().showMessage(tr("Printed"), 4000)
    later = status_line._clock() + 5.0
    monkeypatch.setattr(status_line, "_clock", lambda: later)
    choose_language(window, "zh_CN")
    try:
        assert window.statusBar().currentMessage() == ""
    finally:
        choose_language(window, "en")


def test_what_was_typed_and_not_entered_is_said_again(switched_back, qtbot):
    """A take into the cell being typed in: "Row 3, AC x ["] was changed to “19.25” while
    you were typing in it; …" is said again in Chinese after View › Language, and back
    (day review 64 P6: it stayed in English; the table's signal gave the status line a
    plain copy of the message)."""
    from tests.widgets.test_typing_survives_repaints import _start_typing

    window = switched_back
    bench = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(bench))
    bench.load_sample()
    column = [c.key for c in bench.sheet.columns].index("ac_x_arcsec")
    _start_typing(qtbot, bench, 2, column, "21.7")
    bench.table_model.set_cells([(2, column, "19.25")], "Take reading (row 3)")
    said = window.statusBar().currentMessage()
    assert said.startswith("Row 3, AC x") and "“19.25”" in said and "“21.7”" in said, said
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert chinese.startswith("第 3 行 ") and "“19.25”" in chinese and "未被确认" in chinese, \
        chinese
    assert "typing" not in chinese and "AC x" not in chinese, chinese
    choose_language(window, "en")
    assert window.statusBar().currentMessage() == said


def test_an_import_message_belongs_to_its_workbench(switched_back, samples_dir, qtbot):
    """Day review 65 F11: after switching tabs the status line said another workbench's
    import ("已导入 …/bench_run_0512.csv" on the Positioning tab, the theodolite's). The
    message is put aside on another tab and shown again on its own, for its time left."""
    window = switched_back
    window.show()
    qtbot.waitExposed(window)
    theodolite = window.presenter("theodolite")
    positioning = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(theodolite))
    assert window.import_file(samples_dir / theodolite.kind.sample_file)
    assert "Imported" in window.statusBar().currentMessage()
    bar = window.tabs.tabBar()

    def click_tab(presenter) -> None:
        index = window.presenters.index(presenter)
        qtbot.mouseClick(bar, Qt.MouseButton.LeftButton, pos=bar.tabRect(index).center())
        assert window.tabs.currentIndex() == index

    click_tab(positioning)
    assert "Imported" not in window.statusBar().currentMessage()
    assert theodolite.kind.sample_file not in window.statusBar().currentMessage()
    click_tab(theodolite)
    assert theodolite.kind.sample_file in window.statusBar().currentMessage()
    # in the language chosen meanwhile, on the other tab
    click_tab(positioning)
    choose_language(window, "zh_CN")
    assert window.statusBar().currentMessage() == ""
    click_tab(theodolite)
    shown = window.statusBar().currentMessage()
    assert theodolite.kind.sample_file in shown and HAN.search(shown), shown
    # a file read in while another tab is in front says so on its own tab only
    window.import_file(samples_dir / positioning.kind.sample_file, "positioning")
    assert positioning.kind.sample_file not in window.statusBar().currentMessage()
    click_tab(positioning)
    assert positioning.kind.sample_file in window.statusBar().currentMessage()


def test_a_refusal_to_export_is_said_again_in_the_language_chosen(switched_back):
    """File › Export certificate with no result, then View › Language › 中文: the refusal
    in the status line is said again in Chinese (day review live76 F5: "Polygon encoder
    test: 0 usable readings; …" stayed English, an f-string of its translated parts)."""
    window = switched_back
    window.tell = lambda title, text: window.statusBar().showMessage(text, 15000)
    bench = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(bench))
    bench.table_model.replace_all([], "empty")
    bench.analyse_if_due()
    assert window._current_result() is None
    said = window.statusBar().currentMessage()
    assert said == ("Polygon encoder test: 0 usable readings; a polygon test needs at least 3 "
                    "positions."), said
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert HAN.search(chinese) and "Polygon" not in chinese, chinese
    assert not re.search(r"[A-Za-z]{4,}", chinese), chinese
    choose_language(window, "en")
    assert window.statusBar().currentMessage() == said


def test_words_joined_are_said_again_each(switched_back):
    """A list of translated texts joined (a draft's missing details, the standards left
    out) is said again in the new language, not kept as one plain text."""
    from widgets.i18n import joined

    window = switched_back
    window.statusBar().showMessage(joined("; ", [tr("Printed"), "/tmp/a.pdf"]), 8000)
    assert window.statusBar().currentMessage() == "Printed; /tmp/a.pdf"
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert chinese.endswith("; /tmp/a.pdf") and "Printed" not in chinese and HAN.search(chinese), \
        chinese


def test_the_compensation_tables_message_follows_the_language(switched_back, samples_dir,
                                                              tmp_path):
    """After Export compensation table… (the model's message split into lines, joined as
    plain text) the status line stayed English in the Chinese window (gui77 item 3)."""
    window = switched_back
    presenter = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.import_file(samples_dir / "positioning_sample.csv")
    presenter.refresh()
    assert presenter.result is not None, presenter.problem
    path = tmp_path / "compensation.csv"
    assert presenter.export_compensation(str(path))
    assert path.exists()
    english = window.statusBar().currentMessage()
    assert english.startswith("Compensation table") and " written" in english, english
    choose_language(window, "zh_CN")
    chinese = window.statusBar().currentMessage()
    assert HAN.search(chinese), chinese
    assert "written" not in chinese and "Compensation" not in chinese, chinese
    assert not re.search(r"[A-Za-z]{5,}", chinese), chinese
    choose_language(window, "en")
    assert window.statusBar().currentMessage() == english  # and back, the same text
