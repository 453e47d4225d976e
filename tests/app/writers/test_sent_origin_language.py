"""A run sent to the positioning workbench, saved and opened again, says where its readings
came from in the certificate's language (day review 67 F3: the project file kept the
sending workbench's "Readings:" line as its English text, which a Chinese certificate then
printed in English: "由多面棱体编码器检测工作台发送（其读数：imported from …, edited in
AngleBench）")."""

from __future__ import annotations

import csv
import hashlib
import json
import os
import random
import shutil
import subprocess

import pytest

from models.certificate.metadata import CertificateMetadata
from models.messages import in_language, translator

pytestmark = pytest.mark.slow  # windows, each analysing a polygon run and a positioning one


def _four_sets(samples_dir, path) -> None:
    """A polygon-encoder run of four sets, two each way: the bundled sample's two sets (one
    forward, one back), then both again as a second reading of the same positions — the
    autocollimator's reading differs by its noise (σ 0.15″, seeded), the encoder reads the
    same table angle."""
    with open(samples_dir / "polygon_sample.csv", encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    noise = random.Random(67)
    again = []
    for row in rows:
        row = dict(row)
        row["set"] = str(int(row["set"]) + 2)
        row["ac_x_arcsec"] = f"{float(row['ac_x_arcsec']) + noise.gauss(0, 0.15):.2f}"
        again.append(row)
    with open(path, "w", encoding="utf-8", newline="") as f:
        out = csv.DictWriter(f, fieldnames=list(rows[0]))
        out.writeheader()
        out.writerows(rows + again)


def _settle(window, qtbot) -> None:
    qtbot.waitUntil(lambda: all(not p.analysis_pending for p in window.presenters),
                    timeout=30000)


def _pdf_text(path) -> str:
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    out = subprocess.run(["pdftotext", "-raw", "-enc", "UTF-8", str(path), "-"],
                         capture_output=True, text=True, check=True).stdout
    return "".join(out.split())  # a cell wraps anywhere: compared with no spaces


def _chinese_specimen(window, samples_dir, path) -> str:
    """The positioning workbench's certificate, in Chinese, written as a specimen (nothing
    recorded): its text as pdftotext reads it."""
    data = json.loads((samples_dir / "certificate_positioning.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": "", "language": "zh", "example": True})
    window.certificates.edit_details = lambda shown: CertificateMetadata.from_dict(data)
    window.certificates.view.confirm_standards = lambda warnings: True
    window.certificates.view.confirm_test_report = lambda why: True
    window.certificates.view.confirm_implausible = lambda doubt: True
    window.certificates.view.choose_save_path = lambda title, suggested, kinds: str(path)
    assert window.export_certificate(), window.told
    return _pdf_text(path)


def _sent(recovering_window, qtbot, tmp_path, samples_dir, recovery="recovery"):
    """A window whose polygon run (imported, one reading typed over) was sent to the
    positioning workbench: (the window, the run file's SHA-256)."""
    run = tmp_path / "bench_run_4sets.csv"
    _four_sets(samples_dir, run)
    digest = hashlib.sha256(run.read_bytes()).hexdigest()
    window = recovering_window("a", recovery)
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.import_file(run)
    column = polygon.sheet.column_index("ac_x_arcsec")
    polygon.table_model.set_cells([(2, column, "21.70")])  # one reading typed over
    _settle(window, qtbot)
    assert window.send_to_positioning(), window.told
    _settle(window, qtbot)
    return window, digest


def test_a_sent_origin_is_worded_in_chinese_after_the_project_is_opened_again(
        recovering_window, qtbot, tmp_path, samples_dir):
    window, digest = _sent(recovering_window, qtbot, tmp_path, samples_dir, "reca")
    before = _chinese_specimen(window, samples_dir, tmp_path / "before.pdf")
    project = tmp_path / "sent_positioning.anglebench.json"
    assert window.projects.save_to(project), window.told

    reopened = recovering_window("b", "recb")
    assert reopened.projects.open_project(project), reopened.told
    positioning = reopened.presenter("positioning")
    reopened.tabs.setCurrentIndex(reopened.presenters.index(positioning))
    _settle(reopened, qtbot)
    after = _chinese_specimen(reopened, samples_dir, tmp_path / "after.pdf")
    for text in (before, after):
        assert "bench_run_4sets.csv" in text and digest[:8] in text, text
        # not one English word of the origin on the Chinese certificate
        for english in ("importedfrom", "editedinAngleBench", "sentfrom", "itsreadings"):
            assert english not in text, (english, text)
    # the same words, the project's name before them once it is saved
    start = before.index("原始记录") + len("原始记录")
    said = before[start:before.index(digest[-4:], start) + 4]
    assert said.startswith("由") and f"{project.name}：{said}" in after, (said, after)


def test_a_sent_origin_is_worded_in_chinese_after_a_crash(recovering_window, qtbot, tmp_path,
                                                          samples_dir):
    window, digest = _sent(recovering_window, qtbot, tmp_path, samples_dir)
    line = window._readings_line(window.presenter("positioning"))
    chinese = in_language(line, translator("zh_CN"))
    # the window dies (kill -9) after an autosave: its lock goes with the process
    window.projects.autosave()
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()
    survivor = recovering_window("b")
    assert survivor.projects.offer_recovery(), survivor.told
    positioning = survivor.presenter("positioning")
    _settle(survivor, qtbot)
    recovered = survivor._readings_line(positioning)
    assert str(recovered) == str(line)
    again = in_language(recovered, translator("zh_CN"))
    assert again == chinese and digest in again and "imported from" not in again, again
