"""An interpolator look-up table written as a chip's tools take it (#45): CSV, a C header
(``const int16_t name[N] = {…};``) and Intel HEX. Each states the entries, the bits, the LSB,
the lookup and sign, the separate terms, the predicted residual and the record it was made
from (docs/user-guide/fringe.md, "Interpolator look-up tables", documents the formats).

Intel HEX: the codes in entry order, each as a two's-complement integer of ⌈bits/8⌉ bytes,
little-endian, from address 0; data records (type 00) of 16 bytes, an extended linear
address record (type 04) before each 64 KiB, the end-of-file record ``:00000001FF``.
"""

from __future__ import annotations

import io
import re
from pathlib import Path

from models.fringe.interpolator_table import InterpolatorTable
from models.messages import QT_TR_NOOP, message
from models.project.atomic_write import write_text_atomic

__all__ = ["FORMATS", "table_c_header", "table_csv", "table_intel_hex", "write_interpolator_table"]

FORMATS = (".csv", ".h", ".hex")


def _describe(table: InterpolatorTable, source: str, period_length: float,
              unit: str, caveat: str = "") -> list[str]:
    p = table.profile
    lookup = ("linear between the two entries about the measured phase" if
              p.interpolation == "linear" else "the entry below the measured phase (no "
                                                 "interpolation)")
    sign = ("corrected phase = measured phase + code * LSB" if p.sign == "add" else
            "corrected phase = measured phase - code * LSB")
    lsb_how = " (chosen: the smallest power of two holding the table)" if table.lsb_chosen else ""
    out = [
        f"AngleBench interpolator look-up table, profile {p.key}: {p.name}",
        f"source record: {source or '(not named)'}",
        f"entries: {table.entries} (k = {p.entries_log2}) over one period of the measured "
        f"phase atan2(u_sin, u_cos); entry j at {360.0 / table.entries:.6g} deg * j",
        f"codes: {p.bits}-bit signed, -{p.max_code} ... {p.max_code}",
        f"LSB: {table.lsb_period:.9g} of a period = {table.lsb_period * 360.0:.9g} deg of "
        f"phase = {table.lsb_period * period_length:.6g} {unit}{lsb_how}",
        f"lookup: {lookup}; {sign}",
    ]
    t = table.terms
    if t.applied:
        who = ("written here, applied before the table" if p.terms_written else
               "calibrated by the chip itself, not written; the table assumes them corrected")
        out.append(f"separate terms ({', '.join(t.applied)}): {who}:")
        if "offset" in t.applied:
            out.append(f"  offset_a = {t.offset_a:.9g}, offset_b = {t.offset_b:.9g} (record "
                       f"units, subtracted)")
        if "gain" in t.applied:
            out.append(f"  gain_b = {t.gain_b:.9g} (B multiplied by it)")
        if "phase" in t.applied:
            out.append(f"  phase = {t.phase_deg:.9g} deg (B' = (B + A sin q) / cos q)")
    else:
        out.append("separate terms: none (the table corrects offsets, gain and phase too)")
    for name, r in (("predicted residual, this table", table.residual),
                    ("residual unquantised (the entries alone)", table.residual_unquantised),
                    ("error without a table", table.residual_without)):
        out.append(f"{name}: max |e| {r.max_abs * period_length:.6g} {unit}, RMS "
                   f"{r.rms * period_length:.6g} {unit} (of a period: {r.max_abs:.4g}, "
                   f"{r.rms:.4g})")
    out.append("by simulation of the quantised table on the fitted signals (not including the "
               "chip's own angle resolution)")
    if caveat:  # orders fold at the sampled phases: as the certificate says (day review 68 F8)
        out.append(f"this table and its predicted residual hold {caveat}")
    out.append("profile source: " + p.source)
    return out


def table_csv(table: InterpolatorTable, source: str = "", period_length: float = 1.0,
              unit: str = "period", caveat: str = "") -> str:
    """``caveat``: where the table holds, when orders fold at the sampled phases
    (models.fringe.compensation_at_samples.compensation_caveat); "" when none folds."""
    out = io.StringIO()
    for line in _describe(table, source, period_length, unit, caveat):
        out.write(f"# {line}\n")
    out.write("index,measured_phase_deg,code,value_period,ideal_value_period\n")
    for j, (code, ideal) in enumerate(zip(table.codes.tolist(), table.ideal_period.tolist(),
                                          strict=True)):
        out.write(f"{j},{360.0 * j / table.entries:.9g},{code},{code * table.lsb_period:.9g},"
                  f"{ideal:.9g}\n")
    return out.getvalue()


def _identifier(name: str) -> str:
    name = re.sub(r"\W", "_", name, flags=re.ASCII)
    return name if name and not name[0].isdigit() else f"lut_{name}"


def table_c_header(table: InterpolatorTable, source: str = "", period_length: float = 1.0,
                   unit: str = "period", name: str = "anglebench_interpolator_lut",
                   caveat: str = "") -> str:
    name = _identifier(name)
    upper = name.upper()
    comment = [" * " + line.replace("*/", "* /") for line in
               _describe(table, source, period_length, unit, caveat)]
    lines = ["/* (generated)", *comment, " */", f"#ifndef {upper}_H", f"#define {upper}_H",
             "#include <stdint.h>",
             f"#define {upper}_ENTRIES {table.entries}",
             f"#define {upper}_K {table.profile.entries_log2}",
             f"#define {upper}_BITS {table.profile.bits}",
             f"/* one code = {upper}_LSB of a period */",
             f"#define {upper}_LSB {table.lsb_period:.9e}"]
    t = table.terms
    if t.applied and table.profile.terms_written:
        if "offset" in t.applied:
            lines += [f"#define {upper}_OFFSET_A {t.offset_a:.9e}",
                      f"#define {upper}_OFFSET_B {t.offset_b:.9e}"]
        if "gain" in t.applied:
            lines.append(f"#define {upper}_GAIN_B {t.gain_b:.9e}")
        if "phase" in t.applied:
            lines.append(f"#define {upper}_PHASE_DEG {t.phase_deg:.9e}")
    lines.append(f"const int16_t {name}[{table.entries}] = {{")
    codes = [str(c) for c in table.codes.tolist()]
    for i in range(0, len(codes), 16):
        lines.append("    " + ", ".join(codes[i:i + 16]) + ",")
    lines += ["};", f"#endif /* {upper}_H */", ""]
    return "\n".join(lines)


def _record(address: int, kind: int, data: bytes) -> str:
    body = bytes([len(data), (address >> 8) & 0xFF, address & 0xFF, kind]) + data
    checksum = (-sum(body)) & 0xFF
    return ":" + body.hex().upper() + f"{checksum:02X}"


def table_intel_hex(table: InterpolatorTable) -> str:
    width = (table.profile.bits + 7) // 8
    data = b"".join(int(c).to_bytes(width, "little", signed=True)
                    for c in table.codes.tolist())
    lines, upper = [], -1
    for start in range(0, len(data), 16):
        if start >> 16 != upper:
            upper = start >> 16
            lines.append(_record(0, 0x04, upper.to_bytes(2, "big")))
        lines.append(_record(start & 0xFFFF, 0x00, data[start:start + 16]))
    lines.append(":00000001FF")
    return "\n".join(lines) + "\n"


def write_interpolator_table(path: str | Path, table: InterpolatorTable, source: str = "",
                             period_length: float = 1.0, unit: str = "period",
                             caveat: str = "") -> str:
    """Write by the name's ending (.csv, .h, .hex), atomically; the format's name.
    ``caveat`` (where the table holds, when orders fold) goes into the CSV's and the C
    header's comments; Intel HEX has none (the command's line says it)."""
    suffix = Path(path).suffix.lower()
    if suffix == ".h":
        text, what = table_c_header(table, source, period_length, unit,
                                    name=Path(path).stem, caveat=caveat), "C header"
    elif suffix == ".hex":
        text, what = table_intel_hex(table), "Intel HEX"
    elif suffix == ".csv":
        text, what = table_csv(table, source, period_length, unit, caveat), "CSV"
    else:
        raise ValueError(message(QT_TR_NOOP("{path}: an interpolator table is written as .csv, .h "
                                            "or .hex"), path=str(path)))
    write_text_atomic(path, text)
    return what
