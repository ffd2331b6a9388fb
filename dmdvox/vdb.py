"""The single import point for OpenVDB's Python binding.

OpenVDB >= 12 names its module ``openvdb`` (nanobind); Debian's 10.x ships ``pyopenvdb``
(Boost.Python). Everything in dmdvox imports ``openvdb`` from here.

pyopenvdb 10 is built against numpy 1.x and crashes the process (a segmentation fault, no
message) on its first array copy under numpy 2, so that combination is refused here, before
the binding is loaded, with the fix (``pip install "numpy<2"``).
"""

from __future__ import annotations

import glob
import sys
import sysconfig

from .checks import numpy_refusal
from .errors import DependencyError

DEBIAN_BINDINGS = "/usr/lib/python3/dist-packages/pyopenvdb.cpython-311-*.so"


def missing_binding(reason: str) -> str:
    """The two ways to get a binding, for this interpreter: a wheel installs neither, since
    Debian's is a system package for CPython 3.11 and no OpenVDB wheel is on PyPI for most
    platforms."""
    site = sysconfig.get_paths()["purelib"]
    found = sorted(glob.glob(DEBIAN_BINDINGS))
    binding = found[0] if found else DEBIAN_BINDINGS
    version = f"{sys.version_info[0]}.{sys.version_info[1]}"
    debian = (f"(1) Debian/Ubuntu: sudo apt-get install python3-openvdb, then link its binding into this environment: "
              f"ln -s {binding} {site}/ ")
    debian += ("(scripts/setup.sh does both)" if version == "3.11" else
               f"(it is built for CPython 3.11; this is {version}: make the environment with python3.11 -m venv)")
    return (f"OpenVDB's Python binding is not importable ({reason}). Two ways to get it: {debian}; "
            "(2) OpenVDB >= 12, whose module is named 'openvdb', built for this Python: pip install openvdb "
            "where a wheel exists for your platform, or conda install -c conda-forge openvdb")


try:
    import openvdb  # type: ignore[import-not-found]
except ImportError:
    _problem = numpy_refusal()
    if _problem:
        raise DependencyError(_problem) from None
    try:
        import pyopenvdb as openvdb  # type: ignore[import-not-found, no-redef]
    except ImportError as exc:
        raise DependencyError(missing_binding(f"tried 'openvdb' and 'pyopenvdb': {exc}")) from exc

__all__ = ["openvdb"]
