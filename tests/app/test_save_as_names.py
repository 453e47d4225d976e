"""The name written by a save or export dialog is the name the overwrite question was asked
about (s62). The file dialog asks whether to replace the name typed ("run3"); the extension
the window adds afterwards ("run3.anglebench.json") named a colleague's file that was then
replaced unasked. The file dialog is modal (not driven offscreen): its answer is patched;
the code that adds the extension and asks is the window's own."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QMessageBox

from models.project.file import load_project
from widgets import plot_image, save_file
from widgets.save_file import with_filter_suffix

pytestmark = pytest.mark.slow  # a window

Button = QMessageBox.StandardButton
PROJECT = "AngleBench project (*.anglebench.json *.json)"


class Dialog:
    """The file dialog (widgets.save_file.choose_save_file) answering ``answers`` in turn
    ("" once they are used up: cancelled), recording what it was offered."""

    def __init__(self, *answers):
        self.answers, self.offered = list(answers), []

    def __call__(self, _parent, _title, suggested, _filters, *_rest, **_kwargs):
        self.offered.append(suggested)
        return self.answers.pop(0) if self.answers else ("", "")


class Asked:
    """The window's ``ask``: records the questions, answers ``answer``."""

    def __init__(self, answer):
        self.answer, self.questions = answer, []

    def __call__(self, title, text, _buttons, default):
        self.questions.append((title, text, default))
        return self.answer


def test_the_extension_added_to_the_name_is_the_chosen_types():
    assert with_filter_suffix("/x/run3", PROJECT, PROJECT) == "/x/run3.anglebench.json"
    assert with_filter_suffix("/x/run3.json", PROJECT, PROJECT) == "/x/run3.json"
    assert with_filter_suffix("/x/RUN3.JSON", PROJECT, PROJECT) == "/x/RUN3.JSON"
    assert with_filter_suffix("/x/run3.v2", PROJECT, PROJECT) == "/x/run3.v2.anglebench.json"
    both = "CSV (*.csv);;Excel workbook (*.xlsx)"
    assert with_filter_suffix("/x/out", "Excel workbook (*.xlsx)", both) == "/x/out.xlsx"
    assert with_filter_suffix("/x/out.csv", "Excel workbook (*.xlsx)", both) == "/x/out.csv"
    assert with_filter_suffix("/x/out", "", both) == "/x/out.csv"  # no type said: the first
    assert with_filter_suffix("", "CSV (*.csv)", both) == ""
    controller = "Controller compensation file (*.COM);;All files (*)"
    assert with_filter_suffix("/x/AXIS", "Controller compensation file (*.COM)",
                              controller) == "/x/AXIS.COM"
    assert with_filter_suffix("/x/axis", "All files (*)", controller) == "/x/axis"


def _colleagues_project(window, tmp_path):
    """A project of someone else's, run3.anglebench.json, beside this window's readings."""
    window.load_all_samples()
    theirs = tmp_path / "run3.anglebench.json"
    window.presenter("theodolite").table_model.set_cells([(0, 1, "11.11")])
    assert window.projects.save_to(theirs)
    window.projects.path = None  # this window's own work, not yet saved
    window.presenter("theodolite").table_model.set_cells([(0, 1, "22.22")])
    return theirs, theirs.read_bytes()


def test_save_as_run3_does_not_replace_run3_anglebench_json_unasked(window, tmp_path,
                                                                   monkeypatch):
    theirs, before = _colleagues_project(window, tmp_path)
    dialog, asked = Dialog((str(tmp_path / "run3"), PROJECT)), Asked(Button.No)
    monkeypatch.setattr(save_file, "choose_save_file", dialog)
    window.ask = asked
    window.menus.save_as_action.trigger()
    assert theirs.read_bytes() == before  # the colleague's work is still there
    assert len(asked.questions) == 1
    title, text, default = asked.questions[0]
    assert title == "Replace the file?" and default == Button.No
    assert text == f"run3.anglebench.json already exists in {tmp_path}.\n\nReplace it?"
    # No: the dialog again, with the name that was asked about; cancelled there
    assert dialog.offered[1] == str(theirs)
    assert window.projects.path is None and window.projects.is_modified
    assert not list(tmp_path.glob("run3*.json.*"))  # no temporary file left either


def test_save_as_run3_replaces_run3_anglebench_json_when_told_to(window, tmp_path,
                                                                monkeypatch):
    theirs, before = _colleagues_project(window, tmp_path)
    dialog, asked = Dialog((str(tmp_path / "run3"), PROJECT)), Asked(Button.Yes)
    monkeypatch.setattr(save_file, "choose_save_file", dialog)
    window.ask = asked
    window.menus.save_as_action.trigger()
    assert len(asked.questions) == 1 and len(dialog.offered) == 1
    assert theirs.read_bytes() != before
    assert load_project(theirs).workbenches["theodolite"].rows[0][1] == "22.22"
    assert window.projects.path == theirs and not window.projects.is_modified


def test_a_name_the_dialog_asked_about_is_not_asked_again(window, tmp_path, monkeypatch):
    """The file dialog asked about run3.anglebench.json itself (typed in full), or no file
    of the longer name is there: no second question."""
    theirs, _ = _colleagues_project(window, tmp_path)
    asked = Asked(Button.No)
    window.ask = asked
    monkeypatch.setattr(save_file, "choose_save_file", Dialog((str(theirs), PROJECT)))
    assert window.projects.save_as()
    assert load_project(theirs).workbenches["theodolite"].rows[0][1] == "22.22"
    monkeypatch.setattr(save_file, "choose_save_file", Dialog((str(tmp_path / "run4"), PROJECT)))
    assert window.projects.save_as()
    assert (tmp_path / "run4.anglebench.json").exists() and asked.questions == []


def test_exported_results_named_without_extension_ask_before_replacing(window, tmp_path,
                                                                      monkeypatch):
    window.load_all_samples()
    theirs = tmp_path / "results.xlsx"
    theirs.write_bytes(b"a colleague's workbook")
    chosen = (str(tmp_path / "results"), "Excel workbook (*.xlsx)")
    window.ask = asked = Asked(Button.No)
    monkeypatch.setattr(save_file, "choose_save_file", Dialog(chosen))
    assert not window.export_results()
    assert theirs.read_bytes() == b"a colleague's workbook"
    assert asked.questions[0][1].startswith("results.xlsx already exists in ")
    window.ask = Asked(Button.Yes)
    monkeypatch.setattr(save_file, "choose_save_file", Dialog(chosen))
    assert window.export_results()
    assert theirs.read_bytes()[:2] == b"PK"  # replaced by the workbook, when told to


def test_an_exported_certificate_named_without_pdf_asks_before_replacing(window, tmp_path,
                                                                        monkeypatch):
    window.load_all_samples()
    theirs = tmp_path / "AB-1.pdf"
    theirs.write_bytes(b"%PDF- a colleague's certificate")
    window.ask = asked = Asked(Button.No)
    monkeypatch.setattr(save_file, "choose_save_file",
                        Dialog((str(tmp_path / "AB-1"), "PDF (*.pdf)")))
    path = window.certificates.view.choose_save_path("Export certificate", "x.pdf", "PDF (*.pdf)")
    assert path == "" and len(asked.questions) == 1
    assert theirs.read_bytes() == b"%PDF- a colleague's certificate"


@pytest.mark.parametrize("answer", [Button.No, Button.Yes])
def test_a_plot_image_named_without_png_asks_before_replacing(window, tmp_path, monkeypatch,
                                                              answer):
    theirs = tmp_path / "plot.png"
    theirs.write_bytes(b"a colleague's picture")
    questions = []

    def question(parent, title, text, buttons, default):
        questions.append((parent, title, text, default))
        return answer

    monkeypatch.setattr(QMessageBox, "question", question)
    monkeypatch.setattr(save_file, "choose_save_file",
                        Dialog((str(tmp_path / "plot"), "PNG image (*.png)")))
    plot = window.presenter("theodolite").view.error_plot
    plot_image._save_image(plot, "Error")
    assert [(q[0], q[1], q[3]) for q in questions] == [(plot, "Replace the file?", Button.No)]
    assert questions[0][2] == f"plot.png already exists in {tmp_path}.\n\nReplace it?"
    replaced = theirs.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert replaced is (answer == Button.Yes)


def test_the_fringe_table_gets_the_chosen_types_extension_and_asks(window, qtbot, tmp_path,
                                                                   monkeypatch):
    """C header chosen, "lut" typed: lut.h (a CSV named "lut" before), asked about."""
    fringe = window.presenter("fringe")
    fringe.load_sample()
    qtbot.waitUntil(lambda: fringe.result is not None)
    theirs = tmp_path / "lut.h"
    theirs.write_text("/* a colleague's table */")
    answers = [Button.No, Button.Yes]
    monkeypatch.setattr(QMessageBox, "question", lambda *_a: answers.pop(0))
    typed = (str(tmp_path / "lut"), "C header (*.h)")
    monkeypatch.setattr(save_file, "choose_save_file", Dialog(typed))
    qtbot.mouseClick(fringe.view.export_button, Qt.MouseButton.LeftButton)
    assert theirs.read_text() == "/* a colleague's table */" and not (tmp_path / "lut").exists()
    monkeypatch.setattr(save_file, "choose_save_file", Dialog(typed))
    qtbot.mouseClick(fringe.view.export_button, Qt.MouseButton.LeftButton)
    assert theirs.read_text().startswith("/* AngleBench fringe correction table")
    assert answers == [] and not (tmp_path / "lut").exists()
