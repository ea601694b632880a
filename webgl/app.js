// The app: runs the loop and wires the session (clothCore.session: the panels' cloths, their
// scripts, the recording, the replay), renderer, input, charts and UI, and publishes the test
// seam window.clothApp.
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
// applied when they happen and recorded at frame f by the session (cloth/session.py), so
// that the recording, run by the CLI, is what the page showed.
//
// Replay: a scene that says how many frames it was recorded for (`frames`) plays up to
// that frame and stops there, paused. A person who takes over before the end (a gesture, a
// setting) cuts the script at that frame and is recorded from there on (the session).
//
// Panels: a scene with a `compare` list runs once per entry, side by side (compare.js), each
// panel its own cloth with the entry's settings written in, all under the same hands (the
// session applies every gesture to each). A scene without one is a single panel.
'use strict';

(function () {
  const MAX_GAP = 0.25;        // seconds of wall clock counted per animation frame at most
  const MAX_CATCHUP = 4;       // core frames per animation frame at most
  const FRAME_BUDGET_MS = 12;  // simulation time per animation frame at most (one frame always runs)
  const SLOW_MOTION = 0.9;     // below this share of real time, the readout says "slow motion"
  const READOUT_MS = 250;      // readout refresh period
  const EMA = 0.1;             // smoothing of the timing readouts
  const CAPPED_NOTE_MS = 3000; // the max_speed note is said at most this often

  const core = window.clothCore, scenes = window.clothScenes, runner = window.clothRunner;
  const params = window.clothParams;
  const canvas = document.getElementById('view');
  const options = window.clothOptions.parse(window.location.search, scenes.PRESETS);
  const own = window.clothOptions.own;

  // A panel: {cloth, run (runner.js: ops, script index, batch timing), draw (its renderer
  // panel), snap (what the renderer reads of the cloth: clothCore.snapshot), simMs,
  // clamped}. state.cloth is the first panel's: the one the readouts, the recording's checks
  // and state() describe. state.base is a cloth that follows the scene's settings without the
  // panels' own (never stepped): what the settings panel shows.
  const state = {
    panels: [], cloth: null, base: null, sceneText: '', sceneObj: null, view: null,
    preset: 'curtain', params: null, compare: [],
    mode: 'strain', scaleMode: 'auto', fullScale: 0.05,
    paused: false, acc: 0, last: -1, renders: 0, dirty: true, needMeasure: true,
    renderMs: NaN, fps: NaN, lastReadout: 0, scale: 0,
    wanted: 0, played: 0, speed: 1,   // seconds of wall clock and of simulation since the last readout
    pinEdits: {},       // vertex -> pinned: the pins a person set (true) or removed (false)
    rects: [],          // the panels' rectangles in the canvas, CSS px
    trail: false,       // the blade's trail is fading out: keep drawing it
    linkPending: false, // a link is being copied (the clipboard answers later)
    slowWarning: '',    // what load() warned of a scene too heavy for real time ('' for none)
    relayouts: 0,       // how many times the views were laid out again (info(): the tests)
    cappedAt: -Infinity, // when the max_speed note was last said (performance.now ms)
    replaying: false,   // a replay was playing when the last note about it was said
  };
  // The scene's panels, their scripts, the recording and the replay: clothCore.session (the
  // core's cloth/session.py). Every gesture and setting goes to it, which applies it to every
  // panel and records it; the page never records beside it.
  const session = core.session;
  let sess = null;
  const share = window.clothShare;
  const blade = window.clothBlade.create(document.getElementById('blade'));
  let bladeOn = false;      // the Cut tool (touch and pen cut with it; a mouse with Alt too)

  const ui = window.clothUI.create({
    pause: function () { setPaused(!state.paused); },
    step: function () { setPaused(true); advance(1); sampleCharts(true); },
    reset: function () { reset(); },
    preset: function (name) { usePreset(name); },
    solver: function (name) { setSolver(name); },
    material: function (name) { setMaterial(name); },
    param: function (key, raw) { setParam(key, raw); },
    mode: function (m) { setColorMode(m || (state.mode === 'strain' ? 'stress' : 'strain')); },
    scaleMode: function (m) { setScaleMode(m || (state.scaleMode === 'auto' ? 'fixed' : 'auto')); },
    fullScale: function (raw) { setFullScale(raw); },
    loadJson: function (text) {
      let checked;
      try {
        checked = share.fromText(text);       // decoded as a file of the same bytes; size-checked
      } catch (e) {
        ui.error('Scene not loaded: ' + e.message + (state.cloth ? ' (the previous scene keeps running)' : ''));
        throw e;
      }
      loadScene(checked);
    },
    currentJson: function () { return JSON.stringify(state.sceneObj, null, 1); },
    replay: function () { replay(); },
    exportFile: function () { exportRecording(); },
    copyLink: function () { copyLink(); },
    openFile: function (file) { openFile(file); },
    charts: function (on) { setCharts(on); },
    cutTool: function (on) { setCutTool(on === undefined ? !bladeOn : on); },
  });

  const compareUI = window.clothCompare.create({
    change: function (list, note) { setCompare(list, note); },
    note: function (text) { ui.note(text); },
    running: function (i, key) { return i < state.panels.length ? state.panels[i].cloth.scene[key] : null; },
  });
  const charts = window.clothCharts.create(document.getElementById('charts'));

  const renderer = window.clothRenderer.create(canvas, {
    webgl: options.webgl,
    onLost: function () { ui.error('The WebGL context was lost; waiting for the browser to restore it.', 'context'); },
    onRestored: function () {
      ui.clearError('context');
      state.panels.forEach(function (p) { p.draw.setScene(core.snapshot(p.cloth, p.snap)); });
      state.dirty = true;
    },
    onError: function (msg) { ui.fatal(msg); },
  });
  if (!renderer.ok) ui.fatal(renderer.error);

  // ---- scenes -------------------------------------------------------------

  // The settings the panel shows, as a cloth has them now.
  function paramsOf(cloth) { return params.of(cloth.scene, cloth.cols, cloth.rows); }
  const limitOf = params.limitOf, withSettings = params.written;

  // Load scene JSON text. On a bad scene: show the message, keep the old scene
  // running, and throw an Error with the core's message.
  // holds: [{id, k}] pointers that go on holding vertex k of the new cloth (a grid change);
  // any other pointer lets go.
  function load(text, preset, view, holds) {
    let obj, opened;
    try {
      // The core checks the scene (its messages, as in the CLI); then the page's limits,
      // before anything is built: a scene beyond them would take seconds a frame.
      core.parseScene(text);
      obj = JSON.parse(text);
      const limit = limitOf(obj);
      if (limit) throw new Error(limit);
      opened = session.open(text);
    } catch (e) {
      const msg = e && e.message ? e.message : String(e);
      ui.error('Scene not loaded: ' + msg + (state.cloth ? ' (the previous scene keeps running)' : ''));
      throw new Error(msg);
    }
    ui.clearError();
    gestures.releaseAll(holds || []);
    state.compare = Array.isArray(obj.compare) ? obj.compare.map(function (o) { return Object.assign({}, o); }) : [];
    sess = opened;
    state.panels = sess.panels.map(function (cloth, i) {
      return { cloth: cloth, run: runner.panel(sess, i), draw: renderer.ok ? renderer.panel(i) : null,
               snap: core.snapshot(cloth), simMs: NaN, clamped: 0 };
    });
    state.cloth = sess.panels[0];
    state.base = sess.base;
    state.pinEdits = {};
    state.sceneText = text;
    state.sceneObj = obj;
    state.preset = preset;
    state.view = view || scenes.viewFor(obj);
    state.acc = 0;
    // The scene's own actions of frame 0 came before any frame (the session applied them): a
    // pointer kept over a grid change lets go of a vertex the script took.
    gestures.held().forEach(function (h) { if (state.cloth.held[h.k] !== 0) gestures.forget(h.k); });
    state.params = paramsOf(state.base);
    state.wanted = 0; state.played = 0; state.speed = 1;
    charts.reset(state.panels.length);
    compareUI.render(state.compare);
    if (renderer.ok) {
      state.panels.forEach(function (p) {
        p.draw.setScene(core.snapshot(p.cloth, p.snap));
        p.draw.setView(state.view);
      });
      layout();
    }
    // The pointers that kept a vertex hold it again, where it now is, keeping on with their
    // pointer from here (recorded as grabs, at frame 0 of the new recording).
    gestures.regrab();
    state.panels.forEach(function (p) { p.cloth.measure(); });
    state.needMeasure = false;
    state.dirty = true;
    ui.setPreset(preset);
    ui.setSolver(state.params.solver);
    ui.setParams(state.params);
    if (renderer.ok && !renderer.lost) render();
    const work = scenes.workOf(obj) * Math.max(1, state.compare.length);
    state.slowWarning = work > scenes.REAL_TIME_WORK ?
      'This scene needs about ' + work.toExponential(1) + ' edge updates a frame: ' +
      'expect slow motion on an ordinary machine' : '';
    if (state.slowWarning) ui.note(state.slowWarning);
    state.replaying = sess.replay_end > 0;
    if (sess.replay_end === 0) { session.atReplayEnd(sess); setPaused(true); }
    else if (sess.replay_end > 0) setPaused(false);
    return state.cloth;
  }

  // After the script's actions ran (`ran`: some did): a scripted grab took its vertex from a
  // person's hand (the session's `person`), so the pointer lets go of it here too, and its
  // release will not let go of the script's hold; a scripted set changes what the settings
  // panel shows.
  function scripted(ran) {
    state.params = paramsOf(state.base);
    if (!ran) return;
    if (gestures.count() > 0) {
      gestures.held().forEach(function (h) { if (sess.person[h.k] === 0) gestures.forget(h.k); });
    }
    sess.script_set = false;
    followSets();
    ui.setParams(state.params);
    ui.setSolver(state.params.solver);
    state.needMeasure = true;
    state.dirty = true;
  }

  // A set (the Scene section's or a script's) is written into every panel, the keys a panel
  // has of its own included: the compare list, its editor and a later grid change follow what
  // the panels run (params.running). Returns whether the list changed.
  function followSets() {
    if (!state.compare.length) return false;
    const now = params.running(state.compare, state.panels.map(function (p) { return p.cloth.scene; }));
    if (JSON.stringify(now) === JSON.stringify(state.compare)) return false;
    state.compare = now;
    compareUI.render(now);
    return true;
  }

  // ---- replay, recording, sharing ---------------------------------------------

  // A person acted (a gesture, a setting; the session took over a replay that was playing,
  // cutting its script at this frame): a replay that had ended runs again.
  function acted() {
    if (sess.resumed) { sess.resumed = false; setPaused(false); }
    if (state.replaying && sess.replay_end < 0) {
      state.replaying = false;
      ui.note('You took over the replay at frame ' + sess.frame + ': recording from here');
    }
    state.needMeasure = true;
    state.dirty = true;
  }

  function recordingText() {
    return session.recordingText(sess);
  }

  function recordingName() {
    return 'cloth-' + (state.preset || 'scene') + (state.compare.length ? '-compare' : '') + '-' +
      session.recordingComplete(sess) + 'f.json';
  }

  // Restart the recording from frame 0 at real speed.
  function replay() {
    const text = recordingText();
    load(text, state.preset === 'custom' ? 'custom' : state.preset, state.view);
    ui.note('Replaying ' + sess.replay_end + ' frames; a gesture takes over');
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

  // From the key or click handler itself (share.copyLater: WebKit's clipboard needs the
  // person's task). A link longer than share.MAX_LINK is not copied: the note offers Export.
  function copyLink() {
    const made = link();
    const fits = made.then(function (url) {
      if (url.length > share.MAX_LINK) throw new Error('too long');
      return url;
    });
    return share.copyLater(fits).then(function () {
      return made.then(function (url) {
        ui.note('Link copied (' + url.length + ' characters): it replays this recording');
        return url;
      });
    }, function () {
      return made.then(function (url) {
        if (url.length > share.MAX_LINK) {
          ui.note('This recording makes a link of ' + url.length + ' characters, longer than the ' +
                  share.MAX_LINK + ' a link may have: use Export to save it as a file');
        } else {
          window.prompt('Copy this link (the browser kept the clipboard closed):', url);
        }
        return url;
      });
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

  // A preset keeps compare mode: the same panels run the new scene.
  function usePreset(name, params) {
    const made = scenes.make(name, params || scenes.defaults(name));
    if (state.compare.length) made.scene.compare = state.compare;
    ui.note('');
    return load(JSON.stringify(made.scene), name, made.view);
  }

  function reset() {
    return load(state.sceneText, state.preset, state.view);
  }

  function loadScene(text) {
    if (typeof text !== 'string') text = JSON.stringify(text);
    load(text, 'custom', null);
    return true;
  }

  // Compare mode: the current scene (its grid, pins, script and settings) with a new compare
  // list, from frame 0 and a new recording; [] leaves compare mode.
  function setCompare(list, note) {
    if (!Array.isArray(list)) throw new Error('compare needs an array of objects of scene keys');
    const obj = Object.assign({}, state.sceneObj);
    delete obj.frames;
    if (list.length) obj.compare = list; else delete obj.compare;
    try {
      load(JSON.stringify(obj), state.preset, state.view);
    } catch (e) {
      compareUI.render(state.compare);   // the banner says why; the old panels run on
      return false;
    }
    ui.note(note || (list.length ? 'Comparing ' + list.length + ' panels under the same hands, from frame 0' : ''));
    return true;
  }

  function setCutTool(on) {
    bladeOn = !!on;
    ui.setCutTool(bladeOn);
    canvas.classList.toggle('cutting', bladeOn);
  }

  function setCharts(on) {
    document.getElementById('charts').hidden = !on;
    if (on) charts.draw();
    relayout();
  }

  // Keys that leave the grid as it is apply to the running cloth (core.setSettings): its
  // positions, speeds, pins and held vertices stay. Columns and rows make a new grid.
  const GRID_KEYS = { cols: 1, rows: 1 };

  function setParam(key, raw) {
    const c = scenes.clamp(key, raw);
    if (c.value === null) { ui.note(c.note); ui.setParams(state.params); return; }
    const p = Object.assign({}, state.params);
    p[key] = c.value;
    if (own(GRID_KEYS, key)) regrid(p, c.note);
    else retune(p, c.note);
  }

  // A solver starts from its own substeps and iterations.
  function setSolver(name) {
    const d = own(scenes.SOLVERS, name) ? scenes.SOLVERS[name] : null;
    if (!d) throw new Error('unknown solver: ' + name);
    retune(Object.assign({}, state.params, { solver: name, substeps: d.substeps, iterations: d.iterations }), '');
  }

  // A named fabric: its density and stiffness, set like every setting (recorded as a `set` of
  // density and compliance).
  function setMaterial(name) {
    if (!own(scenes.MATERIALS, name)) { ui.setParams(state.params); return; }
    retune(Object.assign({}, state.params, { material: name }), '');
  }

  // New settings for the running cloth (the core's set: cloth/api.py set_settings, what a
  // recorded `set` action replays), in every panel: keys a panel has of its own are set too,
  // as the recording's `set` sets them; a rejected one leaves everything as it was.
  function retune(p, note) {
    const keys = params.changed(state.params, p, state.base.scene.gravity_x);
    const obj = withSettings(state.sceneObj, p);
    try {
      const limit = limitOf(obj);
      if (limit) throw new Error(limit);
      if (Object.keys(keys).length) {
        session.change(sess, JSON.stringify(keys));
        acted();
      }
    } catch (e) {
      ui.error('Setting not applied: ' + e.message + ' (the cloth runs on as it was)', 'setting');
      ui.setParams(state.params);
      ui.setSolver(state.params.solver);
      return;
    }
    if (followSets()) {
      obj.compare = state.compare;
      note = (note ? note + '; ' : '') + 'set in every panel, over the panels\' own values (the compare editor shows what each runs)';
    }
    // A Solver or Material change that leaves a material unused says so (cloth/scene.py).
    const unused = keys.solver !== undefined || keys.compliance !== undefined ? core.unused(state.base) : '';
    if (unused) note = (note ? note + '; ' : '') + unused.charAt(0).toUpperCase() + unused.slice(1);
    state.sceneObj = obj;
    state.sceneText = JSON.stringify(obj);   // Reset restarts with the new settings
    state.params = paramsOf(state.base);
    ui.setParams(state.params);
    ui.setSolver(state.params.solver);
    ui.clearError('setting');     // a refused setting's banner ends with one that applies
    ui.note(note);
    state.dirty = true;
  }

  // A new grid (grid.js): pins keep their meaning, row and column; the pins a person set or
  // removed are written over the new scene's, and the vertices a hand holds held again. What
  // falls outside the new grid is dropped, and the note says so.
  function regrid(p, note) {
    const m = window.clothGrid.mover(state.cloth.cols, p.cols, p.rows);
    const dropped = [];
    let obj, view, preset = state.preset;
    if (preset !== 'custom') {
      const made = scenes.make(preset, p);
      obj = made.scene; view = made.view;
      if (state.compare.length) obj.compare = state.compare;
    } else {
      obj = window.clothGrid.moveScene(withSettings(state.sceneObj, p), state.cloth.scene.pins, m, p.cols, p.rows, dropped);
      if (state.compare.length) obj.compare = state.compare;   // as the panels run (followSets)
      view = scenes.viewFor(obj);
    }
    const edits = window.clothGrid.applyEdits(obj, state.pinEdits, m, dropped);
    const holds = gestures.held().map(function (h) { return { k: m.moved(h.k), was: h.k, id: h.id }; });
    try {
      load(JSON.stringify(obj), preset, view, holds);
    } catch (e) {
      ui.setParams(state.params);  // the banner shows why; the old scene runs on
      return;
    }
    state.pinEdits = edits;
    holds.forEach(function (h) { if (h.k < 0) dropped.push('the held vertex at ' + m.place(h.was)); });
    const notes = [note, state.slowWarning, window.clothGrid.droppedNote(dropped, p.cols, p.rows)];
    ui.note(notes.filter(function (t) { return !!t; }).join('; '));
  }

  // ---- colour -------------------------------------------------------------

  function setColorMode(mode) {
    if (mode !== 'strain' && mode !== 'stress') throw new Error("colour mode must be 'strain' or 'stress'");
    state.mode = mode;
    ui.setMode(mode);
    state.dirty = true;
  }

  function setScaleMode(mode) {
    if (mode !== 'auto' && mode !== 'fixed') throw new Error("scale must be 'auto' or 'fixed'");
    state.scaleMode = mode;
    ui.setScale(state.scaleMode, state.fullScale);
    state.dirty = true;
  }

  function setFullScale(raw) {
    const c = scenes.clamp('fullScale', raw);
    ui.note(c.note);
    if (c.value !== null) state.fullScale = c.value;
    ui.setScale(state.scaleMode, state.fullScale);
    state.dirty = true;
  }

  // Auto is the seed's normalisation by the frame's maximum, above a floor: solver noise on an
  // inextensible cloth at rest (1e-7 on a curtain, up to 1e-3 in a slack hang's rows) stays
  // dark, while a material's own strain (jersey hung 1.5 m: 0.6% at the rod) fills the scale
  // from the hem to the pins. One scale for every panel: the largest of them, so a colour
  // means one strain everywhere.
  const AUTO_FLOOR = 0.002;
  document.getElementById('auto-floor').textContent = String(AUTO_FLOOR);

  function frameMax() {
    let top = 0;
    for (let i = 0; i < state.panels.length; i++) {
      const c = state.panels[i].cloth;
      const v = state.mode === 'stress' ? c.max_stress : c.max_diff;
      if (v > top) top = v;
    }
    return top;
  }

  function currentScale() {
    if (state.scaleMode === 'fixed') return state.fullScale;
    return Math.max(frameMax(), AUTO_FLOOR);
  }

  // ---- stepping and drawing -------------------------------------------------

  function allAsleep() {
    for (let i = 0; i < state.panels.length; i++) {
      const p = state.panels[i];
      if (!p.cloth.asleep || sess.script_next[i] < p.cloth.scene.actions.length) return false;
    }
    return true;
  }

  // Runs up to n frames in every panel; with a budget (ms), stops once it is spent (at least
  // one frame runs; the first panel decides how many, and the others run as many); a replay
  // stops at its last frame. Returns the frames run.
  function simulate(n, budgetMs) {
    n = session.framesLeft(sess, n);
    if (n <= 0) { atReplayEnd(); return 0; }
    const from = sess.script_next[0];
    if (allAsleep()) {
      // At rest (the core stopped stepping them): nothing to step, measure or draw until an
      // operation wakes them.
      session.framesRan(sess, n, from);
      state.panels.forEach(function (p) { p.run.frame += n; p.simMs = NaN; });
      atReplayEnd();
      return n;
    }
    const share_ = state.panels.length > 1 ? budgetMs / state.panels.length : budgetMs;
    const done = runner.stepPanel(state.panels[0].run, sess, 0, n, budgetMs > 0 ? share_ : 0);
    for (let i = 1; i < state.panels.length; i++) runner.stepPanel(state.panels[i].run, sess, i, done, 0);
    session.framesRan(sess, done, from);
    scripted(sess.script_next[0] > from || sess.script_set);
    for (let i = 0; i < state.panels.length; i++) {
      const p = state.panels[i];
      p.cloth.measure();
      const ms = p.cloth.asleep ? NaN : p.run.ms / done;
      p.simMs = Number.isFinite(p.simMs) && Number.isFinite(ms) ? p.simMs + EMA * (ms - p.simMs) : ms;
      // The core's max_speed safety net engaged. Say so rather than let it pass silently,
      // and say why: a hand that moved faster than the cloth can follow (metres in a frame),
      // or settings that pump energy (one sweep per step on an undamped grid).
      // At most once every CAPPED_NOTE_MS: settings that cap every frame (a tiny max_speed)
      // would otherwise hide every other note, a refused field's among them.
      if (p.cloth.clamped > p.clamped) {
        p.clamped = p.cloth.clamped;
        const now = performance.now();
        if (!(now - state.cappedAt < CAPPED_NOTE_MS)) {
          state.cappedAt = now;
          ui.note((state.panels.length > 1 ? 'Panel ' + (i + 1) + ': ' : '') + cappedNote(p.cloth));
        }
      }
    }
    state.needMeasure = false;
    state.dirty = true;
    atReplayEnd();
    return done;
  }

  function cappedNote(cloth) {
    const speed = cloth.scene.max_speed;
    const capped = 'speeds were capped at ' + (speed < 1000 ? 'the scene\'s max_speed of ' : 'max_speed, ') + speed + ' m/s';
    if (cloth.n_held > 0) return 'A very fast drag: ' + capped + ' (the hand moved faster than the cloth can follow)';
    if (speed < 1000) return capped.charAt(0).toUpperCase() + capped.slice(1);
    // (Damping does not cure it: measured, 1.8 million capped vertex-steps with damping 1.)
    return 'Unstable settings: ' + capped + '; use more iterations or substeps' +
      (cloth.use_xpbd ? '' : ', or the default solver');
  }

  function atReplayEnd() {
    if (session.atReplayEnd(sess)) { state.replaying = false; setPaused(true); }
  }

  const overlays = window.clothOverlays.create(canvas, [document.getElementById('legend'),
    document.getElementById('hud'), document.getElementById('charts')], document.getElementById('overlays'));
  // Every held vertex of every panel, and its hand (which a hand of finite strength's vertex
  // may lag behind or stop short of), in canvas CSS px, to `visit` until it says stop.
  function heldPoints(visit) {
    for (let j = 0; j < state.panels.length; j++) {
      const c = state.panels[j].cloth, d = state.panels[j].draw;
      for (let k = 0; k < c.n_verts; k++) {
        if (c.held[k] === 0) continue;
        const p = d.toCanvas(c.pos[2 * k], c.pos[2 * k + 1]);
        if (visit(p[0], p[1])) return true;
        const q = d.toCanvas(c.target[2 * k], c.target[2 * k + 1]);
        if (visit(q[0], q[1])) return true;
      }
    }
    return false;
  }

  function render() {
    if (!state.cloth || !renderer.ok || renderer.lost) return;
    overlays.fade(gestures.count() > 0 && renderer.ok, heldPoints);
    if (state.needMeasure) { state.panels.forEach(function (p) { p.cloth.measure(); }); state.needMeasure = false; }
    const t0 = performance.now();
    state.scale = currentScale();
    renderer.begin();
    for (let i = 0; i < state.panels.length; i++) {
      const p = state.panels[i];
      p.draw.draw(core.snapshot(p.cloth, p.snap), state.mode, state.scale);
    }
    const ms = performance.now() - t0;
    state.renderMs = Number.isFinite(state.renderMs) ? state.renderMs + EMA * (ms - state.renderMs) : ms;
    state.dirty = false;
    state.renders++;
  }

  // Test seam: run `frames` frames now and draw them (with `undrawn`, leave the drawing to
  // the next animation frame: a script that steps thousands of times in one task would
  // otherwise queue a draw for each).
  function advance(frames, undrawn) {
    const n = Math.max(0, Math.floor(Number(frames) || 0));
    if (n > 0) simulate(n);
    if (!undrawn) render();
    return sess.frame;
  }

  function setPaused(paused) {
    state.paused = !!paused;
    state.acc = 0;
    ui.setPaused(state.paused);
  }

  function fmt(v) { return window.clothUI.fmt(v, 4); }

  function readouts(now) {
    if (now - state.lastReadout < READOUT_MS || !state.cloth) return;
    state.lastReadout = now;
    overlays.measure();
    const c = state.cloth;
    if (state.wanted > 0) state.speed = state.played / state.wanted;
    state.wanted = 0; state.played = 0;
    const slow = !state.paused && state.speed < SLOW_MOTION;
    let simMs = 0;
    state.panels.forEach(function (p) { if (Number.isFinite(p.simMs)) simMs += p.simMs; });
    ui.setReadouts({
      simMs: allAsleep() ? NaN : simMs, renderMs: state.renderMs, fps: state.fps, rms: c.rms_strain, max: c.max_strain,
      size: c.cols + '×' + c.rows + ' · ' + c.n_edges + (c.n_edges === 1 ? ' edge' : ' edges') +
        (c.broken > 0 ? ' left of ' + (c.n_edges + c.broken) : '') +
        (state.panels.length > 1 ? ' · ' + state.panels.length + ' panels' : '') + (allAsleep() ? ' · at rest' : '') +
        (slow ? ' · slow motion ×' + state.speed.toFixed(2) : ''),
    });
    ui.setLegend(state.scale, state.scaleMode === 'fixed' ? 'fixed' : (frameMax() > AUTO_FLOOR ? 'max' : 'floor'));
    ui.setRecording({ frames: sess.frame, actions: session.recordingCount(sess), full: session.recordingFull(sess),
                      complete: session.recordingComplete(sess), replayEnd: sess.replay_end });
    if (state.panels.length > 1) {
      state.panels.forEach(function (p, i) {
        // A narrow panel (a phone, four panels) gets the short label: the solver and its
        // steps; the RMS strain and the cost. The numbers come first on their line and are
        // never cut (compare.js).
        const r = state.rects[i], small = !r || r.w < 340, label = runner.label(p.cloth);
        const ms = Number.isFinite(p.simMs) ? p.simMs.toFixed(2) + (small ? ' ms' : ' ms/frame') : 'at rest';
        compareUI.setLabel(i, (i + 1) + ' · ' + (small ? label.split(',')[0] : label),
          small ? 'rms ' + fmt(p.cloth.rms_strain) + ' · ' + ms
                : 'strain rms ' + fmt(p.cloth.rms_strain) + ' · max ' + fmt(p.cloth.max_strain) + ' · ' + ms);
      });
    }
  }

  // Charts: a sample of each panel every clothCharts.SAMPLE_MS while the simulation runs, and
  // one for every frame stepped by hand.
  function panelRms(i) { return state.panels[i].cloth.rms_strain; }
  function panelMs(i) { return state.panels[i].simMs; }
  function sampleCharts(every) {
    if (charts.sample(performance.now(), panelRms, panelMs, every) && !document.getElementById('charts').hidden) charts.draw();
  }

  function tick(nowMs) {
    window.requestAnimationFrame(tick);
    const now = nowMs / 1000;
    let gap = state.last < 0 ? 0 : now - state.last;
    state.last = now;
    if (gap > 0) state.fps = Number.isFinite(state.fps) ? state.fps + EMA * (1 / gap - state.fps) : 1 / gap;
    if (gap > MAX_GAP) gap = MAX_GAP;
    try {
      if (!state.paused && state.cloth) {
        const dt = state.cloth.dt;
        state.acc += gap;
        const due = Math.min(Math.floor(state.acc / dt), MAX_CATCHUP);
        const done = due > 0 ? simulate(due, FRAME_BUDGET_MS) : 0;
        // What the budget or the catch-up cap left undone is dropped, not owed: a slow scene
        // runs in slow motion (the readout says so) and input is handled every frame.
        state.acc = done < due || Math.floor(state.acc / dt) > MAX_CATCHUP ? 0 : state.acc - done * dt;
        state.wanted += gap;
        state.played += allAsleep() ? gap : done * dt;
        sampleCharts(false);
      }
      if (state.dirty) render();
      if (state.trail) state.trail = blade.draw(performance.now());
    } catch (e) {
      setPaused(true);
      ui.error('Simulation stopped: ' + core.message(e));
    }
    readouts(nowMs);
  }

  // ---- geometry and input ---------------------------------------------------

  // The panels' rectangles for the canvas's size, above the overlays' band (one panel: all
  // of the canvas, its view fitted above the band).
  function layout() {
    if (!renderer.ok) return;
    const n = state.panels.length, v = state.view, w = renderer.cssWidth, h = renderer.cssHeight - overlays.band();
    state.rects = n > 1
      ? window.clothCompare.layout(n, w, h, v.x1 - v.x0, v.y1 - v.y0)
      : [{ x: 0, y: 0, w: w, h: h }];
    state.panels.forEach(function (p, i) {
      const r = state.rects[i];
      // A panel's cloth is fitted below its label (two lines, compare.js), where there is room.
      const top = n > 1 && r.h > 3 * LABEL_HEIGHT ? LABEL_HEIGHT : 0;
      if (n > 1) p.draw.setRect(r.x, r.y, r.w, r.h);
      else p.draw.setRect();
      p.draw.setFit(r.x, r.y + top, r.w, r.h - top);
    });
    compareUI.placeLabels(n > 1 ? state.rects : []);
  }

  const LABEL_HEIGHT = 44;    // CSS px: a panel label's two lines, its padding and offset

  // The panel under a point of the canvas (CSS px), or -1.
  function panelAt(cx, cy) {
    for (let i = 0; i < state.panels.length; i++) if (state.panels[i].draw.contains(cx, cy)) return i;
    return -1;
  }

  // Pointers (input.js) become gestures (gestures.js) on the views below, and a gesture
  // becomes the actions after them: applied at once through the core, in every panel, then
  // recorded at the current frame by the session. A person acting during a replay takes over.
  const gestures = window.clothGestures.create({
    // client px -> {panel, x, y} world metres in the panel under the point (panel -1: none)
    locate: function (clientX, clientY) {
      const r = canvas.getBoundingClientRect(), cx = clientX - r.left, cy = clientY - r.top;
      const i = renderer.ok ? panelAt(cx, cy) : -1;
      const w = i >= 0 ? state.panels[i].draw.toWorld(cx, cy) : [NaN, NaN];
      return { panel: i, x: w[0], y: w[1] };
    },
    toWorld: function (panel, clientX, clientY) {
      const r = canvas.getBoundingClientRect();
      return state.panels[Math.min(panel, state.panels.length - 1)].draw.toWorld(clientX - r.left, clientY - r.top);
    },
    pick: function (panel, x, y, radiusCss) {
      if (!state.cloth || !renderer.ok || panel < 0) return -1;
      const p = state.panels[panel];
      return p.run.ops.nearest(x, y, radiusCss / p.draw.pixelsPerMetre());
    },
    positionOf: function (panel, k) {
      const pos = state.panels[Math.min(panel, state.panels.length - 1)].cloth.pos;
      return [pos[2 * k], pos[2 * k + 1]];
    },
    // Held by someone else: another pointer, or the scene's script (a replay's script lets go
    // when a person takes over, so its vertices can be grabbed then).
    isHeld: function (k) { return state.cloth.held[k] !== 0 && (sess.replay_end < 0 || gestures.holds(k)); },
    bladeOn: function () { return bladeOn; },
    trail: function (clientX, clientY, start) {
      const r = canvas.getBoundingClientRect();
      blade.add(clientX - r.left, clientY - r.top, performance.now(), start);
      state.trail = true;
    },
  }, {
    // The actions: each goes to the session, which applies it to every panel and records it
    // (one cloth: the hand takes hold at (x, y) and goes where the pointer takes it; compare
    // mode: each panel's hand holds its own vertex where it is and moves by the pointer's
    // displacement, cloth/session.py).
    grab: function (k, x, y) { session.grab(sess, k, x, y); acted(); },
    move: function (k, x, y) { if (session.move(sess, k, x, y)) acted(); },
    release: function (k) { if (session.release(sess, k)) acted(); },
    togglePin: function (k) {
      state.pinEdits[k] = state.cloth.pinned[k] === 0;
      session.togglePin(sess, k);
      acted();
    },
    cut: function (x0, y0, x1, y1) { if (session.cut(sess, x0, y0, x1, y1)) acted(); },
  });
  window.clothInput.attach(canvas, gestures);

  function resized(w, h, devW, devH) {
    renderer.resize(w, h, devW, devH);
    relayout();
  }

  // The views laid out again (a resize, the charts shown or hidden): a held vertex stays under
  // its pointer, and the overlays' and the canvas's boxes are measured anew.
  function relayout() {
    state.relayouts++;
    layout();
    gestures.reproject();
    overlays.measure();
    state.dirty = true;
  }

  if (renderer.ok) {
    const r0 = canvas.getBoundingClientRect();
    resized(r0.width, r0.height);
    window.addEventListener('resize', function () {
      const r = canvas.getBoundingClientRect();
      resized(r.width, r.height);
    });
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
        resized(w, h, dev ? dev.inlineSize : 0, dev ? dev.blockSize : 0);
        render();  // same task as the resize: no blank frame
        if (!document.getElementById('charts').hidden) charts.draw();
      });
      try { ro.observe(canvas, { box: 'device-pixel-content-box' }); } catch (e) { ro.observe(canvas); }
    }
  }

  // ---- test seam ----------------------------------------------------------

  // {positions: [[x, y]...] metres, screen: [[clientX, clientY]...], pinned, held, hands} of
  // panel i; hands[k]: for a held vertex, where its hand is (clientX, clientY: the pointer's
  // point in the cloth, which a hand of finite strength takes its vertex toward), else null.
  function stateOf(i) {
    const p = state.panels[i], c = p.cloth, n = c.n_verts, pos = c.pos;
    const r = canvas.getBoundingClientRect();
    const out = { positions: [], screen: [], pinned: [], held: [], hands: [] };
    for (let k = 0; k < n; k++) {
      const x = pos[2 * k], y = pos[2 * k + 1];
      out.positions.push([x, y]);
      if (renderer.ok) {
        const q = p.draw.toCanvas(x, y);
        out.screen.push([r.left + q[0], r.top + q[1]]);
      }
      out.pinned.push(c.pinned[k] !== 0);
      out.held.push(c.held[k] !== 0);
      if (c.held[k] !== 0 && renderer.ok) {
        const q = p.draw.toCanvas(c.target[2 * k], c.target[2 * k + 1]);
        out.hands.push([r.left + q[0], r.top + q[1]]);
      } else {
        out.hands.push(null);
      }
    }
    return out;
  }

  window.clothApp = {
    // The first panel's (the only one outside compare mode).
    state: function () { return stateOf(0); },
    setPaused: setPaused,
    advance: advance,
    // The recording since the last load or reset, as scene JSON text with `frames`.
    recording: recordingText,
    // A Promise of the link that replays the recording.
    link: link,
    replay: function () { replay(); return true; },
    exportRecording: exportRecording,
    // Compare mode: an array of objects of scene keys, one per panel ([] leaves it).
    compare: function (list) { return setCompare(list); },
    // Per panel: {label, scene (the panel's full scene JSON text), positions, screen,
    // rms_strain, max_strain, sim_ms}, and pinned, held, max_diff, max_stress.
    panels: function () {
      return state.panels.map(function (p, i) {
        const st = stateOf(i);
        const obj = Object.assign({}, state.sceneObj);
        delete obj.compare;
        if (state.compare.length) Object.assign(obj, state.compare[i]);
        return { label: runner.label(p.cloth), scene: JSON.stringify(obj), positions: st.positions,
                 screen: st.screen, rms_strain: p.cloth.rms_strain, max_strain: p.cloth.max_strain,
                 sim_ms: p.simMs, pinned: st.pinned, held: st.held, hands: st.hands, max_diff: p.cloth.max_diff,
                 max_stress: p.cloth.max_stress };
      });
    },
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
    setCutTool: setCutTool,
    reset: reset,
    cloth: function () { return state.cloth; },
    // What the charts wrote at their last draw: [text, x, y, width, box x, y, w, h].
    chartTexts: function () { return charts.written(); },
    // RGBA at client coordinates, read right after a fresh draw.
    pixels: function (points) {
      render();
      const r = canvas.getBoundingClientRect();
      return points.map(function (p) { return renderer.readPixel(p[0] - r.left, p[1] - r.top); });
    },
    info: function () {
      let simMs = NaN;
      if (state.panels.length) simMs = state.panels[0].simMs;
      return {
        webgl: renderer.ok ? renderer.version : 0, lost: !!renderer.lost, restores: renderer.restores || 0,
        relayouts: state.relayouts,
        drawCalls: renderer.drawCalls || 0, paused: state.paused, mode: state.mode, scaleMode: state.scaleMode,
        scale: state.scale, fullScale: state.fullScale, autoFloor: AUTO_FLOOR, frames: sess ? sess.frame : 0, preset: state.preset, params: state.params,
        asleep: !!(state.cloth && allAsleep()), renders: state.renders,
        replay: { playing: sess.replay_end >= 0, end: sess.replay_end, ended: sess.replay_ended },
        linkPending: !!state.linkPending, panels: state.panels.length, simMs: simMs, chartLatest: charts.latest(0),
        edges: state.cloth ? state.cloth.n_edges : 0, broken: state.cloth ? state.cloth.broken : 0, cutTool: bladeOn,
        recorded: session.recordingCount(sess), recordingFull: session.recordingFull(sess),
        error: ui.errorText(), note: ui.noteText(), scene: state.sceneText,
        canvas: [canvas.width, canvas.height], dpr: window.devicePixelRatio || 1,
      };
    },
  };

  // ---- start --------------------------------------------------------------

  ui.setMode(state.mode);
  ui.setScale(state.scaleMode, state.fullScale);
  // On a small stage (a phone) the charts start hidden: with the readouts they would take
  // most of it. The Live charts box shows them.
  {
    const r = canvas.getBoundingClientRect();
    if (r.width < 420 || r.height < 420) {
      document.getElementById('charts-on').checked = false;
      document.getElementById('charts').hidden = true;
    }
  }
  ui.setPaused(false);
  try {
    usePreset(options.preset);
  } catch (e) {
    ui.fatal('The default scene failed to load: ' + e.message);
  }
  if (options.paused) setPaused(true);
  if (options.notes.length) ui.note(options.notes.join('. '));
  // A link: the scene (a recording) in the fragment replaces the preset once decoded; it
  // replays and stops at its last frame. One that cannot be read leaves what runs running
  // (the URL's preset, on opening), and says which it is. A link pasted into the address bar
  // of the open page changes only the fragment: the same, over whatever the person had.
  function openLink() {
    const linked = share.sceneIn(window.location.hash);
    if (!linked) return;
    const wasPaused = state.paused;
    setPaused(true);
    state.linkPending = true;
    linked.then(function (text) {
      load(text, 'custom', null);
      ui.note('Replaying the recording from the link (' + sess.replay_end + ' frames); a gesture takes over');
    }).catch(function (e) {
      const shown = own(scenes.PRESETS, state.preset)
        ? 'showing the ' + scenes.PRESETS[state.preset].label + ' preset' : 'the scene shown runs on';
      ui.error('The link could not be opened: ' + core.message(e) + '; ' + shown);
      setPaused(wasPaused);
    }).then(function () { state.linkPending = false; });
  }
  openLink();
  window.addEventListener('hashchange', openLink);
  window.requestAnimationFrame(tick);
})();
