"""What every workbench provides to the GUI, the CLI and the project file.

A workbench kind is its typed readings columns, its settings (declared once as
:class:`~models.parameters.Parameter`), and pure functions: analyse the parsed
readings, turn the result into the CLI's JSON, into a readable summary and into
certificate content.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from models.messages import QT_TR_NOOP
from models.parameters import Parameter, SettingsError, check_parameters
from models.readings.sheet import Column, ParsedReadings

__all__ = ["SIGN_CONVENTION", "SIGN_CONVENTION_TEXT", "AnalysisKind", "SettingsError"]

#: Every workbench states errors of indication (VIM 4.1): indicated − reference; a
#: correction is the negative of an error.
SIGN_CONVENTION = "indicated_minus_reference"
SIGN_CONVENTION_TEXT = QT_TR_NOOP("error = indicated − reference (VIM); correction = −error")


@dataclass(frozen=True)
class AnalysisKind:
    key: str
    title: str
    columns: tuple[Column, ...]
    parameters: tuple[Parameter, ...]
    analyze: Callable[[ParsedReadings, Mapping[str, Any]], Any]
    to_json: Callable[[Any], dict[str, Any]]
    summary: Callable[[Any], str]
    sample_file: str
    method_reference: str = ""
    # (result, CertificateMetadata, source name, method reference) -> CertificateDocument
    certificate: Callable[..., Any] | None = None
    # checked settings -> None; the checks across settings (SettingsError naming the key)
    check_settings: Callable[[dict[str, Any]], None] | None = None
    # "package.module:Class" of the workbench's presenter, imported only by the window
    presenter: str = ""
    # (result, settings, path) -> what was written: the workbench's correction or
    # compensation table (``anglebench analyze … --table``, the window's export button)
    correction_table: Callable[[Any, Mapping[str, Any], str], str] | None = None
    # result -> readings rows (target, run, direction, deviation in arcsec) that the
    # positioning workbench takes: a run sent there to be judged to ISO 230-2 / VDI 3441
    positioning_rows: Callable[[Any], list[list[str]]] | None = None
    # result -> the figures the register keeps to show an instrument's drift over its
    # calibrations ({"name (unit)": value})
    headline: Callable[[Any], dict[str, float]] | None = None
    # result -> the result in one line, shown above everything else in the window
    verdict: Callable[[Any], str] | None = None
    # result -> why a certificate of it needs the user's confirmation first ("" when it does
    # not): figures no instrument of the kind shows (the window asks; the command line
    # refuses without --confirm-implausible)
    certificate_doubt: Callable[[Any], str] | None = None
    # (path, settings) -> the result of a log measured after compensation, and
    # (before, after) -> their comparison (as_dict(), text()): ValueError saying why not
    after_log: Callable[[Any, Any], Any] | None = None
    compare_after: Callable[[Any, Any], Any] | None = None
    # instrument-style entry: the column a nominal step fills as rows are added, and the
    # column where a row's readings begin (Return after an edit goes there, one row down)
    nominal_column: str = ""
    entry_column: str = ""
    # guided acquisition from an instrument (models/capture/guidance.py): (rows above,
    # the current row, settings, nominal step) -> NextReading, what to do next
    acquisition_guide: Callable[..., Any] | None = None

    def headline_figures(self, result: Any) -> dict[str, float]:
        """The headline figures that are numbers (the window's table, the register's trend)."""
        if self.headline is None:
            return {}
        return {k: float(v) for k, v in self.headline(result).items()
                if isinstance(v, int | float) and math.isfinite(v)}

    @property
    def default_settings(self) -> dict[str, Any]:
        return {p.key: p.default for p in self.parameters}

    def parameter(self, key: str) -> Parameter:
        return next(p for p in self.parameters if p.key == key)

    def checked_settings(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        """The settings with defaults, each checked (types and ranges, then across
        settings): for a project file, the form and the command line alike."""
        checked = check_parameters(self.parameters, settings)
        if self.check_settings is not None:
            self.check_settings(checked)
        return checked

    def certificate_document(self, result: Any, metadata: Any, source_name: str = "",
                             settings: Mapping[str, Any] | None = None) -> Any:
        """The certificate content of ``result`` (see models.certificate.document), listing
        the ``settings`` it was analysed with as their declarations word them."""
        if self.certificate is None:
            raise ValueError(f"{self.title}: no certificate is defined")
        document = self.certificate(result, metadata, source_name, self.method_reference)
        if settings is not None:
            checked = self.checked_settings(settings)
            listing = tuple((p.label, p.text(checked[p.key])) for p in self.parameters)
            document = dataclasses.replace(document, settings=listing)
        return document

    def settings_with_defaults(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        merged = dict(self.default_settings)
        if settings:
            merged.update({k: v for k, v in settings.items() if k in self.default_settings})
        return merged
