"""The certificate's own measure of a run of text (``PageFrame._run_width``, which the line
breaking calls for every word added) is fpdf2's ``get_string_width`` to the last bit, in
every font of the certificate, with and without the CJK fallback font, for Latin, Greek,
Chinese, figures and marks mixed: a line breaks where it broke before, so the PDF is the
same bytes (one fragment per script where fpdf2 makes one: the widths summed per fragment
differ from the width of the whole in the last bits)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.writers.certificate_pdf.fonts import CJK_FONT, FONT, close_fonts
from app.writers.certificate_pdf.page import PageFrame

#: Latin, Greek, CJK, the marks and symbols the certificates print, and characters DejaVu
#: lacks (measured in the CJK font's run, or by fpdf2 itself where there is none)
ALPHABET = ("AZaz09 .,;:-+−=±×°″′\"'()（）[]/%‰µψβωθΔσ·—–…"
            "校准证书测量不确定度符合性声明，。、；：“”《》"
            "한\u200b\u00a0")


@pytest.fixture(scope="module")
def frames():
    """A Latin-only certificate's page and one with the CJK fallback font (their font files
    closed after)."""
    made = {"latin": PageFrame(("lab", "AB-1"), ("", "")),
            "cjk": PageFrame(("实验室", "AB-1"), ("", ""), cjk=True, language="zh")}
    yield made
    for pdf in made.values():
        close_fonts(pdf)


@pytest.mark.slow  # ~0.4 s: the CJK font parsed, 150 texts measured twice
@settings(max_examples=150, deadline=None)
@given(text=st.text(ALPHABET, max_size=60), frame=st.sampled_from(["latin", "cjk"]),
       size=st.sampled_from([6.0, 7.5, 8, 8.5, 9, 11]), style=st.sampled_from(["", "B"]))
def test_a_runs_width_is_fpdf2s_to_the_last_bit(frames, text, frame, size, style):
    pdf = frames[frame]
    for font, run in pdf._runs(text):
        pdf._use(font, size, style)
        biggest = pdf.current_font.biggest_size_pt
        ours = pdf._run_width(run)
        pdf.current_font.biggest_size_pt = biggest
        assert ours == pdf.get_string_width(run), (font, run)
    pdf.set_font(FONT, "", 9)


def test_the_fast_measure_is_taken_where_the_certificates_text_is():
    """Not measured by fpdf2 for the usual text (so the figure compared above is ours)."""
    pdf = PageFrame(("实验室", "AB-1"), ("", ""), cjk=True, language="zh")
    calls = []
    pdf.get_string_width = lambda run, *a, **k: calls.append(run) or 0.0
    try:
        for font, run in ((FONT, "Expanded uncertainty U = 0.42\" (k = 2)"),
                          (CJK_FONT, "测量不确定度")):
            pdf._use(font, 9, "")
            assert pdf._run_width(run) > 0
    finally:
        close_fonts(pdf)
    assert calls == []
