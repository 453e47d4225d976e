"""The live signals of the fringe workbench wired to the capture layer: a stream is a
:class:`app.capture.signal_worker.SignalStreamWorker`, the demonstration head a
:class:`app.capture.simulators.ReadHeadSimulator` on a TCP port of 127.0.0.1 in this
process, a take's raw session goes with the workbench's capture sessions (saved with the
project, checked for edits after capture as the capture panel's are) and the presets are
the built-in ones and the lab's own from its defaults."""

from __future__ import annotations

from app.capture.signal_worker import SignalStreamWorker
from app.capture.simulators import ReadHeadSimulator
from models.workbench import JudgesSignals

__all__ = ["DemonstrationHead", "attach_live_signals", "open_live_signals", "open_signal_stream"]

#: where the demonstration head starts: a little off its nominal mounting (0.8 mm, square),
#: so there is something to adjust
DEMONSTRATION_MOUNTING = {"gap_mm": 0.95, "yaw_mrad": 3.0, "roll_mrad": 15.0, "dirt": 0.0}


def open_signal_stream(port: str, pattern: str | None = None, baud: int | None = None
                       ) -> SignalStreamWorker:
    """A started worker reading the stream (ValueError for a pattern that does not hold)."""
    return SignalStreamWorker(port, pattern, baud).start()


class DemonstrationHead:
    """A simulated read head streaming on 127.0.0.1 until :meth:`close`."""

    def __init__(self, **mounting: float) -> None:
        settings = {**DEMONSTRATION_MOUNTING, **mounting}
        self.simulator = ReadHeadSimulator("tcp", seed=None, noise_mv=2.0, signal_hz=25.0,
                                           sample_hz=5000.0, wobble=0.2, **settings)
        self.simulator.__enter__()
        self.port = self.simulator.port

    def __getattr__(self, name: str):
        return getattr(self.__dict__["simulator"], name)

    def set(self, **mounting: float) -> None:
        self.simulator.set(**mounting)

    def close(self) -> None:
        self.simulator.__exit__(None, None, None)


def attach_live_signals(window) -> None:
    """Give every workbench view that has a live signals panel its stream opener, the
    demonstration head, its capture sessions and the lab defaults."""
    for presenter in window.presenters:
        if not isinstance(presenter.kind, JudgesSignals):  # its view_needs: the panel
            continue
        panel = presenter.view.live_signals
        key = presenter.kind.key
        panel.attach(open_signal_stream, DemonstrationHead,
                     sessions=lambda k=key: window.capture_panel.sessions.setdefault(k, []),
                     lab_defaults=lambda k=key: window.certificates.lab_defaults(k),
                     save_lab_defaults_entry=window.certificates.save_lab_defaults_entry,
                     workbench=key)


def open_live_signals(window) -> bool:
    """Instrument › Live signals…: the workbench with a live signals window (the fringe
    workbench) brought to the front, its live window opened; False when there is none."""
    for index, presenter in enumerate(window.presenters):
        if isinstance(presenter.kind, JudgesSignals):  # its view_needs: the opener
            window.tabs.setCurrentIndex(index)
            presenter.view.open_live_signals()
            return True
    return False
