"""The window's manual (F1) and docs/ from one source (#44): every page of
resources/manual/ is generated from the Markdown of docs/ (``make docs``) and is what that
Markdown says now; the Chinese user guide, and the Chinese of the references a technician
needs in the window (capture, certificates and the register), are full translations of the
English pages (every section and every figure), linked from the Chinese pages in place of
the English ones; every link and picture of a page is found where the window looks, from an
installed package too."""

from __future__ import annotations

import fnmatch
import re
from collections import Counter
from pathlib import Path, PurePosixPath

import pytest

from app import manual_pages

ROOT = Path(__file__).resolve().parents[2]
MANUAL = ROOT / "resources" / "manual"
EN, ZH = ROOT / "docs" / "user-guide", ROOT / "docs" / "zh_CN" / "user-guide"
GUIDES = sorted(p.name for p in EN.glob("*.md"))
#: the references translated into Chinese (command-line.md is mostly the generated English
#: --help of every command; benchmarks.md is for developers: both stay English)
TRANSLATED_REFERENCES = ("capture.md", "certificates-and-register.md")
#: every Chinese page and the English page it translates
PAIRS = [(f"docs/user-guide/{name}", f"docs/zh_CN/user-guide/{name}") for name in GUIDES] + [
    (f"docs/{name}", f"docs/zh_CN/{name}") for name in TRANSLATED_REFERENCES]


def test_every_page_of_the_manual_is_its_source_now():
    assert manual_pages.stale() == [], (
        "resources/manual/ differs from docs/ (or holds a page no source makes): run `make docs`")


def test_a_changed_source_or_a_page_without_one_is_stale(tmp_path):
    for source in manual_pages.sources():
        (tmp_path / source).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / source).write_text((ROOT / source).read_text("utf-8"), "utf-8")
    (tmp_path / "resources" / "manual").mkdir(parents=True)
    assert len(manual_pages.write(tmp_path)) == len(manual_pages.sources())
    assert manual_pages.stale(tmp_path) == []
    guide = tmp_path / "docs" / "user-guide" / "polygon.md"
    guide.write_text(guide.read_text("utf-8").replace("## Plots", "## Graphs"), "utf-8")
    (tmp_path / "resources" / "manual" / "old.html").write_text("<html></html>", "utf-8")
    assert manual_pages.stale(tmp_path) == ["resources/manual/polygon.html",
                                            "resources/manual/old.html"]
    assert manual_pages.write(tmp_path) == [PurePosixPath("resources/manual/polygon.html")]
    assert "<h2 id=\"graphs\">Graphs</h2>" in (
        tmp_path / "resources" / "manual" / "polygon.html").read_text("utf-8")


@pytest.mark.parametrize(("english", "chinese"), PAIRS, ids=[zh for _, zh in PAIRS])
def test_the_chinese_page_is_the_whole_english_one(english, chinese):
    """Not a shorter version: the same sections, the same number of list items and every
    figure of the English page (numbers, with their decimals) in the Chinese one."""
    en, zh = (ROOT / english).read_text("utf-8"), (ROOT / chinese).read_text("utf-8")
    name = chinese

    def headings(text):
        return [len(h) for h in re.findall(r"^(#+) ", text, flags=re.MULTILINE)]

    def items(text):
        return len(re.findall(r"^\s*[*-] ", text, flags=re.MULTILINE))

    assert headings(zh) == headings(en), f"{name}: not the English sections"
    assert items(zh) == items(en), f"{name}: not the English list items"
    figures = Counter(re.findall(r"\d+(?:[.,]\d+)?", re.sub(r"\(\.\./[^)]*\)", "", en)))
    missing = sorted(set(figures) - set(re.findall(r"\d+(?:[.,]\d+)?", zh)))
    assert not missing, f"{name} lacks the figures {missing}"


def test_the_translated_references_are_pages_of_the_chinese_manual():
    """Each translated reference is made into its Chinese page, which links to its English
    twin (and back), and no Chinese page sends the reader to the English page of one."""
    sources = manual_pages.sources()
    for name in TRANSLATED_REFERENCES:
        stem = name.removesuffix(".md")
        assert sources[PurePosixPath("docs/zh_CN") / name] == (f"{stem}.zh_CN.html", "zh_CN")
        assert f'href="{stem}.html">English' in (MANUAL / f"{stem}.zh_CN.html").read_text("utf-8")
        assert f'href="{stem}.zh_CN.html">中文' in (MANUAL / f"{stem}.html").read_text("utf-8")
    translated = {p.name.replace(".zh_CN.html", ".html") for p in MANUAL.glob("*.zh_CN.html")}
    assert {"capture.html", "certificates-and-register.html", "index.html"} <= translated
    for page in MANUAL.glob("*.zh_CN.html"):
        own_twin = page.name.replace(".zh_CN.html", ".html")
        english = {t.partition("#")[0] for t in _targets(page)} & translated - {own_twin}
        assert not english, f"{page.name} links to the English {sorted(english)}: link the Chinese"
    for page in sorted(ZH.glob("*.md")):
        assert "（英文）" not in "".join(
            line for line in page.read_text("utf-8").splitlines()
            if "capture.md" in line or "certificates-and-register.md" in line), page.name


@pytest.mark.parametrize("source", list(manual_pages.sources()), ids=str)
def test_no_markdown_shows_as_text(source):
    """Emphasis the Markdown reader did not take (in Chinese, ``**录入。**输入`` stays as
    asterisks: a closing ``**`` after punctuation needs a space or punctuation after it) would
    show its asterisks in the window."""
    import html

    body = manual_pages.render(source).split("<body>", 1)[1]
    body = re.sub(r"<(code|pre)>.*?</\1>", "", body, flags=re.DOTALL)
    text = html.unescape(re.sub(r"<[^>]+>", "", body))
    stray = [text[max(0, m.start() - 20):m.end() + 10] for m in re.finditer(r"\*", text)]
    assert not stray, f"{source}: Markdown shown as text: {stray}"


def _targets(page: Path):
    text = page.read_text("utf-8")
    return re.findall(r'(?:href|src)="([^"]+)"', text)


@pytest.mark.parametrize("page", sorted(MANUAL.glob("*.html")), ids=lambda p: p.name)
def test_every_link_and_picture_of_a_page_is_there(page):
    """Where QTextBrowser goes from this page: a page of the manual and an anchor in it, or
    a screenshot beside the manual; a web address opens outside."""
    for target in _targets(page):
        if re.match(r"[a-z]+:", target):
            continue
        file, _, fragment = target.partition("#")
        linked = (page.parent / file).resolve() if file else page
        assert linked.is_file(), f"{page.name}: {target}: no such file"
        if fragment:
            assert f'id="{fragment}"' in linked.read_text("utf-8"), (
                f"{page.name}: {target}: no such heading")


def test_each_page_links_back_to_its_index_and_its_other_language():
    for page in MANUAL.glob("*.html"):
        text = page.read_text("utf-8")
        index = "index.zh_CN.html" if page.name.endswith(".zh_CN.html") else "index.html"
        if page.name != index:
            assert f'href="{index}"' in text, f"{page.name}: no way back to {index}"
    for name in GUIDES:
        stem = name.removesuffix(".md")
        assert f'href="{stem}.zh_CN.html">中文' in (MANUAL / f"{stem}.html").read_text("utf-8")
        assert f'href="{stem}.html">English' in (MANUAL / f"{stem}.zh_CN.html").read_text("utf-8")


def test_an_installed_package_holds_every_page_and_picture_the_manual_shows():
    """pyproject.toml's package data of ``resources`` covers every file the manual's pages
    are and link to, so F1 works from a wheel, not only from the repository."""
    tomllib = pytest.importorskip("tomllib")  # Python 3.11 on
    config = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))
    patterns = config["tool"]["setuptools"]["package-data"]["resources"]
    needed = {p.relative_to(ROOT / "resources").as_posix() for p in MANUAL.glob("*.html")}
    for page in MANUAL.glob("*.html"):
        needed |= {(page.parent / t.partition("#")[0]).resolve().relative_to(
            ROOT / "resources").as_posix() for t in _targets(page)
            if not re.match(r"[a-z]+:", t) and t.partition("#")[0]}
    assert any("screenshots/" in n for n in needed)  # the pictures are among them
    for name in needed:
        assert any(fnmatch.fnmatch(name, p) for p in patterns), (
            f"resources/{name} is shown by the manual but not in the package data")


def test_a_line_break_between_chinese_characters_joins_them(tmp_path):
    """Chinese has no spaces between words: a Markdown line broken mid-sentence is joined in
    the window; between English words, or Chinese and English, it stays a space."""
    source = PurePosixPath("docs/zh_CN/user-guide/test.md")
    (tmp_path / source).parent.mkdir(parents=True)
    (tmp_path / source).write_text("# 标题\n\n示值误差按设置\n以角秒表示，see the\nguide 与\nISO 230-2。\n",
                                   "utf-8")
    page = manual_pages.render(source, tmp_path)
    assert "示值误差按设置以角秒表示，see the\nguide 与\nISO 230-2。" in page
