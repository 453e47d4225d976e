"""Benchmarks: `make bench` runs them, prints one report and writes it to BENCHMARKS.md.

Each benchmark adds a section through the ``report`` fixture; the file is
written once at the end of the session, headed by the machine and versions.
Timings are given as the median and the interquartile range (p25–p75) of
repeated runs, and compared as ratios of medians.

A benchmark may also give a one-line ``headline``: the headlines open
BENCHMARKS.md and replace the block between the ``bench:headlines`` markers of
docs/benchmarks.md, so the docs' figures are those of the last run, never copied by
hand (tests/test_readme_benchmarks.py checks that the two agree).

The block between the ``notes`` markers at the end of BENCHMARKS.md is written by hand
(why a constant or a design is as it is, with the measurement that decided it): a run
keeps it as it is.

A run of some of the benchmarks (``pytest tests/benchmarks/test_cli_startup.py -o
addopts=""``) replaces their sections and headlines and keeps the others': each section is
written after a hidden ``<!-- bench:section KEY run=… -->`` line that says which run wrote
it and whether it has a headline, and the header's "Run" line gives each run's date.
"""

from __future__ import annotations

import os
import platform
import re
import time
from importlib import metadata
from pathlib import Path

import pytest

from models.project.atomic_write import write_text_atomic

ROOT = Path(__file__).resolve().parents[2]
REPORT = ROOT / "BENCHMARKS.md"
HEADLINES_DOC = ROOT / "docs" / "benchmarks.md"  # (#44: was the README's)
BEGIN, END = "<!-- bench:headlines begin -->", "<!-- bench:headlines end -->"
NOTES_BEGIN, NOTES_END = "<!-- notes begin", "<!-- notes end -->"
SECTION = re.compile(r"^<!-- bench:section (\S+) run=(.+?)( headline)? -->$")
_SECTIONS: dict[str, list[str]] = {}
_HEADLINES: dict[str, str] = {}


def _cpu() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def _version(dist: str) -> str:
    try:
        return metadata.version(dist)
    except metadata.PackageNotFoundError:
        return "not installed"


def _header(runs: dict[str, str], earlier: str) -> list[str]:
    """The title, the machine and versions, and when each section was run (``runs``: a
    section's key → its run's date); ``earlier``: the machine line of the file there was,
    kept beside this run's when sections of earlier runs are kept and it differs."""
    packages = ["numpy", "scipy", "PySide6-Essentials", "pyqtgraph", "fpdf2", "pyswarms"]
    dates = sorted(set(runs.values()), reverse=True)
    if len(dates) == 1:
        when = f"Run: {dates[0]}."
    else:
        when = "Runs: " + "; ".join(
            f"{date} ({', '.join(key for key in sorted(runs) if runs[key] == date)})"
            for date in dates) + "."
    machine = (f"Machine: {_cpu()}, {os.cpu_count()} logical CPUs, {platform.system()} "
               f"{platform.release()}; Python {platform.python_version()}; "
               + ", ".join(f"{p} {_version(p)}" for p in packages) + ".")
    kept = []
    if len(dates) > 1 and earlier.startswith("Machine: ") and earlier != machine:
        kept = [f"Earlier runs' machine: {earlier.removeprefix('Machine: ')}"]
        machine = f"This run's machine: {machine.removeprefix('Machine: ')}"
    return [
        "# Benchmarks",
        "",
        "Written by `make bench` (tests/benchmarks). Timings: median (p25–p75) of repeated "
        "runs; ratios are of medians.",
        "",
        machine,
        *kept,
        when,
        "",
    ]


@pytest.fixture(scope="session")
def report():
    """``report(key, lines, headline=None)``: a section of the report (sections are
    sorted by key) and, optionally, its one-line headline."""

    def add(key: str, lines: list[str], headline: str | None = None) -> None:
        _SECTIONS[key] = lines
        if headline:
            _HEADLINES[key] = headline
        print("\n" + "\n".join(lines))  # noqa: T201 - the benchmark's own output

    return add


def pytest_sessionfinish(session, exitstatus):
    if not _SECTIONS:
        return
    old = REPORT.read_text(encoding="utf-8") if REPORT.exists() else ""
    sections, headlines, runs = _earlier_sections(old)
    now = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    for key, lines in _SECTIONS.items():
        sections[key] = lines
        runs[key] = now
        headlines.pop(key, None)
        if key in _HEADLINES:
            headlines[key] = _HEADLINES[key]
    bullets = [f"* {headlines[key]}" for key in sorted(headlines)]
    head = ["## Headlines", "", *bullets, ""] if bullets else []
    body = []
    for key in sorted(sections):
        flag = " headline" if key in headlines else ""
        body += [f"<!-- bench:section {key} run={runs[key]}{flag} -->", *sections[key], ""]
    earlier = next((line for line in old.splitlines() if line.startswith(("Machine: ",
                                                                         "Earlier runs'"))), "")
    earlier = "Machine: " + earlier.split(": ", 1)[1] if earlier else ""
    write_text_atomic(REPORT, "\n".join(_header(runs, earlier) + head + body) + _notes(old))
    if bullets:
        _update_readme(bullets)


def _earlier_sections(old: str) -> tuple[dict[str, list[str]], dict[str, str], dict[str, str]]:
    """The sections of the BENCHMARKS.md there was (key → lines), their headlines (key →
    text) and their runs' dates (key → date), read back from the section markers; a
    section's headline is the one at its place among the headlines, in the order of the
    keys. Nothing is kept from a file without markers or whose headlines do not match them."""
    lines = old.splitlines()
    notes = [i for i, line in enumerate(lines) if line.startswith(NOTES_BEGIN)]
    lines = lines[:notes[0]] if notes else lines
    sections: dict[str, list[str]] = {}
    runs: dict[str, str] = {}
    with_headline = []
    key = None
    for line in lines:
        found = SECTION.match(line)
        if found:
            key = found.group(1)
            sections[key], runs[key] = [], found.group(2)
            if found.group(3):
                with_headline.append(key)
        elif key is not None:
            sections[key].append(line)
    for kept in sections.values():  # the blank line written after each section
        while kept and not kept[-1].strip():
            kept.pop()
    bullets = []
    if "## Headlines" in lines:
        for line in lines[lines.index("## Headlines") + 1:]:
            if line.startswith(("## ", "<!-- bench:section")):
                break
            if line.startswith("* "):
                bullets.append(line[2:])
    if len(bullets) != len(with_headline):
        return {}, {}, {}
    return sections, dict(zip(sorted(with_headline), bullets, strict=True)), runs


def _notes(old: str) -> str:
    """The hand-written notes block of the BENCHMARKS.md there was (``old``), with its
    markers ("" if none)."""
    start, end = old.find(NOTES_BEGIN), old.find(NOTES_END)
    return "\n" + old[start:end + len(NOTES_END)] + "\n" if 0 <= start < end else ""


def _update_readme(headlines: list[str]) -> None:
    """Put the headlines between docs/benchmarks.md's markers (left alone if they are
    missing)."""
    text = HEADLINES_DOC.read_text(encoding="utf-8")
    start, end = text.find(BEGIN), text.find(END)
    if start < 0 or end < start:
        print(f"\ndocs/benchmarks.md has no {BEGIN} … {END} block; headlines not copied")  # noqa: T201
        return
    block = "\n".join([BEGIN, *headlines, END])
    write_text_atomic(HEADLINES_DOC, text[:start] + block + text[end + len(END):])
