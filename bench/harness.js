// The benchmark's side in the page (bench/page.py adds this file to dist/index.html and drives
// it). Every frame it times is stepped by webgl/sim/runner.js, the code the page's loop runs, so
// what the page shows and what the benchmark reports are stepped and timed alike.
'use strict';

(() => {
  const M = window.clothRunner;
  const B = window.__bench = {};

  // The fastest free vertex, m/s.
  function fastest(cl) {
    let v2 = 0;
    for (let k = 0; k < cl.n_verts; k++) {
      if (cl.fixed[k]) continue;
      const vx = cl.vel[2 * k], vy = cl.vel[2 * k + 1], s = vx * vx + vy * vy;
      if (s > v2) v2 = s;
    }
    return Math.sqrt(v2);
  }

  // Run a scene (JSON text) for `frames` frames, each timed (performance.now() is coarse on
  // file://, but its error averages out over a run). Returns the time per frame (the mean over
  // the run), when every vertex last went under `rest` m/s to stay (s; -1: never), the
  // solver's counters and imbalance, and the final positions.
  B.run = function (text, frames, rest) {
    const cl = clothCore.load(text), r = M.run(cl);
    let total = 0, done = 0, restAt = -1;
    while (done < frames) {
      M.step(r, 1, 0);
      total += r.ms;
      done++;
      const v = fastest(cl);
      if (!(v < rest)) restAt = -1;
      else if (restAt < 0) restAt = done * cl.dt;
    }
    return { frames: done, ms: total / done, restAt: restAt, fastest: fastest(cl),
             imbalance: cl.imbalance, sweeps: cl.sweeps / done, corrected: cl.corrected / done,
             steps: cl.steps, finite: Array.from(cl.pos).every(Number.isFinite),
             pos: Array.from(cl.pos) };
  };

  // A pull and a release: the scene runs `settle` frames; a hand takes vertex k where it is and
  // moves it by (dx, dy) over `pull` frames, holds it `hold` frames and lets go; then `after`
  // frames. Returns the energies (kinetic, elastic, gravitational) just before the release,
  // the free vertices' mass, the most the total rose above them after it, and per frame after
  // it the speed 95% of the vertices stay under and the fastest, and how far the highest free
  // vertex rose above the highest fixed one.
  B.pull = function (text, settle, k, dx, dy, pull, hold, after) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    M.step(r, settle, 0);
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    for (let f = 1; f <= pull; f++) { ops.move(k, x0 + dx * f / pull, y0 + dy * f / pull); M.step(r, 1, 0); }
    M.step(r, hold, 0);
    const held = [cl.pos[2 * k] - x0, cl.pos[2 * k + 1] - y0];
    const before = ops.energies();
    let free = 0;
    for (let i = 0; i < cl.n_verts; i++) if (!cl.fixed[i]) free += cl.mass[i];
    ops.release(k);
    let gain = -Infinity, p95 = 0, top = 0, rise = -Infinity, pins = -Infinity;
    for (let i = 0; i < cl.n_verts; i++) if (cl.fixed[i]) pins = Math.max(pins, cl.pos[2 * i + 1]);
    const speeds = new Float64Array(cl.n_verts);
    for (let f = 0; f < after; f++) {
      M.step(r, 1, 0);
      const e = ops.energies();
      gain = Math.max(gain, (e[0] + e[1] + e[2]) - (before[0] + before[1] + before[2]));
      let m = 0;
      for (let i = 0; i < cl.n_verts; i++) {
        if (cl.fixed[i]) continue;
        speeds[m++] = Math.hypot(cl.vel[2 * i], cl.vel[2 * i + 1]);
        if (Number.isFinite(pins)) rise = Math.max(rise, cl.pos[2 * i + 1] - pins);
      }
      const s = Array.from(speeds.subarray(0, m)).sort(function (a, b) { return a - b; });
      p95 = Math.max(p95, s[Math.floor(0.95 * (m - 1))]);
      top = Math.max(top, s[m - 1]);
    }
    return { before: before, free: free, gain: gain, p95: p95, fastest: top, rise: rise, reached: held,
             finite: Array.from(cl.pos).every(Number.isFinite) };
  };

  // A tap: the scene runs `settle` frames twice, side by side; on one a hand takes vertex k
  // and lets go with no frame between; both run `after` more. Returns the largest distance
  // between the two (0: the tap changed nothing).
  B.tap = function (text, settle, k, after) {
    const a = M.run(clothCore.load(text)), b = M.run(clothCore.load(text));
    M.step(a, settle, 0);
    M.step(b, settle, 0);
    b.ops.grab(k, b.cloth.pos[2 * k], b.cloth.pos[2 * k + 1]);
    b.ops.release(k);
    M.step(a, after, 0);
    M.step(b, after, 0);
    let worst = 0;
    for (let i = 0; i < 2 * a.cloth.n_verts; i++) worst = Math.max(worst, Math.abs(a.cloth.pos[i] - b.cloth.pos[i]));
    return worst;
  };

  // Time `frames` frames of each scene in turn, `rounds` times round-robin (the machine's noise
  // falls on all alike); each scene continues from where its last batch left it. Returns per
  // scene the median batch's ms per frame.
  B.timeSide = function (texts, frames, rounds) {
    const runs = texts.map(function (t) { return M.run(clothCore.load(t)); });
    const ms = texts.map(function () { return []; });
    for (let k = 0; k < rounds; k++) {
      runs.forEach(function (r, i) { M.step(r, frames, 0); ms[i].push(r.ms / frames); });
    }
    return ms.map(function (list) { list.sort(function (a, b) { return a - b; }); return list[list.length >> 1]; });
  };
})();
