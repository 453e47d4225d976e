"""The polygon's figures that are printed as measured but with no coverage interval, and
why: the reversal B (ISO 230-2, largest |x̄↑ − x̄↓|) with its mean B̄, and the 1st and 2nd
harmonics' amplitudes (day review 66 F4: they were printed as results, with no U, although
with one set per direction B cannot be told from the zero drift carried between the sets:
0.112″ in the sample's budget against reversals of 0.08–0.32″).

Each is marked "no coverage interval: …" with its reason in the statistics table (and so
the DCC) and stated in the JSON as {value, interval_low: null, interval_high: null,
coverage_probability: null} beside the reason, as the ISO 230-2 figures' JSON states a figure
the readings do not bound."""

from __future__ import annotations

from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, message, separated
from models.polygon.model import PolygonResult

__all__ = ["HARMONICS_NO_INTERVAL", "ISO230_NO_INTERVAL", "REVERSAL_CONFOUNDED",
           "REVERSAL_NOT_EVALUATED",
           "harmonics_reason", "indicative_figures_json", "no_interval", "reversal_figures",
           "reversal_reason"]

#: one set in each direction: each direction's mean is one set, whose offset from the common
#: zero is the zero drift it carries (and its reading noise): a difference of the two
#: directions holds that drift whole, and nothing in the readings tells it from a reversal
REVERSAL_CONFOUNDED = QT_TR_NOOP(
    "one set per direction: the reversal cannot be told from the zero drift carried between "
    "the sets and their reading noise; indicative, not a calibration result")
#: sets repeated in a direction: the drift carried and the noise could be told apart, but this
#: version evaluates no uncertainty of the reversal
REVERSAL_NOT_EVALUATED = QT_TR_NOOP(
    "the uncertainty of the reversal (the zero drift carried between the sets and their "
    "reading noise enter it) is not evaluated; indicative, not a calibration result")
#: an amplitude √(a² + b²) of noisy Fourier coefficients is biased high, as a range is: pure
#: noise of σ per position gives σ·√(π/n) on average over n positions
HARMONICS_NO_INTERVAL = QT_TR_NOOP(
    "an amplitude is biased high by the readings' noise, as a range is, and its uncertainty "
    "is not evaluated; indicative, not a calibration result")

#: the JSON's ``iso230_arcsec`` (E, M, R, A, B … of the sets, taken as ISO 230-2 runs): plain
#: numbers, no interval (audit 68 finding 4: a lab's system could not tell them from
#: calibrated figures); the reason beside them, ``iso230_arcsec_reason``
ISO230_NO_INTERVAL = QT_TR_NOOP(
    "indicative: no coverage interval evaluated; the ISO 230-2 figures of the sets (not "
    "printed on the certificate) are as computed from the readings, each a largest value or "
    "a range over the faces, biased high by the readings' noise; the calibration results are "
    "the face deviations with their U")


def reversal_reason(result: PolygonResult) -> str | None:
    """Why the reversal has no coverage interval (None: no reversal, one direction run)."""
    if result.reversal_arcsec is None:
        return None
    directions = np.array([s.direction for s in result.sets])
    once = min(int(np.sum(directions > 0)), int(np.sum(directions < 0))) == 1
    return REVERSAL_CONFOUNDED if once else REVERSAL_NOT_EVALUATED


def harmonics_reason(result: PolygonResult) -> str | None:
    """Why the 1st and 2nd harmonics have no coverage interval (None: fewer than 4 faces, no
    2nd harmonic printed)."""
    return HARMONICS_NO_INTERVAL if result.harmonics.amplitude.size > 2 else None


def reversal_figures(result: PolygonResult) -> dict[str, float]:
    """B and B̄ of ISO 230-2 (deviation x = reference − indicated: B̄ the mean of ē↓ − ē↑ of
    the errors); {} when one direction only was run."""
    if result.reversal_arcsec is None or result.mean_reversal_arcsec is None:
        return {}
    return {"B": float(np.max(np.abs(result.reversal_arcsec))),
            "B_mean": -result.mean_reversal_arcsec}


def no_interval(note: Any, reason: str) -> Any:
    """A statistics row's note with "no coverage interval: ``reason``" after it."""
    return separated((note, message(QT_TR_NOOP("no coverage interval: {reason}"),
                                    reason=message(reason))))


def indicative_figures_json(result: PolygonResult) -> dict[str, Any]:
    """The JSON's objects of the figures printed without an interval, each with its reason:
    ``reversal_figures`` (B, B_mean) and ``harmonic_figures`` (first, second; amplitudes),
    nulls and no key where the run gives no such figure."""
    from models.uncertainty.figure_intervals import figure_objects  # scipy: --json only

    out: dict[str, Any] = {}
    reversal = reversal_reason(result)
    if reversal is not None:
        out["reversal_figures"] = figure_objects(("B", "B_mean"), reversal_figures(result), {})
        out["reversal_figures_reason"] = message(reversal)
    harmonics = harmonics_reason(result)
    if harmonics is not None:
        amplitude = result.harmonics.amplitude
        out["harmonic_figures"] = figure_objects(
            ("first", "second"), {"first": amplitude[1], "second": amplitude[2]}, {})
        out["harmonic_figures_reason"] = message(harmonics)
    return out
