"""Settings and certificate fields that verdicts and warnings name, each as the command line
and the files name it (its key and option) and as the window labels it (the set-up's field,
the certificate details' field): :class:`models.messages.Named`. gui78 (live78): the window
showed "(item_resolution)" and "reading_noise_arcsec, --reading-noise-arcsec" to the
technician, in both languages, where the form says "Resolution" and "σ of a reading, when
not evaluated". The window's words follow its labels (models/polygon/analysis.py
PARAMETERS, widgets/certificate_dialog.py _TEXT_FIELDS)."""

from __future__ import annotations

from models.messages import QT_TR_NOOP, Named

__all__ = ["DRIFT_BOUND_SETTING", "ITEM_RESOLUTION_FIELD", "READING_NOISE_IN_SETTINGS"]

#: the item's indication resolution (certificate details ``item_resolution``)
ITEM_RESOLUTION_FIELD = Named(
    QT_TR_NOOP("the item's resolution (item_resolution)"),
    QT_TR_NOOP("the item's resolution (“Resolution” under “Item under test”)"))

#: the polygon's σ of a reading, where it is stated (setting ``reading_noise_arcsec``)
READING_NOISE_IN_SETTINGS = Named(
    QT_TR_NOOP("in the settings (reading_noise_arcsec; on the command line "
               "--reading-noise-arcsec)"),
    QT_TR_NOOP("in the set-up (“σ of a reading, when not evaluated”)"))

#: the cross-calibration's largest drift over a mounting (setting ``drift_bound_arcsec``)
DRIFT_BOUND_SETTING = Named(
    QT_TR_NOOP("(the setting \"largest autocollimator drift over a mounting\"; "
               "--drift-bound-arcsec, drift_bound_arcsec in the metadata)"),
    QT_TR_NOOP("(“largest autocollimator drift over a mounting, when not measured” in the "
               "set-up)"))
