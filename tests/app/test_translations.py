"""The window in Simplified Chinese (#18): every text of the window is translated (a text
added without its translation fails here), the translation files are those Qt's tools
make from the sources, and the language changes at once without losing work."""

from __future__ import annotations

import json
import math
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pyqtgraph as pg
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractButton,
    QComboBox,
    QGroupBox,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QTabWidget,
    QWidget,
)

from app import translations

# words that stay as they are in a Chinese window: names, standards, file types, keys,
# units and the symbols of the papers
KEPT = {
    "AngleBench", "CSV", "XLSX", "xlsx", "xlsm", "csv", "txt", "PDF", "pdf", "PNG", "png",
    "JSON", "json", "anglebench", "ISO", "IEC", "VDI", "DGQ", "GB", "JJF", "ILAC", "LinuxCNC",
    "COMP_FILE", "comp", "Heydemann", "HeNe", "Excel", "sin", "cos", "deg", "mdeg", "rad",
    "urad", "arcsec", "sha", "SHA", "MPE", "Ctrl", "Shift", "Tab", "PgDn", "PgUp", "postgresql",
    "user", "host", "database", "YYYY", "English", "Chinese", "position", "deviation_arcsec",
    "INI", "zero", "Qt", "PySide", "pyqtgraph", "numpy", "scipy", "log", "Fig", "Figs",
    "SINUMERIK", "FANUC", "HEIDENHAIN", "TNC", "COM", "CMA", "Beckhoff", "TwinCAT", "ISG", "Mach",
    "ADC", "LSB",
    # the encoder interfaces' units (1 Vpp, 11 µApp), HEIDENHAIN's ERN encoders, a stream's
    # TCP link and its tcp:// address (#45)
    "Vpp", "App", "ERN", "TCP", "tcp",
    # the digital calibration certificate's format, named as PDF and CSV are (#43)
    "DCC", "XML", "xml",
    # its signature's key and certificate files and the signature's standard (XML-DSig)
    "PEM", "DSig",
    # CMC: as CNAS writes it; SPECIMEN-…: the specimens' numbers; IANA and its zone names
    "CMC", "SPECIMEN", "IANA", "Asia", "Shanghai",
}
# a controller's options as they are typed (axis=AX4, KEY=VALUE): keys, not words
TYPED_OPTION = re.compile(r"[A-Za-z_][A-Za-z0-9_]*=[^,;，；（）\s]*")
# widgets whose text is the user's or the result's (readings, names typed, the models'
# narrative of the result), not the window's
SKIPPED_NAMES = {"figures", "per_target"}  # numbers and the figures named by the models


def english_words(text: str) -> set[str]:
    words = set(re.findall(r"[A-Za-z][A-Za-z_]{2,}", TYPED_OPTION.sub("", text)))
    return {w for w in words if w not in KEPT and "_" not in w}  # B_i, ε_x,zero: symbols


def _skipped(widget: QWidget, window) -> bool:
    while widget is not None:
        if widget.objectName() == "location":  # the register's path or URL
            return True
        for name in SKIPPED_NAMES:
            for presenter in window.presenters:
                if getattr(presenter.view, name, None) is widget:
                    return True
        if any(widget is p.view.table for p in window.presenters):
            return True
        widget = widget.parentWidget()
    return False


def walk_plot_menu(vb, add) -> None:
    """Every text of a plot's right-click menu as pyqtgraph builds it when clicked: the
    view's menu, its submenus and their forms, and what the plot and the scene add."""
    from PySide6.QtWidgets import QWidgetAction

    def walk(menu):
        add(menu.title(), "plot menu")
        for action in menu.actions():
            add(action.text(), "plot menu")
            if action.menu() is not None:
                walk(action.menu())
            if isinstance(action, QWidgetAction) and action.defaultWidget() is not None:
                for widget in action.defaultWidget().findChildren(QWidget):
                    add(widget.toolTip(), "plot menu tooltip")
                    if isinstance(widget, QLabel | QAbstractButton):
                        add(widget.text(), "plot menu")

    walk(vb.getMenu(None))  # built as a right-click builds it
    parent = vb.parentItem()
    while parent is not None:
        if hasattr(parent, "getContextMenus"):
            found = parent.getContextMenus(None) or []
            for extra in found if isinstance(found, list) else [found]:
                walk(extra) if hasattr(extra, "actions") else add(extra.text(), "plot menu")
        parent = parent.parentItem()
    for action in vb.scene().contextMenu:
        add(action.text(), "plot menu")


def window_texts(window, extra: list[QWidget] = ()) -> dict[str, str]:
    """Every text the window shows of its own: {text: where}."""
    out: dict[str, str] = {}

    def add(text, where):
        text = (text or "").replace("&", "")
        if text.strip():
            out.setdefault(text, where)

    def walk_menu(menu, where):
        add(menu.title(), where)
        for action in menu.actions():
            add(action.text(), where)
            add(action.statusTip(), where)
            if action.menu() is not None:
                walk_menu(action.menu(), where + " › " + action.text())

    for action in window.menuBar().actions():
        walk_menu(action.menu(), "menu")
    for root in [window, *extra]:
        for widget in root.findChildren(QWidget):
            if _skipped(widget, window):
                continue
            add(widget.toolTip(), type(widget).__name__ + " tooltip")
            if isinstance(widget, QLabel):
                add(widget.text(), "label")
            elif isinstance(widget, QAbstractButton):
                add(widget.text(), "button")
            elif isinstance(widget, QGroupBox):
                add(widget.title(), "group")
            elif isinstance(widget, QLineEdit):
                add(widget.placeholderText(), "placeholder")
            elif isinstance(widget, QPlainTextEdit) and widget.isReadOnly():
                add(widget.toPlainText(), "result text")
            elif isinstance(widget, QComboBox):
                for i in range(widget.count()):
                    add(widget.itemText(i), "choice")
            elif isinstance(widget, QTabWidget):
                for i in range(widget.count()):
                    add(widget.tabText(i), "tab")
            if isinstance(widget, pg.GraphicsView):
                for item in widget.scene().items():
                    if isinstance(item, pg.AxisItem):
                        add(item.labelText, "axis title")
                    elif isinstance(item, pg.LegendItem):
                        for _sample, label in item.items:
                            add(label.text, "legend")
                    elif isinstance(item, pg.ViewBox) and item.getMenu(None) is not None:
                        walk_plot_menu(item, add)
    for presenter in window.presenters:
        model = presenter.table_model
        for c in range(model.columnCount()):
            add(model.headerData(c, Qt.Orientation.Horizontal), "readings header")
    return out


@pytest.fixture
def chinese(window, qtbot):
    window.set_language("zh_CN")
    window.load_all_samples()
    window.show()
    yield window
    window.set_language("en")


@pytest.mark.slow
def test_every_text_of_the_window_is_translated(chinese, qtbot):
    """The whole window in Chinese, every workbench and plot tab shown, the register and
    the certificate dialog open: no English word left in a text of the window's own."""
    from widgets.certificate_dialog import CertificateDialog
    from widgets.column_mapping_dialog import ColumnMappingDialog

    window = chinese
    for index, presenter in enumerate(window.presenters):
        window.tabs.setCurrentIndex(index)
        for tab in range(presenter.view.plot_tabs.count()):
            presenter.view.plot_tabs.setCurrentIndex(tab)
    window.show_register()
    dialog = CertificateDialog(window.certificates.details("polygon"), window)
    mapping = ColumnMappingDialog(window.presenter("theodolite").kind.columns,
                                  ["a", "b", "c"], [["1", "2", "3"]], "", window)
    texts = window_texts(window, [window.register_window, dialog, mapping])
    assert len(texts) > 300
    left = {text: where for text, where in texts.items() if english_words(text)}
    assert not left, "untranslated: " + "; ".join(f"{w}: {t!r}" for t, w in list(left.items())[:15])
    dialog.deleteLater()
    mapping.deleteLater()


@pytest.mark.slow
def test_the_language_changes_at_once_and_the_work_stays(window, qtbot):
    window.load_all_samples()
    theodolite = window.presenter("theodolite")
    theodolite.table_model.set_cells([(0, 1, "-19°52'58.0\"")])
    rows, undo = theodolite.state().rows, theodolite.undo_stack.count()
    before = theodolite.view.error_plot.corrected_curve.getData()[1].copy()
    chinese = next(a for a in window.menus.language_actions.actions() if a.data() == "zh_CN")
    chinese.trigger()
    assert window.qsettings.value("ui/language") == "zh_CN" and chinese.isChecked()
    assert window.menuBar().actions()[0].text() == "文件(&F)"
    assert window.tabs.tabText(0) == "经纬仪测量"
    assert theodolite.view.error_plot.main_plot.getAxis("left").labelText == "原始误差 (\")"
    assert theodolite.table_model.headerData(0, Qt.Orientation.Horizontal) == "θ [°]"
    assert theodolite.view.settings.findChild(QLabel).text() == "参考行"
    assert theodolite.state().rows == rows and theodolite.undo_stack.count() == undo
    assert (theodolite.view.error_plot.corrected_curve.getData()[1] == before).all()
    theodolite.undo_stack.undo()  # the history survived the change of language
    assert theodolite.state().rows != rows
    next(a for a in window.menus.language_actions.actions() if a.data() == "en").trigger()
    assert window.menuBar().actions()[0].text() == "&File"
    assert theodolite.view.error_plot.main_plot.getAxis("left").labelText == "raw error (\")"


def _sources(ts: Path) -> set[str]:
    return {m.findtext("source") for m in ET.parse(ts).iter("message")}


@pytest.mark.slow
def test_the_translation_files_are_made_from_the_sources(tmp_path, qapp):
    """declared_strings.py holds what the window asks the models' texts for; the .ts
    holds every text of the sources, each translated; the .qm is lrelease's of it."""
    assert translations.declared_texts() == [
        eval(line.strip()[len("QT_TR_NOOP("):-2])  # noqa: S307 - our own generated file
        for line in translations.DECLARED_FILE.read_text("utf-8").splitlines()
        if line.strip().startswith("QT_TR_NOOP(")]
    copy = tmp_path / "copy.ts"
    shutil.copy(translations.TS_FILE, copy)
    translations.update_ts(copy)
    assert _sources(copy) == _sources(translations.TS_FILE), "run make translations"
    unfinished = [m.findtext("source") for m in ET.parse(translations.TS_FILE).iter("message")
                  if m.find("translation").get("type") == "unfinished"
                  or not (m.findtext("translation") or "").strip()]
    assert unfinished == []
    qm = tmp_path / "copy.qm"
    translations.release_qm(qm)
    assert qm.read_bytes() == translations.QM_FILE.read_bytes(), "run make translations"


def test_the_language_follows_the_system_unless_chosen(monkeypatch):
    from PySide6.QtCore import QLocale

    from widgets.i18n import resolve_language

    monkeypatch.setattr(QLocale, "system", lambda: QLocale(QLocale.Language.Chinese,
                                                          QLocale.Country.China))
    assert resolve_language("system") == "zh_CN"
    assert resolve_language("en") == "en"
    monkeypatch.setattr(QLocale, "system", lambda: QLocale(QLocale.Language.German,
                                                          QLocale.Country.Germany))
    assert resolve_language("system") == "en"


@pytest.mark.slow
def test_a_cell_that_cannot_be_read_says_why_in_the_windows_language(chinese):
    """The red cell's tooltip in the Chinese window: no English of ours, the text typed and
    the column's key as they are. Each text typed in turn into one window, undone before
    the next (a window each, its samples and its language, took ~1.3 s of CPU a text)."""
    theodolite = chinese.presenter("theodolite")
    model = theodolite.table_model
    for typed in ("12°75'", "abc", "12.5°30'", ""):
        model.setData(model.index(2, 1), typed)
        tip = model.data(model.index(2, 1), Qt.ItemDataRole.ToolTipRole)
        assert tip and re.search("[\u4e00-\u9fff]", tip), typed
        assert english_words(tip.replace(typed, "").replace("azimuth_deg", "")) == set(), \
            (typed, tip)
        theodolite.undo_stack.undo()
        assert model.data(model.index(2, 1), Qt.ItemDataRole.ToolTipRole) != tip, typed


def test_the_command_line_says_which_cell_is_bad_in_chinese(tmp_path, capsys):
    from app.main import main

    path = tmp_path / "run.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n0,0,0.01\n5,5°70',0.02\n10,10,0.03\n"
                    "15,x,0.04\n", encoding="utf-8")
    assert main(["analyze", "theodolite", str(path), "--language", "zh_CN"]) == 2
    said = capsys.readouterr().err.strip()
    assert said == (f"{path}：第 3 行，列 'azimuth_deg'：'5°70'\'：分 70 超出范围（0 至 59）"
                    "（另有 1 个无法读取的单元格）")
    assert main(["analyze", "theodolite", str(path)]) == 2  # English as before
    assert capsys.readouterr().err.strip() == (
        f"{path}: row 3, column 'azimuth_deg': '5°70'': minutes 70 out of range (0 to 59) "
        "(and 1 more bad cell(s))")


def test_every_translation_keeps_its_figures():
    """A translated template names the same figures as the English one: a figure left out
    would vanish from a certificate or a message."""
    for element in ET.parse(translations.TS_FILE).iter("message"):
        source, translation = element.findtext("source"), element.findtext("translation") or ""
        for figure in (r"\{[^}]*\}", r"%\([a-z_]+\)[sr]|%[sr]"):  # ours, and argparse's
            assert sorted(re.findall(figure, source)) == sorted(
                re.findall(figure, translation)), source


REFUSED = [  # (workbench, file's bytes, names it holds or asks for): input that is refused
    ("fringe", b"u_sin,u_cos\n" + b"1.0,2.0\n" * 40, set()),
    ("fringe", b"u_sin,u_cos\n" + "".join(
        f"{3.7 * math.sin(i / 9):.4f},{3.7 * math.sin(i / 9):.4f}\n" for i in range(200)).encode(),
     set()),
    ("theodolite", b"theta_deg,azimuth_deg,elevation_deg\n\xff\xfe\xfd,1,2\n", {"UTF", "GBK"}),
    ("theodolite", b"theta_deg,azimuth_deg,elevation_deg\n" + b"5,5,0.1\n" * 6, set()),
    ("polygon", b"position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec\n1,0,0,0\n2,180,0,0\n",
     set()),
    ("theodolite", b"angle,az\n1,2\n", {"angle", "run", "direction", "azimuth"}),
]


@pytest.mark.parametrize("kind, content, names", REFUSED)
def test_refused_input_is_explained_in_chinese(tmp_path, capsys, kind, content, names):
    """Bad input on the command line with --language zh_CN: the reason in Chinese, with the
    file's name and what it holds as they are; in English exactly as without the option."""
    from app.main import main

    path = tmp_path / "input.csv"
    path.write_bytes(content)
    assert main(["analyze", kind, str(path)]) == 2
    english = capsys.readouterr().err.strip()
    assert main(["analyze", kind, str(path), "--language", "zh_CN"]) == 2
    chinese = capsys.readouterr().err.strip()
    assert re.search("[\u4e00-\u9fff]", chinese), chinese
    assert english_words(chinese.replace(str(path), "")) - names == set(), chinese
    assert english_words(english.replace(str(path), "")), english  # it was English before


@pytest.mark.slow
def test_a_refused_analysis_says_why_in_the_chinese_window(chinese):
    fringe = chinese.presenter("fringe")
    fringe.table_model.replace_all([["1.0", "2.0", ""]] * 40)
    fringe.refresh()
    summary = fringe.view.summary.toPlainText()
    assert "u_sin" in summary and re.search("[\u4e00-\u9fff]", summary)
    assert english_words(summary) == set(), summary
    fringe.undo_stack.undo()


@pytest.mark.slow
def test_the_command_lines_own_words_in_chinese(tmp_path, capsys, samples_dir):
    """argparse's refusal and the line after a draft certificate is written, in Chinese."""
    from app.main import main

    with pytest.raises(SystemExit) as refused:
        main(["analyze", "sextant", "x.csv", "--language", "zh_CN"])
    said = capsys.readouterr().err.strip()
    assert refused.value.code == 2 and "无效的选项" in said and "'sextant'" in said
    with pytest.raises(SystemExit):
        main(["analyze", "sextant", "x.csv"])
    assert "invalid choice: 'sextant'" in capsys.readouterr().err  # English as before
    out = tmp_path / "draft.pdf"
    assert main(["analyze", "theodolite", str(samples_dir / "theodolite_sample.csv"),
                 "--certificate", str(out), "--language", "zh_CN"]) == 0
    said = capsys.readouterr().err.strip()
    # the missing fields listed with the Chinese enumeration comma (「、」), not ", "
    # no reference standard listed: a test report, a draft too (assessment 72 M3)
    assert said.startswith(f"检测报告已写入 {out}（草稿：缺少报告编号、校准机构")
    assert english_words(said.replace(str(out), "")) == set(), said


@pytest.mark.slow
def test_the_register_window_follows_the_language(window, samples_dir, tmp_path, capsys,
                                                  pdf_stand_in):
    """A record's status and revision are the register's English words as data, shown in
    the window's language; the open register follows a change of language at once. (The
    certificate's PDF a stand-in: the register's record is what is shown.)"""
    from app.main import main

    details = json.loads((samples_dir / "certificate_polygon.json").read_text("utf-8"))
    own = tmp_path / "details.json"  # the lab's own, made from the example (which never
    own.write_text(json.dumps({**details, "example": False}), "utf-8")  # enters a register)
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(own), "--certificate", str(tmp_path / "issued.pdf")]) == 0
    capsys.readouterr()
    window.show_register()
    table = window.register_window.table
    assert (table.item(0, 1).text(), table.item(0, 2).text()) == ("issued", "original")
    window.set_language("zh_CN")
    try:
        assert (table.item(0, 1).text(), table.item(0, 2).text()) == ("已签发", "原始")
        assert table.horizontalHeaderItem(1).text() == "状态"
    finally:
        window.set_language("en")
    assert table.item(0, 1).text() == "issued"


@pytest.mark.slow
def test_no_english_left_where_a_technician_looks_31(window, qtbot, tmp_path, samples_dir,
                                                     monkeypatch):
    """#31's leftovers: the empty plots' legends (before any readings), a positioning run
    of fewer than 5 runs, the draft question's missing details, the printout's title, the
    plots' right-click menus, the polygon's x axes; and the certificate of a Chinese window
    is Chinese, its PDF's title too."""
    import pypdfium2

    import widgets.print_view
    from app.writers.certificate_pdf import certificate_pdf_bytes

    window.set_language("zh_CN")
    try:
        window.show()
        texts = window_texts(window)  # empty plots, nothing analysed yet
        left = {t: w for t, w in texts.items() if english_words(t)}
        assert not left, left
        positioning = window.presenter("positioning")
        rows = [line.split(",") for line in
                (samples_dir / "positioning_sample.csv").read_text().splitlines()[1:]]
        positioning.table_model.replace_all([r for r in rows if int(r[1]) <= 3])
        positioning.refresh()
        assert positioning.result is not None and not positioning.result.minimum_runs_met
        caption = positioning.view.readings_label.text()
        assert english_words(caption) == set(), caption
        asked = []
        window.ask = lambda title, text, *a: asked.append(text)
        window.certificates.view.confirm_draft(window.certificates.details("polygon").missing_fields())
        assert "计量标准" in asked[0] and english_words(asked[0]) == set(), asked[0]
        printed = []
        monkeypatch.setattr(widgets.print_view, "print_workbench",
                            lambda view, printer, title: printed.append(title))
        window.print_to(None)
        assert english_words(printed[0]) == set(), printed[0]
        window.load_all_samples()
        polygon = window.presenter("polygon").view
        for axis in (polygon.error_plot.residual_plot.getAxis("bottom"),
                     polygon.tilt_plot.plot.getAxis("bottom")):
            assert "(°)" in axis.labelText and "deg" not in axis.labelText, axis.labelText
        meta = window.certificates.details("polygon")
        assert meta.language == "zh"
        window.tabs.setCurrentIndex(1)
        presenter = window.current
        document = presenter.kind.certificate_document(presenter.result, meta, "polygon.csv",
                                                       presenter.settings)
        pdf = pypdfium2.PdfDocument(certificate_pdf_bytes(document))
        title = pdf.get_metadata_dict()["Title"]
        pdf.close()
        assert re.search("[\u4e00-\u9fff]", title) and english_words(title) == set(), title
    finally:
        window.set_language("en")
    assert window.certificates.details("theodolite").language == "en"


def test_the_application_owns_one_language_with_the_texts_that_follow_it(qapp, qtbot):
    """widgets/i18n.py keeps no module state: the application's Language holds the
    language installed, its translators, and every live text and callback; a text or
    callback whose owner was closed is let go."""
    import shiboken6
    from PySide6.QtCore import QCoreApplication

    from tests.pseudo_translation import marked, pseudo_translated
    from widgets.i18n import application_language, install_language, live, on_language_change, tr

    language = application_language()
    assert language is application_language()
    assert language.parent() is QCoreApplication.instance() and language.code == "en"
    assert install_language("zh_CN") == "zh_CN" and language.code == "zh_CN"
    assert install_language("en") == "en" and language.code == "en"
    label, gone = QLabel(), QLabel()
    qtbot.addWidget(label)
    live(label.setText, tr("Copy image"))
    live(gone.setText, tr("Copy image"))
    calls = []
    on_language_change(label, lambda: calls.append("label"))
    on_language_change(gone, lambda: calls.append("gone"))
    shiboken6.delete(gone)  # its window closed
    with pseudo_translated():
        language.retranslate()
        assert label.text() == marked("Copy image")
    assert calls == ["label"]
    language.retranslate()
    assert label.text() == "Copy image" and calls == ["label", "label"]
