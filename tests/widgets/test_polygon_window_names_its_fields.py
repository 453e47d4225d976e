"""The polygon's warnings and verdicts name a certificate field or a setting as the window
labels it, not by its key (gui78, live78: "Unless the certificate details state the item's
resolution (item_resolution) …" and "(reading_noise_arcsec; on the command line
--reading-noise-arcsec)" were shown to the technician, in both languages). The command
line and the files keep their names: the English text of the message is as it was."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.slow  # a window

#: one set of 6 faces with the encoder set to each face's nominal angle: the step within
#: its display is in no scatter the readings show
ROWS = [[str(face), f"{(face - 1) * 60.0:.4f}", "0", f"{x:.2f}", f"{y:.2f}"]
        for face, x, y in ((1, 0.5, 0.2), (2, 1.1, 0.4), (3, 0.2, 0.1), (4, -0.4, 0.3),
                           (5, 0.9, 0.2), (6, 0.3, 0.5), (1, 0.52, 0.21))]


def test_the_resolution_warning_names_the_details_field_as_the_window_labels_it(window,
                                                                                 qtbot):
    presenter = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    keys = [c.key for c in presenter.sheet.columns]
    rows = [dict(zip(("position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec",
                      "ac_y_arcsec"), r, strict=True)) for r in ROWS]
    presenter.table_model.replace_all([[r.get(k, "") for k in keys] for r in rows], "typed")
    qtbot.waitUntil(lambda: not presenter.analysis_pending and presenter.result is not None,
                    timeout=10000)
    shown = " ".join(presenter.view.warnings.text().split())
    assert ("Unless the certificate details state the item's resolution (“Resolution” under "
            "“Item under test”), it is named as not stated") in shown, shown
    assert "item_resolution" not in shown, shown
    # the command line and the files: the same message in its English text, the key named
    said = [w for w in presenter.result.warnings if "nominal angle" in w]
    assert said and "the item's resolution (item_resolution), it is named" in said[0], said
