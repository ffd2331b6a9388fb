"""The package reads as the pipeline: no module imports from a floor above its own.

Floors, bottom up (docs/DESIGN.md, "Package layout"): the shared floor (errors, memory budget,
progress lines, warnings, defaults, the OpenVDB shim); toolpath, io and the task runner; process;
grid; deposit; the analyses (comparison, collision); study; view and reporting; the verifier; the API;
the command line. Every import is found by walking the source (function-level imports too, since
the lazy ones are where an upward import would hide).
"""

import ast
from pathlib import Path

from .conftest import REPO

PACKAGE = REPO / "dmdvox"
FLOORS = {
    "errors": 0, "memory": 0, "progress": 0, "checks": 0, "defaults": 0, "vdb": 0, "summary": 0, "__version__": 0,
    "toolpath": 1, "io": 1, "tasks": 1,
    "process": 2,
    "grid": 3, "thermal": 3,
    "deposit": 4,
    "comparison": 5, "collision": 5,
    "study": 6,
    "view": 7, "reporting": 7,
    "limits": 8, "changes": 8,
    "api": 9, "build": 9,
    "cli": 10, "demo": 10, "warm": 10, "__init__": 10, "__main__": 10,
}


def imported_parts(source: str, module: tuple[str, ...]) -> list[tuple[int, str]]:
    """(line, first part below ``dmdvox``) of every dmdvox import in the source of ``module``
    (its dotted parts, ``__init__`` last for a package)."""
    package = module[:-1]
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.ImportFrom):
            base = list(package[:len(package) - node.level + 1]) if node.level else []
            target = base + (node.module.split(".") if node.module else [])
            if target[:1] != ["dmdvox"]:
                continue
            if len(target) == 1:  # from dmdvox import x / from . import x at the top
                found += [(node.lineno, alias.name) for alias in node.names]
            else:
                found.append((node.lineno, target[1]))
        elif isinstance(node, ast.Import):
            found += [(node.lineno, alias.name.split(".")[1]) for alias in node.names
                      if alias.name.startswith("dmdvox.")]
    return found


def floor_of(path: Path) -> tuple[str, int]:
    top = path.relative_to(PACKAGE).with_suffix("").parts[0]
    assert top in FLOORS, f"{path}: place {top!r} on a floor in FLOORS (and in docs/DESIGN.md)"
    return top, FLOORS[top]


def test_no_import_from_a_higher_floor():
    upward = []
    for path in sorted(PACKAGE.rglob("*.py")):
        top, floor = floor_of(path)
        for line, other in imported_parts(path.read_text(), path.relative_to(REPO).with_suffix("").parts):
            assert other in FLOORS, f"{path}:{line}: imports dmdvox.{other}, which has no floor in FLOORS"
            if other != top and FLOORS[other] > floor:
                upward.append(f"{path.relative_to(REPO)}:{line}: {top} (floor {floor}) imports {other} "
                              f"(floor {FLOORS[other]})")
    assert not upward, "\n".join(upward)


def test_the_walk_sees_every_kind_of_import():
    """The walker itself: absolute, relative, parent-relative, package-level and in-function
    imports, seen from a module and from a package's ``__init__``."""
    source = ("from ..deposit import engine\nimport dmdvox.reporting.build\nfrom . import sparse\n"
              "from .. import checks\ndef f():\n    from dmdvox.view import pictures\n")
    parts = [other for _, other in imported_parts(source, ("dmdvox", "grid", "probe"))]
    assert parts == ["deposit", "reporting", "grid", "checks", "view"]
    parts = [other for _, other in imported_parts("from .sparse import x\nfrom ..io import y\n",
                                                  ("dmdvox", "grid", "__init__"))]
    assert parts == ["grid", "io"]
