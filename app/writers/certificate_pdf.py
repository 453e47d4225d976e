"""Print a :class:`~models.certificate.document.CertificateDocument` as a PDF.

fpdf2 writes the page: text stays selectable (embedded, subset TrueType
fonts), the plots are drawn as vector paths, and the same inputs give the
same bytes (fixed creation date and document ID). User text is printed as
plain text — fpdf2 interprets no markup unless asked — and wraps inside its
cell, so a long name or a CJK note cannot break the layout.

Fonts (resources/fonts): DejaVu Sans for Latin, Greek and symbols (Bitstream
Vera / DejaVu licence), Droid Sans Fallback for Chinese, Japanese and Korean
(Apache License 2.0), used for any glyph DejaVu lacks.
"""

from __future__ import annotations

import datetime as dt
import functools
import hashlib
import json
import math
import re
import unicodedata
from importlib import resources
from pathlib import Path

import numpy as np
from fpdf import FPDF
from fpdf.enums import TableCellFillMode, XPos, YPos
from fpdf.fonts import FontFace

from models.certificate.document import CertificateDocument, PlotFigure, Table, budget_table
from models.certificate.metadata import PLACES
from models.messages import QT_TR_NOOP, Message, in_language, joined, message, translator
from models.plot_style import drawing_order, legend_series, series_style
from models.project.atomic_write import write_bytes_atomic
from models.quantity import Quantity
from models.software import software_identity
from models.uncertainty.budget import BASIS_DIVISORS
from models.uncertainty.conformity import uncertainty_decimals

__all__ = ["ReportPdf", "certificate_pdf_bytes", "close_fonts", "font_files",
           "write_certificate_pdf"]

FONT = "dejavu"
CJK_FONT = "droid"
PAGE_TOTAL_ALIAS = "{nb}"
INK = (20, 20, 20)
GREY = (110, 110, 110)
RULE = (170, 170, 170)
HEADER_FILL = (228, 233, 240)


def font_files() -> dict[str, Path]:
    """The bundled font files by role: regular, bold, cjk."""
    base = resources.files("resources") / "fonts"
    return {"regular": Path(str(base / "DejaVuSans.ttf")),
            "bold": Path(str(base / "DejaVuSans-Bold.ttf")),
            "cjk": Path(str(base / "DroidSansFallbackFull.ttf"))}


@functools.cache
def _latin_coverage() -> frozenset[int]:
    from fontTools.ttLib import TTFont

    with TTFont(font_files()["regular"], lazy=True) as font:
        return frozenset(font.getBestCmap())


@functools.cache
def _cjk_coverage() -> frozenset[int]:
    from fontTools.ttLib import TTFont

    with TTFont(font_files()["cjk"], lazy=True) as font:
        return frozenset(font.getBestCmap())


def _document_texts(document: CertificateDocument) -> list[str]:
    tables = (document.parameters, document.results, document.statistics)
    return [document.source_name, document.method, document.method_reference,
            *document.warnings, *document.statements, document.standard,
            *(cell for t in tables for row in (t.header, *t.rows) for cell in row),
            *(f"{k} {v}" for k, v in document.settings),
            json.dumps(document.metadata.to_dict(), ensure_ascii=False)]


def right_to_left(document: CertificateDocument) -> str:
    """The right-to-left letters of the document (Arabic, Hebrew…): the certificate sets text
    left to right, one character after another, so such a word would print reversed and
    unjoined."""
    seen = dict.fromkeys(ch for text in _document_texts(document) for ch in text
                         if unicodedata.bidirectional(ch) in ("R", "AL"))
    return "".join(seen)


def unprintable(document: CertificateDocument) -> str:
    """The characters of the document that no bundled font has (they would be dropped
    from the PDF without a word)."""
    covered = _latin_coverage() | _cjk_coverage()
    seen = dict.fromkeys(ch for text in _document_texts(document) for ch in text
                         if ord(ch) > 0x7F and ord(ch) not in covered and ch.isprintable())
    return "".join(seen)


def _needs_fallback(document: CertificateDocument) -> bool:
    """Whether any text of the document has a character DejaVu Sans lacks."""
    texts = _document_texts(document)
    covered = _latin_coverage()
    return any(ord(ch) not in covered for text in texts for ch in text if ord(ch) > 0x7F)


#: the certificate's fixed words in Chinese, metrology terms as JJF 1001-2011 names them
CHINESE = {
    "Calibration certificate": "校准证书", "Test report": "检测报告",
    "Certificate number": "证书编号", "Date of issue": "签发日期", "Laboratory": "校准机构",
    "Accreditation": "认可", "Customer": "委托方", "Item under test": "被校准对象",
    "Manufacturer": "制造单位", "Serial number": "出厂编号",
    "Grade / specification": "准确度等级/技术指标", "Date of calibration": "校准日期",
    "Environment": "环境条件", "Readings": "原始记录",
    "Reference standards and traceability": "计量标准及计量溯源性", "Method": "校准方法",
    "Analysis settings": "分析设置", "Error curves": "误差曲线", "Statistics": "统计结果",
    "Measurement uncertainty": "测量不确定度", "Statement of conformity": "符合性声明",
    "Statements": "声明", "Remarks": "备注", "Uncertainty budget": "不确定度分量一览表",
    "Figures of the axis": "轴线定位指标", "Test": "检测", "Sign convention": "符号约定",
    "Model": "型号", "Place of calibration": "校准地点",
    "Instrument output": "仪器原始输出", "Edited after capture": "采集后修改",
}


def label(document: CertificateDocument, english: str, separator: str = " ") -> str:
    """``english``, with its Chinese in front on a bilingual certificate, or in Chinese
    alone on a Chinese one."""
    language = document.metadata.language
    if language == "zh+en" and english in CHINESE:
        return f"{CHINESE[english]}{separator}{english}"
    if language == "zh":
        return CHINESE.get(english) or _say("zh")(english)
    return english


@functools.cache
def _say(language: str):
    """How the certificate's texts are printed in ``language``: a :class:`Message` in the
    translated template with its own figures, another text looked up whole (a column's
    name, a setting's label), anything else — user input, numbers — as it is. Only a
    Chinese certificate is translated: the bilingual one keeps the English body under
    its two-language headings."""
    if language != "zh":
        return str
    words = translator("zh_CN")
    return lambda text: in_language(text, words)


def _both(text):
    """A column's name in Chinese above the English (a bilingual certificate's headers)."""
    if not text:
        return text
    chinese, english = _say("zh")(text), str(text)
    return english if chinese == english else f"{chinese}\n{english}"


def revision_statement(meta) -> str:
    """ISO/IEC 17025 7.8.8: an amendment says what changed and which certificate it amends; a
    replacement identifies the one it replaces."""
    number = meta.revision.removeprefix("amendment").strip()
    if meta.revision.startswith("amendment") and number:
        what = message(QT_TR_NOOP("Amendment {number} to certificate {certificate}"),
                       number=number, certificate=meta.supersedes)
    elif meta.revision.startswith("amendment"):
        what = message(QT_TR_NOOP("Amendment to certificate {certificate}"),
                       certificate=meta.supersedes)
    else:
        what = message(QT_TR_NOOP("This certificate replaces certificate {certificate}"),
                       certificate=meta.supersedes)
    if meta.change_note:
        return message(QT_TR_NOOP("{what}, which it supersedes; the original stays on record "
                                  "unchanged. Changed: {change}"), what=what,
                       change=meta.change_note)
    return message(QT_TR_NOOP("{what}, which it supersedes; the original stays on record "
                              "unchanged."), what=what)


def _created(document: CertificateDocument) -> dt.datetime:
    meta = document.metadata
    if meta.created:
        try:
            stamp = dt.datetime.fromisoformat(meta.created)
        except ValueError:
            stamp = None
        if stamp is not None:
            return stamp if stamp.tzinfo else stamp.replace(tzinfo=dt.timezone.utc)
    if meta.issue_date:
        return dt.datetime.fromisoformat(meta.issue_date).replace(tzinfo=dt.timezone.utc)
    return dt.datetime.now(dt.timezone.utc).replace(microsecond=0)


class ReportPdf(FPDF):
    """An A4 page with the bundled fonts, a running head and foot, headings, paragraphs,
    tables and vector plots: the certificate and the validation report are made of it.

    ``head`` is (left, right) text at the top of every page, ``foot`` the lines at the
    bottom (the first gets "Page x of y" beside it).
    """

    def __init__(self, head: tuple[str, str], foot: tuple[str, str], cjk: bool = False,
                 language: str = "en") -> None:
        super().__init__(orientation="portrait", unit="mm", format="A4")
        self.head, self.foot = head, foot
        self.say = _say(language)  # how a text is printed ("zh": translated)
        self.language = language
        fonts = font_files()
        self.add_font(FONT, "", str(fonts["regular"]))
        self.add_font(FONT, "B", str(fonts["bold"]))
        if cjk or language == "zh":  # the CJK font costs ~0.3 s to load and subset
            self.add_font(CJK_FONT, "", str(fonts["cjk"]))
            self.set_fallback_fonts([CJK_FONT], exact_match=False)
        self.set_margins(18, 16, 18)
        self.set_auto_page_break(True, margin=20)
        self.alias_nb_pages("")  # see footer()
        self.set_text_color(*INK)

    # -- every run with its font ---------------------------------------------
    # fpdf2 remembers that it has set the font on the page, but sets it inside the "q … Q"
    # that wraps a cell (or a rotation) and so is undone at the "Q": the next text was
    # written with no font at all ("No font in show": a Latin-only lab name in the head of
    # every page after the first, figures between Chinese words). Each text object here
    # selects its font again.
    def _render_styled_text_line(self, *args, **kwargs):
        self.current_font_is_set_on_page = False
        return super()._render_styled_text_line(*args, **kwargs)

    def text(self, *args, **kwargs):
        self.current_font_is_set_on_page = False
        return super().text(*args, **kwargs)

    # -- page furniture ------------------------------------------------------
    def header(self) -> None:
        self.set_font(FONT, "", 8)
        self.set_text_color(*GREY)
        left, right = self.head
        # The right-hand cell first: a CJK lab name switches to the fallback font, and
        # fpdf2 then omits the font selection of the next cell on a fresh page.
        y = self.get_y()
        right_width = min(self.text_width(right, 8) + 2 * self.c_margin + 0.5, self.epw / 2)
        self.set_font(FONT, "", 8)
        self.set_x(self.l_margin + self.epw - right_width)
        self.cell(right_width, 5, right, align="R")
        # the left text (the lab's name) gets what the number leaves, never more: shrunk
        # down to 6 pt, then broken into lines, so it never prints over the number
        room = self.epw - right_width - 3
        size = 8.0
        wide = self.text_width(left, size)
        if wide > room - 2 * self.c_margin:
            size = max(6.0, size * (room - 2 * self.c_margin) / wide)
        self.set_font(FONT, "", size)
        self.set_xy(self.l_margin, y)
        if self.text_width(left, size) <= room - 2 * self.c_margin:
            self.cell(room, 5, left, new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        else:
            self.multi_cell(room, size * 0.45, self._wrapped(left, room - 2 * self.c_margin - 0.6,
                                                             size),
                            wrapmode="CHAR", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
            self.set_y(max(self.get_y(), y + 5))
        self.set_font(FONT, "", 8)
        self.set_draw_color(*RULE)
        self.line(self.l_margin, self.get_y(), self.w - self.r_margin, self.get_y())
        self.ln(3)
        self.set_text_color(*INK)

    def footer(self) -> None:
        self.set_y(-14)
        self.set_font(FONT, "", 7.5)
        self.set_text_color(*GREY)
        self.cell(self.epw * 0.75, 4, self.foot[0], new_x=XPos.RIGHT, new_y=YPos.TOP)
        # The page-count alias is live only here: elsewhere a "{nb}" typed by the user
        # would be replaced by the number of pages.
        previous, self.str_alias_nb_pages = self.str_alias_nb_pages, PAGE_TOTAL_ALIAS
        self.cell(self.epw * 0.25, 4, self.say(message(QT_TR_NOOP("Page {page} of {pages}"),
                                                       page=self.page_no(),
                                                       pages=PAGE_TOTAL_ALIAS)),
                  align="R", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        self.str_alias_nb_pages = previous
        self.cell(self.epw, 4, self.foot[1])
        self._foot_anchor()
        self.set_text_color(*INK)

    def _foot_anchor(self) -> None:
        """The register's head before this certificate, short (see _CertificatePdf)."""

    def output(self, *args, **kwargs):
        self.str_alias_nb_pages = PAGE_TOTAL_ALIAS  # fill in the footer's placeholders
        return super().output(*args, **kwargs)

    # -- building blocks -----------------------------------------------------
    def heading(self, text: str, keep_with: float = 18.0) -> None:
        """A section heading, moved to the next page unless ``keep_with`` mm follow it."""
        if self.will_page_break(keep_with):
            self.add_page()
        self.ln(2)
        self.set_font(FONT, "B", 11)
        self.cell(0, 7, self.say(text), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        self.set_font(FONT, "", 9)

    def paragraph(self, text: str, size: float = 9, color=INK) -> None:
        text = self.say(text)
        self.set_font(FONT, "", size)
        with self.local_context(text_color=color):
            if _mostly_cjk(text):  # Chinese prose: not justified; broken where
                # _units allows (between Chinese characters, at spaces), never inside
                # a figure or a word, never before a closing mark such as "。"
                width = self.epw - 2 * self.c_margin - 0.6
                self.multi_cell(0, 4.6, self._wrapped(text, width, size), wrapmode="CHAR",
                                align="L", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
            else:
                long_word = _long_word(text)  # (a checksum): broken here between words
                width = self.epw - 2 * self.c_margin - 0.6
                self.multi_cell(0, 4.6, self._wrapped(text, width, size) if long_word else text,
                                wrapmode="CHAR" if long_word else "WORD",
                                new_x=XPos.LMARGIN, new_y=YPos.NEXT)

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

    def _wrapped(self, text: str, width: float, size: float, style: str = "") -> str:
        """``text`` broken into lines of at most ``width`` mm where :func:`_units` allows
        (a unit wider than a line is left to fpdf2's character wrap)."""
        lines = []
        for paragraph in text.split("\n"):
            line = ""
            for unit in _units(paragraph):
                if line.strip() and self.text_width((line + unit).rstrip(), size, style) > width:
                    lines.append(line.rstrip())
                    line = unit.lstrip()
                else:
                    line += unit
            lines.append(line.rstrip())
        self.set_font(FONT, "", size)  # text_width() leaves the last run's font selected
        return "\n".join(lines)

    def key_values(self, rows: list[tuple[str, str]]) -> None:
        self.set_font(FONT, "", 9)
        rows = [(self.say(key), self.say(value)) for key, value in rows]
        wrapmode = _wrapmode(cell for row in rows for cell in row)
        if wrapmode == "CHAR":
            rows = [(key, self._cells_wrapped([["", value]], (45, 129), 9, False)[0][1])
                    for key, value in rows]
        with self.table(col_widths=(45, 129), first_row_as_headings=False, borders_layout="NONE",
                        line_height=4.8, text_align=("LEFT", "LEFT"), padding=(0.6, 1.0),
                        wrapmode=wrapmode) as table:
            for key, value in rows:
                row = table.row()
                # a two-line bilingual label is set plain: fpdf2 drops the English line of a
                # bold cell that falls back to the CJK font (seen in poppler: "No font in show")
                row.cell(key, style=None if "\n" in key else FontFace(emphasis="BOLD"))
                row.cell(value or "—")

    def data_table(self, t: Table, widths: tuple[float, ...], align: tuple[str, ...],
                   size: float = 8) -> None:
        self.set_font(FONT, "", size)
        self.set_fill_color(246, 247, 249)
        heading = FontFace(emphasis="BOLD", fill_color=HEADER_FILL)
        header = [_both(cell) if self.language == "zh+en" else cell for cell in t.header]
        cells = [[_no_negative_zero(self.say(cell)) for cell in row] for row in (header, *t.rows)]
        wrapmode = _wrapmode(cell for row in cells for cell in row)
        if wrapmode == "CHAR":
            cells = self._cells_wrapped(cells, widths, size, True)
        with self.table(col_widths=widths, text_align=align, line_height=size * 0.5,
                        headings_style=heading, borders_layout="HORIZONTAL_LINES",
                        cell_fill_color=(246, 247, 249), cell_fill_mode=TableCellFillMode.ROWS,
                        repeat_headings=1, padding=(0.5, 1.0), wrapmode=wrapmode) as table:
            for row in cells:
                table.row(row)
        if t.note:
            self.paragraph(t.note, 7.5, GREY)

    def _runs(self, text: str) -> list[tuple[str, str]]:
        """``text`` cut into runs of one font each: DejaVu Sans, or the CJK font for the
        characters DejaVu lacks (``text()`` has no fallback font of its own, and the CJK
        font has no Latin letters)."""
        latin = _latin_coverage()
        cjk = CJK_FONT in self.fonts
        runs: list[tuple[str, str]] = []
        for ch in text:
            font = CJK_FONT if cjk and ord(ch) > 0x7F and ord(ch) not in latin else FONT
            if runs and runs[-1][0] == font:
                runs[-1] = (font, runs[-1][1] + ch)
            else:
                runs.append((font, ch))
        return runs

    def _use(self, font: str, size: float, style: str) -> None:
        self.set_font(font, style if font == FONT else "", size)

    def text_width(self, text: str, size: float, style: str = "") -> float:
        width = 0.0
        for font, run in self._runs(text):
            self._use(font, size, style)
            width += self.get_string_width(run)
        return width

    def mixed_text(self, x: float, y: float, text: str, size: float, style: str = "") -> None:
        """``text()`` of ``text`` in as many fonts as its characters need."""
        for font, run in self._runs(text):
            self._use(font, size, style)
            self.text(x, y, run)
            x += self.get_string_width(run)

    # -- vector plot ---------------------------------------------------------
    def plot(self, figure: PlotFigure, height: float = 62.0) -> None:
        if self.will_page_break(height + 12):
            self.add_page()
        self.set_font(FONT, "B", 9)
        self.cell(0, 5, self.say(figure.title), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        x0, y0 = self.l_margin + 14, self.get_y() + 2
        w, h = self.epw - 16, height - 14
        xs = np.concatenate([s.x for s in figure.series if s.x.size])
        ys = np.concatenate([s.y for s in figure.series if s.y.size]
                            + [s.y + sign * s.band for s in figure.series if s.band is not None
                               for sign in (-1.0, 1.0)])
        xs = np.concatenate([xs] + [s.x for s in figure.series if s.band is not None
                                    for _ in (0, 1)])
        finite = np.isfinite(xs) & np.isfinite(ys)
        if not finite.any():
            self.paragraph(QT_TR_NOOP("(no data)"))
            return
        x_ticks = _nice_ticks(float(xs[finite].min()), float(xs[finite].max()))
        if xs[finite].min() >= 0 and 270 < xs[finite].max() <= 360:  # a turn: 0…360°, not 400°
            x_ticks = [float(v) for v in range(0, 361, 45)]
        y_ticks = _nice_ticks(float(ys[finite].min()), float(ys[finite].max()))
        if (float(ys[finite].max()) - y_ticks[0]) > 0.85 * (y_ticks[-1] - y_ticks[0]):
            # headroom for the legend, which is drawn inside the top of the frame: a band or
            # curve reaching the top would be hidden under it
            y_ticks.append(round(y_ticks[-1] + y_ticks[-1] - y_ticks[-2], 12))
        xlo, xhi, ylo, yhi = x_ticks[0], x_ticks[-1], y_ticks[0], y_ticks[-1]

        def px(v):
            return x0 + (np.asarray(v) - xlo) / (xhi - xlo) * w

        def py(v):
            return y0 + h - (np.asarray(v) - ylo) / (yhi - ylo) * h

        self.set_line_width(0.1)
        self.set_draw_color(220, 220, 220)
        self.set_font(FONT, "", 6.5)
        for t in y_ticks:
            self.line(x0, float(py(t)), x0 + w, float(py(t)))
            self.text(x0 - 1.2 - self.get_string_width(_tick(t, y_ticks)), float(py(t)) + 1.0,
                      _tick(t, y_ticks))
        for t in x_ticks:
            self.line(float(px(t)), y0, float(px(t)), y0 + h)
            label = _tick(t, x_ticks)
            self.text(float(px(t)) - self.get_string_width(label) / 2, y0 + h + 3.2, label)
        self.set_draw_color(*GREY)
        self.set_line_width(0.25)
        self.rect(x0, y0, w, h)
        if ylo < 0 < yhi:
            self.set_draw_color(120, 120, 120)
            self.line(x0, float(py(0.0)), x0 + w, float(py(0.0)))
        for s in figure.series:
            if s.band is None:
                continue
            ok = np.isfinite(s.x) & np.isfinite(s.y) & np.isfinite(s.band)
            upper = list(zip(px(s.x[ok]).tolist(), py((s.y + s.band)[ok]).tolist(), strict=True))
            lower = list(zip(px(s.x[ok]).tolist(), py((s.y - s.band)[ok]).tolist(), strict=True))
            if len(upper) >= 2:
                colour = series_style(s).colour
                self.set_fill_color(*[int(255 - (255 - c) * 0.25) for c in colour])
                self.polygon(upper + lower[::-1], style="F")
        # drawn as in the window (models/plot_style.py): the set-up model, dashed, first,
        # under the raw error it explains
        for s in drawing_order(figure):
            ok = np.isfinite(s.x) & np.isfinite(s.y)
            pts = list(zip(px(s.x[ok]).tolist(), py(s.y[ok]).tolist(), strict=True))
            style = series_style(s)
            colour = style.colour
            self.set_draw_color(*colour)
            self.set_line_width(0.3)
            if len(pts) >= 2:
                with self.local_context():
                    if style.dashed:
                        self.set_dash_pattern(dash=1.2, gap=0.8)
                    self.polyline(pts)
            if s.markers and len(pts) <= 400:
                self.set_fill_color(*colour)
                for x, y in pts:
                    self.circle(x, y, 0.45, style="F")
        x_label, y_label = self.say(figure.x_label), self.say(figure.y_label)
        self.mixed_text(x0 + w / 2 - self.text_width(x_label, 7) / 2, y0 + h + 7, x_label, 7)
        with self.rotation(90, self.l_margin + 1.5, y0 + h / 2):
            self.mixed_text(self.l_margin + 1.5 - self.text_width(y_label, 7) / 2,
                            y0 + h / 2, y_label, 7)
        lx = x0 + 2
        for s in legend_series(figure):
            self.set_draw_color(*series_style(s).colour)
            self.set_line_width(0.6)
            self.line(lx, y0 + 3, lx + 5, y0 + 3)
            name = self.say(s.label)
            self.mixed_text(lx + 6, y0 + 4, name, 7)
            lx += 9 + self.text_width(name, 7)
        self.set_line_width(0.2)
        self.set_draw_color(*INK)
        self.set_y(y0 + h + 9)


class _CertificatePdf(ReportPdf):
    def __init__(self, document: CertificateDocument) -> None:
        meta = document.metadata
        say = _say(meta.language)
        super().__init__(
            (meta.lab_name or say(QT_TR_NOOP("Laboratory not stated")),
             say(message(QT_TR_NOOP("Certificate {number}"), number=meta.certificate_number)
                 if meta.certificate_number else message(QT_TR_NOOP("Certificate no number")))),
            (say(QT_TR_NOOP("This certificate shall not be reproduced except in full without "
                            "the laboratory's written approval.")),
             say(message(QT_TR_NOOP("Certificate {number} · AngleBench {version}"),
                         number=meta.certificate_number or "—",
                         version=software_identity().short))),
            cjk=_needs_fallback(document) or document.metadata.language != "en",
            language=meta.language)
        self.document = document

    def header(self) -> None:
        super().header()
        if self.document.specimen:
            self._watermark(QT_TR_NOOP("SPECIMEN"), 60)
        elif self.document.is_draft:
            self._watermark(QT_TR_NOOP("DRAFT"), 90)

    def _watermark(self, word: str = QT_TR_NOOP("DRAFT"), size: float = 90) -> None:
        x, y = self.get_x(), self.get_y()
        with (self.local_context(text_color=(235, 200, 200)),
              self.rotation(45, self.w / 2, self.h / 2)):
            self.mixed_text(self.w / 2 - 60, self.h / 2 + 12, self.say(word), size, "B")
        self.set_xy(x, y)

    def _foot_anchor(self) -> None:
        head = self.document.register_head
        if head:
            self.set_xy(self.l_margin, self.h - 6)
            self.cell(self.epw, 3.5, self.say(message(QT_TR_NOOP(
                "Register chain head before this certificate: {head}…"), head=head[:16])))


_NEGATIVE_ZERO = re.compile(r"(?<![\w.])[-−](0(?:\.0+)?)(?![\d.])")


def _no_negative_zero(text):
    """"−0.00" printed "0.00": a figure that rounds to zero has no sign."""
    return _NEGATIVE_ZERO.sub(r"\1", text) if isinstance(text, str) else text


def _wrapmode(cells) -> str:
    """How a table's cells are wrapped: between words when every cell is Latin; between
    characters when one holds CJK text (fpdf2's word wrap dropped a word at a line's end
    with the fallback font, and Chinese breaks anywhere)."""
    return "CHAR" if any(_CJK.search(str(cell or "")) for cell in cells) else "WORD"


_CJK = re.compile("[\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef\uac00-\ud7af]")


def _mostly_cjk(text: str) -> bool:
    """Chinese prose (a Chinese certificate's paragraphs): more CJK characters than spaces."""
    cjk = sum(1 for ch in text if "\u3000" <= ch <= "\u9fff" or "\uff00" <= ch <= "\uffef")
    return cjk > text.count(" ")


def _long_word(text: str) -> bool:
    """A word no line can hold (a sha256 of 64 digits still fits whole on a line)."""
    return any(len(word) > 90 for word in text.split())


_CLOSING = set("。，、；：？！）》」』】”’…%\"″′°")
_OPENING = set("（《「『【“‘")
_OPERATORS = set("+−-=≤≥<>±×≈")


def _units(text: str) -> list[str]:
    """``text`` cut where a line may break: after a space, and between two characters of
    which one is Chinese — but never before a closing mark ("。", "）") or after an opening
    one, and never inside a Latin word or a figure."""
    units, current, previous = [], "", ""
    for ch, nxt in zip(text, text[1:] + " ", strict=False):  # "" (a blank line): no unit
        current += ch
        if (ch.isspace() and previous not in _OPERATORS and nxt not in _OPERATORS
                and nxt not in _CLOSING):  # "95.45 %" is kept whole too
            units.append(current)  # "T + w", "k = 2" are kept on one line
            current = ""
        elif (not ch.isspace() and not nxt.isspace() and nxt not in _CLOSING
              and ch not in _OPENING and (_CJK.match(ch) or _CJK.match(nxt))):
            units.append(current)
            current = ""
        previous = ch if not ch.isspace() else previous
    return [*units, current] if current else units


def _nice_ticks(lo: float, hi: float, count: int = 6) -> list[float]:
    if not math.isfinite(lo) or not math.isfinite(hi):
        return [0.0, 1.0]
    if hi - lo < 1e-12:
        pad = max(abs(lo) * 0.1, 1e-3)
        lo, hi = lo - pad, hi + pad
    raw = (hi - lo) / count
    mag = 10 ** math.floor(math.log10(raw))
    step = next(m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw)
    start = math.floor(lo / step) * step
    ticks = []
    v = start
    while not ticks or ticks[-1] < hi - 1e-9 * step:
        ticks.append(round(v, 12))
        v += step
        if len(ticks) > 50:
            break
    if len(ticks) < 2:
        ticks.append(ticks[-1] + step)
    return ticks


def _tick(value: float, ticks: list[float]) -> str:
    step = ticks[1] - ticks[0]
    if abs(value) < 1e-9 * step:
        value = 0.0  # no "-0.0"
    decimals = max(0, -int(math.floor(math.log10(step))) + (1 if step / 10 ** math.floor(
        math.log10(step)) == 2.5 else 0))
    return f"{value:.{decimals}f}"


def _standards_table(document: CertificateDocument) -> Table:
    rows = []
    for s in document.metadata.standards:
        u = "—" if s.uncertainty is None else message(
            "{u} ({basis})", u=Quantity(s.uncertainty, s.uncertainty_unit),
            basis=message(BASIS_DIVISORS[s.basis][0]))
        if s.uncertainty is None and s.certificate_no and document.stated_inputs:
            u = message(QT_TR_NOOP("as stated in the settings: {inputs}"),
                        inputs=joined(_between(", ", document.stated_inputs)))
        name = s.description or "—"
        if document.traceability_basis:  # no reference standard: a comparator
            name = message(QT_TR_NOOP("{standard} (comparator)"), standard=name)
        rows.append((name, s.serial or "—", s.certificate_no or "—", u, s.due_date or "—"))
    if not rows:
        rows.append((QT_TR_NOOP("not stated"), "", "", "", ""))
    return Table(QT_TR_NOOP("Reference standards"), (
        QT_TR_NOOP("Standard"), QT_TR_NOOP("Serial no."), QT_TR_NOOP("Certificate no."),
        QT_TR_NOOP("Uncertainty"), QT_TR_NOOP("Calibration due")), rows)


def _render(document: CertificateDocument) -> FPDF:
    meta = document.metadata
    pdf = _CertificatePdf(document)
    pdf.set_title(f"{label(document, document.title)} {meta.certificate_number}".strip())
    pdf.set_author(meta.lab_name)
    pdf.set_subject(pdf.say(document.kind_title))
    pdf.set_creator(f"AngleBench {software_identity().printed}")
    pdf.set_producer("AngleBench (fpdf2)")
    created = _created(document)
    pdf.set_creation_date(created)
    if document.register_head:
        from models.register.chain import HEAD_MARK

        pdf.set_keywords(f"{HEAD_MARK}{document.register_head}")
    pdf.add_page()

    pdf.set_font(FONT, "B", 17)
    pdf.cell(0, 9, label(document, document.title), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    pdf.set_font(FONT, "", 11)
    pdf.cell(0, 6, pdf.say(document.kind_title), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    if document.specimen:
        pdf.paragraph(message(QT_TR_NOOP(
            "SPECIMEN — made from example details for training or demonstration; not a "
            "certificate, not recorded in any register.")), 9, (170, 30, 30))
    elif document.is_draft:
        pdf.paragraph(message(QT_TR_NOOP("DRAFT — not valid as a certificate. Missing: "
                                         "{fields}."), fields=_listed(meta.missing_fields())),
                      9, (170, 30, 30))
    if meta.supersedes:
        pdf.paragraph(revision_statement(meta), 9.5, (20, 60, 140))
    pdf.ln(1)
    pdf.key_values([
        (label(document, "Certificate number", "\n"), meta.certificate_number),
        (label(document, "Date of issue", "\n"), meta.issue_date or created.date().isoformat()),
        (label(document, "Laboratory", "\n"),
         ", ".join(p for p in (meta.lab_name, meta.lab_address) if p)),
        (label(document, "Accreditation", "\n"), meta.lab_accreditation),
        (label(document, "Customer", "\n"),
         ", ".join(p for p in (meta.customer_name, meta.customer_address) if p)),
        (label(document, "Item under test", "\n"), meta.item_description),
        (label(document, "Manufacturer", "\n"), meta.item_manufacturer),
        (label(document, "Model", "\n"), meta.item_model),
        (label(document, "Serial number", "\n"), meta.item_serial),
        (label(document, "Grade / specification", "\n"), joined(_between("; ", [
            meta.item_grade, message(QT_TR_NOOP("tolerance ±{tolerance}"),
                                     tolerance=f"{document.tolerance:g}{document.unit}")
            if document.tolerance else ""]))),
        (label(document, "Date of calibration", "\n"), meta.calibration_date),
        (label(document, "Place of calibration", "\n"), _place(meta)),
        (label(document, "Environment", "\n"), _environment(meta)),
        (label(document, "Readings", "\n"), document.source_name),
        *([(label(document, "Instrument output", "\n"),
            f"SHA-256 {document.raw_data_sha256}")] if document.raw_data_sha256 else []),
        *([(label(document, "Edited after capture", "\n"), joined(_between("\n", document.edited_readings)))]
          if document.edited_readings else []),
    ])
    pdf.heading(label(document, "Reference standards and traceability"))
    pdf.data_table(_standards_table(document), (50, 26, 34, 42, 22), ("LEFT",) * 5)
    pdf.paragraph(_traceability(document), 8.5)
    pdf.heading(label(document, "Method"))
    pdf.paragraph(document.method)
    if document.method_reference:
        pdf.paragraph(message(QT_TR_NOOP("Reference: {reference}."),
                              reference=document.method_reference), 8, GREY)
    if document.standard:
        pdf.paragraph(message(QT_TR_NOOP(
            "The evaluation follows {standard}, implemented in AngleBench {version}; its "
            "verification is the validation report of that version (anglebench validate): "
            "simulations with known truth and hand-computed examples, each with its result."),
            standard=document.standard, version=software_identity().printed), 8, GREY)
    else:
        pdf.paragraph(message(QT_TR_NOOP(
            "This is a non-standard method, published in the reference above and implemented "
            "in AngleBench {version}. Its validation record (ISO/IEC 17025 7.2.2) is the "
            "validation report of that version (anglebench validate): the reference figures of "
            "the publication and exact simulations with known truth, each with its result."),
            version=software_identity().printed), 8, GREY)
    pdf.paragraph(joined([label(document, "Sign convention"), _colon(document),
                          _translatable(document.sign_convention), _stop(document)]), 8.5)
    if document.settings:
        pdf.heading(label(document, "Analysis settings"), keep_with=30)
        pdf.key_values(list(document.settings))
    pdf.heading(label(document, document.parameters.title))
    pdf.data_table(document.parameters, (70, 60, 44), ("LEFT", "RIGHT", "RIGHT"))
    pdf.heading(label(document, "Error curves"), keep_with=75.0)
    for figure in document.plots:
        pdf.plot(figure)
    pdf.heading(label(document, document.statistics.title))
    if len(document.statistics.header) == 5:  # figures with their coverage interval
        pdf.data_table(document.statistics, (46, 26, 42, 24, 36),
                       ("LEFT", "RIGHT", "RIGHT", "RIGHT", "LEFT"))
    else:
        pdf.data_table(document.statistics, (56, 42, 76), ("LEFT", "RIGHT", "LEFT"))
    pdf.heading(label(document, "Measurement uncertainty"))
    big_u = document.expanded_uncertainty
    budget_ = document.budget
    pdf.paragraph(message(QT_TR_NOOP(
        "The expanded uncertainty of the error is U = {u} (the largest over the points; each "
        "point's U is in the results table). At each point it is the combined standard "
        "uncertainty multiplied by the coverage factor k of Student's t for that point's "
        "effective degrees of freedom (Welch–Satterthwaite) and a coverage probability of "
        "{p} %; at the largest, k = {k}. The uncertainty was evaluated according to the GUM "
        "(JCGM 100:2008)."), u=f"{big_u:.{uncertainty_decimals(big_u)}f}{document.unit}",
        p=f"{100 * budget_.probability:.2f}", k=f"{budget_.coverage_factor:.2f}"))
    budget = budget_table(document.budget, document.budget_point, document.unit)
    pdf.data_table(budget, (46, 9, 19, 15, 13, 13, 10, 15, 14, 20),
                   ("LEFT", "CENTER", "LEFT") + ("RIGHT",) * 7, size=7)
    notes = [joined([_translatable(row[0]), _colon(document), _translatable(c.note)])
             for row, c in zip(budget.rows, document.budget.components, strict=False) if c.note]
    for note in notes:
        pdf.paragraph(note, 7.5, GREY)
    pdf.heading(label(document, "Statement of conformity"))
    conformity = document.conformity
    pdf.paragraph(conformity.statement)
    if conformity.quantity:
        pdf.paragraph(message(QT_TR_NOOP("Decided quantity: {quantity}."),
                              quantity=_translatable(conformity.quantity)), 8, GREY)
    pdf.paragraph(message(QT_TR_NOOP("Decision rule: {rule}."),
                          rule=_translatable(conformity.rule)), 8, GREY)
    if conformity.zones:
        pdf.paragraph(message(QT_TR_NOOP("Zones: {zones}."),
                              zones=_translatable(conformity.zones)), 8, GREY)
    pdf.heading(label(document, "Statements"))
    for statement in (*document.statements,
                      QT_TR_NOOP("The results relate only to the item calibrated, as received, "
                                 "under the conditions stated.")):
        pdf.paragraph(joined(["• ", _translatable(statement)]))
    if document.warnings or meta.notes:
        pdf.heading(label(document, "Remarks"))
        for w in document.warnings:
            pdf.paragraph(joined(["• ", _translatable(w)]))
        if meta.notes:
            pdf.paragraph(meta.notes)
    pdf.heading(label(document, document.results.title))
    n_cols = len(document.results.header)
    pdf.data_table(document.results, (174 / n_cols,) * n_cols, ("RIGHT",) * n_cols)
    _signatures(pdf)
    pdf.set_font(FONT, "", 8)
    with pdf.local_context(text_color=GREY):
        pdf.multi_cell(0, 5, pdf.say(message(QT_TR_NOOP("— End of certificate {number} —"),
                                             number=meta.certificate_number or "—")),
                       align="C", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        if document.register_head:
            pdf.set_font(FONT, "", 7)
            pdf.multi_cell(0, 4, pdf.say(message(QT_TR_NOOP(
                "The laboratory's certificate register, before this certificate, ended at "
                "chain head {head}; 'anglebench register verify --head' proves the register "
                "still holds that history."), head=document.register_head)),
                align="C", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    digest = hashlib.md5(_identity(document, created).encode(), usedforsecurity=False).hexdigest()
    pdf.file_id = lambda *_: f"<{digest}><{digest}>"
    return pdf


def _colon(document: CertificateDocument) -> str:
    return "：" if document.metadata.language == "zh" else ": "


def _stop(document: CertificateDocument) -> str:
    return "。" if document.metadata.language == "zh" else "."


def _translatable(text: str) -> str:
    """``text`` as a part of a composed text that a Chinese certificate translates: a
    :class:`Message` as it is, any other text looked up whole."""
    return text if isinstance(text, Message) or not text else message(text)


def _between(separator: str, parts) -> list:
    """The non-empty ``parts`` with ``separator`` between them (for :func:`joined`)."""
    out: list = []
    for part in parts:
        if part:
            out += ([separator] if out else []) + [_translatable(part)]
    return out


def _listed(names) -> str:
    return joined(_between(", ", names))


def _traceability(document: CertificateDocument) -> str:
    """What the results are traceable through, and plainly what they are not: a standard
    with no stated uncertainty is no input of the budget, and an input of the result with
    none (document.untraceable) leaves the result untraceable, with no conformity on it."""
    standards = document.metadata.standards
    stated = document.stated_inputs
    listed = [s for s in standards if s.certificate_no and (s.uncertainty is not None
                                                             or stated)]
    names = joined(_between("; ", (
        message(QT_TR_NOOP("{standard} (certificate {certificate})"),
                standard=s.description or message(QT_TR_NOOP("standard")),
                certificate=s.certificate_no) if s.uncertainty is not None else
        message(QT_TR_NOOP("{standard} (certificate {certificate}; its figures enter as the "
                           "inputs stated in the settings: {inputs})"),
                standard=s.description or message(QT_TR_NOOP("standard")),
                certificate=s.certificate_no, inputs=joined(_between(", ", stated)))
        for s in listed)))
    if document.untraceable:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established for these "
                                    "results — {what}; no statement of conformity rests on "
                                    "them."),
                         what=joined(_between("; ", document.untraceable)))]
        if listed:
            parts += [" ", message(QT_TR_NOOP("The standards listed with a certificate and a "
                                              "stated uncertainty: {names}."), names=names)]
    elif document.traceability_gaps:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established for these "
                                    "results — {what}."),
                         what=joined(_between("; ", document.traceability_gaps)))]
        if listed:
            parts += [" ", message(QT_TR_NOOP("The standards listed with a certificate and a "
                                              "stated uncertainty: {names}."), names=names)]
    elif document.traceability_basis:  # a self-calibrating method: its own reference
        parts = [_translatable(document.traceability_basis)]
        if standards:  # no reference value comes from them
            parts += [" ", message(QT_TR_NOOP("The instruments listed are comparators only; "
                                              "their calibration enters the uncertainty, not "
                                              "the reference: {names}."),
                                   names=_listed(s.description or message(QT_TR_NOOP("standard"))
                                                 for s in standards))]
    elif not listed:
        parts = [message(QT_TR_NOOP("Metrological traceability: not established on this "
                                    "document — no reference standard with a calibration "
                                    "certificate and a stated uncertainty is listed."))]
    else:
        parts = [message(QT_TR_NOOP("Metrological traceability: the results are traceable to "
                                    "the SI unit of plane angle through the reference standards "
                                    "listed, calibrated as stated in their certificates: "
                                    "{names}."), names=names)]
    for s in standards:
        if s.uncertainty is None and not (stated and s.certificate_no):
            parts += [" ", message(QT_TR_NOOP("{standard}: no uncertainty stated, so it is no "
                                              "input of the budget and the results are not "
                                              "traceable through it."),
                                   standard=s.description or message(QT_TR_NOOP("standard")))]
    return joined(parts)


def _identity(document: CertificateDocument, created: dt.datetime) -> str:
    """What makes two certificates the same document: for the PDF's /ID."""
    parts = [document.kind_key, repr(document.metadata.to_dict()), created.isoformat(),
             document.source_name, repr(document.results.rows), repr(document.parameters.rows)]
    return "\x1f".join(parts)


def _place(meta) -> str:
    """Where it was calibrated: at the laboratory, or at the customer's site (and where)."""
    place = message(PLACES.get(meta.calibration_place, PLACES["laboratory"]))
    return joined([place, ": ", meta.calibration_site]) if meta.calibration_site else place


def _environment(meta) -> str:
    parts = []
    if meta.temperature_c is not None:
        parts.append(message(QT_TR_NOOP("temperature {t} °C"), t=f"{meta.temperature_c:.1f}"))
    if meta.humidity_pct is not None:
        parts.append(message(QT_TR_NOOP("relative humidity {h} %"),
                             h=f"{meta.humidity_pct:.0f}"))
    return joined(_between(", ", parts))


def _signatures(pdf: _CertificatePdf) -> None:
    meta = pdf.document.metadata
    if pdf.will_page_break(34):
        pdf.add_page()
    pdf.ln(8)
    y = pdf.get_y()
    signers = [(QT_TR_NOOP("Operator"), meta.operator), (QT_TR_NOOP("Approved by"), meta.approver)]
    if meta.checker_role:  # the lab's template asks for a checker (核验员, JJF 1071)
        signers = [(QT_TR_NOOP("Calibrated by"), meta.operator),
                   (QT_TR_NOOP("Checked by"), meta.checker),
                   (QT_TR_NOOP("Approved by"), meta.approver)]
    half = pdf.epw / len(signers)
    for i, (role, name) in enumerate(signers):
        x = pdf.l_margin + i * half
        pdf.set_xy(x, y + 12)
        pdf.set_draw_color(*INK)
        pdf.line(x, y + 12, x + half - 12, y + 12)
        pdf.set_font(FONT, "", 8)
        said = (f"{_say('zh')(role)} {role}" if meta.checker_role and pdf.language == "zh+en"
                else pdf.say(role))
        pdf.cell(half - 12, 4.5, f"{said}{_colon(pdf.document)}{name or '—'}",
                 new_x=XPos.LEFT, new_y=YPos.NEXT)
        pdf.set_x(x)
        pdf.cell(half - 12, 4.5, pdf.say(QT_TR_NOOP("Signature and date")), new_x=XPos.LEFT,
                 new_y=YPos.NEXT)
    pdf.set_y(y + 24)


def close_fonts(pdf: FPDF) -> None:
    """fpdf2 opens the TrueType files lazily and leaves them open: close them."""
    for font in pdf.fonts.values():
        ttfont = getattr(font, "ttfont", None)
        if ttfont is not None:
            ttfont.close()


def certificate_pdf_bytes(document: CertificateDocument) -> bytes:
    """The PDF; ValueError when some text has characters no bundled font can print (Hangul,
    for one): refused rather than printed with those characters silently missing."""
    missing = unprintable(document)
    if missing:
        raise ValueError(f"the certificate's text has characters no bundled font can print: "
                         f"'{missing[:20]}'; write those details in Latin or Chinese script")
    backwards = right_to_left(document)
    if backwards:
        raise ValueError(f"the certificate's text has right-to-left script ('{backwards[:20]}'"
                         f"), which the certificate cannot print in its order (it would read "
                         f"reversed); write those details in Latin or Chinese script")
    final = _render(document)
    try:
        return bytes(final.output())
    finally:
        close_fonts(final)


def write_certificate_pdf(path: str | Path, document: CertificateDocument) -> None:
    """Write the certificate atomically (temp file + rename)."""
    write_bytes_atomic(path, certificate_pdf_bytes(document))
