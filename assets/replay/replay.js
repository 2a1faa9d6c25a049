// The replay page's viewer: plain WebGL2, the project's own shaders (shaders/creature.*), and
// the scene built from the recorded particles exactly as src/render/scene.cc and
// src/render/cue_layers.cc build a movie frame's meshes. Positions are shown as recorded, one
// frame per movie frame, never interpolated: the page shows the run `simulate` computes.
'use strict';
(function () {
  // Milliseconds since the navigation began, at each stage of opening (hexgaitReplay.timings).
  const timings = {script: performance.now()};
  const data = JSON.parse(document.getElementById('replay-data').textContent);
  const $ = (id) => document.getElementById(id);

  // --- The run --------------------------------------------------------------------------
  // Base64 of little-endian arrays (every browser's byte order).
  function decode(text, Type) {
    const bin = atob(text);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer);
  }
  const run = data.run, creature = data.creature, look = data.look;
  const times = decode(data.frames.time, Float32Array);
  const positions = decode(data.frames.position, Float32Array);
  const centres = decode(data.frames.centre, Float32Array);
  const follows = decode(data.frames.follow, Float32Array);
  const feetDown = decode(data.frames.feet_down, Uint8Array);
  const prints = decode(data.footprints, Float32Array);  // time, x, y, leg
  const trail = decode(data.trail, Float32Array);        // time, x, y
  const frames = times.length, n = creature.particles, period = run.cycle_period;
  timings.decoded = performance.now();

  // --- Small vector and matrix helpers (column-major 4x4, as Eigen and GL) ----------------
  const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const mul = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const cross = (a, b) =>
      [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const norm = (a) => Math.sqrt(dot(a, a));
  const unit = (a) => mul(a, 1 / norm(a));
  function multiply(a, b) {
    const m = new Float32Array(16);
    for (let c = 0; c < 4; ++c)
      for (let r = 0; r < 4; ++r) {
        let s = 0;
        for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
        m[c * 4 + r] = s;
      }
    return m;
  }
  function lookAt(eye, target, up) {  // src/render/renderer.cc, LookAt
    const f = unit(sub(target, eye)), s = unit(cross(f, up)), u = cross(s, f);
    const m = new Float32Array(16);
    for (let k = 0; k < 3; ++k) {
      m[k * 4 + 0] = s[k];
      m[k * 4 + 1] = u[k];
      m[k * 4 + 2] = -f[k];
    }
    m[12] = -dot(s, eye);
    m[13] = -dot(u, eye);
    m[14] = dot(f, eye);
    m[15] = 1;
    return m;
  }
  function perspective(fovY, aspect, near, far) {  // src/render/renderer.cc, Perspective
    const t = 1 / Math.tan(fovY * Math.PI / 360), m = new Float32Array(16);
    m[0] = t / aspect;
    m[5] = t;
    m[10] = (far + near) / (near - far);
    m[14] = 2 * far * near / (near - far);
    m[11] = -1;
    return m;
  }
  // src/render/camera.cc, ViewProjection.
  function viewProjection(cam, tracked, aspect) {
    const target = add(tracked, cam.target), eye = add(target, cam.eye);
    const direction = unit(cam.eye);
    const up = Math.abs(direction[2]) > 0.999 ? [0, 1, 0] : [0, 0, 1];
    const distance = norm(cam.eye) + norm(cam.target);
    const far = Math.max(100, 4 * distance), near = Math.max(0.1, far / 1000);
    return {matrix: multiply(perspective(cam.fov, aspect, near, far), lookAt(eye, target, up)),
            eye: eye, up: up, forward: unit(sub(target, eye))};
  }

  // --- State -------------------------------------------------------------------------------
  const copyCamera = (c) => ({eye: c.eye.slice(), target: c.target.slice(), fov: c.fov,
                              tracking: c.tracking});
  const state = {
    frame: 0,
    time: 0,          // playback clock, time units
    playing: false,
    speed: 1,         // gait cycles per second
    view: data.view,  // the preset last chosen (the camera may have moved since)
    camera: copyCamera(data.camera),
    cues: Object.assign({}, data.cues),
    overlay: look.overlay,
    shadow: look.shadow,
  };

  // --- Scene: the meshes of one frame (src/render/scene.cc, cue_layers.cc) ------------------
  const KIND = {lit: 0, ground: 1, shadow: 2, decal: 3, lines: 4, points: 5};
  function particle(f, i) {
    const o = (f * n + i) * 3;
    return [positions[o], positions[o + 1], positions[o + 2]];
  }
  function vertexPosition(f, v) {
    if (v < n) return particle(f, v);
    let p = [0, 0, 0];
    for (const [i, w] of creature.skin[v - n]) p = add(p, mul(particle(f, i), w));
    return p;
  }
  function newellNormal(points) {
    const m = [0, 0, 0];
    for (let i = 0; i < points.length; ++i) {
      const a = points[i], b = points[(i + 1) % points.length];
      m[0] += (a[1] - b[1]) * (a[2] + b[2]);
      m[1] += (a[2] - b[2]) * (a[0] + b[0]);
      m[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const l = norm(m);
    return l > 0 ? mul(m, 1 / l) : [0, 0, 1];
  }
  function push(mesh, p, normal, colour) { mesh.push(p[0], p[1], p[2], ...normal, ...colour); }
  const fade = (ground, mark, w) => add(ground, mul(sub(mark, ground), w));
  const legColour = (leg) => creature.legs[leg % creature.legs.length].colour;
  const UP = [0, 0, 1];

  function disc(mesh, x, y, radius, colour) {
    const sides = 12;
    for (let k = 0; k < sides; ++k) {
      const a0 = 2 * Math.PI * k / sides, a1 = 2 * Math.PI * (k + 1) / sides;
      push(mesh, [x, y, 0], UP, colour);
      push(mesh, [x + radius * Math.cos(a0), y + radius * Math.sin(a0), 0], UP, colour);
      push(mesh, [x + radius * Math.cos(a1), y + radius * Math.sin(a1), 0], UP, colour);
    }
  }
  // The movies' cue history keeps this many items (src/render/gait_cues.h).
  const PRINT_MEMORY = 384, TRAIL_MEMORY = 1024;
  function lastAtOrBefore(array, stride, now) {  // index past the last item with time <= now
    let lo = 0, hi = array.length / stride;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (array[mid * stride] <= now) lo = mid + 1; else hi = mid;
    }
    return lo;
  }
  function footprintMesh(now) {
    const mesh = [], end = lastAtOrBefore(prints, 4, now);
    for (let i = Math.max(0, end - PRINT_MEMORY); i < end; ++i) {
      const t = prints[4 * i], x = prints[4 * i + 1], y = prints[4 * i + 2], leg = prints[4 * i + 3];
      const w = 1 - (now - t) / (4 * period);
      if (w <= 0) continue;
      const colour = legColour(leg);
      disc(mesh, x, y, look.foot_radius, fade(look.ground, mul(colour, 0.45), w));
      disc(mesh, x, y, 0.75 * look.foot_radius, fade(look.ground, colour, w));
    }
    return mesh;
  }
  function trailMesh(now) {
    const mesh = [], end = lastAtOrBefore(trail, 3, now), ink = [0.25, 0.25, 0.28];
    const half = 0.18 * look.foot_radius;
    for (let i = Math.max(1, end - TRAIL_MEMORY + 1); i < end; ++i) {
      const a = [trail[3 * i - 2], trail[3 * i - 1]], b = [trail[3 * i + 1], trail[3 * i + 2]];
      const w = 1 - (now - trail[3 * i]) / (10 * period);
      if (w <= 0) continue;
      const along = [b[0] - a[0], b[1] - a[1]], length = Math.hypot(along[0], along[1]);
      if (length <= 0) continue;
      const side = [-along[1] * half / length, along[0] * half / length];
      const ext = [along[0] * half / length, along[1] * half / length];
      const colour = fade(look.ground, ink, w);
      const q = [[a[0] - side[0], a[1] - side[1], 0],
                 [b[0] + ext[0] - side[0], b[1] + ext[1] - side[1], 0],
                 [b[0] + ext[0] + side[0], b[1] + ext[1] + side[1], 0],
                 [a[0] + side[0], a[1] + side[1], 0]];
      for (const k of [0, 1, 2, 0, 2, 3]) push(mesh, q[k], UP, colour);
    }
    return mesh;
  }
  function buildScene(f, eyeBelowGround) {
    const meshes = [];
    const cx = Math.floor(centres[3 * f]), cy = Math.floor(centres[3 * f + 1]), half = 30;
    const ground = [];
    const corners = [[cx - half, cy - half, 0], [cx + half, cy - half, 0],
                     [cx + half, cy + half, 0], [cx - half, cy + half, 0]];
    for (const i of [0, 1, 2, 0, 2, 3]) push(ground, corners[i], UP, look.ground);
    // From below, the ground would hide the creature: it is left out, with what lies on it.
    if (!eyeBelowGround) meshes.push({kind: KIND.ground, v: ground});

    const solid = [], feet = feetDown[f];
    creature.polygons.forEach((polygon, p) => {
      const points = polygon.v.map((v) => vertexPosition(f, v));
      const normal = newellNormal(points);
      const leg = creature.polygon_legs[p];
      if (leg >= 0 && creature.legs[leg].lost) return;  // a lost leg is not drawn, as in the movies
      let colour = polygon.leg ? look.leg : look.body;
      if (leg >= 0 && creature.legs[leg].damaged) colour = look.damaged_leg;  // as the movies draw it
      if (state.cues.swing && leg >= 0 && !((feet >> leg) & 1)) colour = legColour(leg);
      for (let k = 1; k + 1 < points.length; ++k) {
        push(solid, points[0], normal, colour);
        push(solid, points[k], normal, colour);
        push(solid, points[k + 1], normal, colour);
      }
    });
    if (state.shadow && !eyeBelowGround) {
      const lift = 0.004, light = look.light;
      const litGround = look.ambient + (1 - look.ambient) * light[2];
      const colour = mul(look.ground, litGround * 0.62), shadow = [];
      for (let v = 0; v < solid.length; v += 9) {
        const p = [solid[v], solid[v + 1], solid[v + 2]];
        const height = Math.max(p[2] - lift, 0);
        const g = sub(p, mul(light, height / light[2]));
        push(shadow, [g[0], g[1], lift], UP, colour);
      }
      meshes.push({kind: KIND.shadow, v: shadow});
    }
    if (!eyeBelowGround) {
      if (state.cues.trail) meshes.push({kind: KIND.decal, v: trailMesh(times[f])});
      if (state.cues.footprints) meshes.push({kind: KIND.decal, v: footprintMesh(times[f])});
    }
    meshes.push({kind: KIND.lit, v: solid});
    if (state.overlay) {
      const lines = [], dots = [];
      for (const [a, b, motor] of creature.springs) {
        const c = motor ? [0.75, 0.10, 0.10] : [0.15, 0.15, 0.15];
        push(lines, particle(f, a), UP, c);
        push(lines, particle(f, b), UP, c);
      }
      for (let i = 0; i < n; ++i) {
        if (!creature.loose_particles.includes(i)) push(dots, particle(f, i), UP, [0.05, 0.05, 0.05]);
      }
      meshes.push({kind: KIND.lines, v: lines}, {kind: KIND.points, v: dots});
    }
    return meshes;
  }

  // --- WebGL2 (src/render/renderer.cc, Renderer::Draw) ---------------------------------------
  const canvas = $('scene');
  const gl = canvas.getContext('webgl2', {antialias: true, preserveDrawingBuffer: true});
  function fail(text) {
    const box = $('message');
    box.textContent = text;
    box.hidden = false;
  }
  if (!gl) {
    fail('This browser cannot draw the replay: it has no WebGL2.');
    return;
  }
  timings.context = performance.now();
  // The shaders are the movies' (GLSL 3.30); WebGL2 takes the same code as GLSL ES 3.00.
  const es = (source) => source.replace(/^#version 330 core/,
                                        '#version 300 es\nprecision highp float;\nprecision highp int;');
  function compile(type, source, name) {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, es(source));
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
      throw new Error(name + ' does not compile: ' + gl.getShaderInfoLog(shader));
    }
    return shader;
  }
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl.VERTEX_SHADER, data.shaders.vertex, 'creature.vert'));
  gl.attachShader(program, compile(gl.FRAGMENT_SHADER, data.shaders.fragment, 'creature.frag'));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error('the shaders do not link: ' + gl.getProgramInfoLog(program));
  }
  timings.shaders = performance.now();
  const uniform = (name) => gl.getUniformLocation(program, name);
  const u = {viewProjection: uniform('view_projection'), light: uniform('light_direction'),
             ambient: uniform('ambient'), checker: uniform('checker'),
             pointSize: uniform('point_size')};
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  const buffer = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  for (let a = 0; a < 3; ++a) {
    gl.enableVertexAttribArray(a);
    gl.vertexAttribPointer(a, 3, gl.FLOAT, false, 36, a * 12);
  }

  function trackedPoint(f) {
    switch (state.camera.tracking) {
      case 'follow': return [follows[3 * f], follows[3 * f + 1], follows[3 * f + 2]];
      case 'x': return [centres[3 * f], centres[1], centres[2]];
      default: return [centres[0], centres[1], centres[2]];
    }
  }
  let lastCamera = null;
  function draw() {
    const dpr = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.clientWidth * dpr));
    const height = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    const f = state.frame;
    const cam = viewProjection(state.camera, trackedPoint(f), width / height);
    lastCamera = cam;
    const meshes = buildScene(f, cam.eye[2] < 0);
    gl.viewport(0, 0, width, height);
    gl.clearColor(look.background[0], look.background[1], look.background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.useProgram(program);
    gl.uniform1f(u.pointSize, Math.max(3, height / 90));
    gl.uniformMatrix4fv(u.viewProjection, false, cam.matrix);
    gl.uniform3fv(u.light, look.light);
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    for (const mesh of meshes) {
      if (mesh.v.length === 0) continue;
      gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(mesh.v), gl.STREAM_DRAW);
      const lit = mesh.kind === KIND.lit || mesh.kind === KIND.ground;
      gl.uniform1f(u.ambient, lit ? look.ambient : 1);
      const onGround = mesh.kind === KIND.ground || mesh.kind === KIND.shadow ||
                       mesh.kind === KIND.decal;
      gl.uniform1i(u.checker, onGround ? 1 : 0);
      // Overlays over the polygons they belong to; decals over the ground without flicker.
      if (mesh.kind === KIND.lines || mesh.kind === KIND.points || mesh.kind === KIND.decal) {
        gl.disable(gl.DEPTH_TEST);
      }
      const mode = mesh.kind === KIND.lines ? gl.LINES
                   : mesh.kind === KIND.points ? gl.POINTS : gl.TRIANGLES;
      gl.drawArrays(mode, 0, mesh.v.length / 9);
      gl.enable(gl.DEPTH_TEST);
    }
    drawStrip(width, height);
    showClock();
  }

  // --- The footfall strip (src/render/cue_layers.cc, DrawFootfallStrip) ------------------
  const strip = $('strip'), ctx = strip.getContext('2d');
  const css = (c) => 'rgb(' + c.map((v) => Math.round(255 * v)).join(',') + ')';
  function drawStrip(width, height) {
    if (strip.width !== width || strip.height !== height) {
      strip.width = width;
      strip.height = height;
    }
    ctx.clearRect(0, 0, width, height);
    if (!state.cues.strip) return;
    const dpr = window.devicePixelRatio || 1;
    const rows = creature.legs.length, row = Math.max(3, Math.floor(height / 54));
    const gap = row >= 6 ? 1 : 0, pad = Math.max(2, Math.floor(row / 2));
    const margin = Math.max(4, Math.floor(height / 60));
    // Above the controls, which cover the frame's bottom edge.
    const bottom = height - Math.round($('controls').offsetHeight * dpr);
    const x0box = margin, x1box = width - margin;
    const y1box = bottom - margin, y0box = y1box - rows * row - 2 * pad;
    ctx.fillStyle = 'rgba(0, 0, 0, 0.714)';  // the movie's darkening to 2/7
    ctx.fillRect(x0box, y0box, x1box - x0box, y1box - y0box);
    let labelWidth = 0;
    if (row >= 10) {
      ctx.font = (row - 1) + 'px "DejaVu Sans", sans-serif';
      ctx.textBaseline = 'top';
      creature.legs.forEach((leg, i) => {
        labelWidth = Math.max(labelWidth, ctx.measureText(leg.name).width);
        const y = y0box + pad + i * row;
        ctx.fillStyle = css(leg.colour);
        ctx.fillRect(x0box + pad, y + gap, Math.floor(row / 2), row - 2 * gap);
        ctx.fillStyle = '#fff';
        ctx.fillText(leg.name, x0box + pad + row, y);
      });
      labelWidth += row + pad;
    }
    const x0 = x0box + pad + labelWidth, x1 = x1box - pad;
    if (x1 - x0 < 8) return;
    const now = times[state.frame], windowLength = 3 * period, scale = (x1 - x0) / windowLength;
    const xOf = (t) => x1 - Math.round((now - t) * scale);
    for (let i = state.frame; i >= 0; --i) {
      const since = i > 0 ? times[i - 1] : times[i] - 1 / scale;
      const xa = Math.max(x0, xOf(since)), xb = xOf(times[i]);
      for (let leg = 0; leg < rows; ++leg) {
        if (!((feetDown[i] >> leg) & 1)) continue;
        ctx.fillStyle = css(legColour(leg));
        ctx.fillRect(xa, y0box + pad + leg * row + gap, Math.max(xb - xa, 1), row - 2 * gap);
      }
      if (since <= now - windowLength) break;
    }
    ctx.fillStyle = 'rgb(153,153,153)';
    for (let t = Math.ceil((now - windowLength) / period) * period; t <= now; t += period) {
      const x = xOf(t);
      if (x >= x0) ctx.fillRect(x, y0box + pad / 2, 1, y1box - y0box - pad);
    }
    ctx.fillStyle = '#fff';
    ctx.fillRect(x1, y0box + pad / 2, Math.max(1, Math.floor(row / 5)), y1box - y0box - pad);
  }

  // --- Clock, link and controls ------------------------------------------------------------
  const cycles = Math.max(1, Math.ceil(run.duration / period - 1e-9));
  const fixed = (v, d) => Number(v).toFixed(d);
  function showClock() {
    const f = state.frame, t = times[f];
    const cycle = Math.min(cycles, Math.floor(t / period) + 1);
    const x = centres[3 * f] - centres[0];
    $('clock').textContent = 't = ' + fixed(t, 1) + ' of ' + run.duration + ' \u00b7 cycle ' +
        cycle + ' of ' + cycles + ' \u00b7 walked ' + fixed(x, 3) +
        (run.fell && t >= run.fall_time ? ' \u00b7 fallen' : '');
    $('seek').value = f;
    $('link').href = '#t=' + fixed(t, 1) + '&view=' + encodeURIComponent(state.view);
  }
  function nearestFrame(t) {
    let lo = 0, hi = frames - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid - 1;
    }
    if (lo + 1 < frames && Math.abs(times[lo + 1] - t) < Math.abs(times[lo] - t)) ++lo;
    return lo;
  }
  let pending = false;
  function redraw() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      draw();
    });
  }
  function seekFrame(f) {
    state.frame = Math.max(0, Math.min(frames - 1, f));
    state.time = times[state.frame];
    redraw();
  }
  function setPlaying(on) {
    if (on && state.frame >= frames - 1) seekFrame(0);
    state.playing = on;
    $('play').textContent = on ? 'Pause' : 'Play';
    if (on) {
      lastTick = null;
      requestAnimationFrame(tick);
    }
  }
  let lastTick = null;
  function tick(now) {
    if (!state.playing) return;
    if (lastTick !== null) {
      state.time += (now - lastTick) / 1000 * state.speed * period;
      // The last frame at or before the clock: frames are shown as recorded.
      let f = state.frame;
      while (f + 1 < frames && times[f + 1] <= state.time) ++f;
      if (f !== state.frame) {
        state.frame = f;
        draw();
      }
      if (f >= frames - 1) {
        setPlaying(false);
        return;
      }
    }
    lastTick = now;
    requestAnimationFrame(tick);
  }
  function choosePreset(name) {
    const preset = data.presets.find((p) => p.name === name);
    if (!preset) return false;
    state.view = name;
    state.camera = copyCamera(preset);
    $('track').value = state.camera.tracking;
    for (const b of $('views').children) b.classList.toggle('on', b.dataset.view === name);
    redraw();
    return true;
  }

  // The address: #t=SECONDS opens paused there; #view=NAME picks a preset.
  function readAddress() {
    const params = new URLSearchParams(location.hash.replace(/^#/, ''));
    if (params.has('view') && !choosePreset(params.get('view'))) {
      fail('Unknown view "' + params.get('view') + '" in the address; the views are ' +
           data.presets.map((p) => p.name).join(', ') + '.');
    }
    if (params.has('t')) {
      const t = Number(params.get('t'));
      if (!Number.isFinite(t)) {
        fail('The address asks for t = "' + params.get('t') + '", which is not a number.');
      } else {
        setPlaying(false);
        seekFrame(nearestFrame(t));
      }
      return true;
    }
    return false;
  }

  function buildControls() {
    $('title').textContent = data.title;
    $('summary').textContent = data.summary;
    const seek = $('seek');
    seek.max = frames - 1;
    seek.addEventListener('input', () => seekFrame(Number(seek.value)));
    $('play').addEventListener('click', () => setPlaying(!state.playing));
    $('speed').addEventListener('change', (e) => { state.speed = Number(e.target.value); });
    for (const preset of data.presets) {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = preset.name;
      b.title = preset.description;
      b.dataset.view = preset.name;
      b.addEventListener('click', () => choosePreset(preset.name));
      $('views').appendChild(b);
    }
    for (const b of $('views').children) b.classList.toggle('on', b.dataset.view === state.view);
    $('track').value = state.camera.tracking;
    $('track').addEventListener('change', (e) => {
      state.camera.tracking = e.target.value;
      redraw();
    });
    const toggles = [['footprints', 'footprints'], ['trail', 'trail'], ['swing', 'swing'],
                     ['strip', 'strip'], ['overlay', 'springs'], ['shadow', 'shadow']];
    for (const [key, text] of toggles) {
      const label = document.createElement('label'), box = document.createElement('input');
      box.type = 'checkbox';
      box.id = 'cue-' + key;
      const isCue = key in state.cues;
      box.checked = isCue ? state.cues[key] : state[key];
      box.addEventListener('change', () => {
        if (isCue) state.cues[key] = box.checked; else state[key] = box.checked;
        redraw();
      });
      label.append(box, ' ' + text);
      $('cues').appendChild(label);
    }
    window.addEventListener('keydown', (e) => {
      if (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT' && e.target.type !== 'range')
        return;
      if (e.key === ' ') {
        setPlaying(!state.playing);
        e.preventDefault();
      } else if (e.key === 'ArrowRight' || e.key === 'ArrowLeft') {
        setPlaying(false);
        seekFrame(state.frame + (e.key === 'ArrowRight' ? 1 : -1));
        e.preventDefault();
      }
    });
    window.addEventListener('resize', redraw);
    window.addEventListener('hashchange', readAddress);
  }

  // --- Orbit, pan and zoom: mouse and touch ---------------------------------------------
  function orbit(dx, dy) {
    const e = state.camera.eye, r = norm(e);
    let azimuth = Math.atan2(e[1], e[0]), elevation = Math.asin(Math.max(-1, Math.min(1, e[2] / r)));
    azimuth -= dx * 0.008;
    elevation = Math.max(-1.55, Math.min(1.5705, elevation + dy * 0.008));
    state.camera.eye = [r * Math.cos(elevation) * Math.cos(azimuth),
                        r * Math.cos(elevation) * Math.sin(azimuth), r * Math.sin(elevation)];
    redraw();
  }
  function pan(dx, dy) {
    if (!lastCamera) return;
    const right = unit(cross(lastCamera.forward, lastCamera.up)),
          up = cross(right, lastCamera.forward);
    const perPixel = 2 * norm(state.camera.eye) * Math.tan(state.camera.fov * Math.PI / 360) /
                     canvas.clientHeight;
    state.camera.target = add(state.camera.target,
                              add(mul(right, -dx * perPixel), mul(up, dy * perPixel)));
    redraw();
  }
  function zoom(factor) {
    const r = norm(state.camera.eye), next = Math.max(0.5, Math.min(80, r * factor));
    state.camera.eye = mul(state.camera.eye, next / r);
    redraw();
  }
  let drag = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('mousedown', (e) => {
    drag = {x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey};
  });
  window.addEventListener('mouseup', () => { drag = null; });
  window.addEventListener('mousemove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    if (drag.pan) pan(dx, dy); else orbit(dx, dy);
  });
  canvas.addEventListener('wheel', (e) => {
    zoom(Math.exp(e.deltaY * 0.001));
    e.preventDefault();
  }, {passive: false});
  let touches = null;
  const touchState = (list) => {
    const p = Array.from(list).map((t) => [t.clientX, t.clientY]);
    if (p.length === 1) return {n: 1, x: p[0][0], y: p[0][1]};
    return {n: 2, x: (p[0][0] + p[1][0]) / 2, y: (p[0][1] + p[1][1]) / 2,
            d: Math.hypot(p[0][0] - p[1][0], p[0][1] - p[1][1])};
  };
  canvas.addEventListener('touchstart', (e) => {
    touches = touchState(e.touches);
    e.preventDefault();
  }, {passive: false});
  canvas.addEventListener('touchmove', (e) => {
    const next = touchState(e.touches);
    if (touches && next.n === touches.n) {
      if (next.n === 1) {
        orbit(next.x - touches.x, next.y - touches.y);
      } else {
        pan(next.x - touches.x, next.y - touches.y);
        if (next.d > 0 && touches.d > 0) zoom(touches.d / next.d);
      }
    }
    touches = next;
    e.preventDefault();
  }, {passive: false});
  canvas.addEventListener('touchend', (e) => { touches = e.touches.length ? touchState(e.touches) : null; });

  // --- Start -------------------------------------------------------------------------------
  buildControls();
  const linked = readAddress();
  draw();
  gl.finish();
  timings.firstFrame = performance.now();
  if (!linked) setPlaying(true);
  // For tests and scripts: where the replay is, and a way to move it.
  window.hexgaitReplay = {
    frames: frames,
    frame: () => state.frame,
    time: () => times[state.frame],
    playing: () => state.playing,
    seek: (t) => { setPlaying(false); seekFrame(nearestFrame(t)); draw(); },
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    timings: timings,
  };
  document.body.dataset.ready = '1';
})();
