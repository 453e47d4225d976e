"""File › Overlay a run…: another run of the same workbench drawn against today's (a
readings file, a project file or a certificate in the register), and its removal.

The window's part of models/run_overlay.py and widgets/run_overlay.py: which file or
record, the messages when it cannot be drawn. Dialogs go through ``choose_file`` and
``choose_record`` so tests can answer them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from PySide6.QtWidgets import QInputDialog

from models.run_overlay import overlay_from_file, overlay_from_project_json
from models.workbench import OverlaysRuns
from widgets.i18n import declared, explained, tr
from widgets.open_file import ask_open_file
from widgets.run_overlay import RunOverlay

__all__ = ["RunOverlayActions"]


class RunOverlayActions:
    """The overlays of one main window's workbenches (made when first asked for)."""

    def __init__(self, window: Any) -> None:
        self.window = window
        self.overlays: dict[str, RunOverlay] = {}

    # -- dialogs (tests replace these) ---------------------------------------------
    def choose_file(self) -> str:
        return ask_open_file(
            self.window, tr("Overlay a run on {workbench}").format(
                workbench=declared(self.window.current.kind.title)), self.window.projects.last_dir(),
            tr("Readings or project (*.csv *.txt *.xlsx *.xlsm *.json);;All files (*)"))

    def choose_record(self, labels: list[str]) -> int | None:
        label, ok = QInputDialog.getItem(self.window, tr("Overlay a certificate"),
                                         tr("Certificate of this workbench:"), labels, 0, False)
        return labels.index(label) if ok and label in labels else None

    # -- the overlay of the current workbench ---------------------------------------
    def overlay(self, presenter: Any | None = None) -> RunOverlay | None:
        """The current workbench's overlay, or None (and the user told) where it has no error
        curve to overlay."""
        presenter = presenter or self.window.current
        key = presenter.kind.key
        # OverlaysRuns.view_needs: its view has the panel (the contract test checks each)
        if not isinstance(presenter.kind, OverlaysRuns):
            self.window.tell(tr("Cannot overlay"), tr("{workbench} has no error curve to overlay a "
                                                      "run on.").format(
                workbench=declared(presenter.kind.title)))
            return None
        if key not in self.overlays:
            self.overlays[key] = RunOverlay(presenter)
        return self.overlays[key]

    def overlay_file(self, path: str | Path | None = None) -> bool:
        """Overlay the run in a readings file (analysed with today's settings) or a project
        file (with its own). On the positioning workbench: the log after compensation."""
        if hasattr(self.window.current, "after_compensation"):
            return self.compare_after_compensation(path)
        overlay = self.overlay()
        if overlay is None:
            return False
        path = path or self.choose_file()
        if not path:
            return False
        presenter = self.window.current
        try:
            run = overlay_from_file(presenter.kind, path, presenter.settings)
        except ValueError as exc:
            self.window.tell(tr("Cannot overlay"), explained(exc))
            return False
        overlay.show(run)
        return True

    def compare_after_compensation(self, path: str | Path | None = None) -> bool:
        """The positioning log measured after compensation drawn over today's, with A, B, E
        before → after in the results text (widgets/positioning/before_after.py)."""
        presenter = self.window.current
        path = path or self.choose_file()
        if not path:
            return False
        try:
            after = presenter.kind.after_log(path, presenter.settings)
        except (ValueError, OSError) as exc:
            self.window.tell(tr("Cannot overlay"), explained(exc))
            return False
        presenter.after_compensation.show(after, Path(path).name)
        return True

    def overlay_record(self) -> bool:
        """Overlay a certificate of this workbench from the register (the same instrument's
        first), analysed from the readings and settings it was issued with."""
        overlay = self.overlay()
        if overlay is None:
            return False
        presenter = self.window.current
        key = presenter.kind.key
        try:
            with self.window.certificates.open_register() as register:
                records = [r for r in register.list() if r.workbench == key]
        except Exception as exc:  # noqa: BLE001 - any register failure is told, not raised
            self.window.tell(tr("Cannot overlay"), explained(exc))
            return False
        if not records:
            self.window.tell(tr("Cannot overlay"), tr("The register holds no certificate of "
                                                      "{workbench}.").format(
                workbench=declared(presenter.kind.title)))
            return False
        serial = str(self.window.certificates.details(key).item_serial or "")
        records = ([r for r in records if r.item_serial == serial] +
                   [r for r in records if r.item_serial != serial])
        labels = [f"{r.number} — {r.item_serial} — {r.calibration_date}" for r in records]
        chosen = self.choose_record(labels)
        if chosen is None:
            return False
        record = records[chosen]
        try:
            run = overlay_from_project_json(presenter.kind, record.project_json,
                                            f"{record.number} ({record.calibration_date})")
        except ValueError as exc:
            self.window.tell(tr("Cannot overlay"), explained(exc))
            return False
        overlay.show(run)
        return True

    def remove(self) -> None:
        after = getattr(self.window.current, "after_compensation", None)
        if after is not None:
            after.remove()
        overlay = self.overlays.get(self.window.current.kind.key)
        if overlay is not None:
            overlay.remove()
