"""What every workbench in the registry must have, each requirement with what to add and
where when it is missing. A new workbench (``make new-workbench NAME=…``) is checked by
this file first; the rest of the suite takes every workbench from the registry.

Run it alone on one workbench: ``pytest tests/test_workbench_contract.py -k NAME``.
"""

from __future__ import annotations

import functools
import inspect
import json
import math
import re
from pathlib import Path

import pytest

from models.certificate.metadata import CertificateMetadata
from models.messages import TRANSLATIONS_DIR, catalogue, declared_text, rendered
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS, presenter_class
from models.workbench import (
    CAPABILITIES,
    AcceptsReference,
    AcceptsRuns,
    IssuesCertificates,
    OverlaysRuns,
    SendsReference,
    SendsRuns,
    ShowsHeadline,
    Workbench,
    WritesCorrectionTable,
    view_needs,
)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "resources" / "samples"
MANUAL = ROOT / "resources" / "manual"
GUIDES = ROOT / "docs" / "user-guide"
LANGUAGES = ("zh_CN",)  # the languages besides English the window and certificates speak
SIGN_CONVENTIONS = ("indicated_minus_reference", "actual_minus_target")

pytestmark = pytest.mark.parametrize("key", list(KINDS))


def _where(key: str) -> str:
    return f"models/{key}/analysis.py"


@functools.cache  # each sample analysed once a process (tests only read it)
def _sample(key: str):
    kind = KINDS[key]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    parsed = ReadingsSheet(kind.columns, rows).parse()
    return kind, kind.analyze(parsed, kind.settings_with_defaults(kind.sample_settings))


def _words(text: str) -> bool:
    """Whether a text has words to translate (a symbol, a unit or a standard's name such as
    "ISO 230-2:2014" has none)."""
    return bool(re.search(r"[a-z]{2}", text))


def _templates(text) -> list[str]:
    """Every template a rendered text looked up."""
    seen: list[str] = []
    rendered(text, lambda template: seen.append(template) or template)
    return seen


# -- the core -------------------------------------------------------------------------
def test_is_a_workbench_listed_once_under_its_key(key):
    kind = KINDS[key]
    assert isinstance(kind, Workbench), (
        f"{key}: the registry's entry must be an object of a Workbench class (models/workbench.py)")
    assert kind.key == key and re.fullmatch(r"[a-z][a-z0-9_]*", key), (
        f"{key}: the key is lower-case letters, digits and _ and is the registry's key")
    assert [k for k in KINDS if k == key] == [key]


def test_key_and_title_are_given_once_in_the_package(key):
    import importlib

    package = importlib.import_module(f"models.{key}")
    assert getattr(package, "KEY", None) == key and getattr(package, "TITLE", None) == \
        KINDS[key].title, (f"models/{key}/__init__.py: set KEY = {key!r} and TITLE = "
                           "QT_TR_NOOP('…'); the workbench, its report and its view import them")
    assert KINDS[key].title, f"models/{key}/__init__.py: TITLE is empty"


def test_settings_and_columns_are_declared_whole(key):
    kind = KINDS[key]
    assert kind.columns, f"{_where(key)}: declare the readings columns (COLUMNS)"
    keys = [c.key for c in kind.columns]
    assert len(set(keys)) == len(keys), f"{_where(key)}: a column key is declared twice"
    for column in kind.columns:
        assert column.title and column.help, f"{_where(key)}: column {column.key} needs a title and help"
    for p in kind.parameters:
        assert p.label and p.help, f"{_where(key)}: setting {p.key} needs a label and help"
        assert p.check(p.default) == p.default, f"{_where(key)}: setting {p.key}'s default fails its check"
    assert kind.checked_settings({}) is not None, f"{_where(key)}: the defaults fail check_settings"
    for name in (kind.nominal_column, kind.entry_column):
        assert not name or name in keys, f"{_where(key)}: {name!r} is not one of its columns"
    for shortcut in kind.shortcuts:
        assert kind.parameter(shortcut.key).check(shortcut.value) == shortcut.value, (
            f"{_where(key)}: {shortcut.flag} sets {shortcut.key} to a value it refuses")
    for name, value in kind.sample_settings.items():
        assert kind.parameter(name).check(value) == value, (
            f"{_where(key)}: sample_settings[{name!r}] fails its declaration's check")
    assert kind.method_reference, (
        f"{_where(key)}: method_reference names the publication or standard the method follows")


def test_sample_parses_and_analyses(key):
    kind = KINDS[key]
    path = SAMPLES / kind.sample_file
    assert path.is_file(), f"{key}: add its sample readings as resources/samples/{kind.sample_file}"
    kind, result = _sample(key)
    assert result is not None


@pytest.mark.slow
def test_json_carries_the_sign_convention_and_the_warnings(key):
    kind, result = _sample(key)
    data = kind.to_json(result)
    assert isinstance(data, dict), f"{_where(key)}: to_json returns a dict"
    text = json.dumps(data, allow_nan=True)  # the command line writes it; NaN made null there
    assert json.loads(text) is not None
    assert data.get("sign_convention") in SIGN_CONVENTIONS, (
        f"{_where(key)}: to_json states 'sign_convention' (models.workbench.SIGN_CONVENTION "
        "for errors of indication)")
    assert isinstance(data.get("warnings"), list), f"{_where(key)}: to_json lists 'warnings'"


def test_summary_is_text(key):
    kind, result = _sample(key)
    summary = kind.summary(result)
    assert isinstance(summary, str) and summary.strip(), f"{_where(key)}: summary says something"


# -- documentation and language --------------------------------------------------------
def test_user_guide_and_manual_pages_in_every_language(key):
    """The user guide in docs/ in English and each language, linked from its index; the
    window's manual pages are made from them (``make docs``; tests/app/test_manual_pages.py
    holds them to their source)."""
    for language, folder in (("", GUIDES), *((f".{lang}", ROOT / "docs" / lang / "user-guide")
                                             for lang in LANGUAGES)):
        guide = folder / f"{key}.md"
        assert guide.is_file(), f"{key}: write its user guide {guide.relative_to(ROOT)}"
        index = folder / "index.md"
        assert f"]({key}.md)" in index.read_text("utf-8"), (
            f"{key}: link {guide.name} from {index.relative_to(ROOT)}")
        page = MANUAL / f"{key}{language}.html"
        index_page = MANUAL / f"index{language}.html"
        assert page.is_file() and f'href="{page.name}"' in index_page.read_text("utf-8"), (
            f"{key}: run `make docs` (resources/manual/{page.name} is made from {guide.name})")


def test_its_texts_are_translated(key):
    """The title, the settings and the sample's summary and verdict are in
    resources/translations/anglebench_zh_CN.ts (add them there, then `make translations`);
    a text ending in a unit ("arcseconds (\")") is translated without it."""
    kind, result = _sample(key)
    for language in LANGUAGES:
        words = catalogue(TRANSLATIONS_DIR / f"anglebench_{language}.ts")
        texts = [kind.title] + [t for p in kind.parameters for t in (p.label, p.help)] + [
            t for p in kind.parameters for _, t in p.choices]
        texts += _templates(kind.summary(result))
        if isinstance(kind, ShowsHeadline):
            texts += _templates(kind.verdict(result))
        translate = words.get
        missing = sorted({t for t in texts if _words(t) and declared_text(
            t, lambda s, translate=translate: translate(s) or s) == t})
        assert not missing, (f"{key}: no {language} translation in resources/translations/"
                             f"anglebench_{language}.ts for:\n  " + "\n  ".join(missing))


# -- validation -------------------------------------------------------------------------
@pytest.mark.slow
def test_the_validation_report_has_its_cases(key, validation_cases):
    """The cases of ``anglebench validate`` (computed once a session for the suite's runs of
    the report, tests/conftest.py)."""
    from tests.conftest import VALIDATION_TRIALS

    cases = validation_cases(VALIDATION_TRIALS)
    assert KINDS[key].title in {case.workbench for case in cases}, (
        f"{key}: the validation report (anglebench validate) has no case of it: return its "
        f"reference cases from validation_cases() in {_where(key)} (ValidationCase of "
        "models/validation/cases.py, workbench = its title; or models/<kind>/validation_cases.py) "
        "and update the case count in docs/certificates-and-register.md and its Chinese, "
        "docs/zh_CN/certificates-and-register.md")


# -- the window -------------------------------------------------------------------------
def test_presenter_lives_in_its_folder(key):
    from widgets.workbench_presenter import WorkbenchPresenter

    kind = KINDS[key]
    assert kind.presenter.startswith(f"widgets.{key}."), (
        f"{_where(key)}: presenter = 'widgets.{key}.presenter:…Presenter'")
    cls = presenter_class(kind)
    assert inspect.isclass(cls) and issubclass(cls, WorkbenchPresenter), (
        f"widgets/{key}/presenter.py: the presenter derives from WorkbenchPresenter")
    assert cls.view_class is not None, f"widgets/{key}/presenter.py: set view_class"


def test_its_view_has_what_its_capabilities_need(key, qtbot):
    """Each capability the window serves through the view names what it needs of it
    (``view_needs``: OverlaysRuns draws on ``error_plot.corrected_plot``, …); the window
    relies on them without asking, so every workbench's real view has each."""
    cls = presenter_class(KINDS[key])
    view = cls.view_class()
    qtbot.addWidget(view)
    for capability, needs in view_needs(KINDS[key]).items():
        for dotted in needs:
            holder = view
            for part in dotted.split("."):
                assert hasattr(holder, part), (
                    f"widgets/{key}/view.py: {key} is {capability}, whose view_needs names "
                    f"view.{dotted}; its view has no {part!r}")
                holder = getattr(holder, part)


@pytest.mark.slow
def test_presenter_shows_the_sample(key, qtbot):
    cls = presenter_class(KINDS[key])
    presenter = cls()
    qtbot.addWidget(presenter.view)
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None or bool(presenter.problem), timeout=20000)
    assert presenter.result is not None, f"widgets/{key}: the sample is not analysed: {presenter.problem}"
    assert presenter.view.title == KINDS[key].title, (
        f"widgets/{key}/view.py: the view's title is the workbench's TITLE (from models.{key})")


# -- capabilities ---------------------------------------------------------------------------
@pytest.mark.slow
def test_its_capabilities_work_on_the_sample(key, tmp_path):
    kind, result = _sample(key)
    declared = [c.__name__ for c in CAPABILITIES if isinstance(kind, c)]
    assert declared == [c.__name__ for c in CAPABILITIES if c in type(kind).__mro__]
    if isinstance(kind, ShowsHeadline):
        assert isinstance(kind.verdict(result), str) and kind.verdict(result), (
            f"{_where(key)}: verdict() says the result in one line")
        headline = kind.headline(result)
        assert headline and all(isinstance(v, int | float) for v in headline.values()), (
            f"{_where(key)}: headline() gives figures by name")
        assert any(math.isfinite(v) for v in headline.values())
    if isinstance(kind, SendsRuns):
        receivers = [k for k in KINDS.values() if isinstance(k, AcceptsRuns)]
        assert receivers, f"{key} sends runs, but no workbench accepts them"
        receiver = receivers[0]
        rows = kind.run_rows(result)
        parsed = ReadingsSheet(receiver.columns, rows).parse()
        assert not parsed.errors, f"{_where(key)}: run_rows gives rows {receiver.key} refuses"
    if isinstance(kind, SendsReference):
        receivers = [k for k in KINDS.values() if isinstance(k, AcceptsReference)
                     and k.accepted_reference == kind.reference_kind]
        assert receivers, f"{key} sends a {kind.reference_kind!r} reference, but none accepts it"
        reference = kind.sent_reference(result)
        assert reference.kind == kind.reference_kind and reference.values
        assert set(reference.values) == set(reference.expanded_uncertainty)
    if isinstance(kind, WritesCorrectionTable):
        what = kind.correction_table(result, kind.default_settings, str(tmp_path / "table.csv"))
        assert what and any(tmp_path.iterdir()), f"{_where(key)}: correction_table writes a file"
    if isinstance(kind, OverlaysRuns):
        figure = kind.overlay_figure(result)
        assert figure.by_role("corrected") is not None, (
            f"{_where(key)}: overlay_figure has a series of role 'corrected' to draw over")


@pytest.mark.slow
def test_certificate_of_the_sample(key):
    kind, result = _sample(key)
    if not isinstance(kind, IssuesCertificates):
        pytest.skip(f"{key} issues no certificates")
    path = SAMPLES / f"certificate_{key}.json"
    assert path.is_file(), (f"{key}: add the example certificate details as resources/samples/"
                            f"{path.name} (copy another workbench's; \"example\": true)")
    details = json.loads(path.read_text("utf-8"))
    assert details.get("example") is True, f"resources/samples/{path.name}: set \"example\": true"
    metadata = CertificateMetadata.from_dict(details)
    document = kind.certificate_document(result, metadata, kind.sample_file, kind.sample_settings)
    assert (document.kind_key, document.kind_title) == (key, kind.title), (
        f"models/{key}/report.py: build CertificateDocument with kind_key=KEY, kind_title=TITLE")
    assert document.results.rows and document.budget.points and document.method, (
        f"models/{key}/report.py: the certificate states results, an uncertainty budget and the method")
    assert document.method_reference == kind.method_reference
    assert math.isfinite(document.expanded_uncertainty)
    assert kind.certificate_doubt(result) == "", f"{key}: its own sample is doubted"
