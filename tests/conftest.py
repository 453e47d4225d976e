"""Test set-up: Qt runs offscreen; set before any Qt import."""

import os
import sys

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
# The commands and the window follow the system's language: the suite runs in English
# whatever the machine's locale (a test that wants Chinese asks for it).
for _name in ("LANGUAGE", "LC_ALL", "LC_MESSAGES"):
    os.environ.pop(_name, None)
os.environ["LANG"] = "C.UTF-8"
import atexit  # noqa: E402
import shutil  # noqa: E402
import tempfile  # noqa: E402
from pathlib import Path  # noqa: E402

# The app keeps files outside the project: its settings (~/.config/AngleBench), its register
# and autosaves (~/.local/share/AngleBench). The suite, and every program it starts, gets a
# home of its own: the user's own files are never read or written by a test (#31).
# (a pytest-xdist worker inherits the HOME set below: the user's own is passed on)
USER_HOME = Path(os.environ.setdefault("ANGLEBENCH_TESTS_USER_HOME", str(Path.home())))
_USER_FILES = [USER_HOME / ".config" / "AngleBench", USER_HOME / ".local" / "share" / "AngleBench"]
TEST_HOME = Path(tempfile.mkdtemp(prefix="anglebench-tests-home-"))
atexit.register(shutil.rmtree, TEST_HOME, True)
os.environ["HOME"] = str(TEST_HOME)
for _name, _folder in (("XDG_CONFIG_HOME", ".config"), ("XDG_DATA_HOME", ".local/share"),
                       ("XDG_CACHE_HOME", ".cache"), ("XDG_STATE_HOME", ".local/state")):
    os.environ[_name] = str(TEST_HOME / _folder)
os.environ.pop("ANGLEBENCH_DATA_DIR", None)
os.environ.pop("ANGLEBENCH_REGISTER", None)


def _user_files_state() -> dict[str, tuple]:
    """Every file under the user's AngleBench folders with its size and time."""
    state = {}
    for folder in _USER_FILES:
        if folder.exists():
            for path in [folder, *folder.rglob("*")]:
                info = path.stat()
                state[str(path)] = (info.st_size, info.st_mtime_ns)
    return state


USER_FILES_BEFORE = _user_files_state()

from app.process_setup import tune_process  # noqa: E402

# the process as the app runs it (one BLAS thread: set before numpy is first imported)
assert tune_process(), "numpy was imported before tests/conftest.py"

import pytest  # noqa: E402

SAMPLES = Path(__file__).resolve().parent.parent / "resources" / "samples"


@pytest.fixture
def samples_dir() -> Path:
    return SAMPLES


@pytest.fixture(autouse=True)
def _register_in_tmp(tmp_path, monkeypatch):
    """Every test issues into a register of its own (never the user's)."""
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))


@pytest.fixture
def register(tmp_path, monkeypatch) -> Path:
    """An empty register made in a folder of its own (``reg/register.sqlite``), the one the
    commands use: for tests of what lands beside it or what is done to its file."""
    from models.register.store import Register

    path = tmp_path / "reg" / "register.sqlite"
    path.parent.mkdir()
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(path))
    Register(f"sqlite:///{path}").close()
    return path


@pytest.fixture(scope="session")
def postgres_server():
    """A throw-away PostgreSQL cluster on a Unix socket for the session (see
    tests/postgres_cluster.py); skipped with the reason when none can be started, and a
    failure instead where ANGLEBENCH_REQUIRE_POSTGRES=1 (CI)."""
    from tests.postgres_cluster import PostgresUnavailable, start_cluster

    try:
        server = start_cluster()
    except PostgresUnavailable as exc:
        if os.environ.get("ANGLEBENCH_REQUIRE_POSTGRES") == "1":
            pytest.fail(f"PostgreSQL is required here and could not be started: {exc}")
        pytest.skip(f"no PostgreSQL server could be started: {exc}")
    yield server
    server.stop()


@pytest.fixture(params=["sqlite", "postgresql"])
def register_url(request, tmp_path):
    """A fresh, empty register on each back end."""
    if request.param == "sqlite":
        yield f"sqlite:///{tmp_path / 'register.sqlite'}"
        return
    server = request.getfixturevalue("postgres_server")
    url = server.new_database()
    yield url
    server.drop_database(url)


@pytest.fixture(scope="session", autouse=True)
def _no_automatic_garbage_collection():
    """Python's cyclic collector runs in whichever thread allocates: a Qt object of an earlier
    test, collected in a capture simulator's thread, deadlocked a CI worker (~QObject waiting
    for the interpreter, the GUI thread for Qt's lock; no timeout could fire). Automatic
    collection is off for the whole session; the main thread collects on the collector's own
    schedule (widgets.gui_garbage_collector) at the end of every test, and during a Qt test
    on the window's timer (:func:`_garbage_collected_in_the_gui_thread`)."""
    import gc

    from widgets.gui_garbage_collector import GuiThreadGarbageCollector

    was = gc.isenabled()
    gc.disable()
    schedule = GuiThreadGarbageCollector(None)  # its check() only, run by hand
    yield schedule
    gc.collect()
    if was:
        gc.enable()


@pytest.fixture(autouse=True)
def _garbage_collected_in_the_gui_thread(request, _no_automatic_garbage_collection):
    """Every test ends with the collector's check in the main thread; a Qt test also runs
    the window's timer while it lasts, as the window does."""
    collector = None
    if {"qtbot", "qapp", "window"} & set(request.fixturenames):
        from PySide6.QtWidgets import QApplication

        from widgets.gui_garbage_collector import GuiThreadGarbageCollector

        app = QApplication.instance() or QApplication([])
        collector = GuiThreadGarbageCollector(app).start()
    try:
        yield
    finally:
        if collector is not None:
            collector.stop(full=False)
            collector.deleteLater()
        _no_automatic_garbage_collection.check()


@pytest.fixture(autouse=True)
def _no_modal_mapping_dialog(monkeypatch, tmp_path):
    """A file whose headers are not recognised would ask the user with a modal dialog: in a
    test it is cancelled unless the test answers it, and remembered mappings go to a
    settings file of the test's own."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QDialog

    from widgets.column_mapping_dialog import ColumnMappingDialog

    QSettings.setDefaultFormat(QSettings.Format.IniFormat)
    QSettings.setPath(QSettings.Format.IniFormat, QSettings.Scope.UserScope, str(tmp_path))
    monkeypatch.setattr(ColumnMappingDialog, "exec", lambda _d: QDialog.DialogCode.Rejected)


def answered_window(folder: Path):
    """The main window with settings and autosaves in ``folder``; what it would tell or ask
    the user is recorded (``told``) or answered (discard unsaved work)."""
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QMessageBox

    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    w = MainWindow(settings=QSettings(str(folder / "settings.ini"), QSettings.Format.IniFormat),
                   recovery=RecoveryStore(folder / "recovery"))
    w.told = []
    w.tell = lambda title, text: w.told.append(text)
    w.ask = lambda *a: QMessageBox.StandardButton.Discard
    return w


def delete_window(w) -> None:
    """``w`` deleted, not only closed: a closed window's application-wide shortcuts
    (Ctrl+PgDn) would otherwise still compete with the next test's window."""
    from PySide6.QtCore import QCoreApplication, QEvent

    w.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def window_of_a_module(folder: Path):
    """A generator for a module-scoped fixture: :func:`answered_window` in ``folder``, yielded
    once, then stopped, closed and deleted (the windows several cases of one module share)."""
    made = answered_window(folder)
    yield made
    made.projects.autosave_timer.stop()
    made.close()
    delete_window(made)


@pytest.fixture
def window(qtbot, tmp_path):
    """:func:`answered_window` of the test's own folder."""
    w = answered_window(tmp_path)
    qtbot.addWidget(w)
    yield w
    delete_window(w)


#: the number of Monte Carlo trials of the suite's validation runs (``anglebench validate
#: --trials 100`` in tests/app/test_validation.py and test_command_line_language.py, the
#: contract's check): one number, so one computation serves them all
VALIDATION_TRIALS = 100


def _shared_folder(tmp_path_factory) -> Path:
    """The folder of the run that pytest-xdist's workers share (the parent of each worker's
    own), or the run's own folder without workers."""
    base = tmp_path_factory.getbasetemp()
    return base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base


def once_a_run(tmp_path_factory, name: str, compute):
    """``compute(folder)``'s value, computed once a run: the first worker to ask computes it
    under a file lock (its files in ``folder``, in the folder the workers share) and pickles
    it, the others wait and read it."""
    import fcntl
    import pickle

    shared = _shared_folder(tmp_path_factory)
    stored = shared / f"{name}.pickle"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file is closed
        if not stored.exists():
            folder = shared / name
            folder.mkdir(exist_ok=True)
            stored.write_bytes(pickle.dumps(compute(folder)))
        return pickle.loads(stored.read_bytes())


@pytest.fixture(scope="session")
def validation_cases(tmp_path_factory):
    """``validation_cases(trials)``: every reference case of ``anglebench validate``
    (models.validation.run.run_validation), computed once a session for each number of trials
    (~25 s of CPU: Monte Carlo, the positioning's figure coverage, the half-range study; the
    cases are seeded, the same whatever the language of the report). pytest-xdist's workers
    share one folder of the run: the first to ask computes the cases under a file lock and
    pickles them, the others wait and read them (:func:`once_a_run`)."""
    from models.validation.run import run_validation

    def cases(trials: int) -> list:
        return once_a_run(tmp_path_factory, f"validation-cases-{trials}",
                          lambda _folder: run_validation(trials))

    return cases


@pytest.fixture(scope="session")
def issued_samples(tmp_path_factory):
    """Every sample of tests/app/test_dcc_out.py's ``CASES`` issued once a run with its PDF and
    DCC into one register, and analysed again for its JSON (``anglebench analyze --json``):
    ``{case: (exit code, what the issue said, PDF, DCC, the JSON call's output, JSON)}``.
    The DCC tests (test_dcc_out, test_standard_dcc_u, test_dcc_semantics) read these files and
    never change them: each printed the same certificates and DCCs for itself, in each
    worker (4–6 s of CPU each time). Computed once for all the workers (:func:`once_a_run`)."""

    def issue_every_sample(out: Path) -> dict:
        import contextlib
        import io
        import json

        from app.main import main
        from tests.app.test_dcc_out import CASES, _issue

        class Capture:  # _issue's output is read from the buffers below
            def readouterr(self):
                return type("C", (), {"out": "", "err": ""})()

        results = {}
        mp = pytest.MonkeyPatch()
        mp.setenv("ANGLEBENCH_REGISTER", str(out / "register.sqlite"))
        try:
            for case in CASES:
                said, printed, told = io.StringIO(), io.StringIO(), io.StringIO()
                with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
                    code, _, pdf, xml = _issue(case, out, Capture(), SAMPLES)
                kind, readings, meta, options = CASES[case]
                with contextlib.redirect_stdout(printed), contextlib.redirect_stderr(told):
                    analysed = main(["analyze", kind, str(SAMPLES / readings), "--json",
                                     "--metadata", str(SAMPLES / meta), *options])
                assert analysed == 0, printed.getvalue() + told.getvalue()
                text = printed.getvalue()
                results[case] = (code, said.getvalue(), pdf, xml, text + told.getvalue(),
                                 json.loads(text[text.index("{"):]))
        finally:
            mp.undo()
        return results

    return once_a_run(tmp_path_factory, "issued-samples", issue_every_sample)


def _sample_certificate(key: str, language: str, change: dict) -> tuple[bytes, list[str]]:
    """``key``'s bundled sample analysed, its certificate made with the example's details
    (resources/samples/certificate_<key>.json) updated by ``change`` and printed in
    ``language``: (the PDF, fpdf2's warnings of a character no font has)."""
    import json
    import logging
    from dataclasses import replace

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS[key]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    settings = kind.settings_with_defaults(None)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    details = json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8"))
    document = kind.certificate_document(
        result, CertificateMetadata.from_dict({**details, **change}), kind.sample_file, settings)
    warnings: list[str] = []
    handler = logging.Handler(logging.WARNING)
    handler.emit = lambda record: warnings.append(record.getMessage())
    logger = logging.getLogger("fpdf")
    level = logger.level
    logger.addHandler(handler)
    logger.setLevel(logging.WARNING)
    try:
        pdf = certificate_pdf_bytes(replace(document, metadata=replace(
            document.metadata, language=language)))
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)
    return pdf, [w for w in warnings if "missing" in w]


@pytest.fixture(scope="session")
def sample_certificates(tmp_path_factory):
    """``sample_certificates(key, language, change=None)``: (the PDF, fpdf2's warnings of a
    character no font has) of ``key``'s bundled sample certificate, the example's details
    updated by ``change``, printed in ``language`` (:func:`_sample_certificate`). Each is
    printed once a run for all the workers (:func:`once_a_run`): the Chinese certificate's
    tests (tests/app/writers/test_certificate_chinese.py), the bilingual one's and the
    manufacturer's term read the same sample certificates and never change them (a print
    is 1–3 s of CPU; the theodolite's was printed in four modules)."""
    import hashlib
    import json

    def printed(key: str, language: str, change: dict | None = None) -> tuple[bytes, list[str]]:
        change = dict(change or {})
        tag = hashlib.sha256(json.dumps(change, sort_keys=True).encode()).hexdigest()[:12]
        name = f"sample-certificate-{key}-{language.replace('+', '_')}-{tag}"
        return once_a_run(tmp_path_factory, name,
                          lambda _folder: _sample_certificate(key, language, change))

    return printed


@pytest.fixture(scope="session")
def validation_software_cases(tmp_path_factory):
    """``app.validation_report.software_cases()`` (a Chinese certificate printed and read
    back, a register, two files imported: ~2 s of CPU), computed once a run for all the
    workers (:func:`once_a_run`); the cases hold no path or time of their own."""
    from app.validation_report import software_cases

    return once_a_run(tmp_path_factory, "validation-software-cases",
                      lambda _folder: software_cases())


@pytest.fixture
def validation_once(monkeypatch, validation_cases, validation_software_cases):
    """``anglebench validate`` takes its reference cases from ``validation_cases`` and its
    software cases from ``validation_software_cases``: the English and the Chinese report
    of the suite, and the writes of it tests/app/test_results_never_lost.py checks, share
    one run of each."""
    import app.validation_report as validation_report

    monkeypatch.setattr(validation_report, "run_validation", validation_cases)
    monkeypatch.setattr(validation_report, "software_cases",
                        lambda: list(validation_software_cases))


# -- the fast loop (#44) ----------------------------------------------------------------------
#: tests of more than ~0.25 s in areas other engineers are changing now (the register, capture,
#: fringe, the #39 conformity studies): marked slow here rather than in their files, which are
#: being edited; move the mark into the file (``@pytest.mark.slow``) when touching it next
SLOW_ELSEWHERE = frozenset({
    "tests/app/capture/test_capture_cli.py::test_a_dead_instrument_exits_2_with_one_line_naming_the_port",
    "tests/app/capture/test_capture_pacing.py::test_a_polled_autocollimator_through_the_stability_gate",
    "tests/app/capture/test_capture_pacing.py::test_a_slow_reply_waits_its_timeout_and_a_lost_one_is_a_fault_of_its_own",
    "tests/app/capture/test_capture_pacing.py::test_a_slow_theodolite_gets_one_request_at_a_time_and_every_reading_is_fresh",
    "tests/app/capture/test_capture_pacing.py::test_an_autocollimator_that_answers_only_single_shots_is_polled",
    "tests/app/capture/test_capture_pacing.py::test_geocom_replies_with_and_without_a_transaction_id",
    "tests/models/capture/test_capture_edits.py::test_the_certificate_says_which_rows_were_edited",
    "tests/models/capture/test_take_cells.py::test_a_take_never_lands_on_a_filled_cell",
    "tests/models/fringe/test_fringe_harmonic_basis.py::test_rows_are_the_sines_and_cosines_of_each_order",
    "tests/models/fringe/test_fringe_long_records.py::test_a_superseded_analysis_stops_early_and_only_on_its_thread",
    "tests/models/positioning/test_figure_intervals.py::test_same_readings_same_intervals_and_r_bias_handled",
    "tests/models/register/test_identifiers.py::test_an_invisible_character_anywhere_is_refused_by_its_code_point",
    "tests/models/register/test_identifiers.py::test_dashes_and_spaces_print_alike_and_normalise_alike",
    "tests/models/register/test_identifiers.py::test_normalising_is_idempotent_and_leaves_nothing_invisible",
    "tests/models/register/test_register.py::test_an_amendment_references_the_original_which_stays_unchanged",
    "tests/models/register/test_register_tampering.py::test_a_calibration_interval_changed_is_found",
    "tests/models/register/test_register_tampering.py::test_a_certificate_carries_the_head_before_it",
    "tests/models/register/test_register_tampering.py::test_a_deleted_record_whose_number_is_issued_again_is_found",
    "tests/models/register/test_register_tampering.py::test_a_record_forged_after_the_last_genuine_one_is_found_with_the_labs_key",
    "tests/models/register/test_register_tampering.py::test_a_truncated_tail_is_found",
    "tests/models/register/test_register_tampering.py::test_a_whole_chain_recomputed_is_found_only_by_a_head_noted_outside",
    "tests/models/register/test_register_tampering.py::test_a_withdrawn_certificate_is_a_chained_record_and_set_back_is_found",
    "tests/models/register/test_register_tampering.py::test_an_interval_entry_changed_is_found",
    "tests/models/register/test_register_tampering.py::test_authorised_signatories_and_a_distinct_approver",
    "tests/models/register/test_register_tampering.py::test_the_issuing_user_and_approver_are_chained",
    "tests/models/register/test_register_tampering.py::test_the_last_record_edited_and_rehashed_is_found",
    "tests/models/register/test_register_tampering.py::test_verify_of_a_pdf_copied_into_a_second_record_names_both",
    "tests/models/uncertainty/test_conformity_decision.py::test_u_has_at_most_two_significant_digits_and_the_value_its_decimal",
    "tests/models/uncertainty/test_half_range_coverage.py::test_a_flat_top_is_allowed_for",
})


@pytest.hookimpl(tryfirst=True)  # before ``-m "not slow"`` deselects
def pytest_collection_modifyitems(config, items):
    """The register's PostgreSQL cases (a cluster started, a database made for each) and the
    tests listed above are slow: ``make test`` runs them, ``make test-fast`` leaves them out."""
    for item in items:
        callspec = getattr(item, "callspec", None)
        postgresql = "postgres_server" in getattr(item, "fixturenames", ()) or (
            callspec is not None and callspec.params.get("register_url") == "postgresql")
        if postgresql or item.nodeid.split("[")[0] in SLOW_ELSEWHERE:
            item.add_marker(pytest.mark.slow)


def pytest_sessionfinish(session, exitstatus):
    """The user's own AngleBench files are as they were before the suite ran."""
    if _user_files_state() != USER_FILES_BEFORE:
        session.exitstatus = 1
        sys.stderr.write(f"\nthe tests changed the user's own files under {_USER_FILES}\n")
