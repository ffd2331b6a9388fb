"""`dmdvox view` and `dmdvox scene` handlers, driven headless: keys sent, state checked."""

import numpy as np
import pytest

from dmdvox.errors import DmdvoxError
from dmdvox.process.profiles import BeadProfile
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
    from dmdvox.deposit.simulate import fixed_plan
    from dmdvox.toolpath import read_gcode

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    plan = fixed_plan(tp, BeadProfile("rect", 2.5, tp.layer_step))
    r = build_replay(plan, off_screen=True)
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


# -- the demo with its CAD, clamp and nozzle: translucency, framing, the plate ------------------

@pytest.fixture(scope="module")
def full_replay():
    from dmdvox.deposit.simulate import fixed_plan
    from dmdvox.toolpath import read_gcode

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    plan = fixed_plan(tp, BeadProfile("rect", 2.5, tp.layer_step))
    r = build_replay(plan, off_screen=True, cad_path=DATA / "demo_block.stl",
                     nozzle_spec="cone:tip=4,top=20,length=25", fixtures=[str(DATA / "demo_clamp.stl")],
                     window_size=(480, 360))
    yield r
    r.close()


def _shot(replay) -> np.ndarray:
    replay.plotter.render()
    return replay.plotter.screenshot(return_img=True).astype(int)


def test_depth_peeling_only_where_it_draws_translucency():
    """The probe's answer is what this OpenGL does: with peeling on as it says, a translucent
    square is seen."""
    import pyvista as pv

    from dmdvox.view.interactive import depth_peeling_works

    plotter = pv.Plotter(off_screen=True, window_size=(64, 64))
    try:
        plotter.set_background("white")
        plotter.add_mesh(pv.Plane(i_size=2.0, j_size=2.0), color="blue", opacity=0.5)
        if depth_peeling_works():
            plotter.enable_depth_peeling()
        plotter.view_xy()
        image = plotter.screenshot(return_img=True).astype(int)
    finally:
        plotter.close()
    assert np.mean(image[..., 2] - image[..., 0] > 40) > 0.1


def test_translucent_cad_fixture_and_nozzle_stay_visible(full_replay):
    """Hiding each translucent object changes the picture: it was drawn (under software OpenGL,
    depth peeling used to erase all three)."""
    from dmdvox.view.interactive import depth_peeling_works

    r = full_replay
    assert r.depth_peeling == depth_peeling_works()
    assert bool(r.plotter.renderer.GetUseDepthPeeling()) == r.depth_peeling
    r.handle_key("5")
    shown = _shot(r)
    for actor in (r.cad_actor, *r.fixture_actors, r.nozzle_actor):
        actor.SetVisibility(False)
        hidden = _shot(r)
        actor.SetVisibility(True)
        assert np.count_nonzero(np.abs(shown - hidden).max(axis=2) > 20) > 300


def test_the_part_fills_the_window(full_replay):
    """The finished part alone (everything else hidden) spans nearly all the free area, centred."""
    from dmdvox.view.interactive import FILL, FREE_AREA

    r = full_replay
    r.handle_key("End")
    others = [r.cad_actor, *r.fixture_actors, r.nozzle_actor, r.path_actor, r.marker_actor, r.plate_actor]
    for actor in others:
        actor.SetVisibility(False)
    r.plotter.hide_axes()  # its arrows are coloured too
    try:
        image = _shot(r)
    finally:
        for actor in others:
            actor.SetVisibility(True)
        r.plotter.show_axes()
    height, width = image.shape[:2]
    x0, y0, x1, y1 = FREE_AREA
    # the part: anything not white in the free area (the colour bar is right of it, the time
    # slider above, the status line below); its shaded sides are too dark to tell by colour
    drawn = (image < 245).any(axis=2)
    drawn[:, int(x1 * width):] = False
    drawn[:int((1 - y1) * height)] = False
    drawn[int((1 - y0) * height):] = False
    rows, cols = np.nonzero(drawn)
    free_w, free_h = (x1 - x0) * width, (y1 - y0) * height
    span = max((cols.max() - cols.min() + 1) / free_w, (rows.max() - rows.min() + 1) / free_h)
    assert span == pytest.approx(FILL, abs=0.03)  # the old framing left the part a fifth of the window
    # centred in the free area (image rows count from the top)
    assert (cols.min() + cols.max()) / 2 == pytest.approx((x0 + x1) / 2 * width, abs=0.03 * width)
    assert (rows.min() + rows.max()) / 2 == pytest.approx((1 - (y0 + y1) / 2) * height, abs=0.03 * height)


def test_time_zero_shows_the_plate(full_replay):
    """At t = 0 nothing is deposited, and the plate stands where the part will: its top at the
    part's bottom, its footprint the part's with a tenth of its larger side around."""
    r = full_replay
    r.handle_key("Home")
    assert not r.part_actor.GetVisibility() and r.plate_actor.GetVisibility()
    (lo, hi), (plo, phi) = r.part_bounds, r.plate_bounds
    margin = 0.1 * max(hi[0] - lo[0], hi[1] - lo[1])
    np.testing.assert_allclose(plo[:2], lo[:2] - margin)
    np.testing.assert_allclose(phi[:2], hi[:2] + margin)
    assert phi[2] == lo[2] and plo[2] < phi[2]
    assert lo[2] == pytest.approx(0.0, abs=0.2)  # the demo's first layer stands on Z = 0
    with_plate = _shot(r)
    r.plate_actor.SetVisibility(False)
    without = _shot(r)
    r.plate_actor.SetVisibility(True)
    # the plate covers a good part of the window
    assert np.mean(np.abs(with_plate - without).max(axis=2) > 20) > 0.15


def test_plate_at_a_given_height():
    from dmdvox.toolpath import read_gcode
    from dmdvox.view.interactive import Replay

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    surface = (np.zeros((0, 3)), np.zeros((0, 3), np.int64), np.zeros(0))
    r = Replay(tp, surface, off_screen=True, window_size=(200, 150), plate=-3.0)
    try:
        # no surface: the deposit path's box stands in for the part
        np.testing.assert_allclose(r.part_bounds[0], tp.deposit_bbox()[0])
        assert r.plate_bounds[1][2] == -3.0
    finally:
        r.close()


@pytest.mark.parametrize("color, title", [("time", "deposition time (s)"), ("layer", "layer number (0 = lowest)"),
                                          ("feed", "feed (mm/s)")])
def test_colour_bar_titled_in_words_with_the_unit(color, title):
    """Each colouring's bar says what it shows and in what unit (VTK's own title, the array
    name, is blanked)."""
    from dmdvox.toolpath import read_gcode
    from dmdvox.view.interactive import Replay

    tp = read_gcode(DATA / "demo_block.gcode", dialect="auto")
    # one triangle per deposit row's end, so each colouring has values
    ends = np.flatnonzero(tp.deposit)[:3]
    vertices = np.array([[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [0.0, 10.0, 0.0]])
    surface = (vertices, np.array([[0, 1, 2]]), tp.t_end[ends])
    r = Replay(tp, surface, color=color, off_screen=True, window_size=(200, 150))
    try:
        assert r.bar_title.GetInput() == title
        assert [bar.GetTitle() for bar in r.plotter.scalar_bars.values()] == [""]
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
