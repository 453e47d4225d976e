"""The window's compensation export (outside review comp75, F1/F2): the controller-options
form, where the table is decided, says that its positions are machine coordinates; the
status after a HEIDENHAIN export names the .CMA written beside the .COM and what the user
must know of the table."""

from __future__ import annotations

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication, QDialog, QLabel

from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from widgets.positioning.view import PositioningView

KIND = KINDS["positioning"]


def test_the_controller_options_form_says_the_positions_are_machine_coordinates(qtbot):
    view = PositioningView()
    qtbot.addWidget(view)
    seen = {}

    def look():
        dialog = next(w for w in QApplication.topLevelWidgets()
                      if isinstance(w, QDialog) and w.isVisible())
        label = dialog.findChild(QLabel, "machine_coordinates")
        seen["text"] = label.text() if label is not None else ""
        seen["shown"] = label is not None and label.isVisible()
        dialog.reject()

    QTimer.singleShot(0, look)
    assert view.ask_controller_options("HEIDENHAIN TNC", [("axis", "axis key", "X")]) is None
    assert seen["shown"]
    assert seen["text"] == ("Targets must be machine coordinates: a log in a work offset gives a "
                            "shifted table.")


def test_a_heidenhain_export_names_the_cma_and_the_notes_in_the_status(presenter_and_view,
                                                                       samples_dir, tmp_path):
    presenter, view = presenter_and_view
    presenter.table_model.replace_all(map_columns(read_table(samples_dir / KIND.sample_file),
                                                  KIND.columns))
    presenter.set_settings({**presenter.settings, "compensation_format": "heidenhain",
                            "compensation_tables": "separate",
                            "compensation_controller_options": "axis=C, values=error, modulo=360"})
    presenter.refresh()
    presenter.export_compensation(str(tmp_path / "axis.txt"))
    title, text = view.tell.call_args.args
    assert title == "Cannot export the compensation table" and "name it axis.COM" in text
    assert not list(tmp_path.iterdir())
    presenter.export_compensation(str(tmp_path / "AXIS.COM"))
    status = view.show_status.call_args.args[0]
    assert f"with its .CMA assignment in {tmp_path / 'AXIS.CMA'} written" in status
    assert "taken as machine coordinates" in status and "\n" not in status
    assert sorted(p.name for p in tmp_path.iterdir()) == ["AXIS.CMA", "AXIS.COM"]
