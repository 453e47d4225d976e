"""The manual's window (F1) as a technician uses it (#44): a workbench's page with its
screenshot, its links followed as a click follows them (to the index, to a heading of a
reference page, to the other language) and Back; in English and in Chinese."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from PySide6.QtCore import QUrl
from PySide6.QtGui import QTextDocument

from widgets.manual_window import MANUAL_DIR, ManualWindow


@pytest.fixture
def manual(qtbot):
    window = ManualWindow()
    qtbot.addWidget(window)
    window.resize(760, 700)
    return window


def _follow(manual: ManualWindow, href: str) -> None:
    """What a click on ``<a href=href>`` does in QTextBrowser."""
    manual.browser.setSource(manual.browser.source().resolved(QUrl(href)))


def _attributes(manual: ManualWindow, name: str) -> list[str]:
    """The ``name`` attributes (href, src) of the page shown."""
    page = Path(manual.browser.source().toLocalFile()).read_text("utf-8")
    return re.findall(rf'{name}="([^"]+)"', page)


@pytest.mark.parametrize(("language", "index", "heading"), [
    ("en", "index.html", "What you measure"), ("zh_CN", "index.zh_CN.html", "测量什么")])
def test_a_workbench_page_its_picture_and_the_way_back(manual, language, index, heading):
    manual.show_page("polygon", language)
    text = manual.browser.toPlainText()
    assert heading in text
    pictures = _attributes(manual, "src")
    assert pictures, "the page shows its screenshot"
    image = manual.browser.document().resource(
        QTextDocument.ResourceType.ImageResource, manual.browser.source().resolved(QUrl(pictures[0])))
    assert image is not None and not image.isNull(), f"{pictures[0]} is not found from the page"
    _follow(manual, index)
    assert manual.browser.source().fileName() == index
    assert "polygon" in "".join(_attributes(manual, "href"))  # the index leads to every workbench
    manual.browser.backward()
    assert manual.browser.source().fileName() == ("polygon.html" if language == "en"
                                                  else "polygon.zh_CN.html")


def test_a_link_to_a_heading_of_another_page_scrolls_to_it(manual):
    manual.show_page("polygon")
    assert "certificates-and-register.html#conformity" in _attributes(manual, "href")
    _follow(manual, "certificates-and-register.html#conformity")
    assert manual.browser.source().fileName() == "certificates-and-register.html"
    assert manual.browser.verticalScrollBar().value() > 0  # at the heading, not the top


def test_the_chinese_page_links_a_heading_of_its_own_and_the_english_page(manual):
    manual.show_page("fringe", "zh_CN")
    own = next(h for h in _attributes(manual, "href") if h.startswith("#"))
    _follow(manual, own)
    assert manual.browser.verticalScrollBar().value() > 0
    _follow(manual, "fringe.html")
    assert "What you measure" in manual.browser.toPlainText()
    assert (MANUAL_DIR / "fringe.html").is_file()


def test_the_chinese_guide_leads_to_the_chinese_reference_at_its_heading(manual):
    """The Chinese polygon page sends the technician to conformity in the Chinese page of
    certificates and the register (not the English one), which leads back to the manual."""
    manual.show_page("polygon", "zh_CN")
    hrefs = _attributes(manual, "href")
    assert "certificates-and-register.zh_CN.html#符合性" in hrefs
    assert not any(h.startswith("certificates-and-register.html") for h in hrefs)
    _follow(manual, "certificates-and-register.zh_CN.html#符合性")
    assert manual.browser.source().fileName() == "certificates-and-register.zh_CN.html"
    assert manual.browser.verticalScrollBar().value() > 0  # at the heading, not the top
    assert "判定的量是明确的" in manual.browser.toPlainText()
    _follow(manual, "capture.zh_CN.html")
    assert "稳定时自动取数" in manual.browser.toPlainText()
    _follow(manual, "index.zh_CN.html")
    assert "capture.zh_CN.html" in _attributes(manual, "href")
