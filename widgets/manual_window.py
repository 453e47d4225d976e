"""Help › Manual (F1): the bundled HTML manual, opened at the current workbench's page
(what to measure, how to set up, every setting, what each plot shows, how it works).

The pages are the user guides of docs/ (docs/user-guide/, docs/zh_CN/user-guide/) made into
resources/manual/ by ``make docs`` (app/manual_pages.py); they ship in the ``resources``
package, so the manual is found from an installed package too."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt, QUrl
from PySide6.QtWidgets import QTextBrowser, QVBoxLayout, QWidget

from widgets.i18n import live, tr
from widgets.screen_fit import fit_to_screen

MANUAL_DIR = Path(__file__).resolve().parent.parent / "resources" / "manual"


def manual_page(kind_key: str, language: str = "en") -> Path:
    """The page of a workbench in ``language`` (English when it has none there), or the
    manual's index when the workbench has no page."""
    for name in ((f"{kind_key}.{language}.html",) if language != "en" else ()) + (
            f"{kind_key}.html", f"index.{language}.html", "index.html"):
        if (MANUAL_DIR / name).is_file():
            return MANUAL_DIR / name
    return MANUAL_DIR / "index.html"


class ManualWindow(QWidget):
    """One window, reused: F1 again shows the page of the workbench now in front."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.setWindowFlag(Qt.WindowType.Window)
        live(self.setWindowTitle, tr("AngleBench — manual"))
        self.browser = QTextBrowser()
        self.browser.setOpenExternalLinks(True)
        self.browser.setSearchPaths([str(MANUAL_DIR)])
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.browser)
        fit_to_screen(self, 720, 760)

    def show_page(self, kind_key: str, language: str = "en") -> None:
        self.browser.setSource(QUrl.fromLocalFile(str(manual_page(kind_key, language))))
        self.show()
        self.raise_()
        self.activateWindow()
