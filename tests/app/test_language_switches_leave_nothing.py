"""Switching the window's language back and forth leaves nothing behind (day review 67:
after ~40 switches between English and Chinese each took ~3 s): no widget, object,
plot item or connection more after four switches than after the first two: one more
switch to Chinese and back is enough, what leaks leaks at every switch (the leak found left
two translators behind at every switch to Chinese; three rounds were checked until #44 cut
the suite's time: one fails on that leak as well, shown with widgets/i18n.py's
``Language._translators_of`` making new translators at every choice in a scratch copy)."""

from __future__ import annotations

from collections import Counter

from PySide6.QtCore import (
    QAbstractAnimation,
    QCoreApplication,
    QEvent,
    QMetaMethod,
    QObject,
)
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


def _settled(qtbot) -> Counter:
    """The census once Qt's own transient animations (a style's fade, a scroll bar's) have
    run out and what they delete is deleted: they come and go with the mouse and the
    timers, not with the language (one counted after the switches made the test fail at
    random)."""
    def running() -> bool:
        app = QCoreApplication.instance()
        found = app.findChildren(QAbstractAnimation)
        for top in QApplication.topLevelWidgets():
            found += top.findChildren(QAbstractAnimation)
        return any(a.state() == QAbstractAnimation.State.Running for a in found)

    qtbot.wait(50)
    qtbot.waitUntil(lambda: not running(), timeout=5000)
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    census = _census()
    census.pop("QPropertyAnimation", None)  # kept by a style for the next fade, or not
    return census


def test_language_switches_leave_nothing_behind(window, qtbot):
    window.load_all_samples()
    window.show()
    window.show_register()
    window.menus.live_signals_action.trigger()  # the fringe workbench's live window too
    for choice in ("zh_CN", "en"):  # what is made once, at the first switch, is made
        window.set_language(choice)
    before = _settled(qtbot)
    window.set_language("zh_CN")
    window.set_language("en")
    after = _settled(qtbot)
    grown = {name: (before[name], after[name]) for name in after
             if after[name] > before[name]}
    assert not grown, grown
    assert window.menus.undo_action.text()  # the window still speaks
