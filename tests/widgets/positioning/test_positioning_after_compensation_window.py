"""Before/after in the window (issue 35): File › Overlay a run… on the positioning workbench
takes the log measured after compensation, draws its mean deviations dashed on the
"Deviation per target" plot and states A, B, E before → after in the results text."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from models.display_units import ANGLE_UNITS
from models.positioning.analysis import POSITIONING
from models.positioning.before_after import before_after, log_from_file
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS


def _after_log(samples_dir, tmp_path):
    """The sample log as an ideal controller applying −x̄ per target and direction leaves it:
    each reading less its target's mean (the runs' scatter stays), written as a CSV."""
    kind = KINDS["positioning"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    before = kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                          kind.settings_with_defaults({}))
    up, down = before.iso.forward.mean, before.iso.backward.mean
    out = []
    for t, run, d, x in zip(before.targets, before.runs, before.directions, before.deviations,
                            strict=True):
        i = int(np.argmin(np.abs(before.positions - t)))
        out.append([f"{t:g}", f"{run:g}", "+" if d > 0 else "-",
                    f"{x - (up[i] if d > 0 else down[i]):.4f}"])
    path = tmp_path / "after_compensation.csv"
    with path.open("w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows([["target", "run", "direction", "deviation"], *out])
    return path


def _open(window, qtbot):
    presenter = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None, timeout=10000)
    return presenter


@pytest.mark.slow
def test_the_log_after_compensation_is_drawn_compared_and_removable(window, qtbot, samples_dir,
                                                                   tmp_path):
    presenter = _open(window, qtbot)
    path = _after_log(samples_dir, tmp_path)
    assert window.run_overlays.overlay_file(str(path))
    after = log_from_file(path, presenter.settings, POSITIONING)
    shown = presenter.after_compensation
    assert shown.shown and len(shown.curves) == 2
    for curve, stats in zip(shown.curves, (after.iso.forward, after.iso.backward), strict=True):
        x, y = curve.getData()
        np.testing.assert_allclose(x, after.positions)
        np.testing.assert_allclose(y, stats.mean, atol=1e-9)
        assert np.max(np.abs(y)) < 1e-3  # the ideal table leaves no mean deviation
    legend = presenter.view.deviation_plot.legend
    assert legend.getLabel(shown.curves[0]).text == "after compensation: after_compensation.csv ↑"
    # today's curves unchanged, drawn over
    _, today_up = presenter.view.deviation_plot.curves[0].getData()
    np.testing.assert_allclose(today_up, presenter.result.iso.forward.mean)
    ba = before_after(presenter.result, after)
    text = presenter.view.summary.toPlainText()
    line = [t for t in text.splitlines() if t.startswith("Before → after compensation")]
    assert len(line) == 1
    for key in ("A", "B", "E"):
        change = ba[key]
        assert f'{key} {change.before:.3f}" → {change.after:.3f}" ({-change.percent:+.0f} %)' \
            in line[0]
    assert ba["E"].after < 1e-3 and ba["B"].after < 1e-3 and ba["A"].after < ba["A"].before

    # in another unit: the curves and the figures follow
    presenter.set_angle_unit(ANGLE_UNITS["urad"])
    _, y = shown.curves[1].getData()
    np.testing.assert_allclose(y, after.iso.backward.mean * np.pi / 648000 * 1e6, atol=1e-6)
    assert f"E {ba['E'].before * np.pi / 648000 * 1e6:.3f} µrad" in \
        presenter.view.summary.toPlainText()
    presenter.set_angle_unit(ANGLE_UNITS["arcsec"])

    # today's readings edited: compared again, one line still
    presenter.refresh()
    qtbot.waitUntil(lambda: presenter.view.summary.toPlainText().count("Before → after") == 1,
                    timeout=10000)

    window.run_overlays.remove()
    assert not shown.shown and shown.curves == []
    assert "Before → after" not in presenter.view.summary.toPlainText()
    assert not any("after compensation" in item[1].text for item in legend.items)


@pytest.mark.slow
def test_a_log_that_cannot_be_compared_is_told(window, qtbot, samples_dir, tmp_path):
    presenter = _open(window, qtbot)
    # another workbench's readings: refused naming the file
    assert not window.run_overlays.overlay_file(str(samples_dir / KINDS["theodolite"].sample_file))
    assert "no column" in window.told[-1]
    assert not presenter.after_compensation.shown
    # a log without a common target: drawn, and the text says why it is not compared
    path = tmp_path / "elsewhere.csv"
    with path.open("w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows([["target", "run", "direction", "deviation"]] + [
            [f"{t}", "1", d, "0.5"] for t, d in ((1000, "+"), (1001, "+"), (1001, "-"),
                                                  (1000, "-"))])
    assert window.run_overlays.overlay_file(str(path))
    assert "Not compared with the log after compensation: the log after compensation has no " \
           "target in common" in presenter.view.summary.toPlainText()


@pytest.mark.slow
def test_the_command_line_compares_before_and_after(capsys, samples_dir, tmp_path):
    import json

    from app.main import main

    path = _after_log(samples_dir, tmp_path)
    before = samples_dir / KINDS["positioning"].sample_file
    ba = before_after(log_from_file(before, {}, POSITIONING), log_from_file(path, {}, POSITIONING))
    assert main(["analyze", "positioning", str(before), "--compare-after", str(path)]) == 0
    out = capsys.readouterr().out
    assert ba.text("after_compensation.csv") in out
    assert f'E {ba["E"].before:.3f}" → {ba["E"].after:.3f}" (-100 %)' in out
    assert main(["analyze", "positioning", str(before), "--compare-after", str(path),
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)["before_after"]
    assert data["after_file"] == str(path)
    assert data["figures"]["A"]["before"] == pytest.approx(ba["A"].before)
    assert data["figures"]["B"]["improvement_percent"] == pytest.approx(ba["B"].percent)
    # another workbench, or logs in other units: exit 2 with the reason
    assert main(["analyze", "theodolite", str(samples_dir / KINDS["theodolite"].sample_file),
                 "--compare-after", str(path)]) == 2
    assert "--compare-after is for the positioning workbench" in capsys.readouterr().err
    assert main(["analyze", "positioning", str(before), "--compare-after", str(path),
                 "--deviation-unit", "urad"]) == 0  # both analysed in µrad: comparable
    capsys.readouterr()
