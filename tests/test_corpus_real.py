"""The real-program corpus (data/corpus/real, docs/CORPUS.md "Real programs"): G-code nobody here
wrote, from public repositories, shipped in data/corpus/real with each source repository's licence
text (LICENSES/, README.md tables them); MANIFEST.toml says where each file comes from, its
licence, its checksum and what is true about it.

CI has no network, so the programs are in the repository and the test reads them there; the
environment variable DMDVOX_REAL_CORPUS names another folder to read instead (a fresh copy made by
scripts/get_real_corpus.sh, say). Nothing here skips: a listed file that the folder lacks, or
holds with another sha256, fails the tests that read it.

Four layers of checks:

* the manifest is complete: every entry says where the file is (repository, commit, path), its
  licence (an open one, whose text is in LICENSES/), its sha256 and size, its category and runs;
  the corpus is small;
* the folder holds the corpus and nothing else: every file in it is listed, every listed file in
  it has its sha256;
* the truths are the files' own: an independent reference reader (tests/corpus_reference.py,
  with each file's deposition rule spelt out in the manifest) reproduces every deposit length,
  layer count and duration bound, and the slicers' own comments give the stated layer counts
  and time estimates;
* dmdvox reads each file right or loudly: for every run a user would type (`[[file.run]]`),
  `dmdvox info --json` either gets the checked truths right (deposit length to 0.1 %, layer count
  exactly, duration at least the program's own lower bound, and within the stated tolerance of
  the slicer's estimate), or says the trap (`loud`: then the truths that trap decides, `excuses`,
  may be off), or refuses with exit 2 where that is allowed; never exit 1, never a silently wrong
  number.
"""

from __future__ import annotations

import contextlib
import gzip
import hashlib
import io
import json
import math
import os
import re
import tomllib
from pathlib import Path

import pytest

from dmdvox.cli import main

from . import corpus_reference as ref
from .conftest import DATA

REAL = DATA / "corpus" / "real"  # the manifest's folder, and the programs' unless the variable names another
MANIFEST = tomllib.loads((REAL / "MANIFEST.toml").read_text())
FILES = {entry["name"]: entry for entry in MANIFEST["file"]}
RUNS = [(name, i) for name, entry in FILES.items() for i in range(len(entry["run"]))]
CORPUS_VARIABLE = "DMDVOX_REAL_CORPUS"
CORPUS = Path(os.environ[CORPUS_VARIABLE]) if os.environ.get(CORPUS_VARIABLE) else REAL
NOT_PROGRAMS = {"MANIFEST.toml", "README.md", "LICENSES"}  # beside the programs in data/corpus/real
LICENSES = REAL / "LICENSES"
# What the first lines of each licence's text say (SPDX id -> words that must be there).
LICENCE_TITLES = {"MIT": ("MIT License",), "GPL-2.0-or-later": ("GNU GENERAL PUBLIC LICENSE", "Version 2,"),
                  "GPL-3.0-only": ("GNU GENERAL PUBLIC LICENSE", "Version 3,"),
                  "GPL-3.0-or-later": ("GNU GENERAL PUBLIC LICENSE", "Version 3,"),
                  "AGPL-3.0-only": ("GNU AFFERO GENERAL PUBLIC LICENSE", "Version 3,"),
                  "AGPL-3.0-or-later": ("GNU AFFERO GENERAL PUBLIC LICENSE", "Version 3,")}
# Open licences (SPDX ids); a file without one stays out of the corpus.
OPEN_LICENCES = {"MIT", "BSD-2-Clause", "BSD-3-Clause", "Apache-2.0", "GPL-2.0-only", "GPL-2.0-or-later",
                 "GPL-3.0-only", "GPL-3.0-or-later", "AGPL-3.0-only", "AGPL-3.0-or-later", "LGPL-2.1-or-later",
                 "LGPL-3.0-or-later", "MPL-2.0", "CC0-1.0", "CC-BY-4.0", "CC-BY-SA-4.0", "Unlicense"}
CATEGORIES = {"powder-ded", "laser", "wire-ded", "arc-torch", "five-axis", "slicer"}
DEPOSIT_TOLERANCE = 1e-3  # relative: arcs are exact, and 0.1 % is far below any trap's error
MAX_PLAIN_BYTES = 1_100_000  # a larger file is kept as .gcode.gz
MAX_TOTAL_BYTES = 12_000_000


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def unavailable(folder: Path, files: dict[str, dict]) -> dict[str, str]:
    """The listed files that folder does not hold as the manifest describes them: name -> why."""
    why = {}
    for name, entry in files.items():
        path = folder / name
        if not path.is_file():
            why[name] = "missing"
        elif _sha256(path) != entry["sha256"]:
            why[name] = "sha256 differs"
    return why


UNAVAILABLE = unavailable(CORPUS, FILES)


def _needs_file(name: str) -> Path:
    """The program's path in the corpus folder; a file the folder lacks, or holds changed, fails."""
    if name in UNAVAILABLE:
        pytest.fail(f"{CORPUS / name}: {UNAVAILABLE[name]} (MANIFEST.toml lists it with sha256 "
                    f"{FILES[name]['sha256']}; scripts/get_real_corpus.sh gets it again)")
    return CORPUS / name


def licence_text(repo: str) -> Path:
    """Where the corpus keeps the licence of a source repository: LICENSES/OWNER+NAME.txt."""
    return LICENSES / (repo.replace("/", "+") + ".txt")


def test_manifest_says_where_each_file_is_and_what_it_is():
    assert len(FILES) == len(MANIFEST["file"]), "a file is listed twice"
    for name, entry in FILES.items():
        assert re.fullmatch(r"[\w.-]+\.(gcode|ngc|nc)(\.gz)?", name), name
        assert re.fullmatch(r"[0-9a-f]{40}", entry["commit"]), name
        assert re.fullmatch(r"[\w.-]+/[\w.-]+", entry["repo"]), name
        assert entry["path"] and entry["licence_file"], name
        assert entry["licence"] in OPEN_LICENCES, name
        assert re.fullmatch(r"[0-9a-f]{64}", entry["sha256"]), name
        assert isinstance(entry["bytes"], int) and entry["bytes"] > 0, name
        assert entry["category"] in CATEGORIES, name
        assert entry["run"], f"{name}: no run"
        for run in entry["run"]:
            assert run["check"] and set(run["check"]) <= {"deposit_length_mm", "layers", "min_duration_s",
                                                           "duration_s"}, name
            assert all(key in entry for key in run["check"]), f"{name}: a run checks a truth the entry lacks"
            assert ("loud" in run) == ("excuses" in run) and set(run.get("excuses", [])) <= set(run["check"]), name
    assert len({entry["sha256"] for entry in FILES.values()}) == len(FILES), "two entries are the same file"
    # The floor: 24 programs from 10 sources, every family present.
    assert len(FILES) >= 24
    assert len({entry["repo"] for entry in FILES.values()}) >= 10
    assert {entry["category"] for entry in FILES.values()} == CATEGORIES


def test_every_source_licence_is_shipped_beside_its_files():
    # Redistributed unmodified as data, each under its repository's own licence, whose text is here.
    for name, entry in FILES.items():
        path = licence_text(entry["repo"])
        assert path.is_file(), f"{name}: no {path} ({entry['repo']} {entry['licence_file']})"
        head = path.read_text()[:400]
        assert all(word in head for word in LICENCE_TITLES[entry["licence"]]), \
            f"{path} does not read as {entry['licence']}"
    assert {p.name for p in LICENSES.iterdir()} == {licence_text(e["repo"]).name for e in FILES.values()}
    readme = (REAL / "README.md").read_text()
    for name, entry in FILES.items():  # the table says file -> source -> licence
        row = next((line for line in readme.splitlines() if line.startswith(f"| `{name}` |")), None)
        assert row and entry["repo"] in row and entry["licence"] in row, f"README.md has no row for {name}"


def test_corpus_is_small():
    # What a user fetches and the test reads: a large program is kept gzipped, the whole a few MB.
    assert sum(entry["bytes"] for entry in FILES.values()) < MAX_TOTAL_BYTES
    for name, entry in FILES.items():
        if not name.endswith(".gz"):
            assert entry["bytes"] < MAX_PLAIN_BYTES, f"{name}: keep it as .gz"


def test_folder_holds_listed_files_with_their_checksums():
    if os.environ.get(CORPUS_VARIABLE):
        assert CORPUS.is_dir(), f"{CORPUS_VARIABLE}={CORPUS} is not a folder"
    present = {p.name for p in CORPUS.iterdir()} - NOT_PROGRAMS
    assert present <= set(FILES), f"not in MANIFEST.toml: {sorted(present - set(FILES))}"
    for name in sorted(present):
        path = CORPUS / name
        assert (path.stat().st_size, _sha256(path)) == (FILES[name]["bytes"], FILES[name]["sha256"]), \
            f"{path} is not the file MANIFEST.toml lists (size, sha256)"


def test_unavailable_names_missing_and_changed_files(tmp_path):
    text = b"G1 X1 F600\n"
    entry = {"sha256": hashlib.sha256(text).hexdigest(), "bytes": len(text)}
    (tmp_path / "same.gcode").write_bytes(text)
    (tmp_path / "changed.gcode").write_bytes(text.replace(b"X1", b"X2"))
    files = {"same.gcode": entry, "changed.gcode": entry, "missing.gcode": entry}
    assert unavailable(tmp_path, files) == {"changed.gcode": "sha256 differs", "missing.gcode": "missing"}


def test_reference_reader_arcs_in_closed_form(tmp_path):
    # A quarter circle by I/J, the same by R, the long way round by negative R, a full circle
    # (end = start) and one helical turn; inch words scale by 25.4.
    cases = [("G1 X10 Y0\nG3 X0 Y10 I-10 J0", 10 + 10 * math.pi / 2),
             ("G1 X10 Y0\nG3 X0 Y10 R10", 10 + 10 * math.pi / 2),
             ("G1 X10 Y0\nG3 X0 Y10 R-10", 10 + 10 * 3 * math.pi / 2),
             ("G1 X10 Y0\nG2 X10 Y0 I-10 J0", 10 + 20 * math.pi),
             ("G1 X10 Y0\nG2 X10 Y0 Z5 I-10 J0", 10 + math.hypot(20 * math.pi, 5)),
             ("G20\nG1 X1 Y0\nG3 X0 Y1 I-1 J0", 25.4 * (1 + math.pi / 2))]
    spec = {"deposit": "codes", "deposit_on": ["M3"], "deposit_off": ["M5"], "flavour": "rs274"}
    for i, (text, length) in enumerate(cases):
        path = tmp_path / f"arc{i}.ngc"
        path.write_text("G90 G17 F600\nM3 S1\n" + text + "\nM5\n")
        assert ref.read(path, spec).deposit_length_mm == pytest.approx(length, rel=1e-12), text
    # Radii 50 and 25 from the centre: malformed (LinuxCNC's tolerance), and counted.
    path = tmp_path / "bad.ngc"
    path.write_text("G1 X0 Y0 F600\nG2 X15 Y20 I30 J40\n")
    assert ref.read(path, spec).malformed_arcs == 1


def test_reference_reader_rules(tmp_path):
    # The rules the manifest relies on, each on a minimal program: an M-code owns its words on a
    # RepRap machine; axis words beside an M-code move on an RS-274 one; a parenthesised parameter;
    # M67 ramps; E-only moves do not move; the per-layer E restart.
    path = tmp_path / "p.gcode"
    path.write_text("M201 X10000 Y10000\nG1 X10 E1 F600\nM73 P0 R32\nG1 E0.5\nG1 X20 E1.5\n")
    r = ref.read(path, {"deposit": "e", "flavour": "reprap"})
    assert (r.deposit_length_mm, r.moves) == (20.0, 2)
    path.write_text("G1 F600\nX5 M03 S100\nX6 M03 S0\nG0 X0\n")
    spec = {"deposit": "codes", "deposit_on": ["M3 S>0"], "deposit_off": ["M3 S=0"], "flavour": "rs274"}
    assert ref.read(path, spec).deposit_length_mm == 5.0
    path.write_text("G1 F600\nM201 (SDC 30)\nG1 X4\nM201 (SDC 0)\nG1 Y3\n")
    spec = {"deposit": "codes", "deposit_on": ["M201 SDC>0"], "deposit_off": ["M201 SDC=0"], "flavour": "rs274"}
    assert ref.read(path, spec).deposit_length_mm == 4.0
    path.write_text("G1 F600\nM68 E2 Q50\nG1 X3 M67 E2 Q0\nG1 X7\n")
    spec = {"deposit": "codes", "deposit_on": ["M68 E=2 Q>0", "M67 E=2 Q>0"],
            "deposit_off": ["M68 E=2 Q=0", "M67 E=2 Q=0"], "ramp_codes": ["M67"], "flavour": "rs274"}
    assert ref.read(path, spec).deposit_length_mm == 3.0
    path.write_text(";LAYER_CHANGE\nG1 X0 Y0 Z1 F600\nG1 X10 E5\n;LAYER_CHANGE\nG1 Z2\nG1 X0 E5\n")
    assert ref.read(path, {"deposit": "e", "flavour": "reprap"}).deposit_length_mm == 10.0
    r = ref.read(path, {"deposit": "e", "flavour": "reprap", "e_origin_resets_at": ";LAYER_CHANGE"})
    assert (r.deposit_length_mm, r.layers) == (20.0, 2)
    # Relative E set outside the file (Kiri:Moto): increments without M83; M82 still switches back.
    path.write_text("G1 X0 Y0 Z1 F600\nG1 X10 E0.5\nG1 X20 E0.5\nM82\nG1 X30 E0.5\n")
    assert ref.read(path, {"deposit": "e", "flavour": "reprap"}).deposit_length_mm == 10.0
    assert ref.read(path, {"deposit": "e", "flavour": "reprap", "e_relative": True}).deposit_length_mm == 20.0


def _stated_duration(text: str, comment: str) -> float:
    """The seconds a slicer's own estimate line says: Cura's ;TIME_ELAPSED:, Simplify3D's
    ;TIME: (its [total_print_time_sec]), ideaMaker's ;Print Time:, Kiri:Moto's '; --- print
    time: Ns ---', PrusaSlicer's '= 1h 2m 3s'."""
    for prefix in (";TIME_ELAPSED:", ";TIME:", ";Print Time:"):
        if comment.startswith(prefix):
            return float(comment[len(prefix):])
    kiri = re.fullmatch(r"; --- print time: (\d+)s ---", comment)
    if kiri:
        return float(kiri.group(1))
    m = re.search(r"= (?:(\d+)d )?(?:(\d+)h )?(?:(\d+)m )?(\d+)s$", comment)
    days, hours, minutes, seconds = (int(g or 0) for g in m.groups())
    return ((days * 24 + hours) * 60 + minutes) * 60 + seconds


def _cura_e_reset_excess(text: str) -> float:
    """The seconds CuraEngine's estimator adds for the G92 E0 its exporter writes mid-print: it
    times the next move's E fall from the last E before the reset at machine_max_feedrate_e."""
    setting = "".join(line[len(";SETTING_3 "):] for line in text.splitlines() if line.startswith(";SETTING_3 "))
    feed = float(re.search(r"machine_max_feedrate_e = ([0-9.]+)", setting).group(1))
    excess, last_e, reset = 0.0, None, False
    for line in text.splitlines():
        if line.startswith("G92 E0"):
            reset = last_e is not None
            continue
        e = re.match(r"G1 .*E(-?[0-9.]+)", line)
        if e:
            if reset:
                excess += (last_e - float(e.group(1))) / feed
                reset = False
            last_e = float(e.group(1))
    return excess


# Each slicer's layer marker, one line a layer (Cura states the count instead).
LAYER_MARKERS = (r"^;LAYER_CHANGE",  # PrusaSlicer
                 r"^; BEGIN_LAYER_OBJECT z=",  # KISSlicer
                 r"^; layer \d+, Z = ",  # Simplify3D
                 r"^;; --- layer \d+ ",  # Kiri:Moto
                 )


def _stated_layers(text: str) -> int:
    """The slicer's own layer count: Cura's ;LAYER_COUNT:, else its layer markers."""
    count = re.search(r"^;LAYER_COUNT:(\d+)", text, re.MULTILINE)
    if count:
        return int(count.group(1))
    return max(len(re.findall(marker, text, re.MULTILINE)) for marker in LAYER_MARKERS)


@pytest.mark.parametrize("name", list(FILES))
def test_truths_are_the_files_own(name):
    entry = FILES[name]
    path = _needs_file(name)
    r = ref.read(path, entry)
    assert r.deposit_length_mm == pytest.approx(entry["deposit_length_mm"], rel=1e-6, abs=1e-3)
    if "layers" in entry:
        assert r.layers == entry["layers"]
    if "min_duration_s" in entry:
        assert r.min_duration_s == pytest.approx(entry["min_duration_s"], rel=1e-6, abs=1e-3)
    assert r.malformed_arcs == entry.get("malformed_arcs", 0)
    text = ref.read_text(path)
    if "duration_s" in entry:
        comment = entry["duration_comment"]
        lines = [line.strip() for line in text.splitlines()]
        assert comment in lines
        if comment.startswith(";TIME_ELAPSED:"):  # Cura's running total: the last one is the estimate
            assert [line for line in lines if line.startswith(";TIME_ELAPSED:")][-1] == comment
        assert _stated_duration(text, comment) == pytest.approx(entry["duration_s"], abs=1e-6)
        # What the file fixes from below never exceeds the slicer's whole estimate.
        assert entry.get("min_duration_s", 0.0) <= entry["duration_s"]
    if "estimate_excess_s" in entry:
        assert entry["estimate_excess_why"]
        assert _cura_e_reset_excess(text) == pytest.approx(entry["estimate_excess_s"], rel=1e-6)
    for run in entry["run"]:
        if "rule" in run:  # a run whose user says another rule (custom codes) has its own truth
            other = ref.read(path, {**entry, **run["rule"]})
            assert other.deposit_length_mm == pytest.approx(run["truth"]["deposit_length_mm"], rel=1e-6, abs=1e-3)
            assert other.layers == run["truth"].get("layers", other.layers)
    if "layer_count_stated" in entry:
        assert _stated_layers(text) == entry["layer_count_stated"] == entry["layers"]
    # gzip: the file is the source's text compressed, nothing else, and compressed because it is large
    if name.endswith(".gz"):
        assert gzip.decompress(path.read_bytes()).decode("ascii") == text
        assert len(text) > MAX_PLAIN_BYTES, name


_runs: dict[tuple, tuple[int, dict, str]] = {}


def run_info(name: str, args: list[str]) -> tuple[int, dict, str]:
    """`dmdvox info FILE ARGS --json` in this process, once per session: exit code, JSON, stderr."""
    key = (name, tuple(args))
    if key not in _runs:
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(["info", str(CORPUS / name), *args, "--json"])
        text = out.getvalue().strip()
        _runs[key] = (code, json.loads(text) if text else {}, err.getvalue())
    return _runs[key]


def _compare(key: str, entry: dict, run: dict, out: dict) -> str | None:
    """None when dmdvox's figure holds the truth, else what differs."""
    truth = run.get("truth", {}).get(key, entry[key])
    if key == "deposit_length_mm":
        got = out["deposit_length_mm"]
        if abs(got - truth) <= DEPOSIT_TOLERANCE * truth + 1e-3:
            return None
        return f"deposit length {got:.3f} mm, true {truth:.3f} mm ({(got - truth) / max(truth, 1e-9):+.1%})"
    if key == "layers":
        return None if out["layers"] == truth else f"{out['layers']} layers, true {truth}"
    if key == "min_duration_s":
        got = out["duration_s"]
        if got >= truth * (1 - 1e-3) - 1e-3:
            return None
        return f"duration {got:.2f} s is shorter than the program's own lower bound {truth:.2f} s"
    truth -= entry.get("estimate_excess_s", 0.0)
    got = out["duration_s"]
    tolerance = run["duration_tolerance"]
    if abs(got - truth) <= tolerance * truth:
        return None
    return (f"duration {got:.1f} s, the file's own estimate {truth:.1f} s ({(got - truth) / truth:+.1%}, "
            f"tolerance {tolerance:.0%})")


@pytest.mark.parametrize("name,index", RUNS, ids=[f"{n}-{i}" for n, i in RUNS])
def test_dmdvox_reads_it_right_or_loudly(name, index):
    entry, run = FILES[name], FILES[name]["run"][index]
    _needs_file(name)
    code, out, err = run_info(name, run["args"])
    assert code in (0, 2), f"dmdvox info {' '.join(run['args'])}: exit {code} (internal error)\n{err[-3000:]}"
    said = "\n".join(out.get("warnings", [])) if code == 0 else out.get("error", err)
    loud = run.get("loud")
    is_loud = bool(loud and re.search(loud, said))
    problems = []
    must = run.get("must_say")
    if must and not re.search(must, said):
        problems.append(f"does not say /{must}/ (it says: {said or 'nothing'})")
    if code == 2:
        if not (is_loud or (run.get("refusal_ok") and must and re.search(must, said))):
            problems.append(f"refused with exit 2: {said}")
    else:
        excused = set(run["excuses"]) if is_loud else set()
        problems += [msg for key in run["check"] if key not in excused and (msg := _compare(key, entry, run, out))]
    if problems and said and not any(p.startswith("does not say") for p in problems):
        problems.append(f"(it says: {said[:600]})")
    assert not problems, f"{name} {run['args']}:\n  " + "\n  ".join(problems)
