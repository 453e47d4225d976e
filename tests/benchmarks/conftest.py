"""Benchmarks: `make bench` runs them, prints one report and writes it to BENCHMARKS.md.

Each benchmark adds a section through the ``report`` fixture; the file is
written once at the end of the session, headed by the machine and versions.
Timings are given as the median and the interquartile range (p25–p75) of
repeated runs, and compared as ratios of medians.
"""

from __future__ import annotations

import os
import platform
import time
from importlib import metadata
from pathlib import Path

import pytest

REPORT = Path(__file__).resolve().parents[2] / "BENCHMARKS.md"
_SECTIONS: dict[str, list[str]] = {}


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
    """``report(key, lines)``: a section of the report (sections are sorted by key)."""

    def add(key: str, lines: list[str]) -> None:
        _SECTIONS[key] = lines
        print("\n" + "\n".join(lines))  # noqa: T201 - the benchmark's own output

    return add


def pytest_sessionfinish(session, exitstatus):
    if not _SECTIONS:
        return
    text = "\n".join(_header() + [line for key in sorted(_SECTIONS) for line in
                                  _SECTIONS[key] + [""]])
    REPORT.write_text(text, encoding="utf-8")
