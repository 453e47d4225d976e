"""The instrument's raw frames kept with the project (an optional key: older files open,
the schema version stays) and their SHA-256 in the register's chained record and on the
certificate, so a certificate's readings trace to what the instrument sent."""

from __future__ import annotations

import hashlib
import json
import subprocess

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.certificate_issue import issue_certificate
from models.capture.raw_record import (
    FrameBlocks,
    raw_digest,
    raw_sessions_from_json,
    session_json,
    sessions_json_pieces,
)
from models.certificate.metadata import CertificateMetadata
from models.project.file import (
    SCHEMA_VERSION,
    Project,
    ProjectFileError,
    WorkbenchState,
    load_project,
    project_to_json,
    save_project,
)
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.store import Register
from tests.instrument_simulators import AutocollimatorSimulator
from tests.own_readings import own_readings


def _session(lines=(b"3 003 1.250 -0.500", b"\xff\x00garbage\r", b"3 003 1.260 -0.490")):
    frames = [(0.004 * i, line, not line.startswith(b"\xff")) for i, line in enumerate(lines)]
    return session_json("autocollimator", "/dev/ttyUSB0", 9600,
                        "2026-12-02T01:02:03.000000+00:00", frames, [(0, 0, 2)])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.binary(min_size=1, max_size=60), min_size=1, max_size=20))
def test_any_bytes_survive_the_file_exactly(lines):
    sessions = [_session(tuple(lines))]
    sessions[0]["takes"] = [[0, 0, len(lines) - 1]]
    text = project_to_json(Project({}, {}, {"polygon": sessions}))
    again = json.loads(text)["raw_capture"]["polygon"]
    assert [f[1].encode("latin-1") for f in again["sessions"][0]["frames"]] == list(lines)
    assert raw_sessions_from_json(again["sessions"], "x") == sessions


def test_the_project_file_keeps_the_frames_and_their_digest_as_stored(tmp_path):
    sessions = [_session()]
    path = tmp_path / "p.anglebench.json"
    save_project(path, Project({"polygon": WorkbenchState([["1", "0"]], {})}, {},
                               {"polygon": sessions}))
    text = path.read_text(encoding="utf-8")
    stored = json.loads(text)
    assert stored["schema_version"] == SCHEMA_VERSION  # raw_capture needs no new version
    entry = stored["raw_capture"]["polygon"]
    as_stored = json.dumps(entry["sessions"], ensure_ascii=False, separators=(",", ":"))
    assert as_stored in text  # the digest is of this very text
    assert entry["sha256"] == hashlib.sha256(as_stored.encode()).hexdigest() == raw_digest(sessions)
    assert load_project(path).raw_capture == {"polygon": sessions}
    # a file written before raw frames existed (or without any) opens, and has no key
    bare = project_to_json(Project({"polygon": WorkbenchState([["1", "0"]], {})}))
    assert "raw_capture" not in bare
    old = tmp_path / "old.anglebench.json"
    old.write_text(bare, encoding="utf-8")
    assert load_project(old).raw_capture == {}


@pytest.mark.parametrize("change, words", [
    (lambda d: d["raw_capture"]["polygon"]["sessions"][0]["frames"][0].__setitem__(
        1, "3 003 9.250 -0.500"), "do not give their SHA-256"),
    (lambda d: d["raw_capture"]["polygon"]["sessions"][0]["takes"].append([1, 2, 9]),
     "a frame or a take"),
    # a superseded take names the newer take's key (review 62 F1): only so, and only at -1
    (lambda d: d["raw_capture"]["polygon"]["sessions"][0]["takes"].append(
        [-1, 0, 0, ["autocollimator", "p", "t", 1]]), "a frame or a take"),
    (lambda d: d["raw_capture"]["polygon"]["sessions"][0]["takes"].append(
        [0, 0, 0, ["autocollimator", "p", "t", 1, 1]]), "a frame or a take"),
    (lambda d: d["raw_capture"].__setitem__("polygon", []), "'sha256' and 'sessions'"),
    (lambda d: d.__setitem__("raw_capture", []), "'raw_capture' must be an object"),
])
def test_changed_or_damaged_raw_frames_are_refused_naming_the_file(tmp_path, change, words):
    path = tmp_path / "p.anglebench.json"
    save_project(path, Project({}, {}, {"polygon": [_session()]}))
    document = json.loads(path.read_text(encoding="utf-8"))
    change(document)
    path.write_text(json.dumps(document, ensure_ascii=False), encoding="utf-8")
    with pytest.raises(ProjectFileError, match=words) as caught:
        load_project(path)
    assert str(path) in str(caught.value) and "nothing was changed" in str(caught.value)


@pytest.mark.slow
def test_the_register_chains_the_digest_and_the_certificate_prints_it(register_url, tmp_path,
                                                                     samples_dir):
    from models.registry import KINDS

    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    sessions = [_session()]
    with Register(register_url) as register:
        typed = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                  kind.checked_settings({}), rows, "typed.csv",
                                  str(tmp_path / "typed.pdf"))
        data["item_serial"] += "-2"  # another item: one issued again is refused (#61)
        # with readings of its own (one item's are refused as another's: hostile78 F7)
        rows = map_columns(read_table(own_readings(samples_dir / kind.sample_file,
                                                   data["item_serial"], tmp_path / "own")),
                           kind.columns)
        result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                              kind.checked_settings({}))
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), rows, "captured.anglebench.json",
                                   str(tmp_path / "captured.pdf"), raw_capture=sessions)
        assert typed.raw_sha256 == "" and record.raw_sha256 == raw_digest(sessions)
        assert register.get(record.number).raw_sha256 == raw_digest(sessions)
        assert register.audit(pdfs=True) == []
        kept = json.loads(record.project_json)["raw_capture"]["polygon"]["sessions"]
        assert kept == sessions  # the frames themselves are in the record
    text = subprocess.run(["pdftotext", "-layout", str(tmp_path / "captured.pdf"), "-"],
                          capture_output=True, text=True, check=True).stdout
    # "SHA-256 <digest>": the 64 digits go to a line of their own
    assert "Instrument output" in text and "SHA-256" in text and raw_digest(sessions) in text
    plain = subprocess.run(["pdftotext", str(tmp_path / "typed.pdf"), "-"], capture_output=True,
                           text=True, check=True).stdout
    assert "Instrument output" not in plain


@pytest.mark.slow
def test_a_session_with_no_take_is_not_named_as_the_readings_origin(register_url, tmp_path,
                                                                    samples_dir):
    """rev62day F15: a raw session recorded only because the tab was in front while the
    instruments were connected (frames, no take) printed "Instrument output: SHA-256 …" on a
    report none of whose readings was captured. Its frames stay in the record."""
    from models.registry import KINDS

    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    idle = _session()
    idle["takes"] = []
    with Register(register_url) as register:
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), rows, "typed.anglebench.json",
                                   str(tmp_path / "idle.pdf"), raw_capture=[idle])
        kept = json.loads(record.project_json)["raw_capture"]["polygon"]["sessions"]
        assert kept == [idle]  # the frames are recorded all the same
    text = subprocess.run(["pdftotext", str(tmp_path / "idle.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    assert "Instrument output" not in text and raw_digest([idle]) not in text


def _one_reading_taken_on_the_polygon(window, qtbot):
    """An autocollimator connected, one reading taken into the polygon's first row and the
    instrument disconnected: the capture panel."""
    window.tabs.setCurrentIndex(window.presenters.index(window.presenter("polygon")))
    presenter = window.presenter("polygon")
    presenter.view.table.setCurrentIndex(presenter.table_model.index(0, 3))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(2.5, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=0.2, retries=1)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        panel.take_button.click()
        panel.disconnect_instrument()
    return panel


@pytest.mark.slow
def test_the_window_saves_and_reopens_the_frames_with_the_project(window, qtbot, tmp_path):
    panel = _one_reading_taken_on_the_polygon(window, qtbot)
    saved = panel.raw_capture()
    assert list(saved) == ["polygon"] and saved["polygon"][0]["takes"][0][0] == 0
    assert saved["polygon"][0]["workbench"] == "polygon"  # bound to it (review 61 F7)
    assert saved["polygon"][0]["frames"][saved["polygon"][0]["takes"][0][1]][1] == \
        "3 003 2.500 1.000"
    path = tmp_path / "captured.anglebench.json"
    assert window.projects.save_to(path)
    window.projects.new_project()
    assert panel.raw_capture() == {}
    assert window.projects.open_project(path)
    assert panel.raw_capture() == saved


@pytest.mark.slow
def test_the_autosave_of_a_large_sheet_keeps_the_frames(window, qtbot, monkeypatch):
    """A sheet large enough to be autosaved in a thread of its own: the recovery file holds
    the raw capture too (it was left out: a project recovered from it had its readings and
    no frames, and its certificate no raw digest)."""
    import app.project_presenter as project_presenter

    panel = _one_reading_taken_on_the_polygon(window, qtbot)
    saved = panel.raw_capture()
    monkeypatch.setattr(project_presenter, "AUTOSAVE_THREAD_ROWS", -1)  # every sheet is large
    window.projects.autosave()
    window.projects._autosave_thread.join(timeout=30)
    recovered = window.projects.recovery.load(window.projects.recovery.path)
    assert recovered.raw_capture == saved and saved["polygon"][0]["takes"]


def test_each_takes_step_is_kept_and_checked():
    """#41 live day: ``steps`` (per take, the step its cells were rounded to) is optional,
    kept in order and in the digest; one per take, finite and not negative, else refused."""
    frames = [(0.0, b"3 003 1.000 2.000", True), (0.1, b"3 003 1.004 2.000", True)]
    old = session_json("autocollimator", "/dev/ttyUSB0", 9600, "2026-12-02T01:02:03+00:00",
                       frames, [[0, 0, 1]])
    new = session_json("autocollimator", "/dev/ttyUSB0", 9600, "2026-12-02T01:02:03+00:00",
                       frames, [[0, 0, 1]], steps=[0.01])
    assert raw_sessions_from_json([old], "p") == [old]  # stored before: as it was
    (kept,) = raw_sessions_from_json(json.loads(json.dumps([new])), "p")
    assert list(kept) == ["instrument", "port", "baud", "started_utc", "frames", "takes",
                          "steps"] and kept["steps"] == [0.01]
    assert raw_digest([kept]) == raw_digest([new]) != raw_digest([old])
    for bad in ([0.01, 0.01], [-0.01], [float("nan")], ["0.01"], [True], 0.01):
        with pytest.raises(ValueError, match="session 1"):
            raw_sessions_from_json([{**new, "steps": bad}], "p")


_FRAME = st.tuples(st.floats(0, 1e5, allow_nan=False).map(lambda t: round(t, 6)),
                   st.text(st.characters(min_codepoint=0, max_codepoint=255), max_size=12),
                   st.sampled_from([0, 1])).map(list)


@settings(max_examples=120, deadline=None)
@given(frames=st.lists(_FRAME, max_size=60), per_block=st.integers(1, 7),
       cut=st.integers(0, 70), steps=st.booleans())
def test_frames_held_as_blocks_are_stored_as_the_list_would_be(frames, per_block, cut, steps):
    """FrameBlocks (the frames encoded a block at a time) give the same JSON text, digest and
    frames as the plain list: the file, the register's digest and older files agree."""
    blocks = FrameBlocks(frames, per_block=per_block)
    assert len(blocks) == len(frames) and list(blocks) == frames and blocks == frames
    assert [blocks[i] for i in range(-len(frames), len(frames))] == frames + frames
    assert blocks[2:9] == frames[2:9] and blocks[cut:] == frames[cut:]
    session = {"instrument": "autocollimator", "port": "/dev/ttyUSB0", "baud": 9600,
               "started_utc": "2026-12-05T06:00:00+00:00", "frames": blocks,
               "takes": [[0, 0, 0]] if frames else []}
    if steps:
        session["steps"] = [0.01] if frames else []
    plain = {**session, "frames": frames}
    text = json.dumps([plain, plain], ensure_ascii=False, separators=(",", ":"))
    assert "".join(sessions_json_pieces([session, plain])) == text
    assert raw_digest([session, session]) == hashlib.sha256(text.encode("utf-8")).hexdigest()
    snapshot = blocks.snapshot()
    blocks.extend([[1.0, "later", 1]])
    assert snapshot == frames  # a snapshot keeps the frames it was taken with
    del blocks[cut:]
    assert list(blocks) == (frames + [[1.0, "later", 1]])[:cut]


def test_a_day_of_frames_is_saved_from_its_blocks_and_opens_alike(tmp_path):
    """50,000 frames in blocks (three of them full) go to the file and come back as the list
    they were, digest checked on opening."""
    frames = [[round(0.01 * i, 6), f"3 003 {i % 997 * 0.001:.3f} -1.250", i % 2] for i in
              range(50_000)]
    blocks = FrameBlocks(frames)
    session = {"instrument": "autocollimator", "port": "/dev/ttyUSB0", "baud": 9600,
               "started_utc": "2026-12-05T06:00:00+00:00", "frames": blocks,
               "takes": [[0, 100, 149], [1, 49_900, 49_999]]}
    path = tmp_path / "day.anglebench"
    save_project(path, Project({"polygon": WorkbenchState([["1"], ["2"]], {})}, {},
                               {"polygon": [session]}))
    (opened,) = load_project(path).raw_capture["polygon"]
    assert opened["frames"] == frames and opened["takes"] == session["takes"]
