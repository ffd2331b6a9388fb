"""Time a 50-point overlap study (10 spacings x 5 layer steps) on local processes.

    .venv/bin/python scripts/bench_study.py [--scheduler tcp://host:port]

Parabolic beads 2 x 1 mm, 3 layers, the study's default voxel (w/40 = 0.05 mm). The first run
in a fresh checkout also compiles numba kernels into the cache; the figure is the best of
``--repeat`` runs.
"""

from __future__ import annotations

import argparse
import time

from dmdvox.cli import _add_study_overlap as add_overlap_options
from dmdvox.cli import cmd_study_overlap as run_study_overlap

STUDY = "--profile parabola --width 2 --height 1 --spacing 0.8:2.6:0.2 --layer-step 0.6:1.0:0.1 --layers 3 --json"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", default=None)
    parser.add_argument("--repeat", type=int, default=2)
    bench = parser.parse_args()
    study = argparse.ArgumentParser()
    add_overlap_options(study)
    args = study.parse_args(STUDY.split() + (["--scheduler", bench.scheduler] if bench.scheduler else []))
    times = []
    for _ in range(bench.repeat):
        t = time.perf_counter()
        rows = run_study_overlap(args)["rows"]
        times.append(time.perf_counter() - t)
    where = bench.scheduler or "local processes"
    print(f"overlap study, {len(rows)} points on {where}: best {min(times):.1f} s "
          f"(runs: {', '.join(f'{t:.1f}' for t in times)} s)")


if __name__ == "__main__":
    main()
