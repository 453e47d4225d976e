"""A long stream in the instrument panel: its raw lines are converted to their stored form a
block at a time and stored as those blocks' text, so a save or a take does not encode hours
of frames again (8 h at 100 Hz: an autosave held the window 5 s, 0.14 s now; measured in
the stop note), and what is stored is the same text, digest and frames as before."""

from __future__ import annotations

import json

from app.capture.instruments import Autocollimator
from app.capture.panel import _Session
from app.capture.worker import CaptureWorker
from models.capture.raw_record import FRAMES_PER_BLOCK, raw_digest, session_json


def _worker(lines: int):
    """A worker (not started) holding ``lines`` lines, kept as its thread keeps them."""
    worker = CaptureWorker("/dev/ttyUSB0", Autocollimator(), 9600)
    worker.started_utc = "2026-12-05T07:00:00+00:00"
    for i in range(lines):
        worker._keep(0.01 * i + 0.0004, f"3 003 {i % 997 * 0.001:.3f} -1.250".encode(),
                     i % 3 != 0)
    return worker


def test_a_sessions_frames_are_stored_as_the_plain_conversion_would_store_them():
    worker = _worker(2 * FRAMES_PER_BLOCK + 123)
    session = _Session("polygon", "autocollimator", worker)
    session.takes = [[0, 5, 9], [1, 2 * FRAMES_PER_BLOCK, 2 * FRAMES_PER_BLOCK + 122]]
    session.steps = [0.01, 0.01]
    assert session.behind() == len(worker.raw)
    session.catch_up()  # as the drain does, a block's worth at a time
    assert session.behind() == 0
    worker._keep(999.0, b"3 003 1.000 2.000", True)
    assert session.behind() == 1
    stored = session.stored()
    plain = session_json("autocollimator", worker.port, worker.baud, worker.started_utc,
                         worker.raw, session.takes, session.steps, "polygon")
    assert stored["frames"] == plain["frames"] and len(stored["frames"]) == len(worker.raw)
    text = json.dumps([plain], ensure_ascii=False, separators=(",", ":"))
    assert raw_digest([stored]) == raw_digest([plain])
    assert json.loads(text)[0]["frames"][-1] == [999.0, "3 003 1.000 2.000", 1]
    # what was stored stays as it was while the stream goes on
    worker._keep(1000.0, b"3 003 1.001 2.000", True)
    assert len(stored["frames"]) == len(worker.raw) - 1
    assert len(session.stored()["frames"]) == len(worker.raw)


def test_the_sessions_handed_out_do_not_change_when_the_panels_do(window):
    """An autosave thread writes the sessions raw_sessions gave it while the fringe's live
    take rewrites an earlier session's takes in place (rows to -1) in the window's thread:
    the file's digest then did not match the text written after it (recovery refused)."""
    panel = window.capture_panel
    session = {"instrument": "signals", "port": "tcp://127.0.0.1:1", "baud": 0,
               "started_utc": "2026-12-05T07:00:00+00:00",
               "frames": [[0.0, "0.1 0.2", 1], [0.001, "0.2 0.1", 1]],
               "takes": [[0, 0, 0], [1, 1, 1]], "steps": [0.0, 0.0]}
    panel.sessions["fringe"] = [session]
    handed = panel.raw_sessions("fringe")
    digest = raw_digest(handed)
    session["takes"] = [[-1, a, b] for _, a, b in session["takes"]]  # as LiveSignals.take does
    session["steps"].append(1.0)
    assert raw_digest(handed) == digest and handed[0]["takes"] == [[0, 0, 0], [1, 1, 1]]
    assert list(handed[0]) == list(session)  # the keys in their stored order
