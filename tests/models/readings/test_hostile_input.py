"""The inputs a fuzzing round and a day of hostile files found: each is refused with
one line naming the file and what is wrong, or read as it should be — never a
traceback, a hang, an absurd figure at exit 0, or an input overwritten."""

from __future__ import annotations

import json
import time

import numpy as np
import pytest

from app.main import main
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import TableImportError, read_table
from models.theodolite.analysis import THEODOLITE

THEODOLITE_ROWS = "\n".join(f"{t},{t + 0.001 * t},{0.1 + 0.001 * t}" for t in range(-20, 21, 2))


def run(capsys, *args) -> tuple[int, str, str]:
    code = main(["analyze", *args])
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, *args) -> str:
    code, _, err = run(capsys, *args)
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1, err
    assert "Traceback" not in err
    return err


def test_cr_only_line_endings_read_like_any_file(tmp_path, capsys):
    path = tmp_path / "mac.csv"
    path.write_bytes(("theta_deg,azimuth_deg,elevation_deg\r" + THEODOLITE_ROWS.replace("\n", "\r")
                      + "\r").encode())
    code, out, err = run(capsys, "theodolite", str(path), "--json")
    assert code == 0, err and len(json.loads(out)["theta_deg"]) == 21


@pytest.mark.parametrize("content, message", [
    ("theta_deg,azimuth_deg,elevation_deg\n1,\"2\n", "a quote is not closed"),
    ("theta_deg,azimuth_deg,elevation_deg\n1," + "9" * 5000 + ",3\n", "a cell of 5000 characters"),
    ("theta_deg,azimuth_deg,elevation_deg\n1,2,\"a\rb\"\n", "row 2, column 'elevation_deg'"),
    ("theta_deg,azimuth_deg,elevation_deg\n1_0,2,3\n2,3,4\n3,4,5\n4,5,6\n", "'1_0' is not"),
])
def test_damaged_csv_is_one_line(tmp_path, capsys, content, message):
    path = tmp_path / "bad.csv"
    path.write_bytes(content.encode())
    assert message in refused(capsys, "theodolite", str(path))


def test_underscore_number_is_refused_on_both_paths():
    rows = [["1_0", "2", "3"]] + [[str(i), str(i), "0.1"] for i in range(1, 6)]
    parsed = ReadingsSheet(THEODOLITE.columns, rows).parse()
    assert parsed.errors and "'1_0' is not" in parsed.errors[0].reason
    fast = ReadingsSheet(THEODOLITE.columns, [["1_0", "2", "3"]] * 5000).parse()
    assert fast.n == 0 and len(fast.errors) == 5000


def test_xlsx_declaring_a_million_rows_is_read_in_moments(tmp_path):
    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["theta_deg", "azimuth_deg", "elevation_deg"])
    for i in range(5):
        sheet.append([i, i, 0.1])
    sheet["XFD1048576"] = "x"  # one far cell: the sheet claims A1:XFD1048576
    path = tmp_path / "bomb.xlsx"
    book.save(path)
    start = time.perf_counter()
    with pytest.raises(TableImportError, match="more than 10000 empty rows after row 6"):
        read_table(path)
    assert time.perf_counter() - start < 5.0


def test_xlsx_that_expands_beyond_any_readings_file_is_refused_unread(tmp_path, monkeypatch):
    import openpyxl

    from models.readings import tabular_import

    book = openpyxl.Workbook()
    for i in range(200):
        book.active.append([i, i, 0.1])
    path = tmp_path / "big.xlsx"
    book.save(path)
    monkeypatch.setattr(tabular_import, "MAX_XLSX_EXPANDED_BYTES", 1000)
    with pytest.raises(TableImportError, match="expands to"):
        read_table(path)


@pytest.mark.parametrize("metadata, message", [
    ('{"temperature_c": ' + "9" * 401 + "}", "'temperature_c'"),
    ("[" * 100_000 + "]" * 100_000, "nested too deep"),
    ('["a list"]', "must be a JSON object"),
    ('{"standards": [{"uncertainty": 1e300}]}', "at most 3600"),
    ('{"standards": [{"uncertainty": 0}]}', "must be more than 0"),
    ('{"item_resolution_arcsec": -5}', "must be 0 to 3600"),
    ('{"customer_name": {"a": 1}}', "must be text"),
])
def test_hostile_metadata_is_one_line(tmp_path, capsys, samples_dir, metadata, message):
    meta = tmp_path / "meta.json"
    meta.write_text(metadata)
    err = refused(capsys, "theodolite", str(samples_dir / "theodolite_sample.csv"),
                  "--certificate", str(tmp_path / "c.pdf"), "--metadata", str(meta))
    assert message in err


@pytest.mark.parametrize("flag", ["--results", "--certificate"])
def test_an_output_never_overwrites_the_input(tmp_path, capsys, samples_dir, flag):
    path = tmp_path / "in.csv"
    path.write_bytes((samples_dir / "theodolite_sample.csv").read_bytes())
    before = path.read_bytes()
    err = refused(capsys, "theodolite", str(path), flag, str(tmp_path / "." / "in.csv"))
    assert "is an input" in err and path.read_bytes() == before


def test_control_character_in_the_file_name_still_exports_xlsx(tmp_path, capsys, samples_dir):
    path = tmp_path / "run\x07one.csv"
    path.write_bytes((samples_dir / "theodolite_sample.csv").read_bytes())
    code, _, err = run(capsys, "theodolite", str(path), "--results", str(tmp_path / "r.xlsx"))
    assert code == 0, err


@pytest.mark.parametrize("rows, message", [
    ("\n".join(["5,5,0.1"] * 10), "all θ are equal"),
    ("1e308,1,0.1\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'theta_deg': 1e+308°"),
    ("1,1,114\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'elevation_deg': 114°"),
    ("1,1,-297\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'elevation_deg': -297°"),
    ("1,1,0.1\n1.00001,1,0.1\n1.00002,1,0.1\n1.00003,1,0.1", "too little rotation"),
])
def test_theodolite_readings_that_identify_nothing_are_refused(tmp_path, capsys, rows, message):
    path = tmp_path / "run.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n" + rows + "\n")
    assert message in refused(capsys, "theodolite", str(path))


@pytest.mark.parametrize("kind, args, message", [
    ("theodolite", ["--grade", "3"], "--grade applies to polygon, not theodolite"),
    ("theodolite", ["--reference-row", "-5"], "reference_row must be 0 or 1 to 1e+07, not -5"),
    ("polygon", ["--samples-per-period", "64"], "--samples-per-period applies to fringe"),
    ("fringe", ["--lines-per-rev", "0"], "lines_per_rev must be"),
])
def test_inapplicable_or_out_of_range_options_are_refused(capsys, samples_dir, kind, args, message):
    from models.registry import KINDS

    err = refused(capsys, kind, str(samples_dir / KINDS[kind].sample_file), *args)
    assert message in err


@pytest.mark.parametrize("settings, message", [
    ({"lut_size": 100_000_000}, "lut_size must be 8 to 65536"),
    ({"samples_per_period": "64"}, "samples_per_period must be a number"),
])
def test_fringe_settings_from_a_project_file_are_checked(settings, message):
    from models.fringe.analysis import FRINGE
    from models.parameters import SettingsError

    with pytest.raises(SettingsError, match=message):
        FRINGE.analyze(ReadingsSheet(FRINGE.columns, [["0", "1"]] * 40).parse(), settings)


@pytest.mark.parametrize("settings, message", [
    ({"faces": 1_000_000_000}, r"faces must be 0 or 3 to 360, not 1e\+09"),
    ({"closure_limits_arcsec": [0.1, 0.2]}, "must be text"),
    ({"grade": "3"}, "grade must be one of 1, 2, 3"),
])
def test_polygon_settings_from_a_project_file_are_checked(samples_dir, settings, message):
    from models.parameters import SettingsError
    from models.polygon.analysis import POLYGON
    from models.readings.tabular_import import map_columns

    rows = map_columns(read_table(samples_dir / POLYGON.sample_file), POLYGON.columns)
    with pytest.raises(SettingsError, match=message):
        POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)


# -- the last residue of the fuzz round (issue 30) ---------------------------------------

def _fringe_file(tmp_path, offset_sin: float, offset_cos: float = 0.0, amplitude: float = 3.1,
                 samples: int = 512) -> str:
    """Signals of an encoder turned at N = 64 samples a period: a true phase, offsets."""
    rng = np.random.default_rng(7)
    theta = np.arange(samples) * 2 * np.pi / 64
    u_sin = offset_sin + amplitude * np.sin(theta) + rng.normal(0, 1e-3, samples)
    u_cos = offset_cos + amplitude * np.cos(theta) + rng.normal(0, 1e-3, samples)
    path = tmp_path / "signals.csv"
    path.write_text("u_sin,u_cos\n" + "\n".join(f"{a:.5f},{b:.5f}" for a, b in zip(u_sin, u_cos,
                                                                                     strict=True)))
    return str(path)


@pytest.mark.parametrize("offsets", [(100.0, 0.0), (2.5, 2.5), (1.2, 0.0)])
@pytest.mark.parametrize("n", [["--samples-per-period", "64"], []])
def test_fringe_offset_beyond_the_amplitude_is_no_compensation(tmp_path, capsys, offsets, n):
    path = _fringe_file(tmp_path, *offsets, amplitude=1.0 if offsets[0] == 1.2 else 3.1 if
                        offsets[0] == 100 else 0.5)
    err = refused(capsys, "fringe", path, *n)
    assert path in err and "no compensation: the Lissajous figure does not circle 0 V" in err
    assert f"A0 = +{offsets[0]:.2f}" in err and "turns 0 times a period" in err


@pytest.mark.parametrize("n", [["--samples-per-period", "64"], []])
def test_fringe_offset_inside_the_figure_is_compensated_and_shown_to_be(tmp_path, capsys, n):
    path = _fringe_file(tmp_path, 0.8, 0.0, amplitude=1.0)
    code, out, err = run(capsys, "fringe", path, "--json", *n)
    assert code == 0, err
    data = json.loads(out)
    period = data["period_arcsec"]
    # the offset at 0.8 of the amplitude swings the read phase by ±asin(0.8) ≈ ±53°
    assert data["raw_peak_to_peak_arcsec"] / period == pytest.approx(0.295, abs=0.01)
    assert data["compensated_peak_to_peak_arcsec"] / period < 0.003  # noise and table steps


def _theodolite_text(elevation=None, theta_cell=None, shift=None) -> str:
    """A run with ψ = 1°, α = 30°, β = 0.5° by 3-D rotation of the mirror normal (Rodrigues)."""
    theta = np.arange(-20.0, 21.0, 2.0)
    psi, alpha, beta = np.radians([1.0, 30.0, 0.5])
    p = np.array([-np.sin(psi) * np.cos(alpha), -np.sin(psi) * np.sin(alpha), np.cos(psi)])
    n0 = np.array([np.cos(beta), 0.0, -np.sin(beta)])
    rows = []
    for k, t in enumerate(np.radians(theta)):
        n = n0 * np.cos(t) + np.cross(p, n0) * np.sin(t) + p * (p @ n0) * (1 - np.cos(t))
        az, el = np.degrees(np.arctan2(n[1], n[0])), np.degrees(np.arcsin(n[2]))
        if elevation is not None and k in elevation:
            el = elevation[k]
        el += (shift or {}).get(k, 0.0)
        t_text = theta_cell[1] if theta_cell and k == theta_cell[0] else f"{np.degrees(t):g}"
        rows.append(f"{t_text},{az:.7f},{el:.7f}")
    return "theta_deg,azimuth_deg,elevation_deg\n" + "\n".join(rows) + "\n"


def test_theodolite_clean_run_passes_the_fit_gate(tmp_path, capsys):
    path = tmp_path / "run.csv"
    path.write_text(_theodolite_text())
    code, out, err = run(capsys, "theodolite", str(path), "--json")
    assert code == 0, err
    assert max(abs(e) for e in json.loads(out)["corrected_error_arcsec"]) < 0.01


@pytest.mark.parametrize("elevation, row, words", [  # row: the file's line (header 1)
    ({7: 0.0}, 9, "residual RMS 4"),
    ({7: 12.5}, 9, "R² = 0.0"),
    ({k: v for k, v in enumerate(np.random.default_rng(3).uniform(-0.5, 0.5, 21))}, None, ""),
])
def test_theodolite_elevations_no_setup_explains_are_refused_with_figures(tmp_path, capsys,
                                                                          elevation, row, words):
    path = tmp_path / "run.csv"
    path.write_text(_theodolite_text(elevation))
    err = refused(capsys, "theodolite", str(path))
    assert str(path) in err
    if row is not None:
        assert "no set-up explains the E / V [°] readings" in err and words in err
        assert f"is at row {row}:" in err and "theodolite accuracy 0.5\"" in err


def test_theodolite_fit_gate_follows_the_accuracy_setting(tmp_path, capsys):
    path = tmp_path / "run.csv"
    path.write_text(_theodolite_text(shift={7: 0.002}))  # one elevation 7" off
    assert "no set-up explains" not in run(capsys, "theodolite", str(path))[2]
    # with a stated accuracy of 0.01" the same residual is far beyond it
    assert "is at row 9:" in refused(capsys, "theodolite", str(path), "--accuracy", "0.01")


@pytest.mark.parametrize("cell", ["90", "114", "-297", "12.5"])
def test_theodolite_one_bad_theta_is_refused_naming_its_row(tmp_path, capsys, cell):
    path = tmp_path / "run.csv"
    path.write_text(_theodolite_text(theta_cell=(3, cell)))
    err = refused(capsys, "theodolite", str(path))
    # the file's line (the header line 1), as a cell that does not parse is named
    assert err.startswith(f"{path}: row 5: θ = {cell}°") and "'theta_deg'" in err


def test_theodolite_a_bad_zero_row_is_named(tmp_path, capsys):
    path = tmp_path / "run.csv"
    path.write_text(_theodolite_text(theta_cell=(10, "30")))  # θ = 0 typed as 30 at the zero
    # --reference-row takes the file's line, as the messages name it (contract review 75 F7)
    err = refused(capsys, "theodolite", str(path), "--reference-row", "12")
    assert "row 12, where the theodolite was zeroed (θ = 30°" in err


def _full_width(text: str) -> str:
    return "".join(chr(ord(c) + 0xFEE0) if c.isdigit() or c in ".-," else
                   {"'": "′", '"': "″"}.get(c, c) for c in text)


def test_theodolite_xlsx_with_full_width_dms_reads_as_the_csv(tmp_path, capsys):
    import openpyxl

    from models.readings.angles import format_dms

    lines = [ln.split(",") for ln in _theodolite_text().splitlines()]
    cells = [lines[0]] + [[_full_width(format_dms(float(c), 3)) for c in r] for r in lines[1:]]
    csv_path, xlsx_path = tmp_path / "fw.csv", tmp_path / "fw.xlsx"
    csv_path.write_text("\n".join(",".join(r) for r in cells))
    book = openpyxl.Workbook()
    for r in cells:
        book.active.append(r)
    book.save(xlsx_path)
    results = []
    for path in (csv_path, xlsx_path):
        code, out, err = run(capsys, "theodolite", str(path), "--json")
        assert code == 0, err
        results.append(json.loads(out)["corrected_error_arcsec"])
    assert results[0] == results[1] and max(map(abs, results[0])) < 0.01


def _polygon_text(samples_dir, off_deg: float) -> str:
    from models.readings.angles import format_dms, parse_angle_deg

    lines = (samples_dir / "polygon_sample.csv").read_text().splitlines()
    import csv
    rows = list(csv.reader(lines))
    rows[3][1] = format_dms(parse_angle_deg(rows[3][1]) + off_deg, 2)
    return "\n".join(",".join(f'"{c}"' if '"' in c else c for c in
                              [c.replace('"', '""') if '"' in c else c for c in r])
                     for r in rows) + "\n"


@pytest.mark.slow
@pytest.mark.parametrize("off_deg", [1.0, 2.9, -2.0])
def test_polygon_errors_of_degrees_are_said_first_and_need_confirmation(tmp_path, capsys,
                                                                       samples_dir, off_deg):
    path = tmp_path / "poly.csv"
    path.write_text(_polygon_text(samples_dir, off_deg))
    code, out, err = run(capsys, "polygon", str(path))
    assert code == 0, err
    assert out.splitlines()[1].startswith(f"*** ERRORS OF {abs(off_deg):.2f}°")
    code, out, err = run(capsys, "polygon", str(path), "--json")
    assert json.loads(out)["warnings"][0].startswith("*** ERRORS OF")
    pdf = tmp_path / "c.pdf"
    err = refused(capsys, "polygon", str(path), "--certificate", str(pdf))
    assert "no certificate was written" in err and "--confirm-implausible" in err
    assert not pdf.exists()
    code, _, err = run(capsys, "polygon", str(path), "--certificate", str(pdf),
                       "--confirm-implausible")
    assert code == 0, err and pdf.exists()


def test_polygon_sample_needs_no_confirmation(capsys, samples_dir):
    code, out, err = run(capsys, "polygon", str(samples_dir / "polygon_sample.csv"), "--json")
    assert code == 0 and not any("ERRORS OF" in w for w in json.loads(out)["warnings"])


@pytest.mark.parametrize("seed", range(6))
def test_a_header_of_random_bytes_is_one_clean_line(tmp_path, capsys, seed):
    # bytes that decode (as UTF-8 or GB18030) into control characters, the line breaks
    # str.splitlines knows besides \n and \r, bidi overrides and letters
    rng = np.random.default_rng(seed)
    pool = [chr(c) for c in [*range(0, 9), 11, 12, *range(14, 32), 0x7F, 0x85, 0x2028, 0x2029,
                             0x202E, 0x200B, 0xFEFF]] + list("abcxyz中文")
    raw = "".join(rng.choice(pool, 40)).encode("utf-8")
    if seed % 2:
        raw = bytes(rng.integers(0x81, 0xFF, 20, dtype=np.uint8)) + raw  # + GB18030 pairs
    path = tmp_path / "binary.csv"
    path.write_bytes(raw + b"\n1,2,3\n4,5,6\n7,8,9\n10,11,12\n")
    err = refused(capsys, "theodolite", str(path))
    line = err.rstrip("\n")
    assert line.isprintable() or all(ch.isprintable() or ch == "\u3000" for ch in line), line
    assert str(path) in line


def test_one_line_escapes_what_a_terminal_would_not_print():
    from models.readings.sheet import one_line

    text = one_line("a\x0bb\x1cc\u2028d\x85e\u202ef\x00g\th\n中文\u3000i")
    assert text == "a\\x0bb\\x1cc\\u2028d\\x85e\\u202ef\\x00g\\th⏎中文\u3000i"
    assert len(text.splitlines()) == 1
