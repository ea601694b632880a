// The benchmark's side in the page (bench/page.py injects this file into dist/index.html and
// drives it): groups of configurations, references, the speed-of-light yardstick and the
// gestures. Every frame it times is stepped, timed and measured by webgl/runner.js, the code
// the page's compare mode runs, so that what the page shows and what the benchmark reports
// are measured alike.
'use strict';

(() => {
  const M = window.clothRunner;

  // Distances between two position arrays of n vertices: RMS and largest.
  function rmsError(pos, ref, n) {
    let s = 0;
    for (let k = 0; k < n; k++) {
      const dx = pos[2 * k] - ref[2 * k], dy = pos[2 * k + 1] - ref[2 * k + 1];
      s += dx * dx + dy * dy;
    }
    return Math.sqrt(s / n);
  }

  function maxError(pos, ref, n) {
    let worst = 0;
    for (let k = 0; k < n; k++) {
      const dx = pos[2 * k] - ref[2 * k], dy = pos[2 * k + 1] - ref[2 * k + 1];
      worst = Math.max(worst, dx * dx + dy * dy);
    }
    return Math.sqrt(worst);
  }

  // The rest grid: the exact hang of a curtain.
  function restGrid(cl) {
    const ref = new Float64Array(2 * cl.n_verts);
    for (let r = 0; r < cl.rows; r++) {
      for (let c = 0; c < cl.cols; c++) {
        const k = r * cl.cols + c;
        ref[2 * k] = c * cl.spacing;
        ref[2 * k + 1] = -r * cl.spacing;
      }
    }
    return ref;
  }
  const B = window.__bench = { groups: {} };

  // A group: every configuration of one scene at one size, plus its reference.
  B.setup = function (key, scenes) {
    const g = { runs: [], refStatic: null, refSnaps: {}, ref: null };
    for (const text of scenes) g.runs.push(M.run(clothCore.load(text)));
    B.groups[key] = g;
    return g.runs.map(r => M.describe(r.cloth));
  };

  B.exactRest = function (key) {
    const g = B.groups[key];
    g.refStatic = restGrid(g.runs[0].cloth);
  };

  // An exact reference computed in CPython (cloth/reference.py): [x0, y0, x1, y1, ...].
  B.exactRef = function (key, flat) {
    B.groups[key].refStatic = Float64Array.from(flat);
  };

  // The reference, and optionally a check run of it with half the substeps (`checkText`).
  B.refSetup = function (key, text, checkText) {
    const g = B.groups[key];
    g.ref = M.run(clothCore.load(text));
    g.check = checkText ? M.run(clothCore.load(checkText)) : null;
    g.checkErr = [];
    return M.describe(g.ref.cloth);
  };

  // Advance the reference; keep a copy of its positions at the listed frames (and there,
  // the check run's distance from it).
  B.refAdvance = function (key, frames, snapFrames) {
    const g = B.groups[key], want = new Set(snapFrames);
    for (let i = 0; i < frames; i++) {
      M.step(g.ref, 1, 0);
      if (g.check) M.step(g.check, 1, 0);
      if (want.has(g.ref.frame)) {
        g.refSnaps[g.ref.frame] = Float64Array.from(g.ref.cloth.pos);
        if (g.check) g.checkErr.push(rmsError(g.check.cloth.pos, g.ref.cloth.pos, g.ref.cloth.n_verts));
      }
    }
    return g.ref.frame;
  };

  B.refCheck = function (key) { return B.groups[key].checkErr; };

  B.refStrain = function (key) {
    const cl = B.groups[key].ref.cloth;
    cl.measure();
    return { rms_strain: cl.rms_strain, max_strain: cl.max_strain };
  };

  B.warm = function (key, frames) {
    for (const r of B.groups[key].runs) M.step(r, frames, 0);
  };

  // One repetition: a timed batch of `frames` frames per configuration, in the given order;
  // then each one's strain and position error (untimed).
  B.round = function (key, order, frames) {
    const g = B.groups[key], out = [];
    for (const i of order) {
      const r = g.runs[i], cl = r.cloth;
      M.step(r, frames, 0);
      cl.measure();
      const ref = g.refStatic || g.refSnaps[r.frame];
      out.push({ i: i, ms: r.ms, proj: r.proj, frame: r.frame,
                 rms_strain: cl.rms_strain, max_strain: cl.max_strain,
                 err: ref ? rmsError(cl.pos, ref, cl.n_verts) : null,
                 max_err: ref ? maxError(cl.pos, ref, cl.n_verts) : null });
    }
    return out;
  };

  B.drop = function (key) { delete B.groups[key]; };

  // Compare mode's cost: n panels of one scene stepped one after the other, as the page's
  // loop steps them (app.js simulate), against one; ms per frame of all n together.
  B.panelsSetup = function (text, n) {
    B.panels = [];
    for (let i = 0; i < n; i++) B.panels.push(M.run(clothCore.load(text)));
  };
  // Time `count` panels over `frames` frames; the others then run the same frames untimed, so
  // that every panel stays at the same frame (a cloth's cost depends on how far it settled).
  B.panelsRound = function (count, frames) {
    let ms = 0;
    for (let i = 0; i < B.panels.length; i++) {
      M.step(B.panels[i], frames, 0);
      if (i < count) ms += B.panels[i].ms;
    }
    return ms;
  };

  // The world's cost (issue #24): runs of scenes that differ only by their air and obstacles,
  // each stepped by itself; worldRound(i, frames) -> ms of run i over `frames` frames.
  B.worldSetup = function (texts) { B.world = texts.map(function (t) { return M.run(clothCore.load(t)); }); };
  B.worldRound = function (i, frames) { M.step(B.world[i], frames, 0); return B.world[i].ms; };

  // Tearing's check on its own (issue #15): the check a frame makes (cloth/solve.py
  // mark_overstretched over every edge, at a limit nothing reaches, so nothing breaks and the
  // state is the same each call) against whole frames of the same cloth, timed one after the
  // other on the same state. Frame-to-frame timings of two configurations differ by more than
  // the check costs on these machines; the check timed by itself does not.
  B.tearSetup = function (text) {
    B.tear = M.run(clothCore.load(text));
    if (!(B.tear.cloth.tear > 0)) throw new Error('the scene sets no tear limit');
  };
  B.tearRound = function (frames) {  // ms of `frames` frames, and of as many checks
    const r = B.tear, cl = r.cloth;
    const tearCheck = clothTranscrypt.api.tear_check;
    const most = cl.tear_q.length;
    M.step(r, frames, 0);
    const t0 = performance.now();
    let found = 0;
    // Ten checks a frame: a check is microseconds and the clock's step 100 us on file://.
    for (let i = 0; i < 10 * frames; i++) {
      found += tearCheck(cl, most);
    }
    const check = performance.now() - t0;
    if (found > 0) throw new Error('the check broke edges: the limit is reached');
    return { frame_ms: r.ms, check_ms: check / 10, converged: !!cl.converged };
  };

  // ---- the speed-of-light yardstick: the seed's method, hand-written --------------------
  function kernelFrames(s, frames) {
    const pos = s.pos, prev = s.prev, w = s.w, ea = s.ea, eb = s.eb, rest = s.rest;
    const n = s.n, m = s.m, keep = s.keep, ax = s.ax, ay = s.ay, iters = s.iters;
    for (let f = 0; f < frames; f++) {
      for (let k = 0; k < n; k++) {
        if (w[k] === 0) continue;
        const i = k + k;
        const x = pos[i], y = pos[i + 1];
        pos[i] = x + (x - prev[i]) * keep + ax;
        pos[i + 1] = y + (y - prev[i + 1]) * keep + ay;
        prev[i] = x;
        prev[i + 1] = y;
      }
      for (let it = 0; it < iters; it++) {
        for (let e = 0; e < m; e++) {
          const a = ea[e], b = eb[e];
          const wa = w[a], wb = w[b], ww = wa + wb;
          if (ww === 0) continue;
          const ia = a + a, ib = b + b;
          const dx = pos[ib] - pos[ia], dy = pos[ib + 1] - pos[ia + 1];
          const d2 = dx * dx + dy * dy;
          if (d2 < 1e-30) continue;
          const len = Math.sqrt(d2);
          const q = (len - rest[e]) / len / ww;
          const sa = q * wa, sb = q * wb;
          pos[ia] += dx * sa;
          pos[ia + 1] += dy * sa;
          pos[ib] -= dx * sb;
          pos[ib + 1] -= dy * sb;
        }
      }
    }
  }

  B.solSetup = function (text) {
    const core = M.run(clothCore.load(text));
    const c = clothCore.load(text);
    if (c.substeps !== 1 || c.use_xpbd || c.use_tethers) throw new Error('not the seed method');
    const s = { pos: Float64Array.from(c.pos), prev: Float64Array.from(c.prev),
                w: Float64Array.from(c.inv_mass), ea: Int32Array.from(c.edge_a),
                eb: Int32Array.from(c.edge_b), rest: Float64Array.from(c.rest),
                n: c.n_verts, m: c.n_edges, keep: c.keep, ax: c.ax, ay: c.ay,
                iters: c.iterations };
    B.sol = { core: core, kernel: s };
    return M.describe(core.cloth);
  };

  // Time `frames` frames of the core and of the kernel, in the given order.
  B.solRound = function (frames, kernelFirst) {
    const t = {};
    const runCore = () => { M.step(B.sol.core, frames, 0); t.core = B.sol.core.ms; };
    const runKernel = () => {
      const t0 = performance.now();
      kernelFrames(B.sol.kernel, frames);
      t.kernel = performance.now() - t0;
    };
    if (kernelFirst) { runKernel(); runCore(); } else { runCore(); runKernel(); }
    return t;
  };

  B.solCompare = function () {
    const a = B.sol.core.cloth.pos, b = B.sol.kernel.pos;
    let same = a.length === b.length, maxd = 0;
    for (let i = 0; i < a.length; i++) {
      if (a[i] !== b[i]) same = false;
      const d = Math.abs(a[i] - b[i]);
      if (d > maxd) maxd = d;
    }
    return { identical: same, max_abs_diff: maxd };
  };

  // ---- gestures: a hand pulling beyond reach, letting go, flicking -------------------------
  // Speeds are velocities, (pos - prev) / h at the end of a frame, not distances per frame:
  // a cloth relieved of stretch jumps back to shape without moving fast.
  function fastest(cl) {
    let v = 0;
    for (let k = 0; k < cl.n_verts; k++) {
      const s = Math.hypot(cl.pos[2 * k] - cl.prev[2 * k], cl.pos[2 * k + 1] - cl.prev[2 * k + 1]);
      if (s > v) v = s;
    }
    return v / cl.h;
  }

  // Hang, grab vertex k, pull it by (dx, dy) over a second, hold a second, let go.
  B.overpull = function (text, k, dx, dy) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, ops = r.ops;
    M.step(r, 120, 0);
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    let held = 0;
    for (let f = 0; f < 120; f++) {
      const t = Math.min(1, f / 60);
      ops.move(k, x0 + dx * t, y0 + dy * t);
      M.step(r, 1, 0);
      ops.measure();
      held = Math.max(held, cl.max_strain);
    }
    ops.release(k);
    let after = 0, over5 = 0;
    for (let f = 0; f < 30; f++) {
      M.step(r, 1, 0);
      after = Math.max(after, fastest(cl));
      let n5 = 0;
      for (let i = 0; i < cl.n_verts; i++) {
        if (Math.hypot(cl.pos[2 * i] - cl.prev[2 * i], cl.pos[2 * i + 1] - cl.prev[2 * i + 1]) / cl.h > 5) n5++;
      }
      over5 = Math.max(over5, n5);
    }
    return { held_max_strain: held, after_fastest: after, after_over_5: over5 };
  };

  // A free cloth in zero gravity, vertex k dragged along x at `speed` for 1/3 s and let go:
  // the centre of mass's speed over the next half second.
  B.flick = function (text, k, speed) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, ops = r.ops;
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    for (let f = 1; f <= 20; f++) { ops.move(k, x0 + speed * f / 60, y0); M.step(r, 1, 0); }
    ops.release(k);
    const cx = () => { let s = 0; for (let i = 0; i < cl.n_verts; i++) s += cl.pos[2 * i]; return s / cl.n_verts; };
    const c0 = cx();
    M.step(r, 30, 0);
    return (cx() - c0) / 0.5;
  };
  // ---- release and strain fields (issue #21): the page's own presets -----------------------

  // A preset as the page makes it (webgl/scenes.js), with some of its panel's settings.
  B.preset = function (name, params) { return JSON.stringify(window.clothScenes.make(name, params).scene); };

  // The largest frame displacement / dt of any vertex between two position copies.
  function frameSpeed(a, b, n, dt) {
    let v = 0;
    for (let k = 0; k < n; k++) {
      const s = Math.hypot(b[2 * k] - a[2 * k], b[2 * k + 1] - a[2 * k + 1]);
      if (s > v) v = s;
    }
    return v / dt;
  }

  function highest(cl) {
    let y = -Infinity;
    for (let k = 0; k < cl.n_verts; k++) if (cl.pos[2 * k + 1] > y) y = cl.pos[2 * k + 1];
    return y;
  }

  // A pull as a person makes it: the scene settles `settle` frames, vertex k is grabbed where it
  // is, carried (dx, dy) over 40 frames, held `hold` frames and let go. Returns the fastest
  // vertex (frame displacement / dt) over the 3 frames after, the highest point over the next
  // second above the highest pin (or the cloth's highest point at the release, when the hand
  // lifted it higher), and the largest strain while held.
  B.pull = function (text, settle, k, dx, dy, hold) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, ops = r.ops, n = cl.n_verts;
    M.step(r, settle, 0);
    let pinTop = -Infinity;
    for (let j = 0; j < n; j++) if (cl.pinned[j] === 1 && cl.pos[2 * j + 1] > pinTop) pinTop = cl.pos[2 * j + 1];
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    let held = 0;
    for (let f = 1; f <= 40 + hold; f++) {
      const t = Math.min(1, f / 40);
      ops.move(k, x0 + dx * t, y0 + dy * t);
      M.step(r, 1, 0);
      ops.measure();
      held = Math.max(held, cl.max_strain);
    }
    // Lifted above its pins by the hand, a cloth is let go from there: the ceiling is the
    // higher of the pins and the cloth's highest point at the release.
    const ceiling = Math.max(pinTop, highest(cl));
    ops.release(k);
    let fastestAfter = 0, top = -Infinity;
    let before = Float64Array.from(cl.pos);
    for (let f = 0; f < 60; f++) {
      M.step(r, 1, 0);
      if (f < 3) fastestAfter = Math.max(fastestAfter, frameSpeed(before, cl.pos, n, cl.dt));
      before.set(cl.pos);
      top = Math.max(top, highest(cl));
    }
    return { fastest: fastestAfter, above: top - ceiling, held: held, finite: Number.isFinite(top) };
  };

  // A tap on vertex k of the settled scene: how far any vertex then is from where the same
  // scene puts it without the tap, a frame later.
  B.tap = function (text, settle, k) {
    const a = M.run(clothCore.load(text)), b = M.run(clothCore.load(text));
    M.step(a, settle, 0);
    M.step(b, settle, 0);
    a.ops.grab(k, a.cloth.pos[2 * k], a.cloth.pos[2 * k + 1]);
    a.ops.release(k);
    M.step(a, 1, 0);
    M.step(b, 1, 0);
    let d = 0;
    for (let j = 0; j < 2 * a.cloth.n_verts; j++) d = Math.max(d, Math.abs(a.cloth.pos[j] - b.cloth.pos[j]));
    return d;
  };

  // The settled positions of a scene after `frames` frames, and the fastest vertex then (m/s).
  B.rest = function (text, frames) {
    const r = M.run(clothCore.load(text)), cl = r.cloth;
    M.step(r, frames, 0);
    return { pos: Array.from(cl.pos), speed: fastest(cl) };
  };

  // ---- the README's other figures (python -m bench --figures) ------------------------

  // Frames until the cloth sleeps (-1: not within `cap`), its positions then, how far any
  // vertex was over the last second from where it ended (asleep or not), and the largest
  // distance any vertex moved in one frame over that second.
  B.sleep = function (text, cap) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, n = cl.n_verts;
    const ring = [];
    for (let i = 0; i < 60; i++) ring.push(new Float64Array(2 * n));
    let f = 0;
    while (f < cap && !cl.asleep) { M.step(r, 1, 0); ring[f % 60].set(cl.pos); f++; }
    let swing = 0, jump = 0;
    const last = Math.min(f, 60);
    for (let i = 0; i < last; i++) {
      const p = ring[(f - 1 - i) % 60], q = i + 1 < last ? ring[(f - 2 - i) % 60] : null;
      for (let k = 0; k < n; k++) {
        swing = Math.max(swing, Math.hypot(p[2 * k] - cl.pos[2 * k], p[2 * k + 1] - cl.pos[2 * k + 1]));
        if (q) jump = Math.max(jump, Math.hypot(p[2 * k] - q[2 * k], p[2 * k + 1] - q[2 * k + 1]));
      }
    }
    return { frames: cl.asleep ? f : -1, pos: Array.from(cl.pos), swing: swing, jump: jump };
  };

  // Vertex k's position after every frame, [x0, y0, x1, y1, ...].
  B.track = function (text, frames, k) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, out = [];
    for (let f = 0; f < frames; f++) { M.step(r, 1, 0); out.push(cl.pos[2 * k], cl.pos[2 * k + 1]); }
    return out;
  };

  // Over `frames` frames: the fastest free vertex (frame displacement / dt; a vertex pinned or
  // held is where the scene puts it), the highest free vertex, the vertex-steps the max_speed
  // net slowed, and whether every position stayed finite.
  B.motion = function (text, frames) {
    const r = M.run(clothCore.load(text)), cl = r.cloth, n = cl.n_verts;
    const before = Float64Array.from(cl.pos);
    let fastestFree = 0, top = -Infinity, finite = true;
    for (let f = 0; f < frames; f++) {
      M.step(r, 1, 0);
      for (let k = 0; k < n; k++) {
        const x = cl.pos[2 * k], y = cl.pos[2 * k + 1];
        if (!Number.isFinite(x) || !Number.isFinite(y)) finite = false;
        if (cl.pinned[k] !== 0 || cl.held[k] !== 0) continue;
        fastestFree = Math.max(fastestFree, Math.hypot(x - before[2 * k], y - before[2 * k + 1]) / cl.dt);
        if (y > top) top = y;
      }
      before.set(cl.pos);
    }
    return { fastest: fastestFree, top: top, clamped: cl.clamped, finite: finite };
  };

  return true;
})();
