# hpgen developer tasks. CI (.ci/run) runs `make wheel-test`, `make lint`, then `make test`.
# Installs use the exact versions of constraints.txt; pyproject.toml holds compatible ranges.
#
# Where hpgen is installed: the active virtual environment when there is one (VIRTUAL_ENV
# set), else the project's own .venv, created with BASE_PYTHON on first use; never into a
# system or user Python by surprise. `make test VENV=` installs into BASE_PYTHON's
# environment itself (a throwaway CI machine), `make test PYTHON=/path/to/python` into that
# interpreter's.
BASE_PYTHON ?= python3
VENV ?= $(if $(VIRTUAL_ENV),,.venv)
ifeq ($(strip $(VENV)),)
PYTHON ?= $(BASE_PYTHON)
else
PYTHON ?= $(VENV)/bin/python
endif
PIP_INSTALL = $(PYTHON) -m pip install --quiet -c constraints.txt
# the project venv is a prerequisite only when PYTHON is its interpreter
VENV_PYTHON = $(if $(filter $(VENV)/bin/python,$(PYTHON)),$(VENV)/bin/python)

.PHONY: install demo lint test test-fast test-lowest wheel-test generate docs clean

install: $(VENV_PYTHON)
	$(PIP_INSTALL) -e '.[test,scale,peers]'

ifneq ($(strip $(VENV)),)
$(VENV)/bin/python:
	$(BASE_PYTHON) -m venv $(VENV)
endif

# the heavy top's scene -> out/heavy_top.npz and its figures out/heavy_top-*.png (out/ is
# ignored by git; DEMO_OUT=dir to write elsewhere)
DEMO_OUT ?= out
demo: install
	mkdir -p $(DEMO_OUT)
	$(PYTHON) -m hpgen run examples/heavy_top.yaml --out $(DEMO_OUT)/heavy_top.npz

# ruff (rules and files: [tool.ruff] in pyproject.toml) and mypy ([tool.mypy]: hpgen/abi.py,
# hpgen/schemes.py, hpgen/runtime); the same checks as .pre-commit-config.yaml
lint: install
	$(PYTHON) -m ruff check .
	$(PYTHON) -m mypy

test: install
	$(PYTHON) -m pytest -q -ra

test-fast: install
	$(PYTHON) -m pytest -q -ra -m "not slow"

# the fast tests against the lowest versions pyproject.toml admits (constraints-lowest.txt),
# in a fresh venv (LOWEST_VENV); tests/unit only (the golden generated files of tests/regression
# are CasADi 3.8's output)
LOWEST_VENV ?= .venv-lowest
test-lowest:
	$(BASE_PYTHON) -m venv $(LOWEST_VENV)
	$(LOWEST_VENV)/bin/python -m pip install --quiet -c constraints-lowest.txt -e '.[test]'
	$(LOWEST_VENV)/bin/python -m pytest -q -ra -m "not slow" -p no:cacheprovider tests/unit

# build the wheel, install it in a fresh virtual environment (pinned versions) and compile
# and run a shipped example there, outside the checkout (the templates must be in the wheel)
wheel-test:
	PYTHON=$(BASE_PYTHON) sh .ci/wheel-test

# regenerate the golden modules committed in generated/ and compile the other shipped
# examples into the build cache (default options of each model; hpgen.tools.generate_examples)
generate: install
	$(PYTHON) -m hpgen.tools.generate_examples

# rewrite the generated parts of docs/api.md (signatures, error tree, CLI options, grid file)
# from the code; tests/unit/test_api_docs.py fails while the page is stale
docs: install
	$(PYTHON) -m hpgen.tools.api_docs

clean:
	rm -rf build dist *.egg-info .pytest_cache generated/*/_kernels_*
