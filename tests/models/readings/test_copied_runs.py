"""A run entered twice under two run numbers is one run, not two repeats (#39: a hostile
tester's copies of a positioning run and of a theodolite pass were analysed as independent
repeats, the scatter understated, nothing said). Refused, naming both runs; runs that read
alike by the rounding's chance, or an axis with no scatter at all, are not called copies.
Records simulated from first principles (numpy, tests/theodolite_passes_simulator.py),
analysed through the command line."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from app.main import main
from models.readings.copied_runs import copied_run
from tests.theodolite_passes_simulator import passes_record

TARGETS = np.arange(0.0, 390.0, 30.0)


def _positioning(path, rng, decimals: int = 3, copy: tuple[int, int] | None = None) -> None:
    runs: dict[tuple[int, str], list[str]] = {}
    for run in range(1, 6):
        for sign, order in (("+", TARGETS), ("-", TARGETS[::-1])):
            runs[(run, sign)] = [
                f"{t:g},{run},{sign},"
                f"{round(np.sin(np.radians(t)) + rng.normal(0.0, 0.3), decimals):.{decimals}f}"
                for t in order]
    if copy is not None:  # run copy[1] typed again from run copy[0]'s sheet
        for sign in "+-":
            runs[(copy[1], sign)] = [r.replace(f",{copy[0]},{sign},", f",{copy[1]},{sign},")
                                     for r in runs[(copy[0], sign)]]
    path.write_text("target,run,direction,deviation\n"
                    + "\n".join(r for rows in runs.values() for r in rows) + "\n")


def test_a_positioning_run_typed_twice_is_refused_naming_both(tmp_path, capsys):
    path = tmp_path / "copied.csv"
    _positioning(path, np.random.default_rng(1), copy=(2, 3))
    assert main(["analyze", "positioning", str(path), "--json"]) == 2
    assert "run 3 (+) repeats run 2 at every target" in capsys.readouterr().err
    _positioning(path, np.random.default_rng(1))
    assert main(["analyze", "positioning", str(path), "--json"]) == 0


def test_a_theodolite_pass_typed_twice_is_refused_but_passes_with_no_scatter_are_not(
        tmp_path, capsys):
    """Pass 2 a copy of pass 1, pass 3 read: refused. Every pass alike (no pointing noise at
    all): not a copy; the workbench withholds what the scatter would determine."""
    record = tmp_path / "passes.csv"
    passes_record(record, np.random.default_rng(3), 3, 0.3, 0.6)
    lines = record.read_text().splitlines()
    header, rows = lines[0], [r.split(",") for r in lines[1:]]
    first = {(r[0], r[4]): r for r in rows if r[3] == "1"}
    rows = [first[(r[0], r[4])][:3] + r[3:] if r[3] == "2" else r for r in rows]
    record.write_text("\n".join([header] + [",".join(r) for r in rows]) + "\n")
    assert main(["analyze", "theodolite", str(record), "--json"]) == 2
    assert "run 2 (+) repeats run 1 at every θ" in capsys.readouterr().err
    passes_record(record, np.random.default_rng(3), 3, 0.0, 0.6)
    assert main(["analyze", "theodolite", str(record), "--json"]) == 0


@settings(max_examples=60, deadline=None)
@given(st.integers(0, 10_000), st.floats(0.2, 2.5))
def test_runs_alike_by_the_rounding_are_never_called_copies(seed, scatter_in_steps):
    """Readings to a step of 1 scattering by up to 2.5 steps (where two runs of 4 points may
    read alike by chance): never a copy; the same runs at 1e-6 steps with one copied are."""
    rng = np.random.default_rng(seed)
    points = np.tile(np.arange(4.0), 6)
    run = np.repeat(np.arange(1, 7), 4)
    direction = np.ones(points.size)
    value = np.round(points + rng.normal(0.0, scatter_in_steps, points.size))
    value[4:8] = value[0:4]  # alike, as rounding may make them
    assert copied_run(run, direction, points, value, 1.0, scatter_in_steps) is None
    fine = points + rng.normal(0.0, 1.0, points.size)
    fine[4:8] = fine[0:4]
    assert copied_run(run, direction, points, fine, 1e-6, 1.0) == (1, 2, 1.0)
