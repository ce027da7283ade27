# Two set-up commands (README): `make run` serves the API, the form and the manual; `make test`
# runs every check. Both create the virtual environment and install what they need on first use.
PYTHON ?= python3
VENV ?= .venv
HOST ?= 127.0.0.1
PORT ?= 8000
BIN := $(VENV)/bin

.PHONY: run test test-fast check bench mutate install manual docs clean client

# Dependencies come pinned from the lock files (scripts/lock regenerates them from
# pyproject.toml); the project itself is installed on top without resolving again.
PIP := $(BIN)/python -m pip install --quiet --disable-pip-version-check

# `make run` installs the runtime and the manual's builder (requirements-docs.lock: the
# runtime pins plus mkdocs); the container image takes the runtime alone (requirements.lock).
# The numba kernels (the striker's cycle, the blow) compiled into numba's cache at install time,
# as the container does at build time: the first `make run` then loads them at start-up instead
# of compiling them (about 15 s of CPU) before /readyz says ready.
KERNELS = $(BIN)/python -c "import engine, service.main as m; m.warm_up(engine.MODELS)"

$(VENV)/.installed-run: pyproject.toml requirements-docs.lock
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(PIP) -r requirements-docs.lock
	$(PIP) --no-deps -e .
	$(KERNELS)
	touch $@

$(VENV)/.installed-dev: pyproject.toml requirements-dev.lock
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(PIP) -r requirements-dev.lock
	$(PIP) --no-deps -e '.[dev]'
	$(KERNELS)
	touch $@ $(VENV)/.installed-run

$(VENV)/.installed-mutate: $(VENV)/.installed-dev
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[dev,mutate]'
	touch $@

$(VENV)/.installed-bench: $(VENV)/.installed-dev
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -e '.[dev,bench]'
	touch $@

install: $(VENV)/.installed-run

# The manual (served at /manual/): built into site/ (git-ignored) from docs/, mkdocs.yml, the
# last bench figures and the engine itself, whose worked examples run while it builds; rebuilt
# when any of them changes. `make run` builds it first; if it cannot, the service still starts
# and /manual/ says how to build it.
MANUAL_SOURCES := mkdocs.yml CHANGELOG.md $(wildcard bench/loadtest.json bench/pareto.png) \
	$(shell find docs scripts/manual engine tests/validation static/vendor/katex -type f \
	-not -path '*/__pycache__/*' 2>/dev/null)
site/index.html: $(VENV)/.installed-run $(MANUAL_SOURCES)
	rm -rf site.new
	$(BIN)/python -m mkdocs build --strict --quiet --site-dir site.new
	rm -rf site && mv site.new site

manual: site/index.html
docs: manual

run: $(VENV)/.installed-run
	$(MAKE) --no-print-directory manual || echo "the manual did not build (above); /manual/ says how to build it"
	$(BIN)/python -m service --host $(HOST) --port $(PORT)

test: $(VENV)/.installed-dev
	PY=$(BIN)/python scripts/check

check: test

# The inner loop: format, lint, types and every test but the browser, fresh-venv installs,
# servers and fuzzing (pytest markers, see pyproject.toml), every value test and doctest
# included; property tests at a few examples each (the "fast" hypothesis profile,
# tests/conftest.py); two processes (pytest-xdist). Under a minute on two idle cores.
# The fuzz module is not even collected: building its cases from the schema costs ~10 s.
# The tests that time the service's lanes against an idle run go last, in one process,
# so that the other worker's load does not count as theirs.
# CI runs `make test`: everything, in one process, at the full hypothesis budgets.
FAST := not slow and not browser and not install and not fuzz
# The lanes' timing tests under load are `slow` (tests/conftest.py: SLOW_ITEMS): they time
# the service against an idle run and cannot share the CPU with a second worker.
# PYTHONDONTWRITEBYTECODE is emptied for this loop alone: with it set, each of the three
# pytest processes compiles every module again and pytest rewrites every test module's
# asserts again (about 7 s of CPU per worker, every run); the .pyc files are git-ignored.
# The schemathesis plugin serves the fuzz module alone, which this loop does not collect.
# Work stealing keeps the two workers' shares even to the end (with --dist load, one worker
# ran about 10 % longer than the other).
test-fast: $(VENV)/.installed-dev
	PYTHONDONTWRITEBYTECODE= PY=$(BIN)/python scripts/check -q -m "$(FAST)" \
		--hypothesis-profile=fast -n 2 --dist worksteal -p no:schemathesis \
		--ignore=tests/service/test_fuzz.py

# Mutation testing of engine/physics and engine/procedures, each module against its own tests
# (scripts/mutate.py; survivors judged equivalent: scripts/mutate_equivalent.toml):
# a seeded sample within a time budget; prints the share killed and the survivors. Not in CI.
#   make mutate MODULES="engine/physics/springs.py engine/physics/threads.py" SAMPLE=80 SEED=1
MODULES ?=
SAMPLE ?= 100
SEED ?= 0
MINUTES ?= 50
mutate: $(VENV)/.installed-mutate
	$(BIN)/python scripts/mutate.py $(MODULES) --sample $(SAMPLE) --seed $(SEED) --minutes $(MINUTES)

# Speed against accuracy for every registered model: bench/results.json, bench/pareto.png, a table;
# then the load test on loopback (bench/loadtest.json): every service target beside its figure;
# then each error estimate against a reference over random designs (bench/accuracy_*.py):
# a table and docs/accuracy.md, failing when a claim labelled a bound was exceeded.
bench: $(VENV)/.installed-bench
	$(BIN)/python -m bench.run
	$(BIN)/python scripts/loadtest.py --seconds 4
	$(BIN)/python -m bench.accuracy
	$(BIN)/python -m bench.page

# The Python client in clients/python, regenerated from the service's OpenAPI document by the
# pinned openapi-python-client (clients/generate.py); commit the result. A test fails while
# it is stale (tests/service/test_python_client.py).
client: $(VENV)/.installed-dev
	$(BIN)/python -m clients.generate

clean:
	rm -rf $(VENV) .pytest_cache .mypy_cache .ruff_cache .hypothesis site
