"""#43: the polygon workbench's *Load polygon certificate…* takes the polygon's DCC (.xml):
its face deviations replace the readings' column (said when it held other values), the
polygon with its U joins the workbench's standards (so it enters the budget), and a DCC
refused changes nothing."""

from __future__ import annotations

import pytest

from models.dcc.reader import DccError
from tests import dcc_documents as t


@pytest.mark.slow
def test_a_polygon_dcc_fills_the_deviations_and_joins_the_standards(window, qtbot, tmp_path):
    polygon = window.presenter("polygon")
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    errors = t.polygon_errors(24, seed=5)
    dcc = tmp_path / "poly.xml"
    dcc.write_bytes(t.document("PTB-2026-0099", results=t.polygon_results(
        errors, unit=r"\micro\radian", u_arcsec=0.08), statements=t.validity(date="2099-12-31"),
        item="24-face polygon", serial="P24-3"))
    before = polygon.sheet.copy_rows()
    assert polygon.load_certificate(str(dcc)) == 50  # 24 faces, two sets, closures
    for row in range(polygon.sheet.row_count):
        face = int(polygon.sheet.text(row, 0))
        assert float(polygon.sheet.text(row, 2)) == pytest.approx(errors[face - 1], abs=1e-6)
    assert "held other values" in polygon.certificate_notes[0]
    standards = window.certificates.details("polygon").standards
    ours = [s for s in standards if s.certificate_no == "PTB-2026-0099"]
    assert len(ours) == 1 and ours[0].uncertainty == pytest.approx(0.08)
    assert (ours[0].basis, ours[0].due_date) == ("U95", "2099-12-31")
    assert polygon.load_certificate(str(dcc)) == 50  # again: the same standard, not twice
    assert len([s for s in window.certificates.details("polygon").standards
                if s.certificate_no == "PTB-2026-0099"]) == 1
    assert not any("held other values" in n for n in polygon.certificate_notes)
    polygon.undo_stack.undo()
    polygon.undo_stack.undo()
    assert polygon.sheet.copy_rows() == before
    twelve = tmp_path / "twelve.xml"
    twelve.write_bytes(t.document("OTHER-12"))
    with pytest.raises(DccError, match="faces"):
        polygon.load_certificate(str(twelve))
    assert polygon.sheet.copy_rows() == before


@pytest.mark.slow
def test_an_encoders_dcc_is_refused_and_changes_nothing(window, qtbot):
    """The polygon sample's encoder DCC as 0.8.11 wrote it (its reference polygon's face
    deviations under the calibrated polygon's refType): 0.8.11 filled the column with the
    reference's deviations and listed the encoder's certificate SPECIMEN-45AF2B79 as the
    polygon's. Refused now, naming the polygon's own certificate; nothing changes."""
    from tests.models.dcc.test_reference_polygon import WRITTEN_0_8_11

    polygon = window.presenter("polygon")
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    before = polygon.sheet.copy_rows()
    standards = window.certificates.details("polygon").standards
    with pytest.raises(DccError, match=r"certificate SPECIMEN-45AF2B79 calibrates an encoder "
                                       r"against a reference polygon.* its own certificate "
                                       r"NIM-2026-0871 \(as this DCC lists the standard\)"):
        polygon.load_certificate(str(WRITTEN_0_8_11))
    assert polygon.sheet.copy_rows() == before
    assert window.certificates.details("polygon").standards == standards
    assert not any(s.certificate_no == "SPECIMEN-45AF2B79"
                   for s in window.certificates.details("polygon").standards)
