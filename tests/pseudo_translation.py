"""A pseudo-translation for tests: every text asked of Qt's translation system comes back
marked, ``‹text›``, so that a test checks that a text goes through the translation
mechanism (``tr``, ``declared``, a models ``Message``) without pinning its English words
or needing the compiled Chinese catalogue to hold it."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

from PySide6.QtCore import QCoreApplication, QTranslator


def marked(text: str) -> str:
    return f"‹{text}›"


class PseudoTranslator(QTranslator):
    def translate(self, context, source, disambiguation=None, n=-1):  # noqa: ARG002 - Qt's signature
        return marked(source) if source else source

    def isEmpty(self) -> bool:  # noqa: N802 - Qt's name
        return False


@contextlib.contextmanager
def pseudo_translated() -> Iterator[None]:
    """Every text translated while the block runs comes back marked."""
    app = QCoreApplication.instance()
    translator = PseudoTranslator(app)
    app.installTranslator(translator)
    try:
        yield
    finally:
        app.removeTranslator(translator)
        translator.deleteLater()
