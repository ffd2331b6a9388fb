import os
from pathlib import Path

import pytest

# Headless rendering for every test that draws.
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

REPO = Path(__file__).resolve().parents[1]
DATA = REPO / "data"


@pytest.fixture
def gcode_file(tmp_path):
    """Write G-code text to a file and return its path."""
    counter = iter(range(1_000_000))

    def make(text: str, name: str | None = None) -> Path:
        path = tmp_path / (name or f"prog{next(counter)}.gcode")
        path.write_text(text)
        return path

    return make
