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
in the settings under ``ui/language``. The application owns one :class:`Language`
(``application_language()``): the translators installed, the language they give, and
every text and callback that follows it.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable

from PySide6.QtCore import QT_TR_NOOP, QCoreApplication, QLibraryInfo, QLocale, QObject, QTranslator

from models.messages import TRANSLATIONS_DIR, Message, declared_text, reason_of, rendered

__all__ = ["LANGUAGES", "SEEN_DECLARED", "Language", "Said", "Tr", "application_language",
           "declared", "explained", "install_language", "joined", "live", "on_language_change",
           "resolve_language", "said_again", "tr", "translated"]

LANGUAGES = {"system": QT_TR_NOOP("System language"), "en": "English",
             "zh_CN": "简体中文 (Chinese)"}


class _SaidAgain(str):
    """A text of the window that can be said again in another language
    (:func:`said_again`); joined to another text with ``+``, the two are said again each on
    its own ("Draft written to …" + "; its DCC written to …")."""

    def __add__(self, other):
        if not isinstance(other, str):
            return NotImplemented
        return Said(str.__add__(self, other), lambda: said_again(self) + said_again(other))

    def __radd__(self, other):
        if not isinstance(other, str):
            return NotImplemented
        return Said(str.__add__(other, self), lambda: said_again(other) + said_again(self))


class Tr(_SaidAgain):
    """A translated text that remembers its English source (to translate it again)."""

    source: str
    is_declared: bool  # a text of the models (``declared``), not of the window (``tr``)

    def __new__(cls, text: str, source: str, is_declared: bool = False) -> Tr:
        obj = super().__new__(cls, text)
        obj.source = source
        obj.is_declared = is_declared
        return obj

    def format(self, *args: object, **kwargs: object) -> Said:
        """The translation filled in, remembering its source and arguments: said again, the
        source is translated anew and filled with the arguments said again (a status
        line's message after a change of language: widgets/status_line.py)."""
        # an exception is kept as its text (its traceback would hold its frames alive)
        args = tuple(str(a) if isinstance(a, BaseException) else a for a in args)
        kwargs = {k: str(v) if isinstance(v, BaseException) else v for k, v in kwargs.items()}
        said = Said(str.format(self, *args, **kwargs),
                    lambda: said_again(self).format(*(said_again(a) for a in args),
                                                    **{k: said_again(v) for k, v in
                                                       kwargs.items()}))
        if not args:  # its English source and figures, as a project file keeps a cell's
            # mark (models/project/cell_marks.py): a figure that is a text of the window
            # or the models by its source
            said.spelt = (self.source, {k: v.source if isinstance(v, Tr) else str(v)
                                        for k, v in kwargs.items()})
        return said


class Said(_SaidAgain):
    """A text composed of translated parts (``tr(…).format(…)``, a model's message
    translated, two such texts joined), with how to compose it again in the language now
    installed (:func:`said_again`)."""

    again: Callable[[], str]
    #: (English source, figures) of a ``tr(…).format(…)``; None otherwise
    spelt: tuple[str, dict[str, str]] | None

    def __new__(cls, text: str, again: Callable[[], str]) -> Said:
        obj = super().__new__(cls, text)
        obj.again = again
        obj.spelt = None
        return obj

    def __reduce__(self):  # a copy (a pickle) is the text alone, said again no more
        return (str, (str(self),))


def said_again(text):
    """``text`` in the language now installed: a :class:`Tr` translated anew, a
    :class:`Said` composed again; anything else (a path, a number, a text of no language)
    as it is."""
    if isinstance(text, Tr):
        return declared(text.source) if text.is_declared else tr(text.source)
    if isinstance(text, Said):
        return text.again()
    return text


def joined(separator: str, parts) -> Said:
    """``parts`` joined by ``separator``, said again each in the language then installed
    (day review live76 F5: "; ".join(…) of translated texts stayed in the language it was
    shown in)."""
    parts = list(parts)
    return Said(separator.join(parts), lambda: separator.join(str(said_again(p)) for p in parts))


def tr(source: str) -> Tr:
    return Tr(QCoreApplication.translate("", source), source)


#: every text asked of ``declared`` while the program ran (app.translations gathers them)
SEEN_DECLARED: set[str] = set()


def _translate_declared(source: str) -> str:
    return declared_text(source, lambda text: QCoreApplication.translate("", text))


def translated(text: str) -> str:
    """A result text of the models (models.messages.Message) in the window's language:
    its template translated and filled with the same figures (a :class:`Said`: said again,
    it is translated anew); plain text as it is."""
    said = rendered(text, lambda template: QCoreApplication.translate("", template),
                    window=True)
    return Said(said, lambda: translated(text)) if isinstance(text, Message) else said


def explained(exc: BaseException) -> str:
    """Why ``exc`` was raised, in the window's language (its Message template translated)."""
    return translated(reason_of(exc))


def declared(source: str) -> Tr:
    """A text declared by the models, translated (unchanged when it has no translation)."""
    SEEN_DECLARED.add(source)
    return Tr(_translate_declared(source), source, True)


# -- the language, and the texts that follow it -------------------------------------
def _alive(obj) -> bool:
    if obj is None:
        return False
    try:
        import shiboken6

        return shiboken6.isValid(obj)
    except ImportError:  # pragma: no cover - shiboken ships with PySide6
        return True


class Language(QObject):
    """The language the window is shown in: one per application, a child of the
    ``QCoreApplication`` (:func:`application_language`). It holds the translators it
    installed, the language they give (``code``: ``en`` or ``zh_CN``; English has no
    translator), and every text and callback that follows a change of language."""

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.code = "en"
        self._translators: list[QTranslator] = []
        #: the translators of each language, loaded at its first choice and kept (day review
        #: 67: two new ones at every switch to Chinese, never deleted)
        self._loaded: dict[str, list[QTranslator]] = {}
        self._live: list[tuple[weakref.ref, str, str, bool]] = []
        self._callbacks: list[tuple[weakref.ref, Callable[[], Callable[[], None] | None]]] = []

    def follow(self, setter, text: Tr) -> None:
        """``setter(text)`` again after every change of language (see :func:`live`)."""
        owner = getattr(setter, "__self__", None)
        if owner is not None:
            self._live.append((weakref.ref(owner), setter.__name__, text.source, text.is_declared))

    def on_change(self, owner, callback: Callable[[], None]) -> None:
        """Run ``callback`` after every change of language while ``owner`` lives. A bound
        method is held weakly (a window closed is not kept alive by its language)."""
        held = weakref.WeakMethod(callback) if hasattr(callback, "__self__") else (lambda: callback)
        self._callbacks.append((weakref.ref(owner), held))

    def retranslate(self) -> None:
        """Set every live text again in the language now installed, then run the callbacks."""
        kept = []
        for ref, name, source, is_declared in self._live:
            owner = ref()
            if not _alive(owner):
                continue
            try:
                getattr(owner, name)(declared(source) if is_declared else tr(source))
            except RuntimeError:  # its C++ side went with its window
                continue
            kept.append((ref, name, source, is_declared))
        self._live[:] = kept
        callbacks = []
        for ref, held in self._callbacks:
            callback = held()
            if _alive(ref()) and callback is not None:
                try:
                    callback()
                except RuntimeError:  # a part of it was deleted with its window
                    continue
                callbacks.append((ref, held))
        self._callbacks[:] = callbacks

    def install(self, choice: str) -> str:
        """Install the translators of ``choice`` (ours, and Qt's own for its dialogs), then
        retranslate every live text; returns the language installed."""
        app = QCoreApplication.instance()
        if app is None:
            raise RuntimeError("the language belongs to the application: make a QApplication "
                               "first")
        language = resolve_language(choice)
        if language == self.code:
            return language  # nothing to set again (a second window, the same choice)
        self.code = language
        for translator in self._translators:
            app.removeTranslator(translator)
        self._translators.clear()
        if language != "en":
            for translator in self._translators_of(language):
                app.installTranslator(translator)
                self._translators.append(translator)
        self.retranslate()
        return language

    def _translators_of(self, language: str) -> list[QTranslator]:
        """Ours and Qt's own translators of ``language`` (those that load), the same ones
        at every choice of it."""
        if language not in self._loaded:
            ours, qt = QTranslator(self), QTranslator(self)
            loaded = [ours] if ours.load(
                str(TRANSLATIONS_DIR / f"anglebench_{language}.qm")) else []
            if qt.load(f"qtbase_{language}",
                       QLibraryInfo.path(QLibraryInfo.LibraryPath.TranslationsPath)):
                loaded.append(qt)
            for translator in (ours, qt):
                if translator not in loaded:
                    translator.deleteLater()
            self._loaded[language] = loaded
        return self._loaded[language]


def application_language() -> Language:
    """The application's language: a child of the ``QCoreApplication``, made when first
    asked for (English), and gone with the application."""
    app = QCoreApplication.instance()
    if app is None:
        raise RuntimeError("the language belongs to the application: make a QApplication first")
    language = app.findChild(Language)
    if language is None:
        language = Language(app)
    return language


def live(setter, text: Tr) -> None:
    """``setter(text)`` now and again after every change of language. ``setter`` is a
    bound method of a Qt object (``label.setText``, ``action.setToolTip``)."""
    setter(text)
    application_language().follow(setter, text)


def on_language_change(owner, callback: Callable[[], None]) -> None:
    """Run ``callback`` after every change of language while ``owner`` lives."""
    application_language().on_change(owner, callback)


def resolve_language(choice: str) -> str:
    """``en`` or ``zh_CN`` for a choice of LANGUAGES (``system``: the system's)."""
    if choice in ("en", "zh_CN"):
        return choice
    return "zh_CN" if QLocale.system().language() == QLocale.Language.Chinese else "en"


def install_language(choice: str) -> str:
    """The application's language set to ``choice`` (:meth:`Language.install`)."""
    return application_language().install(choice)
