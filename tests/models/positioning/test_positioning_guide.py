"""The positioning workbench guides the capture (day review 74 F6): the next target with the
run and approach direction of its row, however the direction is written; a target without
a run is said alone; with none the operator is asked to move and type one."""

from __future__ import annotations

import pytest

from models.registry import KINDS
from models.workbench import GuidesAcquisition

GUIDE = KINDS["positioning"]


def test_positioning_guides_the_capture():
    assert isinstance(GUIDE, GuidesAcquisition)


@pytest.mark.parametrize("current, settings, said", [
    ({"target": "15", "run": "2", "direction": "+"}, {"target_unit": "deg"},
     "target 15°, run 2 ↑"),
    ({"target": "30", "run": "1", "direction": "−"}, {"target_unit": "deg"},
     "target 30°, run 1 ↓"),
    ({"target": "30", "run": "1", "direction": "down"}, {}, "target 30°, run 1 ↓"),
    ({"target": "120.5", "run": "3", "direction": "↑"}, {"target_unit": "mm"},
     "target 120.5 mm, run 3 ↑"),
    ({"target": "45"}, {"target_unit": "deg"}, "target 45°"),
    ({"target": ""}, {}, "move the axis to the next target and type it in the target column"),
    ({"target": "x"}, {}, "move the axis to the next target and type it in the target column"),
])
def test_the_guidance_names_the_rows_target(current, settings, said):
    step = GUIDE.acquisition_guide([], current, settings)
    assert str(step.text) == said
    assert (step.reading, step.of, step.fill, step.nominal) == (1, 1, {}, {})
