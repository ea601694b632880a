// The app: runs the loop and wires the session (clothCore.session: the panels' cloths, their
// scripts, the recording, the replay), renderer, input, charts and UI, and publishes the test
// seam (seam.js: window.clothApp).
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
// Panels: a scene with a `compare` list runs once per entry, side by side (stage.js), each
// panel its own cloth with the entry's settings written in, all under the same hands (the
// session applies every gesture to each). A scene without one is a single panel.
import { clothBlade } from './draw/blade.js';
import { clothCapture } from './draw/capture.js';
import { clothCharts } from './draw/charts.js';
import { clothCompare } from './ui/compare.js';
import { clothCore } from './sim/core.js';
import { clothGestures } from './input/gestures.js';
import { clothInput } from './input/input.js';
import { clothObstacles } from './draw/obstacles.js';
import { clothOptions } from './sim/options.js';
import { clothOverlays } from './draw/overlays.js';
import { clothParams } from './sim/params.js';
import { clothReadouts } from './ui/readouts.js';
import { clothRenderer } from './draw/renderer.js';
import { clothRunner } from './sim/runner.js';
import { clothScenes } from './sim/scenes.js';
import { clothSeam } from './ui/seam.js';
import { clothSettings } from './ui/settings.js';
import { clothShare } from './sim/share.js';
import { clothStage } from './draw/stage.js';
import { clothUI } from './ui/ui.js';

(function () {
  const MAX_GAP = 0.25;        // seconds of wall clock counted per animation frame at most
  const MAX_CATCHUP = 4;       // core frames per animation frame at most
  const FRAME_BUDGET_MS = 12;  // simulation time per animation frame at most (one frame always runs)
  const READOUT_MS = 250;      // readout refresh period
  const EMA = 0.1;             // smoothing of the sim readout

  const core = clothCore, scenes = clothScenes, runner = clothRunner;
  const params = clothParams, stage = clothStage;
  const canvas = document.getElementById('view');
  const options = clothOptions.parse(window.location.search, scenes.PRESETS);
  const own = clothOptions.own;

  // A panel: {cloth, run (runner.js: ops, script index, batch timing), draw (its renderer
  // panel), snap (what the renderer reads of the cloth: clothCore.snapshot), simMs}.
  // state.cloth is the first panel's: the one the readouts, the recording's checks
  // and state() describe. state.base is a cloth that follows the scene's settings without the
  // panels' own (never stepped): what the settings panel shows.
  const state = {
    panels: [], cloth: null, base: null, sceneText: '', sceneObj: null, view: null,
    preset: null, params: null, compare: [],
    mode: 'strain', scaleMode: 'auto', fullScale: 0.05, charts: true,
    paused: false, acc: 0, last: -1, renders: 0, dirty: true, needMeasure: true,
    renderMs: NaN, fps: NaN, fpsAt: NaN, lastReadout: 0, scale: 0,
    timeDraw: true,     // the next drawing is timed to completion (once a readout period)
    wanted: 0, played: 0, speed: 1,   // seconds of wall clock and of simulation since the last readout
    pinEdits: {},       // vertex -> pinned: the pins a person set (true) or removed (false)
    rects: [],          // the panels' rectangles in the canvas, CSS px
    trail: false,       // the blade's trail is fading out: keep drawing it
    linkPending: false, // a link is being copied (the clipboard answers later)
    slowWork: 0,        // a frame's edge updates, where load() warned they are too many for real time
    loadNote: '',       // what load() said of the scene it loaded ('' for nothing)
    relayouts: 0,       // how many times the views were laid out again (info(): the tests)
    replaying: false,   // a replay was playing when the last note about it was said
  };
  // The scene's panels, their scripts, the recording and the replay: clothCore.session (the
  // core's cloth/session.py). Every gesture and setting goes to it, which applies it to every
  // panel and records it; the page never records beside it.
  const session = core.session;
  let sess = null;
  const share = clothShare;
  const blade = clothBlade.create(document.getElementById('blade'));
  const obstacles = clothObstacles.create(document.getElementById('obstacles'));
  // Picture and Video: the stage as drawn, the cloth's canvas and the obstacles' over it.
  const capture = clothCapture.create([canvas, document.getElementById('obstacles')],
                                             function (blob, name) { share.download(blob, name); },
                                             function (text) { ui.note(text); });
  let bladeOn = false;      // the Cut tool (touch and pen cut with it; a mouse with Alt too)

  const ui = clothUI.create({
    pause: function () { setPaused(!state.paused); },
    step: function () { setPaused(true); advance(1); sampleCharts(true); },
    reset: function () { reset(); },
    preset: function (name) { usePreset(name); },
    solver: function (name) { settings.setSolver(name); },
    material: function (name) { settings.setMaterial(name); },
    param: function (key, raw) { settings.setParam(key, raw); },
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
    picture: function () { savePicture(); },
    video: function () { ui.setVideo(capture.toggleVideo(mediaName())); },
    openFile: function (file) { openFile(file); },
    charts: function (on) { setCharts(on); },
    cutTool: function (on) { setCutTool(on === undefined ? !bladeOn : on); },
  });

  const compareUI = clothCompare.create({
    change: function (list, note) { setCompare(list, note); },
    note: function (text) { ui.note(text); },
    running: function (i, key) { return i < state.panels.length ? state.panels[i].cloth.scene[key] : null; },
  });
  const charts = clothCharts.create(document.getElementById('charts'));

  const renderer = clothRenderer.create(canvas, {
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

  // The settings the panel shows, as a cloth has them now; the page's limits on a scene.
  const paramsOf = clothSettings.paramsOf, limitOf = params.limitOf;

  // Load scene JSON text. On a bad scene: show the message, keep the old scene
  // running, and throw an Error with the core's message.
  // holds: [{id, k}] pointers that go on holding vertex k of the new cloth (a grid change);
  // any other pointer lets go. pinEdits: the pins a person set or removed that the new scene
  // carries over (a grid change), {} otherwise.
  function load(text, preset, view, holds, pinEdits) {
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
               snap: core.snapshot(cloth), simMs: NaN };
    });
    state.cloth = sess.panels[0];
    state.base = sess.base;
    state.pinEdits = pinEdits || {};
    state.sceneText = text;
    state.sceneObj = obj;
    state.preset = preset;
    state.view = view || scenes.viewFor(obj);
    state.acc = 0;
    // The scene's own actions of frame 0 came before any frame (the session applied them): a
    // pointer kept over a grid change lets go of a vertex the script took.
    gestures.held().forEach(function (h) { if (state.cloth.held[h.k] !== 0) gestures.forget(h.k); });
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
    state.panels.forEach(function (p) { p.run.ops.measure(); });
    state.needMeasure = false;
    state.dirty = true;
    ui.setPreset(preset);
    showSettings();
    if (renderer.ok && !renderer.lost) render();
    // What the page says of the new scene, all of it in one note (one said after another
    // replaced it: a heavy scene of an older model said only that it was old).
    const notes = [];
    const work = scenes.workOf(obj) * Math.max(1, state.compare.length);
    state.slowWork = work > scenes.REAL_TIME_WORK ? work : 0;
    if (state.slowWork) notes.push(scenes.slowNote(state.slowWork));
    // A scene made under an older model runs as a membrane: said, with what became of its keys.
    const legacy = core.notes(state.cloth).legacy;
    if (legacy) notes.push('This scene was ' + legacy);
    // A scene that starts its cloth inside an obstacle: pushed out at once, tangled.
    const inside = state.cloth.n_obstacles > 0 ? state.panels[0].run.ops.inside_obstacles() : 0;
    if (inside > 0) {
      notes.push(inside + (inside === 1 ? ' vertex starts' : ' vertices start') + ' inside an obstacle: the first ' +
                 'step pushes them out, which tangles the cloth; move the obstacle or the cloth in the scene');
    }
    state.loadNote = notes.join('; ');
    if (state.loadNote) ui.note(state.loadNote);
    state.replaying = sess.replay_end > 0;
    if (sess.replay_end === 0) { session.atReplayEnd(sess); setPaused(true); }
    else if (sess.replay_end > 0) setPaused(false);
    return state.cloth;
  }

  // After the script's actions ran (`ran`: some did): a scripted grab took its vertex from a
  // person's hand (the session's `person`), so the pointer lets go of it here too, and its
  // release will not let go of the script's hold; a scripted set changes what the settings
  // panel and the compare editor show. Nothing ran: nothing to do (this runs every frame).
  function scripted(ran) {
    if (!ran) return;
    if (gestures.count() > 0) {
      gestures.held().forEach(function (h) { if (sess.person[h.k] === 0) gestures.forget(h.k); });
    }
    showSettings();
    settings.followSets();
    state.needMeasure = true;
    state.dirty = true;
  }

  // The settings panel shows what the scene's settings are now (state.base's).
  function showSettings() {
    state.params = paramsOf(state.base);
    ui.setParams(state.params);
    ui.setSolver(state.params.solver);
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


  // Restart the recording from frame 0 at real speed.
  function replay() {
    const text = recordingText();
    load(text, state.preset, state.view);
    ui.note(clothReadouts.replayNote(sess.replay_end, ''));
  }

  function exportRecording() {
    return share.exportText(recordingText(), share.fileName(state.preset, state.compare.length > 0,
                                                            session.recordingComplete(sess)), ui.note);
  }

  function link() {
    return share.linkFor(recordingText());
  }

  function copyLink() {
    return share.copyLink(recordingText(), ui.note);
  }

  // A picture's or a video's name: the preset (or 'scene') and the frame it starts at.
  function mediaName() { return 'cloth-' + (state.preset || 'scene') + '-f' + (sess ? sess.frame : 0); }

  // Drawn now and saved in the same task (the WebGL canvas keeps its pixels until shown).
  function savePicture() {
    if (!renderer.ok) { ui.note('Picture: there is no WebGL drawing to save'); return null; }
    render();
    return capture.picture(mediaName());
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

  // A new start: what the notes said of the old one is over.
  function reset() {
    ui.note('');
    return load(state.sceneText, state.preset, state.view);
  }

  function loadScene(text) {
    if (typeof text !== 'string') text = JSON.stringify(text);
    ui.note('');      // what the notes said of the old scene is over (load may say something new)
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
    state.charts = !!on;
    ui.setCharts(state.charts);
    if (on) charts.draw();
    relayout();
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
    const each = state.panels.length > 1 ? budgetMs / state.panels.length : budgetMs;
    const done = runner.stepPanel(state.panels[0].run, sess, 0, n, budgetMs > 0 ? each : 0);
    for (let i = 1; i < state.panels.length; i++) runner.stepPanel(state.panels[i].run, sess, i, done, 0);
    session.framesRan(sess, done, from);
    scripted(sess.script_next[0] > from);
    for (let i = 0; i < state.panels.length; i++) {
      const p = state.panels[i];
      p.run.ops.measure();
      const ms = p.cloth.asleep ? NaN : p.run.ms / done;
      p.simMs = Number.isFinite(p.simMs) && Number.isFinite(ms) ? p.simMs + EMA * (ms - p.simMs) : ms;
    }
    state.needMeasure = false;
    state.dirty = true;
    atReplayEnd();
    return done;
  }

  function atReplayEnd() {
    if (session.atReplayEnd(sess)) { state.replaying = false; setPaused(true); }
  }

  const overlays = clothOverlays.create(canvas, [document.getElementById('legend'),
    document.getElementById('hud'), document.getElementById('charts')], document.getElementById('overlays'));
  function heldPoints(visit) { return stage.heldPoints(state.panels, visit); }

  function render() {
    if (!state.cloth || !renderer.ok || renderer.lost) return;
    overlays.fade(gestures.count() > 0 && renderer.ok, heldPoints);
    if (state.needMeasure) { state.panels.forEach(function (p) { p.run.ops.measure(); }); state.needMeasure = false; }
    const t0 = performance.now();
    const timed = state.timeDraw;
    state.scale = clothReadouts.scaleOf(state.panels, state.mode, state.scaleMode, state.fullScale);
    renderer.begin();
    for (let i = 0; i < state.panels.length; i++) {
      const p = state.panels[i];
      p.draw.draw(core.snapshot(p.cloth, p.snap), state.mode, state.scale);
    }
    obstacles.draw(state.panels, state.rects, gestures.moving());
    capture.drawn();
    // The render readout: one drawing a readout period, timed until WebGL's finish() returns
    // (one wait every READOUT_MS, not one a frame: a wait a frame would stall the pipeline).
    if (timed) {
      renderer.finish();
      state.renderMs = performance.now() - t0;
      state.timeDraw = false;
    }
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

  const numbers = clothReadouts.create(ui, compareUI, runner);
  const frameTimes = clothReadouts.frameClock();
  function readouts(now) {
    if (now - state.lastReadout < READOUT_MS || !state.cloth) return;
    state.lastReadout = now;
    state.timeDraw = true;
    state.fps = frameTimes.rate();
    state.fpsAt = state.last;
    overlays.measure();
    if (state.wanted > 0) state.speed = state.played / state.wanted;
    state.wanted = 0; state.played = 0;
    numbers.show(state, allAsleep());
    ui.setRecording({ frames: sess.frame, actions: session.recordingCount(sess), full: session.recordingFull(sess),
                      complete: session.recordingComplete(sess), replayEnd: sess.replay_end });
  }

  // Charts: a sample of each panel every SAMPLE_MS (charts.js) while the simulation runs, and
  // one for every frame stepped by hand.
  function panelRms(i) { return state.panels[i].cloth.rms_strain; }
  function panelMs(i) { return state.panels[i].simMs; }
  function sampleCharts(every) {
    if (charts.sample(performance.now(), panelRms, panelMs, every) && state.charts) charts.draw();
  }

  function tick(nowMs) {
    window.requestAnimationFrame(tick);
    const now = nowMs / 1000;
    let gap = state.last < 0 ? 0 : now - state.last;
    state.last = now;
    frameTimes.push(now);
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
      if (state.dirty || capture.recording()) render();
      if (state.trail) state.trail = blade.draw(performance.now());
    } catch (e) {
      setPaused(true);
      ui.error('Simulation stopped: ' + core.message(e));
    }
    readouts(nowMs);
  }

  // ---- geometry and input ---------------------------------------------------

  // The panels' rectangles for the canvas's size, above the overlays' band (stage.js).
  function layout() {
    if (!renderer.ok) return;
    state.rects = stage.layout(state.panels, state.view, renderer.cssWidth, renderer.cssHeight - overlays.band());
    compareUI.placeLabels(state.panels.length > 1 ? state.rects : []);
  }
  // Pointers (input.js) become gestures (gestures.js) on the views below, and a gesture
  // becomes the actions after them: applied at once through the core, in every panel, then
  // recorded at the current frame by the session. A person acting during a replay takes over.
  const gestures = clothGestures.create({
    // client px -> {panel, x, y} world metres in the panel under the point (panel -1: none)
    locate: function (clientX, clientY) {
      return renderer.ok ? stage.locate(canvas, state.panels, clientX, clientY) : { panel: -1, x: NaN, y: NaN };
    },
    toWorld: function (panel, clientX, clientY) {
      return stage.toWorld(canvas, state.panels[Math.min(panel, state.panels.length - 1)], clientX, clientY);
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
    obstacleAt: function (panel, x, y) {
      return state.cloth ? state.panels[panel].run.ops.obstacle_under(x, y) : -1;
    },
    centreOf: function (j) { return [state.cloth.obstacle_to[2 * j], state.cloth.obstacle_to[2 * j + 1]]; },
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
    obstacle: function (j, x, y) { if (session.obstacle(sess, j, x, y)) acted(); },
  });
  clothInput.attach(canvas, gestures);

  // The panel's settings (settings.js): a `set` through the session, or a new grid.
  const settings = clothSettings.create({
    state: state, sess: function () { return sess; }, load: load, acted: acted, ui: ui, gestures: gestures,
    followed: function (list) { state.compare = list; compareUI.render(list); },
    // Reset restarts with the new settings.
    retuned: function (obj) {
      state.sceneObj = obj;
      state.sceneText = JSON.stringify(obj);
      showSettings();
      state.dirty = true;
    },
  });

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
    stage.watch(canvas, function (w, h, devW, devH, observed) {
      renderer.resize(w, h, devW, devH);
      relayout();
      if (!observed) return;
      render();  // same task as the resize: no blank frame
      if (state.charts) charts.draw();
    });
  }

  // ---- test seam ----------------------------------------------------------

  clothSeam.publish({
    state: function () { return state; }, sess: function () { return sess; }, canvas: canvas,
    renderer: renderer, charts: charts, ui: ui, runner: runner, session: session,
    bladeOn: function () { return bladeOn; }, allAsleep: allAsleep, autoFloor: clothReadouts.AUTO_FLOOR, render: render,
    setPaused: setPaused, advance: advance, recordingText: recordingText, link: link, replay: replay,
    exportRecording: exportRecording, setCompare: setCompare, setColorMode: setColorMode,
    loadScene: loadScene, setScaleMode: setScaleMode, setFullScale: setFullScale, usePreset: usePreset,
    setParam: settings.setParam, setSolver: settings.setSolver, setCutTool: setCutTool, reset: reset,
  });

  // ---- start --------------------------------------------------------------

  ui.setMode(state.mode);
  ui.setScale(state.scaleMode, state.fullScale);
  // On a small stage (a phone) the charts start hidden: with the readouts they would take
  // most of it. The Live charts box shows them.
  {
    const r = canvas.getBoundingClientRect();
    if (r.width < 420 || r.height < 420) { state.charts = false; ui.setCharts(false); }
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
      ui.note(clothReadouts.replayNote(sess.replay_end, 'the link'));
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
