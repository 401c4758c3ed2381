# hpgen developer tasks. `make test` is what CI runs (.ci/run).
PYTHON ?= python3
EXAMPLES := free_rigid_body heavy_top underwater_vehicle

.PHONY: install demo test test-fast generate bench clean

install:
	$(PYTHON) -m pip install --quiet -e '.[test]'

demo: install
	$(PYTHON) -m hpgen run examples/heavy_top.yaml --out heavy_top.npz

test: install
	$(PYTHON) -m pytest -q -ra

test-fast: install
	$(PYTHON) -m pytest -q -ra -m "not slow"

# regenerate the committed sources of the shipped examples (default options of each model)
generate: install
	$(PYTHON) -m hpgen.tools.generate_examples

clean:
	rm -rf build *.egg-info .pytest_cache generated/*/_kernels_*.so
