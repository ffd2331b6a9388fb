"""`dmdvox view`: the seed's real-time deposition replay on PyVista.

The part is deposited once for the whole program; its surface carries the arrival time of
each vertex, so the part "as it stands at time t" is the set of triangles whose vertices have
all arrived by t. Triangles are sorted by that time once, and a moment is a prefix of the
sorted list: scrubbing costs a slice, not a new deposit.

The keys are the seed's (appendix F, ``main.py``): space play/pause, ``+``/``-`` faster/slower
by 1.3, Right/Left play forward/backward, Home/End and 0-9 seek (digit k goes to k/9 of the
build). :class:`ReplayState` holds that logic without a window, so it is tested directly;
:class:`Replay` applies it to the actors and works on an off-screen plotter too.

The build plate is drawn under the part, so the scene at t = 0 shows where the part will grow;
the camera frames the finished part to fill the window (the nozzle may leave the frame above
it). Translucent objects (CAD, fixtures, nozzle) are sorted by depth peeling only where the
OpenGL draws them with it: Mesa's software renderer peels them away entirely, so a probe
(:func:`depth_peeling_works`) decides.
"""

from __future__ import annotations

import functools
import math
import os
import time as _time

import numpy as np

from ..errors import DmdvoxError

if not (os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")):
    # No screen: render through EGL (an interactive window needs the X one VTK picks by default).
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

SPEED_STEP = 1.3  # the seed's '+' / '-' factor
REPLAY_WALL_SECONDS = 30.0  # at speed x1 the whole build replays in this many seconds
TIMER_MS = 33  # about 30 frames per second
COLOR_MODES = ("time", "layer", "feed", "deposit")
DEPOSIT_COLOR, TRAVEL_COLOR, PART_COLOR, PLATE_COLOR = "orangered", "steelblue", "lightsteelblue", "#a9adb4"
# the part is framed in this part of the window (x0, y0, x1, y1 as fractions from the bottom
# left): right of it the colour bar, above it the time slider, below it the status line
FREE_AREA = (0.03, 0.10, 0.84, 0.78)
FILL = 0.92  # the part spans this fraction of the free area along its tighter axis

# VTK key symbols (and the characters tests may send) -> the seed's key names
KEY_ALIASES = {" ": "space", "+": "plus", "KP_Add": "plus", "=": "plus", "-": "minus", "KP_Subtract": "minus",
               "KP_Home": "Home", "KP_End": "End", "KP_Right": "Right", "KP_Left": "Left", "KP_Up": "Up",
               "KP_Down": "Down"}


def key_name(key: str) -> str:
    """Normalise a key symbol: keypad and character forms map to the main-keyboard names."""
    key = KEY_ALIASES.get(key, key)
    return key[:1].upper() + key[1:] if key.lower() in ("right", "left", "up", "down", "home", "end") else key


def bind_keys(plotter, keys, handler) -> None:
    """Route ``keys`` to ``handler(key, ctrl)``, replacing PyVista's own bindings of them
    (its '+'/'-' change line widths and Up/Down zoom, which would fire alongside ours)."""
    iren = plotter.iren
    for key in keys:
        plotter.clear_events_for_key(key)
        plotter.add_key_event(key, lambda key=key: handler(key, bool(iren.interactor.GetControlKey())))


class ReplayState:
    """Time, play/pause, speed and direction of a replay, driven by the seed's keys.

    ``speed`` is seconds of build per second of wall time; ``base_speed`` (x1) replays the
    whole build in :data:`REPLAY_WALL_SECONDS`.
    """

    KEYS = ("space", "plus", "minus", "Right", "Left", "Home", "End") + tuple("0123456789")

    def __init__(self, duration: float, base_speed: float | None = None, running: bool = False):
        duration = float(duration)
        if not np.isfinite(duration) or duration < 0:
            raise DmdvoxError(f"replay duration must be a finite number of seconds >= 0, got {duration}")
        self.duration = duration
        self.base_speed = float(base_speed) if base_speed is not None else max(duration, 1e-9) / REPLAY_WALL_SECONDS
        self.speed = self.base_speed
        self.direction = 1
        self.running = bool(running)
        self.time = 0.0

    @property
    def speed_factor(self) -> float:
        return self.speed / self.base_speed

    def seek(self, time_s: float) -> None:
        self.time = float(min(self.duration, max(0.0, time_s)))

    def key(self, key: str) -> bool:
        """Apply one key press; False when the key is not a replay key."""
        key = key_name(key)
        if key == "space":
            self.running = not self.running
        elif key == "plus":
            self.speed *= SPEED_STEP
        elif key == "minus":
            self.speed /= SPEED_STEP
        elif key == "Right":
            self.direction = 1
        elif key == "Left":
            self.direction = -1
        elif key == "Home":
            self.seek(0.0)
        elif key == "End":
            self.seek(self.duration)
        elif len(key) == 1 and key.isdigit():
            self.seek(int(key) / 9.0 * self.duration)
        else:
            return False
        return True

    def advance(self, dt_wall: float) -> float:
        """Move the time by ``dt_wall`` seconds of wall time when running; returns the time."""
        if self.running:
            self.seek(self.time + self.direction * self.speed * float(dt_wall))
        return self.time

    def status(self) -> str:
        state = "playing" if self.running else "paused"
        arrow = "forward" if self.direction > 0 else "backward"
        return f"t = {self.time:7.1f} / {self.duration:.1f} s   {state} {arrow}   speed x{self.speed_factor:.2f}"


@functools.lru_cache(maxsize=None)
def depth_peeling_works() -> bool:
    """Whether this OpenGL shows a translucent surface when depth peeling is on: a blue
    half-transparent square is drawn with peeling and looked for. Mesa's llvmpipe (software
    OpenGL, headless machines and some remote desktops) peels it away entirely."""
    import pyvista as pv

    plotter = pv.Plotter(off_screen=True, window_size=(64, 64))
    try:
        plotter.set_background("white")
        plotter.add_mesh(pv.Plane(i_size=2.0, j_size=2.0), color="blue", opacity=0.5)
        plotter.enable_depth_peeling()
        plotter.view_xy()
        image = plotter.screenshot(return_img=True).astype(int)
    finally:
        plotter.close()
    return bool(np.mean(image[..., 2] - image[..., 0] > 40) > 0.1)


def _corner_text(plotter, text: str, x: float, y: float):
    """A text right-aligned at ``(x, y)`` of the window (fractions from the bottom left), its
    bottom there: a colour bar's title that cannot run off the window's edge, whatever its size."""
    import vtk

    actor = vtk.vtkTextActor()
    actor.SetInput(text)
    prop = actor.GetTextProperty()
    prop.SetFontSize(16)
    prop.SetColor(0.0, 0.0, 0.0)
    prop.SetJustificationToRight()
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.GetPositionCoordinate().SetValue(x, y)
    plotter.renderer.AddViewProp(actor)
    return actor


def plate_box(part_lo, part_hi, top: float) -> tuple[np.ndarray, np.ndarray]:
    """The plate drawn under a part: its footprint with a margin of a tenth of its larger side,
    a twenty-fifth of that side thick, its top at ``top``."""
    part_lo, part_hi = np.asarray(part_lo, float), np.asarray(part_hi, float)
    side = max(float(np.max(part_hi[:2] - part_lo[:2])), 1.0)
    margin, thickness = 0.1 * side, max(0.04 * side, 0.5)
    lo = np.array([part_lo[0] - margin, part_lo[1] - margin, top - thickness])
    hi = np.array([part_hi[0] + margin, part_hi[1] + margin, top])
    return lo, hi


def outline_points(vertices: np.ndarray, most: int = 200_000) -> np.ndarray:
    """The points of a mesh that can bound its picture from any side: its convex hull's vertices
    (of an even subsample of at most ``most`` vertices)."""
    from scipy.spatial import ConvexHull, QhullError

    points = np.asarray(vertices, float).reshape(-1, 3)
    points = points[:: max(1, math.ceil(len(points) / most))]
    try:
        return points[ConvexHull(points).vertices]
    except (QhullError, ValueError):  # flat or too few points: all of them
        return points


def fit_camera(plotter, points, free=FREE_AREA, fill: float = FILL) -> None:
    """An isometric view in which ``points`` fill ``fill`` of the ``free`` part of the window
    along its tighter axis, centred there. The perspective is kept: the camera is panned and
    dollied (a few rounds, as near points grow faster than far ones)."""
    renderer = plotter.renderer
    points = np.asarray(points, float).reshape(-1, 3)
    lo, hi = points.min(axis=0), points.max(axis=0)
    plotter.view_isometric()
    plotter.reset_camera(bounds=(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]))
    camera = renderer.GetActiveCamera()
    width, height = plotter.window_size
    x0, y0, x1, y1 = free[0] * width, free[1] * height, free[2] * width, free[3] * height
    homogeneous = np.column_stack([points, np.ones(len(points))])

    def projected() -> np.ndarray:
        # world -> normalised device coordinates -> pixels from the bottom left
        matrix = camera.GetCompositeProjectionTransformMatrix(width / height, -1.0, 1.0)
        m = np.array([[matrix.GetElement(i, j) for j in range(4)] for i in range(4)])
        clip = homogeneous @ m.T
        ndc = clip[:, :2] / clip[:, 3:4]
        return (ndc + 1.0) / 2.0 * [width, height]

    for _ in range(6):
        points = projected()
        (u0, v0), (u1, v1) = points.min(axis=0), points.max(axis=0)
        focal, position = np.array(camera.GetFocalPoint()), np.array(camera.GetPosition())
        distance = float(np.linalg.norm(focal - position))
        per_px = 2 * distance * math.tan(math.radians(camera.GetViewAngle()) / 2) / height
        forward = (focal - position) / distance
        up = np.array(camera.GetViewUp())
        right = np.cross(forward, up)
        right /= np.linalg.norm(right)
        up = np.cross(right, forward)
        shift = ((u0 + u1) / 2 - (x0 + x1) / 2) * per_px * right + ((v0 + v1) / 2 - (y0 + y1) / 2) * per_px * up
        camera.SetFocalPoint(*(focal + shift))
        camera.SetPosition(*(position + shift))
        camera.Dolly(fill * min((x1 - x0) / max(u1 - u0, 1e-9), (y1 - y0) / max(v1 - v0, 1e-9)))
        renderer.ResetCameraClippingRange()


def _lines(pv, points_a: np.ndarray, points_b: np.ndarray):
    n = points_a.shape[0]
    points = np.empty((2 * n, 3))
    points[0::2], points[1::2] = points_a, points_b
    cells = np.column_stack([np.full(n, 2), 2 * np.arange(n), 2 * np.arange(n) + 1]).reshape(-1)
    return pv.PolyData(points, lines=cells)


def _triangles(pv, vertices: np.ndarray, triangles: np.ndarray):
    faces = np.column_stack([np.full(len(triangles), 3, np.int64), triangles]).reshape(-1)
    return pv.PolyData(np.asarray(vertices, np.float64), faces)


def default_nozzle(bead_width: float):
    """A cone standing on its tip, a few bead widths tall (the seed's red arrow head)."""
    from ..collision.bodies import Cone

    return Cone(tip=0.4 * bead_width, top=4.0 * bead_width, length=6.0 * bead_width).mesh(48)


class Replay:
    """The replay scene: the growing deposit, the path so far, the nozzle, a CAD overlay,
    collision markers, a time slider and the seed's keys.

    ``surface`` is ``(vertices, triangles, arrival)`` of the whole part (per-vertex arrival s);
    ``cad`` and each of ``fixtures`` a ``(vertices, triangles)`` mesh in machine coordinates;
    ``nozzle`` a ``(vertices, triangles)`` mesh with its tip at the origin, drawn at the tool
    point raised by ``standoff``; ``markers`` ``(x, y, z, time_s)`` rows, each shown from its time;
    ``plate`` the Z of the build plate's top (default: the bottom of the part).
    """

    def __init__(self, tp, surface, *, color: str = "time", cad=None, fixtures=(), nozzle=None,
                 standoff: float = 0.0, markers=(), off_screen: bool = False, window_size=(1280, 900),
                 bead_width: float = 2.5, plate: float | None = None):
        import pyvista as pv

        from ..toolpath.geometry import linearized

        if color not in COLOR_MODES:
            raise DmdvoxError(f"--color: unknown mode '{color}'; choose one of {', '.join(COLOR_MODES)}")
        # chords of the arcs: the nozzle and the path lines are interpolated linearly per row
        self.tp = linearized(tp)
        self.state = ReplayState(tp.duration)
        self.color = color
        self.standoff = float(standoff)

        vertices, triangles, arrival = surface
        vertices = np.asarray(vertices, np.float64).reshape(-1, 3)
        triangles = np.asarray(triangles, np.int64).reshape(-1, 3)
        arrival = np.asarray(arrival, np.float64).reshape(-1)
        tri_time = arrival[triangles].max(axis=1) if len(triangles) else np.zeros(0)
        order = np.argsort(tri_time, kind="stable")
        self.triangle_time = tri_time[order]
        self._faces = np.column_stack([np.full(len(order), 3, np.int64), triangles[order]]).reshape(-1)
        self.part = pv.PolyData(vertices, self._faces.copy())
        self.n_triangles = len(order)

        markers = np.asarray(markers, np.float64).reshape(-1, 4)
        self.markers = markers[np.argsort(markers[:, 3], kind="stable")]

        self.plotter = pv.Plotter(off_screen=off_screen, window_size=tuple(window_size))
        p = self.plotter
        p.set_background("white")
        part_style = dict(smooth_shading=True, split_sharp_edges=True, show_scalar_bar=True)
        scalars = self._vertex_scalars(arrival)
        if scalars is None:
            self.part_actor = p.add_mesh(self.part, color=PART_COLOR, **part_style)
        else:
            from .pictures import scalar_title

            name, values, cmap = scalars
            self.part.point_data[name] = values
            finite = values[np.isfinite(values)]
            clim = (float(finite.min()), float(max(finite.max(), finite.min() + 1e-9))) if finite.size else (0, 1)
            # upright at the right edge (the bottom holds the status line), titled in words
            bar = dict(title=name, vertical=True, position_x=0.88, position_y=0.12, width=0.05, height=0.64,
                       color="black", fmt="%.4g")
            self.part_actor = p.add_mesh(self.part, scalars=name, cmap=cmap, clim=clim, scalar_bar_args=bar,
                                         **part_style)
            p.scalar_bars[name].SetTitle("")  # VTK centres it on the bar, off the window's edge
            self.bar_title = _corner_text(p, scalar_title(name).replace("\n", " "), 0.99, 0.80)

        # the plate under the part: at t = 0 the scene shows where the part will stand
        if len(triangles):
            part_lo, part_hi = vertices.min(axis=0), vertices.max(axis=0)
            self._outline = outline_points(vertices[np.unique(triangles)])
        else:
            part_lo, part_hi = tp.deposit_bbox() if tp.deposit.any() else (np.zeros(3), np.ones(3))
            self._outline = np.array(np.meshgrid(*zip(part_lo, part_hi))).reshape(3, -1).T
        self.part_bounds = (np.asarray(part_lo, float), np.asarray(part_hi, float))
        self.plate_bounds = plate_box(part_lo, part_hi, float(part_lo[2]) if plate is None else float(plate))
        self.plate_actor = p.add_mesh(pv.Box(bounds=np.column_stack(self.plate_bounds).ravel()), color=PLATE_COLOR,
                                      smooth_shading=False)

        ltp = self.tp
        self._path_all = _lines(pv, ltp.start, ltp.end)
        self._path_all.cell_data["deposit"] = ltp.deposit.astype(np.float64)
        self.path = self._path_all.copy()
        self.path_actor = p.add_mesh(self.path, scalars="deposit", cmap=[TRAVEL_COLOR, DEPOSIT_COLOR], clim=(0, 1),
                                     line_width=2 if color == "deposit" else 1, show_scalar_bar=False)

        nv, nt = default_nozzle(bead_width) if nozzle is None else nozzle
        self.nozzle_actor = p.add_mesh(_triangles(pv, nv, nt), color="red", opacity=0.8, smooth_shading=True)
        # a table-table machine turns the part: its machine X, Y, Z axes, turned about the
        # workpiece origin, show the table's rotation
        self.machine_axis_actors = []
        if "machine" in tp.meta and tp.meta["machine"].get("kind") in ("trt-ac", "trt-bc"):
            rod = 0.3 * float(np.max(np.asarray(part_hi) - np.asarray(part_lo)))
            for colour in ("red", "green", "blue"):
                line = pv.Line((0.0, 0.0, 0.0), (0.0, 0.0, rod))
                self.machine_axis_actors.append(p.add_mesh(line, color=colour, line_width=4))

        self.fixture_actors = [p.add_mesh(_triangles(pv, fv, ft), color="tan", opacity=0.6) for fv, ft in fixtures]
        self.cad_actor = p.add_mesh(_triangles(pv, *cad), color="lightgray", opacity=0.25) if cad is not None else None
        # translucent overlays (and the nozzle) sort correctly with depth peeling, where the
        # OpenGL draws them with it at all; elsewhere they are blended unsorted, but seen
        self.depth_peeling = depth_peeling_works()
        if self.depth_peeling:
            p.enable_depth_peeling()

        self.marker_cloud = pv.PolyData(self.markers[:, :3].copy()) if len(self.markers) else None
        self.marker_actor = None
        if self.marker_cloud is not None:
            self.marker_actor = p.add_mesh(self.marker_cloud, color="magenta", point_size=14,
                                           render_points_as_spheres=True)

        self.status_actor = p.add_text("", position=(10, 10), font_size=11, color="black")
        p.add_text("space play/pause  +/- speed  Right/Left direction  Home/End 0-9 seek", position="upper_left",
                   font_size=9, color="dimgray")
        # add_slider_widget calls back with the initial value before it returns the widget
        self.slider = None
        self.slider = p.add_slider_widget(self._on_slider, rng=(0.0, max(self.state.duration, 1e-9)), value=0.0,
                                          title="time (s)", pointa=(0.25, 0.92), pointb=(0.75, 0.92),
                                          style="modern", interaction_event="always", fmt="%.1f")
        bind_keys(p, ReplayState.KEYS, lambda key, ctrl: self.handle_key(key))
        p.add_axes()
        self.fit_view()
        self.update_scene()

    def fit_view(self) -> None:
        """Frame the finished part to fill the window. Once: the camera must not follow the
        visible subset, or the view would jump at every seek."""
        fit_camera(self.plotter, self._outline)
        self.plotter.camera_set = True

    def _vertex_scalars(self, arrival: np.ndarray):
        """(name, per-vertex values, colormap) for the colour mode; None draws one colour."""
        if self.color == "deposit":
            return None
        if self.color == "time":
            return "arrival_s", arrival, "viridis"
        # the row being deposited when the vertex's material arrived
        ends = self.tp.t_end
        row = np.clip(np.searchsorted(ends, arrival, side="left"), 0, max(len(ends) - 1, 0))
        if self.color == "layer":
            return "layer", self.tp.layer[row].astype(np.float64), "turbo"
        return "feed_mm_s", self.tp.feed[row].astype(np.float64), "plasma"

    def tool_point(self, time_s: float | None = None) -> np.ndarray:
        """The path point at ``time_s`` (default: the replay's time), linear within a row."""
        from .render import tool_pose

        return tool_pose(self.tp, self.state.time if time_s is None else float(time_s))[0]

    def tool_axis(self, time_s: float | None = None) -> np.ndarray:
        """The unit tool axis at ``time_s`` (default: the replay's time): its row's."""
        from .render import tool_pose

        return tool_pose(self.tp, self.state.time if time_s is None else float(time_s))[1]

    def visible_triangles(self) -> int:
        return int(np.searchsorted(self.triangle_time, self.state.time, side="right"))

    def visible_markers(self) -> int:
        return int(np.searchsorted(self.markers[:, 3], self.state.time, side="right"))

    def update_scene(self) -> None:
        """Apply the state's time to the actors (part, path, nozzle, markers, slider, status)."""
        t = self.state.time
        k = self.visible_triangles()
        self.part.faces = self._faces[:4 * k]
        self.part_actor.SetVisibility(k > 0)

        point = self.tool_point()
        # rows started by t; the one in progress is drawn up to the tool point
        rows = int(np.searchsorted(self.tp.t_start, t, side="right"))
        if rows:
            self.path.points = self._path_all.points[:2 * rows].copy()
            self.path.points[2 * rows - 1] = point
            self.path.lines = self._path_all.lines[:3 * rows]
            self.path.cell_data["deposit"] = self._path_all.cell_data["deposit"][:rows]
        self.path_actor.SetVisibility(rows > 0)

        from .render import machine_axes, nozzle_matrix, tool_pose

        _, axis, rotary = tool_pose(self.tp, t)
        if axis[2] == 1.0:
            # vertical: a translation (the actor's position) as on a 3-axis machine
            self.nozzle_actor.user_matrix = np.eye(4)
            self.nozzle_actor.position = tuple(point + np.array([0.0, 0.0, self.standoff]))
        else:
            self.nozzle_actor.position = (0.0, 0.0, 0.0)
            self.nozzle_actor.user_matrix = nozzle_matrix(point, axis, self.standoff)
        if self.machine_axis_actors:
            directions = machine_axes(self.tp, rotary)
            for actor, direction in zip(self.machine_axis_actors, directions):
                actor.user_matrix = nozzle_matrix(np.zeros(3), direction, 0.0)

        if self.marker_actor is not None:
            m = self.visible_markers()
            if m:
                self.marker_cloud.points = self.markers[:m, :3].copy()
            self.marker_actor.SetVisibility(m > 0)

        if self.slider is not None:
            self.slider.GetRepresentation().SetValue(t)
        hits = f"   collisions {self.visible_markers()}/{len(self.markers)}" if len(self.markers) else ""
        pose = ""
        if "machine" in self.tp.meta:
            tilt = float(np.degrees(np.arccos(np.clip(axis[2], -1.0, 1.0))))
            pose = f"   tilt {tilt:.1f} deg  A {rotary[0]:.1f}  B {rotary[1]:.1f}  C {rotary[2]:.1f}"
        self.status_actor.SetInput(self.state.status() + hits + pose)

    def handle_key(self, key: str) -> bool:
        """A key press as from the window; True (and the scene updated) if it is a replay key."""
        if not self.state.key(key):
            return False
        self.update_scene()
        self.plotter.render()
        return True

    def _on_slider(self, value: float) -> None:
        self.state.seek(value)
        self.update_scene()

    def _on_timer(self, _step) -> None:
        now = _time.perf_counter()
        dt, self._last_tick = now - self._last_tick, now
        if self.state.running:
            self.state.advance(dt)
            self.update_scene()
            self.plotter.render()

    def show(self) -> None:
        """Open the window and animate until it is closed."""
        self._last_tick = _time.perf_counter()
        # max_steps bounds the timer's life: a week of frames
        self.plotter.add_timer_event(max_steps=7 * 24 * 3600 * 1000 // TIMER_MS, duration=TIMER_MS,
                                     callback=self._on_timer)
        self.plotter.show(title="dmdvox view")

    def close(self) -> None:
        self.plotter.close()


def collision_markers(tp, part_grid, nozzle, fixtures: list, voxel: float) -> np.ndarray:
    """``(x, y, z, time_s)`` of the nozzle's collisions along ``tp`` (the collide engine's check;
    ``nozzle`` its :class:`~dmdvox.collision.run.NozzleSettings`)."""
    from ..collision.run import collide_part

    check, _ = collide_part(tp, part_grid, nozzle, fixtures, voxel)
    return np.array([[*c["position_mm"], c["time_s"]] for c in check.collisions], np.float64).reshape(-1, 4)


def build_replay(plan, *, voxel: float | None = None, color: str = "time", cad_path=None, nozzle_spec=None,
                 fixtures=(), standoff: float | None = None, max_memory: int | None = None,
                 off_screen: bool = False, plate: float | None = None, window_size=(1280, 900)) -> Replay:
    """Deposit the whole program as planned and set up its :class:`Replay` (collisions when a
    nozzle is given)."""
    from ..collision.bodies import load_fixtures, nozzle_mesh
    from ..collision.run import NozzleSettings
    from ..defaults import STANDOFF_MM
    from ..deposit.engine import deposit_beads
    from ..grid.surface import surface_arrival, surface_mesh
    from ..io.mesh import read_stl

    if fixtures and not nozzle_spec:
        raise DmdvoxError("--fixture needs --nozzle: collisions are those of the nozzle with the fixtures")
    tp, bead = plan.toolpath, plan.profile
    voxel = plan.resolve_voxel(voxel)
    if tp.deposit.any():
        grid = deposit_beads(plan.lay(voxel, max_memory=max_memory).beads, voxel, max_memory=max_memory)[0]
        vertices, triangles = surface_mesh(grid)
        surface = (vertices, triangles, surface_arrival(grid, vertices))
    else:
        grid, surface = None, (np.zeros((0, 3)), np.zeros((0, 3), np.int64), np.zeros(0))
    nozzle, markers = None, np.zeros((0, 4))
    loaded = load_fixtures(fixtures)
    if nozzle_spec:
        standoff = STANDOFF_MM if standoff is None else float(standoff)
        nozzle = nozzle_mesh(nozzle_spec)
        markers = collision_markers(tp, grid, NozzleSettings(nozzle_spec, tuple(fixtures), standoff=standoff), loaded,
                                    voxel)
    cad = read_stl(cad_path) if cad_path is not None else None
    fixture_meshes = [(f.vertices, f.triangles) for f in loaded]
    return Replay(tp, surface, color=color, cad=cad, fixtures=fixture_meshes, nozzle=nozzle,
                  standoff=standoff or 0.0, markers=markers, off_screen=off_screen, bead_width=bead.width,
                  plate=plate, window_size=window_size)
