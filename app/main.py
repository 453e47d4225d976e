"""Entry point of the ``anglebench`` command.

    anglebench [PROJECT]            open the window (optionally on a project file)
    anglebench --version            the version and the source's commit (or digest)
    anglebench --samples            open the window on the bundled samples
    anglebench --screenshot DIR     write DIR/<workbench>.png for every workbench, then exit
    anglebench analyze KIND FILE …  analyse a CSV without a window (see app.cli)
    anglebench validate [--pdf OUT] run the method validation cases (see app.validation_report)
    anglebench register list|show|verify|export …  the certificate register (app.register_cli)
    anglebench capture INSTRUMENT PORT --out FILE.csv  readings from an instrument (app.capture.cli)
    anglebench simulate INSTRUMENT PORT  a demonstration instrument (app.capture.simulate_cli)
"""

from __future__ import annotations

import argparse
import os
import sys

from app.process_setup import tune_process

tune_process()  # before numpy is imported: one BLAS thread, freed arrays kept for reuse

# the commands without a window (``anglebench COMMAND …``); a workbench may not take their
# names (app/new_workbench.py refuses them)
COMMANDS = ("analyze", "register", "capture", "simulate", "validate")


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv[:1] == ["--version"]:
        from models.software import software_identity

        print(software_identity().line())  # noqa: T201 - the command's output
        return 0
    if argv and argv[0] == "analyze":
        from app.cli import run_analyze  # no Qt import on this path

        return run_analyze(argv[1:])
    if argv and argv[0] == "register":
        from app.register_cli import run_register  # no Qt import on this path

        return run_register(argv[1:])
    if argv and argv[0] == "capture":
        from app.capture.cli import run_capture  # no Qt import on this path

        return run_capture(argv[1:])
    if argv and argv[0] == "simulate":
        from app.capture.simulate_cli import run_simulate  # no Qt import on this path

        return run_simulate(argv[1:])
    if argv and argv[0] == "validate":
        from app.validation_report import run_validate  # no Qt import on this path

        return run_validate(argv[1:])
    from app.command_line import Parser, language_asked, speaking
    from models.messages import QT_TR_NOOP

    with speaking(language_asked(argv)) as words:
        parser = Parser(
            prog="anglebench", description=words(QT_TR_NOOP("Angle metrology workbench")),
            epilog=words(QT_TR_NOOP("Commands without a window: anglebench analyze KIND FILE, "
                                    "anglebench validate, anglebench register, anglebench "
                                    "capture, anglebench simulate; each has --help.")))
        parser.add_argument("project", nargs="?", help=words(QT_TR_NOOP("project file to open")))
        parser.add_argument("--version", action="store_true", help=words(QT_TR_NOOP(
            "print the version and the source's commit (or, installed without git, the "
            "digest of its source files), then exit")))
        parser.add_argument("--samples", action="store_true",
                            help=words(QT_TR_NOOP("load the bundled samples")))
        parser.add_argument("--screenshot", metavar="DIR", help=words(QT_TR_NOOP(
            "render every workbench with its sample to DIR/<workbench>.png")))
        parser.add_argument("--size", metavar="WxH", default="1400x900", type=_size_reader(words),
                            help=words(QT_TR_NOOP(
                                "the window's size for --screenshot, in logical pixels (with "
                                "QT_SCALE_FACTOR=2, 960x540 is a 1920x1080 screen at 200 %%)")))
        parser.add_argument("--language", choices=("system", "en", "zh_CN"), default=None,
                            help=words(QT_TR_NOOP(
                                "the language of the window (default: as last chosen in View "
                                "› Language), of --screenshot's window (default: en) and of "
                                "this help")))
        args = parser.parse_args(argv)
    if args.version:
        from models.software import software_identity

        print(software_identity().line())  # noqa: T201 - the command's output
        return 0
    if args.screenshot:
        import tempfile
        from pathlib import Path

        from app.screenshot import offscreen_platform, write_screenshots

        with tempfile.TemporaryDirectory(prefix="anglebench-screenshot-") as scratch:
            # rendered offscreen on a screen of the window's size, so that a window fitted
            # to its screen (the Live signals) is laid out as on that screen (day review 68
            # F10: Qt's offscreen screen of 800×800 px gave another layout than the window's)
            if "QT_QPA_PLATFORM" not in os.environ:
                os.environ["QT_QPA_PLATFORM"] = offscreen_platform(args.size, Path(scratch))
            for path in write_screenshots(args.screenshot, args.size, args.language or "en"):
                print(path)  # noqa: T201 - the command's output
        return 0
    return run_gui(args.project, args.samples, words, args.language)


def _size_reader(words):
    """``--size``'s reader, refusing in the language of ``words``."""
    from models.messages import QT_TR_NOOP, message, rendered

    def size(text: str) -> tuple[int, int]:
        try:
            width, height = (int(v) for v in text.lower().split("x"))
        except ValueError:
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: give the size as WxH, e.g. 1280x720"), text=repr(text)), words)) from None
        if not (320 <= width <= 8000 and 240 <= height <= 8000):
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: 320x240 to 8000x8000"), text=repr(text)), words))
        return width, height

    return size


# Qt's X11 platform needs these system libraries (Debian/Ubuntu package names): those the
# xcb platform plugin (plugins/platforms/libqxcb.so) and its libQt6XcbQpa load
# (``readelf -d``: NEEDED; tests/app/test_x11_libraries.py checks the installed plugin
# against this list) and libEGL/fontconfig, which Qt's GUI module loads. Without one of them
# Qt aborts with "could not load the Qt platform plugin xcb". (Before day review 65 the
# xcb core, util, randr, shm, sync, xfixes, render, shape and xkb libraries, X11's, GL's and
# GLib's were not named: a machine lacking one got Qt's abort, not the apt-get line.)
X11_LIBRARIES = {"libxcb-cursor.so.0": "libxcb-cursor0", "libxcb-icccm.so.4": "libxcb-icccm4",
                 "libxcb-keysyms.so.1": "libxcb-keysyms1", "libxcb-image.so.0": "libxcb-image0",
                 "libxcb-render-util.so.0": "libxcb-render-util0",
                 "libxcb-util.so.1": "libxcb-util1", "libxcb-randr.so.0": "libxcb-randr0",
                 "libxcb-shm.so.0": "libxcb-shm0", "libxcb-sync.so.1": "libxcb-sync1",
                 "libxcb-xfixes.so.0": "libxcb-xfixes0", "libxcb-render.so.0": "libxcb-render0",
                 "libxcb-shape.so.0": "libxcb-shape0", "libxcb-xkb.so.1": "libxcb-xkb1",
                 "libxcb.so.1": "libxcb1", "libX11-xcb.so.1": "libx11-xcb1",
                 "libX11.so.6": "libx11-6", "libxkbcommon.so.0": "libxkbcommon0",
                 "libxkbcommon-x11.so.0": "libxkbcommon-x11-0", "libGL.so.1": "libgl1",
                 "libglib-2.0.so.0": "libglib2.0-0", "libgthread-2.0.so.0": "libglib2.0-0",
                 "libEGL.so.1": "libegl1", "libfontconfig.so.1": "libfontconfig1"}


def xcb_platform_chosen(environ=None) -> bool:
    """Whether Qt will start the window on its X11 (xcb) platform: QT_QPA_PLATFORM's first
    platform (``xcb``, ``xcb:option=…``, ``xcb;wayland``) when it is set, else X11 when
    there is a display (DISPLAY) and no Wayland session (Qt 6 prefers Wayland there). Not
    for ``offscreen``, ``wayland``, ``vnc`` and the others."""
    env = os.environ if environ is None else environ
    asked = env.get("QT_QPA_PLATFORM", "").strip()
    if asked:
        return asked.split(";")[0].split(":")[0].strip().lower() == "xcb"
    wayland = bool(env.get("WAYLAND_DISPLAY")) or env.get("XDG_SESSION_TYPE") == "wayland"
    return bool(env.get("DISPLAY")) and not wayland


def missing_x11_packages() -> list[str]:
    """The Debian packages Qt's X11 platform needs and this machine lacks, each once, in the
    order of :data:`X11_LIBRARIES` (Linux, when the window will start on X11 only: empty
    elsewhere and offscreen)."""
    import ctypes

    if not sys.platform.startswith("linux") or not xcb_platform_chosen():
        return []
    missing: list[str] = []
    for soname, package in X11_LIBRARIES.items():
        try:
            ctypes.CDLL(soname)
        except OSError:
            if package not in missing:
                missing.append(package)
    return missing


def run_gui(project: str | None, samples: bool, words=str, language: str | None = None) -> int:
    missing = missing_x11_packages()
    if missing:
        from models.messages import QT_TR_NOOP, message, rendered

        sys.stderr.write(rendered(message(QT_TR_NOOP(
            "anglebench: the window needs Qt's X11 libraries; install them with\n"
            "  sudo apt-get install {packages}"), packages=" ".join(missing)), words) + "\n")
        return 1
    from PySide6.QtWidgets import QApplication

    from app.main_window import MainWindow

    app = QApplication.instance() or QApplication(sys.argv[:1])
    app.setOrganizationName("AngleBench")
    app.setApplicationName("AngleBench")
    # cyclic garbage (a Qt object in a cycle) destroyed in a worker thread deadlocks the
    # window: collected in the GUI thread only
    from widgets.gui_garbage_collector import collect_in_gui_thread

    collect_in_gui_thread(app)
    window = MainWindow()
    if language:  # --language: the window in it (and View › Language set to it)
        window.set_language(language)
    window.show()
    if not window.projects.offer_recovery():
        if project:
            window.projects.open_project(project)
        elif samples:
            window.load_all_samples()
    return app.exec()


#: the status of a command whose output pipe closed before a binary write: what the shell
#: gives a program that SIGPIPE ended (128 + 13); its verdict is not known
EXIT_CLOSED_PIPE = 141


class _ClosedPipeQuiet:
    """Standard output that a closed pipe silences instead of stopping the command: what
    is written after the reader went (``anglebench register verify | head -1``) is
    discarded, and the command finishes its work and exits with its own status — verify's
    3 for a forged record, not 0 because ``head`` stopped reading (stop 72's leftover)."""

    def __init__(self, stream) -> None:
        self._stream = stream
        self._closed = False

    def _gone(self) -> None:
        self._closed = True
        try:  # Python's own flush of what is still buffered, at exit, must not fail
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, self._stream.fileno())
        except (OSError, ValueError):
            pass

    def write(self, text: str) -> int:
        if not self._closed:
            try:
                return self._stream.write(text)
            except BrokenPipeError:
                self._gone()
        return len(text)

    def flush(self) -> None:
        if not self._closed:
            try:
                self._stream.flush()
            except BrokenPipeError:
                self._gone()

    def __getattr__(self, name: str):
        return getattr(self._stream, name)


def entry() -> int:
    """The console script: a closed pipe (``anglebench analyze … | head``) ends quietly,
    and the command's exit status is still its own (:class:`_ClosedPipeQuiet`)."""
    sys.stdout = _ClosedPipeQuiet(sys.stdout)  # type: ignore[assignment]
    try:
        return main()
    except BrokenPipeError:  # written past the guard (a binary write): nothing is known
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())  # Python's own flush at exit must not fail
        return EXIT_CLOSED_PIPE


if __name__ == "__main__":
    raise SystemExit(entry())
