"""Doubtful inputs said out loud, and requests refused before any work.

Warnings go through :func:`warn`: a :class:`~dmdvox.errors.DmdvoxWarning` through Python's
:mod:`warnings` module (the CLI shows it as one line ``warning: TEXT`` on stderr), and the text
kept in every :func:`collect_warnings` list open around the call: the CLI opens one per command
for the ``warnings`` list of its ``--json`` object, a build one for its result. A warning that
drops or changes data (here: rotary words, whose axes are not modelled) is an error under
``--strict``; a doubt that changes nothing (boxes that do not overlap, a program that deposits
nothing) stays a warning.

Also here, because they must run before any work: output file extensions, numpy's major
version against the OpenVDB binding (numpy 2 makes Debian's pyopenvdb 10 crash), and the binding
itself.
"""

from __future__ import annotations

import contextlib
import contextvars
import importlib.util
import sys
import warnings as _warnings
from pathlib import Path
from typing import Iterator

import numpy as np

from .errors import DependencyError, DmdvoxError, DmdvoxWarning, InputWarning, ParameterError

ROTARY_WARNING = ("A/B/C rotary words are present on axes the machine does not model (no --machine, or a "
                  "machine without those axes): they are not followed; give the machine file with "
                  "--machine FILE.toml (docs/MACHINES.md)")

# The lists open in this context, outermost first. A context variable, not a module list: each
# thread (and each asyncio task) has its own, so two builds running side by side do not see
# each other's warnings. A tuple, replaced on entry and exit, so a nested collection never
# changes the one around it.
_open: contextvars.ContextVar[tuple[list[str], ...]] = contextvars.ContextVar("dmdvox_warnings", default=())


# -- warnings ------------------------------------------------------------------------------------

def warn(text: str, category: type[DmdvoxWarning] = DmdvoxWarning) -> None:
    """Say ``text`` as a ``category`` warning, and keep it in each open :func:`collect_warnings`
    list that lacks it. Inside a collection a text is said once (the first time the outermost
    list sees it); outside any, Python's warning filters decide (by default once per text)."""
    lists = _open.get()
    said = bool(lists) and text in lists[0]
    for kept in lists:
        if text not in kept:
            kept.append(text)
    if not said:
        _warnings.warn(category(text), stacklevel=2)


def record(texts) -> None:
    """Keep ``texts`` in each open :func:`collect_warnings` list that lacks them, without saying
    them again (warnings the caller already heard, from a plan it made itself)."""
    for kept in _open.get():
        kept.extend(text for text in texts if text not in kept)


@contextlib.contextmanager
def collect_warnings() -> Iterator[list[str]]:
    """``with collect_warnings() as said:`` -- ``said`` lists, in order and each once, the
    warnings :func:`warn` gave inside the block (in this thread; nested blocks each get theirs,
    and the blocks around them get them too)."""
    kept: list[str] = []
    token = _open.set((*_open.get(), kept))
    try:
        yield kept
    finally:
        _open.reset(token)


def collected() -> list[str]:
    """The warnings of the run so far: the outermost open collection's (empty outside any)."""
    lists = _open.get()
    return list(lists[0]) if lists else []


@contextlib.contextmanager
def warnings_on_stderr() -> Iterator[None]:
    """For the command line: each DmdvoxWarning as ``warning: TEXT`` on stderr, every time
    :func:`warn` says it (the collection already says each once per command; Python's default
    filter would also hide it from the next command run in the same process). Other warnings
    keep Python's display. Process-wide, as :func:`warnings.catch_warnings` is."""
    with _warnings.catch_warnings():
        shown = _warnings.showwarning
        _warnings.simplefilter("always", DmdvoxWarning)

        def show(message, category, filename, lineno, file=None, line=None):
            if not issubclass(category, DmdvoxWarning):
                return shown(message, category, filename, lineno, file, line)
            try:
                print(f"warning: {message}", file=sys.stderr, flush=True)
            except (BrokenPipeError, ValueError):
                pass

        _warnings.showwarning = show
        yield


def merge_into(result, warnings: list[str]) -> None:
    """Add ``warnings`` to ``result["warnings"]`` (created when missing), each once, in order."""
    if not isinstance(result, dict):
        return
    merged = list(result.get("warnings") or [])
    merged += [w for w in warnings if w not in merged]
    result["warnings"] = merged


# -- the toolpath ----------------------------------------------------------------------------------

def check_toolpath(tp, strict: bool = False) -> None:
    """What every command that reads a program says about it: the reader's warnings, and rotary
    words (an error under ``--strict``: the A/B/C motion is dropped)."""
    for text in tp.meta.get("warnings", []):
        warn(text, InputWarning)
    if tp.meta.get("rotary_used"):
        if strict:
            raise DmdvoxError(f"{tp.source}: {ROTARY_WARNING}; --strict refuses a program it cannot follow "
                              "(drop --strict to run it with a vertical tool axis)")
        warn(f"{tp.source}: {ROTARY_WARNING}", InputWarning)


def first_deposit_time(tp) -> float | None:
    """When the first bead starts (s), None when nothing is deposited."""
    if not np.any(tp.deposit):
        return None
    return float(np.min(tp.t_start[tp.deposit]))


def _nothing_deposited(tp) -> str:
    unknown = tp.meta.get("unknown_codes", {})
    ignored = f"; codes it ignored: {', '.join(sorted(unknown))}" if unknown else ""
    moves = f"{len(tp):,d} move{'' if len(tp) == 1 else 's'}"
    lost = tp.meta.get("moves_from_unknown_position", 0)
    if lost and not len(tp):  # the dialect is not the cause: the reader did not know where the tool was
        return (f"{tp.source}: the program deposits nothing: its {lost:,d} moves start from a position it never "
                "gives (no absolute X, Y and Z, G28 or G92 before them) and none is recorded; give the start with "
                "--start X,Y,Z")
    return (f"{tp.source}: the program deposits nothing under dialect '{tp.dialect}' ({moves}, none with "
            f"deposition on{ignored}); check --dialect (or --dialect custom with --laser-on and --laser-off)")


def warn_if_nothing_deposited(tp) -> None:
    """``info``: a program that deposits nothing is summarised, with a warning."""
    if not np.any(tp.deposit):
        warn(_nothing_deposited(tp), InputWarning)


def require_deposit(tp, until: float | None = None) -> None:
    """Refuse, before any grid is planned, a run with nothing to deposit: the program deposits
    nothing, or ``until`` comes before its first bead."""
    first = first_deposit_time(tp)
    if first is None:
        raise DmdvoxError(_nothing_deposited(tp))
    if until is not None and np.isfinite(until) and until <= first:
        raise ParameterError(f"{{until}} {until:g}: that is before the first deposit, which starts at {first:.3f} s "
                             f"(line {int(tp.line[np.argmax(tp.deposit)])}); give a time after {first:.3f} s "
                             f"(the program runs {tp.duration:.3f} s)", "until")


def warn_if_before_first_deposit(tp, time_s: float | None, option: str) -> None:
    """``render``: a moment before the first bead shows an empty frame; say why."""
    first = first_deposit_time(tp)
    if time_s is not None and first is not None and time_s <= first:
        warn(f"{option}: the moment {time_s:g} s is before the first deposit, at {first:.3f} s: the picture shows "
             "no material", InputWarning)


# -- the voxel --------------------------------------------------------------------------------------

def require_voxel_resolves_bead(plan, voxel: float | None) -> None:
    """Refuse a voxel coarser than half the bead's height or width: fewer than two voxels across
    the bead do not resolve it, and the volumes come out confidently wrong (2.2x the truth at
    10 mm on the demo block's 2.5 x 0.75 mm bead)."""
    if voxel is None or not np.isfinite(voxel) or voxel <= 0:  # the deposit refuses those itself
        return
    bead = plan.profile
    largest = min(bead.width, bead.height) / 2
    if voxel > largest:
        raise ParameterError(f"{{voxel}} {voxel:g}: coarser than half the bead ({bead.name} {bead.width:g} mm "
                             f"wide, {bead.height:g} mm high), which it cannot resolve; use {{voxel}} {largest:g} or "
                             f"finer (default {plan.default_voxel():g})", "voxel")


# -- the CAD part ---------------------------------------------------------------------------------

def deposit_box(tp, bead) -> np.ndarray:
    """``[[lo], [hi]]`` of the material the program lays: the path box widened by half a bead
    in x and y and by the bead height on the side its Z stands for (bottom, or top for slicers)."""
    box = np.array(tp.deposit_bbox(), np.float64)
    box[0, :2] -= bead.width / 2
    box[1, :2] += bead.width / 2
    if tp.z_is_layer_top:
        box[0, 2] -= bead.height
    else:
        box[1, 2] += bead.height
    return box


def suggested_cad_offset(deposit: np.ndarray, cad_lo, cad_hi, offset=(0.0, 0.0, 0.0)) -> np.ndarray:
    """The ``--cad-offset`` that centres the CAD part on the deposit in x and y and puts its
    bottom on the deposit's bottom (``cad_lo``/``cad_hi`` are the part as currently placed,
    ``offset`` included)."""
    cad_lo, cad_hi = np.asarray(cad_lo, np.float64), np.asarray(cad_hi, np.float64)
    shift = np.empty(3)
    shift[:2] = (deposit[0, :2] + deposit[1, :2]) / 2 - (cad_lo[:2] + cad_hi[:2]) / 2
    shift[2] = deposit[0, 2] - cad_lo[2]
    return np.asarray(offset, np.float64) + shift


def warn_if_apart(tp, bead, cad_path, cad_lo, cad_hi, offset=(0.0, 0.0, 0.0)) -> str | None:
    """Warn when the CAD part's box and the deposit's do not overlap (a CAD file in another
    frame, or a forgotten ``--cad-offset``); returns the warning, or None."""
    if not np.any(tp.deposit):
        return None
    deposit = deposit_box(tp, bead)
    cad_lo, cad_hi = np.asarray(cad_lo, np.float64), np.asarray(cad_hi, np.float64)
    if np.all(cad_lo < deposit[1]) and np.all(deposit[0] < cad_hi):
        return None
    text = (f"{cad_path}: the CAD part ({_boxes(deposit, cad_lo, cad_hi)}) do not overlap: every deposit voxel "
            f"counts as overbuild and the whole part as void; {_offset_hint(deposit, cad_lo, cad_hi, offset)}")
    warn(text, InputWarning)
    return text


def _boxes(deposit, cad_lo, cad_hi) -> str:
    (dx0, dy0, dz0), (dx1, dy1, dz1) = deposit
    (cx0, cy0, cz0), (cx1, cy1, cz1) = cad_lo, cad_hi
    return (f"x {cx0:.2f}..{cx1:.2f}, y {cy0:.2f}..{cy1:.2f}, z {cz0:.2f}..{cz1:.2f} mm) and the deposit "
            f"(x {dx0:.2f}..{dx1:.2f}, y {dy0:.2f}..{dy1:.2f}, z {dz0:.2f}..{dz1:.2f} mm")


def _offset_hint(deposit, cad_lo, cad_hi, offset) -> str:
    x, y, z = suggested_cad_offset(deposit, cad_lo, cad_hi, offset)
    fmt = lambda v: f"{round(v, 3) + 0.0:.3f}".rstrip("0").rstrip(".")  # noqa: E731 (no "-0")
    return (f"if the CAD is in another frame, --cad-offset={fmt(x)},{fmt(y)},{fmt(z)} centres it on the deposit in "
            "x and y and puts its bottom on the deposit's")


# void or overbuild beyond this share of the CAD volume: the part and the deposit hardly coincide
MISALIGNED_PERCENT = 50.0


def warn_if_misaligned(tp, bead, cad_path, cad_lo, cad_hi, offset, void_percent: float,
                       overbuild_percent: float) -> str | None:
    """Warn when the comparison's void or overbuild exceeds half the CAD volume although the
    boxes overlap (a CAD frame far off whose box still touches the deposit's by the bead margin
    gave 99.9 % void silently); returns the warning, or None."""
    worst = max((p for p in (void_percent, overbuild_percent) if np.isfinite(p)), default=None)
    if worst is None or worst <= MISALIGNED_PERCENT or not np.any(tp.deposit):
        return None
    deposit = deposit_box(tp, bead)
    text = (f"{cad_path}: void {void_percent:.1f} % and overbuild {overbuild_percent:.1f} % of the CAD volume: the "
            f"CAD part ({_boxes(deposit, cad_lo, cad_hi)}) hardly coincide; "
            f"{_offset_hint(deposit, cad_lo, cad_hi, offset)}")
    warn(text, InputWarning)
    return text


# -- outputs --------------------------------------------------------------------------------------

# (argparse destination, option, accepted suffixes, what is written)
OUTPUT_FILES = (
    ("png", "--png", (".png",), "the picture is written as PNG"),
    ("plot", "--plot", (".png",), "the plot is written as PNG"),
    ("csv", "--csv", (".csv",), "the table is written as CSV"),
    ("junit", "--junit", (".xml",), "the report is written as JUnit XML"),
)


def check_output_names(args) -> None:
    """Refuse, before any work, an output file whose extension names another format."""
    for dest, option, suffixes, what in OUTPUT_FILES:
        value = getattr(args, dest, None)
        if value is None:
            continue
        path = Path(str(value))
        if path.suffix.lower() not in suffixes:
            example = path.with_suffix(suffixes[0]).name if path.name else f"out{suffixes[0]}"
            raise DmdvoxError(f"{option} {value}: {what}; give a file name ending in "
                              f"{' or '.join(suffixes)} (e.g. {example})")
        if path.is_dir():
            raise DmdvoxError(f"{option} {value}: that is a folder; give the name of the file to write")


# -- the environment ------------------------------------------------------------------------------

def numpy_refusal(numpy_version: str | None = None) -> str | None:
    """Why this numpy cannot run OpenVDB's binding, or None when it can.

    Debian's pyopenvdb 10 is built against numpy 1.x: with numpy 2 its array copies crash the
    process (a segmentation fault, exit 139, no message). OpenVDB >= 12 (module ``openvdb``)
    is built for the numpy it is installed with."""
    if numpy_version is None:
        numpy_version = np.__version__
    try:
        major = int(numpy_version.split(".")[0])
    except ValueError:
        return None
    if major < 2 or importlib.util.find_spec("openvdb") is not None:
        return None
    return (f"numpy {numpy_version} is installed, but OpenVDB's Python binding (pyopenvdb 10) is built for numpy 1 "
            'and crashes with numpy 2; install numpy 1: pip install "numpy<2" '
            "(scripts/setup.sh keeps it there with scripts/constraints.txt)")


def require_numpy_for_openvdb() -> None:
    problem = numpy_refusal()
    if problem:
        raise DependencyError(problem)


def require_openvdb() -> None:
    """Refuse, before any work, a command that needs OpenVDB when its binding cannot load: numpy 2
    under pyopenvdb 10 (checked before the binding is imported, which would crash), or no binding
    (the shim's message names the two ways to get one)."""
    require_numpy_for_openvdb()
    importlib.import_module(f"{__package__}.vdb")
