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
"""

from __future__ import annotations

import os
import platform
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


def _header() -> list[str]:
    packages = ["numpy", "scipy", "PySide6-Essentials", "pyqtgraph", "fpdf2", "pyswarms"]
    return [
        "# Benchmarks",
        "",
        "Written by `make bench` (tests/benchmarks). Timings: median (p25–p75) of repeated "
        "runs; ratios are of medians.",
        "",
        f"Machine: {_cpu()}, {os.cpu_count()} logical CPUs, {platform.system()} "
        f"{platform.release()}; Python {platform.python_version()}; "
        + ", ".join(f"{p} {_version(p)}" for p in packages) + ".",
        f"Run: {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}.",
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
    headlines = [f"* {_HEADLINES[key]}" for key in sorted(_HEADLINES)]
    head = ["## Headlines", "", *headlines, ""] if headlines else []
    text = "\n".join(_header() + head + [line for key in sorted(_SECTIONS) for line in
                                         _SECTIONS[key] + [""]])
    write_text_atomic(REPORT, text + _notes())
    if headlines:
        _update_readme(headlines)


def _notes() -> str:
    """The hand-written notes block of the BENCHMARKS.md there is, with its markers ("" if none)."""
    old = REPORT.read_text(encoding="utf-8") if REPORT.exists() else ""
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
