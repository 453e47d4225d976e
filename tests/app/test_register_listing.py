"""``anglebench register list`` as a lab clerk reads it (stop 63: tab-separated, no header,
its third column "not recorded" or "Calibration certificate" unexplained, an amended
certificate "superseded"): number, date of issue, workbench / document, customer, serial,
state, aligned under a header in either language; ``--json`` for scripts."""

from __future__ import annotations

import json
import re

from app.command_line import display_width
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register

PROJECT = '{"workbenches": {}}'


def _register() -> dict[str, str]:
    """An amended calibration certificate of a Chinese customer, a withdrawn test report
    and a replaced one, in the test's register."""
    first = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-01",
                                item_serial="RX-1", customer_name="上海光学仪器有限公司")
    other = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-02",
                                item_serial="X-2", customer_name="Acme Optics")
    third = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-03",
                                item_serial="Z-3", customer_name="Zeta GmbH")
    with Register(register_url()) as register:
        def issue(meta, kind, **how):
            return register.issue(IssueRequest("polygon", meta, PROJECT),
                                  lambda m, head="": f"%PDF {m.certificate_number}".encode(),
                                  document_kind=lambda: kind, **how)[0].number

        names = {"amended": issue(first, "calibration"), "withdrawn": issue(other, "test"),
                 "replaced": issue(third, "calibration")}
        names["amendment"] = issue(first, "calibration", supersedes=names["amended"],
                                   change_note="the serial corrected")
        names["replacement"] = issue(third, "calibration", supersedes=names["replaced"],
                                     replacement=True, change_note="re-issued")
        register.withdraw(names["withdrawn"], "wrong item")
    return names


def _columns(line: str, starts: list[int]) -> list[str]:
    """The cells of an aligned line, cut at the header's column starts (terminal columns)."""
    cells, at, cell = [], 0, ""
    bounds = starts[1:] + [10**6]
    for ch in line:
        if at >= bounds[len(cells)]:
            cells.append(cell.strip())
            cell = ""
        cell += ch
        at += display_width(ch)
    return cells + [cell.strip()]


def test_register_list_is_aligned_under_a_header_in_both_languages(capsys):
    names = _register()
    assert main(["register", "list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "\t" not in "".join(lines)
    header = lines[0]
    titles = ["Number", "Date of issue", "Workbench / document", "Customer", "Serial number",
              "State"]
    starts = [header.index(title) for title in titles]
    assert starts == sorted(starts) and starts[0] == 0
    rows = {cells[0]: cells for cells in (_columns(line, starts) for line in lines[1:])}
    assert rows[names["amended"]][1:] == [
        rows[names["amended"]][1], "polygon / Calibration certificate", "上海光学仪器有限公司",
        "RX-1", f"amended by {names['amendment']}"]
    assert rows[names["withdrawn"]][2:] == ["polygon / Test report", "Acme Optics", "X-2",
                                            "withdrawn"]
    assert rows[names["replaced"]][5] == f"replaced by {names['replacement']}"
    assert rows[names["amendment"]][5] == "issued"
    assert len(rows[names["amended"]][1]) == 10  # YYYY-MM-DD
    # in Chinese: the same columns, aligned by terminal width (a Chinese character is two)
    assert main(["register", "list", "--language", "zh_CN"]) == 0
    chinese = capsys.readouterr().out.splitlines()
    serial_at = {display_width(line[:re.search(r"\b(RX-1|X-2|Z-3)\b", line).start()])
                 for line in chinese[1:]}
    assert len(chinese) == 6 and len(serial_at) == 1, chinese  # each in the same column
    assert any("已作废" in line for line in chinese) and any("检测报告" in line for line in chinese)


def test_register_list_json_gives_the_registers_own_words(capsys):
    names = _register()
    assert main(["register", "list", "--json"]) == 0
    listed = {r["number"]: r for r in json.loads(capsys.readouterr().out)}
    assert listed[names["amended"]] | {"issue_date": ""} == {
        "number": names["amended"], "issue_date": "", "workbench": "polygon",
        "document_kind": "calibration", "customer": "上海光学仪器有限公司", "item_serial": "RX-1",
        "state": "amended", "superseded_by": names["amendment"], "revision": "original",
        "status": "superseded"}
    assert listed[names["withdrawn"]]["state"] == "withdrawn"
    assert listed[names["replaced"]]["state"] == "replaced"
    assert listed[names["amendment"]]["state"] == "issued"
    assert main(["register", "list", "RX-1", "--json", "--language", "zh_CN"]) == 0
    assert {r["state"] for r in json.loads(capsys.readouterr().out)} == {"issued", "amended"}
