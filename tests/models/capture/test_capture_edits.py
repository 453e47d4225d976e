"""A captured reading edited in the sheet afterwards is found, with what the instrument's
frames gave and what the cell holds now (issue 40 item 11)."""

from __future__ import annotations

import dataclasses

import pytest

from app.capture.instruments import frame_values, reading_columns
from app.certificate_issue import readings_edited_after_capture
from models.capture.edits import EditedReading, captured_values, edited_after_capture
from models.capture.raw_record import session_json
from models.registry import KINDS


def _autocollimator_line(x: float, y: float, axes: str = "3") -> bytes:
    """A streamed measurement as the ELCOMAT-kind protocol writes it (code 3, status 00a)."""
    return f"3 00{axes} {x:.3f} {y:.3f}".encode()


def _session(readings, takes, instrument="autocollimator"):
    frames = []
    for i, (x, y) in enumerate(readings):
        frames.append((0.01 * i, _autocollimator_line(x, y), True))
        frames.append((0.01 * i + 0.005, b"garbage \xff", False))  # a refused line between
    return session_json(instrument, "/dev/ttyUSB0", 9600, "2026-12-02T01:02:03+00:00", frames,
                        takes)


POLYGON = [c.key for c in KINDS["polygon"].columns]


def _columns(instrument):
    return reading_columns(instrument, POLYGON)


def test_an_edited_reading_is_found_with_its_captured_and_its_present_value():
    # row 0: one frame; row 2: the mean of three frames (an auto-take's dwell)
    session = _session([(12.5, -3.25), (21.5, 1.0), (21.6, 1.1), (21.58, 0.9)],
                       [[0, 0, 0], [2, 2, 6]])
    rows = [["1", "0", "0", "12.5", "-3.25"], ["2", "30", "0", "", ""],
            ["3", "60", "0", "21.56", "1"]]
    assert edited_after_capture([session], rows, _columns, frame_values) == []
    rows[2][3] = "26.56"
    (edit,) = edited_after_capture([session], rows, _columns, frame_values)
    assert edit == EditedReading(2, "ac_x_arcsec", "21.56", "26.56")
    assert edit.text() == "reading of row 3 edited after capture: 21.56 → 26.56"
    rows[0][4] = ""  # emptied: said cleared (review 62 F1: it was "-3.25 → —")
    edits = edited_after_capture([session], rows, _columns, frame_values)
    assert [e.text() for e in edits] == [
        "reading of row 1 cleared after capture: -3.25",
        "reading of row 3 edited after capture: 21.56 → 26.56"]
    assert [(e.row, e.column, e.what, e.in_sheet) for e in edits][0] == (
        0, "ac_y_arcsec", "cleared", True)  # marked in the window too


AGAIN = ("reading of row 1 captured again, superseding an earlier take (both kept in the "
         "instrument output)")


def test_a_reading_taken_again_is_as_captured_and_the_cache_keeps_the_frames_reading():
    """Two takes of the autocollimator claiming row 1 (a file written before takes were
    marked superseded): the later one is the row's; said once as captured again."""
    session = _session([(5.0, 1.0), (7.0, 2.0)], [[0, 0, 0], [0, 2, 2]])  # row 0 retaken
    rows = [["1", "0", "0", "7", "2"]]
    cache: dict = {}
    assert [e.text() for e in edited_after_capture([session], rows, _columns, frame_values,
                                                   cache)] == [AGAIN]
    assert len(cache) == 2
    calls = []
    assert [e.text() for e in edited_after_capture([session], rows, _columns,
                                                   lambda *a: calls.append(a), cache)] == [AGAIN]
    assert calls == []
    rows[0][3] = "7.5"  # the newer take edited: said as its edit
    assert [e.text() for e in edited_after_capture([session], rows, _columns, frame_values)] \
        == [AGAIN, "reading of row 1 edited after capture: 7 → 7.5"]


def test_a_take_superseded_is_never_an_edit_and_the_row_is_said_captured_again_once():
    """Review 62 F1, row 17: the wrong face taken (300.00002° and 1.509″), its cells cleared
    and taken again. The older take is marked superseded by the newer (take_rows.py): the row
    is checked against the newer alone and said once, for both instruments' takes."""
    ac = _session([(1.509, 0.25), (1.9, 0.5)], [[-1, 0, 0], [16, 2, 2]])
    ac["takes"][0].append(["autocollimator", ac["port"], ac["started_utc"], 2, 2])
    readout = session_json("readout", "tcp://127.0.0.1:47002", 9600, "2026-12-02T01:02:04+00:00",
                           [(0.0, b"300.00002", True), (0.1, b"270.00001", True)],
                           [[-1, 0, 0], [16, 1, 1]])
    readout["takes"][0].append(["readout", readout["port"], readout["started_utc"], 1, 1])
    keys = POLYGON
    rows = [[""] * len(keys) for _ in range(17)]
    rows[16][keys.index("ac_x_arcsec")], rows[16][keys.index("ac_y_arcsec")] = "1.90", "0.50"
    rows[16][keys.index("encoder_deg")] = "270.00001"

    def values(instrument, line):
        return (float(line),) if instrument == "readout" else frame_values(instrument, line)

    said = edited_after_capture([ac, readout], rows, _columns, values)
    # was: "reading of row 17 edited after capture: 300.00002 → —" (and 1.509 → 1.90)
    assert [e.text() for e in said] == [AGAIN.replace("row 1 ", "row 17 ")]
    assert not said[0].in_sheet  # no cell marked in the window
    rows[16][keys.index("encoder_deg")] = ""  # the newer reading cleared: said so
    assert [e.text() for e in edited_after_capture([ac, readout], rows, _columns, values)] == [
        AGAIN.replace("row 1 ", "row 17 "),
        "reading of row 17 edited or cleared after capture: no cell of the row holds "
        "270.00001 now"]


def test_two_readout_takes_in_two_columns_of_a_row_are_each_checked():
    """A readout into "the current cell" taken into two columns of one row: two
    readings, neither supersedes the other; an edit of the first is said."""
    readout = session_json("readout", "tcp://127.0.0.1:47002", 9600, "t",
                           [(0.0, b"100.0", True), (0.1, b"100.5", True)],
                           [[0, 0, 0], [0, 1, 1]])
    keys = POLYGON
    row = [""] * len(keys)
    row[keys.index("encoder_deg")], row[keys.index("polygon_dev_arcsec")] = "100.0", "100.5"

    def values(_instrument, line):
        return (float(line),)

    assert edited_after_capture([readout], [row], _columns, values) == []
    row[keys.index("encoder_deg")] = "100.2"
    assert [e.text() for e in edited_after_capture([readout], [row], _columns, values)] == [
        "reading of row 1 edited or cleared after capture: no cell of the row holds 100 now"]


def test_angles_are_compared_as_angles():
    """A theodolite's Hz settled at 0°: frames at 359.99999° and 0.00001° average to 0°
    (not 180°); a cell typed in D°M'S" with the same angle is not an edit."""
    def values_of(_instrument, line):
        return tuple(float(v) for v in line.split())

    frames = [(0.0, b"359.99999 90", True), (0.1, b"0.00001 90", True),
              (0.2, b"12.5 90", True)]
    session = session_json("theodolite", "tcp://x:1", 9600, "t", frames, [[0, 0, 1], [1, 2, 2]])
    assert captured_values(session, 0, 1, values_of, angles=True)[0] == pytest.approx(0.0,
                                                                                      abs=1e-9)
    keys = [c.key for c in KINDS["theodolite"].columns]
    rows = [["-20", "0", "90"], ["-19", "12°30'00\"", "90"]]
    columns = lambda instrument: reading_columns(instrument, keys, vertical_zenith=True)  # noqa: E731
    assert edited_after_capture([session], rows, columns, values_of) == []
    rows[1][1] = "12°30'01\""
    (edit,) = edited_after_capture([session], rows, columns, values_of)
    assert (edit.row, edit.column, edit.captured) == (1, "azimuth_deg", "12.5")


def test_the_certificate_says_which_rows_were_edited(samples_dir):
    import io

    from pypdf import PdfReader

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table

    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    x = float(rows[2][3])
    session = _session([(x, float(rows[2][4]))], [[2, 0, 0]])
    settings = kind.settings_with_defaults(None)
    assert readings_edited_after_capture(kind, settings, rows, [session]) == []
    edited = [list(r) for r in rows]
    edited[2][3] = f"{x + 5:g}"
    edits = readings_edited_after_capture(kind, settings, edited, [session])
    assert [e.text() for e in edits] == [
        f"reading of row 3 edited after capture: {x:.12g} → {x + 5:g}"]
    result = kind.analyze(ReadingsSheet(kind.columns, edited).parse(), settings)
    document = dataclasses.replace(
        kind.certificate_document(result, CertificateMetadata(), "run.csv", settings),
        raw_data_sha256="ab" * 32, edited_readings=tuple(e.text() for e in edits))
    text = "".join(p.extract_text() for p in PdfReader(io.BytesIO(
        certificate_pdf_bytes(document))).pages)
    flat = " ".join(text.split())
    assert "SHA-256 " + "ab" * 32 in flat.replace("\n", "")
    assert "Changes after capture" in flat  # the heading: edits, retakes, deletions
    assert f"reading of row 3 edited after capture: {x:.12g} → {x + 5:g}" in flat


def test_a_bilingual_certificate_says_the_changes_after_capture_in_both_languages(samples_dir):
    """rev62day F14: on the zh+en certificate the lines under 采集后变动 / Changes after capture
    were English only; each is given in Chinese, then in English, with the same figures."""
    import io

    from pypdf import PdfReader

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table

    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    x = float(rows[2][3])
    session = _session([(x, float(rows[2][4]))], [[2, 0, 0]])
    settings = kind.settings_with_defaults(None)
    edited = [list(r) for r in rows]
    edited[2][3] = f"{x + 5:g}"
    edits = readings_edited_after_capture(kind, settings, edited, [session])
    result = kind.analyze(ReadingsSheet(kind.columns, edited).parse(), settings)
    texts = {}
    for language in ("zh+en", "en"):
        document = dataclasses.replace(
            kind.certificate_document(result, CertificateMetadata(language=language), "run.csv",
                                      settings),
            raw_data_sha256="ab" * 32, edited_readings=tuple(e.text() for e in edits))
        texts[language] = "".join(" ".join(p.extract_text().split()) for p in PdfReader(
            io.BytesIO(certificate_pdf_bytes(document))).pages)
    chinese = f"第 3 行的读数在采集后被修改：{x:.12g} → {x + 5:g}"
    english = f"reading of row 3 edited after capture: {x:.12g} → {x + 5:g}"
    flat = texts["zh+en"]
    assert "采集后变动" in flat and chinese in flat and english in flat
    assert flat.index(chinese) < flat.index(english)
    assert chinese not in texts["en"] and english in texts["en"]


def test_a_reading_rounded_to_the_instruments_resolution_is_as_captured():
    """#41 live day: a take writes its reading rounded to the instrument's resolution (0.01"
    for an autocollimator); the mark then said every auto-take was "edited after capture:
    0.384254901961 → 0.38". Each take keeps the step it was written with (``steps``)."""
    session = _session([(0.381, -3.2), (0.387, -3.21), (0.3848, -3.205)], [[0, 0, 4]])
    session["steps"] = [0.01]
    rows = [["1", "0", "0", "0.38", "-3.21"]]
    assert edited_after_capture([session], rows, _columns, frame_values) == []
    rows[0][3] = "0.39"  # more than half a step from the reading: an edit
    (edit,) = edited_after_capture([session], rows, _columns, frame_values)
    assert (edit.row, edit.column, edit.now) == (0, "ac_x_arcsec", "0.39")
    del session["steps"]  # a session stored before #41: every digit was written
    rows[0][3] = "0.38"
    assert {e.column for e in edited_after_capture([session], rows, _columns, frame_values)} \
        == {"ac_x_arcsec", "ac_y_arcsec"}


def test_a_theodolite_reading_written_as_dms_to_its_resolution_is_as_captured():
    hz = 10.0000123  # 0.0443" off a whole 0.1"
    line = f"%R1P,0,1:0,{hz * 3.141592653589793 / 180:.12f},1.535889741755".encode()
    session = session_json("theodolite", "tcp://x:1", 9600, "2026-12-02T01:02:03+00:00",
                           [(0.0, line, True)], [[0, 0, 0]])
    session["steps"] = [0.1 / 3600]
    keys = [c.key for c in KINDS["theodolite"].columns]
    rows = [["10", "10°00'00.0\"", "2°00'00.0\"", "", ""]]
    columns = lambda instrument: reading_columns(instrument, keys)  # noqa: E731
    assert edited_after_capture([session], rows, columns, frame_values) == []
    rows[0][1] = "10°00'00.2\""
    assert [e.column for e in edited_after_capture([session], rows, columns, frame_values)] \
        == ["azimuth_deg"]


def test_an_edited_elevation_is_found_where_the_column_reads_elevation():
    """A take writes 90° − V into the theodolite's elevation column (its default, "vertical
    reading: elevation E"); the check compared nothing there, so an elevation edited after
    capture went unmarked and uncertified (#41 live day)."""
    v = 88.0000123  # elevation 1.9999877° = 1°59'59.956"
    line = f"%R1P,0,1:0,{10.0 * 3.141592653589793 / 180:.12f}," \
           f"{v * 3.141592653589793 / 180:.12f}".encode()
    session = session_json("theodolite", "tcp://x:1", 9600, "2026-12-02T01:02:03+00:00",
                           [(0.0, line, True)], [[0, 0, 0]], steps=[0.1 / 3600])
    kind = KINDS["theodolite"]
    settings = {"vertical_reading": "elevation"}
    rows = [["10", "10°00'00.0\"", "2°00'00.0\"", "", ""]]
    cache: dict = {}
    assert readings_edited_after_capture(kind, settings, rows, [session], cache) == []
    rows[0][2] = "2°00'10.0\""
    (edit,) = readings_edited_after_capture(kind, settings, rows, [session], cache)
    assert (edit.column, edit.now) == ("elevation_deg", "2°00'10.0\"")
    # read as zenith angles the same cell is compared with V itself
    assert [e.column for e in readings_edited_after_capture(
        kind, {"vertical_reading": "zenith"}, [["10", "10°00'00.0\"", "88°00'00.0\"", "", ""]],
        [session], cache)] == []


def _theodolite(*readings_deg, takes=None):
    """A GeoCOM session of (Hz, V) readings, one frame each; one take per frame unless
    ``takes``."""
    rad = 3.141592653589793 / 180
    frames = [(0.1 * i, f"%R1P,0,1:0,{hz * rad:.15f},{v * rad:.15f}".encode(), True)
              for i, (hz, v) in enumerate(readings_deg)]
    return session_json("theodolite", "tcp://x:1", 9600, "2026-12-02T01:02:03+00:00", frames,
                        takes or [[i, i, i] for i in range(len(readings_deg))])


def test_a_captured_angle_typed_a_whole_turn_away_is_an_edit():
    """Review 62 M3: the cells were compared with the capture on the circle, so a captured
    azimuth of 12.5° typed as 372.5° (or −347.5°, or 732.5°) passed as "as captured". The
    certificate prints the number: another number is an edit, whatever angle it stands
    for."""
    session = _theodolite((12.5, 88.0))
    kind = KINDS["theodolite"]
    settings = {"vertical_reading": "elevation"}

    def said(azimuth, elevation="2"):
        return [str(e.text()) for e in readings_edited_after_capture(
            kind, settings, [["10", azimuth, elevation, "", ""]], [session])]

    assert said("12.5") == said("12°30'00\"") == []
    assert said("372.5") == ["reading of row 1 edited after capture: 12.5 → 372.5"]
    assert said("-347.5") == ["reading of row 1 edited after capture: 12.5 → -347.5"]
    assert said("732°30'00\"") == ["reading of row 1 edited after capture: 12.5 → 732°30'00\""]
    # an elevation (90° − V, within ±90°) is written as it is: −5° typed as 355° is an edit
    below = _theodolite((12.5, 95.0))
    assert readings_edited_after_capture(kind, settings, [["10", "12.5", "-5", "", ""]],
                                         [below]) == []
    assert [str(e.text()) for e in readings_edited_after_capture(
        kind, settings, [["10", "12.5", "355", "", ""]], [below])] == [
        "reading of row 1 edited after capture: -5 → 355"]


def test_a_mean_across_zero_is_as_captured_in_the_turn_a_take_writes_and_no_other():
    """An auto-take's mean of frames at 359.99999° and 0.00001° is written 0° (brought into
    [0°, 360°)); read in the first frame's turn it is 360°: both are the captured number,
    720° and −360° are not."""
    session = _theodolite((359.99999, 88.0), (0.00001, 88.0), takes=[[0, 0, 1]])
    kind = KINDS["theodolite"]
    settings = {"vertical_reading": "elevation"}

    def said(azimuth):
        return [(e.now, e.captured) for e in readings_edited_after_capture(
            kind, settings, [["10", azimuth, "2", "", ""]], [session])]

    assert said("0") == said("0°00'00.0\"") == said("360") == []
    assert said("720") == [("720", "360")]
    assert said("-360") == [("-360", "0")]
    assert said("0.01") == [("0.01", "0")]
    # a mean a hair off 0° (the window's arithmetic and the check's apart) is 0° and 360°
    keys = [c.key for c in kind.columns]
    columns = lambda instrument: reading_columns(instrument, keys, vertical_zenith=True)  # noqa: E731
    for hair in (1e-13, -1e-13):
        session = session_json("theodolite", "tcp://x:1", 9600, "t",
                               [(0.0, f"{hair} 90".encode(), True)], [[0, 0, 0]])
        for azimuth in ("0", "360", "0°00'00.0\"", "360°00'00.0\""):
            assert edited_after_capture([session], [["10", azimuth, "90"]], columns,
                                        lambda _i, line: tuple(map(float, line.split()))) \
                == [], (hair, azimuth)


def test_a_readouts_reading_in_a_dms_cell_is_read_as_the_analysis_reads_the_column():
    """A readout's reading (its key "value", not an angle's) taken into the polygon's encoder
    column kept in D°M′S″: the cell was read with float(), which reads no D°M′S″, and the
    certificate said "edited or cleared after capture" of a cell nobody touched. Each cell
    is read now as the analysis reads its column: an angle column by the angle parser, a
    number column with its decimal comma."""
    kind = KINDS["polygon"]
    keys = [c.key for c in kind.columns]
    readout = session_json("readout", "tcp://127.0.0.1:47002", 9600, "t",
                           [(0.0, b"+90.00012 deg", True)], [[0, 0, 0]])
    readout["steps"] = [0.001 / 3600]  # as sent, written as D°M′S″ to 0.001″
    ac = _session([(0.381, -3.2)], [[0, 0, 0]])
    ac["steps"] = [0.01]
    row = ["4", "90°00'00.432\"", "0", "0.38", "-3.20", "1", "+"]
    assert len(row) == len(keys)

    def said(rows):
        return [e.text() for e in readings_edited_after_capture(kind, {}, rows, [readout, ac])]

    assert said([row]) == []
    for spelled in ("90 00 00.432", "90:00:00,432", "90°00′00.432″"):
        assert said([[*row[:1], spelled, *row[2:]]]) == [], spelled
    assert said([[*row[:3], "0,38", *row[4:]]]) == []  # the analysis reads 0.38
    missing = ("reading of row 1 edited or cleared after capture: no cell of the row holds "
               "90.00012 now")
    assert said([[*row[:1], "90°00'01.432\"", *row[2:]]]) == [missing]  # 1″ more
    assert said([[*row[:1], "90°00'00.434\"", *row[2:]]]) == [missing]  # 2 of its 0.001″
    assert said([[*row[:1], "", *row[2:]]]) == [missing]  # cleared


def test_an_edit_of_a_dms_cell_says_the_captured_reading_as_the_take_wrote_it():
    """Beside a cell typed in D°M′S″ the captured reading is said in D°M′S″ to the step the
    take wrote it to (it was "30.000123398 → 30°00'01.4\"", the customer left to convert);
    beside a decimal cell, or one cleared, as before."""
    hz = 30.0001234  # 30°00'00.444"
    line = f"%R1P,0,1:0,{hz * 3.141592653589793 / 180:.12f},1.535889741755".encode()
    session = session_json("theodolite", "tcp://x:1", 9600, "2026-12-02T01:02:03+00:00",
                           [(0.0, line, True)], [[0, 0, 0]])
    session["steps"] = [0.1 / 3600]
    kind = KINDS["theodolite"]

    def said(azimuth):
        rows = [["30", azimuth, "2°00'00.0\"", "", ""]]
        return [(e.captured, e.now, e.what)
                for e in readings_edited_after_capture(kind, {}, rows, [session])
                if e.column == "azimuth_deg"]

    assert said("30°00'00.4\"") == said("30 00 00.44") == []
    assert said("30°00'01.4\"") == [("30°00'00.4\"", "30°00'01.4\"", "edited")]
    assert said("-30°00'00.4\"") == [("30°00'00.4\"", "-30°00'00.4\"", "edited")]
    ((captured, now, what),) = said("30.0004")
    assert (float(captured), now, what) == (pytest.approx(hz, abs=1e-8), "30.0004", "edited")
    ((captured, now, what),) = said("")
    assert (float(captured), now, what) == (pytest.approx(hz, abs=1e-8), "", "cleared")


def test_a_readouts_cell_recorded_with_its_take_is_checked_as_any_captured_cell():
    """A session that records the column each readout take wrote (``columns``): that cell
    is checked, an edit said beside a D°M′S″ cell in D°M′S″ ("→", as the other columns,
    day review 64 P3: "no cell of the row holds 90.00012 now"), a cleared cell "cleared",
    with the column's key (the window marks it); another cell of the row holding the number
    does not make it as captured."""
    from models.capture.raw_record import raw_sessions_from_json

    kind = KINDS["polygon"]
    keys = [c.key for c in kind.columns]
    readout = session_json("readout", "tcp://127.0.0.1:47002", 9600, "t",
                           [(0.0, b"+90.00012 deg", True)], [[0, 0, 0]])
    readout["steps"] = [0.001 / 3600]
    readout["columns"] = ["encoder_deg"]
    (readout,) = raw_sessions_from_json([readout], "test")  # the key is kept as stored
    assert readout["columns"] == ["encoder_deg"]
    row = ["4", "90°00'00.432\"", "0", "0", "0", "1", "+"]
    assert len(row) == len(keys)

    def said(rows):
        return [(e.column, e.what, str(e.text())) for e in readings_edited_after_capture(
            kind, {}, rows, [readout])]

    assert said([row]) == []
    assert said([[*row[:1], "90°00'01.432\"", *row[2:]]]) == [(
        "encoder_deg", "edited",
        "reading of row 1 edited after capture: 90°00'00.432\" → 90°00'01.432\"")]
    assert said([[*row[:1], "", *row[2:]]]) == [(
        "encoder_deg", "cleared", "reading of row 1 cleared after capture: 90.00012")]
    # the number moved to another cell of the row: not the cell the take wrote
    assert said([[*row[:1], "", "90.00012", *row[3:]]])[0][:2] == ("encoder_deg", "cleared")


def test_a_cleared_dms_cell_is_said_as_its_column_writes_it():
    """A readout's cell in a column kept in D°M′S″, cleared: the captured reading is said in
    D°M′S″ to the step the take wrote it to, as the cell was — it was said in decimal degrees
    ("cleared after capture: 90.00012" beside a column of 30°00'00.036\" cells, in the
    table's tooltip and on the certificate). A take that recorded no step (a file from
    before #41) is said to the decimals of the column's seconds; in a decimal column, or a
    column with no other cell to say how it is written, in decimal degrees as before."""
    kind = KINDS["polygon"]
    keys = [c.key for c in kind.columns]
    readout = session_json("readout", "tcp://127.0.0.1:47002", 9600, "t",
                           [(0.0, b"+90.00012 deg", True)], [[1, 0, 0]])
    readout["steps"] = [0.001 / 3600]
    readout["columns"] = ["encoder_deg"]

    def said(encoder: list[str], session=readout):
        rows = [[str(i + 1), text, "0", "0", "0", "1", "+"] for i, text in enumerate(encoder)]
        assert len(rows[0]) == len(keys)
        return [str(e.text()) for e in readings_edited_after_capture(kind, {}, rows, [session])]

    assert said(["0°00'00.000\"", "90°00'00.432\""]) == []
    assert said(["0°00'00.000\"", ""]) == [
        "reading of row 2 cleared after capture: 90°00'00.432\""]
    # no step recorded: to the column's decimals of seconds
    before = {k: v for k, v in readout.items() if k != "steps"}
    assert said(["0°00'00.00\"", ""], before) == [
        "reading of row 2 cleared after capture: 90°00'00.43\""]
    assert said(["0 00 00.0", ""], before) == [
        "reading of row 2 cleared after capture: 90°00'00.4\""]
    # a decimal column: in decimal degrees
    assert said(["0.00000", ""]) == ["reading of row 2 cleared after capture: 90.00012"]


def test_a_sessions_columns_must_be_one_key_a_take():
    from models.capture.raw_record import raw_sessions_from_json

    readout = session_json("readout", "p", 9600, "t", [(0.0, b"+1 deg", True)], [[0, 0, 0]])
    for bad in (["a", "b"], [1], "encoder_deg"):
        with pytest.raises(ValueError, match="not as stored"):
            raw_sessions_from_json([{**readout, "columns": bad}], "test")
