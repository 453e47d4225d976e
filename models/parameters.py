"""Workbench settings declared once (PyMeasure's ``Parameter`` is the model).

A :class:`Parameter` holds a setting's key, label, unit, type, range, default,
help text and command-line flag. The settings form, the command line's
options, the check of a project file's settings and the listing on a
certificate are all made from the same declaration.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from models.messages import QT_TR_NOOP, message

__all__ = ["Parameter", "SettingsError", "Shortcut", "check_parameters"]


class SettingsError(ValueError):
    """A workbench setting is out of range; the message names it. ``key``: the setting the
    readings refuse (its field the window marks), "" when the message names no one field."""

    def __init__(self, text: str, key: str = "") -> None:
        super().__init__(text)
        self.key = key


@dataclass(frozen=True)
class Parameter:
    """One setting of a workbench.

    ``kind`` is "int", "float", "choice" or "text". For numbers, ``minimum`` …
    ``maximum`` is the range; ``zero`` (its text, e.g. "from the readings")
    admits 0 as well, meaning "automatic". ``choices`` are (value, text) pairs.
    """

    key: str
    label: str
    kind: str
    default: Any
    unit: str = ""
    minimum: float | None = None
    maximum: float | None = None
    choices: tuple[tuple[Any, str], ...] = ()
    help: str = ""
    cli: bool = True  # offered on the command line as --key-with-dashes (or --cli_name)
    cli_name: str = ""
    #: an aid to entering readings in the window (the entry plan): no input of the analysis,
    #: left out of the certificate's settings (day review 65 F13: "entry plan: θ steps
    #: −20:1:41" printed on a certificate whose run used no plan)
    entry_aid: bool = False
    zero: str = ""
    decimals: int = 3
    step: float = 1.0

    @property
    def flag(self) -> str:
        return "--" + (self.cli_name or self.key.replace("_", "-"))

    def from_text(self, text: str) -> Any:
        """A command-line value, checked (SettingsError naming the flag)."""
        if self.kind == "choice":
            value = next((v for v, _ in self.choices if str(v) == text), None)
            if value is None:
                shown = ", ".join(str(v) for v, _ in self.choices)
                raise SettingsError(message(
                    QT_TR_NOOP("{key} must be one of {shown}, not {text}"),
                    key=self.key, shown=shown, text=text))
            return value
        if self.kind == "text":
            return self.check(text)
        try:
            number: Any = int(text) if self.kind == "int" else float(text)
        except ValueError:
            raise SettingsError(message(
                QT_TR_NOOP("{flag}: '{text}' is not a whole number") if self.kind == "int" else
                QT_TR_NOOP("{flag}: '{text}' is not a number"), flag=self.flag, text=text)) from None
        return self.check(number)

    def check(self, value: Any) -> Any:
        """The value, of the declared type and in range; SettingsError naming the key."""
        if self.kind == "choice":
            values = [v for v, _ in self.choices]
            if isinstance(value, bool) or not isinstance(value, str | int | float) or \
                    value not in values:
                shown = ", ".join(str(v) for v in values)
                raise SettingsError(message(
                    QT_TR_NOOP("{key} must be one of {shown}, not {value}"),
                    key=self.key, shown=shown, value=f"{value!r}"))
            return values[values.index(value)]
        if self.kind == "text":
            if not isinstance(value, str):
                raise SettingsError(message(
                    QT_TR_NOOP("{key} must be text, not {name__}"),
                    key=self.key, name__=type(value).__name__))
            return value
        if isinstance(value, bool) or not isinstance(value, int | float) or \
                not math.isfinite(value):
            raise SettingsError(message(
                QT_TR_NOOP("{key} must be a number, not {value}"),
                key=self.key, value=f"{value!r}"))
        if self.zero and value == 0:
            return 0
        if self.kind == "int" and value != int(value):
            raise SettingsError(message(
                QT_TR_NOOP("{key} must be a whole number, not {value}"),
                key=self.key, value=value))
        low = -math.inf if self.minimum is None else self.minimum
        high = math.inf if self.maximum is None else self.maximum
        if not low <= value <= high:
            # "0 or" only where 0 is outside the range (contract75 F13: "must be 0 or 0 to
            # 3600")
            zero = "0 or " if self.zero and not low <= 0 <= high else ""
            raise SettingsError(message(
                QT_TR_NOOP("{key} must be {zero}{low} to {high}{value}, not {value2}"),
                key=self.key, zero=zero, low=f"{low:g}", high=f"{high:g}",
                value=' ' + self.unit if self.unit else '', value2=f"{value:g}"))
        return int(value) if self.kind == "int" else float(value)

    def text(self, value: Any) -> str:
        """The value as a certificate lists it."""
        if self.kind == "choice":
            return next((t for v, t in self.choices if v == value), str(value))
        if self.zero and value == 0:
            return self.zero
        return f"{value:g}{' ' + self.unit if self.unit else ''}" if isinstance(
            value, int | float) else str(value)


@dataclass(frozen=True)
class Shortcut:
    """A command-line switch that sets one setting to one value (``--zenith`` for
    ``--vertical-reading zenith``); ``help`` is a QT_TR_NOOP text."""

    flag: str
    key: str
    value: Any
    help: str


def check_parameters(parameters: Sequence[Parameter],
                     settings: Mapping[str, Any] | None) -> dict[str, Any]:
    """Defaults filled in, unknown keys dropped, every value checked."""
    given = dict(settings or {})
    return {p.key: p.check(given.get(p.key, p.default)) for p in parameters}
