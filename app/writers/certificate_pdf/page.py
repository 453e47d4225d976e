"""An A4 page with the bundled fonts, a running head and foot ("Page x of y"), section
headings and paragraphs, each text run set in the font its characters need."""

from __future__ import annotations

from fpdf import FPDF
from fpdf.enums import CharVPos, XPos, YPos
from fpdf.fonts import TTFFont
from fpdf.unicode_script import UnicodeScript

from app.writers.certificate_pdf.fallback_fragments import fallback_fragments, script_of
from app.writers.certificate_pdf.fonts import CJK_FONT, FONT, _latin_coverage, font_files
from app.writers.certificate_pdf.line_breaks import _CLOSING, _long_word, _mostly_cjk, _units
from app.writers.certificate_pdf.measured_fragments import measured
from app.writers.certificate_pdf.parsed_fonts import add_parsed_font
from app.writers.certificate_pdf.wording import _chinese_then_english, _say
from models.messages import QT_TR_NOOP, message

PAGE_TOTAL_ALIAS = "{nb}"
INK = (20, 20, 20)
GREY = (110, 110, 110)
RULE = (170, 170, 170)


#: how far (mm) inside a line's width a paragraph measured whole is taken to fit: beyond any
#: difference of the last bits between the widths of its parts and of the whole
_FITS_WITHIN = 1e-6

#: the marks that close what comes before them (the Chinese closing ones, and the Latin
#: ones that close a clause or a bracket): never alone on a line
_TRAILING = "".join(sorted(_CLOSING | set(")]},.;:!?")))


class PageFrame(FPDF):
    """The page: ``head`` is (left, right) text at the top of every page, ``foot`` the lines
    at the bottom (the first gets "Page x of y" beside it)."""

    def __init__(self, head: tuple[str, str], foot: tuple[str, str], cjk: bool = False,
                 language: str = "en") -> None:
        super().__init__(orientation="portrait", unit="mm", format="A4")
        self.head, self.foot = head, foot
        self.say = _say(language)  # how a text is printed ("zh": translated)
        self.language = language
        fonts = font_files()
        # each file parsed once a process, each certificate its own fonts (parsed_fonts)
        add_parsed_font(self, FONT, "", fonts["regular"])
        add_parsed_font(self, FONT, "B", fonts["bold"])
        if cjk or language == "zh":  # the CJK font costs ~0.1 s to subset (and, once, to load)
            add_parsed_font(self, CJK_FONT, "", fonts["cjk"])
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

    # every text's runs measured once per character as a line grows, not once per line for
    # every character added (measured_fragments: the same widths to the last bit)
    def _preload_font_styles(self, *args, **kwargs):
        return measured(super()._preload_font_styles(*args, **kwargs))

    # a text with fallback fonts (Chinese) cut into its fragments each character's script
    # looked up once a process (fallback_fragments: the same fragments)
    def _parse_chars(self, text, markdown, **kwargs):
        if markdown or self.text_shaping or not self._fallback_font_ids \
                or set(kwargs) - {"_initial_emphasis"}:
            return super()._parse_chars(text, markdown, **kwargs)
        return fallback_fragments(self, text, kwargs.get("_initial_emphasis"))

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
        # the first line's text may be lines of its own, each with its "Page x of y" (a
        # bilingual certificate's notice in Chinese above the English): they begin higher
        notices = self.foot[0].split("\n")
        self.set_y(-14 - 4 * (len(notices) - 1))
        self.set_font(FONT, "", 7.5)
        self.set_text_color(*GREY)
        page = message(QT_TR_NOOP("Page {page} of {pages}"), page=self.page_no(),
                       pages=PAGE_TOTAL_ALIAS)
        said = (_chinese_then_english(page) if len(notices) == 2 and self.language == "zh+en"
                else [self.say(page)])
        for notice, number in zip(notices, [""] * (len(notices) - len(said)) + said,
                                  strict=True):
            self.cell(self.epw * 0.75, 4, notice, new_x=XPos.RIGHT, new_y=YPos.TOP)
            # The page-count alias is live only here: elsewhere a "{nb}" typed by the user
            # would be replaced by the number of pages.
            previous, self.str_alias_nb_pages = self.str_alias_nb_pages, PAGE_TOTAL_ALIAS
            self.cell(self.epw * 0.25, 4, number, align="R", new_x=XPos.LMARGIN,
                      new_y=YPos.NEXT)
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

    def paragraph(self, text: str, size: float = 9, color=INK, indent: float = 0.0) -> None:
        """``text`` in the certificate's language, ``indent`` mm in from the left margin."""
        text = self.say(text)
        self.set_font(FONT, "", size)
        if indent:
            self.set_x(self.l_margin + indent)
        cell = self.epw - indent if indent else 0  # 0: to the right margin
        width = self.epw - indent - 2 * self.c_margin - 0.6
        with self.local_context(text_color=color):
            if _mostly_cjk(text):  # Chinese prose: not justified; broken where
                # _units allows (between Chinese characters, at spaces), never inside
                # a figure or a word, never before a closing mark such as "。"
                self.multi_cell(cell, 4.6, self._wrapped(text, width, size),
                                wrapmode="CHAR", align="L", new_x=XPos.LMARGIN,
                                new_y=YPos.NEXT)
            else:
                long_word = _long_word(text)  # (a checksum): broken here between words
                self.multi_cell(cell, 4.6,
                                self._wrapped(text, width, size) if long_word else text,
                                wrapmode="CHAR" if long_word else "WORD",
                                new_x=XPos.LMARGIN, new_y=YPos.NEXT)

    def _wrapped(self, text: str, width: float, size: float, style: str = "") -> str:
        """``text`` broken into lines of at most ``width`` mm where :func:`_units` allows. A
        unit wider than a line that is one word and the closing marks after it (a SHA-256
        and its "），") has the word on its line and the marks begin the next, with what
        follows (day review 67 F9: fpdf2's character wrap left "），" alone on a line);
        another unit wider than a line is left to fpdf2's character wrap."""
        lines = []
        for paragraph in text.split("\n"):
            # a paragraph the line holds whole (most of a table's cells) is measured once, not
            # once for every word added: no part of it is wider than the whole (each width a
            # sum of its characters', none negative), so no break would come
            if self.text_width(paragraph.rstrip(), size, style) <= width - _FITS_WITHIN:
                lines.append(paragraph.rstrip())
                continue
            line = ""
            for unit in _units(paragraph):
                if line.strip() and self.text_width((line + unit).rstrip(), size, style) > width:
                    lines.append(line.rstrip())
                    line = unit.lstrip()
                else:
                    line += unit
                word = line.rstrip().rstrip(_TRAILING)
                if word.strip() and word != line.rstrip() and " " not in word.strip() \
                        and self.text_width(line.rstrip(), size, style) > width:
                    lines.append(word)
                    line = line[len(word):].lstrip()
            lines.append(line.rstrip())
        self.set_font(FONT, "", size)  # text_width() leaves the last run's font selected
        return "\n".join(lines)

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
        """The width of ``text`` set in the fonts its characters need; the font in use is
        left as it was (measuring a text that ends in Chinese left the CJK font in use, and
        the next cell set its Latin in it: "AngleBench" missing from the Chinese validation
        report's running head)."""
        family, current_style, current_size = self.font_family, self.font_style, self.font_size_pt
        width = 0.0
        for font, run in self._runs(text):
            self._use(font, size, style)
            width += self._run_width(run)
        if family:
            self.set_font(family, current_style, current_size)
        return width

    def _run_width(self, run: str) -> float:
        """``get_string_width(run)`` in the font in use, the same figure to the last bit,
        summed as fpdf2 2.8 sums it: each fragment its characters' widths (integers, in
        thousandths of the size) times the size, over the scale; a fragment ends where the
        Unicode script changes when there are fallback fonts. fpdf2 builds the fragments
        with a graphics state each and looks each character's script up in a list of ranges,
        and :meth:`_wrapped` measures a line again for every word added: ~13 % of printing
        the samples' certificates, ~5 % so (the same bytes printed). A run fpdf2 would treat
        otherwise (a character the font lacks, text shaping, spacing, stretching, a sub- or
        superscript, the page count's alias) is measured by fpdf2 itself
        (tests/app/writers/test_certificate_text_width.py)."""
        font = self.current_font
        if (not run or type(font) is not TTFFont or not self.is_ttf_font or font.is_symbol
                or self.text_shaping or self.char_spacing != 0 or self.font_stretching != 100
                or self.char_vpos != CharVPos.LINE or "\n" in run
                or (self.str_alias_nb_pages and self.str_alias_nb_pages in run)
                or not all(ord(ch) in font.cmap for ch in run)):
            return self.get_string_width(run)
        pieces: list[str | list[str]] = [run]
        if self._fallback_font_ids:  # fpdf2's _parse_chars: a fragment per script
            pieces, script = [], None
            piece: list[str] = []
            for ch in run:
                found = script_of(ch)
                if found not in (UnicodeScript.COMMON, UnicodeScript.UNKNOWN, script):
                    if piece and script:
                        pieces.append(piece)
                        piece = []
                    script = found
                piece.append(ch)
            if piece:
                pieces.append(piece)
        size = self.font_size_pt
        if size > font.biggest_size_pt:
            font.biggest_size_pt = size
        cw = font.cw
        return sum((sum(cw[ord(c)] for c in piece) * size * 0.001) / self.k for piece in pieces)

    def mixed_text(self, x: float, y: float, text: str, size: float, style: str = "") -> None:
        """``text()`` of ``text`` in as many fonts as its characters need."""
        for font, run in self._runs(text):
            self._use(font, size, style)
            self.text(x, y, run)
            x += self.get_string_width(run)
