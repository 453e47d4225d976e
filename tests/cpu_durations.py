"""``pytest -p tests.cpu_durations``: the tests that took the most CPU time (#44).

On the shared 2-core machine a test's wall time says more about the load than about the
test; its CPU time (user + system of the test process and of the programs it started and
waited for, setup and teardown included) does not. With this plugin the run ends with the
``CPU_DURATIONS`` (default 30) tests of most CPU time and the sum over all tests; it works
with pytest-xdist's workers too. A module- or session-scoped fixture's cost falls on the
first test that asks for it.

    .venv/bin/python -m pytest -p tests.cpu_durations -p no:randomly tests/app/writers
"""

from __future__ import annotations

import os
import resource

import pytest

_SPENT = pytest.StashKey[float]()
_TAKEN: dict[str, float] = {}


def _cpu() -> float:
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def _counted(item: pytest.Item):
    start = _cpu()
    yield
    item.stash[_SPENT] = item.stash.get(_SPENT, 0.0) + _cpu() - start


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    yield from _counted(item)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item):
    yield from _counted(item)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_teardown(item):
    yield from _counted(item)
    item.user_properties.append(("cpu_s", item.stash.get(_SPENT, 0.0)))  # on its report


def pytest_runtest_logreport(report):
    if report.when == "teardown":  # in the process that reports (xdist: the controller)
        spent = dict(report.user_properties).get("cpu_s")
        if spent is not None:
            _TAKEN[report.nodeid] = spent


def pytest_terminal_summary(terminalreporter):
    if not _TAKEN:
        return
    shown = int(os.environ.get("CPU_DURATIONS", "30"))
    write = terminalreporter.write_line
    terminalreporter.section(f"the {min(shown, len(_TAKEN))} tests of most CPU time")
    for nodeid, spent in sorted(_TAKEN.items(), key=lambda kv: -kv[1])[:shown]:
        write(f"{spent:8.2f} s  {nodeid}")
    write(f"{sum(_TAKEN.values()):8.1f} s of CPU in {len(_TAKEN)} tests (start-up and "
          "collection not included)")
