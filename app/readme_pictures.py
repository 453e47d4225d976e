"""Regenerate the README pictures: python -m app.readme_pictures

The workbench screenshots come from ``anglebench --screenshot``; the first page
of the validation report from ``anglebench validate --pdf``; each sample
certificate is written by the CLI with its example details
(``resources/samples/certificate_*.json``), its first three pages rendered by
poppler's ``pdftoppm`` (Debian: poppler-utils) and laid side by side with Qt.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parents[1] / "resources" / "screenshots"
SAMPLES = HERE.parent / "samples"


def _sample_flags(kind: str) -> list[str]:
    """The command-line flags of the settings the workbench's sample certificate is made
    with (``Workbench.sample_settings``: the fringe sample's phase from its θ column)."""
    from models.registry import KINDS

    workbench = KINDS[kind]
    return [part for key, value in workbench.sample_settings.items()
            for part in (workbench.parameter(key).flag, str(value))]


def certificate_picture(kind: str, scratch: Path, chinese_number: str = "") -> Path:
    """The sample certificate's first three pages; with ``chinese_number``, the same
    certificate in Chinese under that number (a number is issued once)."""
    import json

    from PySide6.QtGui import QColor, QImage, QPainter

    name = f"{kind}_zh" if chinese_number else kind
    # the example details, issued into the scratch register (ANGLEBENCH_REGISTER, set by
    # main) that the register's picture shows: an example would go to a register of its own
    data = {**json.loads((SAMPLES / f"certificate_{kind}.json").read_text("utf-8")),
            "example": False}
    if chinese_number:
        data.update(language="zh", certificate_number=chinese_number)
    details = scratch / f"{name}.json"
    details.write_text(json.dumps(data), "utf-8")
    pdf = scratch / f"{name}.pdf"
    from models.registry import KINDS

    # the Chinese one into a register of its own: the scratch register holds the English
    # certificate of the same calibration, and a second original of it is refused (#61)
    env = ({**os.environ, "ANGLEBENCH_REGISTER": f"sqlite:///{scratch / 'register_zh.sqlite'}"}
           if chinese_number else None)
    subprocess.run([sys.executable, "-m", "app.main", "analyze", kind,
                    str(SAMPLES / KINDS[kind].sample_file), "--certificate", str(pdf),
                    "--metadata", str(details), *_sample_flags(kind)],
                   check=True, stdout=subprocess.DEVNULL, env=env)
    subprocess.run(["pdftoppm", "-png", "-r", "60", "-f", "1", "-l", "3", str(pdf),
                    str(scratch / name)], check=True)
    pages = [QImage(str(p)) for p in sorted(scratch.glob(f"{name}-*.png"))]
    gap = 12
    sheet = QImage(sum(p.width() for p in pages) + gap * (len(pages) - 1),
                   max(p.height() for p in pages), QImage.Format.Format_RGB32)
    sheet.fill(QColor("#d0d0d0"))
    painter = QPainter(sheet)
    x = 0
    for page in pages:
        painter.drawImage(x, 0, page)
        x += page.width() + gap
    painter.end()
    out = HERE / f"certificate_{name}.png"
    sheet.save(str(out))
    return out


def validation_picture(scratch: Path) -> Path:
    pdf = scratch / "validation.pdf"
    subprocess.run([sys.executable, "-m", "app.main", "validate", "--pdf", str(pdf)], check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(["pdftoppm", "-png", "-r", "60", "-f", "1", "-l", "1", "-singlefile", str(pdf),
                    str(HERE / "validation_report")], check=True)
    return HERE / "validation_report.png"


def register_picture(scratch: Path) -> Path:
    """The register window on the scratch register the sample certificates went into."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    window = MainWindow(settings=QSettings(str(scratch / "s.ini"), QSettings.Format.IniFormat),
                        recovery=RecoveryStore(scratch / "recovery"))
    window.show_register()
    dialog = window.register_window
    dialog.resize(1100, 560)
    dialog.table.selectRow(dialog.table.rowCount() - 1)
    window.register_presenter.show_history()
    QApplication.processEvents()
    out = HERE / "register.png"
    dialog.grab().save(str(out))
    window.projects.recovery.release()
    return out


#: the README's pictures of a workbench at a screen size, scale and language, each named
#: after its workbench's key ("KEY_…png")
SCALED = (("polygon_1280x720.png", "1280x720", "1", "en"),
          ("polygon_200pct.png", "960x540", "2", "en"),
          ("polygon_zh_CN.png", "1400x900", "1", "zh_CN"),
          ("theodolite_zh_CN.png", "1400x900", "1", "zh_CN"))


def scaled_pictures(scratch: Path) -> list[Path]:
    """The polygon workbench as a technician sees it on a 1280×720 screen and on a
    1920×1080 screen at 200 % (960×540 logical pixels), and two workbenches in Chinese:
    each its own process, since Qt reads the scale factor once, when it starts."""
    out = []
    for name, size, scale, language in SCALED:
        kind = name.split("_")[0]
        folder = scratch / name
        subprocess.run([sys.executable, "-m", "app.main", "--screenshot", str(folder), "--size",
                        size, "--language", language], check=True, stdout=subprocess.DEVNULL,
                       env={**os.environ, "QT_SCALE_FACTOR": scale})
        (folder / f"{kind}.png").replace(HERE / name)
        out.append(HERE / name)
    return out


def main() -> None:
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtWidgets import QApplication

    from app.screenshot import write_screenshots

    QApplication.instance() or QApplication(["readme_pictures"])
    for path in write_screenshots(HERE):
        if path.name in ("certificate_dialog.png", "live_signals.png"):
            path.unlink()  # shown by the tests, not in the README
    with tempfile.TemporaryDirectory() as scratch:
        # the example certificates are issued into a scratch register, not the user's
        os.environ["ANGLEBENCH_REGISTER"] = str(Path(scratch) / "register.sqlite")
        from models.registry import KINDS

        for kind in KINDS:
            certificate_picture(kind, Path(scratch))
        # the first workbench's certificate in Chinese as well
        certificate_picture(next(iter(KINDS)), Path(scratch), chinese_number="AB-2026-0050")
        validation_picture(Path(scratch))
        scaled_pictures(Path(scratch))
        register_picture(Path(scratch))


if __name__ == "__main__":
    main()
