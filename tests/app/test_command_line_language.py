"""The commands in the reader's language (#18): ``--help`` of every command, the register's
listing, record, verification and refusals, and the method validation's lines and report,
in Simplified Chinese when ``--language zh_CN`` is given or the system's locale is Chinese;
in English exactly as before otherwise."""

from __future__ import annotations

import argparse
import io
import json
import re

import pypdfium2 as pdfium
import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.command_line import display_width, language_asked, system_language, wrapped
from app.main import main

CJK = re.compile("[\u4e00-\u9fff]")
COMMANDS = [["analyze"], ["register"], ["register", "list"], ["register", "show"],
            ["register", "verify"], ["register", "export"], ["register", "continue"],
            ["register", "interval"], ["validate"], []]


def english_words(text: str) -> set[str]:
    return set(re.findall(r"(?<![\w./'-])[A-Za-z]{3,}(?![\w/'-])", text))


@pytest.mark.parametrize("environ, language", [
    ({"LANG": "zh_CN.UTF-8"}, "zh_CN"), ({"LANG": "zh_TW.UTF-8"}, "zh_CN"),
    ({"LANG": "en_US.UTF-8"}, "en"), ({}, "en"), ({"LANG": "C"}, "en"),
    ({"LANG": "en_GB.UTF-8", "LC_ALL": "zh_CN.UTF-8"}, "zh_CN"),
    ({"LC_ALL": "zh_CN.UTF-8", "LANGUAGE": "en_US:zh_CN"}, "en"),
    ({"LANG": "zh_CN.UTF-8", "LC_MESSAGES": "de_DE.UTF-8"}, "en"),
    ({"LANGUAGE": "", "LANG": "zh_SG.UTF-8"}, "zh_CN"),
])
def test_the_system_language_is_read_as_gettext_reads_it(environ, language):
    assert system_language(environ) == language


def test_an_explicit_language_wins_over_the_system(monkeypatch):
    monkeypatch.setenv("LANG", "zh_CN.UTF-8")
    assert language_asked(["x", "--language", "en"]) == "en"
    assert language_asked(["x", "--language=en"]) == "en"
    assert language_asked(["x"]) == "zh_CN"
    assert language_asked(["x", "--language", "system"]) == "zh_CN"
    assert language_asked(["x", "--language", "klingon"]) == "zh_CN"  # argparse refuses it


def _helps_recorded(monkeypatch) -> list[str]:
    """Every help text given to argparse while a parser is built (options, positionals and
    subcommands)."""
    seen: list[str] = []
    add_argument = argparse._ActionsContainer.add_argument
    add_parser = argparse._SubParsersAction.add_parser

    def recording_argument(self, *args, **kwargs):
        if kwargs.get("help") not in (None, argparse.SUPPRESS):
            seen.append(kwargs["help"])
        return add_argument(self, *args, **kwargs)

    def recording_parser(self, name, **kwargs):
        if kwargs.get("help"):
            seen.append(kwargs["help"])
        return add_parser(self, name, **kwargs)

    monkeypatch.setattr(argparse._ActionsContainer, "add_argument", recording_argument)
    monkeypatch.setattr(argparse._SubParsersAction, "add_parser", recording_parser)
    return seen


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: " ".join(c) or "window")
def test_every_help_text_is_in_chinese_and_fits_the_terminal(command, monkeypatch, capsys):
    monkeypatch.setenv("COLUMNS", "80")
    seen = _helps_recorded(monkeypatch)
    with pytest.raises(SystemExit) as done:
        main([*command, "--help", "--language", "zh_CN"])
    assert done.value.code == 0
    printed = capsys.readouterr().out
    untranslated = [h for h in seen if not CJK.search(h)]
    assert seen and untranslated == [], untranslated
    assert printed.startswith("用法：") and ("选项:" in printed or "选项：" in printed)
    assert "show this help" not in printed and "usage:" not in printed
    wide = [line for line in printed.splitlines() if display_width(line) > 80]
    assert wide == [], wide  # a Chinese character takes two columns
    first, second = printed.splitlines()[:2]
    if second.startswith(" "):  # the usage goes on under its first argument, by columns
        assert len(second) - len(second.lstrip()) == display_width(first.split(" [")[0]) + 1
    with pytest.raises(SystemExit):
        main([*command, "--help", "--language", "en"])
    english = capsys.readouterr().out
    assert english.startswith("usage: ") and not CJK.search(english.replace(
        "theta_deg=转角,azimuth_deg=方位角", ""))


@given(st.text(st.sampled_from("角度 计量abc, xyz。（）12"), max_size=200),
       st.integers(10, 100))
def test_help_wrapping_keeps_every_character_within_the_width(text, width):
    lines = wrapped(text, width)
    assert "".join("".join(lines).split()) == "".join(text.split())  # nothing lost
    for line in lines:  # a line is only wider when one Latin word alone is wider
        assert display_width(line) <= width or " " not in line.strip()


def test_the_language_follows_the_locale(tmp_path, monkeypatch, capsys):
    bad = tmp_path / "bad.csv"
    bad.write_text("theta_deg,azimuth_deg,elevation_deg\n0,1,2\n5,5°70',0.1\n", "utf-8")
    monkeypatch.setenv("LANG", "zh_CN.UTF-8")
    assert main(["analyze", "theodolite", str(bad)]) == 2
    assert CJK.search(capsys.readouterr().err)
    assert main(["analyze", "theodolite", str(bad), "--language", "en"]) == 2
    assert "minutes 70 out of range" in capsys.readouterr().err


@pytest.fixture
def issued(tmp_path, samples_dir, capsys, pdf_stand_in):
    """A register with one certificate issued from the polygon sample (its PDF a stand-in,
    tests/pdf_stand_in.py: the register's words are what is read, and verify finds the
    file by its SHA-256; printing it cost ~0.6 s of CPU)."""
    pdf = tmp_path / "issued.pdf"
    details = json.loads((samples_dir / "certificate_polygon.json").read_text("utf-8"))
    own = tmp_path / "details.json"  # the lab's own, made from the example
    own.write_text(json.dumps({**details, "example": False}), "utf-8")
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(own), "--certificate", str(pdf)]) == 0
    capsys.readouterr()
    return pdf, details


@pytest.mark.slow
def test_the_register_speaks_chinese(issued, tmp_path, capsys):
    pdf, details = issued
    theirs = " ".join(str(v) for v in details.values() if isinstance(v, str))
    assert main(["register", "list", "--language", "zh_CN"]) == 0
    (header, line) = capsys.readouterr().out.splitlines()
    number = line.split()[0]
    assert line.rstrip().endswith("已签发") and " polygon / " in line  # the key stays a key
    # the header too (day review 65 F7: it stayed in English)
    assert header.split() == ["编号", "签发日期", "工作台", "/", "文件", "委托方", "出厂编号",
                              "制造商", "状态"]
    assert main(["register", "list"]) == 0
    english = capsys.readouterr().out.splitlines()
    assert english[1].rstrip().endswith("issued")  # English
    assert english[0].split()[:3] == ["Number", "Date", "of"]

    assert main(["register", "show", number, "--language", "zh_CN"]) == 0
    shown = capsys.readouterr().out
    assert "签发日期：" in shown and "出厂编号：RX-26-0815" in shown and "主要结果" in shown
    # left in Latin letters: the lab's own words, the machine's name and the operating-system
    # user who issued it (schema v4), the software's names, the workbench's key, "PDF" and
    # "DCC" (the record digest's form names what it covers: 0.8.22); the headline's figure
    # names are translated too
    left = english_words(re.sub(r"(软件|工作站|签发用户)：.*", "", shown)) - english_words(theirs)
    assert left == {"polygon", "PDF", "DCC"}, left

    assert main(["register", "verify", str(pdf), "--language", "zh_CN"]) == 0
    said = capsys.readouterr().out
    assert f"证书 {number}" in said and "已签发" in said and "与记录一致" in said
    tampered = tmp_path / "tampered.pdf"
    tampered.write_bytes(pdf.read_bytes() + b"\n")
    assert main(["register", "verify", str(tampered), "--language", "zh_CN"]) == 1
    assert "不在登记册中" in capsys.readouterr().out

    assert main(["register", "show", "NOPE", "--language", "zh_CN"]) == 2
    refused = capsys.readouterr().err
    assert refused.startswith("anglebench register: ") and CJK.search(refused)
    assert main(["register", "continue", "AB-{year}-{seq:04d}", "5", "--date", "2026-13-01",
                 "--language", "zh_CN"]) == 2
    assert "不是 YYYY-MM-DD 格式" in capsys.readouterr().err
    assert main(["register", "export", str(tmp_path / "all.zip"), "--language", "zh_CN"]) == 0
    assert capsys.readouterr().err.startswith("已将 1 份证书导出到")


@pytest.mark.slow
def test_the_method_validation_in_chinese(tmp_path, capsys, validation_once):
    out = tmp_path / "validation.pdf"
    assert main(["validate", "--pdf", str(out), "--trials", "100", "--language", "zh_CN"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert re.fullmatch(r"\d{2,} 个通过，0 个未通过", lines[-1]), lines[-1]
    for line in lines[:-1]:  # every case: verdict, workbench and name in Chinese
        assert line.startswith("通过  ") and CJK.search(line.split("：", 1)[1]), line
    document = pdfium.PdfDocument(io.BytesIO(out.read_bytes()))
    text = re.sub(r"\s+", " ", " ".join(document[i].get_textpage().get_text_range()
                                        for i in range(len(document))))
    document.close()
    assert "方法确认报告" in text and "参考案例中" in text and "校核数值" in text
    # left in Latin letters: names of software, journals' authors, standards and symbols
    kept = {"AngleBench", "Python", "numpy", "scipy", "Linux", "Tian", "Gao", "UTC", "ISO",
            "IEC", "GUM", "JCGM", "VDI", "RMS", "glibc", "Table", "DGQ", "PDF", "git", "VAL",
            "Estler", "fpdf", "SQLAlchemy", "PySide", "Essentials", "pyqtgraph", "psycopg", "pypdfium",
            "openpyxl", "fonttools", "GTC", "loadtxt", "Hazen",
            "max", "min",  # the operators of the axis figures' formulas
            } | english_words(text.split(
                "平台", 1)[1].split("检查内容", 1)[0])  # the platform string
    assert english_words(text) - kept == set()


@pytest.mark.slow  # a whole main window
def test_language_option_opens_the_window_in_that_language(qtbot, monkeypatch, tmp_path):
    """``anglebench --language zh_CN`` opened an English window (#41)."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QApplication

    import app.main as main_module
    import app.main_window as main_window
    from models.project.recovery import RecoveryStore
    from widgets.i18n import install_language

    made = []
    real = main_window.MainWindow

    def probe():
        window = real(settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat),
                      recovery=RecoveryStore(tmp_path / "recovery"))
        qtbot.addWidget(window)
        made.append(window)
        return window

    monkeypatch.setattr(main_window, "MainWindow", probe)
    monkeypatch.setattr(main_module, "missing_x11_packages", lambda: [])
    monkeypatch.setattr(QApplication, "exec", lambda _app: 0)
    try:
        assert main_module.main(["--language", "zh_CN"]) == 0
        window = made[0]
        assert window.language == "zh_CN"
        assert window.menuBar().actions()[0].text() != "&File"
    finally:
        install_language("en")
