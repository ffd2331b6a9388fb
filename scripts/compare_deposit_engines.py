"""This tree's deposit engine against another checkout's, bit for bit.

    python scripts/compare_deposit_engines.py REF [--scale K] [--only NAME ...]

REF is a checkout of another revision (``git worktree add --detach /tmp/engine_ref main``).
Every G-code in data/ and data/corpus with its default process plan, and synthetic parts for what
the corpus lacks (arcs of every profile, ramps and a climbing spiral, a tilted head, fat beads, a
deposit cut off halfway, a thin-walled box), is deposited three times, each run in its own process:
by REF's engine, by this tree's, and by this tree's with tiny chunks (windows of a few hundred
blocks and outputs of 256 kB: many chunks along x and z, each with its own halo). Every array of
the three grids must be equal. Voxels are ``--scale`` times the plans' defaults (coarse, to stay
fast). Prints one line per part and exits 1 if any differ.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
DATA = REPO / "data"
GRID_ARRAYS = ("block", "leaf_coord", "leaf_active", "leaf_inside", "sdf_offset", "sdf", "arr_offset", "arrival",
               "leaf_octant_arrival", "tile_arrival")

ARCS = """G90 G21
G0 X0 Y0 Z0
M65
G1 X10 F600
G3 X10 Y10 I0 J5
G2 X20 Y10 I5 J0
G3 X20 Y10 I3 J0
G1 X25 Y15
G2 X30 Y20 R5
G3 X30 Y20 I0 J-0.8
G2 X32 Y22 Z1.5 I1 J1
G3 X32 Y22 Z3.0 I-3 J0 P2
G1 X40 Y22 Z3.0
G3 X42 Y24 Z3.0 I0.6 J1.2
M64
"""
TILTED = """G90
G43.4
G0 X0 Y0 Z10 B45 C0
M65
G1 Y20 F600
G1 X5 Y25
M64
G0 X10 Y0 Z10 B90 C30
M65
G1 Y15 F600
G1 Z14
M64
"""
FAT = """G90 G21
G0 X0 Y0 Z0
M65
G1 X20 Y0 F600
G1 X30 Y12
G3 X30 Y30 I0 J9
G1 X5 Y30
G1 X5 Y10 Z2
M64
G0 X0 Y0 Z3
M65
G1 X25 Y3 Z3
M64
"""
FAT_ARC = "G90 G21\nG0 X0 Y0 Z0\nM65\nG3 X0 Y0 I2 J0 F600\nG1 X10\nG2 X14 Y4 I0 J4\nM64\n"


def ramp() -> str:
    """Long sloped segments crossing many blocks in z, and a spiral climbing 0.05 mm a row."""
    lines = ["G90 G21", "G0 X0 Y0 Z0", "M65", "G1 X40 Y5 Z20 F600", "G1 X40 Y30 Z20", "G1 X0 Y30 Z0.5",
             "G1 X-5 Y10 Z12", "M64", "G0 X50 Y0 Z0", "M65"]
    for k in range(40):
        lines.append(f"G1 X{60 + 10 * np.cos(k * 0.5):.4f} Y{10 * np.sin(k * 0.5):.4f} Z{0.05 * (k + 1):.4f}")
    return "\n".join(lines + ["M64"]) + "\n"


def box(side: float, layers: int, step: float = 0.8, width: float = 2.5) -> str:
    """Two concentric square tracks per layer."""
    lines = ["G90 G21", "F750"]
    for k in range(layers):
        for t in range(2):
            a, b = (t + 1) * 0.5 * width, side - (t + 1) * 0.5 * width
            lines += [f"G0 X{a:.4f} Y{a:.4f} Z{k * step:.4f}", "M65", f"G1 X{b:.4f} Y{a:.4f}",
                      f"G1 X{b:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{b:.4f}", f"G1 X{a:.4f} Y{a:.4f}", "M64"]
    return "\n".join(lines) + "\n"


def cases(tmp: Path) -> dict:
    """name -> () -> (process plan, voxel or None for the plan's default, until or None)."""
    from dmdvox.process.flow import FlowSettings
    from dmdvox.process.plan import ProcessSettings, plan_process
    from dmdvox.process.planner import MotionSettings
    from dmdvox.toolpath import read_gcode

    def fixed(tp, profile="rect", width=2.5, height=0.8, exponent=4.0):
        return plan_process(tp, ProcessSettings(profile=profile, width=width, height=height, exponent=exponent,
                                                model="fixed", motion=MotionSettings(accel_mm_s2=0.0)))

    def flow(tp, profile, width, rate):
        return plan_process(tp, ProcessSettings(profile=profile, width=width,
                                                flow=FlowSettings(powder_rate_g_min=rate, density_g_cm3=8.0)))

    def program(name, text, **kw):
        path = tmp / name
        path.write_text(text)
        return read_gcode(path, dialect="seed", **kw)

    out = {}
    for path in sorted(DATA.glob("*.gcode")) + sorted((DATA / "corpus").glob("*.gcode")):
        if path.stem == "tube_trunnion":
            out[path.stem] = (lambda: (fixed(read_gcode(DATA / "tube_trunnion.gcode", dialect="seed",
                                                        machine=DATA / "machines" / "trunnion-ac.toml")), None, None))
        else:
            out[path.stem] = lambda path=path: (plan_process(read_gcode(path), ProcessSettings()), None, None)
    demo = DATA / "demo_block.gcode"
    out["demo_ellipse"] = lambda: (fixed(read_gcode(demo), profile="ellipse", height=None), None, None)
    out["demo_flow"] = lambda: (flow(read_gcode(demo), "parabola", 2.5, 6.0), None, None)
    out["demo_until"] = lambda: (fixed(read_gcode(demo), height=None), None, 0.5)
    for profile in ("rect", "ellipse", "parabola", "cosine", "arc", "lame"):
        out[f"arcs_{profile}"] = (lambda profile=profile: (
            fixed(program("arcs.gcode", ARCS), profile=profile, width=2.0, height=0.9, exponent=3.0), 0.1, None))
    out["arcs_flow"] = lambda: (flow(program("arcs.gcode", ARCS), "parabola", 2.0, 6.0), 0.1, None)
    out["ramp"] = lambda: (fixed(program("ramp.gcode", ramp()), width=2.0), 0.1, None)
    out["tilted_head"] = lambda: (fixed(program("tilted.gcode", TILTED, machine=DATA / "machines" / "head-bc.toml"),
                                        width=2.0, height=1.0), 0.1, None)
    out["fat_rect"] = lambda: (fixed(program("fat.gcode", FAT), width=8.0, height=4.0), 0.1, None)
    out["fat_parabola"] = lambda: (fixed(program("fat.gcode", FAT), profile="parabola", width=8.0, height=4.0), 0.1,
                                   None)
    out["fat_arc_small"] = lambda: (fixed(program("fat_arc.gcode", FAT_ARC), profile="ellipse", width=8.0,
                                          height=4.0), 0.1, None)
    out["fat_flow"] = lambda: (flow(program("fat.gcode", FAT), "rect", 8.0, 60.0), 0.1, None)
    out["box50"] = lambda: (fixed(program("box.gcode", box(50.0, 25))), 0.1, None)
    return out


def deposit_cases(out_dir: Path, names: list[str], scale: float, tiny: bool) -> None:
    """Deposit ``names`` with the dmdvox on the path, saving each grid as OUT_DIR/NAME.npz."""
    from dmdvox.deposit import engine

    if tiny:
        engine.WINDOW_BYTES = 3 * engine.SWEPT_BLOCK_BYTES * 200
        engine.CHUNK_OUTPUT_BYTES = 256 << 10
    with tempfile.TemporaryDirectory() as tmp:
        table = cases(Path(tmp))
        for name in names:
            plan, voxel, until = table[name]()
            voxel = scale * plan.default_voxel() if voxel is None else voxel
            until = None if until is None else until * float(plan.toolpath.t_end.max())
            beads = plan.beads(voxel, until=until)
            t = time.process_time()
            grid, timings = engine.deposit_beads(beads, voxel)
            info = {"voxel": voxel, "primitives": len(beads), "leaves": int(grid.n_leaf), "tiles": int(grid.n_tile),
                    "chunks": int(timings.get("chunks", 1)), "cpu_s": round(time.process_time() - t, 2)}
            np.savez(out_dir / f"{name}.npz", origin=grid.origin, band=grid.band,
                     **{k: getattr(grid, k) for k in GRID_ARRAYS})
            print(json.dumps({name: info}), flush=True)


def run_child(tree: Path, out_dir: Path, names: list[str], scale: float, tiny: bool) -> dict:
    env = dict(os.environ, PYTHONPATH=str(tree))
    cmd = [sys.executable, str(Path(__file__).resolve()), "--child", str(out_dir), "--scale", str(scale),
           *(["--tiny"] if tiny else []), "--only", *names]
    proc = subprocess.run(cmd, env=env, cwd=tree, capture_output=True, text=True)
    if proc.returncode != 0:
        raise SystemExit(f"{tree}: deposit failed\n{proc.stderr}")
    infos = {}
    for line in proc.stdout.splitlines():
        infos.update(json.loads(line))
    return infos


def differing(a: Path, b: Path) -> list[str]:
    x, y = np.load(a), np.load(b)
    return [k for k in ("origin", "band", *GRID_ARRAYS) if x[k].shape != y[k].shape or not np.array_equal(x[k], y[k])]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("ref", type=Path, nargs="?", help="checkout of the reference revision")
    parser.add_argument("--scale", type=float, default=3.0, help="voxel over the plan's default (default 3)")
    parser.add_argument("--only", nargs="+", help="these parts only")
    parser.add_argument("--child", type=Path, help=argparse.SUPPRESS)
    parser.add_argument("--tiny", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child is not None:
        deposit_cases(args.child, args.only, args.scale, args.tiny)
        return 0
    if args.ref is None:
        parser.error("give the reference checkout")
    with tempfile.TemporaryDirectory() as tmp:
        names = args.only or list(cases(Path(tmp)))
    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        runs = {"ref": (args.ref.resolve(), False), "here": (REPO, False), "tiny": (REPO, True)}
        infos = {}
        for key, (tree, tiny) in runs.items():
            (Path(tmp) / key).mkdir()
            infos[key] = run_child(tree, Path(tmp) / key, names, args.scale, tiny)
        for name in names:
            diffs = {key: differing(Path(tmp) / "ref" / f"{name}.npz", Path(tmp) / key / f"{name}.npz")
                     for key in ("here", "tiny")}
            same = not diffs["here"] and not diffs["tiny"]
            bad += not same
            print(f"{name:28s} {'identical' if same else f'DIFFERENT {diffs}'}  ref {json.dumps(infos['ref'][name])}  "
                  f"here {infos['here'][name]['cpu_s']} s, tiny chunks {infos['tiny'][name]['chunks']}", flush=True)
    print(f"{len(names) - bad} of {len(names)} parts identical")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
