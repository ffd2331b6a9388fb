"""Compile and cache every kernel family once, so that the first real command runs warm.

    python -m dmdvox.warm [--jobs 1|2]

numba compiles a kernel the first time it is called and keeps the machine code in the
``__pycache__`` beside its source; on a fresh install that first call makes the demo's
``simulate`` wait about a minute and ``report`` about a minute and a half. ``scripts/setup.sh``
runs this module after installing (again only when dmdvox's sources or the installed packages
changed), so the waiting happens there, once.

Each command runs as the CLI would run it (the first ones in this process, the rest in two
processes side by side, see :func:`split`; ``--jobs 1`` runs them all here) on the shipped
demo block (at its default voxel), the PrusaSlicer block and a small program with arcs and a
helix. A kernel is compiled once per argument signature, and some run only when the grid has inside tiles or
pores, or the program E words: the programs are chosen to reach them all. What runs: ``info``,
``simulate`` (with ``--out``: the .vdb and surface writers), ``compare`` without and with
``--out`` (sampled deviation statistics; maps), ``render``, ``collide`` with a fixture and the
plate, ``report`` with all of it, ``diff`` of the demo against a copy whose last line stops
short (with ``--out``: the diff map's kernels), and one ``study overlap`` case (its worker process
compiles and caches what the study's tasks call).
"""

from __future__ import annotations

import argparse
import contextlib
import fcntl
import functools
import io
import os
import subprocess
import sys
import tempfile
import time
import traceback
from pathlib import Path

# The samples ship inside the package (a wheel has no data/ folder); the repository's data/
# holds links to them.
DATA = Path(__file__).resolve().parent / "samples"
NOZZLE = "cone:tip=4,top=20,length=25"
# seed dialect: straight beads, a G2 and a G3 arc, a helix (swept as chords), a dwell, two layers
ARCS = """M64
G90 G21 G17
F750
G0 X0 Y0 Z5
G1 Z0
M65
G1 X10 Y0
G2 X15 Y5 I0 J5
G3 X20 Y10 I5 J0
G4 P100
G2 X20 Y10 Z1 I-2 J0 P2
G1 X0 Y10 Z1
M64
G0 Z10
M30
"""


def commands(work: Path) -> list[list[str]]:
    demo, cad, clamp = (str(DATA / n) for n in ("demo_block.gcode", "demo_block.stl", "demo_clamp.stl"))
    slicer, slicer_cad = str(DATA / "prusa_block_20.gcode"), str(DATA / "slicer_block.stl")
    arcs = work / "arcs.gcode"
    arcs.write_text(ARCS)
    arcs = str(arcs)
    tube, trunnion = str(DATA / "tube_trunnion.gcode"), str(DATA / "machines" / "trunnion-ac.toml")
    head_program = work / "head.gcode"
    head_program.write_text("G90\nG0 X0 Y0 Z10 B0 C0\nG1 B90 F600\n")
    head_program = str(head_program)
    short = work / "demo_short.gcode"
    lines = (DATA / "demo_block.gcode").read_text().splitlines()
    short.write_text("\n".join(lines[:-4] + ["G1 X18.7500 Y12.5000 Z5.2500"] + lines[-3:]) + "\n")
    # The demo at its default voxel: a coarse one has no inside tiles, whose kernels would then
    # compile on the user's first run. The slicer block (RepRap, E-driven beads, infill pores)
    # at a coarse voxel: its kernels do not depend on the voxel, and the default one is slow.
    coarse = ["--voxel", "0.375"]
    slicer_voxel = ["--voxel", "0.13"]
    return [
        ["info", demo, "--json"],
        ["info", arcs, "--json"],
        ["info", slicer, "--json"],
        ["simulate", demo, "--json"],
        ["simulate", arcs, *coarse, "--out", str(work / "simulate"), "--json"],
        ["simulate", slicer, *slicer_voxel, "--json"],
        ["compare", demo, cad, "--json"],
        ["compare", slicer, slicer_cad, *slicer_voxel, "--json"],
        ["compare", demo, cad, *coarse, "--out", str(work / "compare"), "--json"],
        ["render", demo, "--at", "0.5", "--size", "160x120", "--png", str(work / "half.png"), "--json"],
        ["collide", demo, "--nozzle", NOZZLE, "--fixture", clamp, "--plate", "0", "--json"],
        ["report", demo, "--cad", cad, "--nozzle", NOZZLE, "--fixture", clamp, "--plate", "0",
         "--out", str(work / "report"), "--json"],
        ["diff", demo, str(short), *coarse, "--out", str(work / "diff"), "--json"],
        ["study", "overlap", "--width", "2", "--height", "1", "--spacing", "1.5", "--layers", "2", "--voxel", "0.1",
         "--json"],
        # five-axis: a turning table (tool-centre-point control off: the tip path from the joints)
        # and a tilting head
        ["collide", tube, "--machine", trunnion, "--dialect", "seed", "--width", "2.5", "--height", "0.8",
         *coarse, "--nozzle", NOZZLE, "--json"],
        ["render", tube, "--machine", trunnion, "--dialect", "seed", "--width", "2.5", "--height", "0.8", "--at", "0.5",
         "--size", "160x120", "--png", str(work / "tube.png"), "--json"],
        ["info", head_program, "--machine", str(DATA / "machines" / "head-bc.toml"), "--json"],
    ]


def split(cmds: list[list[str]]) -> tuple[list[list[str]], list[list[str]], list[list[str]]]:
    """The warm-up's commands in three parts. The first, up to the first ``simulate``, compiles
    the G-code interpreter and the deposit kernels that every later command needs, so it runs
    alone; the other two run side by side in two processes, each part compiling mostly kernels of
    its own: the comparison and the diff in one, the rest in the other, ``report`` (which calls
    both parts' kernels) last."""
    k = next(i for i, argv in enumerate(cmds) if argv[0] == "simulate") + 1
    rest = cmds[k:]
    comparing = [argv for argv in rest if argv[0] in ("compare", "diff")]
    others = [argv for argv in rest if argv[0] not in ("compare", "diff", "report")]
    return cmds[:k], comparing, others + [argv for argv in rest if argv[0] == "report"]


def lock_numba_cache_io(lock_path: str) -> bool:
    """Make this process's reads and writes of numba's cache exclusive of every other process
    locking ``lock_path``. numba saves a new signature of a kernel as two files, the kernel's
    index and then the machine code, each atomically but not the pair: another process adding a
    signature of the same kernel meanwhile can take the same data file, and one reading between
    the two writes can load another signature's code. Compilation stays outside the lock. False
    when numba's cache no longer has these methods: then the warm-up runs in one process."""
    try:
        from numba.core.caching import IndexDataCacheFile

        originals = {name: getattr(IndexDataCacheFile, name) for name in ("save", "load")}
    except (ImportError, AttributeError):
        return False

    def locked(original):
        @functools.wraps(original)
        def method(self, *args, **kwargs):
            with open(lock_path, "a") as lock:
                fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
                return original(self, *args, **kwargs)

        return method

    for name, original in originals.items():
        setattr(IndexDataCacheFile, name, locked(original))
    return True


def _run(cmds: list[list[str]]) -> list[str]:
    """Run each command as the CLI would, one line of time each on stderr; the failed ones' labels."""
    from . import progress
    from .cli import main as cli_main

    failed = []
    for argv_ in cmds:
        t = time.perf_counter()
        err = io.StringIO()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            try:
                code = cli_main(argv_)
            except Exception:  # one broken command must not keep the others from compiling
                traceback.print_exc(file=err)
                code = 1
        label = " ".join(argv_[:2] if argv_[0] == "study" else argv_[:1])
        print(f"warm: {label:<15s} {time.perf_counter() - t:6.1f} s{'' if code == 0 else f'  FAILED ({code})'}",
              file=sys.stderr, flush=True)
        if code != 0:
            failed.append(label)
            print(progress.without_progress(err.getvalue()).rstrip(), file=sys.stderr, flush=True)
    return failed


def main(argv: list[str] | None = None) -> int:
    from . import progress

    parser = argparse.ArgumentParser(prog="python -m dmdvox.warm", description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, choices=(1, 2), default=2 if (os.cpu_count() or 1) > 1 else 1,
                        help="processes compiling side by side after the first part (default: 2 on 2 or more cores)")
    parser.add_argument("--others", metavar="LOCK", help=argparse.SUPPRESS)  # the second process of --jobs 2
    args = parser.parse_args(argv)

    with tempfile.TemporaryDirectory(prefix="dmdvox-warm-") as tmp:
        first, comparing, others = split(commands(Path(tmp)))
        if args.others:
            lock_numba_cache_io(args.others)
            return 1 if _run(others) else 0
        started = time.perf_counter()
        cold = progress.cold_kernels(sorted({k for names in progress.COMMAND_KERNELS.values() for k in names}))
        print(f"warm: {len(cold)} kernel famil{'y' if len(cold) == 1 else 'ies'} to compile "
              f"({', '.join(n.split(':')[1] for n in cold) or 'none'}); the other kernels are checked by running",
              file=sys.stderr, flush=True)
        lock = str(Path(tmp) / "numba-cache.lock")
        if args.jobs == 1 or not lock_numba_cache_io(lock):
            failed = _run(first + comparing + others)
        else:
            failed = _run(first)
            child = subprocess.Popen([sys.executable, "-m", "dmdvox.warm", "--others", lock])
            failed += _run(comparing)
            if child.wait() != 0:
                failed.append("the second process (above)")
    print(f"warm: done in {time.perf_counter() - started:.0f} s"
          f"{'; failed: ' + ', '.join(failed) if failed else ''}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
