"""What the ``anglebench`` commands share: the language they speak and a parser that
refuses a command line in one line.

The language is ``--language`` when it is given, otherwise the system's (the first of
``LANGUAGE``, ``LC_ALL``, ``LC_MESSAGES``, ``LANG`` that is set, as gettext reads them):
any Chinese locale speaks Simplified Chinese, as the window does; anything else English.
JSON, CSV and the files written keep their keys whatever the language.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import re
import sys
import unicodedata
from collections.abc import Callable, Iterator, Mapping

from models.messages import QT_TR_NOOP, translator
from models.readings.sheet import one_line

__all__ = ["EXIT_BAD_INPUT", "LANGUAGE_CHOICES", "HelpFormatter", "Parser",
           "add_language_option", "display_width", "language_asked", "say", "speaking",
           "system_language", "wrapped"]

EXIT_BAD_INPUT = 2
#: ``system`` follows the environment's locale
LANGUAGE_CHOICES = ("system", "en", "zh_CN")

#: argparse's own words (its help's headings and its refusals of a command line), for the
#: translators: argparse looks them up through gettext; ``speaking`` hands them to our
#: catalogue instead
ARGPARSE_WORDS = (
    QT_TR_NOOP("usage: "),
    QT_TR_NOOP("positional arguments"),
    QT_TR_NOOP("options"),
    QT_TR_NOOP("show this help message and exit"),
    QT_TR_NOOP("the following arguments are required: %s"),
    QT_TR_NOOP("unrecognized arguments: %s"),
    QT_TR_NOOP("argument %(argument_name)s: %(message)s"),
    QT_TR_NOOP("invalid choice: %(value)r (choose from %(choices)s)"),
    QT_TR_NOOP("invalid %(type)s value: %(value)r"),
    QT_TR_NOOP("expected one argument"),
    QT_TR_NOOP("expected at most one argument"),
    QT_TR_NOOP("expected at least one argument"),
    QT_TR_NOOP("ambiguous option: %(option)s could match %(matches)s"),
    QT_TR_NOOP("ignored explicit argument %r"),
    QT_TR_NOOP("not allowed with argument %s"),
    QT_TR_NOOP("one of the arguments %s is required"),
    QT_TR_NOOP("unknown parser %(parser_name)r (choices: %(choices)s)"),
)


def system_language(environ: Mapping[str, str] | None = None) -> str:
    """``zh_CN`` when the environment's locale is Chinese, else ``en``."""
    environ = os.environ if environ is None else environ
    for name in ("LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"):
        value = environ.get(name, "").split(":")[0]
        if value:
            return "zh_CN" if value.lower().startswith("zh") else "en"
    return "en"


def language_asked(argv: list[str]) -> str:
    """The language a command line asks for (``--language``), or the system's. Read before
    argparse parses: its own words must already be in that language."""
    given = next((argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--language"),
                 next((a.split("=", 1)[1] for a in argv if a.startswith("--language=")),
                      "system"))
    return given if given in ("en", "zh_CN") else system_language()


@contextlib.contextmanager
def speaking(language: str) -> Iterator[Callable[[str], str]]:
    """argparse's headings and refusals in ``language`` while the parser is built and
    parses; yields the translator of our own texts."""
    words = translator(language)
    if language == "en":
        yield words
        return
    saved = argparse._, argparse.ngettext
    argparse._ = words
    argparse.ngettext = lambda one, many, n: words(one if n == 1 else many)
    try:
        yield words
    finally:
        argparse._, argparse.ngettext = saved


def say(text: str) -> None:
    """One line on stderr, whatever the text holds."""
    sys.stderr.write(one_line(text, 1000) + "\n")


def display_width(text: str) -> int:
    """Columns ``text`` takes on a terminal: a CJK (wide) character two."""
    return sum(2 if unicodedata.east_asian_width(ch) in "WF" else 1 for ch in text)


_WIDE = "\u2e80-\u9fff\uf900-\ufaff\uff00-\uffef"


def wrapped(text: str, width: int) -> list[str]:
    """``text`` in lines of at most ``width`` terminal columns (textwrap counts a character
    as one column: Chinese help ran to twice the terminal's width). Broken at spaces;
    Chinese prose (more Chinese characters than spaces) also between its characters, as
    Chinese allows, never inside a run of Latin letters."""
    text = " ".join(text.split())
    chinese = len(re.findall(f"[{_WIDE}]", text)) > text.count(" ")
    pattern = rf"\s+|[{_WIDE}]|[^\s{_WIDE}]+" if chinese else r"\s+|\S+"
    lines: list[str] = []
    line = ""
    for token in re.findall(pattern, text):
        if display_width(line + token) <= width or not line.strip():
            line += token
            continue
        lines.append(line.rstrip())
        line = token.lstrip()
    if line.strip():
        lines.append(line.rstrip())
    return lines


class HelpFormatter(argparse.HelpFormatter):
    """argparse's help, wrapped by terminal columns (see :func:`wrapped`)."""

    def _split_lines(self, text: str, width: int) -> list[str]:
        return wrapped(text, width)

    def _format_usage(self, usage, actions, groups, prefix) -> str:
        # argparse indents the usage's next lines by len(prefix): "用法：" is 3 characters
        # but 6 columns. Laid out under a stand-in of the prefix's width, then swapped.
        prefix = argparse._("usage: ") if prefix is None else prefix
        stand_in = "u" * display_width(prefix)
        text = super()._format_usage(usage, actions, groups, stand_in)
        return prefix + text[len(stand_in):]

    def _fill_text(self, text: str, width: int, indent: str) -> str:
        return "\n".join(indent + line for line in wrapped(text, width - len(indent)))


class Parser(argparse.ArgumentParser):
    """Refuses a command line with one line on stderr and exit status 2 (no usage dump);
    its help wrapped by terminal columns."""

    def __init__(self, *args, **kwargs) -> None:
        kwargs.setdefault("formatter_class", HelpFormatter)
        super().__init__(*args, **kwargs)

    def error(self, message: str):
        say(f"{self.prog}: {message}")
        raise SystemExit(EXIT_BAD_INPUT)


def add_language_option(parser: argparse.ArgumentParser, words: Callable[[str], str],
                        subcommand: bool = False) -> None:
    """``--language``; on a ``subcommand`` too, where a user puts it last (its value is read
    by :func:`language_asked` in any case; the subcommand does not override the command's)."""
    parser.add_argument("--language", choices=LANGUAGE_CHOICES,
                        default=argparse.SUPPRESS if subcommand else "system",
                        help=words(QT_TR_NOOP(
                            "language of what the command prints (zh_CN: Simplified Chinese; "
                            "system, the default: the system's locale); JSON, CSV and the "
                            "files written keep their English keys")))
