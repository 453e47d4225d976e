"""A run in progress on the command line: the complete sets, mountings and runs analysed,
exit 0, JSON key ``incomplete``; the incomplete unit's readings enter no figure."""

import csv
import io
import json

import pytest

from app.main import main


def _rows(path):
    with open(path, encoding="utf-8-sig", newline="") as handle:
        table = list(csv.reader(handle))
    return table[0], table[1:]


def _write(path, header, rows):
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows([header, *rows])
    path.write_text(out.getvalue(), encoding="utf-8")
    return str(path)


def _json(capsys, kind, path, *options):
    code = main(["analyze", kind, path, "--json", *options])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    return json.loads(captured.out)


def _units(rows, column):
    """The rows grouped by the unit column, in the order measured."""
    out: dict[str, list] = {}
    for row in rows:
        out.setdefault(row[column], []).append(row)
    return list(out.values())


def _theodolite_passes(samples_dir):
    header, rows = _rows(samples_dir / "theodolite_sample.csv")
    passes = [[[*r, str(k), "+"] for r in rows] for k in (1, 2, 3)]
    return header + ["run", "direction"], passes


def _cases(samples_dir):
    """(kind, header, complete units, the last unit's rows, readings taken of it, unit, its
    number, readings a complete unit has)."""
    header, rows = _rows(samples_dir / "polygon_sample.csv")
    sets = _units(rows, header.index("set"))
    yield "polygon", header, sets[:-1], sets[-1], 3, "set", 2, 24
    header, rows = _rows(samples_dir / "crosscal_sample.csv")
    mountings = _units(rows, 0)
    yield "crosscal", header, mountings[:-1], mountings[-1], 5, "mounting", 11, 12
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    runs = _units(rows, 1)  # linear cycle: run 1 ↑ ↓, run 2 ↑ ↓, …
    yield "positioning", header, runs[:-1], runs[-1], 17, "run", 5, 26
    header, passes = _theodolite_passes(samples_dir)
    yield "theodolite", header, passes[:-1], passes[-1], 9, "pass", 3, 41


@pytest.mark.parametrize("index", range(4))
@pytest.mark.slow
def test_the_incomplete_unit_enters_no_figure(capsys, samples_dir, tmp_path, index):
    kind, header, complete, last, taken, unit, number, expected = list(_cases(samples_dir))[index]
    done = [r for block in complete for r in block]
    alone = _json(capsys, kind, _write(tmp_path / "complete.csv", header, done))
    partial = _json(capsys, kind, _write(tmp_path / "partial.csv", header, done + last[:taken]))
    assert alone.pop("incomplete") is None
    got = partial.pop("incomplete")
    assert got["unit"] == unit and got["number"] == number
    assert (got["readings"], got["expected"]) == (taken, expected)
    assert (got["first_row"], got["last_row"]) == (len(done) + 1, len(done) + taken)
    assert partial == alone  # every figure (and its U) as the complete part alone gives
    # the readable summary says what is in progress; a certificate is refused
    code = main(["analyze", kind, str(tmp_path / "partial.csv")])
    out = capsys.readouterr().out
    assert code == 0 and f"In progress: {got['text']}" in out
    code = main(["analyze", kind, str(tmp_path / "partial.csv"), "--certificate",
                 str(tmp_path / "c.pdf")])
    assert code == 2 and "a certificate waits for it" in capsys.readouterr().err
    assert not (tmp_path / "c.pdf").exists()
    # the whole of it, complete, is no run in progress
    whole = _json(capsys, kind, _write(tmp_path / "whole.csv", header, done + last))
    assert whole["incomplete"] is None


def test_pilgrim_cycle_in_progress_leaves_out_the_last_target(capsys, samples_dir, tmp_path):
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    targets = list(dict.fromkeys(float(r[0]) for r in rows))
    by_target = [sorted((r for r in rows if float(r[0]) == t), key=lambda r: (int(r[1]), r[2]))
                 for t in targets]
    done = [r for block in by_target[:-1] for r in block]
    alone = _json(capsys, "positioning", _write(tmp_path / "a.csv", header, done))
    partial = _json(capsys, "positioning",
                    _write(tmp_path / "b.csv", header, done + by_target[-1][:4]))
    got = partial.pop("incomplete")
    alone.pop("incomplete")
    assert (got["unit"], got["number"], got["readings"], got["expected"]) == (
        "target", targets[-1], 4, 10)
    assert partial == alone


def test_a_gap_in_the_middle_stays_an_error(capsys, samples_dir, tmp_path):
    header, rows = _rows(samples_dir / "polygon_sample.csv")
    sets = _units(rows, header.index("set"))
    gap = sets[0][:5] + sets[0][6:] + sets[1]  # set 1 lacks face 6, set 2 is complete
    code = main(["analyze", "polygon", _write(tmp_path / "gap.csv", header, gap), "--json"])
    assert code == 2 and "set 1" in capsys.readouterr().err
    header, rows = _rows(samples_dir / "crosscal_sample.csv")
    mountings = _units(rows, 0)
    gap = [r for m in mountings[:3] for r in m] + mountings[3][:4] + mountings[4]
    code = main(["analyze", "crosscal", _write(tmp_path / "gap2.csv", header, gap), "--json"])
    assert code == 2 and "mounting 3" in capsys.readouterr().err


def test_no_complete_unit_yet_is_said(capsys, samples_dir, tmp_path):
    header, rows = _rows(samples_dir / "polygon_sample.csv")
    path = _write(tmp_path / "first.csv", header, rows[:5])
    code = main(["analyze", "polygon", path, "--faces", "24"])
    err = capsys.readouterr().err
    assert code == 2 and "set 1: 5 of 24 faces: none is complete yet" in err


@pytest.mark.slow
def test_rows_waiting_for_their_reading_are_points_not_yet_taken(capsys, samples_dir, tmp_path):
    """A log written from the plan: run 5's remaining rows hold target, run and direction
    and no deviation yet. They are not bad rows; run 5 is in progress."""
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    runs = _units(rows, 1)
    done = [r for block in runs[:-1] for r in block]
    planned = [r[:3] + [""] for r in runs[-1][6:]]
    alone = _json(capsys, "positioning", _write(tmp_path / "a.csv", header, done))
    partial = _json(capsys, "positioning", _write(tmp_path / "b.csv", header,
                                                  done + runs[-1][:6] + planned))
    got = partial.pop("incomplete")
    alone.pop("incomplete")
    assert (got["unit"], got["number"], got["readings"], got["expected"]) == ("run", 5, 6, 26)
    assert partial == alone
    # a blank reading in the middle is still refused, naming its row (the file's line:
    # header line 1, contract review 75 F7)
    gap = done[:10] + [done[10][:3] + [""]] + done[11:]
    code = main(["analyze", "positioning", _write(tmp_path / "c.csv", header, gap)])
    assert code == 2 and "row 12: neither a deviation" in capsys.readouterr().err
