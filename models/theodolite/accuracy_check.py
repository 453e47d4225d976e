"""The theodolite accuracy setting against the u its certificate's budget uses.

The setting (1σ of a reading) gates the fit's residuals as the readings are analysed; a
certificate's budget takes a reading's u from the stated standards instead (the
autocollimating theodolite listed with its calibration certificate,
models.theodolite.report.stated_reading_uncertainty). Where both are given and differ,
one instrument had two u on one certificate and the residual check was judged on the one
the budget does not use (assessment 70 M10: a setting of 0.2″ beside a stated u of 0.5″).
A certificate judges the residuals again on the stated u and says that the setting was not
used.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from models.messages import QT_TR_NOOP, message
from models.theodolite.model import RESIDUAL_ABOVE_ACCURACY, RESIDUAL_WARNED

#: the residuals judged on the stated standards' u, which the budget uses
RESIDUAL_ABOVE_STATED_U = QT_TR_NOOP(
    "Residual RMS {rms} is more than three times the stated standards' u = {u} per reading, "
    "which the uncertainty budget uses: check the readings and the set-up.")
#: the setting differs from the u the budget uses: which one the certificate rests on
ACCURACY_NOT_USED = QT_TR_NOOP(
    "The theodolite accuracy setting {setting} (1σ) differs from the stated standards' u = "
    "{u} per reading: the uncertainty budget and the check of the fit's residuals use {u}, "
    "the setting is not used for these results.")
#: a setting within this share of the stated u is the same figure, rounded
SAME_FIGURE = 0.01


def certificate_warnings(warnings: Sequence[str], residual_rms_arcsec: float,
                         stated_u_arcsec: float,
                         settings: Mapping[str, Any] | None) -> list[str]:
    """The analysis' ``warnings`` as a certificate states them: where standards state a u
    per reading (``stated_u_arcsec`` > 0, arcsec), the residual check judged on it in place
    of the accuracy setting, and a note where the setting (when ``settings`` list it)
    differs from it by more than :data:`SAME_FIGURE`; as they are where no standard states
    a u (the budget then takes the readings' scatter, and the setting gates them)."""
    if not stated_u_arcsec > 0.0:
        return list(warnings)
    kept = [w for w in warnings if getattr(w, "template", None) != RESIDUAL_ABOVE_ACCURACY]
    u = f"{stated_u_arcsec:.2g}\""
    if residual_rms_arcsec > RESIDUAL_WARNED * stated_u_arcsec:
        kept.append(message(RESIDUAL_ABOVE_STATED_U, rms=f"{residual_rms_arcsec:.2f}\"", u=u))
    setting = float((settings or {}).get("accuracy_arcsec") or 0.0)
    if setting > 0.0 and not math.isclose(setting, stated_u_arcsec, rel_tol=SAME_FIGURE):
        kept.append(message(ACCURACY_NOT_USED, setting=f"{setting:g}\"", u=u))
    return kept
