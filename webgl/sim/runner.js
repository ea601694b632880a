// Runs: a cloth stepped frame by frame with its scene's scripted actions, in timed batches.
// The page's loop (every panel of compare mode) and the benchmark (bench/harness.js, in
// Chromium) both step cloths through these functions, so what the page shows and what the
// benchmark reports are stepped and timed alike.
//
// A run is {cloth, ops, next, frame, ms, proj}: a cloth, its operations (clothCore.ops),
// the index of its scene's next scripted action, the frames it has run, and the time and
// sweeps of its last batch. A batch is timed as a whole with
// performance.now() (its resolution is 100 us on file://; per-frame timings would be noise).
import { clothCore } from './core.js';
import { clothScenes } from './scenes.js';

export const clothRunner = (function () {
  const core = clothCore;

  function run(cloth) {
    const r = { cloth: cloth, ops: core.ops(cloth), next: 0, frame: 0, ms: 0, proj: 0 };
    r.next = core.applyDue(cloth, 0, 0);      // the scene's actions of frame 0 come first
    return r;
  }

  // Run up to `frames` frames of run r, each followed by the scene's actions of that frame
  // (cloth/api.py simulate); with a budget (ms) stop once it is spent, after at least one.
  // Returns the frames done; r.ms and r.proj hold the batch's time and its sweeps (the
  // solver's passes over the cloth: a machine-independent cost).
  function step(r, frames, budgetMs) {
    const cloth = r.cloth, ops = r.ops, scripted = cloth.scene.actions.length;
    const p0 = cloth.sweeps;
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
    r.proj = cloth.sweeps - p0;
    return done;
  }

  // Panel i of a session (clothCore.session: its script is the session's to apply) as a run:
  // its cloth, its operations, and the timing of its last batch.
  function panel(session, i) {
    const cloth = session.panels[i];
    return { cloth: cloth, ops: core.ops(cloth), frame: session.frame, ms: 0, proj: 0 };
  }

  // Run up to `frames` frames of session panel i (r = panel(session, i)), each followed by
  // the script's actions of that frame; with a budget (ms) stop once it is spent, after at
  // least one. Returns the frames done; the session's frame count moves on once every panel
  // has run them (clothCore.session.framesRan).
  function stepPanel(r, session, i, frames, budgetMs) {
    const stepOne = core.session.stepPanel, cloth = r.cloth;
    const p0 = cloth.sweeps;
    const t0 = performance.now();
    let done = 0;
    while (done < frames) {
      done++;
      stepOne(session, i, session.frame + done);
      if (budgetMs > 0 && performance.now() - t0 > budgetMs) break;
    }
    r.frame += done;
    r.ms = performance.now() - t0;
    r.proj = cloth.sweeps - p0;
    return done;
  }

  // What a cloth is running, as the benchmark's tables and the compare panels say it.
  function describe(cl) {
    return { solver: cl.scene.solver, substeps: cl.substeps, iterations: cl.iterations,
             corrections: cl.corrections, stretch: cl.scene.stretch, shear: cl.scene.shear,
             density: cl.scene.density, sleep: !!cl.scene.sleep, damping: cl.scene.damping,
             strength: cl.scene.strength, n_verts: cl.n_verts, n_edges: cl.n_edges };
  }

  // 'vbd S1 x 5 +1': the solver and its budget, substeps x iterations (+ corrections), for a
  // narrow compare panel's label.
  function headline(cl) {
    return cl.scene.solver + ' S' + cl.substeps + ' x ' + cl.iterations +
      (cl.corrections > 0 && cl.scene.solver === core.schema().defaultSolver ? ' +' + cl.corrections : '');
  }

  // 'vbd S1 x 5 +1, jersey' or '..., 500/50 N/m 0.2 kg/m²' (the benchmark's setting column):
  // the fabric only where the solver honours it.
  function label(cl) {
    const d = describe(cl);
    const parts = [headline(cl)];
    if (cl.scene.solver !== core.schema().seedSolver) {
      const name = clothScenes ? clothScenes.materialOf(d.stretch, d.shear, d.density) : 'custom';
      parts.push(name !== 'custom' ? name : d.stretch + '/' + d.shear + ' N/m ' + d.density + ' kg/m\u00b2');
    }
    if (d.strength > 0) parts.push('strength ' + d.strength + ' N/m');
    return parts.join(', ');
  }

  return { run: run, step: step, panel: panel, stepPanel: stepPanel, describe: describe, headline: headline, label: label };
})();
