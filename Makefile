# Quick start: `make run` opens the app on the bundled samples, `make test` runs the suite.
# Both create .venv on first use and reinstall when pyproject.toml changes.
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed

.PHONY: run test test-fast bench lint pictures translations new-workbench docs clean

$(STAMP): pyproject.toml
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[test]'
	touch $(STAMP)

run: $(STAMP)
	$(VENV)/bin/anglebench --samples

# the whole suite, one worker per core (pytest-xdist); `make test-fast`: the tests not marked
# slow, also one worker per core (-n auto: its ~1200 tests take ~60 s of CPU in all, each
# worker's start-up and collection included, so two workers finish in ~30-35 s on an idle
# 2-core machine, #44); a test of more than ~0.25 s is marked slow (docs/developer-guide.md: Building and testing).
# PYTHONDONTWRITEBYTECODE is emptied for the run: pytest keeps the test modules it rewrote
# and Python the modules it compiled (__pycache__, ignored by git) instead of compiling every
# test module again in every worker and every program a test starts (~6 s of CPU a worker)
TEST_ENV := QT_QPA_PLATFORM=offscreen PYTHONDONTWRITEBYTECODE=
# --durations: the slowest tests named at the end of every run (a run that slows is read
# from CI's own log); a test that hangs is failed after 600 s with every thread's stack
# (pytest-timeout, pyproject.toml)
test: $(STAMP)
	$(TEST_ENV) $(PY) -m pytest -n auto --dist worksteal --durations=15

test-fast: $(STAMP)
	$(TEST_ENV) $(PY) -m pytest -n auto --dist worksteal -m "not slow"

$(VENV)/.bench-installed: pyproject.toml $(STAMP)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[test,bench]'
	touch $@

# the benchmarks (BENCHMARKS.md, docs/benchmarks.md's headlines) and the long forms of suite tests
# whose covering sets the suite runs (docs/developer-guide.md: Building and testing)
bench: $(STAMP) $(VENV)/.bench-installed
	QT_QPA_PLATFORM=offscreen $(PY) -m pytest -q -p no:cacheprovider tests/benchmarks -o addopts="" -s

# README and docs pictures: workbench screenshots and sample certificates (needs Debian's poppler-utils)
pictures: $(STAMP)
	$(PY) -m resources.samples.make_samples
	QT_QPA_PLATFORM=offscreen $(PY) -m app.readme_pictures

# Qt translations: texts gathered (lupdate), the .ts kept, the .qm compiled (lrelease)
translations: $(STAMP)
	QT_QPA_PLATFORM=offscreen $(PY) -m app.translations

# A new workbench's two folders, sample, manual pages and registry entry (app/new_workbench.py):
# make new-workbench NAME=tilt TITLE="Tilt table" TITLE_ZH="倾斜台"
new-workbench: $(STAMP)
	$(PY) -m app.new_workbench "$(NAME)" --title "$(TITLE)" --title-zh "$(TITLE_ZH)"

# the docs' generated tables (workbenches, settings, every command's --help) between their
# markers in README.md and docs/ (app/docs_tables.py; tests/app/test_docs_tables.py: stale),
# then the window's manual (F1), resources/manual/*.html, from docs/user-guide/ and
# docs/zh_CN/user-guide/ (app/manual_pages.py; tests/app/test_manual_pages.py: stale)
docs: $(STAMP)
	$(PY) -m app.docs_tables
	$(PY) -m app.manual_pages

# ruff; the import contracts (pyproject.toml [tool.importlinter]: layers, no Qt in models/,
# the workbenches independent); mypy on models/ (pyproject.toml [tool.mypy])
lint: $(STAMP)
	$(VENV)/bin/ruff check app models widgets tests resources
	$(VENV)/bin/lint-imports
	$(VENV)/bin/mypy

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
