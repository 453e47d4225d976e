"""Switching the window's language back and forth leaves nothing behind (day review 67:
after ~40 switches between English and Chinese each took ~3 s): no widget, object,
plot item or connection more after ten switches than after the first two."""

from __future__ import annotations

from collections import Counter

from PySide6.QtCore import QCoreApplication, QMetaMethod, QObject
from PySide6.QtWidgets import QApplication, QGraphicsView


def _receivers(obj: QObject) -> int:
    """The connections to ``obj``'s signals."""
    meta, count = obj.metaObject(), 0
    for i in range(meta.methodCount()):
        method = meta.method(i)
        if method.methodType() == QMetaMethod.MethodType.Signal:
            count += obj.receivers("2" + bytes(method.methodSignature()).decode())
    return count


def _census() -> Counter:
    """What the application holds: its widgets, its objects by class, the items of every
    plot's scene, and the connections of them all."""
    app = QCoreApplication.instance()
    objects = [app, *app.findChildren(QObject)]
    for top in QApplication.topLevelWidgets():
        objects += [top, *top.findChildren(QObject)]
    objects = list({id(o): o for o in objects}.values())
    census = Counter(type(o).__name__ for o in objects)
    census["(widgets)"] = len(QApplication.allWidgets())
    census["(plot items)"] = sum(len(v.scene().items()) for v in QApplication.allWidgets()
                                 if isinstance(v, QGraphicsView) and v.scene() is not None)
    census["(connections)"] = sum(_receivers(o) for o in objects)
    return census


def test_ten_language_switches_leave_nothing_behind(window, qtbot):
    window.load_all_samples()
    window.show()
    window.show_register()
    window.menus.live_signals_action.trigger()  # the fringe workbench's live window too
    for choice in ("zh_CN", "en"):  # what is made once, at the first switch, is made
        window.set_language(choice)
    qtbot.wait(50)
    before = _census()
    for _ in range(5):
        window.set_language("zh_CN")
        window.set_language("en")
    qtbot.wait(50)
    after = _census()
    grown = {name: (before[name], after[name]) for name in after
             if after[name] > before[name]}
    assert not grown, grown
    assert window.menus.undo_action.text()  # the window still speaks
