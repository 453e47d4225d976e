"""``capture --out``/``--raw`` never replace a file without --overwrite (contract75 F4: a
50-row polygon readings file became 3 autocollimator readings, and a previous capture's raw
record was replaced, exit 0 and "3 readings written"): refused at the start naming the file,
as 'register export' does; a file that appears under the name during the capture, or an
earlier capture's ``.partial.csv``, is kept and the readings go beside it, said. A killed
capture's journal is still recovered."""

from __future__ import annotations

import csv

from app.main import main
from models.capture.journal import CaptureJournal, journal_path
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

FAST = ["--silence", "0.2", "--retries", "1"]
POLYGON = "position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec\n" + "".join(
    f"{i},{i * 15},0,{i * 0.1:.1f},0\n" for i in range(50))


def rows_of(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.reader(handle))


def test_an_existing_out_or_raw_is_refused_naming_it_and_kept(tmp_path, capsys):
    readings, raw = tmp_path / "prev_readings.csv", tmp_path / "raw1.csv"
    for flag, existing in (("--out", readings), ("--raw", raw)):
        existing.write_text(POLYGON, encoding="utf-8")
        out = readings if flag == "--out" else tmp_path / "new.csv"
        with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)]) as sim:
            assert main(["capture", "autocollimator", sim.port, "--readings", "3",
                         "--out", str(out), "--raw", str(raw), *FAST, "--language", "en"]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert err == [f"anglebench capture: {flag} {existing} exists; nothing was captured: "
                       "choose another name, or add --overwrite to replace it"]
        assert existing.read_text(encoding="utf-8") == POLYGON
        assert not journal_path(out).exists()
        existing.unlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_overwrite_replaces_them(tmp_path, capsys):
    out, raw = tmp_path / "prev_readings.csv", tmp_path / "raw1.csv"
    out.write_text(POLYGON, encoding="utf-8")
    raw.write_text("time_s,reading,line\n0.1,1,old\n", encoding="utf-8")
    with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "3", "--out",
                     str(out), "--raw", str(raw), "--overwrite", *FAST, "--language", "en"]) == 0
    assert [tuple(map(float, r[1:])) for r in rows_of(out)[1:]] == [(12.5, -3.25)] * 3
    assert "old" not in raw.read_text(encoding="utf-8")
    assert f"3 readings written to {out}" in capsys.readouterr().err


def test_an_earlier_partial_file_is_kept_and_the_new_one_goes_beside_it(tmp_path, capsys):
    out = tmp_path / "part.csv"
    earlier = tmp_path / "part.partial.csv"
    earlier.write_text("time_s,value,unit\n0.5,7.25,deg\n", encoding="utf-8")
    with ReadoutSimulator("pty", positions=[(1.5,)]) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "100000", "--timeout",
                     "0.3", "--out", str(out), *FAST, "--language", "en"]) == 2
    assert earlier.read_text(encoding="utf-8") == "time_s,value,unit\n0.5,7.25,deg\n"
    (kept,) = tmp_path.glob("part.partial.captured-*.csv")
    rows = rows_of(kept)
    assert len(rows) > 2 and all(r[1:] == ["1.5", "deg"] for r in rows[1:])
    err = capsys.readouterr().err
    assert (f"{earlier} exists and is not replaced without --overwrite; written to {kept} "
            "instead") in err
    assert f"the {len(rows) - 1} readings taken are in {kept}" in err


def test_a_killed_captures_journal_is_recovered_before_an_existing_out_is_refused(
        tmp_path, capsys):
    out = tmp_path / "ac.csv"
    out.write_text(POLYGON, encoding="utf-8")
    killed = CaptureJournal(journal_path(out), ("time_s", "ac_x_arcsec", "ac_y_arcsec"),
                            {"out": str(out), "raw": ""})
    killed.reading(["0.1", "1.0", "2.0"])
    killed.reading(["0.2", "1.5", "2.5"])
    killed.close()
    assert main(["capture", "autocollimator", "/dev/null", "--out", str(out),
                 "--language", "en"]) == 2
    (recovered,) = tmp_path.glob("ac.recovered-*.csv")
    assert rows_of(recovered)[1:] == [["0.1", "1.0", "2.0"], ["0.2", "1.5", "2.5"]]
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"anglebench capture: an earlier capture into {out} did not end (killed?): "
                   f"its 2 readings are in {recovered}",
                   f"anglebench capture: --out {out} exists; nothing was captured: choose "
                   "another name, or add --overwrite to replace it"]
    assert out.read_text(encoding="utf-8") == POLYGON and not journal_path(out).exists()
