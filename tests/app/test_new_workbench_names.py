"""make new-workbench refuses a key another thing already has (#44): a workbench, an
instrument of capture, a command, a folder of models/ or widgets/; nothing is written."""

from __future__ import annotations

import re

import pytest

from app import new_workbench
from app.capture.instruments import INSTRUMENTS
from app.main import COMMANDS
from models.registry import LOCATIONS


def _tree(root):
    return sorted(p.relative_to(root).as_posix() for p in root.rglob("*")
                  if "__pycache__" not in p.parts and ".venv" not in p.parts)


@pytest.mark.parametrize(("key", "what"), [("theodolite", "a workbench"),
                                           ("crosscal", "a workbench"),
                                           ("autocollimator", "an instrument of capture"),
                                           ("signals", "an instrument of capture"),
                                           ("validate", "a command"),
                                           ("register", "a command"),
                                           ("validation", "a module of models/"),
                                           ("pyramidal", "a module of models/"),
                                           ("error_plot", "a module of widgets/")])
def test_a_taken_key_is_refused_and_nothing_written(key, what):
    before = {p: p.read_bytes() for p in (new_workbench.ROOT / "models" / "registry.py",
                                          new_workbench.ROOT / "resources" / "manual" / "index.html")}
    with pytest.raises(SystemExit, match=rf"'{key}' is taken: it is {re.escape(what)}"):
        new_workbench.new_workbench(key, "Title", "标题")
    assert {p: p.read_bytes() for p in before} == before


def test_every_workbench_instrument_and_command_is_taken():
    taken = new_workbench.taken_names()
    assert set(LOCATIONS) | set(INSTRUMENTS) | set(COMMANDS) <= set(taken)
    assert "autocollimator_test" not in taken  # a free key stays free


def test_the_commands_are_those_main_dispatches():
    source = (new_workbench.ROOT / "app" / "main.py").read_text("utf-8")
    assert set(re.findall(r'argv\[0\] == "(\w+)"', source)) == set(COMMANDS)
