"""Generated programs: the interpreter's lengths and times against an independent computation."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from dmdvox.toolpath import read_gcode

coord = st.floats(-200, 200, allow_nan=False).map(lambda v: round(v, 3))
linear_move = st.tuples(st.just("line"), st.booleans(), coord, coord, coord)
arc_move = st.tuples(st.just("arc"), st.booleans(), st.floats(0.5, 50).map(lambda v: round(v, 3)),
                     st.floats(-math.pi, math.pi), st.floats(0.05, 2 * math.pi - 0.05), st.floats(-5, 5))
programs = st.lists(st.one_of(linear_move, arc_move), min_size=1, max_size=25)


def render(moves):
    """G-code text plus the expected length per move, computed without the interpreter."""
    pos = np.zeros(3)
    lines = ["G90 G21 G17 G1 X0 Y0 Z0 F1200"]
    lengths = []
    for move in moves:
        if move[0] == "line":
            _, relative, x, y, z = move
            target = pos + (x, y, z) if relative else np.array([x, y, z])
            lines.append(("G91 " if relative else "G90 ") + f"G1 X{x:.3f} Y{y:.3f} Z{z:.3f}")
            target = np.round(target, 9)
            lengths.append(float(np.linalg.norm(target - pos)))
            pos = target
        else:
            _, ccw, radius, phase, span, rise = move
            # Centre chosen so the start lies on the circle at angle `phase`.
            centre = pos[:2] - radius * np.array([math.cos(phase), math.sin(phase)])
            end_angle = phase + (span if ccw else -span)
            end_xy = centre + radius * np.array([math.cos(end_angle), math.sin(end_angle)])
            end = np.array([end_xy[0], end_xy[1], pos[2] + rise])
            i, j = centre - pos[:2]
            lines.append(f"G90 G{3 if ccw else 2} X{end[0]:.9f} Y{end[1]:.9f} Z{end[2]:.9f} I{i:.9f} J{j:.9f}")
            lengths.append(math.hypot(radius * span, rise))
            pos = np.round(end, 9)
    return "\n".join(lines) + "\n", np.array(lengths)


@settings(max_examples=150, deadline=None)
@given(programs)
def test_lengths_and_times_match_independent_computation(tmp_path_factory, moves):
    text, expected = render(moves)
    path = tmp_path_factory.mktemp("gen") / "p.gcode"
    path.write_text(text)
    tp = read_gcode(path)
    keep = expected > 1e-9
    np.testing.assert_allclose(tp.length, expected[keep], rtol=1e-4, atol=1e-6)
    np.testing.assert_allclose(tp.t_end[-1] if len(tp) else 0.0, expected.sum() / 20.0, rtol=1e-4, atol=1e-6)
    assert not tp.meta["warnings"]
    # Rows are contiguous: each starts where the previous ended.
    np.testing.assert_allclose(tp.start[1:], tp.end[:-1], atol=1e-9)
