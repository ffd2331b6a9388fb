"""The data of the report's embedded 3-D view: meshes, toolpath, collisions, colourings, layers
and G-code lines, packed small.

Vertex positions are quantised to 16 bits over the scene's bounding box (0.5 µm steps on a
30 mm part, 15 µm on a 1 m one: far below a voxel), indices are 32-bit, per-vertex scalars
float32, all base64 in one JSON object the page's script reads. The deposit surface is
decimated to a triangle budget so that a report stays a few MB whatever the voxel size; its
scalars follow the decimated vertices from the nearest full-resolution vertex, so the time
slider cuts the decimated mesh where the full one would be cut.

Colourings are data: the payload's ``fields`` list names each per-vertex scalar with its words,
unit, colour map and range (:class:`ScalarField`), and each mesh carries the values of the
fields it has, so a new colouring needs no change to ``viewer.js``. Values known per path row
(layer, feed, bead area, ...) reach the surface through its arrival times: a vertex takes the
value of the deposit row under way when its material arrived (:func:`row_values_on_vertices`).

The G-code text shown during the replay is that of the deposit rows' lines, read back from the
source file: at most :data:`MAX_LINE_ROWS` rows (every k-th beyond), each line cut to
:data:`MAX_LINE_CHARS` characters, identical lines stored once, and at most
:data:`MAX_LINE_TEXT_CHARS` characters of distinct text in all (later lines show their number
only). That bounds the text to about 1 MB and the row table to 1.2 MB whatever the program.
"""

from __future__ import annotations

import base64
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

MAX_SURFACE_TRIANGLES = 200_000
MAX_PATH_SEGMENTS = 400_000
COLORMAP_SAMPLES = 16
MAX_LINE_ROWS = 100_000
MAX_LINE_CHARS = 120
MAX_LINE_TEXT_CHARS = 1_000_000
LINE_TRAVEL = -1  # row text index: a travel row (its text is not carried)
LINE_NO_TEXT = -2  # row text index: a deposit row whose text is beyond the cap or unreadable


@dataclass(frozen=True)
class ScalarField:
    """A colouring of the 3-D view: what a per-vertex scalar is, in words, with its unit.

    ``name`` is the key of the values in the meshes' ``scalars`` (with the unit in it, as
    ``bead_area_mm2``); the legend reads ``label (unit)`` over the colour bar and ``note``
    under it. ``range`` fixes the colour limits; without it they are the values' finite
    min..max, or ±max|value| when ``symmetric`` (signed quantities). ``integer`` puts the
    legend's ticks on whole numbers; ``time`` marks the build-time field itself (the cut's cap
    takes the slider's colour)."""

    name: str
    label: str
    unit: str = ""
    colormap: str = "viridis"
    range: tuple[float, float] | None = None
    symmetric: bool = False
    integer: bool = False
    note: str = ""
    time: bool = False

    @property
    def title(self) -> str:
        return f"{self.label} ({self.unit})" if self.unit else self.label


_THROUGH_TIME = "of the path segment that laid each point"
ARRIVAL = ScalarField("arrival_s", "deposition time", "s", "viridis", time=True)
DEVIATION = ScalarField("deviation_mm", "deviation from CAD", "mm", "coolwarm", symmetric=True,
                        note="+ = excess material, − = missing")
# a count, so no unit: the legend says so and where the count starts
LAYER = ScalarField("layer", "layer number", "", "turbo", integer=True,
                    note=_THROUGH_TIME + "; 0 = the lowest layer, a count (no unit)")
FEED = ScalarField("feed_mm_s", "feed", "mm/s", "plasma", note=_THROUGH_TIME)
BEAD_AREA = ScalarField("bead_area_mm2", "bead cross-section area", "mm²", "cividis", note=_THROUGH_TIME)
# Beads from the material: a row's cross-section changes along it (speed ramps), so these are the
# values of the bead piece that laid each point (see element_values_on_vertices)
_THROUGH_PIECE = "of the bead piece that laid each point"
MATERIAL_AREA = ScalarField("bead_area_mm2", "bead cross-section area", "mm²", "cividis", note=_THROUGH_PIECE)
BEAD_HEIGHT = ScalarField("bead_height_mm", "bead height", "mm", "magma", note=_THROUGH_PIECE)
# programmed top minus built top (the flow model)
DRIFT = ScalarField("drift_mm", "drift from the program", "mm", "coolwarm", symmetric=True,
                    note="+ = part below the program, − = above")
# the heat model (report --thermal)
PEAK_TEMPERATURE = ScalarField("peak_temperature_C", "peak temperature", "°C", "inferno",
                               note="of the part's thermal cell nearest each point")
COOLING_RATE = ScalarField("cooling_rate_C_s", "cooling rate at solidification", "°C/s", "plasma",
                           note="of the part's thermal cell nearest each point; none where never molten")


@dataclass(frozen=True, eq=False)
class SceneMesh:
    """One mesh of the view; ``scalars`` maps a field name (e.g. ``arrival_s``) to one value per vertex.

    ``timed`` meshes are cut by the time slider at their ``arrival_s`` scalar; a ``capped`` one
    (a closed solid's outward surface) shows its inside, where a cut opens it, as a solid cap;
    a ``solid`` one keeps its colour whatever the view is coloured by; a ``clipped`` one is cut
    by the Z clip (the part and what is compared with it, not the machine around it)."""

    name: str
    vertices: np.ndarray
    triangles: np.ndarray
    color: tuple[float, float, float]
    opacity: float = 1.0
    scalars: dict = field(default_factory=dict)
    timed: bool = False
    capped: bool = False
    solid: bool = False
    clipped: bool = False


def _b64(array: np.ndarray) -> str:
    return base64.b64encode(np.ascontiguousarray(array).tobytes()).decode("ascii")


def vertex_normals(vertices: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """Area-weighted unit vertex normals as int8 (-127..127): smooth shading for 3 bytes a vertex."""
    corners = vertices[triangles]
    face = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(vertices, dtype=np.float64)
    for k in range(3):
        np.add.at(normals, triangles[:, k], face)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
    return np.rint(normals * 127.0).astype(np.int8)


def colormap(name: str) -> list[list[float]]:
    """``COLORMAP_SAMPLES`` RGB samples of a matplotlib colour map, for the page's shader."""
    from matplotlib import colormaps

    rgba = colormaps[name](np.linspace(0.0, 1.0, COLORMAP_SAMPLES))
    return np.round(rgba[:, :3], 4).tolist()


def path_lines(tp) -> dict:
    """The toolpath as line segments (arcs as chords) with their start and end times and layer."""
    from ..toolpath.geometry import linearized

    lin = linearized(tp)
    keep = np.flatnonzero(np.linalg.norm(lin.end - lin.start, axis=1) > 0)
    if keep.shape[0] > MAX_PATH_SEGMENTS:
        # Every k-th segment keeps the path's look and its timing; the exact path is in the G-code.
        keep = keep[:: int(np.ceil(keep.shape[0] / MAX_PATH_SEGMENTS))]
    points = np.stack([lin.start[keep], lin.end[keep]], 1).reshape(-1, 3)
    times = np.stack([lin.t_start[keep], lin.t_end[keep]], 1).reshape(-1)
    return {"points": points, "times": times, "deposit": lin.deposit[keep].astype(np.uint8),
            "layer": np.minimum(lin.layer[keep], 65535).astype("<u2")}


def deposit_rows_at(tp, times: np.ndarray) -> np.ndarray:
    """Index of the deposit row under way at each of ``times`` (s): the first deposit row that
    ends at or after the time, so a time on a boundary belongs to the row that just ended.
    Times before the first or after the last deposit row take that row; -1 when the program
    deposits nothing."""
    rows = np.flatnonzero(tp.deposit)
    times = np.asarray(times, np.float64).reshape(-1)
    if rows.size == 0:
        return np.full(times.shape, -1, np.int64)
    k = np.searchsorted(tp.t_end[rows], times, side="left")
    return rows[np.clip(k, 0, rows.size - 1)]


def row_values_on_vertices(tp, arrival: np.ndarray, row_values) -> np.ndarray:
    """Per-row values (one per toolpath row) carried to surface vertices through their arrival
    times: each vertex takes the value of the deposit row that laid its material."""
    row_values = np.asarray(row_values, np.float64).reshape(-1)
    if row_values.shape[0] != len(tp):
        raise ValueError(f"row values: {row_values.shape[0]} values for a toolpath of {len(tp)} rows")
    rows = deposit_rows_at(tp, arrival)
    out = np.full(rows.shape, np.nan)
    out[rows >= 0] = row_values[rows[rows >= 0]]
    return out


def element_values_on_vertices(t0, t1, values, arrival) -> np.ndarray:
    """Per-element values (bead pieces in time order over ``[t0, t1]``) carried to surface
    vertices through their arrival times: each vertex takes the value of the piece under way
    when its material arrived (on a boundary, the piece that just ended, as in
    :func:`deposit_rows_at`), or, for a time between two pieces (a run's end or start cap, a blob
    at a stop), of the piece nearer in time. NaN with no piece."""
    t0 = np.asarray(t0, np.float64).reshape(-1)
    t1 = np.asarray(t1, np.float64).reshape(-1)
    values = np.asarray(values, np.float64).reshape(-1)
    arrival = np.asarray(arrival, np.float64).reshape(-1)
    if t0.size == 0:
        return np.full(arrival.shape, np.nan)
    after = np.clip(np.searchsorted(t1, arrival, side="left"), 0, t0.size - 1)
    before = np.maximum(after - 1, 0)
    between = (arrival < t0[after]) & (after > 0)
    nearer_before = between & (arrival - t1[before] <= t0[after] - arrival)
    return values[np.where(nearer_before, before, after)]


def row_bead_area(tp, bead) -> np.ndarray:
    """Bead cross-section area (mm²) of each row: from the row's own width and height where the
    program gives them (slicer ``;WIDTH:``/``;HEIGHT:`` comments), else the bead's."""
    from ..errors import DmdvoxError
    from ..process.profiles import profile_area

    n = len(tp)
    width = np.asarray(getattr(tp, "width", np.full(n, np.nan)), np.float64)
    height = np.asarray(getattr(tp, "height", np.full(n, np.nan)), np.float64)
    own = (np.isfinite(width) & (width > 0)) | (np.isfinite(height) & (height > 0))
    if not own.any():  # the usual case, and a sort of millions of rows saved
        return np.full(n, bead.area)
    width = np.where(np.isfinite(width) & (width > 0), width, bead.width)
    height = np.where(np.isfinite(height) & (height > 0), height, bead.height)
    pairs, inverse = np.unique(np.column_stack([width, height]), axis=0, return_inverse=True)
    areas = np.empty(len(pairs))
    for i, (w, h) in enumerate(pairs):
        try:
            areas[i] = profile_area(bead.code, float(w), float(h), bead.exponent)
        except DmdvoxError:  # sizes the profile cannot take (an arc taller than half its width)
            areas[i] = np.nan
    return areas[np.asarray(inverse).reshape(-1)]


def standard_fields(tp, bead, vertices: np.ndarray, arrival: np.ndarray, extra_fields=()) -> list:
    """``(ScalarField, per-vertex values)`` of the deposit surface: deposition time, layer, feed,
    bead area, then ``extra_fields``.

    ``extra_fields`` is how a new colouring enters the report (``report(request,
    extra_fields=...)``): items ``(ScalarField, values)`` where ``values`` is either an array
    with one value per toolpath row (carried to the surface through the arrival times, see
    :func:`row_values_on_vertices`) or a callable ``values(vertices, arrival)`` returning one
    value per vertex of the full-resolution surface it is given. An extra field named like a
    standard one takes its place (e.g. the deposit's own ``bead_area_mm2`` per vertex)."""
    fields = [(ARRIVAL, np.asarray(arrival, np.float64))]
    if tp.deposit.any():
        fields += [(LAYER, row_values_on_vertices(tp, arrival, tp.layer)),
                   (FEED, row_values_on_vertices(tp, arrival, tp.feed)),
                   (BEAD_AREA, row_values_on_vertices(tp, arrival, row_bead_area(tp, bead)))]
    for spec, values in extra_fields:
        if not isinstance(spec, ScalarField):
            raise TypeError(f"extra field {spec!r}: expected a ScalarField and its values")
        values = values(vertices, arrival) if callable(values) else row_values_on_vertices(tp, arrival, values)
        values = np.asarray(values, np.float64).reshape(-1)
        if values.shape[0] != len(vertices):
            raise ValueError(f"extra field {spec.name!r}: {values.shape[0]} values for {len(vertices)} vertices")
        same = [k for k, (known, _) in enumerate(fields) if known.name == spec.name]
        if same:
            fields[same[0]] = (spec, values)
        else:
            fields.append((spec, values))
    return fields


def field_range(spec: ScalarField, values) -> tuple[float, float]:
    """The colour limits of a field: its own ``range``, else from the finite values."""
    if spec.range is not None:
        return float(spec.range[0]), float(spec.range[1])
    v = np.asarray(values, np.float64)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return 0.0, 1.0
    if spec.symmetric:
        m = float(np.abs(v).max()) or 1e-3
        return -m, m
    return float(v.min()), float(v.max())


def layer_table(tp, bead_height: float) -> list[dict]:
    """One row per deposit layer, in Z order: its Z (as the program gives it), the bead's
    bottom and top there, when it starts and ends (s), time depositing and length deposited,
    the first G-code line, and the interlayer time.

    Layers are the program's distinct deposit Z levels, numbered from 0 at the lowest. A layer
    starts when its first deposit move starts and ends when its last deposit move ends (travel,
    dwells and moves at other Z in between count as part of it). The interlayer time of layer
    k >= 1 is its start minus the end of layer k - 1, the time the layer below had to cool before
    new material landed on it. It is negative when layer k starts before layer k - 1 is finished
    (parts built side by side, layer by layer in turn) and None for layer 0."""
    rows = np.flatnonzero(tp.deposit)
    if rows.size == 0:
        return []
    layer = tp.layer[rows]
    order = np.argsort(layer, kind="stable")  # program order kept within a layer
    rows, layer = rows[order], layer[order]
    cuts = np.flatnonzero(np.diff(layer)) + 1
    starts = np.concatenate([[0], cuts])
    t0, t1 = tp.t_start[rows], tp.t_end[rows]
    begin = np.minimum.reduceat(t0, starts)
    finish = np.maximum.reduceat(t1, starts)
    busy = np.add.reduceat(t1 - t0, starts)
    length = np.add.reduceat(np.asarray(tp.length, np.float64)[rows], starts)
    first_row = rows[starts]  # rows of a layer stay in program order, which is time order
    table = []
    for i, k in enumerate(layer[starts]):
        z = float(tp.layer_z[k])
        bottom, top = (z - bead_height, z) if tp.z_is_layer_top else (z, z + bead_height)
        table.append({"layer": int(k), "z_mm": z, "bottom_mm": bottom, "top_mm": top,
                      "start_s": float(begin[i]), "end_s": float(finish[i]), "deposit_s": float(busy[i]),
                      "length_mm": float(length[i]), "first_line": int(tp.line[first_row[i]]),
                      "interlayer_s": float(begin[i] - finish[i - 1]) if i else None})
    return table


def read_lines(source, wanted: np.ndarray) -> dict[int, str]:
    """The text of the (sorted, 1-based) ``wanted`` lines of ``source``; {} if it cannot be read."""
    texts: dict[int, str] = {}
    if wanted.size == 0 or not source:
        return texts
    try:
        with open(source, "rb") as fh:
            k = 0
            for number, raw in enumerate(fh, 1):
                if number < wanted[k]:
                    continue
                text = raw.decode("utf-8", "replace").strip()
                texts[number] = text if len(text) <= MAX_LINE_CHARS else text[: MAX_LINE_CHARS - 1] + "…"
                k += 1
                if k == wanted.size:
                    break
    except OSError:
        return {}
    return texts


def gcode_lines(tp) -> dict:
    """The replay's G-code line table: per row (program order) its start time, line number and
    index into ``texts`` (``LINE_TRAVEL`` for travel, ``LINE_NO_TEXT`` when not carried)."""
    n = len(tp)
    keep = np.arange(n) if n <= MAX_LINE_ROWS else np.arange(0, n, math.ceil(n / MAX_LINE_ROWS))
    lines = np.asarray(tp.line, np.int64)[keep]
    deposit = np.asarray(tp.deposit, bool)[keep]
    wanted = np.unique(lines[deposit])
    found = read_lines(tp.source, wanted)
    texts: list[str] = []
    index_of: dict[str, int] = {}
    used = 0
    wanted_index = np.full(wanted.size, LINE_NO_TEXT, np.int64)
    for i, number in enumerate(wanted.tolist()):
        text = found.get(number)
        if text is None:
            continue
        if text not in index_of:
            if used + len(text) > MAX_LINE_TEXT_CHARS:
                continue
            index_of[text] = len(texts)
            texts.append(text)
            used += len(text)
        wanted_index[i] = index_of[text]
    index = np.full(keep.size, LINE_TRAVEL, np.int64)
    if wanted.size:
        index[deposit] = wanted_index[np.searchsorted(wanted, lines[deposit])]
    return {"times": np.asarray(tp.t_start, np.float64)[keep], "lines": lines, "text": index, "texts": texts,
            "source": Path(tp.source).name if tp.source else ""}


def scene_payload(meshes: list[SceneMesh], tp, markers: np.ndarray, standoff: float | None,
                  nozzle: tuple[np.ndarray, np.ndarray] | None, fields: list[ScalarField] = (),
                  layers: list[dict] | None = None, clip_margin: float | None = None) -> dict:
    """The JSON object the page's viewer reads (see ``viewer.js``).

    ``markers`` holds ``(x, y, z, time_s)`` rows (nozzle-tip positions of collisions); the
    ``nozzle`` mesh (tip at its origin) follows the path point at the slider's time, lifted by
    ``standoff``. ``fields`` are the colourings offered, in menu order; a mesh coloured by one
    needs a scalar of that name. ``layers`` (:func:`layer_table`) feed the Z clip: layer k's
    clip height is its bead top plus ``clip_margin`` (default a twentieth of the layer step), so
    its top face stays whole whatever the rounding.

    Payload keys: ``fields``: ``[{name, title, label, unit, colormap (16 RGB), range [lo, hi],
    integer, note, time}]``; each mesh's ``scalars``: ``{name: base64 float32 per vertex | number
    when constant}``; ``layers``: ``[{layer, z_mm, top_mm, clip_mm, start_s, end_s}]``;
    ``gcode``: ``{count, times (base64 float32), lines (base64 uint32), text (base64 int32: index
    into texts, -1 travel, -2 not carried), texts, source}``; ``path.layer`` (base64 uint16 per
    segment) lets the clip hide the path above its layer."""
    path = path_lines(tp)
    corners = [path["points"]] + [m.vertices for m in meshes]
    if nozzle is not None:
        corners.append(nozzle[0] + path["points"].min(axis=0) + [0, 0, standoff])
        corners.append(nozzle[0] + path["points"].max(axis=0) + [0, 0, standoff])
    everything = np.concatenate([c for c in corners if len(c)]) if any(len(c) for c in corners) else np.zeros((1, 3))
    lo, hi = everything.min(axis=0), everything.max(axis=0)
    extent = np.maximum(hi - lo, 1e-6)

    def quantised(v: np.ndarray) -> str:
        q = np.clip(np.rint((np.asarray(v) - lo) / extent * 65535.0), 0, 65535).astype("<u2")
        return _b64(q)

    def packed_scalar(values):
        v = np.asarray(values, np.float64).reshape(-1)
        # a constant field costs one number, not a buffer
        if v.size and np.isfinite(v[0]) and np.all(v == v[0]):
            return float(v[0])
        return _b64(v.astype("<f4"))

    def packed_mesh(m: SceneMesh) -> dict:
        return {"name": m.name, "positions": quantised(m.vertices), "indices": _b64(m.triangles.astype("<u4")),
                "normals": _b64(vertex_normals(np.asarray(m.vertices, np.float64), m.triangles)),
                "count": int(m.triangles.size), "color": list(m.color), "opacity": float(m.opacity),
                "timed": m.timed, "capped": m.capped, "solid": m.solid, "clipped": m.clipped,
                "scalars": {k: packed_scalar(v) for k, v in m.scalars.items()}}

    def packed_field(spec: ScalarField) -> dict:
        values = [np.asarray(m.scalars[spec.name], np.float64).reshape(-1) for m in meshes
                  if spec.name in m.scalars and not m.solid]
        lo_hi = field_range(spec, np.concatenate(values) if values else np.zeros(0))
        return {"name": spec.name, "title": spec.title, "label": spec.label, "unit": spec.unit,
                "colormap": colormap(spec.colormap), "range": [lo_hi[0], lo_hi[1]], "integer": spec.integer,
                "note": spec.note, "time": spec.time}

    # the camera frames the first mesh (the deposit), not the travel moves or fixtures around it,
    # and the nozzle's lower third above it
    focus = meshes[0].vertices if meshes and len(meshes[0].vertices) else everything
    focus_lo, focus_hi = focus.min(axis=0), focus.max(axis=0)
    if nozzle is not None:
        focus_hi[2] += float(standoff or 0.0) + np.ptp(np.asarray(nozzle[0])[:, 2]) / 3
    lines = gcode_lines(tp)
    layers = list(layers or [])
    if clip_margin is None:
        clip_margin = 0.05 * (tp.layer_step or (layers[0]["top_mm"] - layers[0]["bottom_mm"] if layers else 0.0))
    payload = {
        "lo": lo.tolist(), "extent": extent.tolist(), "duration": float(tp.duration),
        "focus": [focus_lo.tolist(), focus_hi.tolist()],
        "meshes": [packed_mesh(m) for m in meshes if len(m.triangles)],
        "path": {"points": _b64(path["points"].astype("<f4")), "times": _b64(path["times"].astype("<f4")),
                 "deposit": _b64(path["deposit"]), "layer": _b64(path["layer"]),
                 "count": int(path["deposit"].shape[0])},
        "markers": np.asarray(markers, np.float64).reshape(-1, 4).round(4).tolist(),
        "fields": [packed_field(spec) for spec in fields],
        "layers": [{"layer": r["layer"], "z_mm": r["z_mm"], "top_mm": r["top_mm"],
                    "clip_mm": r["top_mm"] + float(clip_margin), "start_s": r["start_s"], "end_s": r["end_s"]}
                   for r in layers],
        "gcode": {"count": int(lines["lines"].size), "times": _b64(lines["times"].astype("<f4")),
                  "lines": _b64(lines["lines"].astype("<u4")), "text": _b64(lines["text"].astype("<i4")),
                  "texts": lines["texts"], "source": lines["source"]},
        "nozzle": None,
    }
    if nozzle is not None:
        payload["nozzle"] = {"positions": _b64(np.asarray(nozzle[0], "<f4")),
                             "indices": _b64(np.asarray(nozzle[1], "<u4")), "count": int(np.asarray(nozzle[1]).size),
                             "standoff": float(standoff or 0.0)}
    return payload
