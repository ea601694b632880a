// The app: owns the current Cloth, runs the loop, wires renderer, input and UI,
// and publishes the test seam window.clothApp.
//
// Loop: the core advances a fixed dt per frame(); the wall clock appears only
// here. Elapsed time goes into an accumulator, capped at MAX_GAP (a tab switch
// or a stall becomes a short pause, never a huge step), and at most MAX_CATCHUP
// frames run per animation frame (the rest of a backlog is dropped, so a slow
// machine runs in slow motion instead of spiralling).
'use strict';

(function () {
  const MAX_GAP = 0.25;        // seconds of wall clock counted per animation frame at most
  const MAX_CATCHUP = 4;       // core frames per animation frame at most
  const READOUT_MS = 250;      // readout refresh period
  const EMA = 0.1;             // smoothing of the timing readouts

  const core = window.clothCore, scenes = window.clothScenes;
  const canvas = document.getElementById('view');
  const query = new URLSearchParams(window.location.search);

  const s = {
    cloth: null, m: null, sceneText: '', sceneObj: null, view: null,
    preset: 'curtain', params: null,
    mode: 'strain', scaleMode: 'auto', fullScale: 0.05,
    paused: false, acc: 0, last: -1, frames: 0, nextAction: 0, renders: 0, dirty: true, needMeasure: true,
    simMs: NaN, renderMs: NaN, fps: NaN, lastReadout: 0, scale: 0,
  };

  const ui = window.clothUI.create({
    pause: function () { setPaused(!s.paused); },
    step: function () { setPaused(true); advance(1); },
    reset: function () { reset(); },
    preset: function (name) { usePreset(name); },
    solver: function (name) { setSolver(name); },
    param: function (key, raw) { setParam(key, raw); },
    mode: function (m) { setColorMode(m || (s.mode === 'strain' ? 'stress' : 'strain')); },
    scaleMode: function (m) { setScaleMode(m || (s.scaleMode === 'auto' ? 'fixed' : 'auto')); },
    fullScale: function (raw) { setFullScale(raw); },
    loadJson: function (text) { loadScene(text); },
    currentJson: function () { return JSON.stringify(s.sceneObj, null, 1); },
  });

  const renderer = window.clothRenderer.create(canvas, {
    webgl: query.get('webgl') || 'auto',
    onLost: function () { ui.error('The WebGL context was lost; waiting for the browser to restore it.'); },
    onRestored: function () {
      if (ui.errorText().indexOf('WebGL context was lost') >= 0) ui.clearError();
      if (s.cloth) renderer.setScene(s.cloth);
      s.dirty = true;
    },
    onError: function (msg) { ui.fatal(msg); },
  });
  if (!renderer.ok) ui.fatal(renderer.error);

  // ---- scenes -------------------------------------------------------------

  // The core's operations on one cloth, made once per scene (see core.js: no
  // allocation per call in the hot loop).
  function bind(cloth) { return core.ops(cloth); }

  function paramsFrom(obj, cloth) {
    function pick(key) { return obj[key] !== undefined ? obj[key] : cloth[key]; }
    const g = Array.isArray(obj.gravity) ? obj.gravity[1] : undefined;
    return { cols: cloth.cols, rows: cloth.rows, iterations: pick('iterations'),
             substeps: pick('substeps'), gravity: g !== undefined ? g : -9.81,
             damping: cloth.scene.damping,
             solver: obj.solver || (cloth.use_xpbd ? 'xpbd' : 'jakobsen') };
  }

  // Load scene JSON text. On a bad scene: show the message, keep the old scene
  // running, and throw an Error with the core's message.
  function load(text, preset, view) {
    let cloth, obj;
    try {
      cloth = core.load(text);
      obj = JSON.parse(text);
    } catch (e) {
      const msg = e && e.message ? e.message : String(e);
      ui.error('Scene not loaded: ' + msg + (s.cloth ? ' (the previous scene keeps running)' : ''));
      throw new Error(msg);
    }
    ui.clearError();
    input.releaseAll();
    s.cloth = cloth;
    s.m = bind(cloth);
    s.clamped = 0;
    s.sceneText = text;
    s.sceneObj = obj;
    s.preset = preset;
    s.view = view || scenes.viewFor(obj);
    s.params = paramsFrom(obj, cloth);
    s.frames = 0;
    s.nextAction = 0;
    s.acc = 0;
    if (renderer.ok) {
      renderer.setScene(cloth);
      renderer.setView(s.view);
    }
    s.m.measure();
    s.needMeasure = false;
    s.dirty = true;
    ui.setPreset(preset);
    ui.setSolver(s.params.solver);
    ui.setParams(s.params);
    if (renderer.ok && !renderer.lost) render();
    return cloth;
  }

  function usePreset(name, params) {
    const made = scenes.make(name, params || scenes.defaults(name));
    ui.note('');
    return load(JSON.stringify(made.scene), name, made.view);
  }

  function reset() {
    return load(s.sceneText, s.preset, s.view);
  }

  function loadScene(text) {
    if (typeof text !== 'string') text = JSON.stringify(text);
    load(text, 'custom', null);
    return true;
  }

  function setParam(key, raw) {
    const c = scenes.clamp(key, raw);
    if (c.value === null) { ui.note(c.note); ui.setParams(s.params); return; }
    ui.note(c.note);
    const p = Object.assign({}, s.params);
    p[key] = c.value;
    ui.setParams(p);
    rebuild(p, c.note);
  }

  // A solver starts from its own substeps and iterations.
  function setSolver(name) {
    const d = scenes.SOLVERS[name];
    if (!d) throw new Error('unknown solver: ' + name);
    const p = Object.assign({}, s.params, { solver: name, substeps: d.substeps, iterations: d.iterations });
    rebuild(p, '');
  }

  // Reload the current scene with new parameters; a rejected scene leaves the old one.
  function rebuild(p, note) {
    try {
      if (s.preset !== 'custom') {
        usePreset(s.preset, p);
        ui.note(note);
      } else {
        const obj = Object.assign({}, s.sceneObj);
        obj.cols = p.cols; obj.rows = p.rows; obj.iterations = p.iterations; obj.substeps = p.substeps;
        obj.solver = p.solver;
        obj.damping = p.damping;
        obj.gravity = [Array.isArray(obj.gravity) ? obj.gravity[0] : 0, p.gravity];
        if (Array.isArray(obj.pins)) {
          obj.pins = obj.pins.filter(function (k) { return k < p.cols * p.rows; });
        }
        load(JSON.stringify(obj), 'custom', scenes.viewFor(obj));
      }
    } catch (e) {
      ui.setParams(s.params);  // the banner shows why; the old scene runs on
      ui.setSolver(s.params.solver);
    }
  }

  // ---- colour -------------------------------------------------------------

  function setColorMode(mode) {
    if (mode !== 'strain' && mode !== 'stress') throw new Error("colour mode must be 'strain' or 'stress'");
    s.mode = mode;
    ui.setMode(mode);
    s.dirty = true;
  }

  function setScaleMode(mode) {
    if (mode !== 'auto' && mode !== 'fixed') throw new Error("scale must be 'auto' or 'fixed'");
    s.scaleMode = mode;
    ui.setScale(s.scaleMode, s.fullScale);
    s.dirty = true;
  }

  function setFullScale(raw) {
    const c = scenes.clamp('fullScale', raw);
    ui.note(c.note);
    if (c.value !== null) s.fullScale = c.value;
    ui.setScale(s.scaleMode, s.fullScale);
    s.dirty = true;
  }

  function currentScale() {
    if (s.scaleMode === 'fixed') return s.fullScale;
    return s.mode === 'stress' ? s.cloth.max_stress : s.cloth.max_diff;
  }

  // ---- stepping and drawing -------------------------------------------------

  function simulate(n) {
    const m = s.m;
    const scripted = s.cloth.scene.actions.length;
    if (s.cloth.asleep && s.nextAction >= scripted) {
      // At rest (the core stopped stepping it): nothing to step, measure or draw until an
      // operation wakes it.
      s.frames += n;
      s.simMs = Number.isFinite(s.simMs) ? s.simMs + EMA * (0 - s.simMs) : 0;
      return;
    }
    const t0 = performance.now();
    // A scene's scripted actions play at their frames, as in the CLI (core.applyDue).
    for (let i = 0; i < n; i++) {
      if (s.nextAction < scripted) s.nextAction = core.applyDue(s.cloth, s.nextAction, s.frames + i);
      m.frame();
    }
    m.measure();
    // The core's max_speed safety net engaged: the settings are unstable (one sweep per
    // step on an undamped grid). Say so rather than let it pass silently.
    if (s.cloth.clamped > s.clamped) {
      s.clamped = s.cloth.clamped;
      ui.note('Unstable settings: speeds were capped at max_speed; use 2+ iterations, or damping');
    }
    const ms = (performance.now() - t0) / n;
    s.simMs = Number.isFinite(s.simMs) ? s.simMs + EMA * (ms - s.simMs) : ms;
    s.frames += n;
    s.needMeasure = false;
    s.dirty = true;
  }

  function render() {
    if (!s.cloth || !renderer.ok || renderer.lost) return;
    if (s.needMeasure) { s.m.measure(); s.needMeasure = false; }
    const t0 = performance.now();
    s.scale = currentScale();
    renderer.draw(s.cloth, s.mode, s.scale);
    const ms = performance.now() - t0;
    s.renderMs = Number.isFinite(s.renderMs) ? s.renderMs + EMA * (ms - s.renderMs) : ms;
    s.dirty = false;
    s.renders++;
  }

  function advance(frames) {
    const n = Math.max(0, Math.floor(Number(frames) || 0));
    if (n > 0) simulate(n);
    render();
    return s.frames;
  }

  function setPaused(paused) {
    s.paused = !!paused;
    s.acc = 0;
    ui.setPaused(s.paused);
  }

  function readouts(now) {
    if (now - s.lastReadout < READOUT_MS || !s.cloth) return;
    s.lastReadout = now;
    const c = s.cloth;
    ui.setReadouts({
      simMs: s.simMs, renderMs: s.renderMs, fps: s.fps, rms: c.rms_diff, max: c.max_diff,
      size: c.cols + '×' + c.rows + ' · ' + c.n_edges + ' edges' + (c.asleep ? ' · at rest' : ''),
    });
    ui.setLegend(s.scale, s.scaleMode === 'auto');
  }

  function tick(nowMs) {
    window.requestAnimationFrame(tick);
    const now = nowMs / 1000;
    let gap = s.last < 0 ? 0 : now - s.last;
    s.last = now;
    if (gap > 0) s.fps = Number.isFinite(s.fps) ? s.fps + EMA * (1 / gap - s.fps) : 1 / gap;
    if (gap > MAX_GAP) gap = MAX_GAP;
    try {
      if (!s.paused && s.cloth) {
        const dt = s.cloth.dt;
        s.acc += gap;
        let n = Math.floor(s.acc / dt);
        if (n > MAX_CATCHUP) { n = MAX_CATCHUP; s.acc = 0; } else { s.acc -= n * dt; }
        if (n > 0) simulate(n);
      }
      if (s.dirty) render();
    } catch (e) {
      setPaused(true);
      ui.error('Simulation stopped: ' + core.message(e));
    }
    readouts(nowMs);
  }

  // ---- geometry and input ---------------------------------------------------

  function toWorld(clientX, clientY) {
    const r = canvas.getBoundingClientRect();
    return renderer.toWorld(clientX - r.left, clientY - r.top);
  }

  const input = window.clothInput.attach(canvas, {
    toWorld: toWorld,
    pick: function (x, y, radiusCss) {
      if (!s.cloth || !renderer.ok) return -1;
      return s.m.nearest(x, y, radiusCss / renderer.pixelsPerMetre());
    },
    grab: function (k, x, y) { s.m.grab(k, x, y); s.needMeasure = true; s.dirty = true; },
    move: function (k, x, y) { s.m.move(k, x, y); s.needMeasure = true; s.dirty = true; },
    release: function (k) {
      if (k < s.cloth.n_verts) s.m.release(k);
      s.needMeasure = true; s.dirty = true;
    },
    togglePin: function (k) { s.m.toggle_pin(k); s.needMeasure = true; s.dirty = true; },
    isHeld: function (k) { return s.cloth.held[k] !== 0; },
  });

  function resizeFromRect() {
    if (!renderer.ok) return;
    const r = canvas.getBoundingClientRect();
    renderer.resize(r.width, r.height);
    s.dirty = true;
  }

  if (renderer.ok) {
    resizeFromRect();
    window.addEventListener('resize', resizeFromRect);
    if (window.ResizeObserver) {
      // device-pixel-content-box gives the exact drawing-buffer size (sharp at
      // fractional devicePixelRatio); where unsupported, round CSS size * dpr.
      const ro = new ResizeObserver(function (entries) {
        const e = entries[entries.length - 1];
        const css = e.contentBoxSize && e.contentBoxSize[0];
        let dev = e.devicePixelContentBoxSize && e.devicePixelContentBoxSize[0];
        const w = css ? css.inlineSize : e.contentRect.width;
        const h = css ? css.blockSize : e.contentRect.height;
        // Emulated device scale factors (devtools, test drivers) are not reflected
        // in the device-pixel box: trust it only when it agrees with CSS size * dpr.
        const dpr = window.devicePixelRatio || 1;
        if (dev && (Math.abs(dev.inlineSize - w * dpr) > 1 || Math.abs(dev.blockSize - h * dpr) > 1)) dev = null;
        renderer.resize(w, h, dev ? dev.inlineSize : 0, dev ? dev.blockSize : 0);
        s.dirty = true;
        render();  // same task as the resize: no blank frame
      });
      try { ro.observe(canvas, { box: 'device-pixel-content-box' }); } catch (e) { ro.observe(canvas); }
    }
  }

  // ---- test seam ----------------------------------------------------------

  window.clothApp = {
    // {positions: [[x, y]...] metres, screen: [[clientX, clientY]...], pinned: [bool...], held: [bool...]}
    state: function () {
      const c = s.cloth, n = c.n_verts, pos = c.pos;
      const r = canvas.getBoundingClientRect();
      const out = { positions: [], screen: [], pinned: [], held: [] };
      for (let k = 0; k < n; k++) {
        const x = pos[2 * k], y = pos[2 * k + 1];
        out.positions.push([x, y]);
        if (renderer.ok) {
          const p = renderer.toCanvas(x, y);
          out.screen.push([r.left + p[0], r.top + p[1]]);
        }
        out.pinned.push(c.pinned[k] !== 0);
        out.held.push(c.held[k] !== 0);
      }
      return out;
    },
    setPaused: setPaused,
    advance: advance,
    setColorMode: setColorMode,
    loadScene: loadScene,
    // Extras for tests and the console.
    setScaleMode: function (mode, fullScale) {
      if (fullScale !== undefined) setFullScale(fullScale);
      setScaleMode(mode);
    },
    usePreset: function (name) { usePreset(name); return true; },
    setParam: setParam,
    setSolver: setSolver,
    reset: reset,
    cloth: function () { return s.cloth; },
    // RGBA at client coordinates, read right after a fresh draw.
    pixels: function (points) {
      render();
      const r = canvas.getBoundingClientRect();
      return points.map(function (p) { return renderer.readPixel(p[0] - r.left, p[1] - r.top); });
    },
    info: function () {
      return {
        webgl: renderer.ok ? renderer.version : 0, lost: !!renderer.lost, restores: renderer.restores || 0,
        drawCalls: renderer.drawCalls || 0, paused: s.paused, mode: s.mode, scaleMode: s.scaleMode,
        scale: s.scale, fullScale: s.fullScale, frames: s.frames, preset: s.preset, params: s.params,
        asleep: !!(s.cloth && s.cloth.asleep), renders: s.renders,
        error: ui.errorText(), note: ui.noteText(), scene: s.sceneText,
        canvas: [canvas.width, canvas.height], dpr: window.devicePixelRatio || 1,
      };
    },
  };

  // ---- start --------------------------------------------------------------

  ui.setMode(s.mode);
  ui.setScale(s.scaleMode, s.fullScale);
  ui.setPaused(false);
  const first = query.get('preset');
  try {
    usePreset(first && scenes.PRESETS[first] ? first : 'curtain');
  } catch (e) {
    ui.fatal('The default scene failed to load: ' + e.message);
  }
  if (query.get('paused') === '1') setPaused(true);
  window.requestAnimationFrame(tick);
})();
