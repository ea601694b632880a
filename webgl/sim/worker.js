// The session in a Web Worker: the same panels (panels.js) as on the page's own thread, driven
// by messages, each panel's state posted back for the page to draw. Linked by build.py into a
// script of its own, which the page starts as a Worker from a Blob (remote.js); never run on the
// page's thread.
//
// In: {op: 'open', text} | {op: 'step', n, budget} | a gesture {op: 'grab' | 'move' |
// 'release' | 'togglePin' | 'cut' | 'obstacle', args} | {op: 'change', keys} | {op:
// 'recording', id}. Out, after a step and after a burst of gestures: {op: 'state', ...} (what
// `state()` below lists); {op: 'recording', id, text}; {op: 'error', message}.
import { clothCore } from './core.js';
import { clothPanels } from './panels.js';

export const clothWorker = (function () {
  const ARRAYS = clothCore.MIRRORED, EDGES = clothCore.MIRRORED_EDGES, NUMBERS = clothCore.MIRRORED_NUMBERS;

  function serve(scope) {
    const panels = clothPanels.create();
    let opened = false, done = 0, flushing = false;
    let generation = 0;         // the open message's: the page drops a state of a scene it left
    const edgesSent = [];       // per panel: the broken count its edges were last sent at

    let moved = [];             // the copies' buffers, transferred with the message (not copied again)
    function copy(a) { const c = a.slice(0); moved.push(c.buffer); return c; }
    function post(msg) { const list = moved; moved = []; scope.postMessage(msg, list); }

    // Each panel's arrays and numbers, the session's frame and replay, and what the page must
    // follow: the script's actions that ran (the person's holds, the scenes' keys).
    function state(all) {
      const out = { op: 'state', generation: generation, done: done, frame: panels.frame(), replayEnd: panels.replayEnd(),
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

    const GESTURES = { grab: true, move: true, release: true, togglePin: true, cut: true, obstacle: true };

    scope.onmessage = function (e) {
      const m = e.data;
      try {
        if (m.op === 'open') {
          generation = m.generation;
          panels.open(m.text);
          opened = true;
          for (let i = 0; i < panels.count(); i++) edgesSent[i] = -1;
          post(state(true));
        } else if (m.op === 'step') {
          done += panels.simulate(m.n, m.budget);
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
