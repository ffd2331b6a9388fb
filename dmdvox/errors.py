"""The one error family dmdvox raises for problems a user can fix.

The CLI maps :class:`DmdvoxError` to exit code 2 and prints its message without a traceback;
anything else is an internal error (exit 1).
"""

from __future__ import annotations


class DmdvoxError(Exception):
    """A problem with the input or the request, explained so the user can act on it."""

    exit_code = 2


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
