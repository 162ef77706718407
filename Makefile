# Quick start:  `make reports` (set up + regenerate reports/)   `make test` (set up + run the tests)
# `make test-fast`: the tests not marked slow (under 3 minutes; catches a sign error in any element, law or solver)
PYTHON ?= $(shell command -v python3.11 || command -v python3)
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed
PEERS  := $(VENV)/.peers
DOCS   := $(VENV)/.docs
# test processes (pytest-xdist; a test file stays in one process, so its module fixtures run once)
JOBS   ?= 2
# LLVM optimisation level of the kernels the tests compile (numba's NUMBA_OPT; its default, 3,
# for everything else): a cold `make test` spends about a third of its CPU compiling, and
# level 1 compiles a fifth faster with the same numbers bit for bit (no fast-math anywhere).
# Its kernels get a numba cache of their own (ancf/__init__.py), never one a report reads
TEST_OPT ?= 1

# uv (from PyPI) installs the versions pip would, resolving, downloading and writing byte code
# in parallel: a fresh set-up 50 s -> 28 s; where uv cannot run, pip installs
install = $(PY) -m uv pip install --quiet --python $(PY) --compile-bytecode $(1) \
	|| $(PY) -m pip install --quiet $(1)

.PHONY: setup reports check-reports test test-fast bench clean docs

setup: $(STAMP)

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet uv || echo "uv not installed: pip installs"
	$(call install,-e ".[test]")
	# an editable install leaves our modules without byte code; where PYTHONDONTWRITEBYTECODE
	# is set, every process would compile them again (26 ms of a 330 ms `ancf run`)
	$(PY) -m compileall -q ancf analytic benchmarks
	touch $(STAMP)

# the reports and benchmarks set Exudyn beside us (the `peers` extra): every clone's reports hold the same rows
$(PEERS): $(STAMP)
	$(call install,-e ".[peers]")
	touch $(PEERS)

reports: $(PEERS)
	$(PY) -m ancf.reports

# regenerate into a temporary folder and compare every table with reports/ within each
# column's tolerance (docs/reproduce.md); exit 1 and a line per difference beyond it
check-reports: $(PEERS)
	$(PY) -m ancf.reports.check

test: $(STAMP)
	NUMBA_OPT=$(TEST_OPT) $(PY) -m pytest -n $(JOBS) --dist loadfile

test-fast: $(STAMP)
	NUMBA_OPT=$(TEST_OPT) $(PY) -m pytest -n $(JOBS) --dist loadfile -m "not slow"

bench: $(PEERS)
	OPENBLAS_NUM_THREADS=1 $(PY) -m pytest benchmarks --benchmark-enable --benchmark-only --benchmark-json=reports/benchmarks/benchmark.json
	$(PY) -m benchmarks.summarize
	OPENBLAS_NUM_THREADS=1 $(PY) -m benchmarks.core_profile
	$(PY) -m benchmarks.peers
	$(PY) -m benchmarks.peers_belt
	$(PY) -m benchmarks.peers_thread
	$(PY) -m benchmarks.peers_ale
	$(PY) -m benchmarks.peers_3d --repeats 5

# the documentation site (mkdocs.yml) into site/; --strict: a warning (a broken link, a missing
# page or anchor, a docstring that does not render) fails the build
$(DOCS): $(STAMP)
	$(call install,-e ".[docs]")
	touch $(DOCS)

docs: $(DOCS)
	NO_MKDOCS_2_WARNING=1 $(PY) -m mkdocs build --strict --site-dir site

clean:
	rm -rf $(VENV) .pytest_cache .benchmarks "$${XDG_CACHE_HOME:-$$HOME/.cache}/ancf-bench"
