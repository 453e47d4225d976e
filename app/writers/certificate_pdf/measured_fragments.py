"""A run of text on the page whose width is summed once per character, not once per line.

fpdf2 2.8 breaks a cell's text into lines a character at a time, and for every character it
adds measures the whole line again: every fragment's characters joined and each one's width
looked up, so a line of n characters costs n² look-ups (a data table is laid out twice, once
for its rows' heights and once to draw them). A :class:`MeasuredFragment` keeps the sum of
its characters' widths as they are added, and gives the same figure to the last bit as
fpdf2's :meth:`Fragment.get_width` (each character's width, integers in thousandths of the
size, summed in the same order, times the size, over the scale). A fragment fpdf2 would
measure otherwise (a font of another kind, a symbol font, text shaping, character spacing or
stretching) is measured by fpdf2 itself (tests/app/writers/test_certificate_text_width.py).
"""

from __future__ import annotations

from collections.abc import Sequence

from fpdf.fonts import TTFFont
from fpdf.line_break import HYPHEN, SOFT_HYPHEN, Fragment

__all__ = ["MeasuredFragment", "measured"]


class MeasuredFragment(Fragment):
    """fpdf2's fragment, its width summed once per character added."""

    _summed: list[str] | None = None  # the characters list the sum is of (a new list: anew)
    _summed_count = 0
    _summed_width: float = 0  # an int while the widths are (fpdf2 keeps them so)
    _summed_font: TTFFont | None = None

    def _plain_font(self) -> TTFFont | None:
        """The fragment's font when fpdf2 measures it as the plain sum of its characters'
        widths, else None."""
        state = self.graphics_state
        font = state.current_font
        if (type(font) is not TTFFont or font.is_symbol or state.text_shaping
                or state.char_spacing != 0 or state.font_stretching != 100):
            return None
        return font

    def _scaled(self, font: TTFFont, width) -> float:
        size = self.font_size_pt
        if size > font.biggest_size_pt:  # as fpdf2's get_text_width keeps it
            font.biggest_size_pt = size
        return width * size * 0.001 / self.k

    def get_width(self, start: int = 0, end: int | None = None, chars: str | None = None,
                  initial_cs: bool = True) -> float:
        font = self._plain_font() if chars is None and start == 0 and end is None else None
        if font is None:
            return super().get_width(start, end, chars, initial_cs)
        characters = self.characters
        if (self._summed is not characters or self._summed_font is not font
                or self._summed_count > len(characters)):
            self._summed, self._summed_font = characters, font
            self._summed_count, self._summed_width = 0, 0
        if self._summed_count < len(characters):
            cw = font.cw
            width = self._summed_width
            for ch in characters[self._summed_count:]:  # in order: the same sum, float or int
                width += cw[ord(ch)]
            self._summed_width, self._summed_count = width, len(characters)
        return self._scaled(font, self._summed_width)

    def get_character_width(self, character: str, print_sh: bool = False,
                            initial_cs: bool = True) -> float:
        font = self._plain_font()
        if font is None:
            return super().get_character_width(character, print_sh, initial_cs)
        if character == SOFT_HYPHEN and not print_sh:
            character = HYPHEN
        return self._scaled(font, 0 + font.cw[ord(character)])  # sum() starts at 0


def measured(fragments: Sequence[Fragment]) -> tuple[Fragment, ...]:
    """``fragments`` with each plain one (not the page count's stand-in) measured as it
    grows."""
    return tuple(MeasuredFragment(f.characters, f.graphics_state, f.k, f.link)
                 if type(f) is Fragment else f for f in fragments)
