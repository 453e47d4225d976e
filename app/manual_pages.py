"""The window's manual (F1) generated from the Markdown of docs/: ``make docs``
(``python -m app.manual_pages``).

One source: the user guides are written once, in docs/, and the window shows exactly them.

* ``docs/user-guide/<name>.md`` → ``resources/manual/<name>.html`` (English; ``index.md`` is
  the manual's contents page, ``window.md`` what every workbench shares);
* ``docs/zh_CN/user-guide/<name>.md`` → ``resources/manual/<name>.zh_CN.html`` (Chinese);
* the references a guide links to (``docs/capture.md``, ``docs/certificates-and-register.md``,
  ``docs/command-line.md``, ``docs/benchmarks.md``) → ``resources/manual/<name>.html``, and
  those translated (``docs/zh_CN/<name>.md``: capture and certificates-and-register, what a
  technician needs in the window) → ``resources/manual/<name>.zh_CN.html``. The command-line
  reference stays English: most of it is the ``--help`` of every command, generated from the
  code in English (app/docs_tables.py), and the benchmarks are for developers.

Why HTML generated into resources/manual/ rather than Qt reading the Markdown: the pages
ship inside the ``resources`` package (found from an installed package, not only from the
repository), every link between pages and to a heading (``#conformity``) works in Qt's
QTextBrowser (its Markdown reader gives headings no anchors), tables get their rules and
screenshots a width that fits the window, and a link to something the manual does not hold
(a test, the developer guide) becomes plain text instead of a dead link. The generated
pages are checked against their source by ``tests/app/test_manual_pages.py`` (stale: run
``make docs``); ``python -m app.manual_pages --check`` says the same and writes nothing.
markdown-it-py renders; it is needed only here (``make docs``, ``make new-workbench``), so
it is declared with the development extras, not at run time.
"""

from __future__ import annotations

import argparse
import os
import struct
import sys
import unicodedata
from html import escape
from pathlib import Path, PurePosixPath
from urllib.parse import unquote

ROOT = Path(__file__).resolve().parents[1]
MANUAL = PurePosixPath("resources/manual")
SCREENSHOTS = PurePosixPath("resources/screenshots")
GUIDES = {"en": PurePosixPath("docs/user-guide"), "zh_CN": PurePosixPath("docs/zh_CN/user-guide")}
#: the references the user guides link to (``docs/<name>.md``); one translated into a
#: language is in that language's folder (``docs/zh_CN/<name>.md``) and linked from its guides
REFERENCES = ("capture", "certificates-and-register", "command-line", "benchmarks")
REFERENCE_FOLDERS = {"en": PurePosixPath("docs"), "zh_CN": PurePosixPath("docs/zh_CN")}
#: the widest a screenshot is drawn in the manual's window (pixels)
IMAGE_WIDTH = 640
_BACK = {"en": "Manual", "zh_CN": "手册"}
_OTHER = {"en": ("zh_CN", "中文"), "zh_CN": ("en", "English")}
_STYLE = ("h1 { font-size: x-large; } h2 { margin-top: 14px; } "
          "th { background-color: #eeeeee; } code { font-family: monospace; }")


def html_name(name: str, language: str) -> str:
    return f"{name}.html" if language == "en" else f"{name}.{language}.html"


def sources(root: Path = ROOT) -> dict[PurePosixPath, tuple[str, str]]:
    """Every Markdown page the manual is made of: {its path under root: (html name, language)}."""
    out: dict[PurePosixPath, tuple[str, str]] = {}
    for language, folder in GUIDES.items():
        for path in sorted((root / folder).glob("*.md")):
            out[folder / path.name] = (html_name(path.stem, language), language)
    for language, folder in REFERENCE_FOLDERS.items():
        for name in REFERENCES:
            if (root / folder / f"{name}.md").is_file():
                out[folder / f"{name}.md"] = (html_name(name, language), language)
    return out


def twin(source: PurePosixPath, language: str) -> PurePosixPath:
    """The same page in the other language (a guide's or a reference's); it may not exist."""
    other = _OTHER[language][0]
    for folders in (GUIDES, REFERENCE_FOLDERS):
        if source.parent == folders[language]:
            return folders[other] / source.name
    return source


def anchor(heading: str) -> str:
    """A heading's anchor as GitHub makes it (so one link works on GitHub and in the window):
    lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower().replace("`", "")
    kept = "".join(ch for ch in text if ch in " -_" or unicodedata.category(ch)[0] in "LN")
    return kept.replace(" ", "-")


def _png_width(path: Path) -> int | None:
    try:
        head = path.read_bytes()[:24]
    except OSError:
        return None
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return int(struct.unpack(">I", head[16:20])[0])


def _wide(ch: str) -> bool:
    return bool(ch) and unicodedata.east_asian_width(ch) in "WF"


def _join_wide_lines(children) -> None:
    """A line break inside a paragraph between two Chinese characters joins them, as
    Chinese is written (QTextBrowser would show it as a space in mid-sentence)."""
    for i, child in enumerate(children):
        if child.type != "softbreak" or not 0 < i < len(children) - 1:
            continue
        before, after = children[i - 1].content, children[i + 1].content
        if children[i - 1].type == "text" and children[i + 1].type == "text" and \
                _wide(before[-1:]) and _wide(after[:1]):
            child.type, child.tag, child.nesting, child.content = "text", "", 0, ""


def _markdown():
    from markdown_it import MarkdownIt

    return MarkdownIt("commonmark", {"html": True}).enable(["table", "strikethrough"])


def render(source: PurePosixPath, root: Path = ROOT) -> str:
    """The manual page of the Markdown file ``source`` (a path under ``root``)."""
    pages = sources(root)
    name, language = pages.get(source, (html_name(source.stem, "en"), "en"))
    text = (root / source).read_text(encoding="utf-8")
    md = _markdown()
    tokens = md.parse(text)

    def target(href: str) -> str | None:
        """Where a link of the page goes in the manual (None: nowhere, shown as text)."""
        if "://" in href or href.startswith("mailto:"):
            return href
        file, _, fragment = href.partition("#")
        fragment = unquote(fragment)  # markdown-it escapes it; the heading's id is not escaped
        if not file:
            return f"#{fragment}"
        resolved = PurePosixPath(os.path.normpath((source.parent / file).as_posix()))
        if resolved in pages:
            page = pages[resolved][0]
        elif resolved.parent == MANUAL:
            page = resolved.name
        elif resolved.parent == SCREENSHOTS:
            page = f"../screenshots/{resolved.name}"
        else:
            return None
        return page + (f"#{fragment}" if fragment else "")

    title = ""
    seen: dict[str, int] = {}
    for i, token in enumerate(tokens):
        if token.type == "heading_open":
            words = tokens[i + 1].content
            title = title or (words if token.tag == "h1" else "")
            slug = anchor(words)
            count = seen.get(slug, 0)
            seen[slug] = count + 1
            token.attrSet("id", slug if not count else f"{slug}-{count}")
        elif token.type == "table_open":
            for key, value in (("border", "1"), ("cellspacing", "0"), ("cellpadding", "4")):
                token.attrSet(key, value)
        for child in token.children or ():
            if child.type == "link_open":
                href = target(str(child.attrGet("href") or ""))
                if href is None:
                    child.type, child.tag, child.nesting = "text", "", 0
                    child.meta["dropped"] = True
                else:
                    child.attrSet("href", href)
            elif child.type == "image":
                src = target(str(child.attrGet("src") or ""))
                child.attrSet("src", src or "")
                width = _png_width(root / SCREENSHOTS / PurePosixPath(src or "").name)
                if width:
                    child.attrSet("width", str(min(width, IMAGE_WIDTH)))
        if token.children:
            _join_wide_lines(token.children)
        if token.children:  # the closing tag of a link shown as text goes too
            depth: list[bool] = []
            for child in token.children:
                if child.type == "link_open":
                    depth.append(False)
                elif child.type == "text" and child.meta.get("dropped"):
                    depth.append(True)
                elif child.type == "link_close" and depth and depth.pop():
                    child.type, child.tag, child.nesting = "text", "", 0
    body = md.renderer.render(tokens, md.options, {})
    nav = []
    if source.stem != "index" or source.parent != GUIDES[language]:
        nav.append(f'<a href="{html_name("index", language)}">{_BACK[language]}</a>')
    other_page = twin(source, language)
    if other_page != source and other_page in pages:
        nav.append(f'<a href="{pages[other_page][0]}">{_OTHER[language][1]}</a>')
    head = (f'<html><head><meta charset="utf-8"><title>{escape(title)}</title>'
            f"<style>{_STYLE}</style></head><body>\n"
            f"<!-- generated from {source} by `make docs` (app/manual_pages.py): edit that -->\n")
    return head + (f"<p>{' · '.join(nav)}</p>\n" if nav else "") + body + "</body></html>\n"


def generated(root: Path = ROOT) -> dict[PurePosixPath, str]:
    """Every manual page as its source makes it now: {path under root: html}."""
    return {MANUAL / name: render(source, root) for source, (name, _) in sources(root).items()}


def stale(root: Path = ROOT) -> list[str]:
    """The manual's pages that differ from their source (or are missing), and the pages of
    resources/manual that no source makes."""
    pages = generated(root)
    out = [str(path) for path, text in pages.items()
           if not (root / path).is_file() or (root / path).read_text(encoding="utf-8") != text]
    out += [str(MANUAL / p.name) for p in sorted((root / MANUAL).glob("*.html"))
            if MANUAL / p.name not in pages]
    return out


def write(root: Path = ROOT, only: set[PurePosixPath] | None = None) -> list[PurePosixPath]:
    """Writes the pages that changed (of ``only``'s sources, when given); the pages written."""
    from models.project.atomic_write import write_text_atomic

    written = []
    for source, (name, _) in sources(root).items():
        if only is not None and source not in only:
            continue
        path = MANUAL / name
        text = render(source, root)
        if not (root / path).is_file() or (root / path).read_text(encoding="utf-8") != text:
            write_text_atomic(root / path, text)
            written.append(path)
    return written


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m app.manual_pages",
                                description=__doc__.splitlines()[0])
    p.add_argument("--check", action="store_true",
                   help="write nothing; exit 1 naming the manual's pages that are stale")
    args = p.parse_args(argv)
    if args.check:
        old = stale()
        for path in old:
            print(f"{path}: stale or made by no source in docs/; run `make docs`")  # noqa: T201
        return 1 if old else 0
    for path in write():
        print(f"{path}: written")  # noqa: T201
    return 0


if __name__ == "__main__":
    sys.exit(main())
