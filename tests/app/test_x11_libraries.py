"""The window's start-up check of Qt's X11 libraries (app/main.py): it names the Debian
package of every system library the xcb platform plugin loads, and only when the window
will start on X11.

Day review 65: the list named eight packages (the cursor, icccm, keysyms, image and
render-util libraries among them) but not the xcb core, util, randr, shm, sync, xfixes,
render, shape and xkb libraries, X11's, GL's nor GLib's — all loaded by the plugin: a
machine lacking one of those got Qt's "could not load the Qt platform plugin xcb" abort
instead of the apt-get line."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from app import main as entry

#: libraries of the C and C++ runtime: on every Linux system, never a missing package
_RUNTIME = ("libc.so", "libm.so", "libstdc++.so", "libgcc_s.so", "libpthread.so", "libdl.so",
            "ld-linux", "librt.so")


def _needed(library: Path) -> set[str]:
    """The system libraries ``library`` loads itself (its ELF NEEDED entries), Qt's and the
    C/C++ runtime's aside."""
    out = subprocess.run(["readelf", "-d", str(library)], capture_output=True, text=True,
                         check=True).stdout
    names = {line.split("[", 1)[1].split("]", 1)[0] for line in out.splitlines()
             if "(NEEDED)" in line}
    return {n for n in names if not n.startswith("libQt6")
            and not n.startswith(_RUNTIME)}


@pytest.mark.skipif(not sys.platform.startswith("linux") or shutil.which("readelf") is None,
                    reason="the ELF plugin and readelf are Linux's")
def test_every_library_the_xcb_plugin_loads_is_named():
    import PySide6

    qt = Path(PySide6.__file__).parent / "Qt"
    plugin = qt / "plugins" / "platforms" / "libqxcb.so"
    needed = _needed(plugin) | _needed(qt / "lib" / "libQt6XcbQpa.so.6")
    assert "libxcb-cursor.so.0" in needed  # the plugin read
    # was: libxcb-util, -randr, -shm, -sync, -xfixes, -render, -shape, -xkb, libxcb,
    # libX11-xcb, libX11, libxkbcommon, libGL, libglib and libgthread not named
    assert sorted(needed - set(entry.X11_LIBRARIES)) == []


def _linux_with(monkeypatch, absent: set[str], **environment: str) -> None:
    """Linux, with ``environment`` only of the display's variables, and the ``absent``
    libraries failing to load."""
    import ctypes

    monkeypatch.setattr(sys, "platform", "linux")
    for name in ("DISPLAY", "WAYLAND_DISPLAY", "XDG_SESSION_TYPE", "QT_QPA_PLATFORM"):
        monkeypatch.delenv(name, raising=False)
    for name, value in environment.items():
        monkeypatch.setenv(name, value)
    def cdll(name, *args, **kwargs):
        # every other library loads, whatever this machine has (a fresh one may lack
        # libxcb-icccm4 and others until .ci/run installs them)
        if name in absent:
            raise OSError(f"{name}: cannot open shared object file")
        return object()

    monkeypatch.setattr(ctypes, "CDLL", cdll)


def test_the_missing_libraries_are_named_by_their_packages_once(monkeypatch, capsys):
    _linux_with(monkeypatch, {"libxcb-util.so.1", "libxcb-randr.so.0", "libglib-2.0.so.0",
                              "libgthread-2.0.so.0", "libxcb-cursor.so.0"}, DISPLAY=":99")
    # as under xvfb-run: DISPLAY, no QT_QPA_PLATFORM
    assert entry.missing_x11_packages() == ["libxcb-cursor0", "libxcb-util1", "libxcb-randr0",
                                            "libglib2.0-0"]
    assert entry.run_gui(None, False) == 1
    assert ("sudo apt-get install libxcb-cursor0 libxcb-util1 libxcb-randr0 libglib2.0-0"
            in capsys.readouterr().err)


@pytest.mark.parametrize("environment,xcb", [
    ({"DISPLAY": ":99"}, True),
    ({"QT_QPA_PLATFORM": "xcb", "DISPLAY": ":0"}, True),
    # a platform with options, or a list of platforms tried in turn: its first
    ({"QT_QPA_PLATFORM": "xcb:dpi=96", "DISPLAY": ":0"}, True),
    ({"QT_QPA_PLATFORM": "xcb;wayland", "DISPLAY": ":0"}, True),
    ({"QT_QPA_PLATFORM": "wayland;xcb", "DISPLAY": ":0"}, False),
    ({"QT_QPA_PLATFORM": "offscreen", "DISPLAY": ":0"}, False),
    ({"QT_QPA_PLATFORM": "vnc"}, False),
    # a Wayland session: Qt 6 starts on Wayland
    ({"DISPLAY": ":0", "WAYLAND_DISPLAY": "wayland-0"}, False),
    ({"DISPLAY": ":0", "XDG_SESSION_TYPE": "wayland"}, False),
    ({"DISPLAY": ":0", "XDG_SESSION_TYPE": "x11"}, True),
    ({}, False),
])
def test_the_check_is_made_only_where_the_window_starts_on_x11(monkeypatch, environment, xcb):
    _linux_with(monkeypatch, {"libxcb-shape.so.0"}, **environment)
    assert entry.missing_x11_packages() == (["libxcb-shape0"] if xcb else [])
