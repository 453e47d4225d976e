"""The main window's status line: a message shown is said again in the new language after
a change of language (View › Language), for the time it had left, from its source text and
arguments (widgets.i18n.said_again: ``tr(…).format(…)``, a model's message translated, two
joined); a text of no language (a message of its own, a path) stays as it is. Before, the
message stayed in the language it was shown in."""

from __future__ import annotations

import time

from PySide6.QtWidgets import QStatusBar, QWidget

from widgets.i18n import on_language_change, said_again

__all__ = ["StatusLine"]

#: the clock a message's time left is read from (a test holds it still: on a loaded machine
#: the window's own retranslation may outlast a message's seconds)
_clock = time.monotonic


class StatusLine(QStatusBar):
    """A :class:`QStatusBar` that keeps the last message shown through it (its text and
    when its time is up) to say it again after a change of language."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._shown: tuple[str, float | None] | None = None  # text, when its time is up
        self._about: object | None = None  # what the message in sight is about (show_about)
        #: messages about a workbench not in front (:meth:`show_workbench`), by id(about):
        #: (about, text, when its time is up)
        self._aside: dict[int, tuple[object, str, float | None]] = {}
        on_language_change(self, self._say_again)

    def showMessage(self, text: str, timeout: int = 0) -> None:  # noqa: N802 - Qt's name
        self._shown = (text, _clock() + timeout / 1000 if timeout > 0 else None)
        self._about = None
        super().showMessage(text, timeout)

    def show_about(self, text: str, timeout: int, about: object) -> None:
        """A message about the rows of one sheet (``about``: its view), taken away by
        :meth:`forget` when that sheet is replaced (day review 64 P7: "Row 4 … was not
        entered" stayed through File › New)."""
        self.showMessage(text, timeout)
        self._about = about

    def show_workbench(self, about: object) -> None:
        """The workbench ``about`` (its view) is in front now: a message about another
        workbench in sight is put aside with the time it had left, and one put aside about
        this one is shown again for its time left (day review 65 F11: the Positioning tab
        said "Imported …/bench_run_0512.csv", the theodolite's import)."""
        if self._about is not None and self._about is not about and self._shown is not None:
            text, until = self._shown
            if text and self.currentMessage() == text:
                self._aside[id(self._about)] = (self._about, text, until)
                self.clearMessage()
            self._shown, self._about = None, None
        kept = self._aside.pop(id(about), None)
        if kept is None or kept[0] is not about:
            return
        _about, text, until = kept
        left = 0 if until is None else round((until - _clock()) * 1000)
        if until is not None and left <= 0:
            return
        self.show_about(said_again(text), left, about)

    def forget(self, about: object) -> None:
        """The message in sight goes if it is about ``about`` (its sheet replaced), and
        one put aside about it."""
        self._aside.pop(id(about), None)
        if self._about is about and about is not None:
            if self._shown is not None and self.currentMessage() == self._shown[0]:
                self.clearMessage()
            self._shown, self._about = None, None

    def _say_again(self) -> None:
        """The message in sight in the language now installed, for the time it had left
        (one gone, or replaced from Qt itself, as a menu's tip, is not brought back)."""
        if self._shown is None:
            return
        text, until = self._shown
        if not text or self.currentMessage() != text:
            return
        again = said_again(text)
        left = 0 if until is None else round((until - _clock()) * 1000)
        if until is not None and left <= 0:
            # its time is up (the event loop has not run since to take it away): it goes
            # now, never left in sight in the language it was shown in
            self.clearMessage()
            self._shown = None
            return
        super().showMessage(again, left)
        self._shown = (again, until)
