"""The register's search finds what prints alike (hostile78 S1)."""

from __future__ import annotations

import json

_PROJECT = json.dumps({"format": "anglebench-project", "workbenches": {}, "metadata": {}})


def test_the_registers_search_finds_what_prints_alike(tmp_path):
    """hostile78 S1: a customer typed with a Cyrillic "А" was not found by "Acme Optics",
    nor a serial LRA-0980 by "LRA-098O", though the register takes serials that print alike
    as one item; found now, and what was found before still is."""
    from models.certificate.metadata import CertificateMetadata
    from models.register.store import IssueRequest, Register

    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}") as register:
        for serial, customer in (("LRA-0980", "\u0410cme Optics"), ("XY-1", "Zeta Ltd")):
            meta = CertificateMetadata(
                lab_name="Lab", customer_name=customer, item_description="Axis",
                item_serial=serial, calibration_date="2026-11-20", operator="Wang",
                approver="Dr. Li", standards=())
            register.issue(IssueRequest("theodolite", meta, _PROJECT), lambda m: b"%PDF")
        found = {key: [r.customer for r in register.list(key)]
                 for key in ("Acme Optics", "LRA-098O", "lra-0980", "zeta", "XY-1", "0980",
                             "nothing")}
    assert found == {"Acme Optics": ["\u0410cme Optics"], "LRA-098O": ["\u0410cme Optics"],
                     "lra-0980": ["\u0410cme Optics"], "zeta": ["Zeta Ltd"],
                     "XY-1": ["Zeta Ltd"], "0980": ["\u0410cme Optics"], "nothing": []}
