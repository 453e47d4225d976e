"""What every workbench provides to the window, the command line and the project file.

A workbench is one object of a class that derives from :class:`Workbench`, the core
every workbench has (its key and title, readings columns, settings declared once as
:class:`~models.parameters.Parameter`, analysis, JSON, summary, sample file, method
reference and the dotted path of its presenter), and from the capabilities it has, each
a small abstract class of its own::

    class Fringe(Workbench[FringeResult], IssuesCertificates[FringeResult],
                 WritesCorrectionTable[FringeResult], ShowsHeadline[FringeResult]):
        key = KEY  # from models/fringe/__init__.py, with TITLE
        ...

The core and every capability that takes or gives a result are generic over the result's
type (``ResultT``): a workbench names its result class once per base, and mypy checks every
method it defines and every call of the shared code against it (``Workbench[Any]`` where the
shared code holds any workbench).

Shared code asks ``isinstance(workbench, WritesCorrectionTable)``, never a workbench's
key, and never whether a view happens to have an attribute: a capability that the window
serves through the workbench's view names what it needs of it in ``view_needs`` (dotted
attribute paths, e.g. ``"error_plot.corrected_plot"``), and the contract test builds every
workbench's real view and checks that it has each (:func:`view_needs`). The capabilities
are abstract mixins, not ``typing.Protocol``: a workbench states
in its class line what it does (one place to read, one place to grep), a capability
whose method is missing fails when the workbench is created rather than when a user
first clicks, and ``isinstance`` answers by declaration — a runtime-checkable protocol
only looks for an attribute of that name, so a helper that happened to be called
``verdict`` would grant a capability.
"""

from __future__ import annotations

import dataclasses
import math
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any, ClassVar, Generic, TypeVar

import numpy as np

from models.certificate.traceability import test_report_statement, traceability_gaps
from models.messages import QT_TR_NOOP, joined, listed, message, reason_of
from models.parameters import Parameter, SettingsError, Shortcut, check_parameters
from models.readings.incomplete import (
    IncompleteUnit,
    RowInProgress,
    point_groups,
    subset,
    with_row_in_progress,
)
from models.readings.sheet import Column, ParsedReadings
from models.sign_convention import SIGN_CONVENTION, SIGN_CONVENTION_TEXT
from models.uncertainty.lab_scope import cmc_quantity, scope_statement

if TYPE_CHECKING:  # for their types only: a plain analyze draws no plot and plans no entry
    from models.certificate.document import CertificateDocument
    from models.certificate.metadata import CertificateMetadata
    from models.plots import PlotFigure
    from models.readings.entry_plan import EntryPlan

__all__ = ["CAPABILITIES", "SIGN_CONVENTION", "SIGN_CONVENTION_TEXT", "AcceptsReference",
           "view_needs",
           "AcceptsRuns", "ComparesAfterLog", "GuidesAcquisition", "IssuesCertificates",
           "JudgesSignals", "OverlaysRuns", "ResultT", "SendsReference", "SendsRuns",
           "SentReference", "SettingsError", "ShowsHeadline", "Workbench",
           "RAW_ERROR_U_NOTE", "WritesCorrectionTable", "raw_error_u_note"]

# the type of a workbench's result (its analysis gives it; everything else takes it)
ResultT = TypeVar("ResultT")

# Every workbench states errors of indication (VIM 4.1): indicated − reference; a correction
# is the negative of an error (models.sign_convention; SIGN_CONVENTION(_TEXT) imported above)

#: what a concrete workbench class must set (checked when its object is made)
_REQUIRED = ("key", "title", "columns", "parameters", "sample_file", "method_reference",
             "presenter")


class Workbench(ABC, Generic[ResultT]):
    """The core of every workbench. A concrete class sets the attributes below and the
    three methods; its one object is listed in :mod:`models.registry`."""

    key: ClassVar[str]  # the project file's and the command line's name of it
    title: ClassVar[str]  # the tab's, the certificate's and the messages' (QT_TR_NOOP)
    columns: ClassVar[tuple[Column, ...]]
    parameters: ClassVar[tuple[Parameter, ...]]
    sample_file: ClassVar[str]  # a file in resources/samples/
    method_reference: ClassVar[str]  # the published method or standard
    presenter: ClassVar[str]  # "package.module:Class", imported only by the window
    # instrument-style entry: the column a nominal step fills as rows are added, and the
    # column where a row's readings begin (Return after an edit goes there, one row down)
    nominal_column: ClassVar[str] = ""
    entry_column: ClassVar[str] = ""
    # the columns whose cells are a point's readings (typed or captured); the entry plan
    # (Workbench.entry_plan) fills the others
    plan_reading_keys: ClassVar[tuple[str, ...]] = ()
    # command-line switches that set one of the settings (``--zenith``)
    shortcuts: ClassVar[tuple[Shortcut, ...]] = ()
    # the settings the README's sample certificate is made with (beside the defaults)
    sample_settings: ClassVar[Mapping[str, Any]] = {}

    def __init__(self) -> None:
        missing = [name for name in _REQUIRED if not hasattr(self, name)]
        if missing:
            raise TypeError(f"workbench {type(self).__name__} does not set {', '.join(missing)}")

    @abstractmethod
    def analyze(self, parsed: ParsedReadings, settings: Mapping[str, Any]) -> ResultT:
        """The result of the parsed readings analysed with the checked settings."""

    @abstractmethod
    def to_json(self, result: ResultT) -> dict[str, Any]:
        """The result as the command line's JSON (``anglebench analyze … --json``)."""

    @abstractmethod
    def summary(self, result: ResultT) -> str:
        """The result as readable text."""

    def entry_plan(self, settings: Mapping[str, Any]) -> EntryPlan | None:
        """The order its points are taken in, from the settings (models/readings/entry_plan.py;
        None: no plan set, entry follows the nominal step). ValueError why a plan set cannot
        be made."""
        return None

    def reading_positions(self, settings: Mapping[str, Any]) -> Mapping[str, tuple[str, str]]:
        """{reading column: (the column of its row holding the position the plan expects the
        reading at, the unit of both: "deg" or "mm")} — positioning's measured position and
        its target. A take's reading there nearer another of the plan's targets is warned of
        (models/capture/wrong_target.py), and one in degrees is written in its target's
        turn (models/capture/take_cells.py ``in_turn_of``). Empty by default: every reading
        as sent, none checked against a target."""
        return {}

    def shown_in_blank(self, settings: Mapping[str, Any]
                       ) -> Mapping[str, tuple[Callable[[Callable[[str], str]], str | None], str]]:
        """{column key: (the figure a blank cell of that column shows, worked out from its
        row's cells — ``text(key)`` a cell's text — or None; what to say of it
        (QT_TR_NOOP))}: positioning's deviation from the measured position, as the analysis
        takes it. Shown in the readings table, never written into the sheet. Empty by
        default."""
        return {}

    def column_units(self, settings: Mapping[str, Any]) -> Mapping[str, str]:
        """{column key: its unit as ``settings`` make it}, for a column whose unit is a
        setting (positioning's target, measured and deviation): shown in the readings
        table's header as a column's own unit is. Empty by default."""
        return {}

    def column_origins(self, settings: Mapping[str, Any]) -> Mapping[str, float]:
        """{column key: what the analysis adds to the column's values, in its unit, to read
        them as it does}, for a column whose origin is a setting (the theodolite's zenith
        angle V: −90°, E = V − 90°): the register compares readings by the values the
        analysis reads (models/register/readings_identity.py). Empty by default."""
        return {}

    def derived_columns(self, settings: Mapping[str, Any]) -> Mapping[str, tuple[str, str]]:
        """{column key: (source, other)} for a column whose value the analysis takes as
        source − other where its cell is blank, and from its cell (not the source) where it
        is given (positioning's deviation: measured − target, in the deviation unit): the
        register compares readings as the analysis takes them (readings_identity.py), so a
        deviation typed as a measured position is the same reading. Empty by default."""
        return {}

    def read_cells(self, parsed: ParsedReadings, settings: Mapping[str, Any]
                   ) -> Mapping[str, list[Any]]:
        """{column key: each parsed row's cell as the analysis reads it}, for a column the
        analysis reads otherwise than as typed: a choice by its meaning (the first of its
        group: positioning's "up" and "↑" are "+"), a blank cell as the analysis fills it
        (positioning's direction from the order of the targets, its run as the k-th
        approach), through the functions the analysis takes them by. The register compares
        readings by them (models/register/readings_identity.py), so a direction or run typed
        where the analysis would derive the same is the same readings. Empty by default:
        every cell as typed (as it parses)."""
        return {}

    def setting_units(self, settings: Mapping[str, Any]) -> Mapping[str, str]:
        """{setting key: its unit as ``settings`` make it}, for a number setting whose unit
        is another setting's (positioning's budget inputs, in the deviations' unit): shown
        beside its field as a declared unit is. Empty by default."""
        return {}

    def split_incomplete(self, parsed: ParsedReadings, settings: Mapping[str, Any]
                         ) -> tuple[ParsedReadings, IncompleteUnit | None]:
        """The readings of the complete units, and the last unit when it is in progress
        (a set, mounting, run short of readings; models/readings/incomplete.py); by
        default every reading is complete."""
        return parsed, None

    #: the columns that say which point a reading is (face, set, direction …), on which
    #: the n readings of a point agree (models.readings.repeats): a workbench with the
    #: setting ``readings_per_point`` names them; empty: every reading its own point
    point_keys: ClassVar[tuple[str, ...]] = ()

    def point_name(self, parsed: ParsedReadings, index: int) -> str:
        """What point reading ``index`` is ("face 3"), for the progress line of a point
        short of its n readings; by default its sheet row."""
        return message(QT_TR_NOOP("row {row}"), row=int(parsed.row_index[index]) + 1)

    def lone_point_name(self, parsed: ParsedReadings, index: int) -> str:
        """What point reading ``index`` is when that point, short of its n readings, is in
        progress on its own (no unit of the workbench is: a polygon set's closure, read
        after every face of the set), named with the unit it belongs to ("set 1: closure
        on face 1"): the progress line says "set 1: closure on face 1: reading 1 of 2".
        "" (the default): the point is counted ("point 8: 1 of 2 readings")."""
        return ""

    def split_in_points(self, parsed: ParsedReadings, settings: Mapping[str, Any]
                        ) -> tuple[ParsedReadings, IncompleteUnit | None]:
        """:meth:`split_incomplete` with n readings per point: the units are found among
        the points (each point's first reading standing for it), and the last point, when
        it has fewer than n readings, is part of the run in progress — of the last unit
        when that unit is in progress or it completes it, else the unit in progress on its
        own ("point 7: 1 of 2 readings"). A point whose readings disagree on what point
        they are (a reading missing in the middle), or a last point with more than n
        readings, finds no run in progress: the analysis refuses it, naming the rows."""
        n = int(settings.get("readings_per_point", 1) or 1)
        keys = [k for k in self.point_keys if k in parsed.values]
        if n <= 1 or not keys or parsed.n == 0:
            return self.split_incomplete(parsed, settings)
        groups, short = point_groups(parsed, n)

        def same(i: int, j: int) -> bool:
            for key in keys:
                a, b = parsed[key][i], parsed[key][j]
                if isinstance(a, float) or isinstance(b, float):
                    a, b = float(a), float(b)
                    if not (math.isnan(a) and math.isnan(b)) and not abs(a - b) <= 1e-9:
                        return False
                elif (a or "") != (b or ""):
                    return False
            return True

        if not all(same(int(g[0]), int(i)) for g in groups for i in g[1:]):
            return parsed, None  # a reading missing in the middle: refused by the analysis
        if short and len(groups) > 1 and same(int(groups[-1][0]), int(groups[-2][0])):
            return parsed, None  # the last point has more than n readings: refused
        firsts = np.zeros(parsed.n, dtype=bool)
        firsts[[int(g[0]) for g in groups]] = True
        points = subset(parsed, firsts)
        one = {**settings, "readings_per_point": 1}
        last = len(groups) - 1
        unit = self.split_incomplete(points, one)[1]
        counted = 0 if unit is None else unit.readings
        if short and (unit is None or last not in unit.rows):
            head = subset(points, np.arange(points.n) != last)
            unit = self.split_incomplete(head, one)[1] if head.n else None
            if unit is not None and last - 1 in unit.rows:
                counted = unit.readings
                unit = dataclasses.replace(unit, rows=(*unit.rows, last))
            else:  # the short point on its own
                unit = IncompleteUnit("point", float(last + 1), short, n, 0, 0, (last,))
                counted = short
        elif short and unit is not None:
            counted = unit.readings - 1
        if unit is None:
            return parsed, None
        rows = [int(i) for p in unit.rows for i in groups[p]]
        keep = np.ones(parsed.n, dtype=bool)
        keep[rows] = False
        sheet = parsed.row_index.astype(int) + 1
        named = "" if not short else (self.point_name(parsed, int(groups[last][0]))
                                      if unit.unit != "point" else
                                      self.lone_point_name(parsed, int(groups[last][0])))
        return subset(parsed, keep), dataclasses.replace(
            unit, readings=counted, first_row=int(sheet[rows[0]]), last_row=int(sheet[rows[-1]]),
            rows=tuple(rows), point=named, point_readings=short if named else 0, per_point=n)

    def analyze_as_far_as_it_goes(self, parsed: ParsedReadings, settings: Mapping[str, Any],
                                  typing: RowInProgress | None = None) -> ResultT:
        """The result of the complete units (its ``incomplete``: the last unit in progress,
        whose readings enter no figure, with n readings per point its last point short of
        them too: :meth:`split_in_points`); ValueError when no unit is complete yet.

        ``typing``: the row a reading is being typed into (models/readings/incomplete.py
        row_in_progress: not among ``parsed``'s readings), part of the run in progress —
        said after the unit in progress, or on its own — so that a certificate waits for
        it as for a unit (row81)."""
        complete, unit = self.split_in_points(parsed, settings)
        if unit is None and typing is None:
            return self.analyze(parsed, settings)
        if unit is None:
            complete = parsed
        progress = with_row_in_progress(unit, typing) if typing is not None else unit
        assert progress is not None
        if complete.n == 0:
            raise ValueError(message(QT_TR_NOOP("{progress}: none is complete yet"),
                                     progress=progress.text()))
        try:
            result = self.analyze(complete, settings)
        except ValueError as exc:
            raise ValueError(joined((reason_of(exc), message(
                QT_TR_NOOP(" (in progress, left out: {progress})"),
                progress=progress.text())))) from None
        # a field of every result that has units
        object.__setattr__(result, "incomplete", progress)
        return result

    def check_settings(self, checked: dict[str, Any]) -> None:  # noqa: B027 - none by default
        """The checks across settings (SettingsError naming the key); each setting alone
        is checked by its declaration."""

    def error_unit(self, settings: Mapping[str, Any]) -> str:
        """The unit of the errors this workbench finds with ``settings`` (a key of
        models.quantity.UNITS): a certificate's tolerance, resolution and standards'
        uncertainties are converted to it, and a project file of schema 1, which wrote
        them as bare numbers in it, is read in it."""
        return "arcsec"

    def rows_from_table(self, table: Any) -> list[list[str]] | None:
        """A file or pasted block whose headers name none of its columns, read in this
        workbench's own layout (the cross-calibration's n × n matrix) as readings rows of
        its columns; None: not such a table (the column mapping is asked)."""
        return None

    def validation_cases(self, trials: int) -> list[Any]:
        """More reference cases (models.validation.cases.ValidationCase: check figures of the
        method's publication, simulations with known truth) besides those of its folder's
        ``validation_cases.py`` (``validation_cases(trials)``, where every workbench keeps its
        own; models.validation.run gathers both)."""
        return []

    def __repr__(self) -> str:
        return f"<workbench {self.key}>"

    @property
    def default_settings(self) -> dict[str, Any]:
        return {p.key: p.default for p in self.parameters}

    def parameter(self, key: str) -> Parameter:
        return next(p for p in self.parameters if p.key == key)

    def checked_settings(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        """The settings with defaults, each checked (types and ranges, then across
        settings): for a project file, the form and the command line alike."""
        checked = check_parameters(self.parameters, settings)
        self.check_settings(checked)
        return checked

    def settings_with_defaults(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        merged = dict(self.default_settings)
        if settings:
            merged.update({k: v for k, v in settings.items() if k in self.default_settings})
        return merged

    def headline_figures(self, result: ResultT) -> dict[str, float]:
        """The headline figures that are numbers (the window's table, the register's trend)."""
        if not isinstance(self, ShowsHeadline):
            return {}
        return {k: float(v) for k, v in self.headline(result).items()
                if isinstance(v, int | float) and math.isfinite(v)}

    def printed_rounding(self, result: ResultT, metadata: CertificateMetadata,
                         settings: Mapping[str, Any] | None = None) -> Any:
        """How the certificate of ``result`` (with ``metadata``) rounds the figures the
        window shows too, the workbench's own (the decimal of its largest U, GUM 7.2.6; each
        figure's decimal): given to :meth:`summary`, the verdict and
        :meth:`printed_headline` as ``printed``, so that the window shows what the
        certificate prints. None: the workbench prints them to a fixed decimal, which its
        summary uses already (then ``printed`` is not given)."""
        return None

    def printed_headline(self, result: ResultT, printed: Any = None) -> dict[str, str]:
        """The headline figures the certificate prints, as it prints them ({name: text},
        the names of :meth:`headline`), rounded by ``printed`` (:meth:`printed_rounding`;
        None: as the summary without it); the window's figures table shows these, and the
        unrounded value of any other (the register's trend keeps every figure unrounded)."""
        return {}

    def listed_setting(self, parameter: Parameter, settings: Mapping[str, Any]) -> str:
        """``parameter``'s value in ``settings`` (checked) as the certificate lists it: its
        declaration's text (:meth:`Parameter.text`); a workbench whose setting takes its unit
        from another setting (positioning's inputs, in the deviations' unit) says it here."""
        return parameter.text(settings[parameter.key])

    def certificate_document(self, result: ResultT, metadata: CertificateMetadata, source_name: str = "",
                             settings: Mapping[str, Any] | None = None) -> CertificateDocument:
        """The certificate content of ``result`` (see models.certificate.document), listing
        the ``settings`` it was analysed with as their declarations word them.

        ``settings`` are the ones ``result`` was analysed with: the certificate's budget
        reads the settings it needs (the laboratory's CMC, …) from them, and the listing
        states the same ones, so what the certificate says and what it computed cannot
        differ. The caller keeps a result and its settings together (the window's
        presenter: ``result_settings``); None: the defaults for the budget, no listing."""
        if not isinstance(self, IssuesCertificates):
            raise ValueError(f"{self.title}: no certificate is defined")
        checked = self.checked_settings(settings)
        document = self.certificate(result, metadata, source_name,
                                    checked if settings is not None else None)
        if settings is not None:
            # the window's entry aids (the entry plan) are no setting of the analysis
            listing = tuple((p.label, self.listed_setting(p, checked)) for p in self.parameters
                            if not p.entry_aid)
            document = dataclasses.replace(document, settings=listing)
        basis = self.traceability_basis
        if basis and not document.traceability_basis:
            document = dataclasses.replace(document, traceability_basis=basis)
        gaps = traceability_gaps(document.metadata, self.measurand_standards,
                                 document.stated_inputs, self.roles_stated_only)
        if gaps:
            document = dataclasses.replace(document, traceability_gaps=tuple(gaps))
        why = test_report_statement(document)
        if why:
            document = dataclasses.replace(document, statements=(why, *document.statements))
        # an accredited calibration certificate with no CMC stated says that its U was not
        # compared with the scope's (ILAC-P14 5.4; assessment 76 L7), where the workbench
        # has a CMC setting to state it in
        accredited = (bool(document.metadata.lab_accreditation.strip())
                      and not document.is_test_report
                      and any(cmc_quantity(p) for p in self.parameters))
        scope = scope_statement(document.budget, document.unit, document.figures_raised_to_cmc,
                                accredited=accredited)
        if scope:
            document = dataclasses.replace(document, statements=(*document.statements, scope))
        return document


#: what the DCC states of a raw error's U (IssuesCertificates.dcc_column_notes): one rule on
#: every workbench (theodolite, polygon, fringe), the rule of the JSON's
#: expanded_uncertainty_raw_error_* (the polygon's per-set error_arcsec)
RAW_ERROR_U_NOTE = QT_TR_NOOP(
    "U of the raw error: the certificate's budget without the inputs of the correction that "
    "the raw error is before ({inputs}); every other input (the readings', the standards') is "
    "in it, at each point with its own k. So on every workbench: the raw error is what the "
    "readings give, with the effect the correction removes still in it.")


def raw_error_u_note(*inputs: str) -> Any:
    """:data:`RAW_ERROR_U_NOTE` naming the correction's ``inputs`` (QT_TR_NOOP budget input
    names), each in the document's language."""
    return message(RAW_ERROR_U_NOTE, inputs=listed(message("“{name}”", name=message(name))
                                                   for name in inputs))


class IssuesCertificates(ABC, Generic[ResultT]):
    """Issues a test certificate of its result."""

    #: what its results are traceable through when no reference standard enters them
    #: (QT_TR_NOOP; the closure of the circle for a self-calibrating method); None: the
    #: certificate states traceability through the reference standards listed, as usual
    traceability_basis: ClassVar[str | None] = None
    #: its settings always give a tolerance (the polygon's grade): a decision is always made
    tolerance_in_settings: ClassVar[bool] = False
    #: the standards that carry the measurand, each (its role, models.certificate.metadata.
    #: STANDARD_ROLES; its name, a QT_TR_NOOP text): a calibration certificate states
    #: traceability only when each is listed with a certificate and a stated U; otherwise the
    #: document is a test report and says why, naming the ones not listed
    measurand_standards: ClassVar[tuple[tuple[str, str], ...]] = ()
    #: the roles of ``measurand_standards`` that only a standard stating its role carries (a
    #: standard listed with no role fills none of them: the fringe's phase or angle reference,
    #: assessment 78 H1); the others are told from a standard's fields, or filled as before
    roles_stated_only: ClassVar[tuple[str, ...]] = ()
    #: a standard listed with its certificate and no U stands behind inputs stated in its
    #: settings (the fringe's ADC figures), which it names as not stated itself; otherwise a
    #: standard listed with no stated U is an input not stated (the JSON's
    #: uncertainty_inputs_not_stated; its certificate's build_certificate says the same)
    standards_in_settings: ClassVar[bool] = False
    #: its digital certificate (models/dcc/writer.py): each per-point column of the
    #: certificate (its name without the unit) whose U the certificate prints beside it →
    #: that U column's middle part (``expanded_uncertainty_`` + it + the unit)
    dcc_uncertainty_columns: ClassVar[Mapping[str, str]] = {}
    #: the per-point column that holds a polygon's face deviations from face 1 (its U column
    #: the one dcc_uncertainty_columns names): stated in the shared form the polygon
    #: workbench reads back (models/dcc/vocabulary.py); "": none
    dcc_face_deviations_column: ClassVar[str] = ""
    #: per-point column → what the DCC states of its U (QT_TR_NOOP) where the certificate
    #: prints no U beside it (e.g. a U the budget gives without one of its inputs)
    dcc_column_notes: ClassVar[Mapping[str, str]] = {}

    def dcc_reference_face_deviations(self, result: ResultT, metadata: CertificateMetadata) -> Any:
        """A reference polygon's face deviations from face 1 the result rests on, with the U
        and k its certificate states: (deviations, U, k) in arcseconds, stated in the DCC's
        shared form; None: none."""
        return None

    def dcc_point_uncertainties(self, result: ResultT, metadata: CertificateMetadata | None = None,
                                settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """U and k per point of certificate columns whose U no budget of
        :meth:`uncertainty_budgets` holds (e.g. an error stated from a reference point),
        by column name: PointUncertainty, with the certificate details ``metadata`` (the
        standards whose U enters) and the ``settings`` the result was analysed with. The DCC
        takes each point's k from them."""
        return {}

    @abstractmethod
    def certificate(self, result: ResultT, metadata: CertificateMetadata, source_name: str = "",
                    settings: Mapping[str, Any] | None = None) -> CertificateDocument:
        """The :class:`~models.certificate.document.CertificateDocument` of ``result``
        (without the settings' listing: :meth:`Workbench.certificate_document` adds it),
        its budget from the ``settings`` ``result`` was analysed with (None: the defaults)."""

    def uncertainty_budgets(self, result: ResultT, metadata: CertificateMetadata,
                            settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """The budget (models.uncertainty.budget.UncertaintyBudget, or
        models.certificate.uncertainty_json.PointUncertainty) of each error array of the
        JSON, by its name (``"object/name"`` for an array inside an object): the JSON gets
        ``expanded_uncertainty_<name>`` and ``coverage_factor_<name>`` beside it. With the
        ``settings`` ``result`` was analysed with (None: the defaults)."""
        return {}

    def uncertainty_withheld(self, result: ResultT) -> str:
        """Why the U of some of the JSON's arrays is null although their budgets could be
        evaluated (:meth:`uncertainty_budgets` gives them as None): the JSON's
        ``uncertainty_withheld`` says so ("" when every U is given)."""
        return ""

    def certified_cmc_setting(self, settings: Mapping[str, Any] | None) -> str:
        """The setting of the laboratory's CMC for the item the certificate is of, where the
        workbench has CMCs for two items (the JSON's ``laboratory_cmc`` states it first, the
        other under ``other_quantities``); "": the one that holds the most arrays."""
        return ""

    def inputs_not_stated(self, result: ResultT, metadata: CertificateMetadata) -> list[str]:
        """The inputs the certificate names as not stated, so not in U (untranslated): the
        JSON lists them (``uncertainty_inputs_not_stated``), and no statement of conformity
        is made while one is. None by default."""
        return []

    def decided_errors(self, result: ResultT, metadata: CertificateMetadata) -> Any:
        """The error curve the statement of conformity is made on (the array the
        certificate passes to models.uncertainty.conformity.decide_conformity, in the
        budget's unit): the JSON states its measured figure even when no U can be given
        for it. None when the workbench does not say."""
        return None

    def decided_tolerance(self, result: ResultT, metadata: CertificateMetadata, unit: str) -> float | None:
        """The tolerance the statement of conformity is made against, in ``unit`` (the
        certificate details' by default); None when none is set."""
        return metadata.tolerance_in(unit)

    def certified_json(self, result: ResultT, metadata: CertificateMetadata,
                       settings: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """Keys of the JSON whose figures the certificate details change (a figure's
        interval with the reference standards' U): they replace the keys of ``to_json``
        of the same name, so that the JSON states what the certificate prints (with the
        ``settings`` ``result`` was analysed with)."""
        return {}

    def certificate_doubt(self, result: ResultT) -> str:
        """Why a certificate of ``result`` needs the user's confirmation first ("" when it
        does not): figures no instrument of the kind shows (the window asks; the command
        line refuses without --confirm-implausible)."""
        return ""

    def certificate_refusal(self, result: ResultT) -> Any:
        """Why no certificate of ``result`` can be issued whatever its details ("" when one
        can): the window says so before it asks for the details (day review 69 F6: a
        positioning record of 1 run was refused only after the whole details dialog)."""
        return ""


class WritesCorrectionTable(ABC, Generic[ResultT]):
    """Writes a correction or compensation table (``anglebench analyze … --table``, the
    window's export button)."""

    @abstractmethod
    def correction_table(self, result: ResultT, settings: Mapping[str, Any], path: str,
                         metadata: CertificateMetadata | None = None) -> str:
        """Writes the table of ``result`` to ``path``; returns what was written. A table
        that states uncertainties states them as the certificate does with its details
        ``metadata`` (None: none given)."""


class JudgesSignals(ABC, Generic[ResultT]):
    """Its result holds two quadrature signals' fits: they are judged against a signal
    tolerance preset and an interpolator table is made from them (``--signal-preset``,
    ``--interpolator-table``: models/fringe/signal_tolerance.py, interpolator_table.py).
    The command line reaches them only through these methods."""

    #: the argparse destinations of its options (a workbench without the capability
    #: refuses them)
    signal_flags: tuple[str, ...] = ()
    #: its view shows a read head's signals live against the same tolerances (the window's
    #: Instrument › Live signals…, app/capture/signal_live.py): the panel and its opener
    view_needs: ClassVar[tuple[str, ...]] = ("live_signals", "open_live_signals")

    @abstractmethod
    def add_signal_arguments(self, parser: Any, words: Callable[[str], str]) -> None:
        """Its options, their help in the language of ``words``."""

    @abstractmethod
    def signal_setup(self, args: Any) -> Any:
        """What the options ask for; ValueError (a message) when they do not hold."""

    @abstractmethod
    def signal_results(self, args: Any, result: ResultT, setup: Any
                       ) -> tuple[dict[str, Any], list[Any], Any]:
        """(the JSON keys to add, the summary lines, the table to write or None)."""

    @abstractmethod
    def write_signal_table(self, args: Any, result: ResultT, table: Any) -> Any:
        """Write the table (OSError when it cannot be); what to say of it."""


class SendsRuns(ABC, Generic[ResultT]):
    """Its run can be sent to the workbench that accepts runs, to be judged there
    (ISO 230-2 / VDI 3441)."""

    @abstractmethod
    def run_rows(self, result: ResultT) -> list[list[str]]:
        """The result as readings rows (target in °, run, direction, deviation in arcsec)."""


class AcceptsRuns(ABC):
    """Takes the runs other workbenches send (their :meth:`SendsRuns.run_rows`)."""

    @abstractmethod
    def settings_for_runs(self, settings: Mapping[str, Any]) -> dict[str, Any]:
        """``settings`` changed so that they read sent rows (targets in °, deviations in
        arcsec)."""


@dataclasses.dataclass(frozen=True)
class SentReference:
    """A reference one workbench finds for another to read with: a value per position
    (the polygon's face deviations from face 1, in ``unit``), the expanded U of each (for
    the same quantity, with ``coverage_factor``) and the reference standard's name."""

    kind: str  # what it is the reference of (SendsReference.reference_kind)
    values: dict[int, float]
    expanded_uncertainty: dict[int, float]
    coverage_factor: float
    standard_name: str  # the reference standard's name on the receiver's certificate
    unit: str = "arcsec"
    #: what the U leaves out that its certificate would state with complete details ("":
    #: nothing; the name says it too)
    left_out: str = ""

    @property
    def largest_standard_uncertainty(self) -> float:
        """max u = U / k over the positions: one figure for a budget that takes one."""
        return max(self.expanded_uncertainty.values()) / self.coverage_factor

    def digest(self) -> str:
        """SHA-256 of what is sent (the values, each U, k, the unit and the standard's name,
        figures to 1e-9): kept with the receiver, it tells whether its source would send the
        same now (app/reference_sender.py: a sent reference gone stale)."""
        import hashlib
        import json

        def figures(values: Mapping[int, float]) -> list[list[Any]]:
            return [[int(k), round(float(v), 9)] for k, v in sorted(values.items())]

        text = json.dumps([str(self.kind), figures(self.values),
                           figures(self.expanded_uncertainty),
                           round(float(self.coverage_factor), 9), self.unit,
                           str(self.standard_name)], ensure_ascii=False)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()


class SendsReference(ABC, Generic[ResultT]):
    """Its result is a reference standard's values for another workbench (the window's
    "Send … as reference"; the receiver is found by :class:`AcceptsReference`)."""

    reference_kind: ClassVar[str]  # e.g. "polygon face deviations"

    @abstractmethod
    def sent_reference(self, result: ResultT,
                       metadata: CertificateMetadata | None = None) -> SentReference:
        """The reference in ``result`` (ValueError why there is none), its U as the
        certificate states it with its details ``metadata`` (None: none given, and the
        reference's name says what its U leaves out)."""


class AcceptsReference(ABC):
    """Reads with a reference another workbench sends (:class:`SendsReference`) of its
    ``accepted_reference`` kind; its presenter's ``accept_reference`` fills the values, and
    its ``held_reference`` gives them as they are held now (by position)."""

    accepted_reference: ClassVar[str]
    #: the notice its view shows when the reference it holds no longer is what its source
    #: would send (widgets/reference_notice.py; app/reference_sender.py)
    view_needs: ClassVar[tuple[str, ...]] = ("reference_notice",)


class ComparesAfterLog(ABC, Generic[ResultT]):
    """Compares its result with a log measured after compensation."""

    @abstractmethod
    def after_log(self, path: Any, settings: Any) -> ResultT:
        """The result of the log at ``path`` analysed with ``settings`` (ValueError why not)."""

    @abstractmethod
    def compare_after(self, before: ResultT, after: ResultT) -> Any:
        """The comparison of ``before`` and ``after`` (``as_dict()``, ``text(name)``)."""


class OverlaysRuns(ABC, Generic[ResultT]):
    """Draws a second run (before/after, an earlier certificate) over today's error curve."""

    #: the panel the overlay draws on and its legend (widgets/run_overlay.py)
    view_needs: ClassVar[tuple[str, ...]] = ("error_plot.corrected_plot",
                                             "error_plot.corrected_legend")

    @abstractmethod
    def overlay_figure(self, result: ResultT) -> PlotFigure:
        """The figure whose "corrected" series is overlaid."""


class ShowsHeadline(ABC, Generic[ResultT]):
    """States its result in one line and in a few figures."""

    @abstractmethod
    def verdict(self, result: ResultT) -> str:
        """The result in one line, shown above everything else in the window."""

    @abstractmethod
    def headline(self, result: ResultT) -> dict[str, float]:
        """The figures the register keeps to show an instrument's drift over its
        calibrations ({"name (unit)": value})."""


class GuidesAcquisition(ABC):
    """Says what to do next while readings come from an instrument (the window's
    instrument panel; models/capture/guidance.py)."""

    @abstractmethod
    def acquisition_guide(self, rows: Any, current: Mapping[str, str],
                          settings: Mapping[str, Any], step: float = 0.0) -> Any:
        """The next reading's :class:`~models.capture.guidance.NextReading` ("go to face 7
        (encoder ≈ 105°)", "θ = 12°"), from the rows above the current row (column key ->
        text), the current row's cells, the settings and the table's nominal step."""


#: every capability a workbench may declare (the contract test lists them)
CAPABILITIES = (IssuesCertificates, WritesCorrectionTable, SendsRuns, AcceptsRuns,
                ComparesAfterLog, OverlaysRuns, ShowsHeadline, GuidesAcquisition,
                SendsReference, AcceptsReference, JudgesSignals)


def view_needs(workbench: Workbench[Any]) -> dict[str, tuple[str, ...]]:
    """What each capability of ``workbench`` needs of its view, by the capability's name:
    dotted attribute paths (``"error_plot.corrected_plot"``) every view of a workbench that
    declares the capability has. The window relies on them without asking the view; the
    contract test checks each workbench's real view."""
    return {c.__name__: tuple(getattr(c, "view_needs", ())) for c in CAPABILITIES
            if isinstance(workbench, c) and getattr(c, "view_needs", ())}

