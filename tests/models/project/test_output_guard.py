"""No output lands on the register or an input: the same file found through symbolic and
hard links, the register's journal files by name, any SQLite database by its content."""

from __future__ import annotations

import os
import sqlite3

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.project.atomic_write import write_bytes_atomic
from models.project.output_guard import (
    OutputRefused,
    check_output,
    check_outputs,
    input_files,
    open_project,
    refuse_database,
    refuse_other_kinds,
    register_files,
    same_file,
    sqlite_path_of_url,
)


def _database(path):
    connection = sqlite3.connect(path)
    connection.execute("create table t (x)")
    connection.commit()
    connection.close()


def test_same_file_through_symbolic_and_hard_links(tmp_path):
    a = tmp_path / "a.csv"
    a.write_text("x")
    (tmp_path / "sym.csv").symlink_to(a)
    os.link(a, tmp_path / "hard.csv")
    (tmp_path / "dir").mkdir()
    (tmp_path / "dirlink").symlink_to(tmp_path / "dir")
    assert same_file(a, tmp_path / "sym.csv") and same_file(a, tmp_path / "hard.csv")
    assert same_file(a, tmp_path / "dir" / ".." / "a.csv")
    assert not same_file(a, tmp_path / "b.csv")
    # not there yet: compared by the resolved path
    assert same_file(tmp_path / "dir" / "new.pdf", tmp_path / "dirlink" / "new.pdf")
    (tmp_path / "b.csv").write_text("x")  # same content, another file
    assert not same_file(a, tmp_path / "b.csv")


def test_the_register_url_names_its_files():
    assert str(sqlite_path_of_url("sqlite:////data/r.sqlite")) == "/data/r.sqlite"
    assert str(sqlite_path_of_url("/data/r.sqlite")) == "/data/r.sqlite"  # a plain path
    assert str(sqlite_path_of_url("sqlite:///rel/r.sqlite")) == "rel/r.sqlite"
    assert sqlite_path_of_url("postgresql://u@h/db") is None
    assert sqlite_path_of_url("sqlite:///:memory:") is None
    names = [str(p.path) for p in register_files("sqlite:////data/r.sqlite")]
    # and the note naming the process that holds its write lock (reg72 #8)
    assert names == ["/data/r.sqlite", "/data/r.sqlite-journal", "/data/r.sqlite-wal",
                     "/data/r.sqlite-shm", "/data/r.sqlite.issuing", "/data/r.sqlite.writer"]


@pytest.mark.parametrize("suffix", ["", "-wal", "-shm", "-journal"])
def test_an_output_onto_the_register_or_its_journal_is_refused(tmp_path, suffix):
    register = tmp_path / "clash" / "register.sqlite"
    register.parent.mkdir()
    _database(register)
    protected = register_files(f"sqlite:///{register}")
    target = tmp_path / "clash" / f"register.sqlite{suffix}"
    with pytest.raises(OutputRefused, match="is the certificate register"):
        check_output(target, protected, "--certificate")
    link = tmp_path / "innocent.pdf"
    link.symlink_to(target)
    with pytest.raises(OutputRefused, match="is the certificate register"):
        check_output(link, protected)
    check_output(tmp_path / "clash" / "register.pdf", protected)  # beside it: fine


def test_a_hard_link_to_the_register_and_inputs_and_the_open_project(tmp_path):
    register = tmp_path / "register.sqlite"
    _database(register)
    os.link(register, tmp_path / "cert.pdf")
    with pytest.raises(OutputRefused) as refused:
        check_output(tmp_path / "cert.pdf", register_files(f"sqlite:///{register}"), "--pdf")
    assert str(refused.value).startswith(f"--pdf {tmp_path / 'cert.pdf'} is the certificate "
                                         f"register ({register})")
    readings = tmp_path / "r.csv"
    readings.write_text("theta_deg\n")
    with pytest.raises(OutputRefused, match=r"is an input"):
        check_output(readings, input_files([readings, None]))
    project = tmp_path / "p.anglebench.json"
    project.write_text("{}")
    with pytest.raises(OutputRefused, match=r"is the open project"):
        check_output(project, open_project(project))
    with pytest.raises(OutputRefused, match="--out and --raw name the same file"):
        check_outputs((("--out", tmp_path / "o.csv"), ("--raw", tmp_path / "o.csv")), [])
    check_outputs((("--out", tmp_path / "o.csv"), ("--raw", None)), [])


def test_no_write_replaces_a_database_whoever_asks(tmp_path):
    """The last line: write_bytes_atomic refuses a SQLite database (any register, even one
    not configured), its journal files, and leaves it byte for byte."""
    other = tmp_path / "someone-elses-register.sqlite"
    _database(other)
    before = other.read_bytes()
    for target in (other, tmp_path / "someone-elses-register.sqlite-wal"):
        with pytest.raises(OutputRefused, match="is a database"):
            write_bytes_atomic(target, b"%PDF-1.7")
    assert other.read_bytes() == before
    assert isinstance(OutputRefused("x"), OSError)  # every writer's "cannot write" path
    plain = tmp_path / "plain.csv"
    write_bytes_atomic(plain, b"a,b\n")
    write_bytes_atomic(plain, b"c,d\n")  # an ordinary file is replaced as before
    assert plain.read_bytes() == b"c,d\n"


@settings(max_examples=60, deadline=None)
@given(st.binary(max_size=40))
def test_only_a_database_or_its_journal_is_refused_by_content(tmp_path_factory, head):
    path = tmp_path_factory.mktemp("sniff") / "f.bin"
    path.write_bytes(head)
    magic = (b"SQLite format 3\x00", bytes.fromhex("d9d505f920a163d7"),
             bytes.fromhex("377f0682"), bytes.fromhex("377f0683"))
    if any(head.startswith(m) for m in magic):
        with pytest.raises(OutputRefused):
            refuse_database(path)
    else:
        refuse_database(path)


def test_a_folder_or_a_missing_folder_is_refused_before_anything_is_written(tmp_path):
    """#61 review: --certificate naming a folder was found only at the write, after the
    register had issued the number (the PDF then fetched with 'register show')."""
    with pytest.raises(OutputRefused, match="is a folder"):
        check_output(tmp_path, [], "--certificate")
    with pytest.raises(OutputRefused, match="does not exist"):
        check_output(tmp_path / "no such folder" / "c.pdf", [], "--certificate")
    check_output(tmp_path / "c.pdf", [])  # a new file in a folder that is there: fine


@pytest.mark.parametrize("length", [240, 250, 255])
def test_a_name_as_long_as_the_folder_allows_is_written(tmp_path, length):
    """#61 review: a legal 241–255-byte name failed with "File name too long": the temp file
    beside it added 14 bytes. The temp name is cut, the file written under its own name."""
    limit = os.pathconf(tmp_path, "PC_NAME_MAX")
    name = ("证" * ((length - 4) // 3) + "x" * ((length - 4) % 3) + ".pdf")
    assert len(name.encode()) == length <= limit
    write_bytes_atomic(tmp_path / name, b"%PDF once")
    write_bytes_atomic(tmp_path / name, b"%PDF twice")  # replacing it too
    assert (tmp_path / name).read_bytes() == b"%PDF twice"
    assert [p.name for p in tmp_path.iterdir()] == [name]  # no temp file left


@pytest.mark.parametrize("flag, name, other", [
    ("--certificate", "certificate_positioning.json", b'{"customer": "ACME"}'),
    ("--certificate", "readings.csv", b"angle,reading\n0,1.2\n"),
    ("--dcc", "c.xml", b"%PDF-1.7 a certificate, not a DCC"),
    ("--results", "r.xlsx", b"angle,reading\n0,1.2\n"),
    ("--pdf", "notes.txt", b"a lab's notes"),
])
def test_an_output_of_another_kind_than_the_file_it_names_is_refused(tmp_path, flag, name, other):
    """thbias2's run: ``--certificate certificate_positioning.json`` (meant as --metadata)
    wrote a PDF over the lab's JSON, no input of that run; now refused, the file intact."""
    target = tmp_path / name
    target.write_bytes(other)
    with pytest.raises(OutputRefused, match="exists and is not"):
        refuse_other_kinds([(flag, str(target))])
    assert target.read_bytes() == other


@pytest.mark.parametrize("flag, name, same", [
    ("--certificate", "c.pdf", b"%PDF-1.7\n..."),
    ("--dcc", "c.xml", b'\n  <?xml version="1.0"?><dcc/>'),
    ("--dcc", "c.xml", b'\xef\xbb\xbf<?xml version="1.0"?><dcc/>'),
    ("--results", "r.xlsx", b"PK\x03\x04..."),
    ("--results", "r.csv", b"anything: a CSV is text"),
    ("--table", "t.txt", b"anything"),
    ("--certificate", "empty.pdf", b""),
])
def test_an_earlier_output_of_the_same_kind_is_replaced_as_before(tmp_path, flag, name, same):
    target = tmp_path / name
    target.write_bytes(same)
    refuse_other_kinds([(flag, str(target))])
