"""The report's HTML: one file, no external script, style, font or image.

Pictures are embedded as base64 PNG, plots as inline SVG, the 3-D view as a script of our own
(``viewer.js``) reading a JSON block. Every value shown is escaped; the JSON block is made
safe for a ``<script>`` element by escaping ``<``, ``>`` and ``&``.
"""

from __future__ import annotations

import base64
import json
from html import escape
from importlib import resources
from pathlib import Path

from .. import __version__
from ..io.atomic import write_text


def _number(value, digits: int = 3) -> str:
    if value is None:
        return "–"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return f"{value:,d}"
    if isinstance(value, float):
        return f"{value:,.{digits}f}"
    return escape(str(value))


def _table(rows, header: tuple | None = None, cls: str = "kv") -> str:
    head = "<tr>" + "".join(f"<th>{escape(h)}</th>" for h in header) + "</tr>" if header else ""
    body = "".join("<tr>" + "".join(f"<td>{cell}</td>" for cell in row) + "</tr>" for row in rows)
    return f'<table class="{cls}">{head}{body}</table>'


def _picture(path: str, fallback: str) -> str:
    """A PNG captioned with the title it was drawn with (kept in the file), so the two agree;
    ``fallback`` for a picture without one."""
    from ..view.pictures import png_title

    caption = png_title(path) or fallback
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    return (f'<figure><img alt="{escape(caption)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{escape(caption)} ({escape(Path(path).name)})</figcaption></figure>")


def _plot(plot: tuple[str, str, str]) -> str:
    png, svg, caption = plot
    return (f'<figure class="plot">{svg}<figcaption>{escape(caption)} ({escape(Path(png).name)})</figcaption>'
            "</figure>")


def _layers(layers: list[dict]) -> str:
    """The per-layer timing table: when each layer was laid and how long the one below had to cool."""
    if not layers:
        return ""
    gaps = [r["interlayer_s"] for r in layers if r["interlayer_s"] is not None]
    rows = [(str(r["layer"]), f"{r['z_mm']:.3f}", f"{r['start_s']:.2f}", f"{r['end_s']:.2f}",
             f"{r['deposit_s']:.2f}", f"{r['length_mm']:.2f}",
             "–" if r["interlayer_s"] is None else f"{r['interlayer_s']:.2f}", str(r["first_line"]))
            for r in layers]
    table = _table(rows, ("layer", "Z (mm)", "start (s)", "end (s)", "depositing (s)", "deposited length (mm)",
                          "interlayer time (s)", "first line"), "grid layer-table")
    summary = f"Per-layer times ({len(layers)} layer{'s' if len(layers) != 1 else ''})"
    if gaps:
        summary += f": interlayer time {min(gaps):.2f} … {max(gaps):.2f} s"
    note = ('<p class="note">Layers are the program\'s distinct deposit heights, numbered from 0 at the lowest; a '
            "layer starts when its first deposit move starts and ends when its last deposit move ends. "
            "<b>Interlayer time</b> = a layer's start − the end of the layer below: how long the layer below had "
            "to cool before new material landed on it (heat accumulates when it is short). It is negative when a "
            "layer starts before the one below is finished (parts built side by side in turn); the first "
            "layer has none (–).</p>")
    # a short table is read at a glance; a long one stays folded
    opened = " open" if len(layers) <= 40 else ""
    return f'<details id="layer-times"{opened}><summary>{escape(summary)}</summary>{note}{table}</details>'


def _verdict(sections: dict) -> str:
    """The few numbers an engineer looks at first, each marked good, watch or bad."""
    cards = []

    def card(title: str, value: str, level: str, note: str) -> None:
        cards.append(f'<div class="card {level}"><div class="card-title">{escape(title)}</div>'
                     f'<div class="card-value">{value}</div><div class="card-note">{escape(note)}</div></div>')

    sim = sections["simulate"]
    card("Deposit", f"{sim['deposit_volume_mm3']:,.1f} mm³", "info",
         f"{sections['info']['layers']} layers, {sections['info']['duration_s']:,.0f} s")
    porosity = sim["porosity_percent"]
    card("Pores", f"{sim['pore_count']}", "good" if sim["pore_count"] == 0 else "watch" if porosity < 0.5 else "bad",
         f"porosity {porosity:.3f} %")
    if sim.get("lost_volume_mm3"):
        lost, delivered = sim["lost_volume_mm3"], sim["deposited_volume_mm3"] or 0.0
        share = 100.0 * lost / delivered if delivered > 0 else 100.0
        card("Lost material", f"{lost:,.3g} mm³", "bad" if share >= 1.0 else "watch",
             f"{share:.2f} % of the delivered, on {sim['lost_line_count']} line(s), first line {sim['lost_lines'][0]}")
    if "growth" in sections and sections["growth"]["standoff_mm"]:
        standoff, trend = sections["growth"]["standoff_mm"], sim["standoff_trend"]
        contact = sections["growth"]["first_contact"]
        span = f"{standoff['min']:.2f} … {standoff['max']:.2f} mm"
        if contact is not None:
            card("Standoff", span, "bad", f"the part reaches the nozzle at line {contact['line']} "
                                           f"(layer {contact['layer']})")
        elif trend == "runaway":
            card("Standoff", span, "bad", f"runaway growth: final {standoff['final']:.2f} mm")
        else:
            drift = sim["layers"][-1]["drift_mm"]
            card("Standoff", span, "watch" if trend == "drifting" else "good",
                 f"{trend}, final {standoff['final']:.2f} mm; top layer drift {drift:+.2f} mm")
    if "compare" in sections:
        c = sections["compare"]
        worst = max(c["void_percent"], c["overbuild_percent"])
        card("Void / overbuild", f"{c['void_percent']:.2f} % / {c['overbuild_percent']:.2f} %",
             "good" if worst < 1 else "watch" if worst < 5 else "bad", "of the CAD volume")
        card("Surface deviation", f"{c['deviation_mm']['rms']:.3f} mm rms", "info",
             f"p95 |dev| {c['deviation_mm']['p95']:.3f} mm")
    if "collide" in sections:
        k = sections["collide"]
        lines = sorted({c["line"] for c in k["collisions"]})
        if lines:
            card("Collisions", f"{len(lines)} line(s)", "bad", f"first at line {k['first_collision_line']}")
        else:
            clearance = k["min_clearance_mm"]
            card("Collisions", "none", "good" if not k["near_misses"] else "watch",
                 f"min clearance {clearance:.3f} mm" if clearance is not None else "no obstacle within reach")
    return '<div class="cards">' + "".join(cards) + "</div>"


def _inputs(inputs) -> str:
    rows = [("G-code", escape(inputs.gcode)), ("dialect", escape(inputs.dialect)), ("model", escape(inputs.model))]
    if inputs.material:
        rows.append(("material", escape(inputs.material)))
    if inputs.model.startswith("fixed") or not inputs.material:
        rows.append(("bead", f"{escape(inputs.profile)}, {inputs.width:g} × {inputs.height:g} mm"))
    else:  # the height follows from the material: the median is what the voxel was sized on
        rows.append(("bead", f"{escape(inputs.profile)}, {inputs.width:g} mm wide (median), {inputs.height:.3g} mm "
                             "high (median): each row's from its material"))
    rows += [("motion", escape(inputs.motion)), ("voxel", f"{inputs.voxel:g} mm")]
    if inputs.landing:
        rows.append(("landing", escape(inputs.landing)))
    if inputs.cad:
        rows.append(("CAD", escape(inputs.cad) + (f" offset {inputs.cad_offset}" if any(inputs.cad_offset) else "")))
    if inputs.nozzle:
        rows.append(("nozzle", f"{escape(inputs.nozzle)}, standoff {inputs.standoff:g} mm"))
    for spec in inputs.fixtures:
        rows.append(("fixture", escape(spec)))
    if inputs.plate is not None:
        rows.append(("plate", f"Z = {inputs.plate:g} mm"))
    return _table(rows)


def _info(info: dict, warnings: list[str]) -> str:
    (x0, y0, z0), (x1, y1, z1) = info["bbox_mm"]
    rows = [("lines", _number(info["lines"])), ("moves", _number(info["moves"])),
            ("deposit segments", _number(info["deposit_segments"])),
            ("deposit length", f"{info['deposit_length_mm']:,.1f} mm"),
            ("travel length", f"{info['travel_length_mm']:,.1f} mm"), ("layers", _number(info["layers"])),
            ("deposit bounding box", f"X {x0:.2f} … {x1:.2f}, Y {y0:.2f} … {y1:.2f}, Z {z0:.2f} … {z1:.2f} mm"),
            ("duration", f"{info['duration_s']:,.1f} s")]
    if info["unknown_codes"]:
        rows.append(("ignored codes", escape(", ".join(map(str, info["unknown_codes"])))))
    body = _table(rows)
    if warnings:
        items = "".join(f"<li>{escape(str(w))}</li>" for w in warnings)
        body += f'<details><summary>{len(warnings)} warning(s)</summary><ul>{items}</ul></details>'
    return body


def _pore_table(pores: list[dict], with_cad: bool) -> str:
    largest = sorted(pores, key=lambda p: -p["volume_mm3"])[:20]
    header = ("volume (mm³)", "equivalent diameter (mm)", "centroid (mm)") + (("inside CAD",) if with_cad else ())
    rows = [(f"{p['volume_mm3']:.4f}", f"{p['equivalent_diameter_mm']:.3f}",
             "({:.2f}, {:.2f}, {:.2f})".format(*p["centroid_mm"]))
            + ((_number(p["inside_cad"]),) if with_cad else ()) for p in largest]
    caption = f"the {len(largest)} largest of {len(pores)}" if len(pores) > len(largest) else f"all {len(pores)}"
    return f"<p>Pores, {caption}:</p>" + _table(rows, header, "grid")


def _section(anchor: str, title: str, body: str) -> tuple[str, str, str]:
    return anchor, title, f'<section id="{anchor}"><h2>{escape(title)}</h2>{body}</section>'


def _sections(sections: dict, pictures: dict, plots: dict) -> list[tuple[str, str, str]]:
    """(anchor, title, HTML) of each section that applies, in page order."""
    out = [_section("toolpath", "Toolpath", _info(sections["info"], sections.get("warnings", sections["info"]["warnings"])) + _layers(sections.get("layers", [])))]
    sim = sections["simulate"]
    (x0, y0, z0), (x1, y1, z1) = sim["bbox_mm"]
    body = _table([("volume", f"{sim['deposit_volume_mm3']:,.2f} mm³"),
                   ("bounding box", f"X {x0:.2f} … {x1:.2f}, Y {y0:.2f} … {y1:.2f}, Z {z0:.2f} … {z1:.2f} mm"),
                   ("active voxels", f"{sim['active_voxels']:,d} ({sim['memory_bytes'] / 2**20:,.1f} MiB)"),
                   ("pores", f"{sim['pore_count']} (porosity {sim['porosity_percent']:.3f} %)")]
                  + _material_rows(sim))
    body += ('<div class="figures">' + _picture(pictures["iso"], "Deposit, iso view")
             + _picture(pictures["top"], "Deposit, top view") + "</div>")
    out.append(_section("deposit", "Deposit", body))
    if "material" in sections:
        out.append(_section("material", "Material and speed", _material(sections["material"], pictures, plots)))
    if "growth" in sections:
        out.append(_section("growth", "Built layers and standoff",
                            _growth(sim, sections["growth"], pictures, plots)))
    if "heat" in sections:
        out.append(_section("heat", "Heat", _heat(sections["heat"], plots)))
    if "compare" in sections:
        c = sections["compare"]
        d = c["deviation_mm"]
        body = _table([
            ("CAD volume", f"{c['cad_volume_mm3']:,.2f} mm³"),
            ("void (CAD not filled)", f"{c['void_volume_mm3']:,.2f} mm³ ({c['void_percent']:.2f} %), "
                                      f"deepest {c['max_underfill_mm']:.3f} mm"),
            ("overbuild (outside CAD)", f"{c['overbuild_volume_mm3']:,.2f} mm³ ({c['overbuild_percent']:.2f} %), "
                                        f"highest {c['max_overbuild_mm']:.3f} mm"),
            ("CAD surface deviation", f"mean {d['mean']:+.3f}, rms {d['rms']:.3f}, p95 |dev| {d['p95']:.3f} mm "
                                      "(+ = excess material)"),
        ])
        body += '<div class="figures">' + _picture(pictures["deviation"], "CAD surface deviation")
        if "layers" in plots:
            body += _plot(plots["layers"])
        body += "</div>"
        rows = [(str(r["layer"]), f"{r['z_mm']:.3f}", f"{r['void_mm3']:.3f}", f"{r['overbuild_mm3']:.3f}")
                for r in c["layers"]]
        body += (f"<details><summary>Per-layer table ({len(rows)} layers)</summary>"
                 + _table(rows, ("layer", "Z (mm)", "void (mm³)", "overbuild (mm³)"), "grid") + "</details>")
        out.append(_section("compare", "Comparison with the CAD part", body))
    pores = sections["compare"]["pores"] if "compare" in sections else sim["pores"]
    if pores:
        body = '<div class="figures">' + _picture(pictures["pores"], "Pores")
        body += _plot(plots["pores"]) + "</div>" + _pore_table(pores, "compare" in sections)
    else:
        body = "<p>No enclosed cavity: every empty voxel inside the deposit's bounds reaches the outside.</p>"
    out.append(_section("pores", "Pores", body))
    if "collide" in sections:
        k = sections["collide"]
        if k["collisions"]:
            lines = sorted({c["line"] for c in k["collisions"]})
            body = (f'<p class="alarm">The nozzle collides on {len(lines)} G-code line(s); the first is line '
                    f'{k["first_collision_line"]}.</p>')
            rows = [(str(c["line"]), f"{c['time_s']:.2f}", escape(c["obstacle"]), f"{'≥ ' if c.get('depth_capped') else ''}{c['depth_mm']:.3f}",
                     "({:.2f}, {:.2f}, {:.2f})".format(*c["position_mm"])) for c in k["collisions"][:200]]
            body += _table(rows, ("line", "time (s)", "obstacle", "depth (mm)", "nozzle tip (mm)"), "grid")
        else:
            body = "<p>No collision along the whole path.</p>"
        clearance = k["min_clearance_mm"]
        body += f"<p>{k['poses_checked']:,d} nozzle poses checked; minimum clearance " + (
            f"{clearance:.3f} mm" if clearance is not None else "beyond the measuring reach") + ".</p>"
        if k["near_misses"]:
            rows = [(str(m["line"]), f"{m['time_s']:.2f}", escape(m["obstacle"]), f"{m['distance_mm']:.3f}")
                    for m in k["near_misses"][:200]]
            body += (f"<details><summary>{len(k['near_misses'])} near miss(es)</summary>"
                     + _table(rows, ("line", "time (s)", "obstacle", "distance (mm)"), "grid") + "</details>")
        body += '<div class="figures">'
        if "collisions" in pictures:
            body += _picture(pictures["collisions"], "Nozzle at its first collision")
        body += _plot(plots["clearance"]) + "</div>"
        out.append(_section("collide", "Nozzle collisions", body))
    return out


def _mm(value: float, sign: str = "") -> str:
    """A length to the micrometre; a value that rounds to zero is written 0.000 whatever its sign."""
    value = round(float(value), 3) + 0.0
    return f"{value:{sign}.3f}"


def _material_rows(sim: dict) -> list[tuple[str, str]]:
    """The deposit table's material lines: what was delivered, lost and found in the grid."""
    if sim.get("deposited_volume_mm3") is None:
        return []
    rows = [("material delivered", f"{sim['deposited_volume_mm3']:,.2f} mm³ ({escape(str(sim['flow_source']))})")]
    if sim.get("lost_volume_mm3") is not None:
        rows.append(("lost", f"{sim['lost_volume_mm3']:,.2f} mm³"))
    if sim.get("mass_balance_percent") is not None:
        rows.append(("mass balance", f"{sim['mass_balance_percent']:+.2f} % (deposit against delivered)"))
    return rows


def _material(material: dict, pictures: dict, plots: dict) -> str:
    """Speed and cross-section along the path, the bead height map, the rows with most excess."""
    basis = ("the row's length times Q / F, what it would hold at its programmed speed"
             if material["basis"] == "programmed speed" else
             "the row's length times the program's median cross-section")
    body = ('<p class="note">Where the machine slows (corners, short moves, starts and stops) the material keeps '
            "coming and the bead grows: the planned speed (above) and the cross-section the material gives "
            "(below) along the build; below a quarter of a row's top speed the material collects in a round "
            "blob at the stop.</p>")
    body += '<div class="figures">' + _plot(plots["speed_area"])
    if "bead_height" in pictures:
        body += _picture(pictures["bead_height"], "Bead height")
    body += "</div>"
    rows = material["largest_excess"]
    if rows:
        cells = [(str(r["line"]), f"{r['excess_mm3']:.4f}", f"{r['volume_mm3']:.4f}", f"{r['length_mm']:.3f}",
                  f"{r['feed_mm_s']:.2f}", f"{r['speed_start_mm_s']:.2f} / {r['speed_mid_mm_s']:.2f} / "
                  f"{r['speed_end_mm_s']:.2f}", f"<code>{escape(r['text'])}</code>") for r in rows]
        body += (f"<p>The {len(rows)} row{'s' if len(rows) != 1 else ''} with the most excess material "
                 f"(delivered minus {basis}):</p>"
                 + _table(cells, ("line", "excess (mm³)", "delivered (mm³)", "length (mm)", "F (mm/s)",
                                  "planned speed start / mid / end (mm/s)", "G-code"), "grid excess-table"))
    else:
        body += f"<p>No row carries more material than {basis}.</p>"
    return body


def _growth(sim: dict, growth: dict, pictures: dict, plots: dict) -> str:
    """The flow model: programmed against built layers, the standoff, the drift map, alarms."""
    body = ""
    contact = growth["first_contact"]
    if contact is not None:
        body += (f'<p class="alarm">The part grows into the nozzle: the standoff reaches {contact["standoff_mm"]:.2f} '
                 f'mm at line {contact["line"]} (layer {contact["layer"]}, {contact["time_s"]:.2f} s). The programmed '
                 "layer step is smaller than what the beads build.</p>")
    standoff = growth["standoff_mm"]
    if sim.get("standoff_trend") == "runaway" and standoff is not None:
        body += (f'<p class="alarm">Runaway growth: the standoff moves further from its start every layer (final '
                 f'{standoff["final"]:.2f} mm).</p>')
    if sim.get("lost_volume_mm3"):
        lines = ", ".join(map(str, sim["lost_lines"][:10])) + (", …" if sim["lost_line_count"] > 10 else "")
        body += (f'<p class="alarm">{sim["lost_volume_mm3"]:,.3g} mm³ of material never reached the part (programmed '
                 f"more than the max drop above it) on {sim['lost_line_count']} line(s): {lines}.</p>")
    if standoff is not None:
        body += (f"<p>Standoff met by the beads {standoff['min']:.3f} … {standoff['max']:.3f} mm, final "
                 f"{standoff['final']:.3f} mm ({escape(sim['standoff_trend'])}).</p>")
    body += '<div class="figures">' + _plot(plots["growth_layers"]) + _plot(plots["standoff"])
    if "drift" in pictures:
        body += _picture(pictures["drift"], "Drift from the program")
    body += "</div>"
    layers = sim["layers"]
    rows = [(str(r["layer"]), _mm(r["programmed_z_mm"]), _mm(r["built_top_mm"]["mean"] + r["drift_mm"]),
             _mm(r["built_top_mm"]["mean"]), f"{_mm(r['built_top_mm']['min'])} … {_mm(r['built_top_mm']['max'])}",
             _mm(r["drift_mm"], "+"), _mm(r["standoff_mm"])) for r in layers]
    opened = " open" if len(layers) <= 40 else ""
    body += (f'<details id="growth-layers"{opened}><summary>Programmed and built layers ({len(layers)})</summary>'
             '<p class="note">Drift: programmed top minus built top (+ = the part below the program, its standoff '
             "grows). Standoff: nozzle tip to the part below the layer's beads, before they land.</p>"
             + _table(rows, ("layer", "programmed bottom (mm)", "programmed top (mm)", "built top mean (mm)",
                             "built top min … max (mm)", "drift (mm)", "standoff (mm)"), "grid growth-table")
             + "</details>")
    return body


def _celsius(value) -> str:
    return "–" if value is None else f"{value:,.0f} °C"


def _lines(lines) -> str:
    return "–" if lines is None else f"{lines[0]} … {lines[1]}"


def _heat(heat: dict, plots: dict) -> str:
    """The heat on the deposit: totals, interlayer temperature by layer, the melt pool, the
    hottest layers by G-code line and the peak temperature map."""
    width = heat["max_melt_pool_width_mm"]
    body = _table([
        ("material", f"{escape(heat['material'])} (solidus {heat['solidus_C']:,.0f} °C, liquidus "
                     f"{heat['liquidus_C']:,.0f} °C)"),
        ("thermal lattice", f"{heat['thermal_voxel_mm']:.4g} mm cells: {heat['cells']:,d} ({heat['part_cells']:,d} "
                            f"part, {heat['plate_cells']:,d} plate), {heat['steps']:,d} steps of "
                            f"{heat['time_step_s'] * 1e3:.4g} ms"),
        ("energy", f"absorbed {heat['absorbed_J']:,.1f} J = stored {heat['stored_J']:,.1f} + lost "
                   f"{heat['lost_J']:,.1f} J (balance within {heat['energy_balance_max_percent']:.3f} %; of the loss "
                   f"{heat['boiled_J']:,.1f} J boiled off at the boiling point)"),
        ("peak temperature", _celsius(heat["max_peak_temperature_C"])),
        ("highest interlayer temperature", _celsius(heat["max_interlayer_temperature_C"])),
        ("widest melt pool", "–" if width is None else f"{width:.3f} mm"),
        ("longest time above the solidus", f"{heat['max_time_above_solidus_s']:.3f} s (one cell of the part)"),
        ("remelted cells", f"{heat['remelted_cells']:,d}"),
    ])
    body += '<div class="figures">' + _plot(plots["heat_layers"])
    if "melt_pool" in plots:
        body += _plot(plots["melt_pool"])
    body += _plot(plots["peak_map"]) + "</div>"
    what = "interlayer" if heat["hottest_by"] == "interlayer_C" else "peak"
    rows = [(str(r["layer"]), _lines(r["lines"]), _celsius(r["interlayer_C"]), _celsius(r["peak_C"]))
            for r in heat["hottest_layers"]]
    body += (f"<h3>Hottest layers (by {what} temperature)</h3>"
             + _table(rows, ("layer", "G-code lines", "interlayer", "peak"), "grid heat-hottest"))
    interpass = any(r["cool_below_interpass_s"] is not None for r in heat["layers"])
    rows = [(str(r["layer"]), _lines(r["lines"]), f"{r['start_s']:.2f}", f"{r['end_s']:.2f}",
             _celsius(r["interlayer_C"]), _celsius(r["peak_C"]))
            + ((_number(r["cool_below_interpass_s"], 2),) if interpass else ()) for r in heat["layers"]]
    opened = " open" if len(rows) <= 40 else ""
    body += (f'<details id="heat-layers"{opened}><summary>Temperature by layer ({len(rows)})</summary>'
             '<p class="note">Interlayer: the mean temperature of the layer\'s top cells when the next layer '
             "starts.</p>"
             + _table(rows, ("layer", "G-code lines", "start (s)", "end (s)", "interlayer", "peak")
                      + (("cool below interpass (s)",) if interpass else ()), "grid heat-table")
             + "</details>")
    return body


def _viewer(payload: dict) -> str:
    layers = [m["name"] for m in payload["meshes"]]
    toggles = "".join(f'<label><input type="checkbox" data-layer="{escape(n)}" checked> {escape(n)}</label>'
                      for n in layers)
    toggles += '<label><input type="checkbox" data-layer="toolpath"> toolpath</label>'
    if payload["nozzle"]:
        toggles += '<label><input type="checkbox" data-layer="nozzle" checked> nozzle</label>'
    if payload["markers"]:
        toggles += '<label><input type="checkbox" data-layer="collisions" checked> collisions</label>'
    data = json.dumps(payload, separators=(",", ":"), allow_nan=False)
    data = data.replace("&", "\\u0026").replace("<", "\\u003c").replace(">", "\\u003e")
    script = resources.files(__package__).joinpath("viewer.js").read_text(encoding="utf-8")
    # the colour menu and the legend are filled by the script from the payload's fields
    return f"""<div id="viewer" data-state="loading">
<div class="viewer-bar"><button id="viewer-play" type="button">Play</button>
<input id="viewer-time" type="range" min="0" value="0" aria-label="build time">
<span id="viewer-clock"></span><span id="viewer-speed"></span></div>
<div class="viewer-bar"><span id="viewer-line" title="the G-code line under way"></span></div>
<div id="viewer-stage"><canvas id="viewer-canvas" tabindex="0" aria-label="3-D view of the deposit"></canvas>
<div id="viewer-legend" hidden><div class="legend-title"></div>
<div class="legend-body"><div class="legend-bar"></div><div class="legend-ticks"></div></div>
<div class="legend-note"></div></div>
<div id="viewer-scale" title="length at the depth of the view's centre"><div class="scale-bar"></div>
<span class="scale-label"></span></div></div>
<div class="viewer-bar">colour <select id="viewer-colour" aria-label="colour by"></select> {toggles}
<span class="views"><button type="button" data-view="iso">iso</button><button type="button" data-view="top">top</button>
<button type="button" data-view="front">front</button></span></div>
<div class="viewer-bar">Z clip <input id="viewer-clip" type="range" min="0" step="1" aria-label="Z clip: highest layer shown">
<span id="viewer-clip-label"></span></div>
<p id="viewer-note" class="note">Drag to rotate, shift-drag to pan, wheel to zoom, double-click to reset. With the view
focused: space play/pause, + and − speed, arrows step, Home/End, 0–9 seek to tenths of the build, Page Up/Down
move the Z clip a layer. The scale bar holds at the depth of the view's centre.</p>
</div>
<script type="application/json" id="scene-data">{data}</script>
<script>{script}</script>"""


# the viewer's overlays: on the canvas, out of the pointer's way, small enough to leave the part clear
_VIEWER_CSS = """
#viewer-stage { position: relative; }
#viewer-legend { position: absolute; top: 10px; right: 10px; max-width: 12rem; padding: 6px 9px;
                 background: rgba(255, 255, 255, 0.88); border: 1px solid var(--rule); border-radius: 4px;
                 font-size: 12px; pointer-events: none; }
#viewer-legend[hidden] { display: none; }
.legend-title { font-weight: 600; margin-bottom: 5px; }
.legend-body { display: flex; gap: 6px; height: 140px; }
.legend-bar { width: 14px; border: 1px solid #8a90a0; }
.legend-ticks { position: relative; min-width: 3.5rem; font-variant-numeric: tabular-nums; }
.legend-ticks span { position: absolute; left: 0; transform: translateY(-50%); white-space: nowrap; }
.legend-note { color: var(--muted); margin-top: 5px; }
.legend-note:empty { display: none; }
#viewer-scale { position: absolute; left: 12px; bottom: 12px; padding: 3px 6px; font-size: 12px;
                background: rgba(255, 255, 255, 0.8); pointer-events: none; }
.scale-bar { height: 7px; border: 2px solid var(--ink); border-top: none; }
#viewer-line { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 0.85rem; white-space: pre;
               overflow: hidden; text-overflow: ellipsis; max-width: 100%; min-height: 1.2em; }
#viewer-clip { flex: 0 1 320px; }
#viewer-clip-label { color: var(--muted); font-variant-numeric: tabular-nums; }
"""


def write_page(path: Path, inputs, sections: dict, pictures: dict, plots: dict, payload: dict) -> Path:
    """The page. ``pictures`` maps a name to a PNG, ``plots`` to ``(PNG, SVG, caption)``."""
    css = resources.files(__package__).joinpath("report.css").read_text(encoding="utf-8") + _VIEWER_CSS
    name = Path(inputs.gcode).name
    parts = _sections(sections, pictures, plots) + [_section("view3d", "3-D view", _viewer(payload))]
    nav = "".join(f'<a href="#{anchor}">{escape(title)}</a>' for anchor, title, _ in parts)
    html = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>dmdvox report: {escape(name)}</title>
<style>{css}</style></head>
<body>
<header><h1>dmdvox report: {escape(name)}</h1><nav>{nav}</nav></header>
<main>
<section id="summary"><h2>Summary</h2>{_verdict(sections)}{_inputs(inputs)}</section>
{"".join(block for _, _, block in parts)}
</main>
<footer>dmdvox {escape(__version__)}. Pictures and plots are also beside this page as PNG files;
the deposit and the deviation maps as .vdb and VTK files for ParaView.</footer>
</body></html>
"""
    return write_text(path, html)
