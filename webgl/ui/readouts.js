// What the page says in numbers: the colour scale a frame is drawn with, the legend (what the
// colours are, of which fabric, and how well the solver has balanced its forces), the readouts
// under the cloth and the compare panels' labels. Reads the app's state (its panels' measures
// and timings); writes only through the UI.
import { clothCore } from '../sim/core.js';
import { clothScenes } from '../sim/scenes.js';
import { clothUI } from './ui.js';

export const clothReadouts = (function () {
  // Auto: in the stress mode the seed's normalisation by the frame's maximum; in the strain
  // mode the value 99% of the edges are at or below (cloth/measure.py HIGH_SHARE: where a clamp
  // ends the strain peaks more the finer the grid, and a scale by the largest would darken the
  // rest of the cloth with it). Above a floor: a stiff fabric's own strain (cotton hung 1 m:
  // 0.03% at the rod) still fills the scale, a cloth that does not pull at all stays dark. One
  // scale for every panel: the largest of them, so a colour means one strain everywhere.
  const AUTO_FLOOR = 1e-4;
  const SLOW_MOTION = 0.9;     // below this share of real time, the readout says "slow motion"

  // The top of the scale over the panels: the edges' high value (strain mode) or the largest
  // node stress (stress mode).
  function frameMax(panels, mode) {
    let top = 0;
    for (let i = 0; i < panels.length; i++) {
      const c = panels[i].cloth;
      const v = mode === 'stress' ? c.max_stress : c.high_value;
      if (v > top) top = v;
    }
    return top;
  }

  // The full scale of the colours: the fixed one, or Auto's (above).
  function scaleOf(panels, mode, scaleMode, fullScale) {
    if (scaleMode === 'fixed') return fullScale;
    return Math.max(frameMax(panels, mode), AUTO_FLOOR);
  }

  // The legend's words for the first panel: what an edge's colour is (the membrane's tension
  // strain, or the seed's |diff|; cloth/measure.py), the fabric, and how far the solver's last
  // step left its forces from balance (cloth/vbd.py `imbalance`: the RMS unbalanced force over
  // the RMS weight of a vertex): at rest and balanced within the core's rest bound
  // (cloth/sleep.py SLEEP_IMBALANCE), the colours are the fabric's strain field (the field
  // then matches the exact statics within a few per cent: `python -m bench`).
  function legendOf(cloth, mode) {
    const core = clothCore, seed = cloth.scene.solver === core.schema().seedSolver;
    const what = mode === 'stress' ? 'node stress Q' : seed ? 'edge |diff|' : 'tension strain';
    if (seed) return { name: what, note: 'the seed\'s rigid edges' };
    const s = clothScenes, name = s.materialOf(cloth.scene.stretch, cloth.scene.shear, cloth.scene.density);
    const fabric = name === 'custom' ? cloth.scene.stretch + ' N/m' : s.MATERIALS[name].label.split(' (')[0].toLowerCase();
    const off = cloth.imbalance;
    const balance = !(off > 0) ? 'balanced' : off <= core.schema().restImbalance ? 'balanced to ' + fmtPct(off)
      : 'settling: ' + fmtPct(off) + ' off balance';
    return { name: what, note: fabric + ' · ' + balance };
  }

  // The frame rate: frames counted over a window of time. The animation frames' times go into
  // a ring (no allocation per frame); the rate is the gaps counted back from the latest frame
  // until they span FPS_WINDOW seconds and number FPS_MIN_GAPS, over the time they span: 1 /
  // their mean gap (a frame every 0.5 s reads 2; a stall in the window counts whole). An average of 1 / gap over gaps is not a rate: after
  // a long stall the burst of short frames dominates it (a 5.6 frames/s page read 16-43).
  const FPS_WINDOW = 1.0;
  const FPS_MIN_GAPS = 4;
  const FPS_RING = 256;        // frames kept: more than a 1 s window holds at 240 Hz

  function frameClock() {
    const times = new Float64Array(FPS_RING);
    let count = 0, next = 0;
    return {
      // A frame drawn at `t` seconds.
      push: function (t) { times[next] = t; next = (next + 1) % FPS_RING; if (count < FPS_RING) count++; },
      // Frames per second over the window ending at the latest frame (NaN before two frames).
      rate: function () {
        if (count < 2) return NaN;
        const newest = times[(next - 1 + FPS_RING) % FPS_RING];
        let gaps = 0, oldest = newest;
        while (gaps + 1 < count && (newest - oldest < FPS_WINDOW || gaps < FPS_MIN_GAPS)) {
          oldest = times[(next - 2 - gaps + 2 * FPS_RING) % FPS_RING];
          gaps++;
        }
        return newest > oldest ? gaps / (newest - oldest) : NaN;
      },
      reset: function () { count = 0; next = 0; },
    };
  }

  // The note for a scene that replays: `frames` is the session's replay end (a scene's
  // optional `frames`; -1 when it has none, and then nothing replays), `from` where it came
  // from ('the link', or '' for the Replay button).
  function replayNote(frames, from) {
    const where = from ? ' from ' + from : '';
    if (!(frames > 0)) return from ? 'Opened the scene' + where + ': it holds no recorded frames, so it runs live'
      : 'Nothing recorded yet: the scene restarts from its start';
    return 'Replaying the recording' + where + ' (' + frames + (frames === 1 ? ' frame' : ' frames') +
      '); a gesture takes over';
  }

  function fmtPct(v) { return clothUI.fmt(100 * v, 2) + '%'; }

  function fmt(v) { return clothUI.fmt(v, 4); }

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
      const legend = legendOf(c, state.mode);
      ui.setLegend(state.scale, state.scaleMode === 'fixed' ? 'fixed'
        : frameMax(state.panels, state.mode) <= AUTO_FLOOR ? 'floor' : state.mode === 'stress' ? 'max' : 'high',
        legend.name, legend.note);
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

  return { AUTO_FLOOR: AUTO_FLOOR, scaleOf: scaleOf, legendOf: legendOf, create: create, frameClock: frameClock, replayNote: replayNote,
           FPS_WINDOW: FPS_WINDOW, FPS_MIN_GAPS: FPS_MIN_GAPS };
})();
