"""The polygon's calibration certificate: face deviations from nominal, read from a small
CSV/XLSX (``position,deviation_arcsec``; a header row is optional)."""

from __future__ import annotations

from pathlib import Path

from models.messages import QT_TR_NOOP, message
from models.readings.sheet import Column, ColumnKind, ReadingsSheet
from models.readings.tabular_import import TableImportError, map_columns, read_table

__all__ = ["CERTIFICATE_COLUMNS", "read_polygon_certificate"]

CERTIFICATE_COLUMNS = (
    Column("position", "position", "", ColumnKind.INTEGER),
    Column("deviation_arcsec", "deviation", "\"", ColumnKind.NUMBER),
)


def read_polygon_certificate(path: str | Path) -> dict[int, float]:
    """Deviation (") of each face by position. Raises TableImportError naming file and row."""
    table = read_table(path)
    rows = map_columns(table, CERTIFICATE_COLUMNS)
    parsed = ReadingsSheet(CERTIFICATE_COLUMNS, rows).parse()
    if parsed.errors:
        e = parsed.errors[0]
        raise TableImportError(message(
            QT_TR_NOOP("{source}: row {line_numbers}, column '{column_key}': {reason}"),
            source=table.source, line_numbers=table.line_numbers[e.row], column_key=e.column_key,
            reason=e.reason))
    out: dict[int, float] = {}
    for i, (pos, dev) in enumerate(zip(parsed["position"], parsed["deviation_arcsec"],
                                       strict=True)):
        if int(pos) in out:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: row {line_numbers}: position {int} appears twice"),
                source=table.source, line_numbers=table.line_numbers[i], int=int(pos)))
        out[int(pos)] = float(dev)
    if not out:
        raise TableImportError(message(
            QT_TR_NOOP("{source}: no deviations found"),
            source=table.source))
    return out
