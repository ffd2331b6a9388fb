"""G-code in, toolpath out."""

from .model import ArcTable, Toolpath
from .reader import read_gcode

__all__ = ["ArcTable", "Toolpath", "read_gcode"]
