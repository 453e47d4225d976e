"""The bundled fonts are parsed once a process and each certificate gets its own fonts
(app/writers/certificate_pdf/parsed_fonts.py): certificates in Chinese and in English, one
after the other in one process, each embed their own fonts (poppler's pdffonts: the CJK
font only where the text needs it, every font embedded) and print their own text
(pdftotext), the second of each language the same bytes as the first; a font file changed
under the same path is parsed again. Before, every certificate parsed every font file
(~0.2 s for the CJK font); the count of parses fails that."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest
from fpdf import FPDF
from fpdf.fonts import TTFFont

from app.writers.certificate_pdf import certificate_pdf_bytes
from app.writers.certificate_pdf.fonts import font_files
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

pytestmark = pytest.mark.slow  # prints four certificates and reads them back

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
#: the sample's details with every name in Latin letters, so that the English certificate
#: needs no CJK font
LATIN = {"lab_name": "Precision Angle Lab", "customer_name": "Changchun Photonics Ltd.",
         "operator": "Wang", "approver": "Dr. Li"}


def _tool(name: str) -> str:
    path = shutil.which(name)
    if path is None:
        pytest.fail(f"{name} is missing: apt-get install poppler-utils (.ci/run does)")
    return path


def _pdffonts(pdf: bytes, tmp_path: Path) -> dict[str, str]:
    """{font name without its subset tag: 'yes' if embedded}."""
    path = tmp_path / "fonts.pdf"
    path.write_bytes(pdf)
    lines = subprocess.run([_tool("pdffonts"), str(path)], capture_output=True, text=True,
                           check=True).stdout.splitlines()[2:]
    return {line.split()[0].partition("+")[2] or line.split()[0]: line.split()[-5]
            for line in lines if line.strip()}


def _pdftotext(pdf: bytes, tmp_path: Path) -> str:
    path = tmp_path / "text.pdf"
    path.write_bytes(pdf)
    return subprocess.run([_tool("pdftotext"), "-enc", "UTF-8", str(path), "-"],
                          capture_output=True, text=True, encoding="utf-8", check=True).stdout


def _certificate(language: str) -> bytes:
    kind = KINDS["positioning"]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    settings = kind.settings_with_defaults(None)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    details = json.loads((SAMPLES / "certificate_positioning.json").read_text("utf-8"))
    metadata = CertificateMetadata.from_dict({**details, **LATIN, "language": language})
    return certificate_pdf_bytes(kind.certificate_document(result, metadata, kind.sample_file,
                                                           settings))


@pytest.fixture
def parses(monkeypatch):
    """The font files fpdf2 parses (TTFFont made from a file), the process's parsed fonts
    emptied first."""
    try:
        from app.writers.certificate_pdf import parsed_fonts
    except ImportError:  # before the cache: nothing kept to empty
        pass
    else:
        monkeypatch.setattr(parsed_fonts, "_PARSED", {})
    seen: list[str] = []
    original = TTFFont.__init__

    def counted(self, fpdf, font_file_path, *args, **kwargs):
        seen.append(Path(font_file_path).name)
        original(self, fpdf, font_file_path, *args, **kwargs)

    monkeypatch.setattr(TTFFont, "__init__", counted)
    return seen


def test_chinese_and_english_certificates_in_one_process_each_embed_their_fonts(parses,
                                                                                tmp_path):
    zh, en = _certificate("zh"), _certificate("en")
    zh_again, en_again = _certificate("zh"), _certificate("en")
    # every font file parsed once in the process, not once a certificate
    assert sorted(parses) == sorted({"DejaVuSans.ttf", "DejaVuSans-Bold.ttf",
                                     "DroidSansFallbackFull.ttf"}), parses
    # a certificate made from the kept fonts is the one made from the file, byte for byte
    assert zh_again == zh and en_again == en
    zh_fonts, en_fonts = _pdffonts(zh, tmp_path), _pdffonts(en, tmp_path)
    assert zh_fonts == {"DejaVuSansBook": "yes", "DejaVuSansBold": "yes",
                        "DroidSansFallback": "yes"}, zh_fonts
    assert en_fonts == {"DejaVuSansBook": "yes", "DejaVuSansBold": "yes"}, en_fonts
    zh_text, en_text = _pdftotext(zh, tmp_path), _pdftotext(en, tmp_path)
    assert "检测报告" in zh_text and "定位（轴线）" in zh_text and "Precision Angle Lab" in zh_text
    assert "Test report" in en_text and "Positioning (axis)" in en_text
    assert "Precision Angle Lab" in en_text
    assert not any("\u4e00" <= ch <= "\u9fff" for ch in en_text)
    assert "RT-400-0117" in zh_text and "RT-400-0117" in en_text


def test_a_font_file_changed_under_its_path_is_parsed_again(parses, tmp_path):
    from app.writers.certificate_pdf.parsed_fonts import add_parsed_font

    path = tmp_path / "font.ttf"

    def printed() -> dict[str, str]:
        pdf = FPDF()
        add_parsed_font(pdf, "font", "", path)
        pdf.add_page()
        pdf.set_font("font", size=12)
        pdf.cell(text="Angle 12.5\u2033")
        return _pdffonts(bytes(pdf.output()), tmp_path)

    shutil.copyfile(font_files()["regular"], path)
    assert printed() == {"DejaVuSansBook": "yes"}
    assert printed() == {"DejaVuSansBook": "yes"}
    shutil.copyfile(font_files()["bold"], path)
    assert printed() == {"DejaVuSansBold": "yes"}
    assert parses == ["font.ttf", "font.ttf"]


def test_every_slot_of_fpdf2s_font_is_kept_or_made_for_each_document():
    """An fpdf2 whose TTFFont has other slots turns the cache off (every certificate parses
    its fonts, as before): this says when parsed_fonts must be read again."""
    from app.writers.certificate_pdf import parsed_fonts

    kept, own = set(parsed_fonts._KEPT), set(parsed_fonts._PER_DOCUMENT)
    assert not kept & own and kept | own == parsed_fonts.KNOWN_SLOTS
    assert set(TTFFont.__slots__) == parsed_fonts.KNOWN_SLOTS


def _font_without_notdef(path: Path) -> None:
    """A TrueType font of a space and a square "A", with no ``.notdef`` glyph."""
    from fontTools.fontBuilder import FontBuilder
    from fontTools.pens.ttGlyphPen import TTGlyphPen

    builder = FontBuilder(1000, isTTF=True)
    builder.setupGlyphOrder(["space", "A"])
    builder.setupCharacterMap({0x20: "space", 0x41: "A"})
    pen = TTGlyphPen(None)
    pen.moveTo((100, 0))
    pen.lineTo((100, 700))
    pen.lineTo((500, 700))
    pen.lineTo((500, 0))
    pen.closePath()
    builder.setupGlyf({"space": TTGlyphPen(None).glyph(), "A": pen.glyph()})
    builder.setupHorizontalMetrics({"space": (300, 0), "A": (600, 100)})
    builder.setupHorizontalHeader(ascent=800, descent=-200)
    builder.setupNameTable({"familyName": "Square", "styleName": "Regular"})
    builder.setupOS2()
    builder.setupPost()
    builder.save(str(path))


def test_a_font_fpdf2_draws_a_notdef_into_is_parsed_for_every_document(parses, tmp_path):
    """fpdf2 draws a missing ``.notdef`` into the tables it parsed: a font made again from
    the file would lack it, so such a font is not kept."""
    from app.writers.certificate_pdf.parsed_fonts import add_parsed_font

    path = tmp_path / "square.ttf"
    _font_without_notdef(path)
    for _ in range(2):
        pdf = FPDF()
        add_parsed_font(pdf, "square", "", path)
        pdf.add_page()
        pdf.set_font("square", size=12)
        pdf.cell(text="A A")
        assert _pdffonts(bytes(pdf.output()), tmp_path) == {"Square": "yes"}
    assert parses == ["square.ttf", "square.ttf"]


def test_a_certificate_from_the_kept_fonts_reads_nothing_it_would_throw_away(parses,
                                                                            monkeypatch):
    """The second certificate of a process reads neither the CJK font's glyph names again
    (fontTools makes them from the font's whole character map: it has none) nor the layout
    tables fpdf2 drops from what it embeds (fontTools' subsetter read GDEF, GSUB and GPOS
    only to drop them): ~15 % of a printed certificate. The bytes are the same."""
    from fontTools import ttLib

    read: list[str] = []
    named_from_cmap: list[str] = []
    real_read, real_names = ttLib.TTFont._readTable, ttLib.TTFont._getGlyphNamesFromCmap

    def reading(font, tag):
        read.append(tag)
        return real_read(font, tag)

    def naming(font):
        named_from_cmap.append("named")
        return real_names(font)

    monkeypatch.setattr(ttLib.TTFont, "_readTable", reading)
    monkeypatch.setattr(ttLib.TTFont, "_getGlyphNamesFromCmap", naming)
    first = _certificate("zh")
    assert named_from_cmap and {"GDEF", "GSUB", "GPOS"} <= set(read)  # as fpdf2 does
    read.clear()
    named_from_cmap.clear()
    assert _certificate("zh") == first
    assert named_from_cmap == []
    assert not {"GDEF", "GSUB", "GPOS", "kern"} & set(read), read


def test_a_certificate_from_the_kept_fonts_makes_only_the_glyphs_it_prints(parses, monkeypatch):
    """fontTools made an object of every glyph of every font for each certificate (61 831:
    the CJK font's 49 382 and DejaVu's two 6 000; ~0.15 s, half of writing the fonts) and read
    every glyph's width (and the CJK font's heights) again, where the subsetter asks for the
    few hundred printed: the second certificate of a process makes those glyphs only
    (parsed_fonts._GlyphsOnDemand) and takes the metrics kept, and its bytes are the first
    one's, which fontTools made whole."""
    from fontTools import ttLib

    glyph = ttLib.getTableModule("glyf").Glyph
    made: list[int] = []
    read: list[str] = []
    real_init, real_read = glyph.__init__, ttLib.TTFont._readTable

    def counted(self, *args, **kwargs):
        made.append(1)
        real_init(self, *args, **kwargs)

    def reading(font, tag):
        read.append(tag)
        return real_read(font, tag)

    monkeypatch.setattr(glyph, "__init__", counted)
    monkeypatch.setattr(ttLib.TTFont, "_readTable", reading)
    first = _certificate("zh")
    assert len(made) > 49_382  # as fpdf2 and fontTools make them: every glyph of the files
    assert {"glyf", "hmtx", "vmtx"} <= set(read)
    made.clear()
    read.clear()
    assert _certificate("zh") == first
    assert 0 < len(made) < 3_000, len(made)
    assert not {"glyf", "hmtx", "vmtx"} & set(read), read  # the CJK font's heights too
