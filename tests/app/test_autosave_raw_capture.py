"""#62 review F6: a day's raw capture (every frame of both instruments, 2 M frames, 66 MB)
was autosaved in the window's thread after every edit, holding it 0.5 … 3 s (and links
counted the pause as silence). A raw record beyond ``AUTOSAVE_THREAD_FRAMES`` is written
off the GUI thread, whatever the sheets' size, with every frame in the autosave."""

from __future__ import annotations

import json
import threading

from app import project_presenter
from models.capture.raw_record import FrameBlocks
from tests.app.test_project_presenter import load_sample, make


def _session(frames: int) -> dict:
    return {"instrument": "readout", "port": "tcp://127.0.0.1:47002", "baud": 9600,
            "started_utc": "2026-12-05T09:00:00+00:00",
            "frames": FrameBlocks([[round(k * 0.05, 6), f"+{k % 360:.5f} deg", 1]
                                   for k in range(frames)]),
            "takes": [[0, 5, 5]], "steps": [0.0], "workbench": "theodolite"}


def _written_in(presenter, monkeypatch) -> list[str]:
    threads: list[str] = []
    write = presenter._write_recovery

    def watched(*args, **kwargs):
        threads.append(threading.current_thread().name)
        return write(*args, **kwargs)

    monkeypatch.setattr(presenter, "_write_recovery", watched)
    return threads


def test_a_large_raw_capture_is_autosaved_off_the_window_thread(qtbot, tmp_path, samples_dir,
                                                              monkeypatch):
    presenter, _, (theodolite, _) = make(qtbot, tmp_path)
    frames = 25_000  # a morning's stream at 20 Hz is ~600 000
    session = _session(frames)
    presenter.raw_capture = lambda: {"theodolite": [session]}
    load_sample(theodolite, samples_dir)  # a small sheet: 20 rows
    assert theodolite.sheet.row_count < project_presenter.AUTOSAVE_THREAD_ROWS
    threads = _written_in(presenter, monkeypatch)
    presenter.autosave()
    assert presenter._autosave_thread is not None
    presenter._autosave_thread.join(30)
    assert threads and threads[0] != threading.main_thread().name
    saved = json.loads(presenter.recovery.path.read_text(encoding="utf-8"))
    stored = saved["raw_capture"]["theodolite"]["sessions"][0]
    assert len(stored["frames"]) == frames
    assert stored["frames"][-1] == [round((frames - 1) * 0.05, 6),
                                    f"+{(frames - 1) % 360:.5f} deg", 1]
    assert frames > project_presenter.AUTOSAVE_THREAD_FRAMES
    presenter.close()


def test_a_short_raw_capture_is_still_autosaved_at_once(qtbot, tmp_path, samples_dir,
                                                       monkeypatch):
    presenter, _, (theodolite, _) = make(qtbot, tmp_path)
    presenter.raw_capture = lambda: {"theodolite": [_session(300)]}
    load_sample(theodolite, samples_dir)
    threads = _written_in(presenter, monkeypatch)
    presenter.autosave()
    assert threads == [threading.main_thread().name]
    saved = json.loads(presenter.recovery.path.read_text(encoding="utf-8"))
    assert len(saved["raw_capture"]["theodolite"]["sessions"][0]["frames"]) == 300
    presenter.close()
