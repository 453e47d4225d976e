"""Which AngleBench this is: the version and the source it was run from (ISO/IEC 17025
7.11.2: the software is identified on every result it produces).

A version number alone does not identify the code (127 commits once carried 0.1.0, the one
that reversed the polygon correction's sign among them). So the source is named too: run
from a git checkout, by its commit (``git rev-parse HEAD``, with ``git describe --dirty``
saying whether files were changed after it); installed without git, by a SHA-256 digest
over the source files themselves (``*.py`` of app, models and widgets, in path order).
``anglebench --version``, every certificate, the validation report and every register
record carry :func:`software_identity`.
"""

from __future__ import annotations

import functools
import hashlib
import subprocess
from dataclasses import dataclass
from pathlib import Path

from models import __version__

__all__ = ["SoftwareIdentity", "software_identity"]

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("app", "models", "widgets")


@dataclass(frozen=True)
class SoftwareIdentity:
    version: str
    commit: str = ""  # the full hash, when run from a git checkout
    describe: str = ""  # git describe --always --dirty: "-dirty" when files were changed
    source_sha256: str = ""  # without git: the digest of the source files

    @property
    def modified(self) -> bool:
        return self.describe.endswith("-dirty")

    @property
    def source(self) -> str:
        """The source, in one short line: "commit 5cee365e4f12… (modified)" or "source
        sha256 …"."""
        if self.commit:
            return f"commit {self.commit}" + (" + local changes" if self.modified else "")
        return f"source sha256 {self.source_sha256}"

    @property
    def printed(self) -> str:
        """On a document, in any language: "0.2.0 (git 5cee365…, 40 digits)", a "+" after
        the commit when files were changed after it, or "0.2.0 (sha256 …)"."""
        if self.commit:
            return f"{self.version} (git {self.commit}{'+' if self.modified else ''})"
        return f"{self.version} (sha256 {self.source_sha256})"

    @property
    def short(self) -> str:
        """For a page's foot: the version and 12 digits of the commit (or the digest)."""
        if self.commit:
            return f"{self.version} (git {self.commit[:12]}{'+' if self.modified else ''})"
        return f"{self.version} (sha256 {self.source_sha256[:12]})"

    def line(self) -> str:
        """What ``anglebench --version`` prints."""
        return f"AngleBench {self.version}, {self.source}"

    def as_dict(self) -> dict[str, str]:
        out = {"version": self.version}
        if self.commit:
            out["commit"] = self.commit
            out["describe"] = self.describe
        else:
            out["source_sha256"] = self.source_sha256
        return out


def _git(*args: str, root: Path = ROOT) -> str:
    # safe.directory: a checkout owned by another user (a CI container) is still named
    run = subprocess.run(["git", "-c", "safe.directory=*", "-C", str(root), *args],
                         capture_output=True, text=True, timeout=10, check=True)
    return run.stdout.strip()


#: tracked files the software writes as its own pictures (``make pictures``): changed while
#: the pictures are made, they are not a change to the software that makes them
OUTPUTS = ("resources/screenshots",)


def describe_checkout(root: Path = ROOT) -> str:
    """``git describe --always --abbrev=12`` with "-dirty" when a tracked file other than
    the pictures in :data:`OUTPUTS` differs from the commit (``git describe --dirty`` counts
    those too: the README pictures' feet said "+" for the pictures being written)."""
    describe = _git("describe", "--always", "--abbrev=12", root=root)
    changed = _git("status", "--porcelain", "--untracked-files=no", "--", ".",
                   *(f":(exclude){path}" for path in OUTPUTS), root=root)
    return describe + ("-dirty" if changed else "")


def source_digest(root: Path = ROOT) -> str:
    """SHA-256 over the source files (their paths and contents), in path order."""
    digest = hashlib.sha256()
    for package in PACKAGES:
        for path in sorted((root / package).rglob("*.py")):
            if "__pycache__" in path.parts:
                continue
            digest.update(path.relative_to(root).as_posix().encode() + b"\0")
            digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


@functools.cache
def software_identity() -> SoftwareIdentity:
    """This process's AngleBench (computed once: the source does not change under it)."""
    if (ROOT / ".git").exists():
        try:
            commit = _git("rev-parse", "HEAD")
            describe = describe_checkout()
        except (OSError, subprocess.SubprocessError):
            commit = describe = ""
        if len(commit) == 40:
            return SoftwareIdentity(__version__, commit, describe)
    return SoftwareIdentity(__version__, source_sha256=source_digest())
