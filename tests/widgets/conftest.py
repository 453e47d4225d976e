"""Fixtures of the widget tests."""

from __future__ import annotations

from unittest import mock

import pytest


@pytest.fixture
def presenter_and_view(qtbot):
    """The positioning workbench's presenter over a mocked view (what it asks and tells is
    recorded), owned by a widget deleted after the test."""
    import shiboken6
    from PySide6.QtWidgets import QWidget

    from widgets.positioning.presenter import PositioningPresenter
    from widgets.positioning.view import PositioningView

    view = mock.create_autospec(PositioningView, instance=True)
    view.settings_values.return_value = {}
    owner = QWidget()
    presenter = PositioningPresenter(view, parent=owner)
    yield presenter, view
    shiboken6.delete(owner)
