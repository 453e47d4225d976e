"""A file the process may not write, as an archive on a read-only share is to the register:
``os.access(…, W_OK)`` says no for the file and its folder (written once for the register
tests that open a read-only register)."""

from __future__ import annotations

import os


def deny_writing(monkeypatch, path) -> None:
    """``os.access`` says ``path`` and its folder are not writable; anything else as it is."""
    shut = (str(path), os.path.dirname(str(path)))
    real = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **k: False if (
        mode == os.W_OK and str(p) in shut) else real(p, mode, **k))
