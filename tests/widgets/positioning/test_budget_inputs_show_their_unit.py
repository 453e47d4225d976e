"""Leftovers 79, item 2: the positioning set-up's Type B inputs of the budget (misalignment u,
reference resolution, temperature u) are in the deviations' unit, and their fields showed
no unit beside the set-up's "axis temperature 20.0 °C" and "expansion coefficient … µm/(m·K)".
Each shows it, as those do, following the deviation unit chosen, in both languages."""

from __future__ import annotations

import pytest

from widgets.positioning.presenter import PositioningPresenter

#: the laboratory's CMC is in the deviations' unit too (leftovers 80: its field was bare)
KEYS = ("misalignment_u", "reference_resolution", "temperature_u", "cmc")


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_budget_inputs_show_the_deviations_unit(qtbot, language):
    from widgets.i18n import install_language

    install_language(language)
    try:
        presenter = PositioningPresenter()
        qtbot.addWidget(presenter.view)
        form = presenter.view.settings
        # as the neighbours show theirs
        assert form.field("axis_temperature_c").suffix() == " °C"
        assert [form.field(k).suffix() for k in KEYS] == ['"'] * 4
        form.field("misalignment_u").setValue(0.3)
        assert form.field("misalignment_u").text() == '0.3000"'
        # the unit chosen in the set-up (a settings edit, as the form's own)
        presenter.set_settings({**presenter.settings, "deviation_unit": "urad"})
        assert [form.field(k).suffix() for k in KEYS] == [" µrad"] * 4
        form.field("deviation_unit").setCurrentIndex(
            form.field("deviation_unit").findData("um"))
        presenter.settings_edited()
        assert presenter.settings["deviation_unit"] == "um"
        assert [form.field(k).suffix() for k in KEYS] == [" µm"] * 4
        # undone, the unit goes back with it
        presenter.undo_stack.undo()
        assert [form.field(k).suffix() for k in KEYS] == [" µrad"] * 4
        # "not stated" at 0 stays as it is (a special value text has no suffix)
        assert form.field("temperature_u").value() == 0
        assert form.field("temperature_u").text() != ""
        # the other fields keep theirs
        assert form.field("axis_temperature_c").suffix() == " °C"
    finally:
        install_language("en")


def test_the_compensation_step_shows_the_targets_unit(qtbot):
    """The compensation table's step is in the targets' unit (leftovers 80: its field was
    bare): ° on a rotary axis, mm on a linear one, following the target unit chosen."""
    presenter = PositioningPresenter()
    qtbot.addWidget(presenter.view)
    step = presenter.view.settings.field("compensation_step")
    assert step.suffix() == "°"
    presenter.set_settings({**presenter.settings, "target_unit": "mm", "deviation_unit": "um"})
    assert step.suffix() == " mm"
    presenter.set_settings({**presenter.settings, "target_unit": "deg",
                            "deviation_unit": "arcsec"})
    assert step.suffix() == "°"
