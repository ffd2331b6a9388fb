// dmdvox report: the embedded 3-D replay (WebGL2, no library).
// Reads the JSON in #scene-data (see dmdvox/reporting/scene3d.py). The deposit surface is cut at
// the slider's time per fragment, so the part grows as it was deposited; the nozzle follows the
// path point at that time. The colourings are the payload's `fields` (name, words, unit,
// colour map, range): the menu and the legend are built from them, so a new field needs no
// change here. A Z clip hides the part above a layer's top; the G-code line under way is shown.
// Keys (the seed's): space play/pause, + - speed, arrows step, Home/End, 0-9 seek to tenths;
// PageUp/PageDown move the Z clip a layer. Mouse: drag rotates, shift-drag or right-drag pans,
// wheel zooms. State for tests and scripts is mirrored in #viewer's data attributes.
(function () {
  'use strict';
  const root = document.getElementById('viewer');
  const canvas = document.getElementById('viewer-canvas');
  const note = document.getElementById('viewer-note');
  const data = JSON.parse(document.getElementById('scene-data').textContent);
  const gl = canvas.getContext('webgl2', { antialias: true, preserveDrawingBuffer: true });
  if (!gl) {
    note.textContent = 'This browser offers no WebGL2, so the 3-D view is off; the pictures above show the part.';
    root.dataset.state = 'no-webgl';
    return;
  }

  function decode(text, Type) {
    const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
    return new Type(bytes.buffer);
  }

  function compile(vertexSource, fragmentSource) {
    const program = gl.createProgram();
    for (const [type, source] of [[gl.VERTEX_SHADER, vertexSource], [gl.FRAGMENT_SHADER, fragmentSource]]) {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
      gl.attachShader(program, shader);
    }
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
    const uniforms = {};
    for (let i = 0; i < gl.getProgramParameter(program, gl.ACTIVE_UNIFORMS); i++) {
      const name = gl.getActiveUniform(program, i).name.replace(/\[0\]$/, '');
      uniforms[name] = gl.getUniformLocation(program, name);
    }
    return { program, uniforms };
  }

  // Vertex normals shipped as int8; a headlight lights both sides (cut surfaces show their inside).
  const meshProgram = compile(`#version 300 es
    layout(location=0) in vec3 aPos; layout(location=1) in float aTime; layout(location=2) in float aScalar;
    layout(location=3) in vec3 aNormal;
    uniform mat4 uMvp; uniform vec3 uScale; uniform vec3 uOffset;
    out vec3 vPos; out float vTime; out float vScalar; out vec3 vNormal;
    void main() { vec3 p = aPos * uScale + uOffset; vPos = p; vTime = aTime; vScalar = aScalar; vNormal = aNormal;
                  gl_Position = uMvp * vec4(p, 1.0); }`, `#version 300 es
    precision highp float;
    in vec3 vPos; in float vTime; in float vScalar; in vec3 vNormal;
    uniform float uTime; uniform bool uTimed; uniform bool uCapped; uniform int uMode; uniform float uLo; uniform float uHi;
    uniform vec3 uLut[16]; uniform vec3 uColor; uniform float uAlpha; uniform vec3 uEye; uniform bool uCapByTime;
    uniform bool uClipped; uniform float uClipZ;
    out vec4 frag;
    void main() {
      if (uTimed && vTime > uTime) discard;
      if (uClipped && vPos.z > uClipZ) discard;
      // meshes without normals (the nozzle) fall back to facets from screen-space derivatives
      vec3 n = dot(vNormal, vNormal) > 0.01 ? normalize(vNormal) : normalize(cross(dFdx(vPos), dFdy(vPos)));
      float light = 0.35 + 0.65 * abs(dot(n, normalize(uEye - vPos)));
      vec3 base = uColor;
      float value = vScalar;
      // A closed surface cut at uTime is seen from inside only through the cut: its back faces
      // there are drawn flat in the colour of the moment, which reads as a solid cap.
      bool cap = uCapped && !gl_FrontFacing;
      if (cap) { light = 0.85; value = uTime; }
      if (uMode > 0 && (!cap || uCapByTime)) {
        if (isnan(value)) {
          base = vec3(0.55);  // no value here (e.g. no CAD surface near): grey, as in the pictures
        } else {
          float s = clamp((value - uLo) / max(uHi - uLo, 1e-12), 0.0, 1.0) * 15.0;
          int i = int(min(floor(s), 14.0));
          base = mix(uLut[i], uLut[i + 1], s - float(i));
        }
      }
      frag = vec4(base * light, uAlpha);
    }`);
  const lineProgram = compile(`#version 300 es
    layout(location=0) in vec3 aPos; layout(location=1) in float aTime; layout(location=2) in float aDeposit;
    layout(location=3) in float aLayer;
    uniform mat4 uMvp; uniform float uPointSize;
    out float vTime; out float vDeposit; out float vLayer;
    void main() { vTime = aTime; vDeposit = aDeposit; vLayer = aLayer; gl_Position = uMvp * vec4(aPos, 1.0);
                  gl_PointSize = uPointSize; }`, `#version 300 es
    precision highp float;
    in float vTime; in float vDeposit; in float vLayer;
    uniform float uTime; uniform bool uRound; uniform vec3 uDepositColor; uniform vec3 uTravelColor;
    uniform float uMaxLayer;
    out vec4 frag;
    void main() {
      if (vTime > uTime || vLayer > uMaxLayer + 0.5) discard;
      if (uRound && length(gl_PointCoord - 0.5) > 0.5) discard;
      frag = vec4(vDeposit > 0.5 ? uDepositColor : uTravelColor, 1.0);
    }`);

  const lo = data.lo, extent = data.extent;
  const duration = Math.max(data.duration, 1e-9);
  const [focusLo, focusHi] = data.focus;
  const centre = [0, 1, 2].map((a) => (focusLo[a] + focusHi[a]) / 2);
  const radius = Math.max(0.5 * Math.hypot(...[0, 1, 2].map((a) => focusHi[a] - focusLo[a])), 1e-3);
  const sceneRadius = 0.5 * Math.hypot(extent[0], extent[1], extent[2]) + Math.hypot(...[0, 1, 2].map((a) => lo[a] + extent[a] / 2 - centre[a]));

  function buffer(target, array) {
    const b = gl.createBuffer();
    gl.bindBuffer(target, b);
    gl.bufferData(target, array, gl.STATIC_DRAW);
    return b;
  }

  const meshes = data.meshes.map((m) => {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    buffer(gl.ARRAY_BUFFER, decode(m.positions, Uint16Array));
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.UNSIGNED_SHORT, true, 0, 0);
    buffer(gl.ARRAY_BUFFER, decode(m.normals, Int8Array));
    gl.enableVertexAttribArray(3);
    gl.vertexAttribPointer(3, 3, gl.BYTE, true, 0, 0);
    // a scalar is a base64 float32 buffer, or one number when it is the same on every vertex
    const scalars = {};
    for (const [name, packed] of Object.entries(m.scalars)) {
      scalars[name] = typeof packed === 'number' ? { constant: packed }
        : { buffer: buffer(gl.ARRAY_BUFFER, decode(packed, Float32Array)) };
    }
    if (scalars.arrival_s && scalars.arrival_s.buffer) {
      gl.bindBuffer(gl.ARRAY_BUFFER, scalars.arrival_s.buffer);
      gl.enableVertexAttribArray(1);
      gl.vertexAttribPointer(1, 1, gl.FLOAT, false, 0, 0);
    }
    buffer(gl.ELEMENT_ARRAY_BUFFER, decode(m.indices, Uint32Array));
    gl.bindVertexArray(null);
    return { ...m, vao, scalars, visible: true };
  });

  function lineVao(points, times, flags, layers) {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    [[points, 3], [times, 1], [flags, 1], [layers, 1]].forEach(([array, size], location) => {
      buffer(gl.ARRAY_BUFFER, array);
      gl.enableVertexAttribArray(location);
      const type = array instanceof Uint8Array ? gl.UNSIGNED_BYTE : array instanceof Uint16Array ? gl.UNSIGNED_SHORT
        : gl.FLOAT;
      gl.vertexAttribPointer(location, size, type, false, 0, 0);
    });
    gl.bindVertexArray(null);
    return vao;
  }

  // per segment in the payload, per end point for the GPU
  function perEnd(values, Type) {
    const out = new Type(2 * values.length);
    values.forEach((v, i) => { out[2 * i] = v; out[2 * i + 1] = v; });
    return out;
  }
  const pathPoints = decode(data.path.points, Float32Array);
  const pathTimes = decode(data.path.times, Float32Array);
  const path = { vao: lineVao(pathPoints, pathTimes, perEnd(decode(data.path.deposit, Uint8Array), Uint8Array),
                              perEnd(decode(data.path.layer, Uint16Array), Uint16Array)),
                 count: 2 * data.path.count, visible: false };
  const markerPoints = new Float32Array(data.markers.flatMap((m) => m.slice(0, 3)));
  const markerTimes = new Float32Array(data.markers.map((m) => m[3]));
  const markers = { vao: lineVao(markerPoints, markerTimes, new Uint8Array(data.markers.length).fill(1),
                                 new Uint16Array(data.markers.length)),
                    count: data.markers.length, visible: true };

  let nozzle = null;
  if (data.nozzle) {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    buffer(gl.ARRAY_BUFFER, decode(data.nozzle.positions, Float32Array));
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 3, gl.FLOAT, false, 0, 0);
    buffer(gl.ELEMENT_ARRAY_BUFFER, decode(data.nozzle.indices, Uint32Array));
    gl.bindVertexArray(null);
    nozzle = { vao, count: data.nozzle.count, standoff: data.nozzle.standoff, visible: true };
  }

  // --- state -------------------------------------------------------------------------------
  const FOV = 0.6;  // vertical field of view, radians
  const fields = data.fields || [];
  const fieldByName = Object.fromEntries(fields.map((f) => [f.name, f]));
  const layers = data.layers || [];
  const state = { time: duration, playing: false, speed: 1, colour: fields.length ? fields[0].name : 'solid',
                  clip: Math.max(layers.length - 1, 0), yaw: -Math.PI / 4, pitch: 0.6, distance: 3.4 * radius, target: centre.slice() };
  const home = { yaw: state.yaw, pitch: state.pitch, distance: state.distance };
  const slider = document.getElementById('viewer-time');
  const label = document.getElementById('viewer-clock');
  const playButton = document.getElementById('viewer-play');
  const speedLabel = document.getElementById('viewer-speed');
  const lineLabel = document.getElementById('viewer-line');
  const colourMenu = document.getElementById('viewer-colour');
  const clipSlider = document.getElementById('viewer-clip');
  const clipLabel = document.getElementById('viewer-clip-label');
  const legend = document.getElementById('viewer-legend');
  const scaleBox = document.getElementById('viewer-scale');
  slider.max = String(duration);
  slider.step = String(duration / 2000);
  // the top layer's position shows everything, unclipped
  clipSlider.max = String(Math.max(layers.length - 1, 0));
  clipSlider.value = clipSlider.max;
  clipSlider.disabled = layers.length < 2;
  for (const f of fields) colourMenu.add(new Option(f.title, f.name));
  colourMenu.add(new Option('one colour', 'solid'));
  colourMenu.value = state.colour;

  // G-code lines under way: row start times, line numbers and indexes into the texts
  const gcode = data.gcode || { count: 0, texts: [] };
  const rowTimes = gcode.count ? decode(gcode.times, Float32Array) : new Float32Array(0);
  const rowLines = gcode.count ? decode(gcode.lines, Uint32Array) : new Uint32Array(0);
  const rowText = gcode.count ? decode(gcode.text, Int32Array) : new Int32Array(0);

  // --- matrices (column-major, as WebGL wants them) ------------------------------------------
  function perspective(fovy, aspect, near, far) {
    const f = 1 / Math.tan(fovy / 2), d = near - far;
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / d, -1, 0, 0, 2 * far * near / d, 0];
  }
  function lookAt(eye, target, up) {
    const sub = (a, b) => a.map((v, i) => v - b[i]);
    const norm = (a) => { const l = Math.hypot(...a) || 1; return a.map((v) => v / l); };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const z = norm(sub(eye, target)), x = norm(cross(up, z)), y = cross(z, x);
    return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, -dot(x, eye), -dot(y, eye), -dot(z, eye), 1];
  }
  function multiply(a, b) {
    const out = new Array(16).fill(0);
    for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) for (let k = 0; k < 4; k++) out[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
    return out;
  }
  function eye() {
    const cp = Math.cos(state.pitch);
    return [state.target[0] + state.distance * cp * Math.cos(state.yaw),
            state.target[1] + state.distance * cp * Math.sin(state.yaw),
            state.target[2] + state.distance * Math.sin(state.pitch)];
  }

  // The nozzle tip at time t: the path point interpolated on the segment under way, lifted.
  function pathPointAt(t) {
    const n = data.path.count;
    if (n === 0) return centre;
    let a = 0, b = n - 1;
    while (a < b) { const m = (a + b + 1) >> 1; if (pathTimes[2 * m] <= t) a = m; else b = m - 1; }
    const t0 = pathTimes[2 * a], t1 = pathTimes[2 * a + 1];
    const s = t1 > t0 ? Math.min(1, Math.max(0, (t - t0) / (t1 - t0))) : 1;
    return [0, 1, 2].map((k) => pathPoints[6 * a + k] + s * (pathPoints[6 * a + 3 + k] - pathPoints[6 * a + k]));
  }

  // The row under way at time t: the last one started by then (the first before the program starts).
  function rowAt(t) {
    let a = 0, b = gcode.count - 1;
    if (b < 0) return -1;
    while (a < b) { const m = (a + b + 1) >> 1; if (rowTimes[m] <= t) a = m; else b = m - 1; }
    return a;
  }

  // --- Z clip --------------------------------------------------------------------------------
  function clipActive() { return state.clip < layers.length - 1; }
  function clipZ() { return clipActive() ? layers[state.clip].clip_mm : Infinity; }

  // --- legend and scale bar --------------------------------------------------------------------
  function tickFormat(lo, hi, integer) {
    if (integer) return (v) => String(Math.round(v));
    const span = Math.abs(hi - lo) || Math.abs(hi) || 1;
    const decimals = Math.min(6, Math.max(0, 2 - Math.floor(Math.log10(span))));
    return (v) => v.toFixed(decimals).replace(/^-(0\.?0*)$/, '$1');
  }
  function tickValues(lo, hi, integer) {
    if (hi <= lo) return [lo];
    if (integer) {
      // whole numbers 1, 2 or 5 times a power of ten apart, at most nine of them
      const power = Math.pow(10, Math.floor(Math.log10(Math.max(1, (hi - lo) / 8))));
      const step = [1, 2, 5, 10].map((m) => m * power).find((d) => (hi - lo) / d <= 8);
      const out = [];
      for (let v = Math.ceil(lo); v <= hi; v += step) out.push(v);
      return out;
    }
    return [0, 1, 2, 3, 4].map((i) => lo + (hi - lo) * i / 4);
  }
  function updateLegend() {
    const f = fieldByName[state.colour];
    root.dataset.colour = state.colour;
    if (!f) { legend.hidden = true; return; }
    legend.hidden = false;
    const [lo, hi] = f.range;
    const css = (c) => `rgb(${c.map((x) => Math.round(255 * x)).join(',')})`;
    const stops = f.colormap.map((c, i) => `${css(c)} ${(100 * i / (f.colormap.length - 1)).toFixed(2)}%`);
    legend.querySelector('.legend-title').textContent = f.title;
    const bar = legend.querySelector('.legend-bar');
    const ticks = legend.querySelector('.legend-ticks');
    ticks.replaceChildren();
    const format = tickFormat(lo, hi, f.integer);
    if (hi > lo) {
      bar.style.background = `linear-gradient(to top, ${stops.join(', ')})`;
      for (const v of tickValues(lo, hi, f.integer).reverse()) {  // top to bottom, as read
        const tick = document.createElement('span');
        tick.textContent = format(v);
        tick.style.top = `${(100 * (1 - (v - lo) / (hi - lo))).toFixed(2)}%`;
        ticks.append(tick);
      }
    } else {
      // one value everywhere: one swatch and the value
      bar.style.background = css(f.colormap[0]);
      const tick = document.createElement('span');
      tick.textContent = `all ${format(lo)}`;
      tick.style.top = '50%';
      ticks.append(tick);
    }
    legend.querySelector('.legend-note').textContent = f.note || '';
  }

  // A round length (1, 2 or 5 times a power of ten, in mm) at most `px` pixels long at the
  // depth of the view's centre, where a perspective view's scale is exact.
  function updateScaleBar() {
    const pxPerMm = canvas.clientHeight / (2 * state.distance * Math.tan(FOV / 2));
    const most = 120 / pxPerMm;
    const power = Math.pow(10, Math.floor(Math.log10(most)));
    const length = [5, 2, 1].map((m) => m * power).find((l) => l <= most * (1 + 1e-9)) || power;
    const px = length * pxPerMm;
    scaleBox.querySelector('.scale-bar').style.width = `${px.toFixed(1)}px`;
    scaleBox.querySelector('.scale-label').textContent = `${Number(length.toPrecision(1))} mm`;
    root.dataset.scaleMm = String(Number(length.toPrecision(1)));
    root.dataset.scalePx = px.toFixed(3);
    root.dataset.pxPerMm = pxPerMm.toFixed(5);
  }

  // --- drawing -------------------------------------------------------------------------------
  let dirty = true;
  function requestDraw() { dirty = true; }

  function draw() {
    const width = canvas.clientWidth, height = canvas.clientHeight;
    const ratio = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
    }
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(1, 1, 1, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    const e = eye();
    const up = Math.abs(Math.cos(state.pitch)) < 1e-3 ? [Math.cos(state.yaw), Math.sin(state.yaw), 0] : [0, 0, 1];
    const near = Math.max(state.distance - 2 * sceneRadius, state.distance * 1e-3);
    const mvp = multiply(perspective(FOV, canvas.width / Math.max(canvas.height, 1), near, state.distance + 2 * sceneRadius),
                         lookAt(e, state.target, up));
    const field = fieldByName[state.colour];
    const u = meshProgram.uniforms;
    gl.useProgram(meshProgram.program);
    gl.uniformMatrix4fv(u.uMvp, false, mvp);
    gl.uniform3fv(u.uEye, e);
    gl.uniform1f(u.uTime, state.time);
    // a cut by time alone shows its cap in the colour of the moment; a Z section in the mesh's colour
    gl.uniform1i(u.uCapByTime, field && field.time && !clipActive() ? 1 : 0);
    gl.uniform1f(u.uClipZ, clipZ());
    const ordered = meshes.filter((m) => m.visible && m.opacity >= 1).concat(meshes.filter((m) => m.visible && m.opacity < 1));
    for (const m of ordered) {
      gl.bindVertexArray(m.vao);
      gl.uniform3fv(u.uScale, extent);
      gl.uniform3fv(u.uOffset, lo);
      gl.uniform1i(u.uTimed, m.timed ? 1 : 0);
      gl.uniform1i(u.uCapped, m.capped ? 1 : 0);
      gl.uniform1i(u.uClipped, m.clipped && clipActive() ? 1 : 0);
      gl.uniform3fv(u.uColor, m.color);
      gl.uniform1f(u.uAlpha, m.opacity);
      const scalar = m.solid || !field ? null : m.scalars[state.colour];
      if (scalar) {
        if (scalar.buffer) {
          gl.bindBuffer(gl.ARRAY_BUFFER, scalar.buffer);
          gl.enableVertexAttribArray(2);
          gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 0, 0);
        } else {
          gl.disableVertexAttribArray(2);
          gl.vertexAttrib1f(2, scalar.constant);
        }
        gl.uniform1i(u.uMode, 1);
        gl.uniform1f(u.uLo, field.range[0]);
        gl.uniform1f(u.uHi, field.range[1]);
        gl.uniform3fv(u.uLut, field.colormap.flat());
      } else {
        gl.disableVertexAttribArray(2);
        gl.uniform1i(u.uMode, 0);
      }
      if (!m.scalars.arrival_s || !m.scalars.arrival_s.buffer) {
        gl.vertexAttrib1f(1, m.scalars.arrival_s ? m.scalars.arrival_s.constant : 0);
      }
      const translucent = m.opacity < 1;
      if (translucent) {
        // pushed back a little: where the CAD and the deposit coincide the deposit shows clean,
        // and the CAD shows where the deposit falls short of it
        gl.enable(gl.BLEND); gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA); gl.depthMask(false);
        gl.enable(gl.POLYGON_OFFSET_FILL); gl.polygonOffset(2, 8);
      }
      gl.drawElements(gl.TRIANGLES, m.count, gl.UNSIGNED_INT, 0);
      if (translucent) { gl.disable(gl.BLEND); gl.depthMask(true); gl.disable(gl.POLYGON_OFFSET_FILL); }
    }
    if (nozzle && nozzle.visible) {
      const tip = pathPointAt(state.time);
      gl.bindVertexArray(nozzle.vao);
      gl.disableVertexAttribArray(2);
      gl.vertexAttrib3f(3, 0, 0, 0);
      gl.vertexAttrib1f(1, 0);
      gl.uniform3fv(u.uScale, [1, 1, 1]);
      gl.uniform3fv(u.uOffset, [tip[0], tip[1], tip[2] + nozzle.standoff]);
      gl.uniform1i(u.uTimed, 0);
      gl.uniform1i(u.uCapped, 0);
      gl.uniform1i(u.uClipped, 0);
      gl.uniform1i(u.uMode, 0);
      gl.uniform3fv(u.uColor, [0.75, 0.45, 0.2]);
      gl.uniform1f(u.uAlpha, 0.55);
      gl.enable(gl.BLEND); gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA); gl.depthMask(false);
      gl.drawElements(gl.TRIANGLES, nozzle.count, gl.UNSIGNED_INT, 0);
      gl.disable(gl.BLEND); gl.depthMask(true);
    }
    const v = lineProgram.uniforms;
    gl.useProgram(lineProgram.program);
    gl.uniformMatrix4fv(v.uMvp, false, mvp);
    gl.uniform1f(v.uTime, state.time);
    gl.uniform1f(v.uMaxLayer, clipActive() ? layers[state.clip].layer : 1e9);
    if (path.visible && path.count) {
      gl.uniform1i(v.uRound, 0);
      gl.uniform3fv(v.uDepositColor, [0.7, 0.1, 0.1]);
      gl.uniform3fv(v.uTravelColor, [0.6, 0.6, 0.6]);
      gl.bindVertexArray(path.vao);
      gl.drawArrays(gl.LINES, 0, path.count);
    }
    if (markers.visible && markers.count) {
      gl.disable(gl.DEPTH_TEST);
      gl.uniform1i(v.uRound, 1);
      gl.uniform1f(v.uPointSize, 9 * ratio);
      gl.uniform1f(v.uMaxLayer, 1e9);
      gl.uniform3fv(v.uDepositColor, [0.9, 0.0, 0.0]);
      gl.bindVertexArray(markers.vao);
      gl.drawArrays(gl.POINTS, 0, markers.count);
    }
    gl.bindVertexArray(null);
    updateScaleBar();
    root.dataset.distance = state.distance.toFixed(5);
    root.dataset.target = state.target.map((x) => x.toFixed(5)).join(',');
    root.dataset.state = 'drawn';
  }

  let lastFrame = null;
  function frame(now) {
    if (state.playing) {
      if (lastFrame !== null) {
        // a whole build plays in about 20 s at speed 1
        setTime(state.time + (now - lastFrame) / 1000 * state.speed * duration / 20);
        if (state.time >= duration) state.playing = false;
      }
      lastFrame = now;
    } else {
      lastFrame = null;
    }
    if (dirty) { dirty = false; draw(); }
    updateControls();
    requestAnimationFrame(frame);
  }

  function setTime(t) {
    state.time = Math.min(duration, Math.max(0, t));
    requestDraw();
  }

  function setClip(k) {
    state.clip = Math.min(Math.max(layers.length - 1, 0), Math.max(0, Math.round(k)));
    requestDraw();
  }

  let shownLine = null;
  function updateControls() {
    slider.value = String(state.time);
    label.textContent = `t = ${state.time.toFixed(1)} s of ${duration.toFixed(1)} s`;
    playButton.textContent = state.playing ? 'Pause' : 'Play';
    speedLabel.textContent = `speed ${state.speed}x`;
    root.dataset.playing = String(state.playing);
    root.dataset.time = state.time.toFixed(3);
    const row = rowAt(state.time);
    if (row !== shownLine) {
      shownLine = row;
      if (row < 0) {
        lineLabel.textContent = '';
        delete root.dataset.line;
      } else {
        const k = rowText[row];
        const text = k >= 0 ? gcode.texts[k] : k === -1 ? '(travel)' : '(deposit; text not embedded)';
        lineLabel.textContent = `line ${rowLines[row]}: ${text}`;
        root.dataset.line = String(rowLines[row]);
      }
    }
    clipSlider.value = String(state.clip);
    if (clipActive()) {
      const layer = layers[state.clip];
      clipLabel.textContent = `layers 0–${layer.layer} shown (Z ≤ ${layer.top_mm.toFixed(2)} mm)`;
      root.dataset.clipZ = String(layer.clip_mm);
      root.dataset.clipLayer = String(layer.layer);
    } else {
      clipLabel.textContent = layers.length ? `all ${layers.length} layers` : 'no layers';
      root.dataset.clipZ = 'none';
      delete root.dataset.clipLayer;
    }
  }

  // --- controls ------------------------------------------------------------------------------
  function togglePlay() {
    if (!state.playing && state.time >= duration) setTime(0);
    state.playing = !state.playing;
  }
  playButton.addEventListener('click', () => { togglePlay(); updateControls(); });
  slider.addEventListener('input', () => { state.playing = false; setTime(parseFloat(slider.value)); });
  clipSlider.addEventListener('input', () => { setClip(parseInt(clipSlider.value, 10)); updateControls(); });
  colourMenu.addEventListener('change', (ev) => { state.colour = ev.target.value; updateLegend(); requestDraw(); });
  for (const box of root.querySelectorAll('input[data-layer]')) {
    box.addEventListener('change', () => {
      const name = box.dataset.layer;
      const target = name === 'toolpath' ? path : name === 'collisions' ? markers : name === 'nozzle' ? nozzle
        : meshes.find((m) => m.name === name);
      if (target) target.visible = box.checked;
      requestDraw();
    });
  }
  const views = { iso: [-Math.PI / 4, 0.6], top: [-Math.PI / 2, Math.PI / 2 - 1e-4], front: [-Math.PI / 2, 0] };
  for (const button of root.querySelectorAll('button[data-view]')) {
    button.addEventListener('click', () => {
      [state.yaw, state.pitch] = views[button.dataset.view];
      state.distance = home.distance;
      state.target = centre.slice();
      requestDraw();
    });
  }
  canvas.addEventListener('keydown', (ev) => {
    const step = duration / 200;
    const keys = {
      ' ': togglePlay, '+': () => { state.speed = Math.min(64, state.speed * 2); }, '=': () => { state.speed = Math.min(64, state.speed * 2); },
      '-': () => { state.speed = Math.max(1 / 64, state.speed / 2); },
      ArrowRight: () => setTime(state.time + step), ArrowUp: () => setTime(state.time + 10 * step),
      ArrowLeft: () => setTime(state.time - step), ArrowDown: () => setTime(state.time - 10 * step),
      Home: () => setTime(0), End: () => setTime(duration),
      PageUp: () => setClip(state.clip + 1), PageDown: () => setClip(state.clip - 1),
    };
    const action = keys[ev.key] || (/^[0-9]$/.test(ev.key) ? () => setTime(duration * parseInt(ev.key, 10) / 10) : null);
    if (action) { ev.preventDefault(); action(); requestDraw(); updateControls(); }
  });

  let drag = null;
  canvas.addEventListener('contextmenu', (ev) => ev.preventDefault());
  canvas.addEventListener('pointerdown', (ev) => {
    canvas.focus();
    canvas.setPointerCapture(ev.pointerId);
    drag = { x: ev.clientX, y: ev.clientY, pan: ev.shiftKey || ev.button === 2 };
  });
  canvas.addEventListener('pointerup', () => { drag = null; });
  canvas.addEventListener('pointermove', (ev) => {
    if (!drag) return;
    const dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    drag.x = ev.clientX; drag.y = ev.clientY;
    if (drag.pan) {
      const scale = state.distance / canvas.clientHeight;
      const right = [-Math.sin(state.yaw), Math.cos(state.yaw), 0];
      const upward = [-Math.sin(state.pitch) * Math.cos(state.yaw), -Math.sin(state.pitch) * Math.sin(state.yaw), Math.cos(state.pitch)];
      for (let k = 0; k < 3; k++) state.target[k] += scale * (-dx * right[k] + dy * upward[k]);
    } else {
      state.yaw -= dx * 0.01;
      state.pitch = Math.min(Math.PI / 2 - 1e-4, Math.max(-Math.PI / 2 + 1e-4, state.pitch + dy * 0.01));
    }
    requestDraw();
  });
  canvas.addEventListener('wheel', (ev) => {
    ev.preventDefault();
    state.distance = Math.min(20 * radius, Math.max(0.05 * radius, state.distance * Math.exp(ev.deltaY * 0.001)));
    requestDraw();
  }, { passive: false });
  canvas.addEventListener('dblclick', () => { Object.assign(state, home, { target: centre.slice() }); requestDraw(); });
  // the canvas's size follows the page's; the scale bar follows the canvas
  if (window.ResizeObserver) new ResizeObserver(requestDraw).observe(canvas);

  updateLegend();
  updateControls();
  requestAnimationFrame(frame);
})();
