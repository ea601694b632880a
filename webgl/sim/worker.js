// The session in a Web Worker: the same panels (panels.js) as on the page's own thread, driven
// by messages, each panel's state posted back for the page to draw. Linked by build.py into a
// script of its own, which the page starts as a Worker from a Blob (remote.js); never run on the
// page's thread.
//
// The Worker keeps the simulation's own clock (clock.js): while the page runs it, it steps the
// frames due at wall-clock rate, whatever the page's drawing rate, in slices of at most
// SLICE_MS (gestures are taken between them, each at the frame the session is at, so that a
// recording replays bit for bit), and posts its state when the page has taken the last one
// (the page acknowledges each: a page that draws 3 frames a second is sent 3 states, not 60).
//
// In: {op: 'open', text, generation, running} | {op: 'run', on} | {op: 'ack'} | {op: 'step',
// n, budget} (frames run now: the page's Step, the tests) | a gesture {op: 'grab' | 'move' |
// 'release' | 'togglePin' | 'cut' | 'obstacle', args} | {op: 'change', keys} | {op:
// 'recording', id}. Out, after frames and after a burst of gestures: {op: 'state', ...} (what
// `state()` below lists); {op: 'recording', id, text}; {op: 'error', message}.
import { clothClock } from './clock.js';
import { clothCore } from './core.js';
import { clothPanels } from './panels.js';

export const clothWorker = (function () {
  const ARRAYS = clothCore.MIRRORED, EDGES = clothCore.MIRRORED_EDGES, NUMBERS = clothCore.MIRRORED_NUMBERS;
  const SLICE_MS = 16;         // frames stepped at most this long before messages are taken

  function serve(scope) {
    const panels = clothPanels.create();
    let opened = false, done = 0, flushing = false;
    let generation = 0;         // the open message's: the page drops a state of a scene it left
    const edgesSent = [];       // per panel: the broken count its edges were last sent at
    const clock = clothClock.create(1 / 60);
    let running = false;        // the page runs the simulation (not paused, not hidden)
    let timer = 0;              // the clock's next tick, if one is set
    let unacked = 0;            // states posted the page has not taken yet
    let owed = false;           // frames ran since the last state, not yet posted

    let moved = [];             // the copies' buffers, transferred with the message (not copied again)
    function copy(a) { const c = a.slice(0); moved.push(c.buffer); return c; }
    function post(msg) { const list = moved; moved = []; if (msg.op === 'state') unacked++; scope.postMessage(msg, list); }

    // Each panel's arrays and numbers, the session's frame and replay, and what the page must
    // follow: the script's actions that ran (the person's holds, the scenes' keys).
    function state(all) {
      owed = false;
      const out = { op: 'state', generation: generation, done: done, rate: clock.rate, frame: panels.frame(), replayEnd: panels.replayEnd(),
                    replayEnded: panels.replayEnded(), atEnd: panels.atReplayEnd(), asleep: panels.asleep(),
                    scriptRan: panels.scriptRan(), recorded: panels.recordingCount(), full: panels.recordingFull(),
                    complete: panels.recordingComplete(), panels: [] };
      done = 0;
      const s = panels.session();
      if (all || out.scriptRan) out.person = copy(s.person);
      for (let i = 0; i < panels.count(); i++) {
        const c = panels.cloth(i), p = { simMs: panels.simMs(i), edges: false };
        ARRAYS.forEach(function (k) { p[k] = copy(c[k]); });
        NUMBERS.forEach(function (k) { p[k] = c[k]; });
        if (all || edgesSent[i] !== c.broken) {
          EDGES.forEach(function (k) { p[k] = copy(c[k]); });
          p.edges = true;
          edgesSent[i] = c.broken;
        }
        out.panels.push(p);
      }
      return out;
    }

    function flush() {
      flushing = false;
      if (opened) post(state(false));
    }

    function now() { return performance.now() / 1000; }

    // The clock's tick: the frames due, in one slice; the state, if the page has taken the
    // last; the next tick when the next frame is due.
    function tick() {
      timer = 0;
      if (!running || !opened) return;
      const n = clothClock.due(clock, now());
      if (n > 0) {
        const got = panels.simulate(n, SLICE_MS);
        // A replay at its end runs no frame: its time passes all the same.
        clothClock.ran(clock, got > 0 ? got : n, now());
        if (got > 0) { done += got; owed = true; }
      }
      if (owed && unacked === 0) post(state(false));
      schedule();
    }

    function schedule() {
      if (running && opened && !timer) timer = setTimeout(tick, 1000 * clothClock.wait(clock, now()));
    }

    function run(on) {
      running = !!on;
      if (timer) { clearTimeout(timer); timer = 0; }
      if (running && opened) { clothClock.start(clock, now(), panels.cloth(0).dt); schedule(); }
    }

    const GESTURES = { grab: true, move: true, release: true, togglePin: true, cut: true, obstacle: true };

    scope.onmessage = function (e) {
      const m = e.data;
      try {
        if (m.op === 'open') {
          generation = m.generation;
          panels.open(m.text);
          opened = true;
          for (let i = 0; i < panels.count(); i++) edgesSent[i] = -1;
          unacked = 0;
          post(state(true));
          run(m.running);
        } else if (m.op === 'run') {
          run(m.on);
        } else if (m.op === 'ack') {
          unacked = Math.max(0, unacked - 1);
          if (owed && unacked === 0) post(state(false));
        } else if (m.op === 'step') {
          if (m.n > 0) done += panels.simulate(m.n, m.budget);
          panels.refresh();
          const out = state(false);
          out.step = true;
          post(out);
        } else if (GESTURES[m.op]) {
          panels[m.op].apply(null, m.args);
          panels.refresh();
          // One message for a burst of gestures: after those already queued.
          if (!flushing) { flushing = true; setTimeout(flush, 0); }
        } else if (m.op === 'change') {
          panels.change(m.keys);
          panels.refresh();
          post(state(false));
          if (running && clock.dt !== panels.cloth(0).dt) run(true);   // a new dt: the clock anew
        } else if (m.op === 'recording') {
          scope.postMessage({ op: 'recording', id: m.id, text: panels.recordingText() });
        }
      } catch (err) {
        scope.postMessage({ op: 'error', message: clothCore.message(err) });
      }
    };
  }

  return { serve: serve };
})();
