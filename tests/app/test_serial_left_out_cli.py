"""Stop 67 on the command line: LRA-0815's calibration issued again with the serial said to
be none ("n/a", "-") passed as another item (a serial left empty makes a draft). Refused
(exit 2, naming the certificate, nothing written) without --another-lookalike-item; with
it, issued, and `register show` prints the user's word from the chain, which verifies."""

from __future__ import annotations

import json

from app.main import main
from models.register.location import register_url
from models.register.store import Register
from tests.own_readings import own_readings


def test_a_serial_left_out_is_issued_only_with_the_word_that_it_is_another_item(
        samples_dir, tmp_path, capsys, pdf_stand_in):
    """(Its PDFs stand-ins, tests/pdf_stand_in.py: the register's answers are read, no page.)"""
    def analyze(name, serial, *options):
        meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
        meta.update({"example": False, "certificate_number": "", "item_serial": serial})
        (tmp_path / f"{name}.json").write_text(json.dumps(meta), encoding="utf-8")
        # the item of no serial, another, has readings of its own (one item's are refused
        # as another's: hostile78 F7); LRA-0815's the sample's
        readings = samples_dir / "polygon_sample.csv"
        if serial != "LRA-0815":
            readings = own_readings(readings, f"no serial {name}", tmp_path / "readings")
        code = main(["analyze", "polygon", str(readings),
                     "--certificate", str(tmp_path / f"{name}.pdf"), "--metadata",
                     str(tmp_path / f"{name}.json"), *options])
        return code, capsys.readouterr().err

    assert analyze("a", "LRA-0815")[0] == 0
    with Register(register_url()) as register:
        [first] = [r.number for r in register.list()]
    # a serial not typed at all is a draft (the details incomplete), recorded nowhere
    code, err = analyze("draft", "")
    assert code == 0 and "DRAFT" in err and "item serial number missing" in err, err
    with Register(register_url()) as register:
        assert [r.number for r in register.list()] == [first]
    # said to have none: asked
    for blank in ("n/a", "-"):
        code, err = analyze("b", blank)
        assert code == 2, (code, err)
        assert "has no serial number, but an item of that description and maker calibrated " \
            f"2026-11-20 has one in the register: LRA-0815 ({first})" in err, err
        assert "--another-lookalike-item" in err and "no certificate was written" in err
        assert not (tmp_path / "b.pdf").exists()
    code, err = analyze("b", "n/a", "--another-lookalike-item")
    assert code == 0, err
    with Register(register_url()) as register:
        [second] = [r.number for r in register.list() if r.number != first]
    assert main(["register", "show", second]) == 0
    out = capsys.readouterr().out
    assert "another item, as " in out and f"not the item of {first} (LRA-0815)" in out, out
    assert main(["register", "verify"]) == 0
