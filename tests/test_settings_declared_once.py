"""Each setting is declared once (models/parameters.py); the form, the command line, the
project-file check and the certificate's listing all come from that declaration."""

from __future__ import annotations

import io
import re

import pytest
from pypdf import PdfReader

from app.main import main
from models.parameters import SettingsError
from models.registry import KINDS, presenter_class

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

PAIRS = [(key, p) for key, kind in KINDS.items() for p in kind.parameters]


@pytest.fixture(scope="module")
def workbench_view(qapp):
    """``workbench_view(key)``: the workbench's form, made once for the module's ~70 settings
    (the tests only read it; a workbench's view takes ~0.3 s to make)."""
    presenters = {}

    def view(key: str):
        if key not in presenters:
            presenters[key] = presenter_class(KINDS[key])()
        return presenters[key].view

    yield view
    for presenter in presenters.values():
        presenter.view.close()
        presenter.view.deleteLater()


@pytest.fixture(scope="module")
def analyze_help() -> str:
    """What ``anglebench analyze --help`` prints (once for the module)."""
    import contextlib

    printed = io.StringIO()
    with contextlib.redirect_stdout(printed), pytest.raises(SystemExit):
        main(["analyze", "--help"])
    return printed.getvalue()


@pytest.mark.parametrize("key, parameter", PAIRS, ids=[f"{k}.{p.key}" for k, p in PAIRS])
def test_each_setting_reaches_form_cli_and_check(workbench_view, analyze_help, key, parameter):
    field = workbench_view(key).settings.field(parameter.key)
    assert field.toolTip() == parameter.help  # the form: one field, with the declared help
    if parameter.cli:
        assert parameter.flag in analyze_help
    if parameter.kind in ("int", "float") and parameter.maximum is not None:
        with pytest.raises(SettingsError, match=parameter.key):
            KINDS[key].checked_settings({parameter.key: parameter.maximum * 10 + 1})


def test_the_certificate_lists_the_settings_in_their_declared_words(tmp_path, capsys, samples_dir):
    out = tmp_path / "c.pdf"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--certificate",
                 str(out), "--closure-drift", "spread", "--zero-face", "2"]) == 0
    capsys.readouterr()
    text = re.sub(r"\s+", " ", "\n".join(p.extract_text() for p in PdfReader(
        io.BytesIO(out.read_bytes())).pages))
    assert "Analysis settings" in text
    assert "closure drift spread linearly, remove" in text
    assert "common zero at face 2" in text and "encoder counts auto (from the readings)" in text
