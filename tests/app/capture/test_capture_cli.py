"""``anglebench capture`` end to end: the command line against the protocol simulators
over a pseudo-terminal (and TCP), as CI runs it, without hardware."""

from __future__ import annotations

import csv
import math
import subprocess
import sys

import numpy as np
import pytest

from app.main import main
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator, TheodoliteSimulator

FAST = ["--silence", "0.2", "--retries", "1"]


def rows_of(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.reader(handle))


def test_autocollimator_readings_to_csv(tmp_path, capsys):
    out = tmp_path / "ac.csv"
    with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "25",
                     "--out", str(out), *FAST]) == 0
    rows = rows_of(out)
    assert rows[0] == ["time_s", "ac_x_arcsec", "ac_y_arcsec"]
    assert [tuple(map(float, r[1:])) for r in rows[1:]] == [(12.5, -3.25)] * 25
    times = [float(r[0]) for r in rows[1:]]
    assert times == sorted(times) and times[-1] - times[0] == pytest.approx(24 / 250, abs=0.08)
    assert "25 readings written to" in capsys.readouterr().err


@pytest.mark.slow
def test_stability_gated_readings_of_a_set_of_positions(tmp_path):
    """Four positions held 0.3 s each with 0.05" noise: one reading per position, the mean
    of a 0.1 s dwell, within 0.05" of where the instrument really was; the frames while
    it moves never give a reading."""
    positions = [(100.0, 5.0), (200.0, 5.0), (300.0, -5.0), (400.0, 0.0)]
    out = tmp_path / "set.csv"
    with AutocollimatorSimulator("pty", positions=positions, hold_s=0.3, sigma=0.05) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "4", "--stable", "0.5",
                     "--dwell", "0.1", "--out", str(out), *FAST]) == 0
    got = [tuple(map(float, r[1:])) for r in rows_of(out)[1:]]
    assert len(got) == 4
    for (x, y), (tx, ty) in zip(got, positions, strict=True):
        assert abs(x - tx) < 0.05 and abs(y - ty) < 0.05


@pytest.mark.slow
def test_a_stable_reading_never_bridges_a_lost_link(tmp_path):
    """The link is lost 0.2 s into a dwell of 0.5 s (0.4 s of silence): the reading is taken
    0.5 s after the frames come back, from them only (it was taken with the first frame
    after the gap, from the frames before it)."""
    out, raw = tmp_path / "one.csv", tmp_path / "raw.csv"
    with AutocollimatorSimulator("pty", faults=("disconnect",), disconnect_after=50, gap_s=0.4,
                                 positions=[(4.0, 1.0)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "1", "--stable", "0.3",
                     "--dwell", "0.5", "--out", str(out), "--raw", str(raw), *FAST]) == 0
    assert sim.cuts == 1
    taken_at = float(rows_of(out)[1][0])
    times = sorted(float(r[0]) for r in rows_of(raw)[1:])
    gaps = [b - a for a, b in zip(times, times[1:], strict=False)]
    back = times[gaps.index(max(gaps)) + 1]  # the first frame after the silence
    assert max(gaps) > 0.2 and taken_at >= back + 0.5 - 1e-6, (taken_at, back)


@pytest.mark.slow
def test_stable_readings_are_traced_to_the_lines_of_their_dwell(tmp_path):
    """With --stable --raw, the raw lines marked as a reading are those of each reading's
    dwell, and their mean is the reading (every frame of the stream was marked)."""
    out, raw = tmp_path / "set.csv", tmp_path / "set.raw.csv"
    positions = [(100.0, 5.0), (200.0, 5.0), (300.0, -5.0)]
    with AutocollimatorSimulator("pty", positions=positions, hold_s=0.4, sigma=0.05) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "3", "--stable", "0.5",
                     "--dwell", "0.1", "--out", str(out), "--raw", str(raw), *FAST]) == 0
    readings = [tuple(map(float, r)) for r in rows_of(out)[1:]]
    lines = rows_of(raw)[1:]
    runs, run = [], []
    for time_s, used, line in lines:  # the runs of lines marked 1
        if used == "1":
            run.append((float(time_s), [float(v) for v in line.split()[2:]]))
        elif run:
            runs.append(run)
            run = []
    runs += [run] if run else []
    assert len(runs) == 3 and sum(r[1] == "0" for r in lines) > 0
    for (t, x, y), run in zip(readings, runs, strict=True):
        assert run[-1][0] == pytest.approx(t, abs=1e-6)  # the reading's time: its last line's
        assert run[-1][0] - run[0][0] >= 0.1 - 1e-6  # they cover the dwell
        mean = np.mean([v for _, v in run], axis=0)
        assert mean == pytest.approx([x, y], abs=1e-9)


def test_theodolite_over_tcp_and_a_disconnect_mid_set(tmp_path, capsys):
    out = tmp_path / "theo.csv"
    positions = [(30.0 * i, 90.0 + i / 100) for i in range(1, 5)]
    with TheodoliteSimulator("tcp", faults=("disconnect",), disconnect_after=6, positions=positions,
                             hold_s=0.2) as sim:
        assert main(["capture", "theodolite", sim.port, "--readings", "15",
                     "--out", str(out), *FAST]) == 0
    rows = rows_of(out)
    assert rows[0] == ["time_s", "azimuth_deg", "zenith_deg"]
    got = [tuple(map(float, r[1:])) for r in rows[1:]]
    assert len(got) == 15
    for (hz, v), (shz, sv) in zip(got, sim.sent[:15], strict=True):
        assert math.isclose(hz, shz, abs_tol=1e-7) and math.isclose(v, sv, abs_tol=1e-7)
    err = capsys.readouterr().err
    assert f"{sim.port}: the link dropped" in err and "reconnecting" in err


def test_a_readout_with_noise_and_error_lines(tmp_path):
    out = tmp_path / "ro.csv"
    with ReadoutSimulator("pty", faults=("noise", "invalid_axes"), positions=[(105.00012,)]) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "8", "--out", str(out),
                     *FAST]) == 0
    rows = rows_of(out)
    assert rows[0] == ["time_s", "value", "unit"]
    assert [r[1:] for r in rows[1:]] == [["105.00012", "deg"]] * 8


@pytest.mark.parametrize(("fault", "says"), [("silence", "no answer for 0.2 s"),
                                             ("wrong_baud", "a wrong baud rate? 9600 was used")])
def test_a_dead_instrument_exits_2_with_one_line_naming_the_port(tmp_path, capsys, fault, says):
    out = tmp_path / "x.csv"
    # it streams nothing, so it is polled too (--mode auto): each request waits its reply for
    # --reply-timeout (5 s by default: the test waited 2 × 5 s for nothing)
    with AutocollimatorSimulator("pty", faults=(fault,)) as sim:
        assert main(["capture", "autocollimator", sim.port, "--out", str(out), *FAST,
                     "--reply-timeout", "0.2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith(f"anglebench capture: {sim.port}: ") and says in err[-1]
    assert err[-1].endswith("no reading was taken")
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_a_wrong_port_exits_2(tmp_path, capsys):
    out = tmp_path / "x.csv"
    assert main(["capture", "theodolite", "/dev/no-such-port", "--out", str(out), "--retries", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("anglebench capture: /dev/no-such-port: cannot open")


def test_readings_taken_before_a_final_fault_are_kept(tmp_path, capsys):
    out = tmp_path / "part.csv"
    with ReadoutSimulator("pty", positions=[(1.5,)]) as sim:
        # asks for more readings than the time allows
        assert main(["capture", "readout", sim.port, "--readings", "100000", "--timeout", "0.3",
                     "--out", str(out), *FAST]) == 2
    partial = tmp_path / "part.partial.csv"
    assert not out.exists() and partial.exists()
    rows = rows_of(partial)
    assert len(rows) > 2 and all(r[1:] == ["1.5", "deg"] for r in rows[1:])
    err = capsys.readouterr().err.strip()
    assert f"readings in 0.3 s; the {len(rows) - 1} readings taken are in {partial}" in err


@pytest.mark.parametrize(("argv", "says"), [
    (["--stable", "1"], "--stable and --dwell go together"),
    (["--readings", "0"], "'0': give a number greater than 0"),
    (["--pattern", "(?P<v>x)"], "--pattern"),
])
def test_refused_options(tmp_path, capsys, argv, says):
    kind = "readout" if "--pattern" in argv else "autocollimator"
    try:
        status = main(["capture", kind, "/dev/null", "--out", str(tmp_path / "x.csv"), *argv])
    except SystemExit as exc:  # argparse's refusal
        status = exc.code
    assert status == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and says in err[0]


@pytest.mark.slow
def test_the_console_command_in_chinese(tmp_path):
    """The real entry point in a process of its own, speaking Chinese."""
    with ReadoutSimulator("pty", positions=[(2.0,)]) as sim:
        done = subprocess.run([sys.executable, "-m", "app.main", "capture", "readout", sim.port,
                               "--readings", "3", "--out", str(tmp_path / "r.csv"),
                               "--language", "zh_CN"], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert len(rows_of(tmp_path / "r.csv")) == 4
    assert done.stderr.strip() == f"3 个读数已写入 {tmp_path / 'r.csv'}"


def test_a_theodolite_settled_across_zero_azimuth_reads_where_it_is(tmp_path):
    """Hz noise of 2" around 0°: the frames read 359.999…° and 0.000…°; the gated reading
    is their mean near 0° (or just under 360°), never 180°."""
    out = tmp_path / "zero.csv"
    with TheodoliteSimulator("pty", positions=[(0.0, 90.0)], sigma=2.0) as sim:
        assert main(["capture", "theodolite", sim.port, "--readings", "1", "--stable", "20",
                     "--dwell", "0.1", "--timeout", "5", "--out", str(out), *FAST]) == 0
    hz, v = (float(x) for x in rows_of(out)[1][1:])
    assert min(hz, 360.0 - hz) * 3600 < 3.0 and abs(v - 90.0) * 3600 < 3.0
    assert sim.sent and any(h > 180 for h, _ in sim.sent if h) and any(h < 180 for h, _ in sim.sent)


@pytest.mark.slow
def test_a_theodolite_in_face_two_of_its_first_target_settles(tmp_path):
    """A target read in face I (Hz 10°, V 90°), then in face II (Hz 190°, V 270°) with 0.3"
    noise: face II is 180° from the first frame, whose offsets jumped between +180° and
    −180° and never settled (1 of 2 readings before the timeout)."""
    out = tmp_path / "faces.csv"
    with TheodoliteSimulator("pty", positions=[(10.0, 90.0), (190.0, 270.0)], hold_s=1.5,
                             sigma=0.3) as sim:
        assert main(["capture", "theodolite", sim.port, "--readings", "2", "--stable", "5",
                     "--dwell", "0.3", "--timeout", "8", "--out", str(out), *FAST]) == 0
    (hz1, v1), (hz2, v2) = [tuple(float(x) for x in r[1:]) for r in rows_of(out)[1:]]
    assert abs(hz1 - 10.0) * 3600 < 1 and abs(v1 - 90.0) * 3600 < 1
    assert abs(hz2 - 190.0) * 3600 < 1 and abs(v2 - 270.0) * 3600 < 1
    assert any(abs(h - 190.0) * 3600 < 2 and h < 190.0 for h, _ in sim.sent if h) and \
        any(h > 190.0 for h, _ in sim.sent if h)  # its frames fell both sides of 190°


def test_the_raw_record_traces_every_reading_to_the_instruments_line(tmp_path):
    out, raw = tmp_path / "ac.csv", tmp_path / "ac.raw.csv"
    with AutocollimatorSimulator("pty", faults=("invalid_axes",), positions=[(4.0, -2.5)],
                                 sigma=0.3) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "20", "--out", str(out),
                     "--raw", str(raw), *FAST]) == 0
    readings = rows_of(out)[1:]
    lines = rows_of(raw)
    assert lines[0] == ["time_s", "reading", "line"]
    used = [r for r in lines[1:] if r[1] == "1"]
    assert [r[0] for r in used][:20] == [r[0] for r in readings]
    for (_, x, y), (_, _, line) in zip(readings, used, strict=False):
        assert line.split()[2:] == [f"{float(x):.3f}", f"{float(y):.3f}"]
    refused = [r[2] for r in lines[1:] if r[1] == "0"]
    assert refused and all(r.split()[1] in ("001", "002", "000") for r in refused)
    # the record holds the frames the simulator sent, in order, none left out
    assert [r[1] == "1" for r in lines[1:]] == [None not in f for f in sim.sent[:len(lines) - 1]]


def test_a_results_file_issued_under_out_during_the_capture_is_never_replaced(
        tmp_path, capsys, monkeypatch):
    """--out was checked against the issued files at the start only: a results file issued
    under that name while the capture ran (a certificate's --results r.csv) was replaced by
    the final write, the only copy. Checked again when placed: kept, the readings written
    beside it under a name of their own, said."""
    import app.capture.cli as capture_cli
    from models.certificate.metadata import CertificateMetadata
    from models.register.location import register_url
    from models.register.store import IssueRequest, Register

    out = tmp_path / "r.csv"
    issued = b"number,figure\nAB-1,0.25\n"
    real_finish = capture_cli._finish

    def issued_meanwhile(*args, **kwargs):
        meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                                   item_serial="RX-1")
        with Register(register_url()) as register:  # an issue writing r.csv, recorded
            number = register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                                    lambda m, head="": b"%PDF stand-in")[0].number
            register.record_results(number, issued, out.name)
        out.write_bytes(issued)
        return real_finish(*args, **kwargs)

    monkeypatch.setattr(capture_cli, "_finish", issued_meanwhile)
    with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "5",
                     "--out", str(out), *FAST]) == 0
    err = capsys.readouterr().err
    assert out.read_bytes() == issued
    (kept,) = tmp_path.glob("r.captured-*.csv")
    assert [tuple(map(float, r[1:])) for r in rows_of(kept)[1:]] == [(12.5, -3.25)] * 5
    assert f"{out} is the results file of certificate AB-" in err
    assert f"written to {kept} instead" in err and f"5 readings written to {kept}" in err
    assert not list(tmp_path.glob(".*.tmp")) and not list(tmp_path.glob("*journal*"))


@pytest.mark.slow
def test_stable_window_is_arcseconds_for_a_readout_in_degrees(tmp_path, capsys):
    """``--stable`` means arcseconds for every angle, as the window's auto-take does: a
    readout sending degrees and drifting 36″ a second (0.01°/s) is never taken at
    ``--stable 0.5`` (applied in its degrees, 0.5° took the drift as stable); the same
    readout held still is taken, its mean the position it sent."""
    drifting = tmp_path / "drift.csv"
    with ReadoutSimulator("tcp", positions=[(15.0,)], drift_per_s=36.0 / 3600.0) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "1", "--stable", "0.5",
                     "--dwell", "0.3", "--timeout", "1.5", "--out", str(drifting),
                     *FAST]) != 0
    assert "0 of 1 readings in 1.5 s" in capsys.readouterr().err
    steady = tmp_path / "steady.csv"
    with ReadoutSimulator("tcp", positions=[(15.0,)], sigma=0.02 / 3600.0) as sim:
        assert main(["capture", "readout", sim.port, "--readings", "1", "--stable", "0.5",
                     "--dwell", "0.3", "--timeout", "5", "--out", str(steady), *FAST]) == 0
    (row,) = rows_of(steady)[1:]
    assert row[2] == "deg" and float(row[1]) == pytest.approx(15.0, abs=0.5 / 3600.0)


@pytest.mark.slow
def test_stable_window_is_the_readouts_own_unit_when_it_sends_no_angle(tmp_path):
    """A readout in mm drifting 0.01 mm a second settles within ``--stable 0.5`` (mm)."""
    out = tmp_path / "mm.csv"
    with ReadoutSimulator("tcp", positions=[(15.0,)], drift_per_s=0.01, unit="mm") as sim:
        assert main(["capture", "readout", sim.port, "--readings", "1", "--stable", "0.5",
                     "--dwell", "0.3", "--timeout", "5", "--out", str(out), *FAST]) == 0
    (row,) = rows_of(out)[1:]
    assert row[2] == "mm"


def test_a_timeout_while_no_target_is_in_view_says_so(tmp_path, capsys):
    """bench76: frames beyond the range (a mirror out of view) are no fault of the link, so the
    command line neither reconnects nor gives up for them: a --timeout that ends the capture
    then says the frames carried no measurement, and why."""
    out = tmp_path / "ac.csv"
    with AutocollimatorSimulator("pty", positions=[(9999.0, 2.0)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "5", "--out",
                     str(out), "--timeout", "1", *FAST]) == 2
    err = capsys.readouterr().err
    assert "0 of 5 readings in 1 s; its frames carry no measurement since" in err, err
    assert "no target in view?" in err and "reconnecting" not in err
