"""What every workbench provides to the GUI, the CLI and the project file.

A workbench kind is its typed readings columns, its default settings, and
three pure functions: analyse the parsed readings, turn the result into the
CLI's JSON, and into a readable text summary.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from models.readings.sheet import Column, ParsedReadings

__all__ = ["SIGN_CONVENTION", "SIGN_CONVENTION_TEXT", "AnalysisKind", "SettingsError"]

#: Every workbench states errors of indication (VIM 4.1): indicated − reference; a
#: correction is the negative of an error.
SIGN_CONVENTION = "indicated_minus_reference"
SIGN_CONVENTION_TEXT = "error = indicated − reference (VIM); correction = −error"


class SettingsError(ValueError):
    """A workbench setting is out of range; the message names it."""


@dataclass(frozen=True)
class AnalysisKind:
    key: str
    title: str
    columns: tuple[Column, ...]
    default_settings: Mapping[str, Any]
    analyze: Callable[[ParsedReadings, Mapping[str, Any]], Any]
    to_json: Callable[[Any], dict[str, Any]]
    summary: Callable[[Any], str]
    sample_file: str
    method_reference: str = ""
    # (result, CertificateMetadata, source name, method reference) -> CertificateDocument
    certificate: Callable[..., Any] | None = None
    # settings -> the settings checked and completed; raises SettingsError naming the key
    check_settings: Callable[[Mapping[str, Any]], dict[str, Any]] | None = None
    # "package.module:Class" of the workbench's presenter, imported only by the window
    presenter: str = ""

    def checked_settings(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        """The settings with defaults, each checked (types and ranges): for a project file,
        the form and the command line alike."""
        if self.check_settings is None:
            return self.settings_with_defaults(settings)
        return self.check_settings(settings or {})

    def certificate_document(self, result: Any, metadata: Any, source_name: str = "") -> Any:
        """The certificate content of ``result`` (see models.certificate.document)."""
        if self.certificate is None:
            raise ValueError(f"{self.title}: no certificate is defined")
        return self.certificate(result, metadata, source_name, self.method_reference)

    def settings_with_defaults(self, settings: Mapping[str, Any] | None) -> dict[str, Any]:
        merged = dict(self.default_settings)
        if settings:
            merged.update({k: v for k, v in settings.items() if k in self.default_settings})
        return merged
