"""Guards against a broken Qt binding.

PySide6-Essentials 6.12.0 drops a reference to the value a signal emit
returns (True) on every emit; after a few thousand emits the interpreter
aborts with "bool_dealloc: deallocating True or False". pyproject.toml
excludes that release; this test fails on any binding that does it again.
"""

import sys

from PySide6.QtCore import QObject, Signal


class _Emitter(QObject):
    value = Signal(int)


def test_signal_emit_keeps_reference_counts():
    emitter = _Emitter()
    received = []
    emitter.value.connect(received.append)
    before_true, before_none = sys.getrefcount(True), sys.getrefcount(None)
    for i in range(200):
        emitter.value.emit(i)
    assert received == list(range(200))
    assert sys.getrefcount(True) >= before_true - 5
    assert sys.getrefcount(None) >= before_none - 5
