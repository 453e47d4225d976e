"""The settings and fields the models' messages name (models/named_settings.py) read in the
window as the window labels them, and on the command line and in the files as before
(gui78, live78: "(item_resolution)", "reading_noise_arcsec; on the command line
--reading-noise-arcsec" were shown to the technician). The window's words quote the labels
the set-up and the certificate details show: a label renamed must be renamed here."""

from __future__ import annotations

import numpy as np

from models.crosscal.analysis import CROSSCAL
from models.messages import in_language, message, rendered, translator
from models.named_settings import DRIFT_BOUND_SETTING, ITEM_RESOLUTION_FIELD, READING_NOISE_IN_SETTINGS
from models.polygon.analysis import POLYGON
from models.polygon.report import ONE_SET_NOISE_NOT_DETERMINED
from widgets.certificate_dialog import _TEXT_FIELDS
from widgets.i18n import translated


def _label(kind, key: str) -> str:
    (parameter,) = [p for p in kind.parameters if p.key == key]
    return parameter.label


def test_the_window_quotes_the_labels_it_shows():
    assert f"“{_label(POLYGON, 'reading_noise_arcsec')}”" in READING_NOISE_IN_SETTINGS.window
    assert f"“{_label(CROSSCAL, 'drift_bound_arcsec')}”" in DRIFT_BOUND_SETTING.window
    assert f"“{_TEXT_FIELDS['item_resolution']}”" in ITEM_RESOLUTION_FIELD.window


def test_the_command_line_keeps_its_names_and_the_window_says_its_labels(qapp):
    said = message(ONE_SET_NOISE_NOT_DETERMINED, where=READING_NOISE_IN_SETTINGS)
    cli = ("State the σ of a reading, encoder and autocollimator together, in the settings "
           "(reading_noise_arcsec; on the command line --reading-noise-arcsec), or measure")
    assert cli in str(said)  # the English text: the command line's, the JSON's, as before
    assert cli in rendered(said, translator("en"))
    assert "--reading-noise-arcsec" in in_language(said, translator("zh_CN"))
    shown = translated(said)
    assert ("State the σ of a reading, encoder and autocollimator together, in the set-up "
            "(“σ of a reading, when not evaluated”), or measure") in shown, shown
    assert "reading_noise_arcsec" not in shown and "--reading" not in shown


def test_the_cross_calibration_s_drift_bound_named_as_the_set_up_labels_it(qapp):
    from tests.crosscal_simulator import Bench
    from tests.widgets.crosscal.test_crosscal_workbench import HARMONICS

    bench = Bench(8, HARMONICS, np.random.default_rng(5).normal(0, 0.4, 8), noise_arcsec=0.02,
                  drift_arcsec=0.2, drift_common=True, rng=np.random.default_rng(6))
    from models.readings.sheet import ReadingsSheet

    sheet = ReadingsSheet(CROSSCAL.columns)
    for r, (j, i, a, x) in enumerate(bench.rows([0, 1, 3], closure=False)):
        for c, text in enumerate((str(j), str(i), f"{a:.9f}", f"{x:.6f}")):
            sheet.set_text(r, c, text)
    result = CROSSCAL.analyze(sheet.parse(), CROSSCAL.default_settings)
    withheld = result.encoder_u_withheld
    assert withheld is not None
    assert ("(the setting \"largest autocollimator drift over a mounting\"; "
            "--drift-bound-arcsec, drift_bound_arcsec in the metadata)") in str(withheld)
    shown = translated(withheld)
    assert ("state the largest drift over a mounting (“largest autocollimator drift over a "
            "mounting, when not measured” in the set-up)") in shown, shown
    assert "drift_bound_arcsec" not in shown and "--drift" not in shown
