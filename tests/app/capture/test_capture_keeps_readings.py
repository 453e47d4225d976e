"""``anglebench capture`` loses nothing: a real process against the protocol simulators,
ended by SIGTERM, SIGHUP or kill -9 mid-set; the journal beside the output; outputs that
are one file; readings outside the instrument's range; the raw lines in memory capped."""

from __future__ import annotations

import csv
import os
import signal
import subprocess
import sys
import time

import pytest

from app.capture.instruments import Autocollimator, LineReadoutInstrument
from app.capture.worker import CaptureWorker, DroppedLines
from app.main import main
from models.capture.errors import FrameError
from models.capture.journal import CaptureJournal, journal_path, read_journal
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

FAST = ["--silence", "0.5", "--retries", "1"]


def rows_of(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.reader(handle))


def _start(sim, out, raw=None, readings="100000"):
    argv = [sys.executable, "-m", "app.main", "capture", "autocollimator", sim.port,
            "--readings", readings, "--out", str(out), *FAST, "--language", "en"]
    if raw:
        argv += ["--raw", str(raw)]
    return subprocess.Popen(argv, stderr=subprocess.PIPE, text=True)


def _wait_for_readings(journal, n, proc, seconds=60.0):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        assert proc.poll() is None, proc.stderr.read()
        if journal.exists() and len(read_journal(journal).readings) >= n:
            return read_journal(journal).readings
        time.sleep(0.05)
    raise AssertionError(f"fewer than {n} readings in {journal} after {seconds} s")


@pytest.mark.slow
@pytest.mark.parametrize("ending", [signal.SIGTERM, signal.SIGHUP], ids=["SIGTERM", "SIGHUP"])
def test_a_signal_mid_set_leaves_every_reading_taken_on_disk(tmp_path, ending):
    """The process is asked to end after 20-odd readings: every reading it had taken (the
    journal, read just before the signal) is in FILE.partial.csv, each one a frame the
    instrument really sent, in order; the raw trace too; the journal is gone."""
    out, raw = tmp_path / "ac.csv", tmp_path / "ac.raw.csv"
    with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)], sigma=0.4,
                                 rate_hz=100) as sim:
        proc = _start(sim, out, raw)
        before = _wait_for_readings(journal_path(out), 20, proc)
        proc.send_signal(ending)
        _, err = proc.communicate(timeout=60)
    assert proc.returncode == 2, err
    partial = tmp_path / "ac.partial.csv"
    rows = rows_of(partial)
    assert rows[0] == ["time_s", "ac_x_arcsec", "ac_y_arcsec"]
    assert len(rows) - 1 >= len(before) >= 20
    assert rows[1:len(before) + 1] == before  # every reading taken before the signal
    for row, (x, y) in zip(rows[1:], sim.sent, strict=False):  # the instrument's frames
        assert float(row[1]) == pytest.approx(x, abs=6e-4)
        assert float(row[2]) == pytest.approx(y, abs=6e-4)
    lines = rows_of(tmp_path / "ac.raw.partial.csv")
    assert [r[0] for r in lines[1:] if r[2] and r[1] == "1"][:len(rows) - 1] == \
        [r[0] for r in rows[1:]]
    assert not journal_path(out).exists() and not out.exists()
    name = signal.Signals(ending).name
    assert f"stopped by {name}; the {len(rows) - 1} readings taken are in {partial}" in err


@pytest.mark.slow
def test_kill_9_leaves_the_readings_in_the_journal_and_the_next_start_says_where(tmp_path):
    out, raw = tmp_path / "ac.csv", tmp_path / "ac.raw.csv"
    with AutocollimatorSimulator("pty", positions=[(4.0, 2.0)], sigma=0.4, rate_hz=100) as sim:
        proc = _start(sim, out, raw)
        before = _wait_for_readings(journal_path(out), 15, proc)
        proc.kill()
        proc.communicate(timeout=30)
        kept = read_journal(journal_path(out))
        assert kept.readings[:len(before)] == before and len(kept.frames) >= len(before)
        assert kept.info["out"] == str(out.resolve()) and kept.info["instrument"] == \
            "autocollimator"
        done = subprocess.run([sys.executable, "-m", "app.main", "capture", "autocollimator",
                               sim.port, "--readings", "3", "--out", str(out), *FAST,
                               "--language", "en"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    recovered = sorted(tmp_path.glob("ac.recovered-*.csv"))
    raw_recovered = sorted(tmp_path.glob("ac.raw.recovered-*.csv"))
    assert len(recovered) == 1 and len(raw_recovered) == 1
    assert rows_of(recovered[0])[1:] == kept.readings
    assert len(rows_of(raw_recovered[0])) - 1 == len(kept.frames)
    assert (f"an earlier capture into {out} did not end (killed?): its {len(kept.readings)} "
            f"readings are in {recovered[0]}") in done.stderr
    assert len(rows_of(out)) == 4 and not journal_path(out).exists()


def test_out_and_raw_may_not_be_one_file(tmp_path, capsys):
    out = tmp_path / "same.csv"
    out.write_text("kept\n")
    link = tmp_path / "link.csv"
    link.symlink_to(out)
    hard = tmp_path / "hard.csv"
    os.link(out, hard)
    for raw in (out, link, hard):
        assert main(["capture", "autocollimator", "/dev/null", "--out", str(out),
                     "--raw", str(raw)]) == 2
        err = capsys.readouterr().err
        assert "--out and --raw name the same file" in err
    assert out.read_text() == "kept\n" and not journal_path(out).exists()


def test_an_output_onto_the_register_is_refused(tmp_path, capsys, monkeypatch):
    import sqlite3

    register = tmp_path / "register.sqlite"
    sqlite3.connect(register).execute("create table t (x)").connection.commit()
    before = register.read_bytes()
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(register))
    for flag in ("--out", "--raw"):
        other = tmp_path / "x.csv"
        argv = ["capture", "autocollimator", "/dev/null", "--out", str(other), flag,
                str(register)]
        assert main(argv) == 2
        assert "is the certificate register" in capsys.readouterr().err
    assert register.read_bytes() == before


def test_raw_lines_are_written_when_no_reading_was_taken(tmp_path, capsys):
    """Every frame out of the instrument's range (--range 1): nothing is taken, and the raw
    trace, exactly what is needed then, is written with every line marked refused."""
    out, raw = tmp_path / "ro.csv", tmp_path / "ro.raw.csv"
    with ReadoutSimulator("pty", positions=[(5.0,)]) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "3", "--range", "1",
                     "--timeout", "0.5", "--out", str(out), "--raw", str(raw), *FAST]) == 2
    lines = rows_of(tmp_path / "ro.raw.partial.csv")
    assert len(lines) > 3 and all(r[1] == "0" for r in lines[1:])
    assert not out.exists() and not (tmp_path / "ro.partial.csv").exists()
    err = capsys.readouterr().err
    assert "no reading was taken (the instrument's lines are in" in err
    assert not journal_path(out).exists()


def test_a_reading_outside_the_instruments_range_is_refused_as_a_frame(tmp_path, capsys):
    """1 000 000 005" is no autocollimator's reading: refused, counted, not taken."""
    out = tmp_path / "ac.csv"
    with AutocollimatorSimulator("pty", positions=[(1_000_000_005.0, 1.0)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "2", "--timeout",
                     "0.5", "--out", str(out), *FAST]) == 2
    assert not out.exists()
    assert "no reading was taken" in capsys.readouterr().err
    instrument = Autocollimator()
    instrument.check_range((3599.0, -3599.0))
    with pytest.raises(FrameError, match="ac_x_arcsec 1e\\+09 outside the instrument's range"):
        instrument.check_range((1_000_000_005.0, 0.0))
    with pytest.raises(FrameError, match="not a number"):
        instrument.check_range((float("nan"), 0.0))
    readout = LineReadoutInstrument()
    readout.check_range((1e12,))  # a readout's unit is its own: no range unless set
    readout.set_range(10.0)
    readout.check_range((-10.0,))
    with pytest.raises(FrameError, match="value 10.5 outside"):
        readout.check_range((10.5,))


def test_raw_lines_in_memory_are_capped_once_taken():
    worker = CaptureWorker("/dev/null", Autocollimator(), raw_cap=5)
    indices = [worker._keep(i * 0.1, b"line %d" % i, True) for i in range(12)]
    assert indices == list(range(12))
    assert [t for t, _, _ in worker.take_raw()] == [i * 0.1 for i in range(12)]
    assert len(worker.raw) == 5 and worker.raw_first == 7  # the oldest, taken, dropped
    assert worker._keep(9.9, b"next", False) == 12
    assert worker.take_raw() == [(9.9, b"next", False)] and len(worker.raw) == 5
    assert worker.raw[12 - worker.raw_first] == (9.9, b"next", False)


def test_raw_lines_are_read_by_their_index_since_the_start_and_a_dropped_one_is_refused():
    """The panel's worker drops the lines its sessions have converted (release): a line is
    read by its index since the start whatever was dropped, and asking for a dropped one is
    an error, never another line (a slice of the list as held named other lines)."""
    worker = CaptureWorker("/dev/null", Autocollimator())
    for i in range(10):
        worker._keep(i * 0.1, b"line %d" % i, i % 2 == 0)
    assert worker.release(4) == 4 and worker.raw_first == 4 and worker.raw_end == 10
    assert worker.lines(4, 6) == [(0.4, b"line 4", True), (0.5, b"line 5", False)]
    assert [line for _, line, _ in worker.lines(8)] == [b"line 8", b"line 9"]
    assert worker.lines(9, 99) == [(0.9, b"line 9", False)] and worker.lines(10) == []
    with pytest.raises(DroppedLines, match="lines 3…4 asked for, lines before 4 were dropped"):
        worker.lines(3, 5)
    assert worker.release(2) == 0 and worker.release(99) == 6  # never back; never past the newest
    assert worker.raw_first == worker.raw_end == 10 and worker._keep(1.0, b"line 10", True) == 10
    assert worker.lines(10) == [(1.0, b"line 10", True)]


def test_the_journal_reads_back_what_was_synced_and_never_replaces_one(tmp_path):
    path = tmp_path / "x.csv.capture-journal.csv"
    journal = CaptureJournal(path, ("time_s", "value", "unit"), {"out": "x.csv", "raw": ""})
    journal.frame(0.5, b"+1.25 deg\xff", True)
    journal.reading(["0.5", "1.25", "deg"])
    journal.frame(0.6, b'say "hi", 2', False)
    journal.close()
    with open(path, "a", encoding="utf-8") as handle:
        handle.write("reading,0.7,1.2")  # cut short by a kill: not a reading
    got = read_journal(path)
    assert got.columns == ("time_s", "value", "unit")
    assert got.readings == [["0.5", "1.25", "deg"]]
    assert got.frames == [("0.5", "1", "+1.25 deg\\xff"), ("0.6", "0", 'say "hi", 2')]
    assert got.info == {"out": "x.csv", "raw": ""}
    with pytest.raises(FileExistsError):
        CaptureJournal(path, ("time_s",), {})
    (tmp_path / "other.csv").write_text("a,b\n")
    with pytest.raises(ValueError, match="not a capture journal"):
        read_journal(tmp_path / "other.csv")
    (tmp_path / "cut.csv").write_text("# anglebench capt")  # killed while it was created
    assert read_journal(tmp_path / "cut.csv").readings == []


def test_a_full_disk_at_the_end_keeps_the_readings_in_the_journal(tmp_path, capsys,
                                                                   monkeypatch):
    import errno

    import app.issued_outputs as issued_outputs

    def full(url, path, data):  # the final write (checked against the issued files)
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(issued_outputs, "write_sparing_issued", full)
    out = tmp_path / "ro.csv"
    with ReadoutSimulator("pty", positions=[(1.5,)]) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "4", "--out", str(out),
                     *FAST]) == 2  # a write that fails exits 2, as analyze's (write_failure)
    journal = journal_path(out)
    assert read_journal(journal).readings and len(read_journal(journal).readings) == 4
    assert all(r[1:] == ["1.5", "deg"] for r in read_journal(journal).readings)
    err = capsys.readouterr().err
    assert (f"cannot write {out}: the disk is full; the 4 readings taken are kept in {journal}"
            in err), err
    assert "Errno" not in err and "No space left" not in err


def test_a_running_captures_journal_is_never_taken_for_a_killed_ones(tmp_path, capsys):
    out = tmp_path / "ac.csv"
    running = CaptureJournal(journal_path(out), ("time_s", "ac_x_arcsec", "ac_y_arcsec"),
                             {"out": str(out), "raw": ""})
    running.reading(["0.1", "1.0", "2.0"])
    try:
        assert main(["capture", "autocollimator", "/dev/null", "--out", str(out)]) == 2
        assert "another capture is writing into" in capsys.readouterr().err
        assert read_journal(journal_path(out)).readings == [["0.1", "1.0", "2.0"]]
    finally:
        running.close()
