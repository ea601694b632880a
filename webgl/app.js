// The app: owns the current Cloth, runs the loop, wires renderer, input and UI,
// and publishes the test seam window.clothApp.
//
// Loop: the core advances a fixed dt per frame(); the wall clock appears only
// here. Elapsed time goes into an accumulator, capped at MAX_GAP (a tab switch
// or a stall becomes a short pause, never a huge step), and at most MAX_CATCHUP
// frames run per animation frame, and no more once FRAME_BUDGET_MS is spent (the
// rest of a backlog is dropped: a slow scene runs in slow motion and says so,
// instead of spiralling or making input wait for a burst of catch-up frames).
//
// Frames and actions: the state at frame f is the state after f frames and the actions of
// frame f (cloth/api.py simulate). The scene's own actions of frame f are applied as frame f
// ends (those of frame 0 at load), and a person's gestures between frame f and f + 1 are
// applied when they happen and recorded at frame f (recorder.js), so that the recording,
// run by the CLI, is what the page showed.
//
// Replay: a scene that says how many frames it was recorded for (`frames`) plays up to
// that frame and stops there, paused. A person who takes over before the end (a gesture, a
// setting) cuts the script at that frame and is recorded from there on.
'use strict';

(function () {
  const MAX_GAP = 0.25;        // seconds of wall clock counted per animation frame at most
  const MAX_CATCHUP = 4;       // core frames per animation frame at most
  const FRAME_BUDGET_MS = 12;  // simulation time per animation frame at most (one frame always runs)
  const SLOW_MOTION = 0.9;     // below this share of real time, the readout says "slow motion"
  const READOUT_MS = 250;      // readout refresh period
  const EMA = 0.1;             // smoothing of the timing readouts

  const core = window.clothCore, scenes = window.clothScenes;
  const canvas = document.getElementById('view');
  const options = window.clothOptions.parse(window.location.search, scenes.PRESETS);
  const own = window.clothOptions.own;

  const s = {
    cloth: null, m: null, sceneText: '', sceneObj: null, view: null,
    preset: 'curtain', params: null,
    mode: 'strain', scaleMode: 'auto', fullScale: 0.05,
    paused: false, acc: 0, last: -1, frames: 0, nextAction: 0, renders: 0, dirty: true, needMeasure: true,
    simMs: NaN, renderMs: NaN, fps: NaN, lastReadout: 0, scale: 0,
    wanted: 0, played: 0, speed: 1,   // seconds of wall clock and of simulation since the last readout
    replayEnd: -1,      // the frame a replay stops at, or -1 when none is playing
    replayEnded: false, // a replay stopped at its end and nothing has happened since
    pinEdits: {},       // vertex -> pinned: the pins a person set (true) or removed (false)
  };
  const recorder = window.clothRecorder.create();
  const share = window.clothShare;

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
    replay: function () { replay(); },
    exportFile: function () { exportRecording(); },
    copyLink: function () { copyLink(); },
    openFile: function (file) { openFile(file); },
  });

  const renderer = window.clothRenderer.create(canvas, {
    webgl: options.webgl,
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

  // The settings the panel shows, as the cloth has them now.
  function paramsOf(cloth) {
    return { cols: cloth.cols, rows: cloth.rows, iterations: cloth.iterations,
             substeps: cloth.substeps, gravity: cloth.scene.gravity_y,
             damping: cloth.scene.damping, solver: cloth.scene.solver };
  }

  // Load scene JSON text. On a bad scene: show the message, keep the old scene
  // running, and throw an Error with the core's message.
  // holds: [{id, k}] pointers that go on holding vertex k of the new cloth (a grid change);
  // any other pointer lets go.
  function load(text, preset, view, holds) {
    let cloth, obj;
    try {
      // The core checks the scene (its messages, as in the CLI); then the page's limits,
      // before anything is built: a scene beyond them would take seconds a frame.
      const scene = core.parseScene(text);
      obj = JSON.parse(text);
      const limit = scenes.pageLimit(obj);
      if (limit) throw new Error(limit);
      cloth = core.build(scene);
    } catch (e) {
      const msg = e && e.message ? e.message : String(e);
      ui.error('Scene not loaded: ' + msg + (s.cloth ? ' (the previous scene keeps running)' : ''));
      throw new Error(msg);
    }
    ui.clearError();
    input.releaseAll(holds || []);
    s.cloth = cloth;
    s.pinEdits = {};
    s.m = bind(cloth);
    s.clamped = 0;
    s.sceneText = text;
    s.sceneObj = obj;
    s.preset = preset;
    s.view = view || scenes.viewFor(obj);
    s.frames = 0;
    s.acc = 0;
    recorder.start(obj, window.clothRecorder.scriptOf(cloth), cloth.n_verts);
    s.replayEnd = typeof obj.frames === 'number' ? obj.frames : -1;
    s.replayEnded = false;
    s.nextAction = 0;
    script(0);              // the scene's own actions of frame 0 come before any frame
    s.params = paramsOf(cloth);
    s.simMs = NaN;            // timings and speed are the new scene's own
    s.wanted = 0; s.played = 0; s.speed = 1;
    if (renderer.ok) {
      renderer.setScene(cloth);
      renderer.setView(s.view);
    }
    // The pointers that kept a vertex hold it again, where it now is, keeping on with their
    // pointer from here (recorded as grabs, at frame 0 of the new recording).
    input.regrab();
    s.m.measure();
    s.needMeasure = false;
    s.dirty = true;
    ui.setPreset(preset);
    ui.setSolver(s.params.solver);
    ui.setParams(s.params);
    if (renderer.ok && !renderer.lost) render();
    const work = scenes.workOf(obj);
    if (work > scenes.REAL_TIME_WORK) {
      ui.note('This scene needs about ' + work.toExponential(1) + ' edge updates a frame: ' +
              'expect slow motion on an ordinary machine');
    }
    if (s.replayEnd === 0) endReplay();
    else if (s.replayEnd > 0) setPaused(false);
    return cloth;
  }

  // The scene's own actions due at frame f (cloth/api.py apply_due, the CLI's loop). A
  // scripted grab takes its vertex from a pointer that held it (the script moves it now,
  // and the pointer's release must not let go of the script's hold).
  function script(f) {
    const actions = s.cloth.scene.actions;
    if (s.nextAction >= actions.length || actions[s.nextAction].frame > f) return;
    const from = s.nextAction;
    s.nextAction = core.applyDue(s.cloth, s.nextAction, f);
    let settings = false;
    for (let i = from; i < s.nextAction; i++) {
      if (actions[i].op === 'grab') input.forget(actions[i].vertex);
      else if (actions[i].op === 'set') settings = true;
    }
    if (settings) { s.params = paramsOf(s.cloth); ui.setParams(s.params); ui.setSolver(s.params.solver); }
    s.needMeasure = true;
    s.dirty = true;
  }

  // ---- replay, recording, sharing ---------------------------------------------

  function endReplay() {
    s.replayEnd = -1;
    s.replayEnded = true;
    setPaused(true);
  }

  // A person acts (a gesture, a setting): a replay still playing is cut at this frame, the
  // script's holds are let go, and the recording goes on from here; a replay that ended
  // starts running again.
  function takeOver() {
    if (s.replayEnd >= 0) {
      s.replayEnd = -1;
      core.dropActionsAfter(s.cloth, s.frames);
      recorder.cut(s.frames);
      const c = s.cloth;
      for (let k = 0; k < c.n_verts; k++) {
        if (c.held[k] !== 0 && !input.holds(k)) { s.m.release(k); recorder.release(s.frames, k); }
      }
      s.dirty = true;
    }
    if (s.replayEnded) { s.replayEnded = false; setPaused(false); }
  }

  function recordingText() {
    return JSON.stringify(recorder.scene(recorder.complete(s.frames)));
  }

  function recordingName() {
    return 'cloth-' + (s.preset || 'scene') + '-' + recorder.complete(s.frames) + 'f.json';
  }

  // Restart the recording from frame 0 at real speed.
  function replay() {
    const text = recordingText();
    load(text, s.preset === 'custom' ? 'custom' : s.preset, s.view);
    ui.note('Replaying ' + s.replayEnd + ' frames; a gesture takes over');
  }

  function exportRecording() {
    const text = recordingText();
    share.download(text, recordingName());
    share.copy(text).then(function () {
      ui.note('Recording saved as ' + recordingName() + ' and copied');
    }, function () {
      ui.note('Recording saved as ' + recordingName() + ' (the browser kept the clipboard closed)');
    });
    return text;
  }

  function link() {
    return share.linkFor(recordingText());
  }

  function copyLink() {
    return link().then(function (url) {
      if (url.length > share.MAX_LINK) {
        ui.note('This recording makes a link of ' + url.length + ' characters, longer than the ' +
                share.MAX_LINK + ' a link may have: use Export to save it as a file');
        return url;
      }
      return share.copy(url).then(function () {
        ui.note('Link copied (' + url.length + ' characters): it replays this recording');
      }, function () {
        window.prompt('Copy this link (the browser kept the clipboard closed):', url);
      }).then(function () { return url; });
    });
  }

  function openFile(file) {
    share.readFile(file).then(function (text) {
      load(text, 'custom', null);
      ui.note('Opened ' + file.name);
    }).catch(function (e) {
      ui.error('Scene not loaded: ' + core.message(e) + ' (' + file.name + '; the previous scene keeps running)');
    });
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

  // Keys that leave the grid as it is apply to the running cloth (core.setScene): its
  // positions, speeds, pins and held vertices stay. Columns and rows make a new grid.
  const GRID_KEYS = { cols: 1, rows: 1 };

  function setParam(key, raw) {
    const c = scenes.clamp(key, raw);
    if (c.value === null) { ui.note(c.note); ui.setParams(s.params); return; }
    const p = Object.assign({}, s.params);
    p[key] = c.value;
    if (own(GRID_KEYS, key)) regrid(p, c.note);
    else retune(p, c.note);
  }

  // A solver starts from its own substeps and iterations.
  function setSolver(name) {
    const d = own(scenes.SOLVERS, name) ? scenes.SOLVERS[name] : null;
    if (!d) throw new Error('unknown solver: ' + name);
    retune(Object.assign({}, s.params, { solver: name, substeps: d.substeps, iterations: d.iterations }), '');
  }

  // The scene with the settings of p (those the panel shows) written into it.
  function withSettings(obj, p) {
    const out = Object.assign({}, obj);
    out.iterations = p.iterations;
    out.substeps = p.substeps;
    out.solver = p.solver;
    out.damping = p.damping;
    out.gravity = [Array.isArray(obj.gravity) ? obj.gravity[0] : 0, p.gravity];
    return out;
  }

  // New settings for the running cloth (the core's set: cloth/api.py set_settings, what a
  // recorded `set` action replays); a rejected one leaves everything as it was.
  function retune(p, note) {
    const keys = {};
    if (p.iterations !== s.params.iterations) keys.iterations = p.iterations;
    if (p.substeps !== s.params.substeps) keys.substeps = p.substeps;
    if (p.solver !== s.params.solver) keys.solver = p.solver;
    if (p.damping !== s.params.damping) keys.damping = p.damping;
    if (p.gravity !== s.params.gravity) keys.gravity = [s.cloth.scene.gravity_x, p.gravity];
    const obj = withSettings(s.sceneObj, p);
    try {
      const limit = scenes.pageLimit(obj);
      if (limit) throw new Error(limit);
      if (Object.keys(keys).length) {
        takeOver();
        core.setSettings(s.cloth, JSON.stringify(keys));
        recorder.set(s.frames, keys);
      }
    } catch (e) {
      ui.error('Setting not applied: ' + e.message + ' (the cloth runs on as it was)');
      ui.setParams(s.params);
      ui.setSolver(s.params.solver);
      return;
    }
    s.sceneObj = obj;
    s.sceneText = JSON.stringify(obj);   // Reset restarts with the new settings
    s.params = paramsOf(s.cloth);
    ui.setParams(s.params);
    ui.setSolver(s.params.solver);
    ui.note(note);
    s.dirty = true;
  }

  // A new grid. Pins keep their meaning, row and column: the preset's pins for the new size
  // (a custom scene's own pins and scripted actions, moved to the same row and column), with
  // the pins a person set or removed (s.pinEdits, kept over any number of grid changes)
  // written over them, and the vertices a hand holds held again. What falls outside the new
  // grid is dropped, and the note says so.
  function regrid(p, note) {
    const oldCols = s.cloth.cols;
    function moved(k) {
      const r = Math.floor(k / oldCols), c = k - r * oldCols;
      return r < p.rows && c < p.cols ? r * p.cols + c : -1;
    }
    function place(k) { return 'row ' + Math.floor(k / oldCols) + ' column ' + (k % oldCols); }
    const dropped = [];
    let obj, view, preset = s.preset;
    if (preset !== 'custom') {
      const made = scenes.make(preset, p);
      obj = made.scene; view = made.view;
    } else {
      obj = withSettings(s.sceneObj, p);
      obj.cols = p.cols; obj.rows = p.rows;
      delete obj.frames;      // a new grid is a new scene, not the recording it came from
      obj.pins = [];
      s.cloth.scene.pins.forEach(function (k) {
        const m = moved(k);
        if (m >= 0) obj.pins.push(m); else dropped.push('pin at ' + place(k));
      });
      if (Array.isArray(s.sceneObj.actions)) {
        let lost = 0;
        obj.actions = [];
        s.sceneObj.actions.forEach(function (a) {
          if (a.op === 'set') { obj.actions.push(a); return; }
          const m = moved(a.vertex);
          if (m >= 0) obj.actions.push(Object.assign({}, a, { vertex: m })); else lost++;
        });
        if (lost) dropped.push(lost + ' scripted action' + (lost > 1 ? 's' : ''));
      }
      view = scenes.viewFor(obj);
    }
    const pins = {};
    obj.pins.forEach(function (k) { pins[k] = true; });
    const edits = {};
    Object.keys(s.pinEdits).forEach(function (key) {
      const k = Number(key), m = moved(k), pinned = s.pinEdits[key];
      if (m < 0) { if (pinned) dropped.push('your pin at ' + place(k)); return; }
      edits[m] = pinned;
      if (pinned) pins[m] = true; else delete pins[m];
    });
    obj.pins = Object.keys(pins).map(Number).sort(function (x, y) { return x - y; });
    const holds = input.held().map(function (h) { return { k: moved(h.k), was: h.k, id: h.id }; });
    const text = JSON.stringify(obj);
    try {
      load(text, preset, view, holds);
    } catch (e) {
      ui.setParams(s.params);  // the banner shows why; the old scene runs on
      return;
    }
    s.pinEdits = edits;
    holds.forEach(function (h) { if (h.k < 0) dropped.push('the held vertex at ' + place(h.was)); });
    const notes = [];
    if (note) notes.push(note);
    if (ui.noteText().indexOf('slow motion') >= 0) notes.push(ui.noteText());   // load()'s warning
    if (dropped.length) {
      notes.push('outside the ' + p.cols + '×' + p.rows + ' grid, dropped: ' +
                 dropped.slice(0, 6).join(', ') + (dropped.length > 6 ? ', …' : ''));
    }
    ui.note(notes.join('; '));
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

  // Auto is the seed's normalisation by the frame's maximum, above a floor: a cloth at rest
  // has solver noise of up to about 1e-3, which must stay dark, not be painted as strain.
  const AUTO_FLOOR = 0.01;

  function frameMax() { return s.mode === 'stress' ? s.cloth.max_stress : s.cloth.max_diff; }

  function currentScale() {
    if (s.scaleMode === 'fixed') return s.fullScale;
    return Math.max(frameMax(), AUTO_FLOOR);
  }

  // ---- stepping and drawing -------------------------------------------------

  // Runs up to n frames; with a budget (ms), stops once it is spent (at least one frame
  // runs); a replay stops at its last frame. Returns the frames run.
  function simulate(n, budgetMs) {
    if (s.replayEnd >= 0) n = Math.min(n, s.replayEnd - s.frames);
    if (n <= 0) { atReplayEnd(); return 0; }
    const m = s.m;
    const scripted = s.cloth.scene.actions.length;
    if (s.cloth.asleep && s.nextAction >= scripted) {
      // At rest (the core stopped stepping it): nothing to step, measure or draw until an
      // operation wakes it.
      s.frames += n;
      s.simMs = NaN;   // nothing to time: the readout says "at rest"
      atReplayEnd();
      return n;
    }
    const t0 = performance.now();
    let done = 0;
    while (done < n) {
      m.frame();
      done++;
      s.frames++;
      if (s.nextAction < scripted) script(s.frames);
      if (budgetMs > 0 && performance.now() - t0 > budgetMs) break;
    }
    m.measure();
    // The core's max_speed safety net engaged: the settings are unstable (one sweep per
    // step on an undamped grid). Say so rather than let it pass silently.
    if (s.cloth.clamped > s.clamped) {
      s.clamped = s.cloth.clamped;
      // (Damping does not cure it: measured, 1.8 million capped vertex-steps with damping 1.)
      const speed = s.cloth.scene.max_speed;
      ui.note(speed < 1000
        ? 'Speeds were capped at the scene\'s max_speed of ' + speed + ' m/s'
        : 'Unstable settings: speeds were capped at max_speed; use more iterations or ' +
          'substeps, or the default solver');
    }
    const ms = (performance.now() - t0) / done;
    s.simMs = Number.isFinite(s.simMs) ? s.simMs + EMA * (ms - s.simMs) : ms;
    s.needMeasure = false;
    s.dirty = true;
    atReplayEnd();
    return done;
  }

  function atReplayEnd() {
    if (s.replayEnd >= 0 && s.frames >= s.replayEnd) endReplay();
  }

  // The overlays' boxes in client pixels (left, top, right, bottom each), measured on a
  // resize and with each readout, not per frame; an overlay over a held vertex fades.
  const overlayEls = [document.getElementById('legend'), document.getElementById('hud')];
  const overlayBox = new Float64Array(4 * overlayEls.length);
  const overlayUnder = [false, false];

  function measureOverlays() {
    for (let i = 0; i < overlayEls.length; i++) {
      const r = overlayEls[i].getBoundingClientRect();
      overlayBox[4 * i] = r.left; overlayBox[4 * i + 1] = r.top;
      overlayBox[4 * i + 2] = r.right; overlayBox[4 * i + 3] = r.bottom;
    }
  }

  function fadeOverlays() {
    const c = s.cloth, dragging = input.dragging() > 0 && renderer.ok;
    const cr = dragging ? canvasBox : null;
    for (let i = 0; i < overlayEls.length; i++) {
      let under = false;
      if (dragging) {
        const pad = 24;   // a finger's width around the vertex
        for (let k = 0; k < c.n_verts && !under; k++) {
          if (c.held[k] === 0) continue;
          const p = renderer.toCanvas(c.pos[2 * k], c.pos[2 * k + 1]);
          const x = cr[0] + p[0], y = cr[1] + p[1];
          under = x > overlayBox[4 * i] - pad && x < overlayBox[4 * i + 2] + pad &&
                  y > overlayBox[4 * i + 1] - pad && y < overlayBox[4 * i + 3] + pad;
        }
      }
      if (under !== overlayUnder[i]) { overlayUnder[i] = under; overlayEls[i].classList.toggle('under', under); }
    }
  }
  const canvasBox = new Float64Array(2);
  function measureCanvas() {
    const r = canvas.getBoundingClientRect();
    canvasBox[0] = r.left; canvasBox[1] = r.top;
  }

  function render() {
    if (!s.cloth || !renderer.ok || renderer.lost) return;
    fadeOverlays();
    if (s.needMeasure) { s.m.measure(); s.needMeasure = false; }
    const t0 = performance.now();
    s.scale = currentScale();
    renderer.draw(s.cloth, s.mode, s.scale);
    const ms = performance.now() - t0;
    s.renderMs = Number.isFinite(s.renderMs) ? s.renderMs + EMA * (ms - s.renderMs) : ms;
    s.dirty = false;
    s.renders++;
  }

  // Test seam: run `frames` frames now and draw them (with `undrawn`, leave the drawing to
  // the next animation frame: a script that steps thousands of times in one task would
  // otherwise queue a draw for each).
  function advance(frames, undrawn) {
    const n = Math.max(0, Math.floor(Number(frames) || 0));
    if (n > 0) simulate(n);
    if (!undrawn) render();
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
    measureOverlays();
    measureCanvas();
    const c = s.cloth;
    if (s.wanted > 0) s.speed = s.played / s.wanted;
    s.wanted = 0; s.played = 0;
    const slow = !s.paused && s.speed < SLOW_MOTION;
    ui.setReadouts({
      simMs: s.simMs, renderMs: s.renderMs, fps: s.fps, rms: c.rms_strain, max: c.max_strain,
      size: c.cols + '×' + c.rows + ' · ' + c.n_edges + (c.n_edges === 1 ? ' edge' : ' edges') + (c.asleep ? ' · at rest' : '') +
        (slow ? ' · slow motion ×' + s.speed.toFixed(2) : ''),
    });
    ui.setLegend(s.scale, s.scaleMode === 'fixed' ? 'fixed' : (frameMax() > AUTO_FLOOR ? 'max' : 'floor'));
    ui.setRecording({ frames: s.frames, actions: recorder.count(), full: recorder.full(),
                      complete: recorder.complete(s.frames), replayEnd: s.replayEnd });
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
        const due = Math.min(Math.floor(s.acc / dt), MAX_CATCHUP);
        const done = due > 0 ? simulate(due, FRAME_BUDGET_MS) : 0;
        // What the budget or the catch-up cap left undone is dropped, not owed: a slow scene
        // runs in slow motion (the readout says so) and input is handled every frame.
        s.acc = done < due || Math.floor(s.acc / dt) > MAX_CATCHUP ? 0 : s.acc - done * dt;
        s.wanted += gap;
        s.played += s.cloth.asleep ? gap : done * dt;
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

  // What a person does to the cloth: applied at once through the core, then recorded at the
  // current frame (recorder.js). A person acting during a replay takes over (takeOver).
  const input = window.clothInput.attach(canvas, {
    toWorld: toWorld,
    pick: function (x, y, radiusCss) {
      if (!s.cloth || !renderer.ok) return -1;
      return s.m.nearest(x, y, radiusCss / renderer.pixelsPerMetre());
    },
    positionOf: function (k) { return [s.cloth.pos[2 * k], s.cloth.pos[2 * k + 1]]; },
    grab: function (k, x, y) {
      takeOver();
      s.m.grab(k, x, y);
      recorder.grab(s.frames, k, x, y);
      touched();
    },
    move: function (k, x, y) {
      const pos = s.cloth.pos, x0 = pos[2 * k], y0 = pos[2 * k + 1];
      if (x === x0 && y === y0) return;       // a hand held still changes nothing
      takeOver();
      s.m.move(k, x, y);
      recorder.move(s.frames, k, x, y, x0, y0);
      touched();
    },
    release: function (k) {
      if (k >= s.cloth.n_verts || s.cloth.held[k] === 0) return;
      takeOver();
      s.m.release(k);
      recorder.release(s.frames, k);
      touched();
    },
    togglePin: function (k) {
      takeOver();
      const pinned = s.cloth.pinned[k] !== 0;
      s.m.toggle_pin(k);
      if (pinned) recorder.unpin(s.frames, k); else recorder.pin(s.frames, k);
      s.pinEdits[k] = !pinned;
      touched();
    },
    // Held by someone else: another pointer, or the scene's script (a replay's script lets go
    // when a person takes over, so its vertices can be grabbed then).
    isHeld: function (k) { return s.cloth.held[k] !== 0 && (s.replayEnd < 0 || input.holds(k)); },
  });

  function touched() {
    s.needMeasure = true;
    s.dirty = true;
  }

  function resizeFromRect() {
    if (!renderer.ok) return;
    const r = canvas.getBoundingClientRect();
    renderer.resize(r.width, r.height);
    input.reproject();
    measureOverlays();
    measureCanvas();
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
        input.reproject();   // a held vertex stays under its pointer through the resize
        measureOverlays();
        measureCanvas();
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
    // The recording since the last load or reset, as scene JSON text with `frames`.
    recording: recordingText,
    // A Promise of the link that replays the recording.
    link: link,
    replay: function () { replay(); return true; },
    exportRecording: exportRecording,
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
        replay: { playing: s.replayEnd >= 0, end: s.replayEnd, ended: s.replayEnded },
        linkPending: !!s.linkPending,
        recorded: recorder.count(), recordingFull: recorder.full(),
        error: ui.errorText(), note: ui.noteText(), scene: s.sceneText,
        canvas: [canvas.width, canvas.height], dpr: window.devicePixelRatio || 1,
      };
    },
  };

  // ---- start --------------------------------------------------------------

  ui.setMode(s.mode);
  ui.setScale(s.scaleMode, s.fullScale);
  ui.setPaused(false);
  try {
    usePreset(options.preset);
  } catch (e) {
    ui.fatal('The default scene failed to load: ' + e.message);
  }
  if (options.paused) setPaused(true);
  if (options.notes.length) ui.note(options.notes.join('. '));
  // A link: the scene (a recording) in the fragment replaces the preset once decoded; it
  // replays and stops at its last frame. One that cannot be read leaves the preset running.
  // A link pasted into the address bar of the open page changes only the fragment: the same.
  function openLink() {
    const linked = share.sceneIn(window.location.hash);
    if (!linked) return;
    setPaused(true);
    s.linkPending = true;
    linked.then(function (text) {
      load(text, 'custom', null);
      ui.note('Replaying the recording from the link (' + s.replayEnd + ' frames); a gesture takes over');
    }).catch(function (e) {
      if (s.preset !== options.preset) usePreset(options.preset);
      ui.error('The link could not be opened: ' + core.message(e) + '; showing the default scene');
      setPaused(options.paused);
    }).then(function () { s.linkPending = false; });
  }
  openLink();
  window.addEventListener('hashchange', openLink);
  window.requestAnimationFrame(tick);
})();
