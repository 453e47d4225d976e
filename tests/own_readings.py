"""A bundled sample's readings as another item's own: tests that issue several items' certificates
into one register give each item readings of its own, as real calibrations have (the register
refuses one item's readings issued as another's: hostile78 F7)."""

from __future__ import annotations

import csv
import hashlib
import json
import re
from pathlib import Path

__all__ = ["one_reading_moved", "own_readings", "theodolite_project", "theodolite_sample_rows"]

#: the columns that set a point, not read at it, and a standard's known deviations: kept
_SET = frozenset({"theta_deg", "position", "set", "direction", "run", "target", "mounting",
                  "polygon_dev_arcsec"})
#: a cell's last number with a decimal part, and what follows it (a unit mark: ", ″)
_LAST = re.compile(r"(\d+)\.(\d+)(\D*)$")


def _moved(cell: str, steps: int) -> str:
    """``cell`` with its last decimal digit moved by ``steps`` (±1 or ±2), the other way where
    that would pass 0 or, for seconds of arc, 60: the reading of another item, one or two of
    its last digits away."""
    found = _LAST.search(cell)
    if found is None:
        return cell
    whole, decimals, tail = found.groups()
    places = len(decimals)
    units = int(whole) * 10 ** places + int(decimals)
    limit = 60 * 10 ** places if tail.strip() in ('"', "″") else None
    moved = units + steps
    if moved < 0 or (limit is not None and moved >= limit):
        moved = units - steps
    text = f"{moved // 10 ** places:0{len(whole)}d}.{moved % 10 ** places:0{places}d}"
    return cell[:found.start()] + text + tail


def own_readings(sample: Path, serial: str, folder: Path) -> Path:
    """``sample`` (a CSV of readings) as the readings of the item ``serial``: every reading
    (each cell with a decimal part, the columns that set a point aside) one or two in its
    last digit away from the sample's, up or down as the serial's SHA-256 says — a
    calibration's scatter, so the results stay the sample's within a few tenths of an
    arcsecond. Written under ``folder``/``serial``/ with the sample's name (the certificate
    names the file it came from as the sample's); its path."""
    seed = hashlib.sha256(serial.encode()).digest()
    with open(sample, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    header, out, n = rows[0], [rows[0]], 0
    for row in rows[1:]:
        cells = []
        for key, cell in zip(header, row, strict=False):
            if key.strip() in _SET:
                cells.append(cell)
                continue
            bits = seed[n % len(seed)] >> (n // len(seed) % 4) * 2
            cells.append(_moved(cell, (1 + (bits & 1)) * (1 if bits & 2 else -1)))
            n += 1
        out.append(cells + row[len(header):])
    target = folder / serial
    target.mkdir(parents=True, exist_ok=True)
    path = target / sample.name
    with open(path, "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows(out)
    return path


def theodolite_sample_rows() -> list[list[str]]:
    """The bundled theodolite sample's rows as the sheet maps them (41 readings)."""
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS["theodolite"]
    samples = Path(__file__).resolve().parents[1] / "resources" / "samples"
    return map_columns(read_table(samples / kind.sample_file), kind.columns)


def one_reading_moved(rows: list[list[str]]) -> list[list[str]]:
    """The theodolite sample's ``rows`` with one reading of 41 a tenth of a second of arc
    away: readings of their own, one digit from the sample's."""
    moved = [list(r) for r in rows]
    assert moved[7][1] == "-12°55'35.8\""
    moved[7][1] = "-12°55'35.9\""
    return moved


def theodolite_project(rows: list[list[str]]) -> str:
    """A project file's text holding ``rows`` on the theodolite workbench, with no settings."""
    return json.dumps({"format": "anglebench-project",
                       "workbenches": {"theodolite": {"rows": rows, "settings": {}}}})
