"""Key sequences of an action, each once: a platform's standard binding (QKeySequence's
StandardKey, expanded to every sequence the platform binds to it) and the extra keys we
add, without repeating one the platform already binds. Qt runs neither action of a key
bound twice ("Ambiguous shortcut overload"): Ctrl+Shift+Z, X11's Redo, added again as an
extra, did nothing on X11."""

from __future__ import annotations

from PySide6.QtGui import QKeySequence

__all__ = ["key_sequences", "platform_bindings"]


def platform_bindings(key: QKeySequence.StandardKey) -> list[QKeySequence]:
    """Every sequence this platform binds to ``key`` (a test puts another platform's)."""
    return QKeySequence.keyBindings(key)


def key_sequences(*keys: QKeySequence.StandardKey | QKeySequence | str) -> list[QKeySequence]:
    """The sequences of ``keys`` in order, each once (a StandardKey expanded)."""
    out: list[QKeySequence] = []
    for key in keys:
        if isinstance(key, QKeySequence.StandardKey):
            found = platform_bindings(key)
        else:
            found = [key if isinstance(key, QKeySequence) else QKeySequence(key)]
        for sequence in found:
            if not sequence.isEmpty() and sequence not in out:
                out.append(sequence)
    return out
