# hpgen developer tasks. CI (.ci/run) runs `make wheel-test`, then `make test`.
# Installs use the exact versions of constraints.txt; pyproject.toml holds compatible ranges.
PYTHON ?= python3
PIP_INSTALL = $(PYTHON) -m pip install --quiet -c constraints.txt

.PHONY: install demo test test-fast test-lowest wheel-test generate clean

install:
	$(PIP_INSTALL) -e '.[test,scale,peers]'

# the heavy top's scene -> out/heavy_top.npz and its figures out/heavy_top-*.png (out/ is
# ignored by git; DEMO_OUT=dir to write elsewhere)
DEMO_OUT ?= out
demo: install
	mkdir -p $(DEMO_OUT)
	$(PYTHON) -m hpgen run examples/heavy_top.yaml --out $(DEMO_OUT)/heavy_top.npz

test: install
	$(PYTHON) -m pytest -q -ra

test-fast: install
	$(PYTHON) -m pytest -q -ra -m "not slow"

# the fast tests against the lowest versions pyproject.toml admits (constraints-lowest.txt),
# in a fresh venv (LOWEST_VENV); tests/unit only (the golden generated files of tests/regression
# are CasADi 3.8's output)
LOWEST_VENV ?= .venv-lowest
test-lowest:
	$(PYTHON) -m venv $(LOWEST_VENV)
	$(LOWEST_VENV)/bin/python -m pip install --quiet -c constraints-lowest.txt -e '.[test]'
	$(LOWEST_VENV)/bin/python -m pytest -q -ra -m "not slow" -p no:cacheprovider tests/unit

# build the wheel, install it in a fresh virtual environment (pinned versions) and compile
# and run a shipped example there, outside the checkout (the templates must be in the wheel)
wheel-test:
	PYTHON=$(PYTHON) sh .ci/wheel-test

# regenerate the committed sources of the shipped examples (default options of each model)
generate: install
	$(PYTHON) -m hpgen.tools.generate_examples

clean:
	rm -rf build dist *.egg-info .pytest_cache generated/*/_kernels_*
