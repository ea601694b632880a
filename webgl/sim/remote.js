// The panels with their session in a Web Worker (worker.js): the page's thread turns gestures
// and settings into messages and draws the latest state the Worker posted, so a heavy cloth
// slows the simulation (the readout says slow motion), never the input or the drawing.
//
// The same functions as panels.js. Beside the Worker the page keeps the same session opened
// from the same text, never stepped: a mirror into which each message's arrays and numbers are
// copied, whose scripts follow the Worker's frames, and to which gestures and settings are
// applied too, so that what the page asks synchronously (a setting refused, the scene's keys,
// which vertex is under a pointer, who holds it) is answered at once from the state it shows.
// What only the Worker knows comes later: the recording's text (recording(then)). The Worker
// keeps the simulation's clock (worker.js): the page says whether it runs (running(on)) and
// takes each state it posts (an acknowledgement asks for the next).
import { clothCore } from './core.js';
import { clothPanels } from './panels.js';

export const clothRemote = (function () {
  const core = clothCore, session = core.session;
  const ARRAYS = core.MIRRORED, EDGES = core.MIRRORED_EDGES, NUMBERS = core.MIRRORED_NUMBERS;

  // Starts the Worker from the page's inline scripts: the core's (id cloth-core) and the
  // Worker's (id cloth-worker: build.py). Returns null where a Worker cannot start (the page
  // then runs panels.js itself). arrived(done): a message brought `done` more frames (0:
  // gestures or settings); failed(message): the Worker reported an error.
  function start(arrived, failed) {
    let worker;
    try {
      const source = document.getElementById('cloth-core').textContent + '\n' +
        document.getElementById('cloth-worker').textContent;
      worker = new Worker(URL.createObjectURL(new Blob([source], { type: 'text/javascript' })));
    } catch (e) {
      return null;
    }
    const local = clothPanels.create();
    let inFlight = 0;            // step requests not yet answered
    let asleep = false, atEnd = false, ran = false, recorded = 0, full = false, complete = false;
    let generation = 0;          // the scene opened last (0: none): a state posted for another is dropped
    let simMs = [];
    let wantRunning = false;     // the page runs the simulation (the Worker's clock goes)
    let rate = 1;                // simulated seconds per second, the Worker's clock says
    const waiting = {};          // recording requests: id -> then(text)
    let nextId = 1;
    const idleWaiters = [];

    function post(msg) { worker.postMessage(msg); }
    function whenIdle() { return new Promise(function (resolve) { if (inFlight === 0) resolve(); else idleWaiters.push(resolve); }); }

    worker.onerror = function (e) { e.preventDefault(); failed('the simulation\'s Worker stopped: ' + (e.message || 'error')); };
    worker.onmessage = function (e) {
      const m = e.data;
      if (m.op === 'recording') { const then = waiting[m.id]; delete waiting[m.id]; if (then) then(m.text); return; }
      if (m.op === 'error') { failed(m.message); return; }
      if (m.op !== 'state') return;
      post({ op: 'ack' });
      if (m.generation !== generation) return;
      rate = m.rate;
      if (m.step) inFlight--;
      if (m.done > 0 || m.scriptRan) follow(m);
      const s = local.session();
      for (let i = 0; i < m.panels.length && i < local.count(); i++) {
        const c = local.cloth(i), p = m.panels[i];
        if (p.edges) for (let j = 0; j < EDGES.length; j++) c[EDGES[j]].set(p[EDGES[j]]);
        for (let j = 0; j < ARRAYS.length; j++) c[ARRAYS[j]].set(p[ARRAYS[j]]);
        for (let j = 0; j < NUMBERS.length; j++) c[NUMBERS[j]] = p[NUMBERS[j]];
        simMs[i] = p.simMs;
      }
      if (m.person) s.person.set(m.person);
      s.replay_end = m.replayEnd; s.replay_ended = m.replayEnded;
      asleep = m.asleep; atEnd = atEnd || m.atEnd; ran = ran || m.scriptRan;
      recorded = m.recorded; full = m.full; complete = m.complete;
      local.snapshots();
      arrived(m.done);
      if (inFlight === 0) while (idleWaiters.length) idleWaiters.shift()();
    };

    // The mirror's scripts follow the Worker's frames: their actions up to the frame it
    // reached (a scripted set changes the scene's keys the settings panel shows; a scripted
    // grab takes a vertex from a person's hand).
    function follow(m) {
      const s = local.session(), from = s.script_next[0];
      for (let i = 0; i < local.count(); i++) {
        const c = local.cloth(i);
        if (s.script_next[i] < c.scene.actions.length) s.script_next[i] = core.applyDue(c, s.script_next[i], m.frame);
      }
      session.framesRan(s, m.frame - s.frame, from);
    }

    // A gesture or a setting: applied to the mirror at once (its answer is the page's) and
    // sent to the Worker, which applies it at the frame it is at.
    function gesture(op) {
      return function () {
        const args = Array.prototype.slice.call(arguments);
        const did = local[op].apply(null, args);
        if (did) post({ op: op, args: args });
        return did;
      };
    }

    const remote = Object.assign({}, local, {
      remote: true,
      open: function (text) {
        local.open(text);              // throws the core's Error on a bad scene, as panels.js
        asleep = false; atEnd = false; ran = false; inFlight = 0;
        simMs = local.times().map(function () { return NaN; });
        generation++;
        rate = 1;
        post({ op: 'open', text: text, generation: generation, running: wantRunning });
      },
      // Whether the Worker's clock runs (the page not paused and shown).
      running: function (on) {
        on = !!on;
        if (on !== wantRunning) { wantRunning = on; post({ op: 'run', on: on }); }
      },
      // Simulated seconds per wall-clock second, over the Worker's last second.
      rate: function () { return rate; },
      // Frames run now in the Worker, beside its clock (the page's Step, the tests): `n` more
      // when it is idle (request); simulate() is not used in this mode.
      idle: function () { return inFlight === 0; },
      request: function (n, budgetMs) {
        n = session.framesLeft(local.session(), n);
        if (n <= 0 || inFlight > 0) return 0;
        inFlight++;
        post({ op: 'step', n: n, budget: budgetMs || 0 });
        return n;
      },
      // A Promise that resolves once every frame asked for has come back.
      whenIdle: whenIdle,
      // A Promise: n frames run (all of them, no budget), once those asked for before are back;
      // it resolves once the Worker has answered, so every state its clock posted before is in.
      run: function (n) {
        return whenIdle().then(function () {
          n = n > 0 ? session.framesLeft(local.session(), n) : 0;
          inFlight++;
          post({ op: 'step', n: n > 0 ? n : 0, budget: 0 });
          return whenIdle();
        });
      },
      asleep: function () { return asleep; },
      scriptRan: function () { const r = ran; ran = false; return r; },
      atReplayEnd: function () { const r = atEnd; atEnd = false; return r; },
      simMs: function (i) { return simMs[i]; },
      times: function () { return simMs; },
      // The mirror is measured by the Worker: only its snapshots are brought up to date.
      refresh: function () { local.snapshots(); },
      measure: function () { local.snapshots(); },
      grab: gesture('grab'), move: gesture('move'), release: gesture('release'),
      togglePin: gesture('togglePin'), cut: gesture('cut'), obstacle: gesture('obstacle'),
      change: function (keysText) { local.change(keysText); post({ op: 'change', keys: keysText }); },
      recordingCount: function () { return recorded; },
      recordingFull: function () { return full; },
      recordingComplete: function () { return complete; },
      // then(text): the recording as the Worker made it.
      recording: function (then) { const id = nextId++; waiting[id] = then; post({ op: 'recording', id: id }); },
    });
    return remote;
  }

  return { start: start };
})();
