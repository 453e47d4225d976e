"""Day 74 finding 13 (the caption): the Chinese readings caption "读数 — 已用 3 个 — 少于 5 次测量：
已标注" wrapped to three lines with "标注" (flagged) alone on the last, the "已" (already) of its
word left on the line above. Qt may break between any two ideographs; the caption's last
words ("测量：已标注") are now kept whole on its last line at every width the label can take,
the characters shown unchanged, and an English caption wraps at its spaces as before.

The lines are laid out as the label lays out its plain word-wrapped text (QTextLayout, the
label's font, word wrap) at each width from 30 to 400 pixels."""

from __future__ import annotations

from PySide6.QtGui import QTextLayout, QTextOption

from widgets.fonts import ensure_cjk_font
from widgets.workbench_view import WorkbenchView

CAPTION = "读数 — 已用 3 个"
FLAGGED = " — 少于 5 次测量：已标注"  # as the positioning presenter appends it
#: the caption's last words, "已标注" (flagged) after "测量" (runs): never broken, the last
#: line never "标注" nor "注" alone
WORD = "测量：已标注"
#: U+2060 WORD JOINER, drawn as nothing
JOINER = "\u2060"


def _lines(label, width: int) -> list[str]:
    """The label's text as it wraps at ``width`` pixels (plain text, word wrap)."""
    layout = QTextLayout(label.text(), label.font())
    option = QTextOption()
    option.setWrapMode(QTextOption.WrapMode.WordWrap)
    layout.setTextOption(option)
    layout.beginLayout()
    lines = []
    while (line := layout.createLine()).isValid():
        line.setLineWidth(width)
        lines.append(label.text()[line.textStart():line.textStart() + line.textLength()])
    layout.endLayout()
    return [line.replace(JOINER, "") for line in lines]


def test_the_captions_last_word_is_never_broken_onto_a_line_alone(qtbot):
    family = ensure_cjk_font()
    view = WorkbenchView("Positioning (axis)")
    qtbot.addWidget(view)
    if family:
        font = view.readings_label.font()
        font.setFamilies([font.family(), family])
        view.readings_label.setFont(font)
    view.set_readings_caption(CAPTION)
    view.append_to_readings_caption(FLAGGED)
    # the characters shown are the caption's (joiners are drawn as nothing)
    assert view.readings_label.text().replace(JOINER, "") == CAPTION + FLAGGED
    wrapped = 0
    for width in range(30, 401, 2):
        lines = _lines(view.readings_label, width)
        wrapped += len(lines) > 1
        assert lines[-1].strip().endswith(WORD), (width, lines)
    assert wrapped > 50  # the label did wrap at most of those widths


def test_the_caption_set_again_is_joined_at_its_new_end_only(qtbot):
    view = WorkbenchView("Positioning (axis)")
    qtbot.addWidget(view)
    view.set_readings_caption(CAPTION + FLAGGED)
    view.set_readings_caption(CAPTION)
    assert view.readings_label.text().replace(JOINER, "") == CAPTION
    view.append_to_readings_caption("，另加说明文字")
    text = view.readings_label.text()
    assert text.replace(JOINER, "") == CAPTION + "，另加说明文字"
    assert JOINER not in text[:text.index("，")]


def test_an_english_caption_is_as_it_was(qtbot):
    view = WorkbenchView("Positioning (axis)")
    qtbot.addWidget(view)
    view.set_readings_caption("Readings — 7 used")
    view.append_to_readings_caption(" — fewer than 5 runs: flagged")
    assert view.readings_label.text() == "Readings — 7 used — fewer than 5 runs: flagged"
