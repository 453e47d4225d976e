"""Start-up of the command line (#44): ``anglebench analyze theodolite <sample>`` (and the
polygon's) against ``python -c "import numpy"`` on the same machine, whole processes timed
from outside — start-up, imports, reading, analysis and summary included. The two commands
run in turn (A B A B …) after a warm-up of each, and the ratio is taken pair by pair, so a
drift of the machine's speed during the run moves both; the median of the pairs is quoted,
in wall and in CPU time (user + system, the kernel's accounting of the finished child).
Target: within 1.5× numpy's import. What a plain analyze may import is a unit test
(tests/app/test_cli_imports.py)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from models.registry import KINDS

ROOT = Path(__file__).resolve().parents[2]
PAIRS = 15
WARMUP = 2
TARGET = 1.5


def _command(kind: str) -> list[str]:
    """The command as a user types it (the installed console script), on the sample."""
    script = Path(sys.executable).with_name("anglebench")
    start = [str(script)] if script.exists() else [shutil.which("anglebench") or "anglebench"]
    return [*start, "analyze", kind, str(ROOT / "resources" / "samples" / KINDS[kind].sample_file)]


def _whole_process(argv: list[str], env: dict[str, str]) -> tuple[float, float]:
    """(wall, cpu) seconds of one run of ``argv``, its output thrown away."""
    t0 = time.perf_counter()
    child = subprocess.Popen(argv, cwd=ROOT, env=env, stdin=subprocess.DEVNULL,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - t0
    child.returncode = os.waitstatus_to_exitcode(status)
    err = child.stderr.read().decode(errors="replace")
    child.stderr.close()
    assert child.returncode == 0, f"{argv}: exit {child.returncode}: {err}"
    return wall, usage.ru_utime + usage.ru_stime


def _paired(a: list[str], b: list[str], env: dict[str, str]) -> dict[str, np.ndarray]:
    for _ in range(WARMUP):
        _whole_process(a, env)
        _whole_process(b, env)
    runs = np.array([[*_whole_process(a, env), *_whole_process(b, env)] for _ in range(PAIRS)])
    return {"a_wall": runs[:, 0], "a_cpu": runs[:, 1], "b_wall": runs[:, 2], "b_cpu": runs[:, 3],
            "wall": runs[:, 0] / runs[:, 2], "cpu": runs[:, 1] / runs[:, 3]}


def test_cli_startup_against_importing_numpy(tmp_path, report):
    # as a user's Python runs: it keeps the modules it compiled (__pycache__). With
    # PYTHONDONTWRITEBYTECODE set (as on this workplace's machines) every run compiled every
    # module of the package again while numpy's came compiled from its wheel: 1.72× where
    # the same commands with their caches measure 1.2× in CPU (2026-12-02)
    env = {**{k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"},
           "ANGLEBENCH_REGISTER": str(tmp_path / "register.sqlite")}
    numpy_import = [sys.executable, "-c", "import numpy"]
    load_before = os.getloadavg()[0]
    results = {kind: _paired(_command(kind), numpy_import, env) for kind in ("theodolite", "polygon")}
    load_after = os.getloadavg()[0]

    def mark(ratio: float) -> str:
        return "met" if ratio <= TARGET else "**missed**"

    def ms(values: np.ndarray) -> str:
        return (f"{np.median(values) * 1e3:.0f} ms ({np.percentile(values, 25) * 1e3:.0f}–"
                f"{np.percentile(values, 75) * 1e3:.0f})")

    rows = []
    for kind, r in results.items():
        rows.append(f"| `anglebench analyze {kind}` on its sample | {ms(r['a_wall'])} | "
                    f"{ms(r['a_cpu'])} | {np.median(r['wall']):.2f}× | "
                    f"{np.median(r['cpu']):.2f}× | {mark(np.median(r['wall']))} |")
    both = np.concatenate([r["b_wall"] for r in results.values()])
    both_cpu = np.concatenate([r["b_cpu"] for r in results.values()])
    theodolite = results["theodolite"]
    ratio, ratio_cpu = np.median(theodolite["wall"]), np.median(theodolite["cpu"])
    polygon = np.median(results["polygon"]["wall"])
    report("6-cli-startup", [
        "## Command line start-up (whole process)",
        "",
        f"Each command on the bundled sample against `python -c \"import numpy\"`, run in turn "
        f"(A B A B …), {WARMUP} warm-up runs each, {PAIRS} pairs; the ratio is taken pair by "
        "pair (median). Wall: from the start of the process to its exit; CPU: user + system "
        f"of the finished child. Target: ≤ {TARGET}× numpy's import. Load average (1 min) "
        f"{load_before:.1f} before, {load_after:.1f} after (on a shared machine the ratio "
        "holds better than either time).",
        "",
        "| command | wall | CPU | ratio (wall) | ratio (CPU) | target |",
        "|---|---|---|---|---|---|",
        *rows,
        f"| `python -c \"import numpy\"` | {ms(both)} | {ms(both_cpu)} | 1 | 1 | |",
        "",
        "A plain analyze imports the named workbench's models only (models/registry.py loads a "
        "workbench when it is first asked for; the command line is read with its options "
        "alone unless it names another's): no Qt, scipy, SQLAlchemy, fpdf2, openpyxl or lxml "
        "(tests/app/test_cli_imports.py).",
    ], headline=(
        f"Start-up: `anglebench analyze theodolite` on its sample takes {ratio:.2f}× the time "
        f"of `python -c \"import numpy\"` ({ratio_cpu:.2f}× its CPU time), {mark(ratio)}; "
        f"the polygon's {polygon:.2f}×, {mark(polygon)} (target {TARGET}×)."))
    assert ratio < 3 * TARGET  # a regression guard; the target is reported above
