"""Hostile readings files for the command line, and the judge of what it answers.

Shared by the property test (tests/app/test_cli_fuzz.py: hypothesis draws the choices) and the
full fuzz round (``python tests/hostile_records.py --cases 10000``: a seeded numpy
generator draws them, every case is run and counted, nothing stops at the first finding).

Each case starts from a plausible record of a workbench, made from first principles (a
mirror normal rotated about a tilted axis, a polygon's faces, quadrature signals with a
true phase), and is damaged the way files are in the field: hostile cells, lost or
repeated rows, odd line endings and delimiters, full-width or European spellings, an
XLSX, a header of binary bytes, off-centre signals, elevations of no set-up.

What the command line answers is judged: exit 0 with finite figures no instrument
contradicts, or exit 2 with exactly one clean line (nothing a terminal would not print as
itself) that names the file — never a traceback.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import math
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import numpy as np

HOSTILE = [
    "", " ", "nan", "inf", "-inf", "1e308", "-1e308", "1e300", "1e-320", "0", "-0", "1_0",
    "١٢", "１２", "12°61'", "12°34'56.7\"", "-0°00'12.5\"", "abc", "=cmd|' /C calc'!A0", "+",
    "\"", "\"unterminated", "a\rb", "1,5", "1.5.5", "0x10", "9" * 400, "x" * 2000, "−3", "+-1",
    "1e5", "360", "720", "-720", "90", "91", "-91", "114", "-297", "\t", "NaN", "None",
    "６°１２′３０″", "138°24'05,15\"", "12,5°", "\x00", "a\x0bb", "\u2028", "\x1c", "\u202e12",
]

#: Corrected axis errors of a theodolite run beyond this are refused (models.theodolite.model
#: MAX_AXIS_ERROR_ARCSEC); polygon errors beyond this must be said first.
THEODOLITE_AXIS_LIMIT = 3600.0
POLYGON_IMPLAUSIBLE = 600.0


# -- the records, from first principles -------------------------------------------------------

def polygon(rng: np.random.Generator, n: int) -> list[list[str]]:
    faces = max(3, n)
    nominal = np.arange(faces) * 360.0 / faces
    rows = [[str(i + 1), f"{(10 + nominal[i] + rng.normal(0, 0.0005)) % 360:.6f}",
             f"{rng.normal(0, 0.2):.2f}", f"{rng.normal(0, 2):.2f}", f"{rng.normal(0, 50):.2f}",
             "1", "+"] for i in range(faces)]
    return [["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec", "ac_y_arcsec", "set",
             "direction"]] + rows + [rows[0][:]]


def _mirror(theta_deg: np.ndarray, psi: float, alpha: float, beta: float):
    """Azimuth and elevation (deg) of a mirror normal rotated about a tilted axis (Rodrigues)."""
    psi, alpha, beta = np.radians([psi, alpha, beta])
    p = np.array([-np.sin(psi) * np.cos(alpha), -np.sin(psi) * np.sin(alpha), np.cos(psi)])
    n0 = np.array([np.cos(beta), 0.0, -np.sin(beta)])
    t = np.radians(theta_deg)[:, None]
    n = n0 * np.cos(t) + np.cross(p, n0) * np.sin(t) + p * (p @ n0) * (1 - np.cos(t))
    return np.degrees(np.arctan2(n[:, 1], n[:, 0])), np.degrees(np.arcsin(n[:, 2]))


def theodolite(rng: np.random.Generator, n: int, random_elevations: bool = False
               ) -> list[list[str]]:
    theta = np.linspace(-20, 20, max(n, 4))
    az, el = _mirror(theta, rng.uniform(0.01, 5), rng.uniform(0, 360), rng.uniform(-2, 2))
    az = az + rng.normal(0, 0.5, theta.size) / 3600
    el = el + rng.normal(0, 0.5, theta.size) / 3600
    if random_elevations:
        el = rng.uniform(-5, 5, theta.size)
    return [["theta_deg", "azimuth_deg", "elevation_deg"]] + [
        [f"{t:g}", f"{a:.6f}", f"{e:.6f}"] for t, a, e in zip(theta, az, el, strict=True)]


def fringe(rng: np.random.Generator, n: int, offset: float = 0.0) -> list[list[str]]:
    theta = np.cumsum(rng.uniform(0.05, 0.4, 8 * max(n, 4)))
    amplitude = rng.uniform(0.5, 3.5)
    off_sin = offset * amplitude * rng.choice([-1, 1])
    off_cos = offset * amplitude * rng.uniform(-1, 1)
    return [["u_sin", "u_cos"]] + [[f"{off_sin + amplitude * math.sin(t):.5f}",
                                    f"{off_cos + amplitude * math.cos(t):.5f}"] for t in theta]


def positioning(rng: np.random.Generator, n: int) -> list[list[str]]:
    targets = np.arange(0, 30 * max(2, n // 8), 30.0)
    rows = []
    for run in (1, 2, 3):
        for sign, order in (("+", targets), ("-", targets[::-1])):
            rows += [[f"{t:g}", str(run), sign, f"{rng.normal(0, 3):.2f}"] for t in order]
    return [["target", "run", "direction", "deviation"]] + rows


KINDS = ("polygon", "theodolite", "fringe", "positioning")
ANGLE_COLUMNS = {"polygon": (1,), "theodolite": (0, 1, 2), "fringe": (), "positioning": ()}


# -- the damage --------------------------------------------------------------------------------

class Picks:
    """The choices of a case, from a numpy generator (the round) or hypothesis (the test)."""

    def __init__(self, rng: np.random.Generator | None = None, draw=None) -> None:
        self.rng, self.draw = rng, draw

    def integer(self, low: int, high: int) -> int:
        if self.draw is not None:
            from hypothesis import strategies as st

            return self.draw(st.integers(low, high))
        return int(self.rng.integers(low, high + 1))

    def choice(self, options):
        options = list(options)
        return options[self.integer(0, len(options) - 1)]


def _dms(value: float, comma: bool) -> str:
    sign = "-" if value < 0 else ""
    total = round(abs(value) * 360000)  # hundredths of an arcsecond
    d, rest = divmod(total, 360000)
    m, s = divmod(rest, 6000)
    text = f"{sign}{d}°{m:02d}'{s // 100:02d}.{s % 100:02d}\""
    return text.replace(".", ",") if comma else text


def _full_width(text: str) -> str:
    return "".join(chr(ord(c) + 0xFEE0) if c.isdigit() or c in ".,-" else
                   {"'": "′", '"': "″"}.get(c, c) for c in text)


def twins(picks: Picks, kind: str) -> tuple[bytes, bytes]:
    """The same D°M'S" record (full-width, primes, Chinese or European spellings, a hostile
    cell or two) as a CSV and as an XLSX: both paths must read it alike."""
    seed = picks.integer(0, 2**31 - 1)
    rng = np.random.default_rng(seed)
    rows = {"polygon": polygon, "theodolite": theodolite}[kind](rng, picks.integer(4, 30))
    wide, comma = picks.integer(0, 1) == 1, picks.integer(0, 1) == 1
    chinese = picks.integer(0, 3) == 0
    for r in rows[1:]:
        for c in ANGLE_COLUMNS[kind]:
            text = _dms(float(r[c]), comma)
            text = text.replace("°", "度").replace("'", "分").replace('"', "秒") if chinese else text
            r[c] = _full_width(text) if wide else text
    from openpyxl.cell.cell import ILLEGAL_CHARACTERS_RE

    for _ in range(picks.integer(0, 2)):
        r = picks.integer(1, len(rows) - 1)
        # the same cell in both: a worksheet cannot hold a control character such as NUL, so
        # the XLSX twin's cell lost it and the two were no longer one record (a NUL in the
        # encoder of the closure row: the CSV refused it, the XLSX read a closure not measured)
        rows[r][picks.choice(ANGLE_COLUMNS[kind])] = ILLEGAL_CHARACTERS_RE.sub(
            "", picks.choice(HOSTILE[:50]))
    text = "\n".join(";".join(_quoted(c, ";") for c in cells) for cells in rows) + "\n"
    return text.encode("utf-8"), _xlsx(rows)


def judge_twins(kind: str, csv_path: str, xlsx_path: str) -> list[str]:
    """What differs between the two paths' answers to the same record."""
    from app.main import main

    answers = []
    for path in (csv_path, xlsx_path):
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(["analyze", kind, path, "--json"])
        answers.append((code, json.loads(out.getvalue()) if code == 0 else
                        err.getvalue().replace(path, "FILE").strip()))
    (code_csv, csv_answer), (code_xlsx, xlsx_answer) = answers
    if code_csv != code_xlsx:
        return [f"CSV exit {code_csv}, XLSX exit {code_xlsx}: {str(csv_answer)[:150]} | "
                f"{str(xlsx_answer)[:150]}"]
    if code_csv == 0:
        key = "corrected_error_arcsec"
        a, b = np.array(csv_answer[key]), np.array(xlsx_answer[key])
        if a.shape != b.shape or not np.allclose(a, b, atol=1e-6):
            return [f"CSV and XLSX differ: {a[:4]} | {b[:4]}"]
    return []


def case(picks: Picks, kind: str, family: str = "") -> tuple[str, bytes, list[str]]:
    """(file suffix, content, extra command-line arguments) of one hostile case."""
    seed = picks.integer(0, 2**31 - 1)
    n = picks.integer(3, 40)
    rng = np.random.default_rng(seed)
    family = family or picks.choice(["damaged"] * 6 + ["spelling", "xlsx", "binary header"]
                                    + (["off-centre"] * 2 if kind == "fringe" else [])
                                    + (["no set-up"] * 2 if kind == "theodolite" else []))
    if family == "off-centre":
        rows = fringe(rng, n, offset=picks.choice([0.5, 0.9, 1.1, 2.0, 30.0]))
    elif family == "no set-up":
        rows = theodolite(rng, n, random_elevations=True)
    else:
        rows = {"polygon": polygon, "theodolite": theodolite, "fringe": fringe,
                "positioning": positioning}[kind](rng, n)
    extra = []
    if kind == "fringe" and picks.integer(0, 2) == 0:
        extra = ["--samples-per-period", "16"]
    delimiter = picks.choice([",", ",", ";", "\t"])
    if family == "spelling":  # D°M'S" full-width or with decimal commas, as labs write them
        comma, wide = picks.integer(0, 1) == 1, picks.integer(0, 1) == 1
        for r in rows[1:]:
            for c in ANGLE_COLUMNS[kind]:
                with contextlib.suppress(ValueError):
                    r[c] = _dms(float(r[c]), comma and delimiter != ",")
                    r[c] = _full_width(r[c]) if wide else r[c]
    for _ in range(picks.integer(0, 4) if family in ("damaged", "xlsx") else 0):
        action = picks.choice(["cell", "cell", "cell", "drop", "repeat", "blank", "swap"])
        r = picks.integer(0, len(rows) - 1)
        if action == "cell":
            rows[r][picks.integer(0, len(rows[r]) - 1)] = picks.choice(HOSTILE)
        elif action == "drop" and len(rows) > 2:
            rows.pop(r)
        elif action == "repeat":
            rows.insert(r, list(rows[r]))
        elif action == "blank":
            rows.insert(r, [""] * len(rows[0]))
        else:
            r2 = picks.integer(0, len(rows) - 1)
            rows[r], rows[r2] = rows[r2], rows[r]
    if family == "xlsx":
        return ".xlsx", _xlsx(rows), extra
    newline = picks.choice(["\n", "\r\n", "\r"])
    text = newline.join(delimiter.join(_quoted(c, delimiter) for c in cells) for cells in rows)
    data = (text + newline).encode("utf-8")
    if family == "binary header":
        head = bytes(rng.integers(0, 256, picks.integer(1, 80), dtype=np.uint8))
        pool = [chr(c) for c in [*range(0, 32), 0x7F, 0x85, 0x2028, 0x2029, 0x202E, 0xFEFF]]
        head = head if picks.integer(0, 1) else "".join(rng.choice(pool + list("ab中"), 30)).encode()
        data = head + data[data.find(newline.encode()):]
    return ".csv", data, extra


def _quoted(cell: str, delimiter: str) -> str:
    if any(ch in cell for ch in (delimiter, '"', "\n", "\r")) and picks_quote(cell):
        return '"' + cell.replace('"', '""') + '"'
    return cell


def picks_quote(cell: str) -> bool:
    return not cell.startswith('"')  # a cell that starts a quote is left to damage the file


def _xlsx(rows: list[list[str]]) -> bytes:
    import openpyxl
    from openpyxl.cell.cell import ILLEGAL_CHARACTERS_RE

    book = openpyxl.Workbook()
    sheet = book.active
    for cells in rows:
        values = []
        for cell in cells:
            cell = ILLEGAL_CHARACTERS_RE.sub("", cell)  # a worksheet cannot hold them
            try:
                number = float(cell)
                values.append(number if math.isfinite(number) and cell.strip() == cell
                              and "_" not in cell and cell.isascii() else cell)
            except ValueError:
                values.append(cell)
        sheet.append(values)
    out = io.BytesIO()
    book.save(out)
    return out.getvalue()


# -- the judge ---------------------------------------------------------------------------------

def _beyond(value: float, key: str) -> bool:
    """Beyond any figure; or an error beyond half a turn (in arcsec)."""
    return not math.isfinite(value) or abs(value) >= 1e9 or ("error" in key
                                                             and abs(value) > 648_000.0)


def _figures(value, key: str = "", found: list[str] | None = None) -> list[str]:
    found = [] if found is None else found
    if isinstance(value, dict):
        for k, v in value.items():
            _figures(v, k, found)
    elif isinstance(value, list):
        for v in value:
            _figures(v, key, found)
    elif isinstance(value, float) and _beyond(value, key):
        found.append(f"{key} = {value}")
    return found


def absurd(kind: str, data: dict) -> list[str]:
    """What no instrument of the kind shows in a result given at exit 0."""
    found = _figures(data)
    if kind == "theodolite":
        worst = max(map(abs, data["corrected_error_arcsec"]))
        if worst > THEODOLITE_AXIS_LIMIT:
            found.append(f"corrected error {worst:.0f}\"")
    elif kind == "polygon":
        worst = max(max(map(abs, data["error_arcsec"])), max(map(abs,
                                                                data["corrected_error_arcsec"])))
        if worst > POLYGON_IMPLAUSIBLE and not (data["warnings"] and
                                                data["warnings"][0].startswith("***")):
            found.append(f"polygon error {worst:.0f}\" not said first")
    elif kind == "fringe":
        unit = data["error_unit"]
        period, raw = data[f"period_{unit}"], data[f"raw_peak_to_peak_{unit}"]
        after = data[f"compensated_peak_to_peak_{unit}"]
        if after > 0.5 * raw and after > 0.05 * period:
            found.append(f"compensation {100 * after / period:.1f} % of a period after "
                         f"{100 * raw / period:.1f} %: it did nothing")
    for key, values in data.items():
        if isinstance(values, list) and key.endswith(("error_arcsec", "error_nm")) and not all(
                isinstance(v, float | int) for v in values):
            found.append(f"{key} holds a non-number")
    return found


def unclean(err: str, path: str) -> list[str]:
    """What is wrong with a refusal: more than one line, a character a terminal would not
    print as itself, no file named."""
    found = []
    line = err[:-1] if err.endswith("\n") else err
    if "Traceback" in err:
        found.append("traceback")
    if len(err.strip().splitlines()) != 1 or "\n" in line:
        found.append("not one line")
    bad = sorted({ch for ch in line if not ch.isprintable() and not ch.isspace()} |
                 {ch for ch in line if ch.isspace() and ch not in " \u3000\u00a0"})
    if bad:
        found.append("unprintable " + ", ".join(repr(ch) for ch in bad[:5]))
    if path not in line and "anglebench analyze" not in line:
        found.append("file not named")
    return found


def judge(kind: str, path: str, extra: list[str]) -> tuple[str, list[str], str]:
    """Run ``anglebench analyze KIND PATH --json``: (outcome, problems, message)."""
    from app.main import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(["analyze", kind, path, "--json", *extra])
        except SystemExit as exc:
            code = exc.code
        except Exception as exc:  # noqa: BLE001 - the round counts what escapes
            return "traceback", [f"{type(exc).__name__}: {exc}"], ""
    if code == 0:
        return "result", absurd(kind, json.loads(out.getvalue())), ""
    problems = unclean(err.getvalue(), path)
    if code != 2:
        problems.append(f"exit {code}")
    return "refused", problems, err.getvalue().strip()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="A full fuzz round over the command line.")
    parser.add_argument("--cases", type=int, default=2000, help="cases per workbench")
    parser.add_argument("--seed", type=int, default=30)
    parser.add_argument("--show", type=int, default=3, help="examples shown per finding")
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    counts: Counter = Counter()
    examples: dict[str, list[str]] = {}
    unnamed_rows: Counter = Counter()
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        for kind in KINDS:
            for i in range(args.cases):
                suffix, data, extra = case(Picks(rng), kind)
                path = Path(folder) / f"{kind}-{i}{suffix}"
                path.write_bytes(data)
                outcome, problems, text = judge(kind, str(path), extra)
                counts[(kind, outcome)] += 1
                if outcome == "refused" and " row " not in text and "row" not in text:
                    unnamed_rows[kind] += 1
                for problem in problems:
                    key = f"{kind}: {outcome}: {problem.split(' = ')[0][:60]}"
                    counts[("finding", key)] += 1
                    examples.setdefault(key, [])
                    if len(examples[key]) < args.show:
                        examples[key].append(f"{path.name}: {problem} | {text[:300]}")
                path.unlink()
            if kind in ("polygon", "theodolite"):  # the same record through CSV and XLSX
                for i in range(args.cases // 5):
                    paths = [Path(folder) / f"{kind}-twin-{i}{s}" for s in (".csv", ".xlsx")]
                    for path, data in zip(paths, twins(Picks(rng), kind), strict=True):
                        path.write_bytes(data)
                    counts[(kind, "twins")] += 1
                    for problem in judge_twins(kind, *map(str, paths)):
                        key = f"{kind}: CSV vs XLSX: {problem[:40]}"
                        counts[("finding", key)] += 1
                        examples.setdefault(key, [])
                        if len(examples[key]) < args.show:
                            examples[key].append(f"{paths[0].name}: {problem}")
                    for path in paths:
                        path.unlink()
    seconds = time.perf_counter() - start
    say = sys.stdout.write
    total = sum(v for (k, o), v in counts.items() if k != "finding" and o != "twins")
    say(f"{total} cases in {seconds:.0f} s (seed {args.seed})\n")
    for kind in KINDS:
        say(f"  {kind}: {counts[(kind, 'result')]} results, {counts[(kind, 'refused')]} "
            f"refused ({unnamed_rows[kind]} naming no row), {counts[(kind, 'traceback')]} "
            f"tracebacks; {counts[(kind, 'twins')]} records read as CSV and as XLSX\n")
    findings = {k: v for (c, k), v in counts.items() if c == "finding"}
    say(f"findings: {sum(findings.values())}\n")
    for key, count in sorted(findings.items()):
        say(f"  {count:5d}  {key}\n")
        for example in examples[key]:
            say(f"         {example}\n")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    raise SystemExit(main())
