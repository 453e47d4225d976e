"""Result texts that can be shown in another language (the models have no Qt).

A verdict or a warning is written once, in English, as a :class:`Message`: a ``str``
(the English text, as every caller, test and file sees it) that also remembers its
template and its figures. The window translates the template with Qt's translator and
fills in the same figures; the command line, the JSON and the certificate use the
English text. ``QT_TR_NOOP`` marks a template for ``pyside6-lupdate``, which finds it
by name; here it does nothing else. A :class:`Message` built from parts
(:func:`joined`) is translated part by part.

A figure with a unit is best passed as a :class:`~models.quantity.Quantity`
(``ptp=Quantity(x, "arcsec", ".2f")``): it prints with its unit at its resolution, and
:func:`models.display_units.in_unit` converts it for another angle unit from the number
itself. A figure passed already formatted (``ptp=f"{x:.2f}\\""``) is converted only when
it is one number with its angle unit; the finished text is never rewritten.
"""

from __future__ import annotations

import functools
import re
import string
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any, cast

__all__ = ["JOINS", "LIST_JOIN", "QT_TR_NOOP", "TRANSLATIONS_DIR", "Message", "Named", "as_sentence",
           "catalogue", "declared_text", "in_language", "joined", "lines", "listed", "message", "reason_of",
           "rendered", "separated", "translator", "typed_name", "unit_tail"]

#: the .ts sources and compiled .qm files (the window loads the .qm; the command line reads
#: the .ts, without Qt)
TRANSLATIONS_DIR = Path(__file__).resolve().parents[1] / "resources" / "translations"


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

    def __reduce__(self) -> tuple[type[Message], tuple[str, dict[str, Any], tuple[Any, ...]]]:
        # copies and pickles keep the template and figures
        return (Message, (self.template, self.figures, self.parts))


class Named(Message):
    """A setting or a certificate field named in a message, as the command line and the
    files name it (the English text and :attr:`template`: its key and option, e.g.
    "reading_noise_arcsec; on the command line --reading-noise-arcsec") and as the window
    labels it (:attr:`window`, e.g. the set-up field's label): :func:`rendered` for the
    window gives the latter. gui78 (live78): the window's verdicts named internal keys
    ("item_resolution") to the technician, in both languages."""

    window: str

    def __new__(cls, template: str, window: str = "") -> Named:
        obj = cast(Named, super().__new__(cls, template))
        obj.window = window or template
        return obj

    def __reduce__(self):
        return (Named, (self.template, self.window))


def message(template: str, **figures: Any) -> Message:
    """``template.format(**figures)``, remembering both; a message with no figures given is
    itself (a reason that is already a message, its figures filled in, stays translatable)."""
    if isinstance(template, Message) and not figures:
        return template
    return Message(template, figures)


def joined(parts: Iterable[Any]) -> Message:
    """Parts (messages or plain text) one after another, each translated on its own."""
    return Message("", None, tuple(p for p in parts if p))


#: how :func:`separated` joins two parts of a composed text: a template each, which a
#: translation gives its own punctuation (Chinese: full-width "；" and "，", and no space
#: between two sentences, the first ending in "。")
JOINS = {
    "; ": QT_TR_NOOP("{first}; {second}"),
    ", ": QT_TR_NOOP("{first}, {second}"),
    " ": QT_TR_NOOP("{first} {second}"),
}


def separated(parts: Iterable[Any], separator: str = "; ") -> Any:
    """The non-empty ``parts`` with ``separator`` ("; ", ", ", or " " between sentences)
    between them, through its template in :data:`JOINS`, so that a translated text joins
    its parts in its own punctuation ("a; b" in English, "甲；乙" in Chinese); one part as
    it is, none "". Numbers and units in the parts are never touched."""
    return _chained(parts, JOINS[separator], "first", "second")


def _chained(parts: Iterable[Any], template: str, before: str, after: str) -> Any:
    """The non-empty ``parts`` joined two at a time through ``template``, the text so far
    as its figure ``before``, the next part as ``after``; one part as it is, none ""."""
    out: Any = ""
    for part in parts:
        if part:
            out = message(template, **{before: out, after: part}) if out else part
    return out


#: how :func:`listed` joins the items of a list (names of inputs, fields, figures): Chinese
#: puts the enumeration comma "、" between them, not the clause comma "，"
LIST_JOIN = QT_TR_NOOP("{items}, {item}")


def listed(parts: Iterable[Any]) -> Any:
    """The non-empty ``parts`` as a list ("a, b, c" in English, "甲、乙、丙" in Chinese), each
    translated on its own; one part as it is, none ""."""
    return _chained(parts, LIST_JOIN, "items", "item")


#: a name the user typed (a standard's description) inside a sentence: as it is in English,
#: quoted in Chinese (“…”, as the catalogue's other quoted names), so that a Latin name does
#: not run straight into the Chinese around it (assessment 78 L5: "未说明Data acquisition
#: (16-bit ADC)的角色")
TYPED_NAME = QT_TR_NOOP("{typed_name}")


def typed_name(name: Any) -> Any:
    """``name``, typed by the user, to be set inside a sentence (:data:`TYPED_NAME`); a
    name of ours (a :class:`Message`, such as "standard") or an empty one as it is."""
    if not name or isinstance(name, Message):
        return name
    return message(TYPED_NAME, typed_name=name)


def lines(parts: Iterable[Any]) -> Message:
    """Parts one to a line (a summary)."""
    out: list[Any] = []
    for part in parts:
        out += (["\n"] if out else []) + [part]
    return joined(out)


def as_sentence(text: str) -> str:
    """``text`` beginning with a capital, as a sentence does (a reason begins in lower case,
    to follow "anglebench analyze: " on the command line or "…: " in a longer message); a
    text in a script without case as it is, and one that begins with a name that is no word
    (a file, a certificate number "ab-2026-0001", a setting's key) too: its case is its own."""
    words = text.split(maxsplit=1)
    first = words[0].rstrip(",:;.") if words else ""
    if first.isalpha() and text[:1].islower():
        return text[:1].upper() + text[1:]
    return text


def reason_of(exc: BaseException) -> str:
    """What an exception says, as the :class:`Message` it was raised with when it was one
    (``str(exc)`` would keep the English only)."""
    if len(exc.args) == 1 and isinstance(exc.args[0], Message):
        return exc.args[0]
    return str(exc)


def rendered(text: str, translate: Callable[[str], str], window: bool = False) -> str:
    """``text`` with each template translated by ``translate`` and filled with the same
    figures (a plain ``str`` comes back as it is). ``window``: for the window, which names
    a setting as its form labels it (:class:`Named`); else as the command line does."""
    if not isinstance(text, Message):
        return text
    if text.parts:
        return "".join(rendered(part, translate, window) for part in text.parts)
    template = text.window if window and isinstance(text, Named) else text.template
    figures = {key: rendered(value, translate, window) if isinstance(value, str) else value
               for key, value in text.figures.items()}
    words = translate(template)
    # a translation that quotes a typed name itself ("未说明“{unnamed}”的角色") does not quote
    # it twice where the name comes quoted already (:func:`typed_name`, once the catalogue
    # quotes it)
    for key, value in text.figures.items():
        shown = figures[key]
        if (isinstance(value, Message) and value.template == TYPED_NAME
                and isinstance(shown, str) and shown[:1] in "“「" and shown != str(value)):
            words = words.replace(f"“{{{key}}}”", f"{{{key}}}").replace(
                f"「{{{key}}}」", f"{{{key}}}")
    return _filled(words, figures) if figures else words


#: a character of Chinese text: an ideograph, or CJK or full-width punctuation ("。", "（")
_CJK = re.compile(r"[\u3000-\u303f\u3400-\u4dbf\u4e00-\u9fff\uff00-\uffef]")
#: a figure's end that is Chinese text's own: also the quotation marks a Chinese text quotes a
#: typed name with (“…”, :func:`typed_name`), which Chinese sets with no space beside them
_CJK_FIGURE_END = re.compile(r"[\u3000-\u303f\u3400-\u4dbf\u4e00-\u9fff\uff00-\uffef“”]")


def _filled(words: str, figures: dict[str, Any]) -> str:
    """``words.format(**figures)``, but with no space between two runs of Chinese where a
    space of the template meets a figure: a translation spaces a Chinese word from a figure
    that may be in Latin ("起决定作用的点为 {point}": "为 θ = −5°"), which between Chinese runs
    is a stray ("为 目标位置 90°", assessment 76 L3). Only a space between the template's own
    Chinese and a figure that begins (ends) in Chinese goes; a space between two figures,
    the figures and the template's other spaces stay as they are, and an English text is
    never changed (its template has no Chinese)."""
    if " " not in words or not _CJK.search(words):
        return words.format(**figures)
    pieces: list[tuple[str, bool]] = []  # (text, whether it is a figure)
    formatter = string.Formatter()
    for literal, field, spec, conversion in formatter.parse(words):
        if literal:
            pieces.append((literal, False))
        if field is not None:
            value = formatter.convert_field(formatter.get_field(field, (), figures)[0],
                                            conversion)
            pieces.append((formatter.format_field(value, spec or ""), True))
    for i, (text, figure) in enumerate(pieces):
        if figure or " " not in (text[:1], text[-1:]):
            continue
        before = pieces[i - 1] if i else ("", False)
        after = pieces[i + 1] if i + 1 < len(pieces) else ("", False)
        if (text[:1] == " " and before[1] and _CJK_FIGURE_END.match(before[0][-1:])
                and _CJK.match(text[1:2])):
            text = text[1:]
        if (text[-1:] == " " and after[1] and _CJK_FIGURE_END.match(after[0][:1])
                and _CJK.match(text[-2:-1])):
            text = text[:-1]
        pieces[i] = (text, figure)
    return "".join(text for text, _ in pieces)


_UNIT_TAIL = re.compile(r"^(.*?)(\s*\((?:\"|″|µrad|mdeg|arcsec|deg|°|V|mV|nm|µm|mm|%|°C|V, log10|"
                        r"V, log)\))$")


@functools.lru_cache(maxsize=8192)
def unit_tail(source: str) -> tuple[str, str]:
    """("error", " (µrad)") for "error (µrad)"; (source, "") when it has no unit. Every
    declared text of a window passes here at each build and language switch (~430 a
    window): a text that does not end in ")" is answered without the pattern, whose
    lazy head is tried at every length of a long text, and the answers are kept."""
    if not source.endswith(")"):
        return source, ""
    found = _UNIT_TAIL.match(source)
    return (found.group(1), found.group(2)) if found else (source, "")


def declared_text(source: str, translate: Callable[[str], str]) -> str:
    """A text the models declare (a column, a setting, a plot's title) in another language:
    looked up whole, or, when it ends in a unit, its words looked up and the unit kept
    ("error (µrad)" is "error" translated, then " (µrad)"); unchanged when it has no
    translation."""
    text = translate(source)
    if text != source or not source:
        return text
    head, unit = unit_tail(source)
    if unit:
        words = translate(head)
        if words != head:
            return words + unit
    return source


def in_language(text: str, translate: Callable[[str], str]) -> str:
    """Any text of ours in another language: a :class:`Message` in its translated template
    with its own figures, another text looked up whole (:func:`declared_text`); a text
    with no translation (user input, figures) as it is."""
    if isinstance(text, Message):
        return rendered(text, translate)
    return declared_text(text, translate)


@functools.cache
def translator(language: str) -> Callable[[str], str]:
    """English → ``language`` ("en": as it is) from the window's own catalogue."""
    if language == "en":
        return lambda text: text
    words = catalogue(TRANSLATIONS_DIR / f"anglebench_{language}.ts")
    return lambda text: words.get(text, text)


def catalogue(ts_file: str | Path) -> dict[str, str]:
    """The finished translations of a Qt ``.ts`` file, read without Qt (the command line
    prints in Chinese without loading Qt)."""
    import xml.etree.ElementTree as ET

    out: dict[str, str] = {}
    for element in ET.parse(ts_file).iter("message"):
        source, translation = element.find("source"), element.find("translation")
        if (source is not None and translation is not None and translation.text
                and translation.get("type") not in ("unfinished", "obsolete", "vanished")):
            out[source.text or ""] = translation.text
    return out
