// The recording: everything that happens to the cloth from a load or a reset, kept as a
// scene that replays bit for bit in the CLI and in clothCore.run (issue #13).
//
// A recording is the scene as loaded (its own scripted actions included) plus every gesture
// and live setting change as an `actions` entry at the frame where it took effect: the page
// applies a gesture between frame f and frame f + 1, after the scripted actions of frame f,
// which is where the core applies an action of frame f that comes after them in the list
// (cloth/api.py simulate). The recorder only listens: the app applies each gesture to the
// cloth and then tells it what happened.
//
// Moves between two frames are coalesced into one move to the last position: for a held
// vertex only its final position and whether the cloth was woken matter, and a move that
// ends where the vertex was (the core ignores a move to where a vertex is) would lose the
// wake, so a run of moves that comes back to its start keeps one move away from it.
//
// Memory: typed arrays, grown by doubling when a gesture needs room (never per frame, never
// while nobody touches the cloth), up to MAX_ACTIONS entries in all, the scene format's own
// limit (about 28 minutes of one finger dragging without a pause, a move per frame). Past it
// the recording stops where it is complete (the frame before the first gesture it could not
// keep) and says so; the cloth goes on.
'use strict';

window.clothRecorder = (function () {
  // The scene format's limit and its action ops (cloth/scene.py MAX_ACTIONS, OPS): an action
  // is kept as its op's index there.
  const SCHEMA = window.clothCore.schema();
  const MAX_ACTIONS = SCHEMA.maxActions;
  const OPS = SCHEMA.ops;
  function code(op) {
    const i = OPS.indexOf(op);
    if (i < 0) throw new Error('the core has no action op ' + op);
    return i;
  }
  const GRAB = code('grab'), MOVE = code('move'), RELEASE = code('release'), PIN = code('pin'),
    UNPIN = code('unpin'), SET = code('set'), CUT = code('cut');
  // Compare mode's forms (each panel holds its own vertex where it is, and every hand moves by
  // one displacement): a grab with no `to`, a move `by` [dx, dy] from where the hand took hold.
  const GRAB_HERE = OPS.length, MOVE_BY = OPS.length + 1;
  const FIRST_CAPACITY = 1024;

  function create() {
    let base = null;         // the scene object as loaded, without actions and frames
    let scripted = [];       // its own actions (objects), in the core's order
    let cap = 0, count = 0;
    let frameOf = new Int32Array(0), opOf = new Uint8Array(0), vertexOf = new Int32Array(0);
    let xOf = new Float64Array(0), yOf = new Float64Array(0);
    let fromX = new Float64Array(0), fromY = new Float64Array(0);   // a cut's blade start
    const settings = [];     // the keys of each set, indexed by vertexOf[i]
    // Per vertex, for coalescing: the frame of its current run of moves, the index of the
    // run's last move (-1: none) and where that move started from.
    let runFrame = new Int32Array(0), runLast = new Int32Array(0);
    let runFromX = new Float64Array(0), runFromY = new Float64Array(0);
    let droppedAt = -1;      // the frame of the first gesture that did not fit, or -1

    function grow() {
      const next = Math.min(Math.max(cap * 2, FIRST_CAPACITY), MAX_ACTIONS);
      function more(Type, old) { const a = new Type(next); a.set(old); return a; }
      frameOf = more(Int32Array, frameOf); opOf = more(Uint8Array, opOf);
      vertexOf = more(Int32Array, vertexOf);
      xOf = more(Float64Array, xOf); yOf = more(Float64Array, yOf);
      fromX = more(Float64Array, fromX); fromY = more(Float64Array, fromY);
      cap = next;
    }

    // Room for one more action? Past the limit the recording ends where it is complete.
    function room(f) {
      if (droppedAt >= 0) return false;
      if (scripted.length + count >= MAX_ACTIONS) { droppedAt = f; return false; }
      if (count === cap) grow();
      return true;
    }

    function push(f, op, k, x, y) {
      frameOf[count] = f; opOf[count] = op; vertexOf[count] = k; xOf[count] = x; yOf[count] = y;
      return count++;
    }

    function other(f, op, k, x, y) {
      if (!room(f)) return;
      push(f, op, k, x, y);
      if (k >= 0 && k < runLast.length) runLast[k] = -1;
    }

    // A move (MOVE: to (x, y); MOVE_BY: by (x, y)) of vertex k from (x0, y0) at frame f,
    // coalesced with the run of moves of k in that frame.
    function moved(f, op, k, x, y, x0, y0) {
      if (x === x0 && y === y0) return;               // the core did nothing either
      const last = runFrame[k] === f ? runLast[k] : -1;
      if (last >= 0 && !(x === runFromX[k] && y === runFromY[k])) {
        xOf[last] = x; yOf[last] = y;                 // still a move away from its start
        return;
      }
      if (!room(f)) return;
      runFrame[k] = f;
      runFromX[k] = last >= 0 ? xOf[last] : x0;
      runFromY[k] = last >= 0 ? yOf[last] : y0;
      runLast[k] = push(f, op, k, x, y);
    }

    function actionAt(i) {
      const op = opOf[i];
      if (op === SET) return { frame: frameOf[i], op: 'set', scene: settings[vertexOf[i]] };
      if (op === CUT) return { frame: frameOf[i], op: 'cut', from: [fromX[i], fromY[i]], to: [xOf[i], yOf[i]] };
      if (op === GRAB_HERE) return { frame: frameOf[i], op: 'grab', vertex: vertexOf[i] };
      if (op === MOVE_BY) return { frame: frameOf[i], op: 'move', vertex: vertexOf[i], by: [xOf[i], yOf[i]] };
      const a = { frame: frameOf[i], op: OPS[op], vertex: vertexOf[i] };
      if (op === GRAB || op === MOVE) a.to = [xOf[i], yOf[i]];
      return a;
    }

    return {
      // A new recording of `scene` (the object as loaded) on n vertices; `actions`: its own
      // actions as the core sorted them (objects).
      start: function (scene, actions, n) {
        base = {};
        Object.keys(scene).forEach(function (key) {
          if (key !== 'actions' && key !== 'frames') base[key] = scene[key];
        });
        scripted = actions.slice();
        count = 0;
        settings.length = 0;
        droppedAt = -1;
        if (runLast.length < n) {
          runFrame = new Int32Array(n); runLast = new Int32Array(n);
          runFromX = new Float64Array(n); runFromY = new Float64Array(n);
        }
        runLast.fill(-1, 0, n);
      },
      grab: function (f, k, x, y) { other(f, GRAB, k, x, y); },
      // Vertex k held where it is, in each panel (compare mode).
      grabHere: function (f, k) { other(f, GRAB_HERE, k, 0, 0); },
      release: function (f, k) { other(f, RELEASE, k, 0, 0); },
      pin: function (f, k) { other(f, PIN, k, 0, 0); },
      unpin: function (f, k) { other(f, UNPIN, k, 0, 0); },
      // A blade from (x0, y0) to (x1, y1) at frame f (every cut is kept: each breaks what it
      // crosses where the cloth is, and several in a frame are their union).
      cut: function (f, x0, y0, x1, y1) {
        if (!room(f)) return;
        const i = push(f, CUT, -1, x1, y1);
        fromX[i] = x0; fromY[i] = y0;
      },
      set: function (f, keys) {
        if (!room(f)) return;
        settings.push(keys);
        push(f, SET, settings.length - 1, 0, 0);
      },
      // Vertex k moved from (x0, y0) to (x, y) at frame f.
      move: function (f, k, x, y, x0, y0) { moved(f, MOVE, k, x, y, x0, y0); },
      // The hands holding k moved by (dx, dy) from where they took hold, (dx0, dy0) before.
      moveBy: function (f, k, dx, dy, dx0, dy0) { moved(f, MOVE_BY, k, dx, dy, dx0, dy0); },
      // A person took over a replay at frame f: the script's later actions are gone.
      truncate: function (f) {
        scripted = scripted.filter(function (a) { return a.frame <= f; });
      },
      count: function () { return scripted.length + count; },
      // The frame up to which the recording is complete, given the page's frame count.
      complete: function (frames) { return droppedAt < 0 ? frames : Math.max(droppedAt - 1, 0); },
      full: function () { return droppedAt >= 0; },
      // The recording as a scene object, `frames` frames long. Within a frame the script's
      // actions come first: the page applied them when the frame ended, before any gesture.
      scene: function (frames) {
        const out = {};
        Object.keys(base).forEach(function (key) { out[key] = base[key]; });
        const actions = [];
        let i = 0, j = 0;
        while (i < scripted.length || j < count) {
          if (j >= count || (i < scripted.length && scripted[i].frame <= frameOf[j])) actions.push(scripted[i++]);
          else actions.push(actionAt(j++));
        }
        if (actions.length) out.actions = actions;
        out.frames = frames;
        return out;
      },
    };
  }

  // The core's parsed actions (cloth.scene.actions) as scene objects.
  function scriptOf(cloth) {
    const list = cloth.scene.actions, out = [];
    for (let i = 0; i < list.length; i++) {
      const a = list[i];
      if (a.op === 'set') { out.push({ frame: a.frame, op: 'set', scene: a.keys }); continue; }
      if (a.op === 'cut') { out.push({ frame: a.frame, op: 'cut', from: [a.from_x, a.from_y], to: [a.to_x, a.to_y] }); continue; }
      const o = { frame: a.frame, op: a.op, vertex: a.vertex };
      if (a.by) o.by = [a.to_x, a.to_y];
      else if (a.has_to) o.to = [a.to_x, a.to_y];
      out.push(o);
    }
    return out;
  }

  return { create: create, scriptOf: scriptOf };
})();
