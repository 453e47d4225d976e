"""Validation cases: designs the readings cannot determine are refused or withheld, naming
why (issue 39). Each case simulates the degenerate design from first principles (the rigs of
this package) and runs it through the whole analysis:

* a polygon whose vertical readings are all equal (true tilt 300″): the tilt is not
  identified (ψ = 0 is no finding), U is withheld until a σ of a reading is stated, and with
  it and the tilt bound U covers the truth;
* a polygon of 3 faces: the tilt fit has no degrees of freedom, said so (not "vertical
  readings missing"), and the same;
* a fringe record shorter than one period, and harmonic orders that alias at the samples per
  period: refused, naming the share and the pair;
* harmonics with the phase estimated from the signals: no interval of the decided quantity,
  no U per sample, no statement of conformity (the round part of their distortion is not
  observable);
* a theodolite run of 3 points: no degrees of freedom for its reading noise, refused.
"""

from __future__ import annotations

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.certificate.withheld import UncertaintyWithheld
from models.fringe.analysis import FRINGE
from models.messages import QT_TR_NOOP, Message, message
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ParsedReadings, ReadingsSheet
from models.theodolite.model import analyze_run
from models.validation.cases import EXACT_SIMULATION, ValidationCase
from models.validation.fringe_rig import FringeHead, equal_steps
from models.validation.polygon_rig import PolygonRig
from models.validation.theodolite_rig import theodolite_readings

__all__ = ["degenerate_design_cases"]

SIGMA = 0.03  # the simulated autocollimator's noise, arcsec


def _polygon_rows(faces: int, seed: int, flat: bool) -> tuple[list[list[str]], np.ndarray]:
    rng = np.random.default_rng(seed)
    th = np.radians(np.arange(faces) * 360.0 / faces)
    error = rng.uniform(0.1, 0.4) * np.cos(th + rng.uniform(0.0, 6.3)) + 0.05 * np.sin(2 * th)
    rig = PolygonRig(faces, error, psi_arcsec=300.0, omega_deg=float(rng.uniform(0.0, 360.0)),
                     noise_arcsec=SIGMA, rng=rng)
    rows = rig.set_rows()
    if flat:  # the vertical column copied down, not read
        rows = [[*r[:4], "12.5", *r[5:]] for r in rows]
    return rows, rig.truth_arcsec()


def _polygon(rows, **settings):
    return POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), {"grade": 3, **settings})


def _refused(workbench: str, name: str, expected: str, run) -> ValidationCase:
    """A case passes when ``run`` raises ValueError whose message holds ``expected``."""
    try:
        run()
    except ValueError as exc:
        said = exc.args[0] if exc.args else str(exc)  # a Message: the report translates it
        return ValidationCase(workbench, name, EXACT_SIMULATION,
                              message(QT_TR_NOOP("refused: “{words}”"), words=Message(expected)),
                              said, expected in str(said))
    return ValidationCase(workbench, name, EXACT_SIMULATION,
                          message(QT_TR_NOOP("refused: “{words}”"), words=Message(expected)),
                          QT_TR_NOOP("accepted"), False)


def _polygon_cases(runs: int) -> list[ValidationCase]:
    w = POLYGON.title
    cases = []
    for faces, flat, name, words in (
            (12, True, QT_TR_NOOP("12 faces, every vertical reading equal (true tilt 300″): "
                                  "tilt not identified, U withheld without a stated σ"),
             QT_TR_NOOP("no variation")),
            (3, False, QT_TR_NOOP("3 faces (true tilt 300″): the tilt fit has no degrees of "
                                  "freedom, U withheld without a stated σ"),
             QT_TR_NOOP("no degrees of freedom"))):
        rows, _ = _polygon_rows(faces, 7, flat)
        result = _polygon(rows)
        reason = result.sets[0].tilt_not_identified
        try:
            polygon_budget(result, CertificateMetadata())
            withheld = ""
        except UncertaintyWithheld as exc:
            withheld = str(exc)
        passed = (result.sets[0].tilt is None and words in reason
                  and "no degrees of freedom" in withheld)
        cases.append(ValidationCase(
            w, name, EXACT_SIMULATION,
            message(QT_TR_NOOP("ψ not reported; the reason says “{words}”; U withheld"),
                    words=Message(words)),
            message(QT_TR_NOOP("ψ {psi}; U {u}"),
                    psi=Message(QT_TR_NOOP("not reported")) if result.sets[0].tilt is None
                    else f"{result.sets[0].tilt.psi_arcsec:.1f}\"",
                    u=Message(QT_TR_NOOP("withheld") if withheld else QT_TR_NOOP("given"))),
            passed))
        inside = total = 0
        for seed in range(runs):
            rows, truth = _polygon_rows(faces, 1000 + seed, flat)
            result = _polygon(rows, reading_noise_arcsec=SIGMA)
            big_u = polygon_budget(result, CertificateMetadata(),
                                   {"reading_noise_arcsec": SIGMA}).expanded
            miss = np.abs(result.mean_corrected_arcsec - truth)
            inside += int(np.sum(miss[1:] <= big_u[1:]))  # face 1: the zero, 0 by definition
            total += faces - 1
        share = inside / total
        cases.append(ValidationCase(
            w, message(QT_TR_NOOP("{faces} faces, tilt not identified, σ stated: U with the "
                                  "tilt bound 300″ covers the truth ({runs} runs, random "
                                  "direction)"), faces=faces, runs=runs),
            EXACT_SIMULATION,
            QT_TR_NOOP("≥ 95 % of the points (the bound's worst direction, rectangular: on "
                       "the safe side)"),
            f"{100 * share:.1f} %", share >= 0.95))
    return cases


def _fringe_parsed(count: int, per_period: int) -> ParsedReadings:
    head = FringeHead(sin_harmonics={3: (0.012, 0.3), 5: (0.004, 1.0)},
                      cos_harmonics={3: (0.009, -0.2)}, noise_v=0.001)
    u_sin, u_cos = head.channels(equal_steps(count, per_period), np.random.default_rng(3))
    return ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                           "theta_deg": np.full(count, np.nan)}, np.arange(count))


def _estimated_phase_case() -> ValidationCase:
    """Harmonics of 0.3-0.4 % of the amplitude with the phase estimated from the signals:
    the part of their distortion that leaves the Lissajous figure round is not observable,
    so no interval of the decided quantity, no U per sample and no statement of conformity,
    however the phase reference's u is stated."""
    head = FringeHead(sin_harmonics={3: (0.004, 0.4), 5: (0.003, 1.3)},
                      cos_harmonics={3: (0.004, 1.97), 5: (0.003, 2.87)}, noise_v=0.0003)
    u_sin, u_cos = head.channels(equal_steps(16 * 128, 128) + 0.7, np.random.default_rng(11))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(u_sin.size, np.nan)}, np.arange(u_sin.size))
    result = FRINGE.analyze(parsed, {"phase_reference_u": 0.2})
    conformity = FRINGE.certificate(
        result, CertificateMetadata(tolerance=2.0, tolerance_unit="arcsec")).conformity
    try:
        FRINGE.uncertainty_budgets(result, CertificateMetadata())
        withheld = ""
    except ValueError as exc:
        withheld = str(exc)
    interval = np.isfinite(conformity.interval_low) and np.isfinite(conformity.interval_high)
    passed = (conformity.verdict == "not assessed" and not interval
              and "estimated from the signals" in withheld
              and "estimated from the signals" in str(conformity.reason))
    return ValidationCase(
        FRINGE.title, QT_TR_NOOP("phase estimated from the signals, 3rd and 5th harmonics of "
                                 "0.3–0.4 %, a phase reference u of 0.2° stated"),
        EXACT_SIMULATION,
        QT_TR_NOOP("no interval of the decided quantity, no U per sample, no statement of "
                   "conformity; the reason names the estimated phase"),
        message(QT_TR_NOOP("interval {interval}; statement {verdict}; U per sample {u}"),
                interval=Message(QT_TR_NOOP("given") if interval else QT_TR_NOOP("withheld")),
                verdict=Message(QT_TR_NOOP("none") if conformity.verdict == "not assessed"
                                else QT_TR_NOOP("made")),
                u=Message(QT_TR_NOOP("withheld") if withheld else QT_TR_NOOP("given"))),
        passed)


def degenerate_design_cases(trials: int) -> list[ValidationCase]:
    """The degenerate designs of issue 39; ``trials`` sets the polygon's coverage runs."""
    runs = max(10, min(50, trials // 4))
    cases = _polygon_cases(runs)
    w = FRINGE.title
    cases.append(_refused(
        w, QT_TR_NOOP("40 of the 64 samples of one period"), QT_TR_NOOP("covers 62.5 % of one period"),
        lambda: FRINGE.analyze(_fringe_parsed(40, 64), {"samples_per_period": 64})))
    cases.append(_refused(
        w, QT_TR_NOOP("N = 8 samples per period, orders 1, 3, 5 (the 5th aliases onto the 3rd)"),
        QT_TR_NOOP("orders 3 and 5 alias at N = 8"),
        lambda: FRINGE.analyze(_fringe_parsed(80, 8), {"samples_per_period": 8})))
    cases.append(_estimated_phase_case())
    theta = np.array([-10.0, 0.0, 10.0])
    azimuth, elevation = theodolite_readings(theta, 3.0, 45.0, 2.0)
    from models.theodolite.analysis import THEODOLITE

    cases.append(_refused(
        THEODOLITE.title, QT_TR_NOOP("3 points: ψ, α, β leave no degrees of freedom for the "
                                     "reading noise"), QT_TR_NOOP("at least 4"),
        lambda: analyze_run(theta, azimuth, elevation, reference_index=1)))
    return cases
