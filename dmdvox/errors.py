"""The error and warning families dmdvox raises for problems a user can fix, or should know of.

The CLI maps :class:`DmdvoxError` to exit code 2 and prints its message without a traceback;
anything else is an internal error (exit 1).

An error about one value the caller gave names that value as the caller knows it: the library's
parameter (``voxel``, ``max_drop_mm``) for a Python caller, the option (``--voxel``,
``--max-drop``) at the command line. The library writes the message with the parameter as
``{voxel}`` and gives ``parameter="voxel"``; ``str(error)`` fills in the parameter's own name,
and :meth:`DmdvoxError.worded` the caller's words (``dmdvox.cli`` holds the table
parameter -> option).

Warnings (:class:`DmdvoxWarning`) go through Python's :mod:`warnings` module, so that
``warnings.simplefilter("ignore", dmdvox.DmdvoxWarning)`` silences them and ``"error"`` makes
them errors; :func:`dmdvox.checks.collect_warnings` keeps those of one run.
"""

from __future__ import annotations

from typing import Mapping


class DmdvoxError(Exception):
    """A problem with the input or the request, explained so the user can act on it.

    ``parameter``: the library's name of the value at fault (None when the problem is not one
    value's); ``parameters``: every parameter the message names (``parameter`` first)."""

    exit_code = 2

    def __init__(self, message: str = "", *, parameter: str | None = None, also: tuple[str, ...] = ()):
        self.template = message
        self.parameter = parameter
        self.parameters = (parameter, *also) if parameter is not None else tuple(also)
        super().__init__(self.worded({}))

    def worded(self, words: Mapping[str, str]) -> str:
        """The message with each parameter it names in ``words`` (name -> the caller's word;
        a name missing from ``words`` stays itself)."""
        text = self.template
        for name in self.parameters:
            text = text.replace("{" + name + "}", words.get(name, name))
        return text

    def prefixed(self, prefix: str, *, also: tuple[str, ...] = ()) -> "DmdvoxError":
        """This error, its message after ``prefix`` (what it concerns, worded with ``also``'s
        parameters as ``{name}``), its parameters kept."""
        error = _rebuild(type(self), (), dict(self.__dict__))
        error.template = prefix + self.template
        error.parameters = (*self.parameters, *also)
        error.args = (error.worded({}),)
        return error

    def __reduce__(self):
        # the subclasses' constructors differ (GcodeError takes path, line, message): rebuild
        # from the state, so that an error raised on a worker reaches the caller whole
        return _rebuild, (type(self), self.args, self.__dict__)


def _rebuild(cls, args, state):
    error = cls.__new__(cls)
    error.args = args
    error.__dict__.update(state)
    return error


class ParameterError(DmdvoxError):
    """A value the caller gave that cannot be used (``parameter`` names it)."""

    def __init__(self, message: str, parameter: str, *, also: tuple[str, ...] = ()):
        super().__init__(message, parameter=parameter, also=also)


class GcodeError(DmdvoxError):
    """A G-code line that cannot be interpreted; the message starts with ``FILE:LINE:``."""

    def __init__(self, path: str, line: int, message: str):
        self.path = path
        self.line = line
        self.reason = message
        super().__init__(f"{path}:{line}: {message}")


class InputFileError(DmdvoxError):
    """A file that is missing, empty, truncated or not of the expected kind."""


class ResourceError(DmdvoxError):
    """A request refused because it would not fit in the available memory."""


class DependencyError(DmdvoxError):
    """A required library is missing; the message names the install step."""


class DmdvoxWarning(UserWarning):
    """A doubt about the input or the result that does not stop the run."""


class InputWarning(DmdvoxWarning):
    """About what was given: the program (its reader's doubts, rotary words not followed), the
    CAD mesh (open, degenerate, far from the deposit), a moment before the first bead."""


class PhysicsWarning(DmdvoxWarning):
    """About what the process does: material lost, a part growing into the nozzle, runaway
    growth, a power read from the program's S words."""
