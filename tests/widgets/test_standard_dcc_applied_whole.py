"""A DCC read into the certificate details' standards (*Read from DCC…*) or into the polygon
workbench (*Load polygon certificate…*) is applied as a whole or not at all (dccin74 F1,
F3, F4, F10): the row's standard must be the DCC's item; the row takes the number, U, basis,
unit, what U is per and the due date together, emptied where the DCC states none; a DCC
refused leaves the table, the column and the standards as they were and says why.

The DCCs are AngleBench's own (the cross-calibration sample's: polygon P12-7, its face 1
exact, from face 1), altered here with lxml."""

from __future__ import annotations

import json

import pytest
from lxml import etree

from models.certificate.metadata import CertificateMetadata
from tests.app.test_reference_dcc_checked import NS, polygon_dcc

pytestmark = pytest.mark.slow  # the cross-calibration sample is issued once (conftest)


@pytest.fixture(scope="module")
def issued_polygon(issued_samples):
    code, said, _, xml, _, _ = issued_samples["crosscal"]
    assert code == 0, said
    return xml


def _dialog(qtbot, samples_dir, **changes):
    from widgets.certificate_dialog import CertificateDialog

    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update(changes)
    dialog = CertificateDialog(CertificateMetadata.from_dict(data))
    qtbot.addWidget(dialog)
    return dialog


def _rows(dialog) -> list[dict]:
    return [s.__dict__.copy() for s in dialog.metadata().standards]


def test_a_polygons_dcc_never_overwrites_another_standards_row(issued_polygon, samples_dir,
                                                                qtbot):
    """F1: the polygon P12-7's DCC read while the autocollimator's row (AC-17) was selected
    wrote the polygon's number and U into the autocollimator's row; read into the row of
    polygon P24-3, it was taken for that polygon."""
    dialog = _dialog(qtbot, samples_dir)
    before = _rows(dialog)
    for row in (1, 0):  # the autocollimator's, then polygon P24-3's
        dialog.standards.selectRow(row)
        assert not dialog.read_standard_dcc(str(issued_polygon))
        assert _rows(dialog) == before
        assert "serial P12-7" in dialog.error_label.text()
        assert ("serial P24-3", "serial AC-17")[row] in dialog.error_label.text()


def test_the_row_takes_the_dcc_whole(issued_polygon, samples_dir, qtbot, tmp_path):
    """F3: a DCC that states no U kept the old certificate's U 0.2″ beside its new number;
    a polygon's DCC with U per reading left the row 'from face 1' (its U understated)."""
    dialog = _dialog(qtbot, samples_dir)
    dialog.standards.selectRow(0)  # polygon P24-3, NIM-2026-0871, 0.2″ U95 from face 1
    tree = etree.parse(str(issued_polygon))
    tree.find(".//dcc:identification/dcc:value", NS).text = "P24-3"
    for mu in list(tree.iter(f"{{{NS['si']}}}measurementUncertaintyUnivariateXMLList",
                             f"{{{NS['si']}}}measurementUncertaintyUnivariate")):
        mu.getparent().remove(mu)
    number = tree.findtext(".//dcc:coreData/dcc:uniqueIdentifier", namespaces=NS)
    no_u = tmp_path / "no_u.xml"
    tree.write(str(no_u), xml_declaration=True, encoding="UTF-8")
    assert dialog.read_standard_dcc(str(no_u)), dialog.error_label.text()
    row = dialog.metadata().standards[0]
    assert (row.certificate_no, row.serial, row.uncertainty) == (number, "P24-3", None)
    # per reading: face 1 with a deviation and a U of its own (as the polygon sample's)
    per_reading = polygon_dcc(issued_polygon, tmp_path / "reading.xml",
                              {i: 0.1 * ((-1) ** i) for i in range(1, 25)},
                              u=[0.15] * 24, serial="P24-3", alone=True)
    assert dialog.read_standard_dcc(str(per_reading)), dialog.error_label.text()
    row = dialog.metadata().standards[0]
    assert (row.uncertainty, row.basis, row.applies_to) == (0.15, "U95", "reading")


def test_an_empty_calibration_date_checks_expiry_against_today(issued_polygon, samples_dir,
                                                                qtbot, tmp_path):
    """F10: with the date field empty the expiry check was skipped: a calibration due in
    2011 was filled in without a word."""
    dialog = _dialog(qtbot, samples_dir, calibration_date="")
    dialog.standards.selectRow(0)
    before = _rows(dialog)
    expired = polygon_dcc(issued_polygon, tmp_path / "expired.xml",
                          {i: 0.0 for i in range(1, 25)}, serial="P24-3", end_date="2010-01-05",
                          period="P1Y")
    assert not dialog.read_standard_dcc(str(expired))
    assert "2011-01-05" in dialog.error_label.text() and _rows(dialog) == before
    # F5: a validity period past the year 9999 escaped the slot (ValueError), unsaid
    huge = polygon_dcc(issued_polygon, tmp_path / "huge.xml", {i: 0.0 for i in range(1, 25)},
                       serial="P24-3", period="P9999Y")
    assert not dialog.read_standard_dcc(str(huge))
    assert "after the year 9999" in dialog.error_label.text() and _rows(dialog) == before


def test_the_polygon_workbench_applies_nothing_of_a_refused_dcc(issued_polygon, samples_dir,
                                                                window, qtbot, tmp_path):
    """F4: a DCC with one face's U 5000″ filled the deviation column, then the details
    refused its U and the exception escaped the slot: the column held the DCC's deviations
    beside the previous certificate. F1: another polygon's DCC is refused the same way."""
    polygon = window.presenter("polygon")
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    window.certificates.store_details("polygon", CertificateMetadata.from_dict(json.loads(
        (samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))))
    before = polygon.sheet.copy_rows()
    standards = window.certificates.details("polygon").standards
    shifted = {i: 0.5 + 0.01 * i for i in range(1, 25)}
    big_u = polygon_dcc(issued_polygon, tmp_path / "big_u.xml", shifted,
                        u=[0.1] * 23 + [5000.0], serial="P24-3")
    other = polygon_dcc(issued_polygon, tmp_path / "other.xml", shifted)  # P12-7's
    told = []
    polygon.view.tell = lambda title, text: told.append(text)
    for dcc, said in ((big_u, "5000″ is beyond"), (other, "serial P12-7")):
        polygon.view.ask_certificate_file = lambda dcc=dcc: str(dcc)
        polygon.load_certificate_dialog()
        assert told and said in told[-1], told
        assert polygon.sheet.copy_rows() == before
        assert window.certificates.details("polygon").standards == standards
