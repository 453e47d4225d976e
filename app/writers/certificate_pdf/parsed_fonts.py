"""The bundled TrueType fonts parsed once a process, each certificate given its own font.

fpdf2's ``add_font`` reads a font file's tables and builds its maps of every character to
its width and glyph (``TTFFont``): ~0.03 s for DejaVu Sans, ~0.2 s for the CJK font, for
every certificate. What it builds from the file alone (the character and glyph maps, the
widths, the font's descriptor, its name and metrics) is kept here by the file (its real
path, size and modification time) and the font's key (family and style), and each
certificate gets a font of its own made from it, with everything a document changes made
new: the fontTools font of the file (fpdf2 subsets it in place when the PDF is written:
shared, the next certificate would embed the first one's subset), the subset of glyphs
used, the glyphs found missing, the largest size printed, the descriptor (its name and
object number are set at output), the width map (a defaultdict, which grows on reading a
missing character) and the glyph ids. fpdf2's own copy of a font (``TTFFont.__deepcopy__``,
for its FPDFRecorder) shares the same read-only parts.

Each certificate's fontTools font is given what it would read again from the file only to
reach the same result (:func:`_for_document`): the file's glyph order (the CJK font has no
glyph names: fontTools makes them from its whole character map, ~0.1 s), and none of the
layout tables fpdf2's subsetter drops on output (GDEF, GSUB, GPOS: fontTools reads them
before it drops them, ~0.1 s; and ``kern``, which it drops where the font has GPOS). The
bytes printed are the same (tests/app/writers/test_certificate_parsed_fonts.py: the second
certificate of a process, made so, and the first, made as fpdf2 makes it).

This reaches into fpdf2's ``TTFFont`` by its slots: where the installed fpdf2's slots are
not the ones this was written for (:data:`KNOWN_SLOTS`), or a font needed fpdf2's
fallback ``.notdef`` glyph drawn into its file's tables, every certificate parses its fonts
as before (``add_font``).
"""

from __future__ import annotations

import copy
import os
import threading
from pathlib import Path
from typing import Any

from fontTools import ttLib
from fpdf import FPDF
from fpdf.font_type_3 import get_color_font_object
from fpdf.fonts import SubsetMap, TTFFont

__all__ = ["KNOWN_SLOTS", "add_parsed_font"]

#: the slots of fpdf2 2.8's TTFFont: each is below either kept from the parse (``_KEPT``)
#: or made new for each document (``_PER_DOCUMENT``)
KNOWN_SLOTS = frozenset({
    "i", "type", "name", "desc", "glyph_ids", "_hbfont", "sp", "ss", "up", "ut", "cw",
    "ttffile", "fontkey", "emphasis", "scale", "subset", "cmap", "ttfont", "missing_glyphs",
    "biggest_size_pt", "color_font", "unicode_range", "palette_index", "is_compressed",
    "is_cff", "is_cid_keyed", "is_symbol", "cff_ros", "collection_font_number"})

#: made from the file alone and never changed by a document (fpdf2 reads them only)
_KEPT = ("type", "name", "sp", "ss", "up", "ut", "ttffile", "fontkey", "emphasis", "scale",
         "cmap", "unicode_range", "palette_index", "is_compressed", "is_cff", "is_cid_keyed",
         "is_symbol", "cff_ros", "collection_font_number")
#: a document's own (made in :func:`_for_document`)
_PER_DOCUMENT = ("i", "desc", "glyph_ids", "_hbfont", "cw", "subset", "ttfont",
                 "missing_glyphs", "biggest_size_pt", "color_font")

#: the layout tables fpdf2 drops from the font it embeds (fpdf/output.py: ``drop_tables``)
#: which fontTools' subsetter reads before it drops them
_DROPPED_LAYOUT = ("GDEF", "GSUB", "GPOS")

_PARSED: dict[tuple[str, str, int, int], dict[str, Any]] = {}
_LOCK = threading.Lock()


def add_parsed_font(pdf: FPDF, family: str, style: str, path: str | Path) -> None:
    """``pdf.add_font(family, style, path)``, the file parsed once a process."""
    fontkey = f"{family.lower()}{''.join(sorted(style.upper()))}"
    if frozenset(TTFFont.__slots__) != KNOWN_SLOTS or fontkey in pdf.fonts:
        pdf.add_font(family, style, str(path))
        return
    stat = os.stat(path)
    key = (fontkey, os.path.realpath(path), stat.st_size, stat.st_mtime_ns)
    with _LOCK:
        parsed = _PARSED.get(key)
    if parsed is None:
        pdf.add_font(family, style, str(path))
        font = pdf.fonts[fontkey]
        if isinstance(font, TTFFont) and _file_has_notdef(font):
            with _LOCK:
                _PARSED.setdefault(key, _kept(font))
        return
    font = _for_document(parsed, pdf)
    pdf.fonts[fontkey] = font
    if font.is_cff and font.is_cid_keyed:  # as add_font does
        pdf._set_min_pdf_version("1.6")


def _file_has_notdef(font: TTFFont) -> bool:
    """Whether the font file has its own ``.notdef`` glyph, where the OpenType specification
    puts it, first. fpdf2 draws one into the parsed tables where the file has none, which a
    font opened again from the file would lack; the glyph it adds goes last in the glyph
    order, which add_font has read already (opening the file again to look cost 0.2–0.4 s
    for the CJK font: more than a certificate that prints only once saves)."""
    order = font.ttfont.getGlyphOrder()
    return bool(order) and order[0] == ".notdef"


def _kept(font: TTFFont) -> dict[str, Any]:
    """What a freshly parsed font keeps for the next documents: its read-only parts, and
    copies of those a document changes, taken before any document used them."""
    # (a slot fpdf2 never sets, unicode_range in 2.8, is left unset as it leaves it)
    kept = {slot: getattr(font, slot) for slot in _KEPT if hasattr(font, slot)}
    kept["desc"] = copy.copy(font.desc)
    kept["cw"] = font.cw.copy()
    kept["glyph_ids"] = dict(font.glyph_ids)
    kept["glyph_order"] = tuple(font.ttfont.getGlyphOrder())
    return kept


def _for_document(parsed: dict[str, Any], pdf: FPDF) -> TTFFont:
    """A font for ``pdf`` made from ``parsed`` (:func:`_kept`), as ``add_font`` would make it."""
    font = TTFFont.__new__(TTFFont)
    for slot in _KEPT:
        if slot in parsed:
            setattr(font, slot, parsed[slot])
    font.i = len(pdf.fonts) + 1
    font.desc = copy.copy(parsed["desc"])
    font.cw = parsed["cw"].copy()
    font.glyph_ids = dict(parsed["glyph_ids"])
    font._hbfont = None
    font.ttfont = ttLib.TTFont(font.ttffile, recalcTimestamp=False,
                               fontNumber=font.collection_font_number, lazy=True)
    font.ttfont.setGlyphOrder(list(parsed["glyph_order"]))
    if font.is_compressed:
        font.ttfont.flavor = None
    else:  # (fpdf2's text shaping reads a compressed font's layout from this font)
        if "GPOS" in font.ttfont and "kern" in font.ttfont:
            del font.ttfont["kern"]  # as the subsetter does where the font has GPOS
        for tag in _DROPPED_LAYOUT:
            if tag in font.ttfont:
                del font.ttfont[tag]
    font.missing_glyphs = []
    font.biggest_size_pt = 0
    font.subset = SubsetMap(font)
    font.color_font = (get_color_font_object(pdf, font, font.palette_index)
                       if pdf.render_color_fonts else None)
    return font
