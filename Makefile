# Two entry points for a fresh clone on Debian/Ubuntu: `make demo` and `make test`.
# Both install everything first (scripts/setup.sh is idempotent and fast when done).
PY := .venv/bin/python
OUT ?= out/demo

.PHONY: setup demo test test-suite test-wheel bench samples
setup:
	bash scripts/setup.sh

demo: setup
	.venv/bin/dmdvox demo --out $(OUT)

# The tests on every core (pytest-xdist; TEST_WORKERS=0 runs them in this one process), then the
# wheel in a fresh venv outside the repository (scripts/test_wheel.sh). setup compiled numba's
# kernels first, so the workers load them from the cache rather than each compiling them at once.
TEST_WORKERS ?= auto
test: test-suite
	bash scripts/test_wheel.sh

test-suite: setup
	$(PY) -m pytest -q -n $(TEST_WORKERS) --dist worksteal

test-wheel: setup
	bash scripts/test_wheel.sh

bench: setup
	$(PY) scripts/bench_gcode.py
	$(PY) scripts/bench_deposit.py
	$(PY) scripts/bench_deposit.py --size 100,100 --layers 63 --repeat 1
	$(PY) scripts/bench_compare.py
	$(PY) scripts/bench_collide.py

samples: setup
	$(PY) scripts/make_demo_part.py
	bash scripts/make_slicer_sample.sh
	bash scripts/make_corpus.sh
