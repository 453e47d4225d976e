"""Where the register is: ``ANGLEBENCH_REGISTER`` (a database URL or a file path) when set,
else a SQLite file in the user's data folder (nothing to set up)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

__all__ = ["ENV_VAR", "default_register_url", "register_url", "url_for_path"]

ENV_VAR = "ANGLEBENCH_REGISTER"


def _data_dir() -> Path:
    if sys.platform == "win32":
        base = Path(os.environ.get("APPDATA") or Path.home() / "AppData" / "Roaming")
    elif sys.platform == "darwin":
        base = Path.home() / "Library" / "Application Support"
    else:
        base = Path(os.environ.get("XDG_DATA_HOME") or Path.home() / ".local" / "share")
    return base / "AngleBench"


def url_for_path(path: str | os.PathLike[str]) -> str:
    return f"sqlite:///{Path(path).expanduser().resolve()}"


def default_register_url() -> str:
    return url_for_path(_data_dir() / "register.sqlite")


def register_url(configured: str = "", explicit: str = "") -> str:
    """Return the URL of the register to use. The first one given wins: ``explicit`` (a
    command-line option), then the environment variable, then ``configured`` (the window's
    setting), and otherwise the default file. A value without ``://`` is taken as the path of
    a SQLite file."""
    value = explicit.strip() or os.environ.get(ENV_VAR, "").strip() or configured.strip()
    if not value:
        return default_register_url()
    return value if "://" in value else url_for_path(value)
