"""Result texts that can be shown in another language (the models have no Qt).

A verdict or a warning is written once, in English, as a :class:`Message`: a ``str``
(the English text, as every caller, test and file sees it) that also remembers its
template and its figures. The window translates the template with Qt's translator and
fills in the same figures; the command line, the JSON and the certificate use the
English text. ``QT_TR_NOOP`` marks a template for ``pyside6-lupdate``, which finds it
by name; here it does nothing else. A :class:`Message` built from parts
(:func:`joined`) is translated part by part.

Figures are passed already formatted (``ptp=f"{x:.2f}\\""``), with their unit, so the
translated text keeps their resolution and can still be shown in another angle unit.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

__all__ = ["QT_TR_NOOP", "Message", "joined", "lines", "message"]


def QT_TR_NOOP(text: str) -> str:  # noqa: N802 - the name lupdate looks for
    return text


class Message(str):
    """English text with its ``template`` and ``figures`` (or its ``parts``)."""

    template: str
    figures: dict[str, Any]
    parts: tuple[Any, ...]

    def __new__(cls, template: str, figures: dict[str, Any] | None = None,
                parts: tuple[Any, ...] = ()) -> Message:
        figures = dict(figures or {})
        text = "".join(map(str, parts)) if parts else (template.format(**figures) if figures
                                                       else template)
        obj = super().__new__(cls, text)
        obj.template, obj.figures, obj.parts = template, figures, tuple(parts)
        return obj

    def __reduce__(self):  # copies and pickles keep the template and figures
        return (Message, (self.template, self.figures, self.parts))


def message(template: str, **figures: Any) -> Message:
    """``template.format(**figures)``, remembering both."""
    return Message(template, figures)


def joined(parts: Iterable[Any]) -> Message:
    """Parts (messages or plain text) one after another, each translated on its own."""
    return Message("", None, tuple(p for p in parts if p))


def lines(parts: Iterable[Any]) -> Message:
    """Parts one to a line (a summary)."""
    out: list[Any] = []
    for part in parts:
        out += (["\n"] if out else []) + [part]
    return joined(out)
