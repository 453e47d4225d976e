"""Export of the identified signal parameters and the correction table for the
encoder's processor: CSV, or a C header with a const array."""

from __future__ import annotations

import io
import math
from pathlib import Path

from models.fringe.compensation_at_samples import compensation_caveat
from models.fringe.result import FringeResult
from models.project.atomic_write import write_text_atomic

__all__ = ["correction_table_c_header", "correction_table_csv", "write_correction_table"]


_ZERO_TEXT = {"mean": "the table's mean is zero (the phase origin is arbitrary)",
              "phase0": "the entry at measured phase 0 is zero"}


def correction_table_csv(result: FringeResult) -> str:
    out = io.StringIO()
    out.write("# AngleBench fringe correction table: corrected phase = measured - correction\n")
    out.write(f"# zero: {_ZERO_TEXT[result.table.zero]}\n")
    out.write(f"# phase from: {result.phase_source}\n")
    out.write(f"# table sha256: {result.table.sha256}\n")
    caveat = compensation_caveat(result)
    if caveat:  # orders fold at the sampled phases: as the certificate says (day review 68 F8)
        out.write(f"# this table holds {caveat}\n")
    for name, fit in (("sin", result.sin_fit), ("cos", result.cos_fit)):
        params = ",".join(f"{k}={v:.9g}" for k, v in fit.as_dict().items())
        out.write(f"# {name}: {params}\n")
    out.write(f"index,measured_phase_rad,correction_rad,correction_{result.unit}\n")
    for j, value in enumerate(result.table.correction_rad):
        phase = 2 * math.pi * j / result.table.size
        out.write(f"{j},{phase:.9f},{value:.9e},{value / (2 * math.pi) * result.period_length:.6f}\n")
    return out.getvalue()


def correction_table_c_header(result: FringeResult, name: str = "anglebench_fringe_lut") -> str:
    size = result.table.size
    lines = [
        "/* AngleBench fringe correction table (generated).",
        " * corrected_phase = measured_phase - lut[j] with j = measured_phase / (2*pi) * SIZE,",
        " * linear interpolation between entries; values in radians of electrical phase.",
        f" * zero: {_ZERO_TEXT[result.table.zero]}.",
        *([f" * this table holds {caveat}."] if (caveat := compensation_caveat(result)) else []),
        f" * table sha256: {result.table.sha256} */",
        f"#ifndef {name.upper()}_H",
        f"#define {name.upper()}_H",
        f"#define {name.upper()}_SIZE {size}",
        f"static const float {name}[{size}] = {{",
    ]
    values = [f"{v:.9e}f" for v in result.table.correction_rad]
    for i in range(0, size, 6):
        lines.append("    " + ", ".join(values[i:i + 6]) + ",")
    lines += ["};", f"#endif /* {name.upper()}_H */", ""]
    return "\n".join(lines)


def write_correction_table(path: str | Path, result: FringeResult) -> None:
    """Write a CSV, or a C header when the name ends in .h (atomically)."""
    text = (correction_table_c_header(result) if str(path).endswith(".h")
            else correction_table_csv(result))
    write_text_atomic(path, text)
