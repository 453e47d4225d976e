"""The positioning table's headers carry the units the set-up gives (live78): "target",
"deviation" and "measured" had none — 2.556 under "deviation" was arcseconds only because
the set-up below the table said so, and the same bare figures mean µm on a linear axis —
while every other workbench's headers carry theirs ("encoder a [deg]", "polygon dev ["])."""

from __future__ import annotations

from PySide6.QtCore import Qt

from widgets.polygon.presenter import PolygonPresenter
from widgets.positioning.presenter import PositioningPresenter


def _headers(presenter) -> list[str]:
    model = presenter.table_model
    return [model.headerData(c, Qt.Orientation.Horizontal)
            for c in range(model.columnCount())]


def test_the_positioning_headers_follow_the_set_up_units(qtbot):
    presenter = PositioningPresenter()
    qtbot.addWidget(presenter.view)
    assert _headers(presenter) == ["target [deg]", "run", "dir [+/−]", "deviation [\"]",
                                   "measured [deg]"]
    changed = []
    presenter.table_model.headerDataChanged.connect(lambda *args: changed.append(args))
    presenter.set_settings({**presenter.settings, "target_unit": "mm", "deviation_unit": "um"})
    assert _headers(presenter) == ["target [mm]", "run", "dir [+/−]", "deviation [µm]",
                                   "measured [mm]"]
    assert changed  # the header repainted
    presenter.set_settings({**presenter.settings, "target_unit": "deg",
                            "deviation_unit": "urad"})
    assert _headers(presenter)[3] == "deviation [µrad]"


def test_a_column_s_own_unit_is_left_as_it_is(qtbot):
    presenter = PolygonPresenter()
    qtbot.addWidget(presenter.view)
    assert _headers(presenter)[:3] == ["pos", "encoder a [deg]", "polygon dev [\"]"]
