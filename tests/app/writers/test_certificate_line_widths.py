"""A text's fragments as the certificate cuts it (``fallback_fragments``: each character's
script looked up once a process) are fpdf2's, and a line's width as the certificate's cells
grow it (``measured_fragments``: each fragment's width summed once per character added) is
fpdf2's to the last bit, in every font of the certificate, with and without the CJK fallback
font, soft hyphens and page-count aliases included: every line breaks where fpdf2 broke it,
so the PDF is the same bytes."""

from __future__ import annotations

import pytest
from fpdf import FPDF
from fpdf.enums import WrapMode
from fpdf.fonts import TTFFont
from fpdf.line_break import Fragment, MultiLineBreak
from hypothesis import given, settings
from hypothesis import strategies as st

from app.writers.certificate_pdf.fonts import FONT, close_fonts
from app.writers.certificate_pdf.measured_fragments import MeasuredFragment
from app.writers.certificate_pdf.page import PageFrame

ALPHABET = ("AZaz09 .,;:-+−=±×°″′\"'()（）[]/%µψβωθΔσ·—–…"
            "校准证书测量不确定度符合性声明，。、；：“”《》"
            "\u00ad\u00a0\n{nb}")


@pytest.fixture(scope="module")
def frames():
    made = {"latin": PageFrame(("lab", "AB-1"), ("", "")),
            "cjk": PageFrame(("实验室", "AB-1"), ("", ""), cjk=True, language="zh")}
    for pdf in made.values():
        pdf.add_page()
    yield made
    for pdf in made.values():
        close_fonts(pdf)


def _lines(fragments, width: float, wrapmode: WrapMode) -> list[tuple]:
    breaker = MultiLineBreak(fragments, width, (1.0, 1.0), wrapmode=wrapmode)
    lines = []
    while (line := breaker.get_line()) is not None:
        lines.append((["".join(f.characters) for f in line.fragments], line.text_width,
                      line.number_of_spaces, line.trailing_nl))
    return lines


@pytest.mark.slow  # ~1 s: 150 texts broken into lines twice
@settings(max_examples=150, deadline=None)
@given(text=st.text(ALPHABET, max_size=120), frame=st.sampled_from(["latin", "cjk"]),
       size=st.sampled_from([6.0, 7.5, 8, 9, 11]), style=st.sampled_from(["", "B"]),
       width=st.sampled_from([8.0, 20.0, 45.0, 129.0]),
       wrapmode=st.sampled_from([WrapMode.WORD, WrapMode.CHAR]))
def test_lines_break_where_fpdf2_breaks_them_with_the_same_widths(frames, text, frame, size,
                                                                   style, width, wrapmode):
    pdf = frames[frame]
    pdf.set_font(FONT, style, size)
    pdf.str_alias_nb_pages = "{nb}" if size == 11 else ""  # the page foot's
    theirs = tuple(FPDF._parse_chars(pdf, text, False))  # fpdf2's own
    assert [(type(f), f.characters, f.graphics_state, f.k, f.link)
            for f in pdf._parse_chars(text, False)] \
        == [(type(f), f.characters, f.graphics_state, f.k, f.link) for f in theirs]
    ours = pdf._preload_font_styles(text, False)
    pdf.str_alias_nb_pages = ""
    assert [type(f) for f in ours] == [MeasuredFragment if type(f) is Fragment else type(f)
                                       for f in theirs] if text else ours == ()
    theirs = tuple(f for f in theirs if type(f) is Fragment) if text else ()
    ours = tuple(f for f in ours if type(f) is MeasuredFragment)
    try:
        expected = _lines(theirs, width, wrapmode)
    except Exception as exc:  # noqa: BLE001 - fpdf2's refusal (a character wider than the cell)
        with pytest.raises(type(exc)):
            _lines(ours, width, wrapmode)
        return
    assert _lines(ours, width, wrapmode) == expected
    # and a fragment measured as it grows, then cut short (a line broken at a space)
    for plain in theirs:
        grown = MeasuredFragment([], plain.graphics_state, plain.k)
        for i, ch in enumerate(plain.characters):
            grown.characters.append(ch)
            assert grown.get_width() == Fragment(plain.characters[:i + 1],
                                                 plain.graphics_state, plain.k).get_width()
            assert grown.get_character_width(ch) == plain.get_character_width(ch)
        grown.trim(len(plain.characters) // 2)
        assert grown.get_width() == Fragment(plain.characters[:len(plain.characters) // 2],
                                             plain.graphics_state, plain.k).get_width()


def test_the_page_count_alias_and_the_usual_text_are_measured_by_the_fast_path(monkeypatch):
    """The page count's stand-in is left to fpdf2; the usual text never asks the font for a
    width (so the figure compared above is the fast path's)."""
    pdf = PageFrame(("实验室", "AB-1"), ("", ""), cjk=True, language="zh")
    try:
        pdf.add_page()
        pdf.set_font(FONT, "", 9)
        pdf.str_alias_nb_pages = "{nb}"
        kinds = [type(f).__name__ for f in pdf._preload_font_styles("Page 1 of {nb}", False)]
        assert kinds == ["MeasuredFragment", "TotalPagesSubstitutionFragment"]
        pdf.str_alias_nb_pages = ""
        monkeypatch.setattr(TTFFont, "get_text_width", None)  # would raise if called
        fragments = pdf._preload_font_styles("Expanded uncertainty U = 0.42″ 测量不确定度", False)
        assert len(_lines(fragments, 30.0, WrapMode.WORD)) > 1
    finally:
        close_fonts(pdf)


@pytest.mark.slow  # ~0.5 s: 150 texts wrapped twice
@settings(max_examples=150, deadline=None)
@given(text=st.text(ALPHABET.replace("{nb}", ""), max_size=80),
       frame=st.sampled_from(["latin", "cjk"]), size=st.sampled_from([7.5, 8, 9]),
       style=st.sampled_from(["", "B"]), width=st.sampled_from([5.0, 20.0, 41.8, 126.4]))
def test_a_paragraph_that_fits_is_wrapped_as_word_by_word(frames, text, frame, size, style,
                                                          width):
    """``_wrapped`` takes a paragraph the line holds whole without measuring it word by word:
    the same lines as measured word by word (the fast path off)."""
    import app.writers.certificate_pdf.page as page

    pdf = frames[frame]
    pdf.set_font(FONT, "", size)
    ours = pdf._wrapped(text, width, size, style)
    with pytest.MonkeyPatch.context() as patched:
        patched.setattr(page, "_FITS_WITHIN", float("inf"))  # never taken as fitting
        assert pdf._wrapped(text, width, size, style) == ours


def test_a_cell_the_line_holds_is_measured_once(frames, monkeypatch):
    pdf = frames["cjk"]
    measured: list[str] = []
    real = PageFrame.text_width
    monkeypatch.setattr(PageFrame, "text_width",
                        lambda self, text, *a: measured.append(text) or real(self, text, *a))
    text = "扩展不确定度 U = 0.42″ (k = 2)"
    assert pdf._wrapped(text, 60.0, 8) == text
    assert measured == [text]
    measured.clear()
    assert "\n" in pdf._wrapped(text, 20.0, 8)  # too wide: word by word
    assert len(measured) > 5
