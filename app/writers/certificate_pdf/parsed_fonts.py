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
glyph names: fontTools makes them from its whole character map, ~0.1 s), none of the
layout tables fpdf2's subsetter drops on output (GDEF, GSUB, GPOS: fontTools reads them
before it drops them, ~0.1 s; and ``kern``, which it drops where the font has GPOS), and a
``glyf`` table whose glyphs are made from the file's bytes only when asked for
(:class:`_GlyphsOnDemand`): fontTools made an object of every one of the CJK font's 49 382
glyphs for each certificate (~0.15 s, half the time of writing its fonts) where the
subsetter asks for the few hundred printed; and the ``hmtx`` table's widths and the
``vmtx`` table's heights (the CJK font's: ~0.09 s a certificate) as the file's were read
once (the subsetter keeps the printed glyphs' in a table of its own). The bytes printed are the same
(tests/app/writers/test_certificate_parsed_fonts.py: the second certificate of a process,
made so, and the first, made as fpdf2 makes it).

This reaches into fpdf2's ``TTFFont`` by its slots: where the installed fpdf2's slots are
not the ones this was written for (:data:`KNOWN_SLOTS`), or a font needed fpdf2's
fallback ``.notdef`` glyph drawn into its file's tables, every certificate parses its fonts
as before (``add_font``).
"""

from __future__ import annotations

import copy
import os
import threading
from collections.abc import Iterator, MutableMapping
from pathlib import Path
from typing import Any

from fontTools import ttLib
from fontTools.ttLib.tables._g_l_y_f import Glyph as _Glyph
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

#: the tables of each glyph's metrics, kept from the parse (:func:`_metrics_kept`)
_METRICS = ("hmtx", "vmtx")

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
    kept["glyf"] = _GlyfBytes.of(font.ttfont, kept["glyph_order"])
    # each glyph's (advance, side bearing), as the file has them (fpdf2 only reads them)
    # each glyph's (advance, side bearing), as the file has them (fpdf2 only reads them),
    # across (hmtx) and down (vmtx: the CJK font's, which only the subsetter reads)
    for tag in _METRICS:
        kept[tag] = dict(font.ttfont[tag].metrics) if tag in font.ttfont else None
    return kept


class _GlyfBytes:
    """A TrueType font file's ``glyf`` table as its bytes and each glyph's place in them (its
    ``loca``), by glyph name: what fontTools' ``glyf`` decompile reads, kept once a process."""

    def __init__(self, data: bytes, offsets: tuple[int, ...], index: dict[str, int]) -> None:
        self.data, self.offsets, self.index = data, offsets, index

    @classmethod
    def of(cls, ttfont: ttLib.TTFont, order: tuple[str, ...]) -> _GlyfBytes | None:
        """The font's, or None where it has no ``glyf`` (CFF outlines) or its glyphs are not
        one a name (names repeated, or a ``loca`` longer than the glyph order: fontTools
        names those itself); such a font's table is read whole for each document, as before."""
        if "glyf" not in ttfont or "loca" not in ttfont or len(set(order)) != len(order):
            return None
        offsets = tuple(int(o) for o in ttfont["loca"])
        if len(offsets) - 1 != len(order):
            return None
        data = bytes(ttfont.reader["glyf"])
        if offsets and (offsets[0] > offsets[-1] or offsets[-1] > len(data)):
            return None
        return cls(data, offsets, {name: i for i, name in enumerate(order)})

    def glyph(self, name: str) -> Any:
        """The glyph ``name`` as fontTools' ``glyf`` decompile makes it (not yet expanded)."""
        i = self.index[name]
        return _Glyph(self.data[self.offsets[i]:self.offsets[i + 1]])


class _GlyphsOnDemand(MutableMapping):
    """The ``glyphs`` of a document's ``glyf`` table (name → Glyph, in the glyph order): each
    made from the kept bytes (:class:`_GlyfBytes`) the first time it is asked for, then the
    document's own to change, as the table's dict holds them; a name set or deleted is the
    document's too."""

    def __init__(self, source: _GlyfBytes) -> None:
        self.source = source
        self.made: dict[str, Any] = {}
        self.added: dict[str, None] = {}  # names set that the file's glyph order lacks
        self.deleted: set[str] = set()

    def __getitem__(self, name: str) -> Any:
        glyph = self.made.get(name)
        if glyph is None:
            if name in self.deleted or name not in self.source.index:
                raise KeyError(name)
            glyph = self.made[name] = self.source.glyph(name)
        return glyph

    def __setitem__(self, name: str, glyph: Any) -> None:
        self.made[name] = glyph
        self.deleted.discard(name)
        if name not in self.source.index:
            self.added[name] = None

    def __delitem__(self, name: str) -> None:
        if name not in self:
            raise KeyError(name)
        self.made.pop(name, None)
        self.added.pop(name, None)
        if name in self.source.index:
            self.deleted.add(name)

    def __contains__(self, name: object) -> bool:
        return name not in self.deleted and (name in self.source.index or name in self.added)

    def __iter__(self) -> Iterator[str]:
        for name in self.source.index:
            if name not in self.deleted:
                yield name
        yield from list(self.added)

    def __len__(self) -> int:
        return len(self.source.index) - len(self.deleted) + len(self.added)


def _metrics_kept(ttfont: ttLib.TTFont, metrics: dict[str, tuple[int, int]],
                  tag: str = "hmtx") -> None:
    """``ttfont``'s ``hmtx`` (or ``vmtx``) table as fontTools' decompile makes it from the
    file, from the metrics kept: a dict of the document's own (the subsetter replaces it
    with the printed glyphs' and adds to that; the values are tuples, never changed)."""
    table = ttLib.newTable(tag)
    table.metrics = dict(metrics)
    ttfont[tag] = table


def _glyf_on_demand(ttfont: ttLib.TTFont, source: _GlyfBytes) -> None:
    """``ttfont``'s ``glyf`` table as fontTools' decompile leaves it (lazily), its glyphs
    made when asked for (:class:`_GlyphsOnDemand`)."""
    table = ttLib.newTable("glyf")
    table.glyphOrder = ttfont.getGlyphOrder()
    table._reverseGlyphOrder = {}
    table.glyphs = _GlyphsOnDemand(source)
    ttfont["glyf"] = table


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
    if parsed.get("glyf") is not None:
        _glyf_on_demand(font.ttfont, parsed["glyf"])
    for tag in _METRICS:
        if parsed.get(tag) is not None:
            _metrics_kept(font.ttfont, parsed[tag], tag)
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
