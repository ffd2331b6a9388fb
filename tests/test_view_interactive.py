"""`dmdvox view` and `dmdvox scene` handlers, driven headless: keys sent, state checked."""

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.view.interactive import ReplayState, build_replay
from dmdvox.view.scene_app import SceneApp, load_scene_config

from .conftest import DATA


# -- ReplayState: the seed's key arithmetic --------------------------------------------------------

def test_speed_keys_multiply_by_1_3():
    s = ReplayState(90.0)
    s.key("plus")
    s.key("+")
    assert s.speed_factor == pytest.approx(1.69)
    s.key("minus")
    assert s.speed_factor == pytest.approx(1.3)


def test_digits_home_end_seek():
    s = ReplayState(90.0)
    s.key("3")
    assert s.time == pytest.approx(30.0)
    s.key("9")
    assert s.time == pytest.approx(90.0)
    s.key("0")
    assert s.time == 0.0
    s.key("End")
    assert s.time == 90.0
    s.key("Home")
    assert s.time == 0.0


def test_space_direction_advance_and_clamping():
    s = ReplayState(30.0, base_speed=2.0)
    s.advance(1.0)
    assert s.time == 0.0  # paused: time stands still
    s.key("space")
    assert s.running
    s.advance(1.5)
    assert s.time == pytest.approx(3.0)
    s.key("Left")
    s.advance(1.0)
    assert s.time == pytest.approx(1.0)
    s.advance(10.0)
    assert s.time == 0.0  # clamped at the start
    s.key("Right")
    s.advance(100.0)
    assert s.time == 30.0  # clamped at the end
    s.key(" ")
    assert not s.running
    assert not s.key("x")


# -- Replay on the demo block --------------------------------------------------------------------

@pytest.fixture(scope="module")
def replay():
    from dmdvox.deposit.simulate import bead_from_options
    from dmdvox.toolpath import read_gcode

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    bead = bead_from_options(tp, "rect", 2.5, None, 4.0)
    r = build_replay(tp, bead, off_screen=True)
    r.plotter.window_size = (400, 300)
    yield r
    r.close()


def test_end_shows_every_triangle_and_home_none(replay):
    assert replay.handle_key("End")
    assert replay.state.time == replay.state.duration
    assert replay.part.n_cells == replay.n_triangles > 1000
    replay.handle_key("Home")
    shown = replay.part.n_cells
    assert shown == np.count_nonzero(replay.triangle_time <= 0.0) == 0
    assert not replay.part_actor.GetVisibility()


def test_digit_shows_the_part_so_far_and_the_nozzle_at_the_path_point(replay):
    replay.handle_key("4")
    t = replay.state.time
    assert t == pytest.approx(4 / 9 * replay.state.duration)
    assert 0 < replay.part.n_cells < replay.n_triangles
    # independent interpolation on the (all-linear) demo program
    tp = replay.tp
    row = np.flatnonzero((tp.t_start <= t) & (t <= tp.t_end))[0]
    frac = (t - tp.t_start[row]) / (tp.t_end[row] - tp.t_start[row])
    expected = tp.start[row] + frac * (tp.end[row] - tp.start[row])
    np.testing.assert_allclose(replay.nozzle_actor.position, expected + [0, 0, replay.standoff], atol=1e-9)
    # the path drawn so far ends at the tool point
    np.testing.assert_allclose(replay.path.points[-1], expected, atol=1e-6)


def test_screenshots_not_blank_and_differ_between_times(replay):
    replay.handle_key("3")
    early = replay.plotter.screenshot(return_img=True).astype(int)
    replay.handle_key("End")
    late = replay.plotter.screenshot(return_img=True).astype(int)
    for img in (early, late):
        spread = img.max(axis=2) - img.min(axis=2)
        assert np.count_nonzero(spread > 40) > 500  # coloured part / nozzle pixels, not a blank canvas
    assert np.abs(early - late).mean() > 1.0


def test_slider_and_timer_follow_the_state(replay):
    replay.handle_key("Home")
    replay._on_slider(0.5 * replay.state.duration)
    assert replay.state.time == pytest.approx(0.5 * replay.state.duration)
    assert replay.slider.GetRepresentation().GetValue() == pytest.approx(replay.state.time)
    replay.handle_key("space")
    replay.state.advance(1.0)
    assert replay.state.time == pytest.approx(0.5 * replay.state.duration + replay.state.base_speed)
    replay.handle_key("space")


def test_collision_markers_appear_at_their_time():
    from dmdvox.view.interactive import Replay
    from dmdvox.toolpath import read_gcode

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    surface = (np.zeros((0, 3)), np.zeros((0, 3), np.int64), np.zeros(0))
    markers = [(5.0, 5.0, 1.0, 0.25 * tp.duration), (6.0, 5.0, 1.0, 0.75 * tp.duration)]
    r = Replay(tp, surface, markers=markers, off_screen=True, window_size=(200, 150))
    try:
        assert not r.marker_actor.GetVisibility()
        r.state.seek(0.5 * tp.duration)
        r.update_scene()
        assert r.marker_actor.GetVisibility() and r.marker_cloud.n_points == 1
        r.handle_key("End")
        assert r.marker_cloud.n_points == 2
    finally:
        r.close()


# -- SceneApp on data/scene.toml -----------------------------------------------------------------

@pytest.fixture(scope="module")
def scene_app():
    app = SceneApp(load_scene_config(DATA / "scene.toml"), off_screen=True, window_size=(300, 200))
    yield app
    app.close()


def test_a_step_into_another_object_is_refused(scene_app):
    app = scene_app
    assert app.handle_key("1")
    assert app.selected_name == "nozzle"
    start = app.position()
    for _ in range(40):  # the nozzle sits above component I: moving down must stop at it
        before = app.position()
        app.handle_key("End")
        if app.last_refused:
            break
    assert app.last_refused
    np.testing.assert_array_equal(app.position(), before)
    assert "REFUSED" in app.status_actor.GetInput()
    assert before[2] < start[2]
    app.handle_key("Home")  # away: accepted
    assert not app.last_refused
    np.testing.assert_allclose(app.position(), before + [0, 0, app.config.step])
    rotation = app.scene.objects["nozzle"].rotation.copy()
    app.handle_key("Right", ctrl=True)
    assert not app.last_refused and not np.allclose(app.scene.objects["nozzle"].rotation, rotation)
    # the actor follows the pose
    np.testing.assert_allclose(np.asarray(app.mesh_actors["nozzle"].user_matrix)[:3, 3], app.position())


def test_function_keys_toggle_boxes_edges_translucency(scene_app):
    app = scene_app
    assert not app.box_actors["workpiece"].GetVisibility()
    app.handle_key("F1")
    assert app.show_boxes and all(a.GetVisibility() for a in app.box_actors.values())
    assert app.box_actors["workpiece"].mapper.dataset.n_lines > 0
    app.handle_key("F2")
    assert app.show_edges and app.mesh_actors["component_I"].prop.show_edges
    app.handle_key("F3")
    assert app.translucent and app.mesh_actors["component_I"].prop.opacity < 1
    for key in ("F1", "F2", "F3"):
        app.handle_key(key)
    assert not (app.show_boxes or app.show_edges or app.translucent)
    assert app.mesh_actors["component_I"].prop.opacity == 1.0


def test_digit_beyond_the_objects_keeps_the_selection(scene_app):
    scene_app.handle_key("2")
    scene_app.handle_key("7")
    assert scene_app.selected_name == "component_I"


# -- configuration errors name the file and the field ---------------------------------------------

@pytest.mark.parametrize("body, field", [
    ('[a]\nfile = "missing.stl"\n', "file"),
    ('[a]\nfile = "box.stl"\npos = [1, 2]\n', "pos"),
    ('[a]\nfile = "box.stl"\ncolor = "nocolour"\n', "color"),
    ('[a]\nfile = "box.stl"\ndepth = -1\n', "depth"),
    ('[a]\npos = [0, 0, 0]\n', "file"),
])
def test_bad_config_names_file_and_field(tmp_path, body, field):
    from dmdvox.io.mesh import box_mesh, write_stl

    write_stl(tmp_path / "box.stl", *box_mesh((0, 0, 0), (1, 1, 1)))
    cfg = tmp_path / "bad.toml"
    cfg.write_text(body)
    with pytest.raises(DmdvoxError, match=rf"bad\.toml.*\[a\] {field}"):
        load_scene_config(cfg)


def test_ini_config_reads_the_seed_fields(tmp_path):
    from dmdvox.io.mesh import box_mesh, write_stl

    write_stl(tmp_path / "box.stl", *box_mesh((0, 0, 0), (1, 1, 1)))
    cfg = tmp_path / "scene.ini"
    cfg.write_text("[scene]\nvoxel = 0.25\n\n[part]\nfile = box.stl\npos = 1, 2, 3\ncolor = 255, 0, 0\ndepth = 2\n")
    config = load_scene_config(cfg)
    assert config.voxel == 0.25
    (obj,) = config.objects
    assert obj.name == "part" and obj.pos == (1.0, 2.0, 3.0) and obj.color == (1.0, 0.0, 0.0) and obj.depth == 2
