"""The documentation's generated tables: ``make docs`` (``python -m app.docs_tables``).

What the code declares is written into the Markdown between markers
``<!-- generated:NAME begin -->`` and ``<!-- generated:NAME end -->``, never copied by hand:

* ``workbenches`` (README.md, docs/README.md): every workbench of ``models.registry`` —
  key, title, method reference, sample, user guide;
* ``settings`` (docs/command-line.md): every setting each workbench declares
  (``models.parameters.Parameter``): its command-line option, label, unit, range or
  choices, default and help;
* ``commands`` (docs/command-line.md): the ``--help`` of every command, in English, at
  100 columns, as ``anglebench … --help`` prints it.

``python -m app.docs_tables --check`` writes nothing and exits 1 naming the stale files;
``tests/app/test_docs_tables.py`` does the same. Only what is between the markers is
replaced; the text around them is the writers'.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import sys
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: the width the commands' help is laid out at (argparse reads $COLUMNS)
HELP_COLUMNS = 100

#: the commands whose help is written, each as its arguments
COMMANDS: tuple[tuple[str, ...], ...] = (
    (), ("analyze",), ("validate",), ("register",), ("capture",), ("simulate",))


def _cell(text: object) -> str:
    """A table cell: one line, its pipes escaped."""
    return " ".join(str(text).split()).replace("|", "\\|")


def _number(value: object) -> str:
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def workbench_table(guide_prefix: str = "docs/user-guide/") -> str:
    """The registry's workbenches as a Markdown table (in the window's tab order)."""
    from models.registry import KINDS

    rows = ["| key | workbench | method (reference) | sample | user guide |",
            "|---|---|---|---|---|"]
    for key, kind in KINDS.items():
        guide = f"[{key}.md]({guide_prefix}{key}.md)"
        rows.append(f"| `{key}` | **{_cell(kind.title)}** | {_cell(kind.method_reference)} | "
                    f"`resources/samples/{kind.sample_file}` | {guide} |")
    return "\n".join(rows)


def _range(parameter) -> str:
    if parameter.choices:
        return ", ".join(f"`{value}` ({_cell(text)})" for value, text in parameter.choices)
    if parameter.kind == "text":
        return "text"
    low = "" if parameter.minimum is None else _number(parameter.minimum)
    high = "" if parameter.maximum is None else _number(parameter.maximum)
    text = f"{low} … {high}" if (low or high) else parameter.kind
    if parameter.zero:
        text += f"; 0: {_cell(parameter.zero)}"
    return text


def settings_tables() -> str:
    """Every workbench's settings as declared (one table each)."""
    from models.registry import KINDS

    out: list[str] = []
    for key, kind in KINDS.items():
        out += [f"#### {_cell(kind.title)} (`{key}`)", "",
                "| option | setting | unit | range or choices | default | help |",
                "|---|---|---|---|---|---|"]
        for p in kind.parameters:
            option = f"`{p.flag}`" if p.cli else "(window and project file only)"
            default = "" if p.default in ("", None) else f"`{_number(p.default)}`"
            out.append(f"| {option} | {_cell(p.label)} (`{p.key}`) | {_cell(p.unit)} | "
                       f"{_range(p)} | {default} | {_cell(p.help)} |")
        out.append("")
    return "\n".join(out).rstrip()


def command_help(argv: tuple[str, ...]) -> str:
    """What ``anglebench ARGV --help --language en`` prints at ``HELP_COLUMNS`` columns."""
    from app.main import main

    saved = os.environ.get("COLUMNS")
    os.environ["COLUMNS"] = str(HELP_COLUMNS)
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
            main([*argv, "--help", "--language", "en"])
    finally:
        if saved is None:
            os.environ.pop("COLUMNS", None)
        else:
            os.environ["COLUMNS"] = saved
    return out.getvalue().rstrip()


def commands_reference() -> str:
    """Every command's help, each under its own heading."""
    out: list[str] = []
    for argv in COMMANDS:
        name = " ".join(("anglebench", *argv))
        out += [f"### `{name}`", "", "```text", command_help(argv), "```", ""]
    return "\n".join(out).rstrip()


#: each file's generated blocks: name → what is written between its markers
BLOCKS: dict[str, dict[str, Callable[[], str]]] = {
    "README.md": {"workbenches": workbench_table},
    "docs/README.md": {"workbenches": lambda: workbench_table("user-guide/")},
    "docs/command-line.md": {"settings": settings_tables, "commands": commands_reference},
}


def markers(name: str) -> tuple[str, str]:
    return f"<!-- generated:{name} begin -->", f"<!-- generated:{name} end -->"


def block(text: str, name: str) -> str:
    """What is between the markers of ``name`` in ``text`` (stripped; ValueError when
    missing)."""
    begin, end = markers(name)
    start, stop = text.find(begin), text.find(end)
    if start < 0 or stop < start:
        raise ValueError(f"no {begin} … {end} block")
    return text[start + len(begin):stop].strip()


def filled(text: str, name: str, content: str, path: str = "") -> str:
    """``text`` with ``content`` between the markers of ``name`` (ValueError when missing)."""
    begin, end = markers(name)
    start, stop = text.find(begin), text.find(end)
    if start < 0 or stop < start:
        raise ValueError(f"{path or 'the text'} has no {begin} … {end} block")
    return text[:start + len(begin)] + "\n" + content + "\n" + text[stop:]


def regenerated(root: Path = ROOT) -> dict[str, tuple[str, str]]:
    """Each file's text now and as generated: {path: (now, generated)}."""
    cache: dict[Callable[[], str], str] = {}
    out = {}
    for path, blocks in BLOCKS.items():
        now = (root / path).read_text(encoding="utf-8")
        text = now
        for name, make in blocks.items():
            if make not in cache:
                cache[make] = make()
            text = filled(text, name, cache[make], path)
        out[path] = (now, text)
    return out


def stale(root: Path = ROOT) -> list[str]:
    """The files whose generated blocks differ from what the code declares now."""
    return [path for path, (now, text) in regenerated(root).items() if now != text]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m app.docs_tables",
                                description=__doc__.splitlines()[0])
    p.add_argument("--check", action="store_true",
                   help="write nothing; exit 1 naming the files whose tables are stale")
    args = p.parse_args(argv)
    files = regenerated()
    if args.check:
        old = [path for path, (now, text) in files.items() if now != text]
        for path in old:
            print(f"{path}: generated tables are stale; run `make docs`")  # noqa: T201
        return 1 if old else 0
    from models.project.atomic_write import write_text_atomic

    for path, (now, text) in files.items():
        if now != text:
            write_text_atomic(ROOT / path, text)
            print(f"{path}: written")  # noqa: T201
    return 0


if __name__ == "__main__":
    sys.exit(main())
