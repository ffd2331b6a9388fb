"""A `simulate --out` run's memory estimate against its peak RSS (docs/PERFORMANCE.md).

    .venv/bin/python scripts/bench_run_memory.py data/prusa_block_20.gcode [simulate options]

The run goes in a fresh process that first imports what the run uses (VTK among it) and runs the
demo block once at 0.25 mm (numba loading its kernels); the peak RSS is then reset and the
figure is the run's peak above that baseline, as in tests/test_memory_estimate.py, which holds
the ratio within 0.7-2x on five parts. The deposit cache is off.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def main(argv: list[str]) -> int:
    test = (REPO / "tests" / "test_memory_estimate.py").read_text()
    child = re.search(r'RUN_CHILD = r"""(.*?)"""', test, re.S).group(1)
    proc = subprocess.run([sys.executable, "-c", child, str(REPO / "data" / "demo_block.gcode"), *argv],
                          capture_output=True, text=True, cwd=REPO, env={**os.environ, "DMDVOX_CACHE": "off"})
    if proc.returncode != 0:
        print(proc.stderr, file=sys.stderr)
        return proc.returncode
    run = json.loads(proc.stdout)
    print(f"estimate {run['estimate'] / 2**20:,.0f} MiB, peak above the baseline {run['measured'] / 2**20:,.0f} MiB "
          f"(ratio {run['estimate'] / run['measured']:.2f}); grid {run['grid'] / 2**20:,.1f} MiB, "
          f"{run['active']:,d} active voxels")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
