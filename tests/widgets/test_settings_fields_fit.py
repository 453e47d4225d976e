"""#41 (technician's review): every set-up field's text in sight at 1280×720 with the capture
panel docked. One long caption set the form's label column and left every field ~110 px: the
polygon's faces field read "rom the readings", its closure limits "0.125, 0.25, 0.5, 1, 2.5"."""

from __future__ import annotations

import pytest

from tests.capture_panel_probe import docked_probed

pytestmark = pytest.mark.slow  # a window in a process of its own, on a screen of 1280×720
# (the capture panel's test's: tests/capture_panel_probe.py docked_probed)



def test_every_settings_field_shows_its_whole_text_at_1280x720_panel_docked(tmp_path_factory):
    found = docked_probed(tmp_path_factory)["fields"]
    assert {f["area"] for f in found} == {"right", "left", "bottom"}
    assert {f["workbench"] for f in found} == {"theodolite", "polygon", "fringe",
                                               "positioning", "crosscal"}
    assert any(f["key"] == "closure_limits_arcsec" and f["text"] for f in found)
    clipped = [f"{f['workbench']} ({f['area']}): {f['key']} '{f['text']}' needs {f['needs']} px,"
               f" has {f['has']} px" for f in found if f["needs"] > f["has"]]
    assert not clipped, "; ".join(clipped)
    assert all(f["window"] <= 1280 for f in found)
