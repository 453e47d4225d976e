"""A reference standard's due date (#43): printed in the PDF's standards table and in the
DCC's measuringEquipment; a standard whose calibration was due before the date of
calibration had expired, and — as for a standard with no certificate or no U — the
results are not traceable through it: the document is a test report naming it."""

from __future__ import annotations

import json
import shutil
import subprocess

import pytest
from lxml import etree

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.certificate.traceability import traceability_gaps
from models.dcc import vocabulary as v
from tests.app.test_dcc_out import NS, SCHEMA

THEODOLITE = "Autocollimating theodolite"


def _details(due: str) -> CertificateMetadata:
    return CertificateMetadata.from_dict({
        "certificate_number": "X", "lab_name": "L", "calibration_date": "2026-11-20",
        "standards": [{"description": THEODOLITE, "serial": "T-1", "certificate_no": "NIM-1",
                       "uncertainty": 0.5, "basis": "u", "due_date": due}]})


@pytest.mark.parametrize("due, expired", [("2027-05-01", False), ("2026-11-20", False),
                                          ("2026-11-19", True), ("", False)])
def test_a_standard_due_before_the_calibration_date_is_a_gap_naming_it(due, expired):
    gaps = [str(g) for g in traceability_gaps(_details(due), (("reference", "the theodolite"),))]
    if expired:
        assert len(gaps) == 1 and THEODOLITE in gaps[0] and "2026-11-19" in gaps[0]
        assert "expired" in gaps[0]
    else:
        assert gaps == []


@pytest.mark.slow
@pytest.mark.parametrize("due, expired", [("2027-05-01", False), ("2026-10-31", True)])
def test_the_due_date_is_printed_and_stated_in_the_dcc(due, expired, tmp_path, samples_dir,
                                                      monkeypatch, capsys):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    details["standards"][0]["due_date"] = due
    # real details: a specimen declares itself a specimen, not a calibration (assessment 70 M6)
    del details["example"], details["certificate_number"]
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    pdf, xml = tmp_path / "c.pdf", tmp_path / "c.xml"
    args = ["analyze", "theodolite", str(samples_dir / "theodolite_sample.csv"), "--metadata",
            str(meta), "--certificate", str(pdf), "--dcc", str(xml)]
    if SCHEMA is not None:
        args += ["--dcc-schema", str(SCHEMA)]
    code = main(args)
    said = capsys.readouterr()
    assert code == 0, said.out + said.err
    tree = etree.fromstring(xml.read_bytes())
    eq = tree.find(".//dcc:measuringEquipments/dcc:measuringEquipment", NS)
    quantity = eq.find(f".//dcc:measuringEquipmentQuantity[@refType='{v.REFTYPE_STANDARD_DUE}']",
                       NS)
    assert quantity.findtext("dcc:charsXMLList", namespaces=NS) == due
    assert eq.findtext("dcc:certificate/dcc:inValidityRange", namespaces=NS) == \
        ("false" if expired else "true")
    types = {s.get("refType") for s in tree.iterfind(".//dcc:statements/dcc:statement", NS)}
    assert (v.REFTYPE_NOT_A_CALIBRATION in types) is expired
    assert (v.REFTYPE_CALIBRATION_CERTIFICATE in types) is not expired
    if expired:
        assert "had expired" in xml.read_text(encoding="utf-8")
    if shutil.which("pdftotext"):
        text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True,
                              text=True).stdout
        assert due in text
        assert ("had expired" in " ".join(text.split())) is expired


@pytest.mark.parametrize("kind", ["theodolite", "polygon"])
@pytest.mark.parametrize("due, expired", [("2027-05-01", False), ("2026-10-31", True)])
def test_an_expired_standard_withholds_the_statement_of_conformity(kind, due, expired, tmp_path,
                                                                  samples_dir, capsys):
    """The U a standard's certificate states does not hold after its due date, so no
    statement of conformity is made on results it carries (ILAC-G8 4.2) — in the JSON as on
    the certificate — while the decided value and its interval are still given."""
    details = json.loads((samples_dir / f"certificate_{kind}.json").read_text(encoding="utf-8"))
    assert details.get("tolerance") is not None or kind == "polygon"  # the grade gives T
    for standard in details["standards"]:
        standard["due_date"] = due
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    code = main(["analyze", kind, str(samples_dir / f"{kind}_sample.csv"), "--metadata",
                 str(meta), "--json"])
    out = capsys.readouterr().out
    assert code == 0
    decided = json.loads(out[out.index("{"):])["decided_quantity"]
    assert isinstance(decided["value"], float) and decided["interval_high"] >= decided["value"]
    if expired:
        assert decided["verdict"] is None
        assert "had expired" in decided["reason"] and "2026-10-31" in decided["reason"]
    else:
        assert decided["verdict"] in ("pass", "conditional pass", "conditional fail", "fail")
