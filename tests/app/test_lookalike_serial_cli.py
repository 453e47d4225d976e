"""rev65 F7 on the command line: a serial one look-alike from an item's in the register
("1ra-0815" beside LRA-0815) is refused without --another-lookalike-item, naming that
certificate; with it, issued as another item and `register show` prints the user's word from
the chain, which verifies."""

from __future__ import annotations

import json

from app.main import main
from models.register.location import register_url
from models.register.store import Register
from tests.own_readings import own_readings


def test_a_lookalike_serial_is_issued_only_with_its_option_and_shown(samples_dir, tmp_path,
                                                                     capsys, pdf_stand_in):
    """(Its PDFs stand-ins, tests/pdf_stand_in.py: the register's answers are read, no page.)"""
    def analyze(name, serial, *options, maker="Möller-Wedel Optical GmbH"):
        meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
        meta.update({"example": False, "certificate_number": "", "item_serial": serial,
                     "item_manufacturer": maker})
        (tmp_path / f"{name}.json").write_text(json.dumps(meta), encoding="utf-8")
        # another item, readings of its own (one item's are refused as another's: hostile78
        # F7); LRA-0815's the sample's
        readings = samples_dir / "polygon_sample.csv"
        if serial != "LRA-0815":
            readings = own_readings(readings, serial, tmp_path / "readings")
        code = main(["analyze", "polygon", str(readings),
                     "--certificate", str(tmp_path / f"{name}.pdf"), "--metadata",
                     str(tmp_path / f"{name}.json"), *options])
        return code, capsys.readouterr().err

    assert analyze("a", "LRA-0815")[0] == 0
    with Register(register_url()) as register:
        [first] = [r.number for r in register.list()]
    code, err = analyze("b", "1ra-0815")  # issued as another item before (rev65 F7)
    assert code == 2, (code, err)
    assert err.startswith(f"anglebench analyze: serial 1ra-0815 is in no certificate of the "
                          "register, but looks like LRA-0815 of Möller-Wedel Optical GmbH "
                          f"({first}). [1]ra-0815 vs [L]RA-0815: the digit 1 and the capital "
                          "letter L print alike, case aside."), err
    assert "--another-lookalike-item" in err and "no certificate was written" in err
    assert not (tmp_path / "b.pdf").exists()
    # the other question's word is not this one's
    code, err = analyze("b", "1ra-0815", "--another-makers-item")
    assert code == 2 and "looks like LRA-0815" in err, err
    # a makerless certificate's serial is any maker's
    code, err = analyze("c", "1RA-0815", maker="")
    assert code == 2 and "looks like LRA-0815" in err, err
    code, err = analyze("b", "1ra-0815", "--another-lookalike-item")
    assert code == 0, err
    with Register(register_url()) as register:
        [second] = [r.number for r in register.list() if r.number != first]
    assert main(["register", "show", second]) == 0
    out = capsys.readouterr().out
    assert "another item, as " in out and \
        f": serial 1ra-0815, not the item of {first} (LRA-0815)" in out, out
    assert main(["register", "verify"]) == 0
