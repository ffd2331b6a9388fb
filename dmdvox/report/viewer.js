// dmdvox report: the embedded 3-D replay (WebGL2, no library).
// Reads the JSON in #scene-data (see dmdvox/report/scene3d.py). The deposit surface is cut at
// the slider's time per fragment, so the part grows as it was deposited; the nozzle follows the
// path point at that time. Keys (the seed's): space play/pause, + - speed, arrows step,
// Home/End, 0-9 seek to tenths. Mouse: drag rotates, shift-drag or right-drag pans, wheel zooms.
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
    out vec4 frag;
    void main() {
      if (uTimed && vTime > uTime) discard;
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
        float s = clamp((value - uLo) / max(uHi - uLo, 1e-12), 0.0, 1.0) * 15.0;
        int i = int(min(floor(s), 14.0));
        base = mix(uLut[i], uLut[i + 1], s - float(i));
      }
      frag = vec4(base * light, uAlpha);
    }`);
  const lineProgram = compile(`#version 300 es
    layout(location=0) in vec3 aPos; layout(location=1) in float aTime; layout(location=2) in float aDeposit;
    uniform mat4 uMvp; uniform float uPointSize;
    out float vTime; out float vDeposit;
    void main() { vTime = aTime; vDeposit = aDeposit; gl_Position = uMvp * vec4(aPos, 1.0);
                  gl_PointSize = uPointSize; }`, `#version 300 es
    precision highp float;
    in float vTime; in float vDeposit;
    uniform float uTime; uniform bool uRound; uniform vec3 uDepositColor; uniform vec3 uTravelColor;
    out vec4 frag;
    void main() {
      if (vTime > uTime) discard;
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
    const scalars = {};
    for (const name of Object.keys(m.scalars)) {
      const values = decode(m.scalars[name], Float32Array);
      scalars[name] = { buffer: buffer(gl.ARRAY_BUFFER, values), range: finiteRange(values) };
    }
    if (scalars.arrival_s) {
      gl.bindBuffer(gl.ARRAY_BUFFER, scalars.arrival_s.buffer);
      gl.enableVertexAttribArray(1);
      gl.vertexAttribPointer(1, 1, gl.FLOAT, false, 0, 0);
    }
    buffer(gl.ELEMENT_ARRAY_BUFFER, decode(m.indices, Uint32Array));
    gl.bindVertexArray(null);
    return { ...m, vao, scalars, visible: true };
  });

  function finiteRange(values) {
    let min = Infinity, max = -Infinity;
    for (const v of values) if (Number.isFinite(v)) { if (v < min) min = v; if (v > max) max = v; }
    return min <= max ? [min, max] : [0, 1];
  }

  function lineVao(points, times, flags) {
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    [[points, 3], [times, 1], [flags, 1]].forEach(([array, size], location) => {
      buffer(gl.ARRAY_BUFFER, array);
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, array instanceof Uint8Array ? gl.UNSIGNED_BYTE : gl.FLOAT, false, 0, 0);
    });
    gl.bindVertexArray(null);
    return vao;
  }

  const pathDeposit = decode(data.path.deposit, Uint8Array);
  const pathFlags = new Uint8Array(2 * data.path.count);
  pathDeposit.forEach((d, i) => { pathFlags[2 * i] = d; pathFlags[2 * i + 1] = d; });
  const pathPoints = decode(data.path.points, Float32Array);
  const pathTimes = decode(data.path.times, Float32Array);
  const path = { vao: lineVao(pathPoints, pathTimes, pathFlags), count: 2 * data.path.count, visible: false };
  const markerPoints = new Float32Array(data.markers.flatMap((m) => m.slice(0, 3)));
  const markerTimes = new Float32Array(data.markers.map((m) => m[3]));
  const markers = { vao: lineVao(markerPoints, markerTimes, new Uint8Array(data.markers.length).fill(1)),
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
  const state = { time: duration, playing: false, speed: 1, colour: 'arrival_s',
                  yaw: -Math.PI / 4, pitch: 0.6, distance: 3.4 * radius, target: centre.slice() };
  const home = { yaw: state.yaw, pitch: state.pitch, distance: state.distance };
  const slider = document.getElementById('viewer-time');
  const label = document.getElementById('viewer-clock');
  const playButton = document.getElementById('viewer-play');
  const speedLabel = document.getElementById('viewer-speed');
  slider.max = String(duration);
  slider.step = String(duration / 2000);

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
    const mvp = multiply(perspective(0.6, canvas.width / Math.max(canvas.height, 1), near, state.distance + 2 * sceneRadius),
                         lookAt(e, state.target, up));
    const u = meshProgram.uniforms;
    gl.useProgram(meshProgram.program);
    gl.uniformMatrix4fv(u.uMvp, false, mvp);
    gl.uniform3fv(u.uEye, e);
    gl.uniform1f(u.uTime, state.time);
    gl.uniform1i(u.uCapByTime, state.colour === 'arrival_s' ? 1 : 0);
    const ordered = meshes.filter((m) => m.visible && m.opacity >= 1).concat(meshes.filter((m) => m.visible && m.opacity < 1));
    for (const m of ordered) {
      gl.bindVertexArray(m.vao);
      gl.uniform3fv(u.uScale, extent);
      gl.uniform3fv(u.uOffset, lo);
      gl.uniform1i(u.uTimed, m.timed ? 1 : 0);
      gl.uniform1i(u.uCapped, m.capped ? 1 : 0);
      gl.uniform3fv(u.uColor, m.color);
      gl.uniform1f(u.uAlpha, m.opacity);
      const scalar = m.solid ? null : m.scalars[state.colour];
      if (scalar) {
        gl.bindBuffer(gl.ARRAY_BUFFER, scalar.buffer);
        gl.enableVertexAttribArray(2);
        gl.vertexAttribPointer(2, 1, gl.FLOAT, false, 0, 0);
        const range = state.colour === 'deviation_mm' && data.deviation_range
          ? [-data.deviation_range, data.deviation_range] : state.colour === 'arrival_s' ? [0, duration] : scalar.range;
        gl.uniform1i(u.uMode, 1);
        gl.uniform1f(u.uLo, range[0]);
        gl.uniform1f(u.uHi, range[1]);
        gl.uniform3fv(u.uLut, data.colormaps[state.colour].flat());
      } else {
        gl.disableVertexAttribArray(2);
        gl.uniform1i(u.uMode, 0);
      }
      if (!m.scalars.arrival_s) gl.vertexAttrib1f(1, 0);
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
      gl.uniform3fv(v.uDepositColor, [0.9, 0.0, 0.0]);
      gl.bindVertexArray(markers.vao);
      gl.drawArrays(gl.POINTS, 0, markers.count);
    }
    gl.bindVertexArray(null);
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

  function updateControls() {
    slider.value = String(state.time);
    label.textContent = `t = ${state.time.toFixed(1)} s of ${duration.toFixed(1)} s`;
    playButton.textContent = state.playing ? 'Pause' : 'Play';
    speedLabel.textContent = `speed ${state.speed}x`;
    root.dataset.playing = String(state.playing);
    root.dataset.time = state.time.toFixed(3);
  }

  // --- controls ------------------------------------------------------------------------------
  function togglePlay() {
    if (!state.playing && state.time >= duration) setTime(0);
    state.playing = !state.playing;
  }
  playButton.addEventListener('click', () => { togglePlay(); updateControls(); });
  slider.addEventListener('input', () => { state.playing = false; setTime(parseFloat(slider.value)); });
  document.getElementById('viewer-colour').addEventListener('change', (ev) => { state.colour = ev.target.value; requestDraw(); });
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

  updateControls();
  requestAnimationFrame(frame);
})();
