"""An amendment's or a replacement's DCC names the certificate it supersedes as PTB's schema
spells the change (coreData/reportAmendedSubstituted/typeOfChange: "amended" or
"substituted"); the writer wrote "amendment"/"substitution", which DCC 3.3.0 refuses, so
an amendment issued with its DCC validated was refused and none issued."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lxml import etree

from app.certificate_issue import issue_certificate
from app.dcc_issue import render_dcc
from models.certificate.metadata import CertificateMetadata
from models.dcc import vocabulary as v
from models.dcc.schema import validate
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.store import Register
from models.registry import KINDS

pytestmark = pytest.mark.slow  # three certificates with their DCCs

ROOT = Path(__file__).resolve().parents[2]
SCHEMA = next((p / "shared" / "dcc" for p in ROOT.parents
               if (p / "shared" / "dcc" / "dcc.xsd").is_file()), None)
NS = {"dcc": v.DCC_NAMESPACE}


@pytest.mark.skipif(SCHEMA is None, reason="PTB's DCC schema set (../shared/dcc) is not "
                                           "beside the repository")
def test_an_amendment_and_a_replacement_give_schema_valid_dccs(tmp_path, samples_dir):
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    settings = kind.checked_settings({})
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    data = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    data.update(certificate_number="", example=False, approver="Dr. Li")
    metadata = CertificateMetadata.from_dict(data)

    def dcc(document, pdf):
        return render_dcc(kind, result, document, pdf, "c.pdf", str(SCHEMA), settings)

    def issue(name: str, **revision):
        return issue_certificate(register, kind, result, metadata, settings, rows,
                                 "theodolite_sample.csv", str(tmp_path / f"{name}.pdf"),
                                 dcc=dcc, dcc_path=str(tmp_path / f"{name}.xml"), **revision)

    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}") as register:
        original = issue("original")
        amended = issue("amended", supersedes=original.number, change_note="the humidity")
        replaced = issue("replaced", supersedes=amended.number, replacement=True,
                         change_note="the customer's address")
    for name, change, superseded in (("amended", "amended", original.number),
                                     ("replaced", "substituted", amended.number)):
        xml = (tmp_path / f"{name}.xml").read_bytes()
        assert validate(xml, SCHEMA) == []
        core = etree.fromstring(xml).find(".//dcc:coreData/dcc:reportAmendedSubstituted", NS)
        assert core.findtext("dcc:typeOfChange", namespaces=NS) == change
        assert core.findtext("dcc:replacedUniqueIdentifier", namespaces=NS) == superseded
    assert replaced.supersedes == amended.number


@pytest.mark.skipif(SCHEMA is None, reason="PTB's DCC schema set (../shared/dcc) is not "
                                           "beside the repository")
def test_the_dcc_of_an_amendment_says_what_changed(tmp_path, samples_dir):
    """ISO/IEC 17025 7.8.8.2: the amended report identifies the change. The PDF said it under
    its title; the DCC named only the certificate superseded (reportAmendedSubstituted has
    no room for a reason): now a statement says it, a confirmed corrected serial first, in
    English and Chinese, schema-valid, the superseded certificate as its reference."""
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    settings = kind.checked_settings({})
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    data = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    data.update(certificate_number="", example=False, approver="Dr. Li", language="zh+en")
    metadata = CertificateMetadata.from_dict(data)

    def dcc(document, pdf):
        return render_dcc(kind, result, document, pdf, "c.pdf", str(SCHEMA), settings)

    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}") as register:
        original = issue_certificate(register, kind, result, metadata, settings, rows,
                                     "theodolite_sample.csv", str(tmp_path / "o.pdf"), dcc=dcc,
                                     dcc_path=str(tmp_path / "o.xml"))
        corrected = CertificateMetadata.from_dict({**metadata.to_dict(),
                                                   "item_serial": metadata.item_serial + "9"})
        issue_certificate(register, kind, result, corrected, settings, rows,
                          "theodolite_sample.csv", str(tmp_path / "a.pdf"), dcc=dcc,
                          dcc_path=str(tmp_path / "a.xml"), supersedes=original.number,
                          change_note="the humidity was 45 %, not 54 %",
                          correction_confirmed=True)
    original_xml = etree.fromstring((tmp_path / "o.xml").read_bytes())
    assert original_xml.find(".//dcc:statement[@refType='anglebench_revision']", NS) is None
    xml = (tmp_path / "a.xml").read_bytes()
    assert validate(xml, SCHEMA) == []
    statement = etree.fromstring(xml).find(".//dcc:statement[@refType='anglebench_revision']",
                                           NS)
    assert statement is not None
    assert statement.findtext("dcc:reference", namespaces=NS) == original.number
    said = {c.get("lang"): c.text for c in statement.find("dcc:declaration", NS)}
    serial = metadata.item_serial
    assert said["en"] == (
        f"Amendment 1 to certificate {original.number}, which it supersedes; the original "
        f"stays on record unchanged. Changed: serial number corrected from {serial} (on "
        f"{original.number}) to {serial}9; the humidity was 45 %, not 54 %")
    assert said["zh"].startswith(f"证书 {original.number} 的第 1 号修改")
    assert f"序列号由 {serial}（见 {original.number}）更正为 {serial}9" in said["zh"]
    assert said["zh"].endswith("the humidity was 45 %, not 54 %")
