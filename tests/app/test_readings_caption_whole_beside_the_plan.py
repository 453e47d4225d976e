"""gui80: the Chinese positioning window at 1280×720, mid-run on an entry plan of two readings
per approach: the readings caption "读数 — 已用 6 个 — 少于 5 次测量：已标注" beside the plan's
long next-reading caption was squeezed to about 60 px, narrower than its last words
"测量：已标注" (kept on one line), and drawn as "…测量：已标" — "注" (flagged) cut off. Beside
the next reading, the caption keeps the width its last words need, and shows every line."""

from __future__ import annotations

import pytest
from PySide6.QtGui import QFontMetrics

from tests.app.capture.window_steps import show_workbench as _show

pytestmark = pytest.mark.slow  # a window

#: the caption's last words, kept on one line (widgets.unbroken_last_word)
WORD = "测量：已标注"


@pytest.mark.parametrize("language", ["zh_CN", "en"])
def test_the_readings_caption_is_whole_beside_a_long_next_caption(window, qtbot, language):
    window.set_language(language)
    window.show()
    window.resize(1254, 662)  # the window maximized on a 1280×720 screen
    bench = _show(window, "positioning")
    bench.set_settings({**bench.settings, "plan_runs": 2, "plan_targets": "0:90:4",
                        "plan_directions": "both", "target_unit": "deg",
                        "deviation_unit": "arcsec", "readings_per_point": 2})
    keys = [c.key for c in bench.sheet.columns]
    rows = []
    for k, target in enumerate(("0", "0", "90", "90", "180", "180")):
        row = dict.fromkeys(keys, "")
        row.update(target=target, run="1", direction="+", deviation=f"{0.05 * k - 0.1:.2f}")
        rows.append([row[key] for key in keys])
    bench.table_model.replace_all(rows, "typed")
    bench.refresh()
    qtbot.wait(300)
    view = bench.view
    label = view.readings_label
    shown = label.text().replace("\u2060", "")
    assert shown.endswith("少于 5 次测量：已标注" if language == "zh_CN"
                          else "fewer than 5 runs: flagged"), shown
    assert "(6/32)" in view.next_label.text()
    assert not view._caption_above  # beside the next reading's caption, as at 1280×720
    # every line of the caption is drawn: none wider than the label, none below it
    assert label.heightForWidth(label.width()) <= label.height(), (label.width(),
                                                                   label.height())
    if language == "zh_CN":
        assert label.width() >= QFontMetrics(label.font()).horizontalAdvance(WORD)
    # and the next reading's caption is whole too
    nxt = view.next_label
    assert nxt.heightForWidth(nxt.width()) <= nxt.height(), (nxt.width(), nxt.height())
