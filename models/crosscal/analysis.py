"""Cross-calibration of a polygon and an encoder as a workbench: readings columns,
settings, the analysis (models/crosscal/solve.py), JSON and summary.

The workbench is declared here (:class:`CrossCal`) and registered by one line in
models/registry.py.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from models.crosscal import DEFAULT_TILT_BOUND_ARCSEC, KEY, POLYGON_SIGN_CONVENTION, TITLE
from models.crosscal.acquisition import crosscal_guide
from models.crosscal.export import (
    WITHOUT_COMPARATORS,
    comparators_stated,
    polygon_deviation_rows,
    polygon_deviations,
)
from models.crosscal.figures import ENCODER_FIGURES_NO_INTERVAL, encoder_figures
from models.crosscal.readings import COLUMNS, CrossCalReadings, matrix_rows, read_crosscal
from models.crosscal.solve import CrossCalibration, CrossCalibrationInputError, solve_crosscal
from models.messages import QT_TR_NOOP, Message, joined, lines, message, reason_of, separated
from models.named_settings import DRIFT_BOUND_SETTING
from models.parameters import Parameter, SettingsError
from models.readings.entry_plan import crosscal_plan
from models.readings.incomplete import IncompleteUnit, short_last_unit, subset
from models.uncertainty.conformity import expanded_text
from models.uncertainty.lab_scope import cmc_parameter
from models.uncertainty.printed_figure import printed_range_figures
from models.uncertainty.rounding import significant_decimals
from models.uncertainty.tilt_bound_words import TILT_BOUND_ZERO, tilt_bound_origin
from models.workbench import (
    SIGN_CONVENTION,
    GuidesAcquisition,
    IssuesCertificates,
    SendsReference,
    SentReference,
    ShowsHeadline,
    Workbench,
    WritesCorrectionTable,
)

if TYPE_CHECKING:
    from models.certificate.uncertainty_json import PointUncertainty
    from models.uncertainty.budget import UncertaintyBudget

__all__ = ["CROSSCAL", "CrossCalResult", "analyze", "polygon_deviation_rows", "summary", "to_json"]

PARAMETERS = (
    Parameter("faces", "faces n", "int", 0, minimum=3, maximum=360, zero="from the readings",
              help="Faces of the polygon (= the encoder's steps); 0: as many as the readings "
                   "have"),
    Parameter("closure_drift", "closure drift", "choice", "fit",
              choices=(("fit", "fit linearly, remove"),
                       ("spread", "spread linearly, remove"),
                       ("report", "report it (not removed)")),
              help="Each mounting's drift, seen by its closure reading: fitted by least squares "
                   "as a linear drift over the mounting and removed; or its closure spread "
                   "linearly over the mounting and removed, as the polygon workbench does; or "
                   "only reported"),
    Parameter("ac_alignment", "autocollimator set-up", "choice", "levelled",
              choices=(("levelled", "levelled with the rotary axis"),
                       ("polygon", "vertical along the polygon's axis (rolled with the tilt)")),
              help="The frame the tilt correction is made in when vertical readings are given, "
                   "as in the polygon workbench: the autocollimator levelled with the rotary "
                   "axis, or its vertical along the polygon's axis"),
    Parameter("noise_arcsec", "σ of a reading", "float", 0.0, "\"", 0.0, 100.0, decimals=3,
              step=0.01, zero="from the residuals",
              help="Standard deviation of one reading when known (the autocollimator's and the "
                   "encoder's noise together); 0: taken from the residuals of the fit, with its "
                   "degrees of freedom"),
    Parameter("ac_scale_pct", "autocollimator scale error up to", "float", 0.2, "%", 0.0, 10.0,
              decimals=3, step=0.05, zero="none",
              help="Largest relative error of the autocollimator's indication over the readings' "
                   "span (its scale and linearity, from its calibration), rectangular: it enters "
                   "the uncertainty through the design (a constant offset cancels in each "
                   "mounting's offset); 0: not in the budget"),
    Parameter("ac_roll_arcmin", "AC roll ≤", "float", 1.0, "′", 0.0, 60.0, decimals=1,
              step=0.5, cli_name="ac-roll", zero="none",
              help="Largest roll of the autocollimator about its line of sight, relative to "
                   "the set-up's vertical, as in the polygon workbench: it turns part of each "
                   "vertical reading into the horizontal one, one unknown roll for the whole "
                   "run (rectangular), through the design; used where vertical readings are "
                   "given; 0: not in the budget"),
    Parameter("tilt_bound_arcsec", "largest tilt of the polygon on the shaft, when not measured",
              "float", DEFAULT_TILT_BOUND_ARCSEC, "\"", 0.0, 3600.0, decimals=1, step=10.0,
              zero=TILT_BOUND_ZERO,
              help="Without vertical readings the polygon's tilt on the shaft is neither "
                   "identified nor removed: its exact effect for a tilt up to this, the worst "
                   "direction, enters the uncertainty (rectangular); not used when vertical "
                   "readings are given (the tilt is then fitted and removed); 0: a polygon on "
                   "the shaft with no tilt at all, which no set-up achieves, refused where a "
                   "mounting's tilt is not identified"),
    Parameter("drift_bound_arcsec", "largest autocollimator drift over a mounting, when not "
              "measured", "float", 0.0, "\"", 0.0, 100.0, decimals=3, step=0.05,
              zero="none stated",
              help="Without a closure reading (the first face read again at the end of the "
                   "mounting) a mounting's drift is neither measured nor removed (unless the "
                   "other mountings' closure readings let it be fitted), and a drift "
                   "the same way in every mounting is a ramp over the encoder's steps that the "
                   "readings cannot tell from the encoder's error: its exact effect for a "
                   "linear drift up to this over a mounting (a full turn), in every such "
                   "mounting, enters the uncertainty (rectangular); with σ of a reading "
                   "stated, each such mounting drifting its own way up to this too (that "
                   "moves the face deviations as well); 0: none stated, and the encoder's U "
                   "is then withheld (the face deviations are not affected by a drift common "
                   "to the mountings)"),
    Parameter("certificate_of", "certificate of", "choice", "polygon",
              choices=(("polygon", "the polygon (face deviations)"),
                       ("encoder", "the encoder (error at its steps)")),
              help="Which instrument the certificate is issued for: the polygon's face "
                   "deviations or the encoder's error at its steps"),
    Parameter("plan_mountings", "entry plan: mountings", "int", 0, minimum=2, maximum=360,
              zero="no plan", cli=False,
              help="Mountings of the entry plan: with the number of faces set, entry fills "
                   "mounting and face as readings arrive (mounting j from face j + 1) and shows "
                   "the next one. 0: no plan",
              entry_aid=True),
    cmc_parameter("cmc_arcsec", "laboratory's CMC (smallest U), polygon", "\"",
                  "a polygon's face deviations"),
    cmc_parameter("cmc_encoder_arcsec", "laboratory's CMC (smallest U), encoder", "\"",
                  "an encoder's error at its steps"),
)

#: a residual is marked as an outlier beyond the limit that all of a clean run's residuals
#: (normal, as many as the readings) stay within but once in this many runs: Šidák's share
#: of it for each (cov76 F8: a fixed 3σ flagged one of 156 clean readings in a third of runs)
OUTLIER_RUNS = 100
#: the limit never below this many σ
OUTLIER_SIGMAS = 3.0


def _residual_count(result) -> int:
    """How many residuals the outliers are judged among."""
    s = result.solution
    return int((s.scatter_residuals_arcsec if s.scatter_residuals_arcsec.size
                else s.residuals_arcsec).size)


def outlier_sigmas(readings: int) -> float:
    """The limit, in σ of the fit, beyond which one of ``readings`` residuals is an outlier:
    a clean run's largest |residual| passes it once in :data:`OUTLIER_RUNS` runs (3.0 for
    one reading … 4.0 for 156, 4.42 for 1000)."""
    from scipy.special import ndtri

    each = 1.0 - (1.0 - 1.0 / OUTLIER_RUNS) ** (1.0 / max(int(readings), 1))
    return max(OUTLIER_SIGMAS, float(ndtri(1.0 - each / 2.0)))


@dataclass(frozen=True)
class CrossCalResult:
    readings: CrossCalReadings
    solution: CrossCalibration
    closure_arcsec: np.ndarray  # per mounting, (x′ − x) − (a′ − a); NaN without closure
    drift_removed: bool  # "fit" or "spread": the drift was removed
    certificate_of: str
    warnings: list[str] = field(default_factory=list)
    drift_mode: str = "fit"  # "fit" | "spread" | "report" (setting closure_drift)
    ac_scale_pct: float = 0.0  # setting: the autocollimator's scale error bound (budget)
    #: setting: the tilt bound of a mounting without vertical readings (budget)
    tilt_bound_arcsec: float = DEFAULT_TILT_BOUND_ARCSEC
    ac_roll_arcmin: float = 0.0  # setting: the autocollimator's roll bound (budget, ρ·y)
    incomplete: object = None  # the last unit in progress (models.readings.incomplete), left out
    cmc_polygon_arcsec: float = 0.0  # setting: the lab's CMC for face deviations (U floor)
    cmc_encoder_arcsec: float = 0.0  # setting: the lab's CMC for the encoder's error (U floor)
    #: setting: the largest autocollimator drift over a mounting without a closure reading
    #: (budget, through the design); 0: none stated
    drift_bound_arcsec: float = 0.0

    @property
    def unidentified_tilt_mountings(self) -> tuple[int, ...]:
        """The mountings whose tilt on the shaft the vertical readings do not identify (none
        read, some missing, or too few faces): their tilt is not removed and the bound
        ``tilt_bound_arcsec`` enters the budget for it."""
        return unidentified_tilt_mountings(self.solution)

    @property
    def unchecked_drift_mountings(self) -> tuple[int, ...]:
        """The mountings with no closure reading (their drift neither measured nor removed)."""
        from models.crosscal.uncertainty import unchecked_drift_mountings

        return unchecked_drift_mountings(self.solution)

    @property
    def encoder_u_withheld(self) -> str | None:
        """Why the encoder's U is not given (None when it is): mountings without a closure
        reading and no drift bound stated. A drift the same way in every mounting is, step by
        step, exactly an encoder error growing linearly over the steps (every mounting starts
        at step 0 and reads in step order); only a closure reading — step 0 read again after
        the full turn — tells the two apart. The face deviations are not affected by it."""
        unchecked = self.unchecked_drift_mountings
        if not unchecked or self.drift_bound_arcsec > 0:
            return None
        return message(QT_TR_NOOP(
            "the encoder's U is withheld: mounting(s) {mountings} have no closure reading, so "
            "the autocollimator's drift is not measured, and a drift the same way in every "
            "mounting is a ramp over the encoder's steps that these readings cannot tell from "
            "the encoder's error; add a closure reading to each mounting (its first face read "
            "again at the end) or state the largest drift over a mounting {setting}"),
            mountings=", ".join(map(str, unchecked)), setting=DRIFT_BOUND_SETTING)

    @property
    def polygon_u_withheld(self) -> str | None:
        """Why the face deviations' U is not given (None when it is): mountings without a
        closure reading, no drift bound stated, and a drift of theirs that moves the face
        deviations — one that differs from mounting to mounting with σ stated (taken from the
        residuals, the scatter holds it), or one not shared by every mounting (a mounting
        with no closure reading among others whose drift is fitted). A drift the same way in
        every mounting does not move them (it follows the steps): then the U is given."""
        from models.crosscal.uncertainty import drift_effect_arcsec, own_drift_effect_arcsec

        unchecked = self.unchecked_drift_mountings
        if not unchecked or self.drift_bound_arcsec > 0:
            return None
        s, n = self.solution, self.faces
        moved = np.hypot(drift_effect_arcsec(s), own_drift_effect_arcsec(s))[n:]
        if not np.max(moved, initial=0.0) > 1e-9:
            return None
        return message(QT_TR_NOOP(
            "the face deviations' U is withheld: mounting(s) {mountings} have no closure "
            "reading, so the autocollimator's drift is not measured, and a drift that differs "
            "from mounting to mounting moves the face deviations, which nothing in these "
            "readings bounds (σ stated, or a drift not shared by every mounting); add a closure "
            "reading to each mounting (its first face read again at the end) or state the "
            "largest drift over a mounting {setting}"),
            mountings=", ".join(map(str, unchecked)), setting=DRIFT_BOUND_SETTING)

    def u_withheld(self, item: str) -> str | None:
        """Why ``item``'s U ("encoder", "polygon") is not given, or None."""
        return self.encoder_u_withheld if item == "encoder" else self.polygon_u_withheld

    @property
    def cmc(self) -> float:
        """The laboratory's CMC for the certificate's item (0: none stated)."""
        return self.cmc_encoder_arcsec if self.certificate_of == "encoder" else self.cmc_polygon_arcsec

    @property
    def faces(self) -> int:
        return self.solution.faces

    @property
    def step_deg(self) -> np.ndarray:
        """The encoder's steps from its start, first step first (°)."""
        return np.arange(self.faces) * 360.0 / self.faces

    @property
    def outliers(self) -> np.ndarray:
        """Indices of the readings whose residual exceeds :func:`outlier_sigmas`·σ (the residuals σ
        is judged by: in the "report" mode those with the drifts fitted)."""
        s = self.solution
        if not s.sigma_arcsec > 0:
            return np.zeros(0, dtype=int)
        residuals = (s.scatter_residuals_arcsec if s.scatter_residuals_arcsec.size
                     else s.residuals_arcsec)
        limit = outlier_sigmas(residuals.size) * s.sigma_arcsec
        return np.flatnonzero(np.abs(residuals) > limit)

    def encoder_runs_arcsec(self) -> np.ndarray:
        """Each mounting's own estimate of the encoder's error at each step (mountings ×
        steps): E_k plus that reading's residual (closure readings left out)."""
        r, s = self.readings, self.solution
        e = s.encoder_error_determined_arcsec
        k = (r.position - 1 - r.mounting) % self.faces
        out = np.full((len(r.mountings), self.faces), np.nan)
        for q, j in enumerate(r.mountings):
            rows = np.flatnonzero((r.mounting == j) & ~r.closure)
            out[q, k[rows]] = e[k[rows]] + s.residuals_arcsec[rows]
        return out

    @property
    def encoder_start_deg(self) -> float:
        """The encoder's reading where every mounting starts (its first mounting's first)."""
        r = self.readings
        return float(r.encoder_deg[np.flatnonzero(r.mounting == r.mountings[0])[0]])

    def _u_from_first(self, block: int, metadata: Any = None) -> np.ndarray:
        """Standard uncertainty of x_i − x_1 within one result set (0: E, 1: d): the scatter's
        from the full covariance (var x_i + var x_1 − 2 cov), with the bench's stated bounds
        through the design, and — given the certificate details — each comparator's stated
        uncertainty through the design (as in the budget about the mean)."""
        n, cov = self.faces, self.solution.covariance_arcsec2
        c = cov[block * n:(block + 1) * n, block * n:(block + 1) * n]
        var = np.diag(c) + c[0, 0] - 2.0 * c[:, 0]
        from_first = np.zeros((n, 2 * n))
        from_first[:, block * n:(block + 1) * n] = np.eye(n)
        from_first[:, block * n] -= 1.0
        var = var + self.systematic_u_arcsec(from_first) ** 2
        if metadata is not None:
            from models.crosscal.report import comparator_u_arcsec

            var = var + comparator_u_arcsec(self, metadata, from_first) ** 2
        return np.sqrt(np.clip(var, 0.0, None))

    def u_from_first(self, item: str, metadata: Any = None) -> PointUncertainty:
        """U and k of the ``item``'s values stated from its first point ("polygon": d_i − d_1,
        from face 1; "encoder": E_k − E_0, from step 0), k the solution's: the scatter's with
        the bench's stated bounds through the design, and with the certificate details the
        comparators' stated U. Held to the laboratory's CMC of that quantity (ILAC-P14 5.4, as
        every U stated about the mean is by its budget) at every point but the first, the
        reference, where the value and its U are zero by definition; ``below_floor`` marks
        the points raised to it (the JSON's and the DCC's flags), ``floor`` is that CMC (0:
        none set)."""
        from models.certificate.uncertainty_json import PointUncertainty

        k = float(self.solution.coverage_factor)
        computed = k * self._u_from_first(0 if item == "encoder" else 1, metadata)
        cmc = self.cmc_encoder_arcsec if item == "encoder" else self.cmc_polygon_arcsec
        raised = np.zeros(computed.size, dtype=bool)
        if cmc > 0:
            raised[1:] = computed[1:] < cmc
        return PointUncertainty(np.where(raised, cmc, computed), np.full(computed.size, k),
                                raised if cmc > 0 else None, cmc if cmc > 0 else 0.0)

    def encoder_u_from_step0_arcsec(self, metadata: Any = None) -> np.ndarray:
        """Expanded U of E_k − E_0 (zero at step 0), held to the laboratory's CMC for the
        encoder (:meth:`u_from_first`); with the certificate details, the comparators'
        stated U in (the certificate's column)."""
        return np.asarray(self.u_from_first("encoder", metadata).expanded, dtype=float)

    def encoder_u_from_step0_standard_arcsec(self, metadata: Any = None) -> np.ndarray:
        """Standard uncertainty of E_k − E_0 (zero at step 0), as these readings give it."""
        return self._u_from_first(0, metadata)

    def polygon_u_from_face1_standard_arcsec(self, metadata: Any = None) -> np.ndarray:
        """Standard uncertainty of d_i − d_1 (zero at face 1, the reference), as these
        readings give it (not held to the CMC: no U is stated from it)."""
        return self._u_from_first(1, metadata)

    def polygon_u_from_face1_arcsec(self, metadata: Any = None) -> np.ndarray:
        """Expanded U of d_i − d_1 (what a polygon certificate stated from face 1 carries): the
        scatter's (k from its ν) with the bench's stated bounds through the design; with the
        certificate details, the comparators' stated U in (the certificate's column). Held
        to the laboratory's CMC for face deviations but at face 1 (:meth:`u_from_first`)."""
        return np.asarray(self.u_from_first("polygon", metadata).expanded, dtype=float)

    @functools.cached_property
    def expanded_u_arcsec(self) -> tuple[np.ndarray, np.ndarray]:
        """(U of E, U of d) about their mean as the certificates state them: the reading
        scatter through the design with the bench's stated bounds (scale, unmeasured tilt), k
        from each value's ν_eff (models.crosscal.report.crosscal_budget, without the item's
        resolution, which only the certificate details give)."""


        e, d = (budget.expanded for budget in self.bench_budgets)
        e, d = np.asarray(e, dtype=float), np.asarray(d, dtype=float)
        if self.encoder_u_withheld is not None:  # not determined: no figure (NaN)
            e = np.full(e.shape, np.nan)
        if self.polygon_u_withheld is not None:
            d = np.full(d.shape, np.nan)
        return e, d

    @functools.cached_property
    def bench_budgets(self) -> tuple[UncertaintyBudget, UncertaintyBudget]:
        """The budgets of E and of d without the certificate details (no item resolution,
        the default coverage probability)."""
        import dataclasses

        from models.certificate.metadata import CertificateMetadata
        from models.crosscal.report import crosscal_budget

        details = CertificateMetadata.from_dict({"certificate_number": "", "lab_name": ""})
        encoder, polygon = (crosscal_budget(dataclasses.replace(self, certificate_of=item), details)
                            for item in ("encoder", "polygon"))
        return encoder, polygon

    def systematic_u_arcsec(self, combine=None) -> np.ndarray:
        """Standard uncertainty of (E, d) — or of ``combine``·(E, d) — from the bench's stated
        bounds (the autocollimator's scale error; the tilt when not measured; the drift of a
        mounting with no closure reading), each rectangular, through the design, and the bias
        the closure drifts reported, not removed, leave (in quadrature, as in the budget)
        (models.crosscal.uncertainty)."""
        from models.crosscal.uncertainty import (
            drift_effect_arcsec,
            own_drift_effect_arcsec,
            reported_drift_bias_arcsec,
            roll_effect_arcsec,
            scale_effect_arcsec,
            tilt_effect_arcsec,
        )

        s, r = self.solution, self.readings
        scale = self.ac_scale_pct / 100.0 * scale_effect_arcsec(s, r.ac_x_arcsec, combine)
        tilt = tilt_effect_arcsec(s, r.mounting, r.position, self.tilt_bound_arcsec,
                                  combine=combine)
        roll = math.radians(self.ac_roll_arcmin / 60.0) * roll_effect_arcsec(
            s, r.ac_y_arcsec, combine)
        drift = self.drift_bound_arcsec * np.hypot(drift_effect_arcsec(s, combine),
                                                   own_drift_effect_arcsec(s, combine))
        bias = reported_drift_bias_arcsec(s, combine)
        return np.sqrt((scale**2 + tilt**2 + roll**2 + drift**2) / 3.0 + bias**2)

    def cross_correlation(self) -> float:
        """The largest |correlation| between an encoder error and a face deviation."""
        n = self.faces
        block = self.solution.correlation[:n, n:]
        return float(np.max(np.abs(block))) if block.size else 0.0


def unidentified_tilt_mountings(solution: CrossCalibration) -> tuple[int, ...]:
    """The mountings of ``solution`` whose tilt was not fitted from vertical readings."""
    tilts = solution.tilts or (None,) * len(solution.mountings)
    return tuple(j for j, t in zip(solution.mountings, tilts, strict=True) if t is None)


#: why a zero tilt bound is refused (a mounting's tilt not identified): audit 73 finding 1,
#: the theodolite's and the polygon's, here for the cross-calibration; the refusal and what
#: to do first, then why, as theirs (day 74 finding 10)
ZERO_TILT_BOUND_REFUSED = QT_TR_NOOP(
    "a tilt bound of 0\" is refused: state the largest tilt the set-up can have (the setting "
    "\"largest tilt of the polygon on the shaft, when not measured\", --tilt-bound-arcsec), "
    "or read vertical readings of every face in mounting(s) {mountings} so that their tilt "
    "is fitted. The polygon's tilt on the shaft is not identified in mounting(s) "
    "{mountings} ({why}): 0 would claim that the polygon sits on the shaft with no tilt at "
    "all there, which no set-up achieves and these readings cannot show")


def _refuse_zero_tilt_bound(readings: CrossCalReadings, solution: CrossCalibration,
                            bound_arcsec: float) -> None:
    """SettingsError (key ``tilt_bound_arcsec``: the window marks its field) when the bound
    is 0 and some mounting's tilt is not identified: 0 would enter that tilt's effect in U as
    nothing, a claim no set-up meets and the readings cannot check. Where every mounting's
    tilt is fitted the bound is not used and 0 is taken."""
    unidentified = unidentified_tilt_mountings(solution)
    if not unidentified or bound_arcsec > 0:
        return
    why = (QT_TR_NOOP("no vertical readings") if readings.ac_y_arcsec is None else
           QT_TR_NOOP("fewer than 4 faces: vertical readings cannot identify a tilt")
           if solution.faces < 4 else
           QT_TR_NOOP("vertical readings missing there"))
    raise SettingsError(message(ZERO_TILT_BOUND_REFUSED,
                                mountings=", ".join(map(str, unidentified)),
                                why=message(why)), key="tilt_bound_arcsec")


def _sheet_row(text: str, row: int | None, readings: CrossCalReadings) -> str:
    """The model's reason naming the sheet's row (the model counts the rows given it)."""
    if row is None:
        return text
    sheet = readings.row(row - 1)
    if isinstance(text, Message) and any(v == row for v in text.figures.values()):
        key = next(k for k, v in text.figures.items() if v == row)
        return message(text.template, **{**text.figures, key: sheet})
    return text.replace(f"row {row}", f"row {sheet}", 1) if f"row {row}" in text else \
        message(QT_TR_NOOP("row {row}: {reason}"), row=sheet, reason=text)


def split_incomplete(parsed, settings: Mapping[str, Any]):
    """The complete mountings, and the last mounting when it is in progress: its rows the
    last ones, each face read once, fewer than the polygon has (the face count from the
    setting, else from the first mounting), no closure yet."""
    if parsed.n == 0 or not (np.all(np.isfinite(parsed["mounting"]))
                             and np.all(np.isfinite(parsed["position"]))):
        return parsed, None
    mounting = parsed["mounting"].astype(int).tolist()
    position = parsed["position"].astype(int).tolist()
    faces = int(settings.get("faces", 0) or 0)
    if not faces:
        first = [p for j, p in zip(mounting, position, strict=True) if j == mounting[0]]
        if mounting[-1] == mounting[0]:
            return parsed, None  # one mounting and no face count: nothing says it is short
        faces = max(len(set(first)), max(position))
    rows = short_last_unit(mounting, position, set(range(1, faces + 1)))
    if rows is None:
        return parsed, None
    keep = np.ones(parsed.n, dtype=bool)
    keep[rows] = False
    sheet = parsed.row_index.astype(int) + 1
    return subset(parsed, keep), IncompleteUnit(
        "mounting", float(mounting[-1]), int(rows.size), faces, int(sheet[rows[0]]),
        int(sheet[rows[-1]]), tuple(int(i) for i in rows))


def analyze(parsed, settings: Mapping[str, Any]) -> CrossCalResult:
    readings = read_crosscal(parsed, int(settings.get("faces", 0) or 0))
    noise = float(settings.get("noise_arcsec", 0.0) or 0.0)
    mode = str(settings.get("closure_drift", "fit"))
    removed = mode != "report"
    try:
        solution = solve_crosscal(readings.mounting, readings.position, readings.encoder_deg,
                                  readings.ac_x_arcsec, faces=readings.faces,
                                  noise_arcsec=noise or None, drift=mode,
                                  ac_y_arcsec=readings.ac_y_arcsec,
                                  ac_alignment=settings.get("ac_alignment", "levelled"))
    except CrossCalibrationInputError as exc:
        raise ValueError(_sheet_row(reason_of(exc), exc.row, readings)) from None
    tilt_bound = float(settings.get("tilt_bound_arcsec", DEFAULT_TILT_BOUND_ARCSEC) or 0.0)
    _refuse_zero_tilt_bound(readings, solution, tilt_bound)
    # the model's own: no closure, no vertical readings, harmonics it cannot see
    warnings: list[str] = list(solution.warnings)
    result = CrossCalResult(readings, solution, readings.closure_arcsec(), removed,
                            str(settings.get("certificate_of", "polygon")), warnings, mode,
                            float(settings.get("ac_scale_pct", 0.2) or 0.0),
                            tilt_bound,
                            cmc_polygon_arcsec=float(settings.get("cmc_arcsec", 0.0) or 0.0),
                            cmc_encoder_arcsec=float(settings.get("cmc_encoder_arcsec", 0.0) or 0.0),
                            ac_roll_arcmin=float(settings.get("ac_roll_arcmin", 1.0) or 0.0),
                            drift_bound_arcsec=float(settings.get("drift_bound_arcsec", 0.0)
                                                     or 0.0))
    if result.outliers.size:
        shown = ", ".join(str(readings.row(i)) for i in result.outliers[:8])
        warnings.append(message(QT_TR_NOOP("{count} reading(s) lie beyond {sigmas}σ of the fit "
                                           "(rows {rows}): check them"),
                                count=int(result.outliers.size),
                                sigmas=f"{outlier_sigmas(_residual_count(result)):.1f}",
                                rows=shown + (" …" if result.outliers.size > 8 else "")))
    return result


# the settings a cross-calibration result holds as it was analysed with them (setting → the
# result's field): its own U figures (expanded_u_arcsec, the JSON's) are made from them,
# so they stay in the result, and a certificate given other settings is refused
_ANALYSED_WITH = (("certificate_of", "certificate_of"), ("closure_drift", "drift_mode"),
                  ("ac_scale_pct", "ac_scale_pct"), ("tilt_bound_arcsec", "tilt_bound_arcsec"),
                  ("ac_roll_arcmin", "ac_roll_arcmin"),
                  ("drift_bound_arcsec", "drift_bound_arcsec"),
                  ("cmc_arcsec", "cmc_polygon_arcsec"),
                  ("cmc_encoder_arcsec", "cmc_encoder_arcsec"))


def _check_analysed_with(result: CrossCalResult, settings: Mapping[str, Any] | None) -> None:
    """ValueError naming the setting when ``settings`` (those a certificate is to state) are
    not the ones ``result`` was analysed with: the certificate would list one figure and
    compute with another. None: nothing to compare."""
    if settings is None:
        return
    for key, field_name in _ANALYSED_WITH:
        if key in settings and settings[key] != getattr(result, field_name):
            raise ValueError(message(QT_TR_NOOP(
                "the setting {setting} is {now}, but the result was analysed with {then}: "
                "analyse again before a certificate is made"),
                setting=key, now=settings[key], then=getattr(result, field_name)))


def _list(values) -> list[float] | None:
    return None if values is None else [float(v) for v in values]


#: why a mounting's closure is null in the JSON (``closure_arcsec_reason``)
CLOSURE_NOT_READ = QT_TR_NOOP("null for mounting(s) {mountings}: no closure reading of the first "
                              "face after the full turn was taken there")
#: why a mounting's drift is null in the JSON (``drift_arcsec_reason``)
DRIFT_NOT_MEASURED = QT_TR_NOOP("null for mounting(s) {mountings}: the drift is not measured "
                                "there (no closure reading of its own, and the design does not "
                                "determine it through the other mountings' closure readings)")


def _null_mountings_reason(mountings, values, template: str) -> Message | None:
    """``template`` naming the mountings whose value in ``values`` is not a finite number;
    None where every one is."""
    if values is None:
        return None
    missing = [str(j) for j, v in zip(mountings, np.asarray(values, dtype=float), strict=False)
               if not math.isfinite(float(v))]
    return message(template, mountings=", ".join(missing)) if missing else None


def to_json(result: CrossCalResult) -> dict[str, Any]:
    s = result.solution
    u_e, u_d = result.expanded_u_arcsec if s.separable else (None, None)
    out: dict[str, Any] = {
        "faces": s.faces,
        "mountings": list(s.mountings),
        # what each result set is stated relative to (its U is for that same quantity)
        "encoder_error_reference": "mean",
        "polygon_deviation_reference": "mean",
        "encoder_error_arcsec": _list(s.encoder_error_arcsec),
        "encoder_error_U_arcsec": None if s.encoder_error_arcsec is None
        or result.encoder_u_withheld is not None else _list(u_e),
        "polygon_deviation_arcsec": _list(s.polygon_deviation_arcsec),
        "polygon_deviation_U_arcsec": None if s.polygon_deviation_arcsec is None
        or result.polygon_u_withheld is not None else _list(u_d),
        "coverage_factor": s.coverage_factor,
        "sigma_arcsec": s.sigma_arcsec,
        "dof": s.dof,
        "separable": s.separable,
        "undetermined_encoder_harmonics": list(s.undetermined_encoder_harmonics),
        "undetermined_polygon_harmonics": list(s.undetermined_polygon_harmonics),
        "largest_correlation_encoder_polygon": result.cross_correlation(),
        "closure_arcsec": _list(result.closure_arcsec),
        "closure_drift": result.drift_mode,
        "drift_arcsec": _list(s.drift_arcsec),
        "residual_rms_arcsec": float(np.sqrt(np.mean(s.residuals_arcsec**2))),
        "outlier_rows": [result.readings.row(i) for i in result.outliers],
        "nominal_encoder_steps": result.readings.nominal_encoder,
        "sign_convention": SIGN_CONVENTION,  # the encoder's error
        "polygon_deviation_sign_convention": POLYGON_SIGN_CONVENTION,
        "warnings": result.warnings,
        # the mountings whose tilt is not identified, the tilt bound whose effect enters the
        # uncertainty for them, and whether the lab stated it or it is the program's default
        # (the bound and its origin null where every mounting's tilt is fitted)
        "tilt_not_identified_mountings": list(result.unidentified_tilt_mountings),
        "tilt_bound_arcsec": (result.tilt_bound_arcsec if result.unidentified_tilt_mountings
                              else None),
        "tilt_bound_origin": (tilt_bound_origin(result.tilt_bound_arcsec,
                                                DEFAULT_TILT_BOUND_ARCSEC)
                              if result.unidentified_tilt_mountings else None),
    }
    # the mountings whose closure or drift is null, and why (assessment 73 M3: null with no
    # reason where no closure reading was taken); null where every value is given
    out["closure_arcsec_reason"] = _null_mountings_reason(
        s.mountings, result.closure_arcsec, CLOSURE_NOT_READ)
    out["drift_arcsec_reason"] = _null_mountings_reason(s.mountings, s.drift_arcsec,
                                                        DRIFT_NOT_MEASURED)
    if result.encoder_u_withheld is not None:  # the encoder's U null, and why
        out["encoder_error_U_withheld"] = result.encoder_u_withheld
    if result.polygon_u_withheld is not None:  # the face deviations' U null, and why
        out["polygon_deviation_U_withheld"] = result.polygon_u_withheld
    # not separable (E or d not determined): what the design does see, labelled, never the result
    d = s.polygon_deviation_arcsec
    if s.encoder_error_arcsec is None or d is None:
        out["unseen_components"] = {
            "encoder_harmonics": list(s.undetermined_encoder_harmonics),
            "polygon_harmonics": list(s.undetermined_polygon_harmonics),
            "encoder_error_without_them_arcsec": _list(s.encoder_error_determined_arcsec),
            "polygon_deviation_without_them_arcsec": _list(s.polygon_deviation_determined_arcsec)}
    else:
        out["polygon_deviation_from_face1_arcsec"] = _list(d - d[0])  # reference "face 1"
        out["polygon_deviation_U_from_face1_arcsec"] = (
            None if result.polygon_u_withheld is not None
            else _list(result.polygon_u_from_face1_arcsec()))
        # the encoder's errors referred to step 0 (E_k − E_0, the certificate's "From step 0"
        # column): their U and k beside them come from uncertainty_budgets (#39's rule)
        e = s.encoder_error_arcsec
        out["encoder_error_from_step0_arcsec"] = _list(e - e[0])  # reference "step 0"
        out["encoder_figures_arcsec"] = encoder_figures(result)
        # plain numbers, no interval: said beside them (the key's meaning kept, #39)
        out["encoder_figures_arcsec_reason"] = message(ENCODER_FIGURES_NO_INTERVAL)
    return out


def _printed(values: np.ndarray, readings_u: float, printed: Mapping[str, float] | None,
             item: str) -> dict[str, str]:
    """{span, ptp, u} of an item's values as its certificate prints them: U its budget's
    largest (``printed``, :meth:`CrossCal.printed_rounding`; without it, the readings' own
    U), the range to U's decimal (0.001″ where none) and the peak-to-peak the difference of
    the ends as printed (models/crosscal/report.py)."""
    expanded = (printed or {}).get(item)
    decimals = 3 if expanded is None else significant_decimals(expanded)
    # each figure rounded from its unrounded value in the unit it is read in (assessment 72 L5)
    ends = printed_range_figures(float(np.min(values)), float(np.max(values)),
                                 3 if decimals is None else decimals)
    return {"span": joined([ends["low"], " … ", ends["high"]]), "ptp": ends["ptp"],
            "u": expanded_text(readings_u if expanded is None else expanded)}


def summary(result: CrossCalResult, printed: Mapping[str, float] | None = None) -> str:
    """The result as text; ``printed``: the largest U of each item's certificate
    ({"encoder": U, "polygon": U}, :meth:`CrossCal.printed_rounding`), which its U and the
    rounding of its range are then (None: the readings' own U, ranges to 0.001″)."""
    s = result.solution
    nu = "∞" if not math.isfinite(s.dof) else f"{s.dof:.0f}"
    out = [message(QT_TR_NOOP("{faces}-face polygon on the encoder, {count} mountings ({mountings}); "
                              "σ of a reading {sigma} (ν = {nu}), k = {k}"),
                   faces=s.faces, count=len(s.mountings),
                   mountings=", ".join(map(str, s.mountings)), sigma=f"{s.sigma_arcsec:.3f}\"",
                   nu=nu, k=f"{s.coverage_factor:.2f}")]
    if result.readings.nominal_encoder:
        out.append(message(QT_TR_NOOP("Encoder set to its nominal steps (no encoder readings).")))
    if s.encoder_error_arcsec is not None and result.encoder_u_withheld is not None:
        encoder = _printed(s.encoder_error_arcsec, math.nan, None, "encoder")
        out.append(message(QT_TR_NOOP("Encoder error {span} (peak-to-peak {ptp}), U withheld: "
                                      "drift not measured (no closure reading) and no drift "
                                      "bound stated"), span=encoder["span"], ptp=encoder["ptp"]))
    elif s.encoder_error_arcsec is not None:
        out.append(message(QT_TR_NOOP("Encoder error {span} (peak-to-peak {ptp}), U up to {u}"),
                           **_printed(s.encoder_error_arcsec,
                                      float(np.max(result.expanded_u_arcsec[0])), printed,
                                      "encoder")))
    else:
        out.append(message(QT_TR_NOOP("Encoder error NOT determined (withheld)")))
    if s.polygon_deviation_arcsec is not None and result.polygon_u_withheld is not None:
        face = _printed(s.polygon_deviation_arcsec, math.nan, None, "polygon")
        out.append(message(QT_TR_NOOP("Face deviations {span} (about their mean), U withheld: "
                                      "drift not measured (no closure reading) and no drift "
                                      "bound stated"), span=face["span"]))
    elif s.polygon_deviation_arcsec is not None:
        face = _printed(s.polygon_deviation_arcsec, float(np.max(result.expanded_u_arcsec[1])),
                        printed, "polygon")
        out.append(message(QT_TR_NOOP("Face deviations {span} (about their mean), U up to {u}"),
                           span=face["span"], u=face["u"]))
    else:
        out.append(message(QT_TR_NOOP("Face deviations NOT determined (withheld)")))
    closures = result.closure_arcsec[np.isfinite(result.closure_arcsec)]
    if closures.size:
        out.append(message(QT_TR_NOOP("Closures {count} of {mountings}: {low} … {high}; drift "
                                      "removed") if result.drift_removed else
                           QT_TR_NOOP("Closures {count} of {mountings}: {low} … {high}; drift "
                                      "reported, not removed"),
                           count=int(closures.size), mountings=len(s.mountings),
                           low=f"{np.min(closures):+.2f}\"", high=f"{np.max(closures):+.2f}\""))
    else:
        out.append(message(QT_TR_NOOP("No closure readings: drift not measured")))
    if s.separable:
        out.append(message(QT_TR_NOOP("Largest correlation between an encoder error and a face "
                                      "deviation: {r}"), r=f"{result.cross_correlation():.2f}"))
        figures = encoder_figures(result)
        out.append(joined((message(QT_TR_NOOP("JJF 1115: division error {value}"),
                                   value=f"{figures['division_error_jjf1115']:.3f}\""),
                           ", ISO 230-2: " + ", ".join(
                               f"{k[7:]} = {v:.3f}\"" for k, v in figures.items()
                               if k.startswith("iso230_") and math.isfinite(v)))))
    return lines(out)


def verdict(result: CrossCalResult, printed: Mapping[str, float] | None = None) -> str:
    s = result.solution
    e, d = s.encoder_error_arcsec, s.polygon_deviation_arcsec  # each None: not determined
    if e is None or d is None:  # (the solution is separable exactly when both are given)
        return message(QT_TR_NOOP("This design cannot separate every harmonic: the undetermined "
                                  "results are withheld (see the warnings)."))
    # as each item's certificate prints them (its U; its range to U's decimal)
    encoder = _printed(e, float(np.max(result.expanded_u_arcsec[0])), printed, "encoder")
    face = _printed(d, float(np.max(result.expanded_u_arcsec[1])), printed, "polygon")
    low, high = face["span"].split(" … ")
    if result.polygon_u_withheld is not None:  # (the encoder's is then withheld too)
        return message(QT_TR_NOOP("Encoder error peak-to-peak {ptp}, face deviations {low} … "
                                  "{high} (U of both withheld: drift not measured)"),
                       ptp=encoder["ptp"], low=low, high=high)
    if result.encoder_u_withheld is not None:
        return message(QT_TR_NOOP("Encoder error peak-to-peak {ptp} (U withheld: drift not "
                                  "measured); face deviations {low} … {high} (U ≤ {ud})"),
                       ptp=encoder["ptp"], low=low, high=high, ud=face["u"])
    return message(QT_TR_NOOP("Encoder error peak-to-peak {ptp} (U ≤ {ue}); face deviations "
                              "{low} … {high} (U ≤ {ud})"),
                   ptp=encoder["ptp"], ue=encoder["u"], low=low, high=high, ud=face["u"])


#: what the cross-calibration sends and the polygon workbench accepts
POLYGON_FACE_DEVIATIONS = QT_TR_NOOP("polygon face deviations")


def polygon_reference(result: CrossCalResult, metadata: Any = None) -> SentReference:
    """The polygon's face deviations from face 1 with the U of each (d_i − d_1, from the full
    covariance), for the polygon workbench's reference column and its standard's U: the U
    the cross-calibration's certificate states from face 1 with the same certificate details
    ``metadata`` (the comparators' stated calibration U in, held to the CMC but at face 1).
    Without details that list a comparator with a stated U the name says so: that U leaves
    the comparators' calibration out."""
    d = polygon_deviations(result)  # ValueError when the design does not determine them
    held = result.u_from_first("polygon", metadata)  # the certificate's "U from face 1"
    u1 = np.asarray(held.expanded, dtype=float)
    k = result.solution.coverage_factor
    raised = held.below_floor is not None and bool(np.any(held.below_floor))
    left_out = "" if comparators_stated(metadata) else message(WITHOUT_COMPARATORS)
    # (a standard's name holds at most 200 characters: models/certificate/metadata.py)
    if left_out and raised:
        name = message(QT_TR_NOOP("Polygon, {faces} faces, cross-calibrated (closure principle); "
                                  "largest U of d_i − d_1 {u} (k = {k}), each ≥ the laboratory's "
                                  "CMC {cmc}, without the comparators' calibration U: not "
                                  "stated"),
                       faces=result.faces, u=f"{np.max(u1):.4f}\"", k=f"{k:.2f}",
                       cmc=f"{held.floor:g}\"")
    elif left_out:
        name = message(QT_TR_NOOP("Polygon, {faces} faces, cross-calibrated (closure principle); "
                                  "largest U of d_i − d_1 {u} (k = {k}), without the "
                                  "comparators' calibration U: not stated"),
                       faces=result.faces, u=f"{np.max(u1):.4f}\"", k=f"{k:.2f}")
    elif raised:
        name = message(QT_TR_NOOP("Polygon, {faces} faces, cross-calibrated (closure principle); "
                                  "its U is the largest U of d_i − d_1 over the faces, {u} (k = "
                                  "{k}), each at least the laboratory's CMC {cmc}"),
                       faces=result.faces, u=f"{np.max(u1):.4f}\"", k=f"{k:.2f}",
                       cmc=f"{held.floor:g}\"")
    else:
        name = message(QT_TR_NOOP("Polygon, {faces} faces, cross-calibrated (closure principle); "
                                  "its U is the largest U of d_i − d_1 over the faces, {u} (k = "
                                  "{k})"),
                       faces=result.faces, u=f"{np.max(u1):.4f}\"", k=f"{k:.2f}")
    return SentReference(POLYGON_FACE_DEVIATIONS, {i + 1: float(d[i] - d[0]) for i in range(result.faces)},
                         {i + 1: float(u1[i]) for i in range(result.faces)}, float(k), name,
                         left_out=left_out)


class CrossCal(Workbench[CrossCalResult], IssuesCertificates[CrossCalResult],
               WritesCorrectionTable[CrossCalResult], ShowsHeadline[CrossCalResult],
               SendsReference[CrossCalResult], GuidesAcquisition):
    key = KEY
    title = TITLE
    columns = COLUMNS
    parameters = PARAMETERS
    sample_file = "crosscal_sample.csv"
    method_reference = ("Kinnane M. et al., Metrologia 52 (2015) 244; Estler W. T., Uncertainty "
                        "analysis for angle calibrations using circle closure, J. Res. NIST 103 "
                        "(1998) 141")
    presenter = "widgets.crosscal.presenter:CrossCalPresenter"
    traceability_basis = QT_TR_NOOP(
        "Metrological traceability: the results are traceable to the SI unit of plane angle "
        "through the closure of the circle (2π rad, exact): the polygon and the encoder are "
        "calibrated against each other by the closure principle; no reference standard is used.")
    nominal_column = "position"
    entry_column = "ac_x_arcsec"
    reference_kind = POLYGON_FACE_DEVIATIONS
    # the certificate's U columns (polygon: about the mean, from face 1; encoder: about the
    # mean, from step 0), and the polygon's face deviations in the DCC's shared form
    dcc_uncertainty_columns = {"deviation": "", "deviation_from_face1": "from_face1_",
                               "error": "", "error_from_step0": "from_step0_"}
    dcc_face_deviations_column = "deviation_from_face1_arcsec"
    analyze = staticmethod(analyze)
    split_incomplete = staticmethod(split_incomplete)
    plan_reading_keys = ("encoder_deg", "ac_x_arcsec", "ac_y_arcsec")

    def entry_plan(self, settings):
        mountings = int(settings.get("plan_mountings", 0) or 0)
        if not mountings:
            return None
        faces = int(settings.get("faces", 0) or 0)
        if not faces:
            raise ValueError(message(QT_TR_NOOP("the entry plan needs the number of faces "
                                                "(set-up: faces n)")))
        return crosscal_plan(faces, mountings)

    to_json = staticmethod(to_json)
    sent_reference = staticmethod(polygon_reference)
    rows_from_table = staticmethod(matrix_rows)  # the n × n matrix labs write
    acquisition_guide = staticmethod(crosscal_guide)
    summary = staticmethod(summary)
    verdict = staticmethod(verdict)

    def certificate(self, result, metadata, source_name="", settings=None):
        from models.crosscal.report import crosscal_certificate  # the PDF's content, when asked

        _check_analysed_with(result, settings)
        return crosscal_certificate(result, metadata, source_name, self.method_reference,
                                    settings)

    def inputs_not_stated(self, result, metadata):
        # the comparator's calibration, where no comparator is listed with a stated U: an
        # input of every reading whether or not a standard is listed (assessment 73 M2)
        from models.crosscal.export import comparator_not_stated

        return comparator_not_stated(metadata)

    def dcc_point_uncertainties(self, result, metadata=None, settings=None):
        """The encoder's error from step 0: its U (the certificate's "U from step 0", the
        comparators in) with the solution's k, as the polygon's from face 1 in
        :meth:`uncertainty_budgets`."""

        s = result.solution
        if not s.separable or result.encoder_u_withheld is not None:
            return {}
        return {"error_from_step0_arcsec": result.u_from_first("encoder", metadata)}

    def decided_errors(self, result, metadata):
        # the item's values about their mean (None: the design does not determine them)
        from models.crosscal.report import _per_point

        return _per_point(result)[0]

    def uncertainty_budgets(self, result, metadata, settings=None):
        # each item's budget as its certificate states it (about the mean of the n values);
        # nothing when the design does not separate them (the values are not the result)
        import dataclasses

        from models.certificate.metadata import CertificateMetadata
        from models.crosscal.report import crosscal_budget

        _check_analysed_with(result, settings)
        s = result.solution
        if not s.separable:
            return {}
        names = ("encoder_error_arcsec", "polygon_deviation_arcsec")
        plain = CertificateMetadata.from_dict({"certificate_number": "", "lab_name": ""})
        if (not metadata.item_resolution_in("arcsec") and not comparators_stated(metadata)
                and metadata.coverage_probability == plain.coverage_probability):
            budgets = dict(zip(names, result.bench_budgets, strict=True))  # computed once
        else:
            budgets = {name: crosscal_budget(dataclasses.replace(result, certificate_of=item),
                                             metadata)
                       for item, name in zip(("encoder", "polygon"), names, strict=True)}
        budgets["polygon_deviation_from_face1_arcsec"] = result.u_from_first("polygon", metadata)
        # the certificate's "U from step 0" (models/crosscal/report.py), the comparators in
        budgets["encoder_error_from_step0_arcsec"] = result.u_from_first("encoder", metadata)
        if result.encoder_u_withheld is not None:  # the encoder's U null (to_json says why)
            budgets["encoder_error_arcsec"] = None
            budgets["encoder_error_from_step0_arcsec"] = None
        if result.polygon_u_withheld is not None:  # the face deviations' U null, likewise
            budgets["polygon_deviation_arcsec"] = None
            budgets["polygon_deviation_from_face1_arcsec"] = None
        return budgets

    def uncertainty_withheld(self, result):
        # the encoder's U null (no closure reading, no drift bound): why, whichever item is
        # certified (its arrays' U are null in either JSON)
        return separated([result.encoder_u_withheld or "", result.polygon_u_withheld or ""],
                         "; ")

    def certified_cmc_setting(self, settings):
        item = str((settings or {}).get("certificate_of", "polygon"))
        return "cmc_encoder_arcsec" if item == "encoder" else "cmc_arcsec"

    def certified_json(self, result, metadata, settings=None):
        """With the certificate details, the U arrays that exist since before #39 are the
        certificate's too (the comparators' stated U in): one figure for each value in the
        JSON, the certificate and the DCC."""
        if not result.solution.separable:
            return {}
        budgets = self.uncertainty_budgets(result, metadata, settings)
        encoder, polygon = budgets["encoder_error_arcsec"], budgets["polygon_deviation_arcsec"]
        from_face1 = budgets["polygon_deviation_from_face1_arcsec"]
        return {"encoder_error_U_arcsec": None if encoder is None else _list(encoder.expanded),
                "polygon_deviation_U_arcsec": None if polygon is None else _list(polygon.expanded),
                "polygon_deviation_U_from_face1_arcsec":
                    None if from_face1 is None else _list(from_face1.expanded)}

    def correction_table(self, result, settings, path, metadata=None) -> str:
        """The polygon's deviations as the polygon workbench reads a certificate (--table,
        and the window's "Save face deviations for the polygon workbench"), each with the U
        from face 1 that the certificate states with the details ``metadata``."""
        from models.crosscal.export import write_polygon_reference

        return write_polygon_reference(result, settings, path, metadata)

    def printed_rounding(self, result, metadata, settings=None):
        """The largest U each item's certificate states ({"encoder": U, "polygon": U}):
        its budget's, with the certificate details' inputs (the comparators' U)."""
        try:
            budgets = self.uncertainty_budgets(result, metadata, settings)
        except (ValueError, ArithmeticError, IndexError):
            return None
        out = {item: float(budgets[name].max_expanded) for item, name in (
            ("encoder", "encoder_error_arcsec"), ("polygon", "polygon_deviation_arcsec"))
            if budgets.get(name) is not None}
        return out or None

    def printed_headline(self, result, printed=None):
        s, out = result.solution, {}
        for item, values, name in (
                ("encoder", s.encoder_error_arcsec, "encoder error peak-to-peak (\")"),
                ("polygon", s.polygon_deviation_arcsec, "face deviation peak-to-peak (\")")):
            if values is not None:
                out[name] = _printed(values, math.nan, printed, item)["ptp"][:-1]
        return out

    def headline(self, r):
        s = r.solution
        return {"encoder error peak-to-peak (\")": float(np.ptp(s.encoder_error_arcsec))
                if s.encoder_error_arcsec is not None else float("nan"),
                "face deviation peak-to-peak (\")": float(np.ptp(s.polygon_deviation_arcsec))
                if s.polygon_deviation_arcsec is not None else float("nan")}


CROSSCAL = CrossCal()
