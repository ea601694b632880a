// The measuring code shared by the page's compare mode and the benchmark (bench/ drives
// it in Chromium): what the page shows and what the benchmark reports are timed and
// measured by these same functions.
//
// A run is {cloth, ops, next, frame, ms, proj}: a cloth, its operations (clothCore.ops),
// the index of its scene's next scripted action, the frames it has run, and the time and
// constraint projections of its last batch. A batch is timed as a whole with
// performance.now() (its resolution is 100 us on file://; per-frame timings would be noise).
'use strict';

window.clothMeasure = (function () {
  const core = window.clothCore;

  function run(cloth) {
    const r = { cloth: cloth, ops: core.ops(cloth), next: 0, frame: 0, ms: 0, proj: 0 };
    r.next = core.applyDue(cloth, 0, 0);      // the scene's actions of frame 0 come first
    return r;
  }

  // Run up to `frames` frames of run r, each followed by the scene's actions of that frame
  // (cloth/api.py simulate); with a budget (ms) stop once it is spent, after at least one.
  // Returns the frames done; r.ms and r.proj hold the batch's time and projections.
  function step(r, frames, budgetMs) {
    const cloth = r.cloth, ops = r.ops, scripted = cloth.scene.actions.length;
    const p0 = cloth.projections;
    const t0 = performance.now();
    let done = 0;
    while (done < frames) {
      ops.frame();
      done++;
      r.frame++;
      if (r.next < scripted) r.next = core.applyDue(cloth, r.next, r.frame);
      if (budgetMs > 0 && performance.now() - t0 > budgetMs) break;
    }
    r.ms = performance.now() - t0;
    r.proj = cloth.projections - p0;
    return done;
  }

  // What a cloth is running, as the benchmark's tables and the compare panels say it.
  function describe(cl) {
    return { solver: cl.use_xpbd ? 'xpbd' : 'jakobsen', substeps: cl.substeps,
             iterations: cl.iterations, tethers: !!cl.use_tethers, tolerance: cl.tolerance,
             shear: !!cl.scene.shear, compliance: cl.scene.compliance, sleep: !!cl.use_sleep,
             cells: !!cl.use_cells, lines: !!cl.use_lines, damping: cl.scene.damping,
             tear: cl.tear, n_verts: cl.n_verts, n_edges: cl.n_edges };
  }

  // 'xpbd S8 x 1, tethers, cells, lines, tol 0.0001' (the benchmark's setting column).
  function label(cl) {
    const d = describe(cl);
    const parts = [d.solver + ' S' + d.substeps + ' x ' + d.iterations];
    if (d.tethers) parts.push('tethers');
    if (d.cells) parts.push('cells');
    if (d.lines) parts.push('lines');
    if (d.shear) parts.push('shear');
    // The seed's method ignores compliance: only a solver that honours it says it.
    if (d.compliance > 0 && d.solver === 'xpbd') parts.push('compliance ' + d.compliance);
    if (d.tolerance > 0) parts.push('tol ' + d.tolerance);
    if (d.tear > 0) parts.push('tear ' + d.tear);
    return parts.join(', ');
  }

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

  return { run: run, step: step, describe: describe, label: label, rmsError: rmsError,
           maxError: maxError, restGrid: restGrid };
})();
