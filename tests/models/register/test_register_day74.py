"""day74 #4: a customer's copy edited after issue (a comment line appended before %%EOF;
its keywords, record digest and proof untouched) is ALTERED when the register proves its
record intact (signed, every signature checked), not "altered, or the register's record of
it was replaced"; and a genuine certificate No. 1 of another register — it prints the
all-zero head every register's first certificate prints — is said not to be this
register's, not ALTERED."""

from __future__ import annotations

import os
import shutil

import pytest

from models.register.store import IssueRequest, Register
from tests.models.register.test_register_reg72 import ISSUED, META, PROJECT
from tests.register_forgery import stand_in_pdf


def _key(tmp_path, name: str) -> str:
    path = tmp_path / name
    path.write_bytes(os.urandom(31) + b"k")
    return str(path)


def _open(url: str, key: str = "") -> Register:
    register = Register(url, timezone="UTC", key_file=key)
    register.clock = lambda: ISSUED  # type: ignore[method-assign]
    return register


def _issue(url: str, n: int, key: str = "") -> list[bytes]:
    with _open(url, key) as register:
        return [register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf,
                               document_kind="calibration")[1] for _ in range(n)]


def _said(url: str, data: bytes, key: str = "") -> str:
    from models.register.printed_place import say_its_place

    said: list[str] = []
    with _open(url, key) as register:
        assert not register.verify_all(data)  # not the PDF of any record
        assert not say_its_place(register, "c.pdf", data, lambda m: said.append(str(m)))
    return " ".join(said)


def _commented(pdf: bytes) -> bytes:
    """A comment line added before the last %%EOF (at the end when there is none, as in
    the stand-in): what a PDF tool's save may add; keywords, digest and proof untouched."""
    at = pdf.rfind(b"%%EOF")
    at = len(pdf) if at < 0 else at
    return pdf[:at] + b"\n% edited after issue\n" + pdf[at:]


@pytest.mark.parametrize("which", [0, 1])
def test_a_copy_altered_in_a_signed_intact_register_is_altered(tmp_path, which):
    url = f"sqlite:///{tmp_path / 'keyed.sqlite'}"
    key = _key(tmp_path, "lab.key")
    pdfs = _issue(url, 2, key)
    altered = _commented(pdfs[which])
    said = _said(url, altered, key)
    assert said.startswith("ALTERED: c.pdf (") and "the copy was altered after issue" in said
    assert "replaced" not in said and "not this PDF" not in said


def test_without_the_key_a_replaced_record_is_not_ruled_out(tmp_path):
    """The same copy in a register without the key: a record rewritten with its chain
    recomputed cannot be excluded, so ALTERED is not said alone."""
    url = f"sqlite:///{tmp_path / 'keyless.sqlite'}"
    altered = _commented(_issue(url, 1)[0])
    said = _said(url, altered)
    assert not said.startswith("ALTERED") and "replaced" in said


@pytest.mark.parametrize("keyed", [True, False])
def test_another_registers_first_certificate_is_not_this_registers(tmp_path, keyed):
    ours = f"sqlite:///{tmp_path / 'ours.sqlite'}"
    theirs = f"sqlite:///{tmp_path / 'theirs.sqlite'}"
    key = _key(tmp_path, "ours.key") if keyed else ""
    _issue(ours, 2, key)
    # another lab's register: its own key (or none), the same number scheme, another item
    import dataclasses

    other_meta = dataclasses.replace(META, customer_name="Another customer Ltd")
    with _open(theirs, _key(tmp_path, "theirs.key") if keyed else "") as register:
        _, their_first = register.issue(IssueRequest("polygon", other_meta, PROJECT),
                                        stand_in_pdf, document_kind="calibration")
    said = _said(ours, their_first, key)
    assert said.startswith("NOT ISSUED BY THIS REGISTER: c.pdf (") and "ALTERED" not in said
    # this register's own first certificate, edited, is still not called another's
    said = _said(ours, _commented(_first(ours, key)), key)
    assert "NOT ISSUED BY THIS REGISTER" not in said


def _first(url: str, key: str) -> bytes:
    with _open(url, key) as register:
        return register.pdf(register.list()[-1].number)


def test_the_newest_record_rewritten_is_not_said_to_be_removed(tmp_path):
    """regwin74: the high-water mark's finding said "records were removed since" of a
    register that holds every record, its newest rewritten (its chain recomputed): the
    data show a record replaced at the mark's place, and that is said."""
    from tests.models.register.test_register_reg73 import _rewrite_newest

    url = f"sqlite:///{tmp_path / 'keyed.sqlite'}"
    key = _key(tmp_path, "lab.key")
    _issue(url, 2, key)
    _rewrite_newest(url, customer="Someone else")
    with _open(url, key) as register:
        said = [str(p) for p in register.problems]
    assert not any("records were removed" in text for text in said)
    assert any("holds 2 record(s), but record 2 is not the one it held there" in text
               for text in said)
    # an older copy restored (a record fewer) is still said to have lost records
    url2 = f"sqlite:///{tmp_path / 'second.sqlite'}"
    _issue(url2, 1, key)
    shutil.copy(tmp_path / "second.sqlite", tmp_path / "backup.sqlite")
    _issue(url2, 1, key)
    shutil.copy(tmp_path / "backup.sqlite", tmp_path / "second.sqlite")
    with _open(url2, key) as register:
        assert any("records were removed since" in str(p) for p in register.problems)
