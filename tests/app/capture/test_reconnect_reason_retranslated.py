"""The reason a link reconnected after is said in the window's language now (live78): the
status "Connected: … (reconnected after: cannot open (timed out))" kept the reason in the
language it was first said in — "已连接：…（曾因以下原因重新连接：cannot open (timed out)）" after
View › 中文 — though the status is written anew at every reading."""

from __future__ import annotations

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator

pytestmark = pytest.mark.slow  # a window and an instrument for seconds


def test_the_reconnect_reason_follows_the_language(window, qtbot):
    _show(window, "polygon")
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", faults=("disconnect",), disconnect_after=50,
                                 gap_s=0.4, positions=[(4.0, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=0.2, retries=4,
                         retry_pause_s=0.05)
        head = f"Connected: {sim.port} (reconnected after: "
        qtbot.waitUntil(lambda: panel.status.text().startswith(head), timeout=20000)
        english = panel.status.text()[len(head):-1]
        assert english  # e.g. "no answer for 0.2 s"
        try:
            window.set_language("zh_CN")
            qtbot.waitUntil(lambda: panel.status.text().startswith("已连接"), timeout=5000)
            qtbot.wait(300)  # a few readings more: the status written anew
            said = panel.status.text()
            assert "重新连接" in said and english not in said, said
        finally:
            window.set_language("en")
        panel.disconnect_instrument()
