"""``python -m app.translations`` (``make translations``): the translation sources
brought up to date with Qt's own tools.

1. The window is built offscreen on the bundled samples, every plot tab shown, in each
   angle unit, and every text it asks ``widgets.i18n.declared`` for (the models' setting
   labels, column titles, plot titles and legends; the models have no Qt) is written to
   ``resources/translations/declared_strings.py`` as ``QT_TR_NOOP`` lines. A title with a
   unit is written without it (``error (")`` → ``error``): the unit is never translated.
2. ``pyside6-lupdate`` reads that file with ``app/`` and ``widgets/`` (their ``tr("…")``
   calls) into ``anglebench_zh_CN.ts``, keeping every translation already made and
   dropping texts no longer used.
3. ``pyside6-lrelease`` compiles it to ``anglebench_zh_CN.qm``, which the window loads.

The ``.ts`` is the source a translator edits (Qt Linguist, or any text editor); the
``.qm`` is committed beside it so the program runs without Qt's tools. It then lists the
texts still without Chinese (``type="unfinished"``). ``python -m app.translations --fill
FILE.json`` (a JSON object, English text → Chinese) fills those in, then brings the ``.ts``
and ``.qm`` up to date the same way: the public way to add the Chinese of a new workbench's
texts (:func:`fill_unfinished`).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from models.messages import TRANSLATIONS_DIR

ROOT = Path(__file__).resolve().parents[1]
DECLARED_FILE = TRANSLATIONS_DIR / "declared_strings.py"
TS_FILE = TRANSLATIONS_DIR / "anglebench_zh_CN.ts"
QM_FILE = TRANSLATIONS_DIR / "anglebench_zh_CN.qm"


def _tool(name: str) -> str:
    here = Path(sys.executable).parent / name
    return str(here) if here.exists() else name


def _visit_every_tab(app, window, units) -> None:
    for unit in units:
        window.set_angle_unit(unit)
        for index, presenter in enumerate(window.presenters):
            window.tabs.setCurrentIndex(index)
            presenter.refresh()
            for tab in range(presenter.view.plot_tabs.count()):
                presenter.view.plot_tabs.setCurrentIndex(tab)
                app.processEvents()


def declared_texts() -> list[str]:
    """Every text the window asks to be translated as a declared one, units left off."""
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    from app.main_window import MainWindow
    from models.display_units import ANGLE_UNITS
    from models.messages import unit_tail
    from models.project.recovery import RecoveryStore
    from widgets.i18n import SEEN_DECLARED
    from widgets.workbench_presenter import SAMPLES_DIR

    app = QApplication.instance() or QApplication(["translations"])
    SEEN_DECLARED.clear()  # this run's texts only
    register = os.environ.get("ANGLEBENCH_REGISTER")
    with tempfile.TemporaryDirectory() as scratch:
        os.environ["ANGLEBENCH_REGISTER"] = str(Path(scratch) / "register.sqlite")
        settings = QSettings(str(Path(scratch) / "settings.ini"), QSettings.Format.IniFormat)
        window = MainWindow(settings=settings, recovery=RecoveryStore(Path(scratch) / "r"))
        window.show()
        # then each further sample of a workbench, "KEY_…_sample.csv" (the fringe record
        # without a phase reference: the texts of a phase estimated from the signals)
        runs = [None] + [(p.kind.key, path) for p in window.presenters
                         for path in sorted(SAMPLES_DIR.glob(f"{p.kind.key}_*_sample.csv"))]
        for run in runs:
            if run is None:
                window.load_all_samples()
            else:
                window.presenter(run[0]).import_file(run[1])
            _visit_every_tab(app, window, ANGLE_UNITS.values())
        window.show_register()
        from widgets.certificate_dialog import CertificateDialog

        CertificateDialog(window.certificates.details(window.current.kind.key),
                          window).deleteLater()
        app.processEvents()
        for presenter in window.presenters:
            presenter.mark_saved()  # nothing to ask about on closing
        window.projects.recovery.discard()
        window.close()
        window.deleteLater()
    if register is None:
        os.environ.pop("ANGLEBENCH_REGISTER", None)
    else:
        os.environ["ANGLEBENCH_REGISTER"] = register
    texts = {unit_tail(text)[0] for text in SEEN_DECLARED}  # the unit is never translated
    return sorted(t for t in texts if re.search(r"[A-Za-z]{2}", t))


def write_declared(texts: list[str]) -> None:
    from models.project.atomic_write import write_bytes_atomic

    lines = ["# ruff: noqa: E501 - one text a line, as lupdate reads it",
             '"""Texts the models declare, for lupdate (written by python -m app.translations;',
             'do not edit: run it again). Never imported: no Qt here, as in every resource."""',
             "", "", "def QT_TR_NOOP(text: str) -> str:  # noqa: N802 - the name lupdate reads",
             "    return text", "", "", "DECLARED = ("]
    lines += [f"    QT_TR_NOOP({text!r})," for text in texts]
    lines += [")", ""]
    write_bytes_atomic(DECLARED_FILE, "\n".join(lines).encode("utf-8"))


def lupdate_sources() -> list[str]:
    """The files whose texts are translated: the window's (tr), the models' result texts
    (QT_TR_NOOP in models.messages' templates) and the declared texts gathered."""
    return sorted(str(p) for folder in ("app", "widgets", "models")
                  for p in (ROOT / folder).rglob("*.py")) + [str(DECLARED_FILE)]


def update_ts(ts: Path = TS_FILE) -> None:
    subprocess.run([_tool("pyside6-lupdate"), *lupdate_sources(), "-locations",
                    "none", "-no-obsolete", "-source-language", "en", "-target-language",
                    "zh_CN", "-ts", str(ts)], check=True, stdout=subprocess.DEVNULL)


def release_qm(qm: Path = QM_FILE) -> None:
    subprocess.run([_tool("pyside6-lrelease"), str(TS_FILE), "-qm", str(qm)], check=True,
                   stdout=subprocess.DEVNULL)


#: a message's comments, between its source and its translation
_COMMENTS = r"((?:\s*<(?:extra)?comment>[^<]*</(?:extra)?comment>)*\s*)"
_UNFINISHED = re.compile(r"<source>([^<]*)</source>" + _COMMENTS
                         + r"<translation type=\"unfinished\">\s*</translation>", re.DOTALL)


def unfinished(ts: Path = TS_FILE) -> list[str]:
    """The English texts of the .ts that have no translation yet."""
    from html import unescape

    return [unescape(source) for source, _ in _UNFINISHED.findall(ts.read_text("utf-8"))]


def _escaped(text: str) -> str:
    """``text`` as lupdate writes it in the .ts (&, <, >, ' and " escaped)."""
    from html import escape

    return escape(text, quote=False).replace("'", "&apos;").replace('"', "&quot;")


def fill_unfinished(texts: dict[str, str], ts: Path = TS_FILE) -> list[str]:
    """Each unfinished message whose English is a key of ``texts`` given its Chinese; the
    English texts given that the .ts has no unfinished message for (to be checked)."""
    content = ts.read_text("utf-8")
    missing = []
    for en, zh in texts.items():
        # as lupdate writes it: ' and " escaped too
        source = f"<source>{_escaped(en)}</source>"
        pattern = re.compile(re.escape(source) + _COMMENTS
                             + r"<translation type=\"unfinished\">\s*</translation>", re.DOTALL)
        content, count = pattern.subn(lambda m, zh=zh, source=source: (
            f"{source}{m.group(1)}<translation>{_escaped(zh)}</translation>"), content)
        if not count:
            missing.append(en)
    ts.write_text(content, "utf-8")
    return missing


def main(argv: list[str] | None = None) -> int:
    import argparse
    import json

    parser = argparse.ArgumentParser(prog="python -m app.translations")
    parser.add_argument("--fill", metavar="FILE.json",
                        help="a JSON object, English text → Chinese: fills those messages in")
    args = parser.parse_args(argv)
    if args.fill:
        missing = fill_unfinished(json.loads(Path(args.fill).read_text("utf-8")))
        for en in missing:
            print(f"not an unfinished message of the .ts, left: {en}")  # noqa: T201
    write_declared(declared_texts())
    update_ts()
    release_qm()
    print(f"{TS_FILE.relative_to(ROOT)} and {QM_FILE.name} brought up to date")  # noqa: T201
    left = unfinished()
    if left:
        print(f"{len(left)} texts have no Chinese yet (type=\"unfinished\" in "  # noqa: T201
              f"{TS_FILE.relative_to(ROOT)}); give it in a JSON object, English → Chinese, "
              "and run: python -m app.translations --fill FILE.json")
        for text in left:
            print(f"  {text}")  # noqa: T201
    return 0


if __name__ == "__main__":
    sys.exit(main())
