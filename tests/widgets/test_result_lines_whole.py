"""The Result pane's bold line and its warnings can be read whole at 200 % on a 1280×720
screen (640×360 logical pixels; day review 69, finding 5): fringe N = 8 with the highest
harmonic 3 and positioning at 3 runs had the bold line cut through mid-line and the warning
showing 2½ of its 6 lines, the qualifier "…the error it leaves there is not determined" out
of sight. Each label must now be given the height its whole word-wrapped text needs, and
what the pane cannot show at once must scroll into sight.

The fringe record is simulated from first principles (tests/fringe_channels.py); the
positioning one from tests/repeatability_rig.py; nothing from models/."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from PySide6.QtWidgets import QAbstractScrollArea, QLabel

from tests.fringe_channels import Channels, equal_steps
from tests.repeatability_rig import iso230_rows

pytestmark = pytest.mark.slow  # the window, analysed twice

HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4), 5: (0.004, 1.1)},
                cos_harmonics={3: (0.003, -0.3), 5: (0.0025, 0.2)}, noise_v=0.0003)
#: 1280×720 at QT_SCALE_FACTOR=2, in logical pixels
SIZE = (640, 360)


def _fringe_record(tmp_path: Path) -> Path:
    u_sin, u_cos = HEAD.sample(equal_steps(64 * 8, 8), np.random.default_rng(6905))
    path = tmp_path / "n8.csv"
    path.write_text("u_sin,u_cos\n" + "".join(f"{s:.9f},{c:.9f}\n"
                                             for s, c in zip(u_sin, u_cos, strict=True)))
    return path


def _axis_record(tmp_path: Path) -> Path:
    rng = np.random.default_rng(6906)
    angles = np.linspace(0.0, 360.0, 12, endpoint=False)
    f = 6.0 * np.sin(np.radians(angles)) + 2.0 * np.cos(np.radians(2 * angles))
    rows, _ = iso230_rows(angles, {"+": f + 2.5, "-": f - 2.5}, 3, 0.8, rng)
    path = tmp_path / "axis3.csv"
    path.write_text("target,run,direction,deviation\n" + "".join(
        f"{a},{r},{sign},{x}\n" for a, r, sign, x, _ in rows), encoding="utf-8")
    return path


def _scroll_area(label: QLabel) -> QAbstractScrollArea | None:
    parent = label.parentWidget()
    while parent is not None and not isinstance(parent, QAbstractScrollArea):
        parent = parent.parentWidget()
    return parent


def _whole(label: QLabel) -> list[str]:
    """What keeps ``label``'s text from being read whole, if anything: word-wrapped, as tall
    as its text at its width, and inside a scroll area that can bring all of it in sight."""
    wrong = []
    if not label.wordWrap():
        wrong.append("not word-wrapped")
    needs = label.heightForWidth(label.width())
    if label.height() < needs:
        wrong.append(f"{label.height()} px tall for {needs} px of text")
    area = _scroll_area(label)
    if area is None:
        wrong.append("in no scroll area")
    else:
        inside = area.widget() if hasattr(area, "widget") else None
        top = label.mapTo(inside, label.rect().topLeft()).y() if inside else 0
        bar = area.verticalScrollBar()
        reach = area.viewport().height() + bar.maximum()
        if top + label.height() > reach:
            wrong.append(f"ends at {top + label.height()} px, scrolls to {reach} px")
        if area.horizontalScrollBar().maximum() > 0:
            wrong.append("scrolls sideways")
    return wrong


def _show(window, qtbot) -> None:
    window.resize(*SIZE)
    window.show()
    qtbot.waitExposed(window)
    assert (window.width(), window.height()) == SIZE


def _check(window, qtbot, key: str, record: Path, settings: dict, ready) -> None:
    presenter = window.presenter(key)
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.import_file(record)
    if settings:
        presenter.set_settings({**presenter._settings, **settings})
    qtbot.waitUntil(lambda: presenter.result is not None and not presenter.analysis_pending
                    and ready(presenter.result), timeout=60000)
    view = presenter.view
    qtbot.waitUntil(lambda: view.verdict.isVisible() and view.warnings.isVisible(),
                    timeout=10000)
    qtbot.wait(50)  # the layout's own pass
    wrong = {name: _whole(label) for name, label in (("bold line", view.verdict),
                                                      ("warning", view.warnings))}
    assert not any(wrong.values()), (key, wrong, view.verdict.text())


def test_the_fringe_lines_can_be_read_whole_at_200_percent(window, qtbot, tmp_path):
    _show(window, qtbot)
    _check(window, qtbot, "fringe", _fringe_record(tmp_path),
           {"max_order": 3, "lines_per_rev": 16384, "samples_per_period": 8},
           lambda r: bool(r.folded_orders))


def test_the_positioning_lines_can_be_read_whole_at_200_percent(window, qtbot, tmp_path):
    _show(window, qtbot)
    _check(window, qtbot, "positioning", _axis_record(tmp_path), {}, lambda r: True)
