"""No line of a Chinese certificate's 原始记录 (Readings) is a closing mark alone, and the
SHA-256 stays whole on its line (day review 67 F9: "），" stood alone on a line after the
SHA-256 of the file imported, which fills a line by itself, and fpdf2's character wrap
pushed the marks after it down)."""

from __future__ import annotations

import hashlib
import json

import pytest

from models.certificate.metadata import CertificateMetadata
from tests.pdf_text import CLOSING, pdf_lines

pytestmark = pytest.mark.slow  # a Chinese specimen written for each file name



@pytest.mark.parametrize("name", ["r.csv", "rrr.csv", "bench_run_0512.csv"])
def test_no_line_of_the_chinese_readings_line_is_a_closing_mark_alone(
        window, qtbot, tmp_path, samples_dir, name):
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    csv = tmp_path / name
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    digest = hashlib.sha256(csv.read_bytes()).hexdigest()
    polygon.import_file(csv)
    polygon.table_model.set_cells([(3, polygon.sheet.column_index("ac_x_arcsec"), "20.00")])
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": "", "language": "zh", "example": True})
    window.certificates.edit_details = lambda shown: CertificateMetadata.from_dict(data)
    window.certificates.view.confirm_standards = lambda warnings: True
    window.certificates.view.confirm_test_report = lambda why: True
    window.certificates.view.choose_save_path = (
        lambda title, suggested, kinds: str(tmp_path / "cert.pdf"))
    assert window.export_certificate(), window.told
    lines = pdf_lines(tmp_path / "cert.pdf")
    first = next(i for i, line in enumerate(lines) if name in line)
    last = next(i for i in range(first, len(lines)) if "编辑过" in lines[i])
    said = lines[first:last + 1]
    assert any(digest in line for line in said), said  # whole, on one line
    assert not [line for line in said if not line.strip(CLOSING + " ")], said
    assert said[-1].endswith("导入后在 AngleBench 中编辑过")
