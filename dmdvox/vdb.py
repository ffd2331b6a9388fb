"""The single import point for OpenVDB's Python binding.

OpenVDB >= 12 names its module ``openvdb`` (nanobind); Debian's 10.x ships ``pyopenvdb``
(Boost.Python). Everything in dmdvox imports ``openvdb`` from here.

pyopenvdb 10 is built against numpy 1.x and crashes the process (a segmentation fault, no
message) on its first array copy under numpy 2, so that combination is refused here, before
the binding is loaded, with the fix (``pip install "numpy<2"``).
"""

from __future__ import annotations

from .checks import numpy_refusal
from .errors import DependencyError

try:
    import openvdb  # type: ignore[import-not-found]
except ImportError:
    _problem = numpy_refusal()
    if _problem:
        raise DependencyError(_problem) from None
    try:
        import pyopenvdb as openvdb  # type: ignore[import-not-found, no-redef]
    except ImportError as exc:  # pragma: no cover - exercised only on broken installs
        raise DependencyError(
            "OpenVDB's Python binding is not importable (tried 'openvdb' and 'pyopenvdb'). "
            "Run scripts/setup.sh, or on Debian/Ubuntu: apt-get install python3-openvdb "
            f"and link its pyopenvdb*.so into your environment ({exc})"
        ) from exc

__all__ = ["openvdb"]
