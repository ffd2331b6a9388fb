"""`dmdvox scene`: the seed's interactive collision scene on :class:`dmdvox.collision.scene.Scene`.

The configuration keeps the seed's ``scene.ini`` fields (appendix D): one section per object
with ``file`` (an STL, relative to the configuration), ``pos`` (x, y, z), ``color`` and
``depth`` (how many times the object's octree is split). It is read as TOML (``.toml``) or INI
(anything else); a section named ``scene`` holds the settings (``voxel``, ``step``, ``angle``).

The keys are the seed's (appendix C): 0-9 select an object; the arrows move it in x and y,
Home/End in z; with Ctrl the same keys rotate it (Left/Right about z, Up/Down about x,
Home/End about y); a step that would make it collide is refused. F1 toggles the octree boxes,
F2 the mesh edges, F3 translucency.
"""

from __future__ import annotations

import configparser
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import DmdvoxError
from .interactive import bind_keys, key_name

DEFAULT_VOXEL_MM = 0.5
DEFAULT_STEP_MM = 1.0
DEFAULT_ANGLE_DEG = 5.0
TRANSLUCENT_OPACITY = 0.35
PALETTE = ((0.8, 0.8, 0.8), (0.9, 0.3, 0.2), (0.2, 0.5, 0.9), (0.3, 0.7, 0.3), (0.9, 0.7, 0.1))

# key -> unit translation (world axes); with Ctrl -> (rotation axis, sign)
MOVES = {"Right": (1, 0, 0), "Left": (-1, 0, 0), "Up": (0, 1, 0), "Down": (0, -1, 0), "Home": (0, 0, 1),
         "End": (0, 0, -1)}
TURNS = {"Right": ("z", 1), "Left": ("z", -1), "Up": ("x", 1), "Down": ("x", -1), "Home": ("y", 1),
         "End": ("y", -1)}


@dataclass(frozen=True)
class ObjectConfig:
    name: str
    file: Path
    pos: tuple[float, float, float]
    color: tuple[float, float, float]
    depth: int | None  # None: the finest level of the object's tree


@dataclass(frozen=True)
class SceneConfig:
    objects: tuple[ObjectConfig, ...]
    voxel: float = DEFAULT_VOXEL_MM
    step: float = DEFAULT_STEP_MM
    angle: float = DEFAULT_ANGLE_DEG


def _numbers(value, n: int, where: str) -> tuple[float, ...]:
    """A list (TOML) or a comma/space separated string (INI) of ``n`` finite numbers."""
    items = value.replace(",", " ").split() if isinstance(value, str) else value
    try:
        numbers = tuple(float(v) for v in items)
    except (TypeError, ValueError):
        numbers = ()
    if len(numbers) != n or not all(np.isfinite(numbers)):
        raise DmdvoxError(f"{where}: expected {n} numbers, got {value!r}")
    return numbers


def _color(value, where: str) -> tuple[float, float, float]:
    """An RGB triple in 0..1 (or 0..255, as colour pickers give) or a colour name."""
    if isinstance(value, str) and not any(c.isdigit() for c in value):
        import pyvista as pv

        try:
            return tuple(float(c) for c in pv.Color(value.strip()).float_rgb)
        except ValueError:
            raise DmdvoxError(f"{where}: unknown colour name {value!r}") from None
    rgb = np.array(_numbers(value, 3, where))
    if rgb.min() < 0 or rgb.max() > 255:
        raise DmdvoxError(f"{where}: colour components must be in 0..1 or 0..255, got {value!r}")
    return tuple(float(c) for c in (rgb / 255.0 if rgb.max() > 1.0 else rgb))


def _positive(value, where: str) -> float:
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = float("nan")
    if not (np.isfinite(number) and number > 0):
        raise DmdvoxError(f"{where}: expected a positive number, got {value!r}")
    return number


def load_scene_config(path) -> SceneConfig:
    """Read a scene configuration (TOML or INI); errors name the file, section and field."""
    path = Path(path)
    try:
        text = path.read_text()
    except OSError as exc:
        raise DmdvoxError(f"{path}: cannot read the scene configuration ({exc.strerror})") from None
    if path.suffix.lower() == ".toml":
        try:
            sections = tomllib.loads(text)
        except tomllib.TOMLDecodeError as exc:
            raise DmdvoxError(f"{path}: not valid TOML ({exc})") from None
    else:
        parser = configparser.ConfigParser()
        try:
            parser.read_string(text, source=str(path))
        except configparser.Error as exc:
            raise DmdvoxError(f"{path}: not a valid INI file ({exc})") from None
        sections = {name: dict(parser[name]) for name in parser.sections()}
    settings = sections.pop("scene", {})
    if not isinstance(settings, dict):
        raise DmdvoxError(f"{path}: [scene] must be a section of settings")
    objects = []
    for name, fields in sections.items():
        where = f"{path}: [{name}]"
        if not isinstance(fields, dict):
            raise DmdvoxError(f"{where}: expected a section with file, pos, color and depth")
        unknown = set(fields) - {"file", "pos", "color", "depth"}
        if unknown:
            raise DmdvoxError(f"{where}: unknown field(s) {', '.join(sorted(unknown))}")
        if "file" not in fields:
            raise DmdvoxError(f"{where} file: missing (the object's STL, relative to the configuration)")
        stl = path.parent / str(fields["file"])
        if not stl.is_file():
            raise DmdvoxError(f"{where} file: no such file {str(stl)!r}")
        depth = fields.get("depth")
        if depth is not None:
            try:
                depth = int(depth)
            except (TypeError, ValueError):
                depth = -1
            if depth < 0:
                raise DmdvoxError(f"{where} depth: expected an integer >= 0, got {fields['depth']!r}")
        pos = _numbers(fields.get("pos", (0, 0, 0)), 3, f"{where} pos")
        color = _color(fields["color"], f"{where} color") if "color" in fields else PALETTE[len(objects) % len(PALETTE)]
        objects.append(ObjectConfig(name, stl, pos, color, depth))
    if not objects:
        raise DmdvoxError(f"{path}: no objects (give one section per object with file, pos, color, depth)")
    if len(objects) > 10:
        raise DmdvoxError(f"{path}: {len(objects)} objects; keys 0-9 select at most 10")
    unknown = set(settings) - {"voxel", "step", "angle"}
    if unknown:
        raise DmdvoxError(f"{path}: [scene] unknown field(s) {', '.join(sorted(unknown))}")
    return SceneConfig(tuple(objects), **{k: _positive(v, f"{path}: [scene] {k}") for k, v in settings.items()})


def _pose_matrix(obj) -> np.ndarray:
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = obj.rotation, obj.position
    return m


def _box_edges(lo: np.ndarray, hi: np.ndarray):
    """Line segments (as a PolyData) of the edges of boxes ``lo[i]..hi[i]``."""
    import pyvista as pv

    corners = np.stack([np.where(np.array(bits, bool), hi, lo) for bits in np.ndindex(2, 2, 2)], axis=1)  # (n, 8, 3)
    edges = np.array([(a, b) for a in range(8) for b in range(a + 1, 8) if bin(a ^ b).count("1") == 1])
    n = corners.shape[0]
    ids = (8 * np.arange(n)[:, None, None] + edges[None]).reshape(-1, 2)
    lines = np.column_stack([np.full(len(ids), 2), ids]).reshape(-1)
    return pv.PolyData(corners.reshape(-1, 3), lines=lines)


def octree_boxes(obj, depth: int | None):
    """The boxes of the object's block tree (occupied nodes) at the level of ``depth`` splits
    below the root, in the object's frame. Block level is the finest drawn: deeper splits
    happen inside 8^3 blocks, which the tree does not store as nodes."""
    body = obj.body
    n_levels = int(body.level_shape.shape[0])
    level = 0 if depth is None else int(np.clip(n_levels - 1 - depth, 0, n_levels - 1))
    occ = body.occupancy[body.level_offset[level]:body.level_offset[level + 1]].reshape(body.level_shape[level])
    ijk = np.argwhere(occ > 0)
    span = 8 * 2**level * body.voxel
    corner = body.grid.origin - 0.5 * body.voxel
    lo = corner + ijk * span
    return _box_edges(lo, lo + span), level


class SceneApp:
    """The scene window: objects as posed meshes, the seed's keys, a status line."""

    KEYS = tuple("0123456789") + tuple(MOVES) + ("F1", "F2", "F3")

    def __init__(self, config: SceneConfig, off_screen: bool = False, window_size=(1280, 900)):
        import pyvista as pv

        from ..collision.scene import Scene
        from ..io.mesh import read_stl

        self.config = config
        # reach 0: moves only ask "do they overlap", not how far apart they are
        self.scene = Scene(voxel=config.voxel, reach=0.0)
        self.names = []
        for oc in config.objects:
            vertices, triangles = read_stl(oc.file)
            try:
                self.scene.add(oc.name, vertices, triangles, position=oc.pos, color=oc.color)
            except DmdvoxError as exc:
                raise DmdvoxError(f"[{oc.name}] file {oc.file}: {exc}") from None
            self.names.append(oc.name)
        self.selected = 0
        self.last_refused = False
        self.show_boxes = False
        self.show_edges = False
        self.translucent = False
        self.message = ""

        self.plotter = pv.Plotter(off_screen=off_screen, window_size=tuple(window_size))
        p = self.plotter
        p.set_background("white")
        self.mesh_actors, self.box_actors, self.box_levels = {}, {}, {}
        for oc in config.objects:
            obj = self.scene.objects[oc.name]
            v, t = obj.mesh
            faces = np.column_stack([np.full(len(t), 3, np.int64), t]).reshape(-1)
            self.mesh_actors[oc.name] = p.add_mesh(pv.PolyData(np.asarray(v, np.float64), faces), color=obj.color,
                                                   smooth_shading=True, split_sharp_edges=True)
            boxes, self.box_levels[oc.name] = octree_boxes(obj, oc.depth)
            self.box_actors[oc.name] = p.add_mesh(boxes, color=obj.color, line_width=1)
        self.status_actor = p.add_text("", position=(10, 10), font_size=11, color="black")
        p.add_text("0-9 select  arrows/Home/End move  Ctrl+keys rotate  F1 octree  F2 edges  F3 translucent",
                   position="upper_left", font_size=9, color="dimgray")
        bind_keys(p, self.KEYS, self.handle_key)
        p.add_axes()
        p.view_isometric()
        self.update_scene()

    @property
    def selected_name(self) -> str:
        return self.names[self.selected]

    def position(self, name: str | None = None) -> np.ndarray:
        return self.scene.objects[name or self.selected_name].position.copy()

    def handle_key(self, key: str, ctrl: bool = False) -> bool:
        """One key press (``ctrl``: Control held); True if the key is a scene key."""
        key = key_name(key)
        if len(key) == 1 and key.isdigit():
            if int(key) >= len(self.names):
                self.message = f"no object {key}: the scene has {len(self.names)}"
            else:
                self.selected = int(key)
                self.message = f"selected {self.selected_name}"
        elif key in MOVES:
            name = self.selected_name
            if ctrl:
                axis, sign = TURNS[key]
                done = self.scene.rotate(name, axis, sign * self.config.angle)
                what = f"rotate {sign * self.config.angle:+g} deg about {axis}"
            else:
                done = self.scene.move(name, np.array(MOVES[key], np.float64) * self.config.step)
                what = f"move {key}"
            self.last_refused = not done
            self.message = f"{name}: {what} " + ("REFUSED: it would collide" if not done else "done")
        elif key == "F1":
            self.show_boxes = not self.show_boxes
        elif key == "F2":
            self.show_edges = not self.show_edges
        elif key == "F3":
            self.translucent = not self.translucent
        else:
            return False
        self.update_scene()
        self.plotter.render()
        return True

    def status(self) -> str:
        p = self.position()
        flags = [name for name, on in (("octree", self.show_boxes), ("edges", self.show_edges),
                                       ("translucent", self.translucent)) if on]
        return (f"[{self.selected}] {self.selected_name} at ({p[0]:.2f}, {p[1]:.2f}, {p[2]:.2f})"
                f"   {self.message}" + (f"   ({', '.join(flags)})" if flags else ""))

    def update_scene(self) -> None:
        """Apply poses and toggles to the actors."""
        for name in self.names:
            pose = _pose_matrix(self.scene.objects[name])
            actor = self.mesh_actors[name]
            actor.user_matrix = pose
            actor.prop.show_edges = self.show_edges
            actor.prop.opacity = TRANSLUCENT_OPACITY if self.translucent else 1.0
            self.box_actors[name].user_matrix = pose
            self.box_actors[name].SetVisibility(self.show_boxes)
        self.status_actor.SetInput(self.status())

    def show(self) -> None:
        self.plotter.show(title="dmdvox scene")

    def close(self) -> None:
        self.plotter.close()


def run_scene(args) -> dict:
    """The `scene` command: open the scene window; returns the final poses when it is closed."""
    app = SceneApp(load_scene_config(args.config))
    app.show()
    return {name: [float(c) for c in app.position(name)] for name in app.names}
