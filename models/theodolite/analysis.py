"""Theodolite run as a workbench: readings columns, settings, JSON and summary."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from models.messages import QT_TR_NOOP, joined, lines, message
from models.parameters import Parameter, SettingsError, Shortcut
from models.readings.incomplete import IncompleteUnit, short_last_unit, subset
from models.readings.repeats import REPEATS_PARAMETER, average_repeats
from models.readings.sheet import Column, ColumnKind, ParsedReadings
from models.theodolite import KEY, MEASURAND_STANDARDS, TITLE
from models.theodolite.acquisition import theodolite_guide
from models.theodolite.model import (
    DEFAULT_TILT_BOUND_ARCSEC,
    MODEL_INPUT,
    TheodoliteResult,
    analyze_run,
)
from models.uncertainty.iso230 import once_note
from models.uncertainty.lab_scope import cmc_parameter
from models.uncertainty.printed_figure import PrintedFigure, printed_range_figures
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import fixed_places, uncertainty_decimals
from models.uncertainty.tilt_bound_words import TILT_BOUND_ZERO
from models.workbench import (
    SIGN_CONVENTION,
    GuidesAcquisition,
    IssuesCertificates,
    OverlaysRuns,
    SendsRuns,
    ShowsHeadline,
    Workbench,
    raw_error_u_note,
)

if TYPE_CHECKING:  # the certificate's modules are loaded when a certificate is asked for
    from models.certificate.document import CertificateDocument
    from models.certificate.metadata import CertificateMetadata
    from models.plots import PlotFigure
    from models.readings.entry_plan import EntryPlan

__all__ = ["THEODOLITE"]

COLUMNS = (
    Column("theta_deg", "θ", "deg", ColumnKind.ANGLE_DEG,
           help="Indicated angle of the axis under test (decimal or D°M'S\")",
           aliases=("theta", "转角", "转台转角", "指示角", "angle")),
    Column("azimuth_deg", "A", "deg", ColumnKind.ANGLE_DEG,
           help="Theodolite horizontal reading after autocollimating on the mirror",
           aliases=("azimuth", "方位角", "水平角", "水平度盘读数", "Hz")),
    Column("elevation_deg", "E / V", "deg", ColumnKind.ANGLE_DEG,
           help="Theodolite vertical reading: elevation (OZ down), or zenith angle V "
                "if chosen in the set-up (E = V − 90°)",
           aliases=("elevation", "E", "V", "俯仰角", "高低角", "竖直角", "天顶距", "zenith")),
    Column("run", "run", "", ColumnKind.INTEGER, required=False,
           help="Pass number when the run was repeated (optional)"),
    Column("direction", "dir", "+/−", ColumnKind.TEXT, required=False, choices=("+", "-"),
           help="Approach direction of the pass: + forward, − backward (optional)"),
)

PARAMETERS = (
    Parameter("reference_row", "reference row", "int", 0, minimum=1, maximum=10_000_000,
              zero="auto (θ nearest 0)",
              help="Row where the theodolite was zeroed on the mirror; 0: the row with θ nearest 0"),
    Parameter("vertical_reading", "vertical reading", "choice", "elevation",
              choices=(("elevation", "elevation E"), ("zenith", "zenith angle V (E = V − 90°)")),
              help="What the theodolite's vertical circle reads; E as in the method's paper (Tian "
                   "et al. 2017), positive below the horizontal (OZ down): elevations read "
                   "positive upward give α + 180° and −β, with the same corrected errors"),
    Parameter("method", "identify from", "choice", "elevation",
              choices=(("elevation", "elevations (recommended)"),
                       ("azimuth", "azimuth errors (absorbs axis error!)")),
              help="The elevations identify the set-up without touching the axis' own error; "
                   "the azimuth route absorbs any part of it that looks like the model"),
    Parameter("psi_max_deg", "bound |ψ| ≤", "float", 45.0, "°", 0.001, 89.0, decimals=1, step=5.0,
              help="Admissible axis tilt: the inversion's other root (ψ near 90°) is rejected"),
    Parameter("beta_max_deg", "bound |β| ≤", "float", 45.0, "°", 0.001, 89.0, decimals=1,
              step=5.0, help="Admissible elevation of the mirror normal"),
    Parameter("accuracy_arcsec", "theodolite accuracy (1σ)", "float", 0.5, "\"", 0.0, 3600.0,
              decimals=2, step=0.1,
              help="The theodolite's standard uncertainty of a reading, as its reference standard "
                   "states it (basis u, the same figure); residuals above 3× it raise a warning; "
                   "beyond 100× it, or beyond 10× it when the set-up model explains less than 99 % "
                   "(R²), the result is refused; 0: no check"),
    Parameter("tilt_bound_arcsec", "largest axis tilt ψ, when not identified", "float",
              DEFAULT_TILT_BOUND_ARCSEC, "\"", 0.0, 3600.0, decimals=1, step=10.0,
              zero=TILT_BOUND_ZERO,
              help="When the elevations cannot identify the tilt (all equal, only 2 distinct "
                   "values, or no degrees of freedom) the set-up's error is not removed: its "
                   "effect for a tilt up to this, in the worst direction, enters the "
                   "uncertainty (rectangular); not used when the tilt is fitted; 0: an axis "
                   "with no tilt at all, which no set-up achieves, refused where the "
                   "elevations cannot identify the tilt"),
    cmc_parameter("cmc_arcsec", "laboratory's CMC (smallest U)", "\"", "the axis error"),
    # its budget counts the means' noise once (#39), unlike the other workbenches' help says
    dataclasses.replace(
        REPEATS_PARAMETER,
        help="n readings taken one after another at each θ point: every n rows are one point, "
             "averaged. The budget's reading error of a point's mean is one input, the larger "
             "of the fit's scatter of the means and √(u_c² + (s/√n)²): the repeats' pooled "
             "s/√n (ν = points · (n − 1)) with u_c = √max(u² − s², 0), the part of the stated "
             "standards' u per reading the repeats do not show to scatter (the instrument's "
             "error at that circle position, the same in every repeat: not divided by √n). "
             "1: every row is a point"),
    Parameter("plan_passes", "entry plan: passes", "int", 0, minimum=1, maximum=100,
              zero="no plan", cli=False,
              help="Passes of the entry plan over the θ steps below: entry fills θ (and run "
                   "and direction with more than one pass) as readings arrive and shows the "
                   "next step. 0: no plan",
              entry_aid=True),
    Parameter("plan_thetas", "entry plan: θ steps", "text", "-20:1:41", cli=False,
              help="The plan's θ: start:step:count (-20:1:41) or a list (-20, -10, 0, 10, 20)",
              entry_aid=True),
)


def _settings(settings: Mapping[str, Any]) -> dict[str, Any]:
    return THEODOLITE.checked_settings(settings)


def elevation_origin(settings: Mapping[str, Any]) -> float:
    """What the analysis adds to the vertical column's readings (deg) to read them as
    elevations E: −90 for zenith angles V (E = V − 90°), 0 for elevations."""
    return -90.0 if settings.get("vertical_reading") == "zenith" else 0.0


def pass_directions(stated: Any) -> np.ndarray | None:
    """Each reading's direction as the analysis takes it where any is stated: −1 for "-",
    +1 for "+" and for a blank cell (forward); None where none is stated (no directions)."""
    if not any(d for d in stated):
        return None
    return np.array([-1.0 if d == "-" else 1.0 for d in stated])


def analyze(parsed: ParsedReadings, settings: Mapping[str, Any]) -> TheodoliteResult:
    s = _settings(settings)
    parsed, repeats = average_repeats(parsed, s["readings_per_point"], Theodolite.point_keys,
                                      ("azimuth_deg", "elevation_deg"),
                                      angles=("azimuth_deg", "elevation_deg"))
    if parsed.n < 4:
        raise ValueError(message(
            QT_TR_NOOP("{n} usable readings; at least 4 are needed"),
            n=parsed.n))
    elevation = parsed["elevation_deg"] + elevation_origin(s)
    reference = int(s["reference_row"])
    reference_index = None
    if reference > 0:
        matches = (np.nonzero(parsed.row_index == reference - 1)[0] if repeats is None else
                   np.nonzero(np.any(repeats.rows == reference - 1, axis=1))[0])
        if matches.size == 0:
            raise SettingsError(message(
                QT_TR_NOOP("reference row {reference} is blank, unreadable or missing"),
                reference=reference))
        reference_index = int(matches[0])
    directions = pass_directions(parsed["direction"])
    result = analyze_run(
        parsed["theta_deg"], parsed["azimuth_deg"], elevation,
        reference_index=reference_index, method=str(s["method"]),
        psi_max_deg=float(s["psi_max_deg"]), beta_max_deg=float(s["beta_max_deg"]),
        accuracy_arcsec=float(s["accuracy_arcsec"]) or None, directions=directions,
        row_numbers=parsed.row_index + 1, tilt_bound_arcsec=float(s["tilt_bound_arcsec"]),
    )
    runs = parsed["run"]
    result.runs = runs.astype(int) if np.all(np.isfinite(runs)) else None
    result.directions = directions
    result.repeats = repeats
    if result.runs is not None and result.iso230 is not None:
        from models.readings.copied_runs import COPIED_PASS, copied_run
        from models.readings.resolution import readings_step
        from models.theodolite.figures import passes_scatter

        copy = copied_run(result.runs, np.ones(result.runs.size) if directions is None
                          else directions, result.theta_deg, result.raw_error_arcsec,
                          readings_step(result.raw_error_arcsec), passes_scatter(result)[0])
        if copy is not None:
            raise ValueError(message(COPIED_PASS, later=copy[1], earlier=copy[0],
                                     direction="+" if copy[2] > 0 else "−"))
    return result


def split_incomplete(parsed: ParsedReadings, settings: Mapping[str, Any]
                     ) -> tuple[ParsedReadings, IncompleteUnit | None]:
    """The complete passes, and the last pass (run column) when it is in progress: its rows
    the last ones, fewer (θ, direction) steps than the passes before it, each once."""
    runs = parsed["run"]
    if parsed.n < 2 or not (np.all(np.isfinite(runs)) and np.all(np.isfinite(parsed["theta_deg"]))):
        return parsed, None
    r = runs.astype(int).tolist()
    steps = list(zip(np.round(parsed["theta_deg"].astype(float), 9).tolist(),
                     [d or "+" for d in parsed["direction"]], strict=True))
    earlier = {steps[i] for i in range(parsed.n) if r[i] != r[-1]}
    rows = short_last_unit(r, steps, earlier)
    if rows is None:
        return parsed, None
    keep = np.ones(parsed.n, dtype=bool)
    keep[rows] = False
    sheet = parsed.row_index.astype(int) + 1
    per_point = int(settings.get("readings_per_point", 1) or 1)
    return subset(parsed, keep), IncompleteUnit(
        "pass", float(r[-1]), int(rows.size) // per_point if per_point > 1 else int(rows.size),
        len(earlier), int(sheet[rows[0]]), int(sheet[rows[-1]]), tuple(int(i) for i in rows))


def positioning_rows(result: TheodoliteResult) -> list[list[str]]:
    """The run as readings of the positioning workbench: target = θ, deviation = −corrected
    error (actual − target is reference − indicated); run and direction as read, else blank
    (the positioning workbench then takes them from the order of θ)."""
    rows = []
    for k, (theta, error) in enumerate(zip(result.theta_deg, result.corrected_error_arcsec,
                                           strict=True)):
        run = "" if result.runs is None else str(result.runs[k])
        direction = "" if result.directions is None else ("+" if result.directions[k] > 0
                                                          else "-")
        rows.append([f"{theta:.6f}", run, direction, f"{-error:.4f}", ""])
    return rows


def to_json(result: TheodoliteResult) -> dict[str, Any]:
    # only the JSON says whose the bound is: a plain summary loads no budget (test_cli_imports)
    from models.uncertainty.tilt_bound_words import tilt_bound_origin

    ident = result.identification
    u = ident.uncertainty_deg
    out: dict[str, Any] = {
        "theta_deg": result.theta_deg.tolist(),
        "raw_error_arcsec": result.raw_error_arcsec.tolist(),
        "model_error_arcsec": result.model_error_arcsec.tolist(),
        "corrected_error_arcsec": result.corrected_error_arcsec.tolist(),
        # null where the elevations do not identify the tilt (tilt_not_identified says why)
        "psi_deg": ident.setup.psi_deg if ident.tilt_identified else None,
        # null where ψ is not told from 0 (models.uncertainty.tilt_direction; a warning says so)
        "alpha_deg": ident.setup.alpha_deg if ident.alpha_determined else None,
        "beta_deg": ident.setup.beta_deg,
        "r_squared": ident.r_squared if ident.tilt_identified else None,
        "psi_u_deg": float(u[0]) if ident.tilt_identified else None,
        "tilt_identified": ident.tilt_identified,
        "tilt_not_identified": ident.tilt_not_identified or None,
        # the tilt bound whose effect enters the uncertainty (null when the tilt is fitted)
        "tilt_bound_arcsec": None if ident.tilt_identified else ident.tilt_bound_arcsec,
        # "stated" by the lab, or "program default" (none stated: audit 73 finding 3)
        "tilt_bound_origin": None if ident.tilt_identified else tilt_bound_origin(
            ident.tilt_bound_arcsec, DEFAULT_TILT_BOUND_ARCSEC),
        "alpha_u_deg": float(u[1]) if ident.alpha_determined else None,
        "beta_u_deg": float(u[2]),
        "residual_rms_arcsec": ident.residual_rms_arcsec,
        "method": ident.method,
        "corrected_stats_arcsec": result.corrected_stats.as_dict(),
        "raw_stats_arcsec": result.raw_stats.as_dict(),
        "sign_convention": SIGN_CONVENTION,
        "warnings": result.warnings,
    }
    if result.iso230 is not None:
        iso = result.iso230
        out["iso230_arcsec"] = iso.figures
        per_point: dict[str, Any] = {"theta_deg": iso.positions.tolist()}
        for name, stats in (("forward", iso.forward), ("backward", iso.backward)):
            if stats is not None:
                per_point[f"{name}_mean"] = stats.mean.tolist()
                per_point[f"{name}_std"] = stats.std.tolist()
        if iso.reversal is not None:
            per_point["reversal"] = iso.reversal.tolist()
        if iso.bidirectional_repeatability is not None:
            per_point["bidirectional_repeatability"] = iso.bidirectional_repeatability.tolist()
        out["iso230_per_point_arcsec"] = per_point
    return out


def _intervals_line(result: TheodoliteResult, printed: Mapping[str, int] | None = None
                    ) -> str:
    """The ISO 230-2 figures' coverage intervals (the stated standards' u not known here:
    the readings alone, at 95.45 %), or why there are none; each to its figure's decimal
    (``printed``: the certificate's, where known)."""
    from models.certificate.metadata import CertificateMetadata
    from models.readings.resolution import readings_step
    from models.theodolite.figures import (
        figure_intervals_withheld,
        figures_scatter,
        least_passes,
        readings_theodolite_figure_intervals,
        theodolite_figure_decimals,
        withheld_theodolite_figure_reasons,
    )
    from models.theodolite.report import theodolite_budget
    from models.uncertainty.budget import DEFAULT_COVERAGE_PROBABILITY
    from models.uncertainty.wide_intervals import wide_intervals_statement
    from models.uncertainty.without_interval_note import figures_without_interval_note

    withheld = figure_intervals_withheld(result)
    if withheld is not None:  # the certificate's note: why, and the place every figure is
        # printed to, the one its readings support (leftovers 80)
        scatter, about_fit = figures_scatter(result)
        return figures_without_interval_note(message(withheld), scatter,
                                             readings_step(result.raw_error_arcsec), '"',
                                             about_fit)
    budget = theodolite_budget(result, CertificateMetadata())
    intervals = readings_theodolite_figure_intervals(result, budget)
    parts: list = [message(QT_TR_NOOP("Coverage intervals ({p} %, from the readings alone; a "
                                      "certificate adds its stated standards' u): "),
                           p=f"{100 * DEFAULT_COVERAGE_PROBABILITY:.2f}")]
    decimals = theodolite_figure_decimals(result, budget, held=False) | dict(printed or {})
    for i, (key, iv) in enumerate(intervals.items()):
        d = decimals.get(key, 2)  # the figure's, as its value is printed
        # each end with its unit: shown in µrad or mdeg, both ends are converted (the low
        # end, bare, stayed in arcseconds beside a converted high end)
        parts += [", " if i else "", f"{key} {fixed_places(iv.low, d)}\" … {fixed_places(iv.high, d)}\""]
        if iv.probability < DEFAULT_COVERAGE_PROBABILITY:
            parts.append(f" ({percent_text(iv.probability)} %)")
    # R, R↑, R↓ of two passes: no interval, and why (audit 68 finding 3)
    for key, reason in withheld_theodolite_figure_reasons(result, budget,
                                                          readings_alone=True).items():
        parts += ["\n", message(QT_TR_NOOP("No coverage interval is given for {figure}: "
                                           "{reason}."), figure=key, reason=reason)]
    # an upper end far above its figure (few passes): why, as the certificate says (F6)
    wide = wide_intervals_statement(result.iso230.figures if result.iso230 else {}, intervals,
                                    least_passes(result), "\"", passes=True, outwards=False)
    if wide is not None:
        parts += ["\n", wide]
    return joined(parts)


def _printed(stats, decimals: int) -> dict[str, PrintedFigure]:
    """{low, high, ptp} of an error curve's statistics as its certificate prints them, each
    rounded from its unrounded value in whichever unit it is read in (assessment 72 L5)."""
    return printed_range_figures(stats.min, stats.max, decimals)


class PrintedDecimals(int):
    """How a theodolite certificate rounds: its decimal for the errors (the int itself) and
    each ISO 230-2 figure's, ``figures`` (its interval's with the stated standards' u and
    the laboratory's CMC), which the window's summary prints its figures to."""

    figures: dict[str, int]

    def __new__(cls, errors: int, figures: Mapping[str, int]) -> PrintedDecimals:
        made = super().__new__(cls, errors)
        made.figures = dict(figures)
        return made


def _standard_u(u_arcsec: float) -> str:
    """A set-up parameter's standard uncertainty u as the summary prints it, to two
    significant digits in whichever angle unit it is read in (converted from its value, not
    from its printed digits: assessment 70 H3)."""
    from models.messages import joined
    from models.uncertainty.printed_figure import printed

    return joined([printed(u_arcsec, "\""), " (u, k = 1)"])


def _to_digit_of(value_deg: float, u_arcsec: float) -> str:
    """A set-up parameter in degrees to the digit of its u's second significant digit
    (GUM 7.2.6; assessment 70 L8: β = -0.0395° beside a u of 0.12″ = 0.00003°), four
    decimals at the least and where u is not a positive number."""
    if not (math.isfinite(u_arcsec) and u_arcsec > 0):
        return f"{value_deg:.4f}"
    return f"{value_deg:.{max(4, uncertainty_decimals(u_arcsec / 3600.0))}f}"


def summary(result: TheodoliteResult, printed: int | None = None) -> str:
    """The result as text; ``printed``: the certificate's decimal for the error ranges and
    the RMS (:meth:`Theodolite.printed_rounding`; None: two), each peak-to-peak as printed,
    and its figures' decimals (:class:`PrintedDecimals`) where it gives them."""
    d = 2 if printed is None else printed
    ident = result.identification
    u = ident.uncertainty_deg * 3600.0
    s, c, r = ident.setup, result.corrected_stats, result.raw_stats
    out: list[str] = [
        message(QT_TR_NOOP("Set-up not identified from the elevation readings ({n} points, "
                           "reference θ = {theta}°): {why}") if not ident.tilt_identified else
                QT_TR_NOOP("Set-up identified from the elevation readings ({n} points, "
                           "reference θ = {theta}°):") if ident.method == "elevation" else
                QT_TR_NOOP("Set-up identified from the azimuth readings ({n} points, "
                           "reference θ = {theta}°):"),
                n=r.n, theta=f"{result.reference_theta_deg:g}", why=ident.tilt_not_identified),
        *((message(QT_TR_NOOP("  axis tilt       ψ = {value}° ± {u}"),
                   value=_to_digit_of(s.psi_deg, u[0]), u=_standard_u(u[0])),
           message(QT_TR_NOOP("  tilt direction  α = {value}° ± {u}"),
                   value=_to_digit_of(s.alpha_deg, u[1]), u=_standard_u(u[1]))
           if ident.alpha_determined else
           message(QT_TR_NOOP("  tilt direction  α not identified (ψ not told from 0)")),
           message(QT_TR_NOOP("  mirror normal   β = {value}° ± {u}"),
                   value=_to_digit_of(s.beta_deg, u[2]), u=_standard_u(u[2])),
           message(QT_TR_NOOP("  R² = {r2}, residual RMS = {rms}"), r2=f"{ident.r_squared:.8f}",
                   rms=f"{ident.residual_rms_arcsec:.3f}\""))
          if ident.tilt_identified else
          (message(QT_TR_NOOP("  axis tilt ψ and direction α not identified: nothing removed; "
                              "a tilt up to {bound} (stated) enters the uncertainty")
                   if ident.tilt_bound_arcsec != DEFAULT_TILT_BOUND_ARCSEC else
                   QT_TR_NOOP("  axis tilt ψ and direction α not identified: nothing removed; "
                              "a tilt up to {bound} (the program's default: no bound was "
                              "stated) enters the uncertainty"),
                   bound=f"{ident.tilt_bound_arcsec:g}\""),
           message(QT_TR_NOOP("  mirror normal   β = {value}° (from the reference reading)"),
                   value=f"{s.beta_deg:.4f}"))),
        message(QT_TR_NOOP("Raw error        {low} … {high} (peak-to-peak {ptp})"),
                **_printed(r, d)),
        message(QT_TR_NOOP("Corrected error  {low} … {high} (peak-to-peak {ptp}, RMS {rms})"),
                **_printed(c, d), rms=PrintedFigure(c.rms, "\"", decimals=d,
                                                    resolution_only=True)),
    ]
    if result.iso230 is not None:
        # each figure to the decimal of its interval, as the certificate prints it (day
        # review 68 F5: "R_up = 4.24″" here, "4″" on the certificate)
        from models.certificate.metadata import CertificateMetadata
        from models.theodolite.figures import theodolite_figure_decimals
        from models.theodolite.report import theodolite_budget

        decimals = theodolite_figure_decimals(
            result, theodolite_budget(result, CertificateMetadata()), held=False)
        decimals |= getattr(printed, "figures", {})  # the certificate's, where known
        figs = ", ".join(f"{k} = {fixed_places(v, decimals.get(k, 2))}\""
                         for k, v in result.iso230.figures.items())
        out.append(f"ISO 230-2: {figs}")
        out.append(_intervals_line(result, getattr(printed, "figures", {})))
        from models.theodolite.figures import pointing_in_figures_note

        pointing = pointing_in_figures_note(result)
        if pointing is not None:
            out.append(pointing)
        note = once_note(result.iso230, "°")
        if note is not None:
            out.append(note)
    return lines(out)


class Theodolite(Workbench[TheodoliteResult], IssuesCertificates[TheodoliteResult],
                 SendsRuns[TheodoliteResult], OverlaysRuns[TheodoliteResult],
                 ShowsHeadline[TheodoliteResult], GuidesAcquisition):
    key = KEY
    title = TITLE
    columns = COLUMNS
    parameters = PARAMETERS
    sample_file = "theodolite_sample.csv"
    point_keys = ("theta_deg", "run", "direction")

    def point_name(self, parsed: ParsedReadings, index: int) -> str:
        return message(QT_TR_NOOP("θ = {theta}°"), theta=f"{parsed['theta_deg'][index]:g}")
    measurand_standards = MEASURAND_STANDARDS
    dcc_uncertainty_columns = {"corrected_error": ""}  # the certificate's U column (DCC)
    #: what the DCC says of the raw error's U (the JSON's raw_error_arcsec budget)
    dcc_column_notes = {"raw_error_arcsec": raw_error_u_note(MODEL_INPUT)}
    method_reference = ("Tian L. et al., Test method of angle error of limited rotation axis "
                        "system, Acta Photonica Sinica 46(11):1112005 (2017)")
    presenter = "widgets.theodolite.presenter:TheodolitePresenter"
    nominal_column = "theta_deg"
    entry_column = "azimuth_deg"
    shortcuts = (Shortcut("--zenith", "vertical_reading", "zenith",
                          QT_TR_NOOP("theodolite: the vertical column is the zenith angle V "
                                     "(same as --vertical-reading zenith)")),)
    analyze = staticmethod(analyze)
    split_incomplete = staticmethod(split_incomplete)
    plan_reading_keys = ("azimuth_deg", "elevation_deg")

    def column_origins(self, settings: Mapping[str, Any]) -> Mapping[str, float]:
        return {"elevation_deg": elevation_origin(settings)}

    def read_cells(self, parsed: ParsedReadings, settings: Mapping[str, Any]
                   ) -> Mapping[str, list[Any]]:
        # a blank direction beside stated ones is forward, as pass_directions takes it
        directions = pass_directions(parsed["direction"])
        if directions is None:
            return {}
        return {"direction": ["+" if d > 0 else "-" for d in directions.tolist()]}

    def entry_plan(self, settings: Mapping[str, Any]) -> EntryPlan | None:
        from models.readings.entry_plan import targets_from_text, theodolite_plan

        passes = int(settings.get("plan_passes", 0) or 0)
        if not passes:
            return None
        return theodolite_plan(targets_from_text(str(settings.get("plan_thetas", ""))), passes,
                               readings=int(settings.get("readings_per_point", 1) or 1))

    to_json = staticmethod(to_json)
    summary = staticmethod(summary)
    acquisition_guide = staticmethod(theodolite_guide)
    run_rows = staticmethod(positioning_rows)

    def certificate(self, result: TheodoliteResult, metadata: CertificateMetadata,
                    source_name: str = "", settings: Mapping[str, Any] | None = None
                    ) -> CertificateDocument:
        from models.theodolite.report import theodolite_certificate

        return theodolite_certificate(result, metadata, source_name, self.method_reference,
                                      settings)

    def uncertainty_budgets(self, result: TheodoliteResult, metadata: CertificateMetadata,
                            settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
        from models.theodolite.report import theodolite_json_budgets

        return dict(theodolite_json_budgets(result, metadata, settings))

    def certified_json(self, result: TheodoliteResult, metadata: CertificateMetadata,
                       settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
        # the ISO 230-2 figures of a run with passes with their intervals (the certificate's
        # budget: its stated theodolite u), as the certificate prints them
        from models.theodolite.figures import theodolite_figures_json
        from models.theodolite.report import (
            stated_pair_factor,
            stated_reading_uncertainty,
            theodolite_budget,
        )

        if result.iso230 is None:
            return {}
        return theodolite_figures_json(result, theodolite_budget(result, metadata, settings),
                                       stated_reading_uncertainty(metadata)[0],
                                       stated_pair_factor(metadata))

    def decided_errors(self, result: TheodoliteResult, metadata: CertificateMetadata
                       ) -> np.ndarray:
        from models.theodolite.pass_means import decided_on_means, pass_means

        if metadata.decision_quantity == "half_range" and decided_on_means(result):
            return pass_means(result)[0]  # the means over the passes (the certificate's)
        return result.corrected_error_arcsec

    def overlay_figure(self, result: TheodoliteResult) -> PlotFigure:
        from models.theodolite.plots import error_figure  # the window's: a plot's module

        return error_figure(result)

    def printed_rounding(self, result, metadata, settings=None):
        from models.theodolite.figures import theodolite_figure_decimals
        from models.theodolite.report import (  # not for a plain analysis
            stated_pair_factor,
            stated_reading_uncertainty,
            theodolite_budget,
        )

        try:  # the certificate's statistics: to the decimal of its largest U
            budget = theodolite_budget(result, metadata, settings)
            # and each ISO 230-2 figure to its certificate interval's decimal (day review
            # 69 F6: "E_up 1.70″ M 1.55″" in the window, "1.7″ 1.5″" on the certificate)
            figures = (theodolite_figure_decimals(
                result, budget, stated_reading_uncertainty(metadata)[0],
                stated_pair_factor(metadata)) if result.iso230 is not None else {})
        except (ValueError, ArithmeticError, IndexError):
            return None
        return PrintedDecimals(uncertainty_decimals(budget.max_expanded), figures)

    def printed_headline(self, result, printed=None):
        d = 2 if printed is None else printed
        return {"corrected peak-to-peak (\")": _printed(result.corrected_stats, d)["ptp"][:-1],
                "raw peak-to-peak (\")": _printed(result.raw_stats, d)["ptp"][:-1]}

    def verdict(self, r: TheodoliteResult, printed: int | None = None) -> str:
        d = 2 if printed is None else printed
        corrected = _printed(r.corrected_stats, d)
        share = (float(_printed(r.raw_stats, d)["ptp"][:-1])  # of the peak-to-peaks printed
                 - float(corrected["ptp"][:-1]))
        return message(
            QT_TR_NOOP("Corrected error {low} … {high} (peak-to-peak {ptp}); the set-up "
                       "contributed {share} to the raw peak-to-peak"),
            **corrected, share=f"{fixed_places(share, d, '+')}\"")

    def headline(self, r: TheodoliteResult) -> dict[str, float]:
        return {"corrected peak-to-peak (\")": r.corrected_stats.peak_to_peak,
                "raw peak-to-peak (\")": r.raw_stats.peak_to_peak}


THEODOLITE = Theodolite()
