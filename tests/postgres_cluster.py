"""A throw-away PostgreSQL cluster for the tests: initdb into a temporary folder, a server
on a Unix socket in that folder (no TCP port), one fresh database per test. As root (CI)
the server runs as the ``postgres`` user the Debian package creates, since PostgreSQL
refuses to run as root."""

from __future__ import annotations

import glob
import itertools
import os
import pwd
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["PostgresUnavailable", "start_cluster"]


class PostgresUnavailable(RuntimeError):
    pass


def _binary(name: str) -> str:
    found = shutil.which(name) or next(iter(sorted(
        glob.glob(f"/usr/lib/postgresql/*/bin/{name}"), reverse=True)), None)
    if not found:
        raise PostgresUnavailable(f"'{name}' not found (Debian: apt-get install postgresql)")
    return found


def _as_server_user(command: list[str]) -> list[str]:
    if os.geteuid() != 0:
        return command
    try:
        pwd.getpwnam("postgres")
    except KeyError:
        raise PostgresUnavailable("running as root and no 'postgres' user to run the server "
                                  "as") from None
    return ["runuser", "-u", "postgres", "--", *command]


@dataclass
class Cluster:
    folder: Path
    port: int
    _count: itertools.count = field(default_factory=lambda: itertools.count(1))

    @property
    def socket_dir(self) -> Path:
        return self.folder / "socket"

    def url(self, database: str = "postgres") -> str:
        return (f"postgresql+psycopg://postgres@/{database}?host={self.socket_dir}"
                f"&port={self.port}")

    def new_database(self) -> str:
        import psycopg

        name = f"register_{os.getpid()}_{next(self._count)}"
        with psycopg.connect(host=str(self.socket_dir), port=self.port, user="postgres",
                             dbname="postgres", autocommit=True, connect_timeout=30) as conn:
            conn.execute(f'CREATE DATABASE "{name}"')
        return self.url(name)

    def drop_database(self, url: str) -> None:
        """Drop the database of ``url`` (one of :meth:`new_database`'s), its sessions ended
        (a test may leave one open). Each test's is dropped after it: a session's ~200 kept
        to the end made ~1.6 GB a worker, whose removal at the end took 10-36 s of every
        worker's run (wall time on CI); a drop takes ~10 ms. A drop that fails is left to
        :meth:`stop`."""
        import psycopg

        name = url.split("@/", 1)[1].split("?", 1)[0]
        try:
            with psycopg.connect(host=str(self.socket_dir), port=self.port, user="postgres",
                                 dbname="postgres", autocommit=True,
                                 connect_timeout=30) as conn:
                conn.execute(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)')
        except psycopg.Error:
            pass

    def stop(self) -> None:
        subprocess.run(_as_server_user([_binary("pg_ctl"), "-D", str(self.folder / "data"),
                                        "-m", "immediate", "stop"]),
                       capture_output=True, check=False)
        shutil.rmtree(self.folder, ignore_errors=True)


def start_cluster() -> Cluster:
    """A cluster in a new folder under the system's temporary folder (pytest's own is
    private to root, which the server's user cannot enter)."""
    initdb, pg_ctl = _binary("initdb"), _binary("pg_ctl")
    folder = Path(tempfile.mkdtemp(prefix="anglebench-pg-"))
    (folder / "socket").mkdir(exist_ok=True)
    if os.geteuid() == 0:
        try:
            entry = pwd.getpwnam("postgres")
        except KeyError:
            raise PostgresUnavailable("running as root and no 'postgres' user") from None
        for path in (folder, folder / "socket"):
            os.chown(path, entry.pw_uid, entry.pw_gid)
        folder.chmod(0o755)
    port = 54_000 + os.getpid() % 1000
    run = subprocess.run(_as_server_user([initdb, "-D", str(folder / "data"), "-A", "trust",
                                          "-U", "postgres", "--no-sync", "-E", "UTF8"]),
                         capture_output=True, text=True, check=False)
    if run.returncode:
        raise PostgresUnavailable(f"initdb failed: {run.stderr.strip()[-300:]}")
    options = f"-k {folder / 'socket'} -c listen_addresses='' -p {port} -c fsync=off"
    run = subprocess.run(_as_server_user([pg_ctl, "-D", str(folder / "data"), "-o", options,
                                          "-l", str(folder / "server.log"), "-w", "start"]),
                         capture_output=True, text=True, check=False)
    if run.returncode:
        log = (folder / "server.log").read_text(errors="replace")[-300:] \
            if (folder / "server.log").exists() else run.stderr
        raise PostgresUnavailable(f"the server did not start: {log.strip()}")
    return Cluster(folder, port)
