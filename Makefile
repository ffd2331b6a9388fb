# Two entry points for a fresh clone on Debian/Ubuntu: `make demo` and `make test`.
# Both install everything first (scripts/setup.sh is idempotent and fast when done).
PY := .venv/bin/python
OUT ?= out/demo

.PHONY: setup demo test bench samples
setup:
	bash scripts/setup.sh

demo: setup
	.venv/bin/dmdvox info data/demo_block.gcode

test: setup
	$(PY) -m pytest -q

bench: setup
	$(PY) scripts/bench_gcode.py

samples: setup
	$(PY) scripts/make_demo_part.py
	bash scripts/make_slicer_sample.sh
