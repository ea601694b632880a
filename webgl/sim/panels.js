// The simulation's side of the page: the session (clothCore.session, cloth/session.py: the
// scene's panels under one pair of hands, their scripts, the recording and the replay) and a
// snapshot of each panel (clothCore.snapshot) for everything that draws or reads it out. The
// only page module that holds the core's cloths and calls the session: the drawing, the input
// and the UI see snapshots and call these functions.
//
// Frames and actions: the state at frame f is the state after f frames and the actions of
// frame f (cloth/api.py simulate). The scene's own actions of frame f are applied as frame f
// ends (those of frame 0 at load), and a person's gestures between frame f and f + 1 are
// applied when they happen and recorded at frame f by the session, so that the recording, run
// by the CLI, is what the page showed.
import { clothCore } from './core.js';
import { clothRunner } from './runner.js';

export const clothPanels = (function () {
  const core = clothCore, session = core.session, runner = clothRunner;
  const EMA = 0.1;             // smoothing of a panel's sim time (ms a frame)

  function create() {
    let sess = null;
    // list[i]: {cloth, run (runner.js: ops and batch timing), snap (what the renderer draws),
    // read (what the readouts say: clothCore.readings), simMs}
    let list = [];
    let reads = [], times = [];    // each panel's readings and sim time (ms a frame), in order
    let ran = false;           // the last simulate() applied some of the scripts' actions
    let stale = false;         // a gesture or setting changed the cloths since the last measure

    // Opens scene JSON text (already checked against the page's limits): its panels replace
    // the old ones. Throws the core's Error on a bad scene, changing nothing.
    function open(text) {
      const opened = session.open(text);
      sess = opened;
      list = sess.panels.map(function (cloth, i) {
        return { cloth: cloth, run: runner.panel(sess, i), snap: core.snapshot(cloth), read: core.readings(cloth),
                 simMs: NaN };
      });
      reads = list.map(function (p) { return p.read; });
      times = list.map(function () { return NaN; });
      measure();
    }

    // What the page says of a scene it opened ('' for nothing): an older model's scene runs
    // as a membrane; vertices that start inside an obstacle are pushed out, tangled.
    function openNotes() {
      const notes = [];
      const legacy = core.notes(list[0].cloth).legacy;
      if (legacy) notes.push('This scene was ' + legacy);
      const inside = list[0].cloth.n_obstacles > 0 ? list[0].run.ops.inside_obstacles() : 0;
      if (inside > 0) {
        notes.push(inside + (inside === 1 ? ' vertex starts' : ' vertices start') + ' inside an obstacle: the first ' +
                   'step pushes them out, which tangles the cloth; move the obstacle or the cloth in the scene');
      }
      return notes;
    }

    // Every panel at rest (the core stopped stepping it) with no scripted action to come.
    function asleep() {
      for (let i = 0; i < list.length; i++) {
        if (!list[i].cloth.asleep || sess.script_next[i] < list[i].cloth.scene.actions.length) return false;
      }
      return true;
    }

    // The measures the colours and readouts show, and the snapshots, brought up to date.
    function measure() {
      for (let i = 0; i < list.length; i++) {
        list[i].run.ops.measure();
        core.snapshot(list[i].cloth, list[i].snap);
        core.readings(list[i].cloth, list[i].read);
      }
      stale = false;
    }

    // The snapshots and readings of the cloths as they are.
    function snapshots() {
      for (let i = 0; i < list.length; i++) {
        core.snapshot(list[i].cloth, list[i].snap);
        core.readings(list[i].cloth, list[i].read);
      }
    }

    // Before a drawing: the snapshots, measured again if a gesture changed the cloths (once a
    // drawing, not once a pointer event).
    function refresh() {
      if (stale) measure();
      else snapshots();
    }

    // Runs up to n frames in every panel; with a budget (ms), stops once it is spent (at least
    // one frame runs; the first panel decides how many, and the others run as many); a replay
    // stops at its last frame. Returns the frames run.
    function simulate(n, budgetMs) {
      ran = false;
      n = session.framesLeft(sess, n);
      if (n <= 0) return 0;
      const from = sess.script_next[0];
      if (asleep()) {
        // At rest: nothing to step or measure until an operation wakes them.
        session.framesRan(sess, n, from);
        for (let i = 0; i < list.length; i++) { list[i].run.frame += n; list[i].simMs = NaN; times[i] = NaN; }
        return n;
      }
      const each = list.length > 1 ? budgetMs / list.length : budgetMs;
      const done = runner.stepPanel(list[0].run, sess, 0, n, budgetMs > 0 ? each : 0);
      for (let i = 1; i < list.length; i++) runner.stepPanel(list[i].run, sess, i, done, 0);
      session.framesRan(sess, done, from);
      ran = sess.script_next[0] > from;
      for (let i = 0; i < list.length; i++) {
        const p = list[i];
        const ms = p.cloth.asleep ? NaN : p.run.ms / done;
        p.simMs = Number.isFinite(p.simMs) && Number.isFinite(ms) ? p.simMs + EMA * (ms - p.simMs) : ms;
        times[i] = p.simMs;
      }
      measure();
      return done;
    }

    // A person's gestures and settings: each applied to every panel and recorded at the
    // current frame (cloth/session.py); each says whether it did anything.
    function acted(did) { if (did) stale = true; return did; }

    return {
      remote: false,
      open: open, openNotes: openNotes, asleep: asleep, measure: measure, refresh: refresh, snapshots: snapshots,
      simulate: simulate,
      // Whether the last simulate() applied some of the scripts' actions.
      scriptRan: function () { return ran; },
      count: function () { return list.length; },
      snap: function (i) { return list[i].snap; },
      read: function (i) { return list[i].read; },
      simMs: function (i) { return list[i].simMs; },
      // Every panel's readings, and sim times (arrays kept for the scene: read, never changed).
      reads: function () { return reads; },
      times: function () { return times; },
      // Panel i's running scene (its keys as the cloth has them now).
      scene: function (i) { return list[i].cloth.scene; },
      // What the settings panel shows: the keys of a cloth that follows the scene's settings
      // without the panels' own (never stepped).
      baseScene: function () { return sess.base.scene; },
      label: function (i) { return runner.label(list[i].cloth); },
      headline: function (i) { return runner.headline(list[i].cloth); },
      // The vertex nearest (x, y) in panel i within `radius` metres, or -1; the obstacle there.
      nearest: function (i, x, y, radius) { return list[i].run.ops.nearest(x, y, radius); },
      obstacleUnder: function (i, x, y) { return list[i].run.ops.obstacle_under(x, y); },
      // The script's and a person's holds: held by either (first panel); by a person.
      held: function (k) { return list[0].cloth.held[k] !== 0; },
      byPerson: function (k) { return sess.person[k] !== 0; },
      frame: function () { return sess ? sess.frame : 0; },
      // The replay's last frame (-1: nothing replays), and whether it ended there.
      replayEnd: function () { return sess.replay_end; },
      replayEnded: function () { return sess.replay_ended; },
      atReplayEnd: function () { return session.atReplayEnd(sess); },
      // A person's gesture resumed a replay that had ended (said once).
      resumed: function () { const r = sess.resumed; sess.resumed = false; return r; },
      grab: function (k, x, y) { session.grab(sess, k, x, y); return acted(true); },
      move: function (k, x, y) { return acted(session.move(sess, k, x, y)); },
      release: function (k) { return acted(session.release(sess, k)); },
      togglePin: function (k) { session.togglePin(sess, k); return acted(true); },
      cut: function (x0, y0, x1, y1) { return acted(session.cut(sess, x0, y0, x1, y1)); },
      obstacle: function (j, x, y) { return acted(session.obstacle(sess, j, x, y)); },
      // New settings (JSON text of scene keys) in every panel; throws, changing nothing.
      change: function (keysText) { session.change(sess, keysText); stale = true; },
      unusedNote: function () { return core.notes(sess.base).unused; },
      recordingText: function () { return session.recordingText(sess); },
      // then(text): the recording (at once here; later from a Worker, remote.js).
      recording: function (then) { then(session.recordingText(sess)); },
      recordingCount: function () { return session.recordingCount(sess); },
      recordingFull: function () { return session.recordingFull(sess); },
      recordingComplete: function () { return session.recordingComplete(sess); },
      // The live session and cloth of panel i, for the test seam only.
      session: function () { return sess; },
      cloth: function (i) { return list[i].cloth; },
    };
  }

  return { create: create };
})();
