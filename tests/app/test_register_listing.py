"""``anglebench register list`` as a lab clerk reads it (stop 63: tab-separated, no header,
its third column "not recorded" or "Calibration certificate" unexplained, an amended
certificate "superseded"): number, date of issue, workbench / document, customer, serial,
manufacturer (stop 67: none, though a serial is unique only within its maker), state,
aligned under a header in either language; ``--json`` for scripts."""

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
              "Manufacturer", "State"]
    starts = [header.index(title) for title in titles]
    assert starts == sorted(starts) and starts[0] == 0
    rows = {cells[0]: cells for cells in (_columns(line, starts) for line in lines[1:])}
    assert rows[names["amended"]][1:] == [
        rows[names["amended"]][1], "polygon / Calibration certificate", "上海光学仪器有限公司",
        "RX-1", "—", f"amended by {names['amendment']}"]
    assert rows[names["withdrawn"]][2:] == ["polygon / Test report", "Acme Optics", "X-2", "—",
                                            "withdrawn"]
    assert rows[names["replaced"]][6] == f"replaced by {names['replacement']}"
    assert rows[names["amendment"]][6] == "issued"
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
        "item_manufacturer": "", "state": "amended", "superseded_by": names["amendment"],
        "revision": "original", "status": "superseded"}
    assert listed[names["withdrawn"]]["state"] == "withdrawn"
    assert listed[names["replaced"]]["state"] == "replaced"
    assert listed[names["amendment"]]["state"] == "issued"
    assert main(["register", "list", "RX-1", "--json", "--language", "zh_CN"]) == 0
    assert {r["state"] for r in json.loads(capsys.readouterr().out)} == {"issued", "amended"}


def _two_makers_001() -> list[str]:
    """Acme's and Zeta's serial "001" (two items: the interval and due date are per serial
    and maker), and a certificate naming no maker."""
    with Register(register_url()) as register:
        def issue(serial, maker, day):
            meta = CertificateMetadata(approver="Dr. Li", calibration_date=day,
                                       item_serial=serial, item_manufacturer=maker,
                                       customer_name="Customer X")
            return register.issue(IssueRequest("polygon", meta, PROJECT),
                                  lambda m, head="": f"%PDF {m.certificate_number}".encode(),
                                  separate_calibration="", another_makers_item=True,
                                  document_kind="calibration")[0].number

        return [issue("001", "Acme  Optics GmbH", "2026-01-01"),
                issue("001", "Zeta Instruments", "2026-01-01"),
                issue("002", "", "2026-01-02")]


def test_register_list_names_each_certificates_manufacturer(capsys):
    """Stop 67: the list had no manufacturer, so Acme's and Zeta's "001" read as one item.
    The column stands after the serial, the columns before it where they were; "—" for a
    certificate naming none; spaces collapsed (a line break would break the line)."""
    acme, zeta, makerless = _two_makers_001()
    assert main(["register", "list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    titles = ["Number", "Date of issue", "Workbench / document", "Customer", "Serial number",
              "Manufacturer", "State"]
    starts = [lines[0].index(title) for title in titles]
    assert starts == sorted(starts) and lines[0].split()[-1] == "State"
    rows = {cells[0]: cells for cells in (_columns(line, starts) for line in lines[1:])}
    assert rows[acme][4:] == ["001", "Acme Optics GmbH", "issued"]
    assert rows[zeta][4:] == ["001", "Zeta Instruments", "issued"]
    assert rows[makerless][4:] == ["002", "—", "issued"]
    # in Chinese: the header in its language, the maker in its column
    assert main(["register", "list", "--language", "zh_CN"]) == 0
    chinese = capsys.readouterr().out.splitlines()
    assert "制造商" in chinese[0] and "Manufacturer" not in chinese[0]
    maker_at = {display_width(line[:line.index(maker)]) for line in chinese[1:]
                for maker in ("Acme Optics GmbH", "Zeta Instruments") if maker in line}
    assert len(maker_at) == 1, chinese
    # --json: a key added, every key before kept (scripts that read them go on working)
    assert main(["register", "list", "--json"]) == 0
    listed = {r["number"]: r for r in json.loads(capsys.readouterr().out)}
    assert listed[acme]["item_manufacturer"] == "Acme  Optics GmbH"  # as the register keeps it
    assert listed[zeta]["item_manufacturer"] == "Zeta Instruments"
    assert listed[makerless]["item_manufacturer"] == ""
    assert set(listed[acme]) == {"number", "issue_date", "workbench", "document_kind",
                                 "customer", "item_serial", "item_manufacturer", "state",
                                 "superseded_by", "revision", "status"}


def test_a_listing_read_by_head_ends_quietly(monkeypatch, capsys):
    """``anglebench register list | head -1``: the reader closes the pipe; the console script
    ends quietly (exit 0, nothing on stderr) as ``analyze … | head`` does, not with
    "cannot write: [Errno 32] Broken pipe" (stop 67)."""
    import io

    from app.main import entry

    _register()

    class ClosedPipe(io.StringIO):
        def write(self, text):
            raise BrokenPipeError(32, "Broken pipe")

        def fileno(self):
            return 1

    monkeypatch.setattr("sys.argv", ["anglebench", "register", "list"])
    monkeypatch.setattr("sys.stdout", ClosedPipe())
    monkeypatch.setattr("os.dup2", lambda *args: None)  # the test's stdout stays
    assert entry() == 0
    assert capsys.readouterr().err == ""
