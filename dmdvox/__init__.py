"""dmdvox: predict what a Directed Energy Deposition toolpath builds.

The library's entry points (:mod:`dmdvox.api`, docs/API.md) are loaded on first use, so that
``import dmdvox`` and the command line's start stay light.
"""

__version__ = "0.1.0"

from .errors import (DependencyError, DmdvoxError, DmdvoxWarning, GcodeError, InputFileError, InputWarning,
                     ParameterError, PhysicsWarning, ResourceError)

_ERRORS = ("DependencyError", "DmdvoxError", "DmdvoxWarning", "GcodeError", "InputFileError", "InputWarning",
           "ParameterError", "PhysicsWarning", "ResourceError")

_API = ("Build", "CheckRequest", "CheckResult", "CollideRequest", "Collisions", "CompareRequest", "Comparison", "Diff",
        "DiffRequest", "FlowSettings", "LandingSettings", "MotionSettings", "NozzleSettings", "ProcessPlan",
        "ProcessSettings", "Report", "ReportRequest", "SimulateRequest", "Simulation", "Toolpath", "check", "collide",
        "compare", "diff", "plan", "read_gcode", "report", "simulate")


def __getattr__(name: str):
    if name in _API:
        from . import api

        return getattr(api, name)
    raise AttributeError(f"module 'dmdvox' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_API])


__all__ = ["__version__", *_ERRORS, *_API]
