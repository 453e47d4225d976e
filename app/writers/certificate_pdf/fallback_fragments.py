"""A text cut into fragments of one font and one script each, as fpdf2 2.8 cuts it when the
document has fallback fonts (a certificate with Chinese: its CJK font).

fpdf2's ``FPDF._parse_chars`` takes the text a character at a time, and for each looks its
Unicode script up in a list of ranges, asks whether it begins a Markdown marker (also where
there is no Markdown) and slices the rest of the text off: ~8 % of printing a certificate.
:func:`fallback_fragments` makes the same fragments (the same characters, graphics states,
fallback fonts and page-count placeholders, in the same order), each character's script
looked up once a process. Markdown and text shaping, which the certificates do not use, are
left to fpdf2 (:meth:`PageFrame._parse_chars`;
tests/app/writers/test_certificate_line_widths.py compares the two).
"""

from __future__ import annotations

from collections.abc import Iterator

from fpdf import FPDF
from fpdf.line_break import Fragment, TotalPagesSubstitutionFragment
from fpdf.unicode_script import UnicodeScript, get_unicode_script

__all__ = ["fallback_fragments", "script_of"]

_SCRIPTS: dict[str, UnicodeScript] = {}
_NO_SCRIPT = (UnicodeScript.COMMON, UnicodeScript.UNKNOWN)


def script_of(ch: str) -> UnicodeScript:
    """fpdf2's ``get_unicode_script(ch)``, each character looked up once a process."""
    found = _SCRIPTS.get(ch)
    if found is None:
        found = _SCRIPTS[ch] = get_unicode_script(ch)
    return found


def fallback_fragments(pdf: FPDF, text: str,
                       initial_emphasis: tuple[bool, bool, bool, bool] | None = None
                       ) -> Iterator[Fragment]:
    """fpdf2's ``pdf._parse_chars(text, markdown=False)`` for a document with fallback fonts
    and no text shaping."""
    if initial_emphasis is None:
        initial_emphasis = ("B" in pdf.font_style, "I" in pdf.font_style,
                            bool(pdf.strikethrough), bool(pdf.underline))
    in_bold, in_italics, in_strikethrough, in_underline = initial_emphasis
    style = ("B" if in_bold else "") + ("I" if in_italics else "")
    txt_frag: list[str] = []
    current_fallback_font: str | None = None
    current_text_script: UnicodeScript | None = None

    def frag() -> Fragment:
        nonlocal txt_frag, current_fallback_font, current_text_script
        gstate = pdf._get_current_graphics_state()
        gstate.font_style = style
        gstate.strikethrough = in_strikethrough
        gstate.underline = in_underline
        if current_fallback_font:
            gstate.font_family = current_fallback_font.replace("B", "").replace("I", "")
            gstate.font_style = "".join(c for c in current_fallback_font if c in ("BI"))
            gstate.current_font = pdf.fonts[current_fallback_font]
            current_fallback_font = None
            current_text_script = None
        fragment = Fragment(txt_frag, gstate, pdf.k)
        txt_frag = []
        return fragment

    ttf = pdf.is_ttf_font
    font_glyphs = pdf.current_font.cmap if ttf else ()  # type: ignore[union-attr]
    alias = pdf.str_alias_nb_pages
    i, end = 0, len(text)
    while i < end:
        ch = text[i]
        text_script = script_of(ch)
        if text_script not in _NO_SCRIPT and text_script != current_text_script:
            if txt_frag and current_text_script:
                yield frag()
            current_text_script = text_script
        if alias and text.startswith(alias, i):
            if txt_frag:
                yield frag()
            gstate = pdf._get_current_graphics_state()
            gstate.font_style = style
            gstate.strikethrough = in_strikethrough
            gstate.underline = in_underline
            yield TotalPagesSubstitutionFragment(
                alias, gstate, pdf.k,
                dummy_width_string=("0" * max(1, len(alias) - 1) if alias == "{nb}"
                                    else "0" * len(alias)),
                align=pdf.alias_nb_pages_align)
            i += len(alias)
            continue
        if ttf and ch != "\n" and ord(ch) not in font_glyphs:
            fallback_font = pdf.get_fallback_font(ch, style)
            if fallback_font:
                if fallback_font != current_fallback_font:
                    if txt_frag:
                        yield frag()
                    current_fallback_font = fallback_font
                txt_frag.append(ch)
                i += 1
                continue
        if current_fallback_font:
            if txt_frag:
                yield frag()
            current_fallback_font = None
        txt_frag.append(ch)
        i += 1
    if txt_frag:
        yield frag()
    pdf._markdown_emphasis = (in_bold, in_italics, in_strikethrough, in_underline)
