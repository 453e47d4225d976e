"""The window's look-alike serial question (Another item?) as its message box lays it out:
no serial or certificate number is broken across two lines at any width of the box, and
with several earlier look-alike serials the question lists them one a line, at most three
and how many more, each pair of characters that print alike named once.

Day review 68 F11: a marked serial broke at its hyphen ("RX-2[G]-" / "[0]815"), and with
three earlier look-alikes the question was a paragraph of 16 lines comparing the serial with
each of them in turn ("the small letter o and the digit 0" three times).

The question is raised from the register's facts as the register raises it
(models/register/store.py); the lines are Qt's own text layout in the message box's font."""

from __future__ import annotations

import re

import pytest
from PySide6.QtGui import QTextLayout, QTextOption
from PySide6.QtWidgets import QLabel, QMessageBox

from app.certificate_dialogs import CertificateDialogs
from models.certificate.metadata import CertificateMetadata
from models.register.store import _lookalike_serial

MAKER = "Example Instruments"
EARLIER = [("AB-2026-0002", "RX-26-0815"), ("AB-2026-0007", "RX-26-0815"),
           ("AB-2026-0024", "RX-2G-0815"), ("AB-2026-0025", "RX-Z6-081S"),
           ("AB-2026-0031", "RX-26-0B15"), ("AB-2026-0032", "RX-Z6-O815")]
#: what a word joiner or the like may put between a serial's characters
INVISIBLE = "\u2060\u200b\u00ad"


class _Window:
    """The main window's ``ask``: the question recorded, answered No."""

    def __init__(self) -> None:
        self.asked: list[tuple[str, str]] = []

    def ask(self, title, text, buttons, default):
        self.asked.append((title, text))
        return QMessageBox.StandardButton.No


def _asked(serial: str, earlier) -> str:
    meta = CertificateMetadata.from_dict({"item_serial": serial, "item_manufacturer": MAKER})
    question = _lookalike_serial(meta, [(n, s, MAKER) for n, s in earlier])
    window = _Window()
    assert CertificateDialogs(window).confirm_lookalike_serial(question) is False
    [(title, text)] = window.asked
    assert title == "Another item?"
    return text


def _shown(text: str) -> str:
    return "".join(c for c in text if c not in INVISIBLE)


def _lines(text: str, label: QLabel, width: int) -> list[str]:
    """The lines Qt lays ``text`` out in, in ``label``'s font, ``width`` px wide, words
    wrapped as a message box's label wraps them."""
    out = []
    for paragraph in text.split("\n"):
        layout = QTextLayout(paragraph, label.font())
        option = QTextOption()
        option.setWrapMode(QTextOption.WrapMode.WordWrap)
        layout.setTextOption(option)
        layout.beginLayout()
        while True:
            line = layout.createLine()
            if not line.isValid():
                break
            line.setLineWidth(width)
        layout.endLayout()
        out += [paragraph[layout.lineAt(i).textStart():layout.lineAt(i).textStart()
                          + layout.lineAt(i).textLength()] for i in range(layout.lineCount())]
    return out


@pytest.mark.parametrize("earlier", [EARLIER[:1], EARLIER[2:3], EARLIER[:4]],
                         ids=["one", "one marked", "three"])
def test_no_serial_nor_number_is_broken_across_lines(qtbot, earlier):
    text = _asked("rx-26-o815", earlier)
    box = QMessageBox(QMessageBox.Icon.Question, "Another item?", text)
    qtbot.addWidget(box)
    label = box.findChild(QLabel, "qt_msgbox_label")
    assert label is not None and _shown(label.text()) == _shown(text)
    # every serial and certificate number, plain or marked, as the question shows it
    words = set(re.findall(r"[\w\[\]]+(?:-[\w\[\]]+)+", _shown(text), re.ASCII))
    assert "rx-26-o815" in words and {n for n, _s in earlier} <= words, words
    for width in range(120, 520, 7):
        for line in _lines(text, label, width):
            shown = _shown(line).strip()
            # was: "… RX-2[G]-" ending a line and "[0]815 …" beginning the next
            for word in words:
                for cut in range(1, len(word)):
                    assert not (shown.endswith(word[:cut]) and word[cut] == "[" or
                                shown.endswith(word[:cut]) and word[cut - 1] == "-"), (
                        width, word, shown)


def test_three_earlier_lookalikes_one_a_line_each_pair_named_once():
    text = _shown(_asked("rx-26-o815", EARLIER[:4]))
    lines = text.splitlines()
    # each earlier serial marked, with its certificates, on a line of its own
    for marked, numbers in (("RX-26-[0]815", "AB-2026-0002, AB-2026-0007"),
                            ("RX-2[G]-[0]815", "AB-2026-0024"),
                            ("RX-[Z]6-[0]81[S]", "AB-2026-0025")):
        [line] = [x for x in lines if marked in x]
        assert numbers in line and len(line) <= 50, line
    # each pair of characters that print alike named once (was: o and 0 three times)
    for pair in ("the small letter o and the digit 0", "the digit 6 and the capital letter G",
                 "the digit 2 and the capital letter Z", "the digit 5 and the capital letter S"):
        assert len(re.findall(re.escape(pair), text, re.IGNORECASE)) == 1, (pair, text)
    assert " vs " not in text
    assert "Is rx-26-o815 a different item from each of them? Yes: issue it" in text
    # as short as a list of three can be: was 16 lines of a 420 px box, so ~1400 characters
    assert len(text) < 800, len(text)


def test_more_than_three_are_counted_not_listed():
    text = _shown(_asked("rx-26-o815", EARLIER))
    listed = [x for x in text.splitlines() if x.startswith("• RX-")]
    assert len(listed) == 3, text
    # five serials in six certificates: three listed, two counted, neither named
    assert "• and 2 more" in text, text
    assert "0B15" not in text and "O815" not in text, text


def test_one_earlier_lookalike_is_said_in_a_sentence_as_before():
    text = _shown(_asked("RX-2G-0815", EARLIER[:1]))
    assert text.startswith(f"Serial RX-2G-0815 is in no certificate of the register, but looks "
                           f"like RX-26-0815 of {MAKER} (AB-2026-0002). RX-2[G]-0815 vs "
                           "RX-2[6]-0815: the capital letter G and the digit 6 print alike, "
                           "case aside."), text
    assert "Is RX-2G-0815 a different item from RX-26-0815? Yes: issue it" in text
