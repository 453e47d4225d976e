"""The main window's menu bar (File, Edit, View, Instrument, Help): every action with its
shortcut and status tip in the window's language, and what the menus show of the window's
state — the undo and redo texts, the angle unit and the language checked, the recent
files (app/project_dialogs.py fills them), whether the workbench in front can send its
run to the positioning workbench.

The actions call the window and its presenters; the menus decide nothing."""

from __future__ import annotations

from typing import Any

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import QMenu

from app.capture.signal_live import open_live_signals
from app.reference_sender import receiver_of, send_reference
from models.display_units import ANGLE_UNITS
from models.workbench import JudgesSignals, SendsRuns
from widgets.i18n import LANGUAGES, Tr, declared, live, tr
from widgets.shortcuts import key_sequences

__all__ = ["MainMenus"]


class MainMenus:
    """The menus of ``window`` (the main window: its presenters, ``projects``,
    ``certificates``, ``run_overlays``, ``capture_panel`` and ``undo_group``)."""

    def __init__(self, window: Any) -> None:
        self.window = window
        bar = window.menuBar()
        self._file_menu(self._menu(bar, tr("&File")))
        self._edit_menu(self._menu(bar, tr("&Edit")))
        self._view_menu(self._menu(bar, tr("&View")))
        instrument_menu = self._menu(bar, tr("&Instrument"))
        panel = window.capture_panel
        self.connect_instrument_action = self._action(
            instrument_menu, tr("&Connect…"),
            lambda: (panel.show(), panel.connect_dialog(0)))
        self.connect_second_action = self._action(
            instrument_menu, tr("Connect a &second instrument…"),
            lambda: (panel.show(), panel.connect_dialog(1)),
            tip=tr("e.g. the encoder's readout beside the autocollimator: one take fills the "
                   "row from both"))
        self.disconnect_instrument_action = self._action(
            instrument_menu, tr("&Disconnect"), lambda: panel.disconnect_instrument())
        instrument_menu.addSeparator()
        self.demonstration_action = self._action(
            instrument_menu, tr("D&emonstration instrument…"),
            lambda: (panel.show(), panel.demonstration_dialog()),
            tip=tr("A simulated autocollimator, theodolite or readout, for training and for "
                   "trying the program without hardware"))
        self.live_signals_action = self._action(
            instrument_menu, tr("&Live signals…"), lambda: open_live_signals(window),
            tip=tr("A read head's sin/cos signals live against the interface's tolerances "
                   "while it is mounted (fringe workbench)"))
        self.live_signals_action.setEnabled(any(
            isinstance(p.kind, JudgesSignals) for p in window.presenters))
        self.show_panel_action = panel.toggleViewAction()
        live(self.show_panel_action.setText, tr("Show the instrument &panel"))
        instrument_menu.addAction(self.show_panel_action)
        help_menu = self._menu(bar, tr("&Help"))
        self._action(help_menu, tr("&Manual (this workbench)"), window.show_manual,
                     QKeySequence.StandardKey.HelpContents,
                     tip=tr("What to measure, how to set up, every setting and plot"))
        self._action(help_menu, tr("&Quick guide"), window.show_guide)
        self._action(help_menu, tr("&About AngleBench"), window.show_about)
        window.tabs.currentChanged.connect(self._enable_send)
        self._enable_send(window.tabs.currentIndex())

    def _menu(self, parent, title: Tr) -> QMenu:
        menu = parent.addMenu(title)
        live(menu.setTitle, title)
        return menu

    def _action(self, menu, text: Tr, slot, shortcut=None, tip: Tr | str = "") -> QAction:
        action = QAction(text, self.window)
        live(action.setText, text)
        if shortcut is not None:
            action.setShortcuts(key_sequences(shortcut))
        if isinstance(tip, Tr):
            live(action.setStatusTip, tip)
        action.triggered.connect(slot)
        menu.addAction(action)
        return action

    def _file_menu(self, file_menu: QMenu) -> None:
        window, projects, overlays = self.window, self.window.projects, self.window.run_overlays
        self.new_action = self._action(file_menu, tr("&New"), projects.new_project,
                                       QKeySequence.StandardKey.New)
        self.open_action = self._action(file_menu, tr("&Open…"), projects.open_project_dialog,
                                        QKeySequence.StandardKey.Open)
        self.recent_menu = self._menu(file_menu, tr("Open &recent"))
        self.save_action = self._action(file_menu, tr("&Save"), projects.save,
                                        QKeySequence.StandardKey.Save)
        self.save_as_action = self._action(file_menu, tr("Save &as…"), projects.save_as,
                                           QKeySequence.StandardKey.SaveAs)
        file_menu.addSeparator()
        self.import_action = self._action(file_menu, tr("&Import CSV/XLSX…"), window.import_dialog,
                                          QKeySequence("Ctrl+Shift+I"),
                                          tr("Replace the current workbench's readings with a "
                                             "file's"))
        self.sample_action = self._action(file_menu, tr("Load bundled &sample"), window.load_sample)
        self.export_action = self._action(
            file_menu, tr("&Export certificate…"), window.export_certificate, QKeySequence("Ctrl+E"),
            tr("Write the current workbench's test certificate (PDF)"))
        self.export_results_action = self._action(
            file_menu, tr("Export &results (CSV/XLSX)…"), window.export_results,
            tip=tr("Write every point's raw, correction, corrected error and U"))
        self.register_action = self._action(
            file_menu, tr("Certificate re&gister…"), window.show_register,
            tip=tr("Every issued certificate: search, verify a PDF, amend, an instrument's "
                   "history"))
        self.send_action = self._action(
            file_menu, tr("Send to &positioning"), window.send_to_positioning,
            tip=tr("Judge this run to ISO 230-2 / VDI 3441 in the positioning workbench (its "
                   "readings are replaced; Edit > Undo there restores them)"))
        self.send_reference_action = self._action(
            file_menu, tr("Send as &reference"), lambda: send_reference(window),
            tip=tr("Send this result to the workbench that reads with it as its reference, with "
                   "its U (the polygon's face deviations from face 1 to the polygon workbench)"))
        self.overlay_action = self._action(
            file_menu, tr("O&verlay a run…"), lambda: overlays.overlay_file(),
            tip=tr("Draw another run of this workbench against today's: a readings or project "
                   "file (before/after compensation …)"))
        self.overlay_record_action = self._action(
            file_menu, tr("Overlay a certificate from the register…"),
            lambda: overlays.overlay_record(),
            tip=tr("Draw this instrument's earlier certificate against today's run"))
        self.remove_overlay_action = self._action(
            file_menu, tr("Remove the overlaid run"), lambda: overlays.remove())
        file_menu.addSeparator()
        self.print_action = self._action(
            file_menu, tr("&Print…"), window.print_dialog, QKeySequence.StandardKey.Print,
            tr("Print the current workbench's result and plot (the certificate is the PDF)"))
        file_menu.addSeparator()
        self._action(file_menu, tr("&Quit"), window.close, QKeySequence.StandardKey.Quit)

    def _edit_menu(self, edit_menu: QMenu) -> None:
        window, group = self.window, self.window.undo_group
        # our own actions, not QUndoGroup's: theirs keep the prefix of the language they
        # were made in ("Undo Paste 3 rows" stays English in a Chinese window)
        undo = QAction(window)
        undo.triggered.connect(group.undo)
        undo.setShortcuts(key_sequences(QKeySequence.StandardKey.Undo))
        redo = QAction(window)
        redo.triggered.connect(group.redo)
        redo.setShortcuts(key_sequences(QKeySequence.StandardKey.Redo, "Ctrl+Shift+Z", "Ctrl+Y"))
        edit_menu.addAction(undo)
        edit_menu.addAction(redo)
        self.undo_action, self.redo_action = undo, redo
        for signal in (group.undoTextChanged, group.redoTextChanged, group.canUndoChanged,
                       group.canRedoChanged, group.activeStackChanged):
            signal.connect(self.update_undo_actions)
        self.update_undo_actions()
        edit_menu.addSeparator()
        self._action(edit_menu, tr("&Copy"), lambda: window.current.view.table.copy_selection())
        self._action(edit_menu, tr("&Paste"), lambda: window.current.view.table.paste())
        self._action(edit_menu, tr("&Insert row"), lambda: window.current.view.table.insert_row())
        self._action(edit_menu, tr("&Delete rows"), lambda: window.current.view.table.delete_rows())

    def _view_menu(self, view_menu: QMenu) -> None:
        window = self.window
        for text, keys, step in ((tr("&Next workbench"), ("Ctrl+PgDown", "Ctrl+Tab"), 1),
                                 (tr("&Previous workbench"), ("Ctrl+PgUp", "Ctrl+Shift+Tab"),
                                  -1)):
            action = self._action(view_menu, text, lambda _=False, s=step: window.switch_tab(s))
            action.setShortcuts(key_sequences(*keys))
            action.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        focus = self._action(view_menu, tr("Next &pane (table, set-up, result, plots)"),
                             window.focus_next_pane, QKeySequence("F6"))
        focus.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        units_menu = self._menu(view_menu, tr("Angle &unit of results"))
        self.angle_unit_actions = QActionGroup(window)
        for unit in ANGLE_UNITS.values():
            action = self._action(units_menu, declared(unit.name),
                                  lambda _=False, u=unit: window.set_angle_unit(u),
                                  tip=tr("Plots, figures, texts and exported results in this "
                                         "unit (certificates keep the unit of the evaluation)"))
            action.setCheckable(True)
            action.setData(unit.key)
            self.angle_unit_actions.addAction(action)
        language_menu = self._menu(view_menu, tr("&Language"))
        self.language_actions = QActionGroup(window)
        for key, name in LANGUAGES.items():
            action = self._action(language_menu, tr(name) if key == "system" else Tr(name, name),
                                  lambda _=False, k=key: window.set_language(k))
            action.setCheckable(True)
            action.setData(key)
            self.language_actions.addAction(action)

    # -- what the menus show ------------------------------------------------------------
    @staticmethod
    def check(group: QActionGroup, key: str) -> None:
        """The action of ``key`` (an angle unit's or a language's) checked, the others not."""
        for action in group.actions():
            action.setChecked(action.data() == key)

    def update_undo_actions(self, *_args) -> None:
        group = self.window.undo_group
        what = group.undoText()
        self.undo_action.setText(tr("&Undo {what}").format(what=what) if what else tr("&Undo"))
        self.undo_action.setEnabled(group.canUndo())
        what = group.redoText()
        self.redo_action.setText(tr("&Redo {what}").format(what=what) if what else tr("&Redo"))
        self.redo_action.setEnabled(group.canRedo())

    def _enable_send(self, index: int) -> None:
        presenters = self.window.presenters
        presenter = presenters[index] if 0 <= index < len(presenters) else None
        self.send_action.setEnabled(presenter is not None
                                    and isinstance(presenter.kind, SendsRuns))
        self.send_reference_action.setEnabled(presenter is not None
                                              and receiver_of(self.window, presenter) is not None)
