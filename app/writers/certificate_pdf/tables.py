"""Tables on the page: the key–value list of the certificate's details and the ruled data
tables (headers in both languages on a bilingual certificate, no "−0.00")."""

from __future__ import annotations

import re

from fpdf.enums import TableCellFillMode
from fpdf.fonts import FontFace

from app.writers.certificate_pdf.fonts import FONT
from app.writers.certificate_pdf.line_breaks import _CLOSING, _wrapmode
from app.writers.certificate_pdf.page import GREY, PageFrame
from app.writers.certificate_pdf.wording import _both, _chinese_then_english
from models.certificate.document import Table

HEADER_FILL = (228, 233, 240)


def _marks_begin_a_line(text: str) -> bool:
    """Whether a line after the first of ``text`` begins with a closing mark ("），")."""
    return any(line[:1] in _CLOSING for line in str(text or "").split("\n")[1:])


class TableDrawing(PageFrame):
    """The page with its tables: the details' key–value list and the ruled data tables."""

    def _cells_wrapped(self, rows, widths, size: float, bold_first: bool) -> list[list[str]]:
        """A table's cells pre-wrapped as :meth:`_wrapped` does (for a table fpdf2 wraps by
        character: one holding Chinese), so that no word or figure is cut in two."""
        scale = self.epw / sum(widths)
        out = []
        for r, row in enumerate(rows):
            style = "B" if bold_first and r == 0 else ""
            out.append([self._wrapped(str(cell or ""), w * scale - 2.6, size, style)
                        if cell else cell for cell, w in zip(row, widths, strict=False)])
        self.set_font(FONT, "", size)
        return out

    def key_values(self, rows: list[tuple[str, str]]) -> None:
        self.set_font(FONT, "", 9)
        rows = [(self.say(key), self.say(value)) for key, value in rows]
        wrapmode = _wrapmode(cell for row in rows for cell in row)
        sizes = [9.0] * len(rows)
        if wrapmode == "CHAR":
            wrapped = []
            for i, (key, value) in enumerate(rows):
                sizes[i], text = self._value_wrapped(value)
                # a label broken between words too (a bilingual setting's English: "when
                # not me / asured" where fpdf2 broke it by character, zh81)
                style = "" if "\n" in key else "B"
                key = "\n".join(self._wrapped(line, 45 - 2.6, 9, style) if line else line
                                 for line in key.split("\n"))
                wrapped.append((key, text))
            rows = wrapped
            self.set_font(FONT, "", 9)  # the wrapping leaves its last size selected
        with self.table(col_widths=(45, 129), first_row_as_headings=False, borders_layout="NONE",
                        line_height=4.8, text_align=("LEFT", "LEFT"), padding=(0.6, 1.0),
                        wrapmode=wrapmode) as table:
            for (key, value), size in zip(rows, sizes, strict=True):
                row = table.row()
                # a two-line bilingual label is set plain: fpdf2 drops the English line of a
                # bold cell that falls back to the CJK font (seen in poppler: "No font in show")
                row.cell(key, style=None if "\n" in key else FontFace(emphasis="BOLD"))
                row.cell(value or "—", style=None if size == 9.0 else FontFace(size_pt=size))

    def _cell_said(self, cell, in_both: bool, report: bool) -> list[str]:
        """A body cell's text, in the certificate's language, or ``in_both``: in Chinese,
        then in English (once where it has no Chinese: a figure)."""
        if in_both and isinstance(cell, str) and cell:
            return [_no_negative_zero(part) for part in _chinese_then_english(cell, report)]
        return [_no_negative_zero(self.say(cell))]

    def _value_wrapped(self, value: str) -> tuple[float, str]:
        """A details value wrapped for its 129 mm column, at 9 pt, or a little smaller where
        that keeps a word no line holds with the closing marks after it (a SHA-256 and its
        "），") on one line: at 9 pt the marks began the next line (day review 68 F12; the
        digest alone fills 125 of the line's 126 mm). The size and the text."""
        text = self._cells_wrapped([["", value]], (45, 129), 9, False)[0][1]
        if not value or not _marks_begin_a_line(text):
            return 9.0, text
        for size in (8.5, 8.0):
            smaller = self._cells_wrapped([["", value]], (45, 129), size, False)[0][1]
            if not _marks_begin_a_line(smaller):
                return size, smaller
        return 9.0, text  # no size a reader can read holds them: the marks go down

    def data_table(self, t: Table, widths: tuple[float, ...], align: tuple[str, ...],
                   size: float = 8, rows_in_both: bool = False, report: bool = False) -> None:
        """``t`` as a ruled table; a cell too tall for a page below it, marked ("[1]"). On a
        bilingual certificate the header's names in Chinese above the English, and with
        ``rows_in_both`` every cell too (the statistics: their rows and notes, read by the
        assessor; assessment zh81: English only under "统计结果 Statistics"), a cell below the
        table then in Chinese, then in English; ``report``: a test report's words."""
        self.set_font(FONT, "", size)
        self.set_fill_color(246, 247, 249)
        heading = FontFace(emphasis="BOLD", fill_color=HEADER_FILL)
        both = self.language == "zh+en"
        header = [_both(cell) if both else cell for cell in t.header]
        in_both = both and rows_in_both
        said = [[self._cell_said(cell, in_both, report) for cell in row] for row in t.rows]
        cells = [[_no_negative_zero(self.say(cell)) for cell in header],
                 *[["\n".join(parts) for parts in row] for row in said]]
        cells, moved = _long_cells_below(cells, widths, size, said)
        wrapmode = _wrapmode(cell for row in cells for cell in row)
        if wrapmode == "CHAR":
            cells = self._cells_wrapped(cells, widths, size, True)
        with self.table(col_widths=widths, text_align=align, line_height=size * 0.5,
                        headings_style=heading, borders_layout="HORIZONTAL_LINES",
                        cell_fill_color=(246, 247, 249), cell_fill_mode=TableCellFillMode.ROWS,
                        repeat_headings=1, padding=(0.5, 1.0), wrapmode=wrapmode) as table:
            for row in cells:
                table.row(row)
        for text in moved:
            self.paragraph(text, 7.5, GREY)
        for note in (_chinese_then_english(t.note, report) if in_both else [t.note]) \
                if t.note else []:
            self.paragraph(note, 7.5, GREY)


#: a cell taller than this (mm, estimated) goes below its table: a table row cannot break
#: across pages (fpdf2 raises), and a positioning decided quantity's note with the rule's
#: U beside a tolerance below a point's U ran past a page in a 36 mm column (#61)
_TALLEST_CELL_MM = 90.0


def _text_width(text: str) -> int:
    """Characters, a CJK one counted twice (it prints about twice as wide)."""
    return sum(2 if ord(c) >= 0x2E80 else 1 for c in text)


def _long_cells_below(cells: list[list], widths: tuple[float, ...], size: float,
                      said: list[list[list[str]]] | None = None) -> tuple[list[list], list[str]]:
    """The table's cells with any too tall for a page replaced by a mark ("[1]"), and their
    texts to print below the table ("[1] Decided quantity: …"). ``said``: each body cell's
    texts, one a language (Chinese, then English, on a bilingual certificate's rows in
    both): a cell moved is then printed below in each, its row's name in the same."""
    per_char_mm = size * 0.19  # an 8 pt Latin character's mean advance is about 1.5 mm
    moved: list[str] = []
    marks = 0
    out = [list(cells[0])]
    for r, row in enumerate(cells[1:]):
        row = list(row)
        parts = said[r] if said is not None else [[cell] for cell in row]
        for j, cell in enumerate(row):
            if not isinstance(cell, str) or j >= len(widths):
                continue
            lines = _text_width(cell) * per_char_mm / max(widths[j] - 2.0, 1.0) + cell.count("\n")
            if lines * size * 0.5 > _TALLEST_CELL_MM:
                marks += 1
                mark = f"[{marks}]"  # the text once a language, below: no figure twice
                row[j] = mark
                names = parts[0] if len(parts[0]) == len(parts[j]) else [row[0]] * len(parts[j])
                for i, (name, text) in enumerate(zip(names, parts[j], strict=True)):
                    colon = "：" if i == 0 and len(parts[j]) > 1 else ": "  # Chinese, English
                    moved.append(f"{mark} {_without_probability(name)}{colon}{text}" if j
                                 else f"{mark} {text}")
        out.append(row)
    return out, moved


_ROW_PROBABILITY = re.compile(r"\s*[(（]p = [^)）]*[)）]$")


def _without_probability(name: str) -> str:
    """A row's name as a moved cell's text names it, without the "(p = 92.5 %)" the row
    carries ("[1] Decided quantity: …"): the probability is printed once, in the row."""
    return _ROW_PROBABILITY.sub("", name) if isinstance(name, str) else name


_NEGATIVE_ZERO = re.compile(r"(?<![\w.])[-−](0(?:\.0+)?)(?![\d.])")


def _no_negative_zero(text):
    """"−0.00" printed "0.00": a figure that rounds to zero has no sign."""
    return _NEGATIVE_ZERO.sub(r"\1", text) if isinstance(text, str) else text
