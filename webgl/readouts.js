// What the page says in numbers: the colour scale a frame is drawn with, the readouts under
// the cloth, the compare panels' labels, and the words for the core's speed cap. Reads the
// app's state (its panels' measures and timings); writes only through the UI.
'use strict';

window.clothReadouts = (function () {
  // Auto is the seed's normalisation by the frame's maximum, above a floor: solver noise on an
  // inextensible cloth at rest (1e-7 on a curtain, up to 1e-3 in a slack hang's rows) stays
  // dark, while a material's own strain (jersey hung 1.5 m: 0.6% at the rod) fills the scale
  // from the hem to the pins. One scale for every panel: the largest of them, so a colour
  // means one strain everywhere.
  const AUTO_FLOOR = 0.002;
  const SLOW_MOTION = 0.9;     // below this share of real time, the readout says "slow motion"

  // The largest edge |diff| (strain mode) or node stress (stress mode) over the panels.
  function frameMax(panels, mode) {
    let top = 0;
    for (let i = 0; i < panels.length; i++) {
      const c = panels[i].cloth;
      const v = mode === 'stress' ? c.max_stress : c.max_diff;
      if (v > top) top = v;
    }
    return top;
  }

  // The full scale of the colours: the fixed one, or Auto's (above).
  function scaleOf(panels, mode, scaleMode, fullScale) {
    if (scaleMode === 'fixed') return fullScale;
    return Math.max(frameMax(panels, mode), AUTO_FLOOR);
  }

  // The core's max_speed safety net engaged: say why. A hand that moved faster than the cloth
  // can follow (metres in a frame), or settings that pump energy (one sweep per step on an
  // undamped grid; damping does not cure it: measured, 1.8 million capped vertex-steps with
  // damping 1).
  const DEFAULT_MAX_SPEED = window.clothCore.schema().keys.max_speed.fallback;
  function cappedNote(cloth) {
    const speed = cloth.scene.max_speed, own = speed < DEFAULT_MAX_SPEED;
    const capped = 'speeds were capped at ' + (own ? 'the scene\'s max_speed of ' : 'max_speed, ') + speed + ' m/s';
    if (cloth.n_held > 0) return 'A very fast drag: ' + capped + ' (the hand moved faster than the cloth can follow)';
    if (own) return capped.charAt(0).toUpperCase() + capped.slice(1);
    return 'Unstable settings: ' + capped + '; use more iterations or substeps' +
      (cloth.use_xpbd ? '' : ', or the default solver');
  }

  function fmt(v) { return window.clothUI.fmt(v, 4); }

  function create(ui, compareUI, runner) {
    ui.setAutoFloor(AUTO_FLOOR);
    // The readouts for the app's state (panels, rects, paused, speed, renderMs, fps, scale,
    // scaleMode, mode); asleep: every panel is at rest.
    function show(state, asleep) {
      const c = state.cloth;
      const slow = !state.paused && state.speed < SLOW_MOTION;
      let simMs = 0;
      state.panels.forEach(function (p) { if (Number.isFinite(p.simMs)) simMs += p.simMs; });
      ui.setReadouts({
        simMs: asleep ? NaN : simMs, renderMs: state.renderMs, fps: state.fps, rms: c.rms_strain, max: c.max_strain,
        size: c.cols + '×' + c.rows + ' · ' + c.n_edges + (c.n_edges === 1 ? ' edge' : ' edges') +
          (c.broken > 0 ? ' left of ' + (c.n_edges + c.broken) : '') +
          (state.panels.length > 1 ? ' · ' + state.panels.length + ' panels' : '') + (asleep ? ' · at rest' : '') +
          (slow ? ' · slow motion ×' + state.speed.toFixed(2) : ''),
      });
      ui.setLegend(state.scale, state.scaleMode === 'fixed' ? 'fixed'
        : (frameMax(state.panels, state.mode) > AUTO_FLOOR ? 'max' : 'floor'));
      if (state.panels.length > 1) {
        state.panels.forEach(function (p, i) {
          // A narrow panel (a phone, four panels) gets the short label: the solver and its
          // steps; the RMS strain and the cost. The numbers come first on their line and are
          // never cut (compare.js).
          const r = state.rects[i], small = !r || r.w < 340;
          const label = small ? runner.headline(p.cloth) : runner.label(p.cloth);
          const ms = Number.isFinite(p.simMs) ? p.simMs.toFixed(2) + (small ? ' ms' : ' ms/frame') : 'at rest';
          compareUI.setLabel(i, (i + 1) + ' · ' + label,
            small ? 'rms ' + fmt(p.cloth.rms_strain) + ' · ' + ms
                  : 'strain rms ' + fmt(p.cloth.rms_strain) + ' · max ' + fmt(p.cloth.max_strain) + ' · ' + ms);
        });
      }
    }

    return { show: show };
  }

  return { AUTO_FLOOR: AUTO_FLOOR, scaleOf: scaleOf, cappedNote: cappedNote, create: create };
})();
