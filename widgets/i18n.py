"""The window in English or Simplified Chinese, with Qt's own translation system.

* ``tr("…")`` marks a text of the window and translates it now (``pyside6-lupdate``
  reads these calls; their context is the empty one). It returns a :class:`Tr`: the
  translation, remembering its English source.
* ``live(setter, tr("…"))`` sets a text and sets it again, translated anew, whenever
  the language changes; ``on_language_change(owner, callback)`` runs ``callback`` then
  (a form re-labelled, a result redrawn). Nothing is rebuilt and no work is lost.
* ``declared(text)`` translates a text the models declare (a setting's label, a
  column's title, a plot's title) or a plot title the window composes: the models have
  no Qt, so ``python -m app.translations`` builds the window on the samples, records
  every text asked of ``declared`` and writes them to
  ``resources/translations/declared_strings.py`` for ``lupdate``. A title with a unit,
  ``error (µrad)``, is translated without its unit, which stays as it is.

Everything is in one translation context (the empty one), so a text is translated the
same wherever it appears.

The language follows the system's unless one was chosen (View › Language); it is kept
in the settings under ``ui/language``.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable

from PySide6.QtCore import QT_TR_NOOP, QCoreApplication, QLibraryInfo, QLocale, QTranslator

from models.messages import TRANSLATIONS_DIR, declared_text, reason_of, rendered

__all__ = ["LANGUAGES", "SEEN_DECLARED", "Tr", "current_language", "declared", "explained",
           "install_language", "live",
           "on_language_change", "resolve_language", "tr", "translated"]

LANGUAGES = {"system": QT_TR_NOOP("System language"), "en": "English",
             "zh_CN": "简体中文 (Chinese)"}


class Tr(str):
    """A translated text that remembers its English source (to translate it again)."""

    source: str
    is_declared: bool  # a text of the models (``declared``), not of the window (``tr``)

    def __new__(cls, text: str, source: str, is_declared: bool = False) -> Tr:
        obj = super().__new__(cls, text)
        obj.source = source
        obj.is_declared = is_declared
        return obj


def tr(source: str) -> Tr:
    return Tr(QCoreApplication.translate("", source), source)


#: every text asked of ``declared`` while the program ran (app.translations gathers them)
SEEN_DECLARED: set[str] = set()


def _translate_declared(source: str) -> str:
    return declared_text(source, lambda text: QCoreApplication.translate("", text))


def translated(text: str) -> str:
    """A result text of the models (models.messages.Message) in the window's language:
    its template translated and filled with the same figures; plain text as it is."""
    return rendered(text, lambda template: QCoreApplication.translate("", template))


def explained(exc: BaseException) -> str:
    """Why ``exc`` was raised, in the window's language (its Message template translated)."""
    return translated(reason_of(exc))


def declared(source: str) -> Tr:
    """A text declared by the models, translated (unchanged when it has no translation)."""
    SEEN_DECLARED.add(source)
    return Tr(_translate_declared(source), source, True)


# -- texts that follow the language -------------------------------------------------
_live: list[tuple[weakref.ref, Callable[[str], None], str, bool]] = []
_callbacks: list[tuple[weakref.ref, Callable[[], Callable[[], None] | None]]] = []


def live(setter, text: Tr) -> None:
    """``setter(text)`` now and again after every change of language. ``setter`` is a
    bound method of a Qt object (``label.setText``, ``action.setToolTip``)."""
    setter(text)
    owner = getattr(setter, "__self__", None)
    if owner is not None:
        _live.append((weakref.ref(owner), setter.__name__, text.source, text.is_declared))


def on_language_change(owner, callback: Callable[[], None]) -> None:
    """Run ``callback`` after every change of language while ``owner`` lives. A bound
    method is held weakly (a window closed is not kept alive by its language)."""
    held = weakref.WeakMethod(callback) if hasattr(callback, "__self__") else (lambda: callback)
    _callbacks.append((weakref.ref(owner), held))


def _alive(obj) -> bool:
    if obj is None:
        return False
    try:
        import shiboken6

        return shiboken6.isValid(obj)
    except ImportError:  # pragma: no cover - shiboken ships with PySide6
        return True


def retranslate() -> None:
    """Set every live text again in the language now installed, then run the callbacks."""
    kept = []
    for ref, name, source, is_declared in _live:
        owner = ref()
        if not _alive(owner):
            continue
        try:
            getattr(owner, name)(declared(source) if is_declared else tr(source))
        except RuntimeError:  # its C++ side went with its window
            continue
        kept.append((ref, name, source, is_declared))
    _live[:] = kept
    callbacks = []
    for ref, held in _callbacks:
        callback = held()
        if _alive(ref()) and callback is not None:
            try:
                callback()
            except RuntimeError:  # a part of it was deleted with its window
                continue
            callbacks.append((ref, held))
    _callbacks[:] = callbacks


# -- the language -----------------------------------------------------------------
_installed: list[QTranslator] = []
_current = ["en"]  # the language installed (English: no translator)


def current_language() -> str:
    """The language installed: ``en`` or ``zh_CN``."""
    return _current[0]


def resolve_language(choice: str) -> str:
    """``en`` or ``zh_CN`` for a choice of LANGUAGES (``system``: the system's)."""
    if choice in ("en", "zh_CN"):
        return choice
    return "zh_CN" if QLocale.system().language() == QLocale.Language.Chinese else "en"


def install_language(choice: str) -> str:
    """Install the translators of ``choice`` (ours, and Qt's own for its dialogs), then
    retranslate every live text; returns the language installed."""
    app = QCoreApplication.instance()
    language = resolve_language(choice)
    if language == _current[0]:
        return language  # nothing to set again (a second window, the same choice)
    _current[0] = language
    for translator in _installed:
        app.removeTranslator(translator)
    _installed.clear()
    if language != "en":
        ours = QTranslator(app)
        if ours.load(str(TRANSLATIONS_DIR / f"anglebench_{language}.qm")):
            app.installTranslator(ours)
            _installed.append(ours)
        qt = QTranslator(app)
        if qt.load(f"qtbase_{language}",
                   QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)):
            app.installTranslator(qt)
            _installed.append(qt)
    retranslate()
    return language
