"""The instrument simulators the tests use: served from ``app/capture/simulators.py`` (the
window's and ``anglebench simulate``'s demonstration instruments), written from the
published protocols, not from the drivers (that module imports nothing of
``models.capture`` or ``app.capture``'s drivers; tests/test_architecture.py keeps it so)."""

from app.capture.simulators import (
    SIMULATORS,
    AutocollimatorSimulator,
    ReadoutSimulator,
    TheodoliteSimulator,
)

__all__ = ["SIMULATORS", "AutocollimatorSimulator", "ReadoutSimulator", "TheodoliteSimulator"]
