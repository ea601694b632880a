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
  // The cost of several configurations of one scene, measured side by side: each loaded and
  // run `warm` frames untimed (the same warm-up), then `rounds` rounds in which each in turn
  // (the order rotated every round) runs a timed block of `block` frames from where it was.
  // Returns per configuration its ms a frame in every round (the rounds line up: a ratio of two
  // configurations is taken round by round, where the machine's noise fell on both alike), and
  // its sweeps and coarse corrections a frame over the timed blocks.
  B.interleave = function (texts, warm, block, rounds) {
    const runs = texts.map(function (t) { return M.run(clothCore.load(t)); });
    runs.forEach(function (r) { M.step(r, warm, 0); });
    const ms = texts.map(function () { return []; });
    const sweeps = texts.map(function () { return 0; }), corrected = texts.map(function () { return 0; });
    for (let k = 0; k < rounds; k++) {
      for (let j = 0; j < runs.length; j++) {
        const i = (j + k) % runs.length, r = runs[i], cl = r.cloth, s0 = cl.sweeps, c0 = cl.corrected;
        M.step(r, block, 0);
        ms[i].push(r.ms / block);
        sweeps[i] += cl.sweeps - s0;
        corrected[i] += cl.corrected - c0;
      }
    }
    return texts.map(function (t, i) {
      return { ms: ms[i], sweeps: sweeps[i] / (block * rounds), corrected: corrected[i] / (block * rounds),
               finite: Array.from(runs[i].cloth.pos).every(Number.isFinite) };
    });
  };

  B.timeSide = function (texts, frames, rounds) {
    const runs = texts.map(function (t) { return M.run(clothCore.load(t)); });
    const ms = texts.map(function () { return []; });
    for (let k = 0; k < rounds; k++) {
      runs.forEach(function (r, i) { M.step(r, frames, 0); ms[i].push(r.ms / frames); });
    }
    return ms.map(function (list) { list.sort(function (a, b) { return a - b; }); return list[list.length >> 1]; });
  };
})();

(() => {
  const M = window.clothRunner;
  const B = window.__bench;

  function speeds(cl, free) {
    let top = 0;
    for (let k = 0; k < cl.n_verts; k++) {
      if (cl.fixed[k] || (free && !cl.falling[k])) continue;
      top = Math.max(top, Math.hypot(cl.vel[2 * k], cl.vel[2 * k + 1]));
    }
    return top;
  }

  function strainMax(cl) {
    let top = 0;
    for (let e = 0; e < cl.n_struct; e++) {
      const a = cl.edge_a[e], b = cl.edge_b[e];
      top = Math.max(top, Math.hypot(cl.pos[2 * b] - cl.pos[2 * a], cl.pos[2 * b + 1] - cl.pos[2 * a + 1]) / cl.rest[e] - 1);
    }
    return top;
  }

  // A hand on vertex k (where it is) goes through `path` ([dx, dy] from where it took hold, one
  // a frame), lets go, and `after` frames follow. Returns the most edges through an obstacle
  // while held and after, the fastest vertex after, the largest strain at the end.
  B.carry = function (text, settle, k, path, after) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    M.step(r, settle, 0);
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    let held = 0, later = 0, fastest = 0;
    for (let i = 0; i < path.length; i++) {
      ops.move(k, x0 + path[i][0], y0 + path[i][1]);
      M.step(r, 1, 0);
      held = Math.max(held, ops.edges_through());
    }
    ops.release(k);
    for (let f = 0; f < after; f++) {
      M.step(r, 1, 0);
      later = Math.max(later, ops.edges_through());
      fastest = Math.max(fastest, speeds(cl, false));
    }
    return { held: held, after: later, fastest: fastest, strain: strainMax(cl),
             finite: Array.from(cl.pos).every(Number.isFinite) };
  };

  // Obstacle j sent (dx, dy) from where it is, evenly over `frames` frames; `after` frames
  // follow. Returns the most edges through it, how far it got (its share of the way), how far
  // the pins fastened to it strayed from its move, the fastest vertex at the end.
  B.drag = function (text, settle, j, dx, dy, frames, after) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    M.step(r, settle, 0);
    const x0 = cl.obstacle_at[2 * j], y0 = cl.obstacle_at[2 * j + 1];
    const fastened = [], from = [];
    for (let k = 0; k < cl.n_verts; k++) {
      if (cl.fixed[k] && cl.fastened[k] === j + 1) { fastened.push(k); from.push([cl.pos[2 * k], cl.pos[2 * k + 1]]); }
    }
    let through = 0;
    for (let f = 1; f <= frames; f++) {
      ops.move_obstacle(j, x0 + dx * f / frames, y0 + dy * f / frames);
      M.step(r, 1, 0);
      through = Math.max(through, ops.edges_through());
    }
    for (let f = 0; f < after; f++) {
      M.step(r, 1, 0);
      through = Math.max(through, ops.edges_through());
    }
    const mx = cl.obstacle_at[2 * j] - x0, my = cl.obstacle_at[2 * j + 1] - y0;
    let stray = 0;
    fastened.forEach(function (k, i) {
      stray = Math.max(stray, Math.hypot(cl.pos[2 * k] - from[i][0] - mx, cl.pos[2 * k + 1] - from[i][1] - my));
    });
    return { through: through, got: (mx * dx + my * dy) / (dx * dx + dy * dy), stray: stray, fastened: fastened.length,
             fastest: speeds(cl, false), finite: Array.from(cl.pos).every(Number.isFinite) };
  };

  // Run until the cloth sleeps, at most `frames`; returns when (s, -1: never), the fastest
  // vertex and the most edges through an obstacle on the way.
  // Run a scene `frames` frames; the mean of its positions over the last `avg` of them, and its
  // imbalance at the end (the air's figures: a flag's shape in its gusts).
  B.meanShape = function (text, frames, avg) {
    const cl = clothCore.load(text), r = M.run(cl), n2 = 2 * cl.n_verts, acc = new Float64Array(n2);
    for (let f = 1; f <= frames; f++) {
      M.step(r, 1, 0);
      if (f > frames - avg) for (let i = 0; i < n2; i++) acc[i] += cl.pos[i];
    }
    for (let i = 0; i < n2; i++) acc[i] /= avg;
    return { pos: Array.from(acc), imbalance: cl.imbalance, finite: acc.every(Number.isFinite) };
  };

  B.rest = function (text, frames) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    let through = 0;
    for (let f = 1; f <= frames; f++) {
      M.step(r, 1, 0);
      through = Math.max(through, ops.edges_through());
      if (cl.asleep) return { restAt: f * cl.dt, fastest: 0, through: through };
    }
    return { restAt: -1, fastest: speeds(cl, false), through: through, imbalance: cl.imbalance };
  };

  // The hand's pull on what it grips, N.
  function handPull(cl) {
    let fx = 0, fy = 0;
    for (let h = 0; h < cl.n_gripped; h++) {
      const v = cl.gripped[h];
      const dx = cl.aim[2 * v] - cl.pos[2 * v], dy = cl.aim[2 * v + 1] - cl.pos[2 * v + 1];
      const kh = cl.grip_k[v], rr = cl.grip_f[v] / kh;
      const s = kh / Math.sqrt(1 + (dx * dx + dy * dy) / (rr * rr));
      fx += s * dx; fy += s * dy;
    }
    return Math.hypot(fx, fy);
  }

  // A slow pull: a hand on vertex k moves (ux, uy) (a unit direction) at `speed` m/s until the
  // first yarns break (at most `frames`). Returns the hand's pull in that frame, the way it
  // went, how many structural and diagonal edges broke then, and whether any diagonal broke
  // with no yarn of its cell.
  B.tearPull = function (text, settle, k, ux, uy, speed, frames) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    M.step(r, settle, 0);
    const x0 = cl.pos[2 * k], y0 = cl.pos[2 * k + 1];
    ops.grab(k, x0, y0);
    const s0 = cl.n_struct, e0 = cl.n_edges;
    for (let f = 1; f <= frames; f++) {
      const d = speed * cl.dt * f;
      ops.move(k, x0 + ux * d, y0 + uy * d);
      M.step(r, 1, 0);
      if (cl.n_edges < e0) {
        return { force: handPull(cl), travel: d, yarns: s0 - cl.n_struct, diagonals: (e0 - cl.n_edges) - (s0 - cl.n_struct),
                 frame: f };
      }
    }
    return { force: handPull(cl), travel: speed * cl.dt * frames, yarns: 0, diagonals: 0, frame: -1 };
  };
})();

(() => {
  const M = window.clothRunner;
  const B = window.__bench;

  // A reproducible draw in [0, 1) (the runs must be the same on every machine).
  function drawer(seed) {
    let s = seed >>> 0;
    return function () { s = (Math.imul(s, 1664525) + 1013904223) >>> 0; return s / 4294967296; };
  }

  // Random gestures (a hand taking a vertex and dragging it in a straight line at up to
  // `most` m a frame, or a blade), `count` of them, then 5 s with no hand. Returns the most a
  // piece freed by a break raised its energy over the 20 frames after (J; none may), the
  // fastest vertex of a freed piece and the fastest hand, m/s, and the fastest motion of a
  // free vertex about its piece's centre after the 5 s.
  B.gestures = function (text, settle, seed, count, most) {
    const cl = clothCore.load(text), r = M.run(cl), ops = r.ops;
    const rnd = drawer(seed);
    M.step(r, settle, 0);
    let gain = 0, freed = 0, hand = 0;
    let watch = [];                     // {rep, size, e0, until}
    const wasFalling = new Uint8Array(cl.n_verts);
    function pieceOf(rep) {
      ops.energies();
      const p = cl.piece[rep];
      let size = 0;
      for (let k = 0; k < cl.n_verts; k++) if (cl.piece[k] === p) size++;
      return { p: p, size: size, e: cl.piece_energy[3 * p] + cl.piece_energy[3 * p + 1] + cl.piece_energy[3 * p + 2] };
    }
    function step() {
      for (let k = 0; k < cl.n_verts; k++) wasFalling[k] = cl.falling[k];
      const edges = cl.n_edges;
      M.step(r, 1, 0);
      const left = [];
      watch.forEach(function (w) {
        if (!cl.falling[w.rep]) return;
        const now = pieceOf(w.rep);
        if (now.size !== w.size || r.frame > w.until) return;
        gain = Math.max(gain, now.e - w.e0);
        left.push(w);
      });
      watch = left;
      if (cl.n_edges < edges) {
        const seen = {};
        for (let k = 0; k < cl.n_verts; k++) {
          if (!cl.falling[k] || wasFalling[k] || seen[cl.piece[k]]) continue;
          seen[cl.piece[k]] = true;
          const now = pieceOf(k);
          watch.push({ rep: k, size: now.size, e0: now.e, until: r.frame + 20 });
        }
      }
      for (let k = 0; k < cl.n_verts; k++) {
        if (cl.falling[k]) freed = Math.max(freed, Math.hypot(cl.vel[2 * k], cl.vel[2 * k + 1]));
      }
    }
    for (let a = 0; a < count; a++) {
      if (rnd() < 0.8) {
        const k = Math.floor(rnd() * cl.n_verts);
        let x = cl.pos[2 * k], y = cl.pos[2 * k + 1];
        ops.grab(k, x, y);
        const n = 3 + Math.floor(rnd() * 13), ang = 2 * Math.PI * rnd(), sp = most * (0.02 + 0.98 * rnd());
        hand = Math.max(hand, sp / cl.dt);
        for (let i = 0; i < n; i++) {
          x += sp * Math.cos(ang); y += sp * Math.sin(ang);
          ops.move(k, x, y);
          step();
        }
        ops.release(k);
      } else {
        const x0 = 2 * rnd(), y0 = -1.3 * rnd(), x1 = x0 + rnd() - 0.5, y1 = y0 + rnd() - 0.5;
        ops.cut(x0, y0, x1, y1);
      }
      const rest = 1 + Math.floor(rnd() * 10);
      for (let i = 0; i < rest; i++) step();
    }
    M.step(r, Math.round(5 / cl.dt), 0);
    // motion about each free piece's centre
    const P = {};
    for (let k = 0; k < cl.n_verts; k++) {
      if (!cl.falling[k]) continue;
      const p = cl.piece[k], m = cl.mass[k];
      const q = P[p] || (P[p] = { m: 0, x: 0, y: 0 });
      q.m += m; q.x += m * cl.vel[2 * k]; q.y += m * cl.vel[2 * k + 1];
    }
    let inner = 0;
    for (let k = 0; k < cl.n_verts; k++) {
      if (!cl.falling[k]) continue;
      const q = P[cl.piece[k]];
      inner = Math.max(inner, Math.hypot(cl.vel[2 * k] - q.x / q.m, cl.vel[2 * k + 1] - q.y / q.m));
    }
    return { gain: gain, freed: freed, hand: hand, inner: inner, broken: cl.broken,
             finite: Array.from(cl.pos).every(Number.isFinite) };
  };
})();
