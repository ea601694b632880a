// What the page says in numbers: the legend (what the colours are, of which fabric, and how
// well the solver has balanced its forces), the readouts under the cloth and the compare
// panels' labels. Reads the panels' readings (clothCore.readings: a snapshot of their
// measures) and the timings it is given; writes only through the UI.
import { clothCore } from '../sim/core.js';
import { clothRunner } from '../sim/runner.js';
import { clothScenes } from '../sim/scenes.js';
import { clothPainter } from '../draw/painter.js';
import { clothUI } from './ui.js';

export const clothReadouts = (function () {
  const AUTO_FLOOR = clothPainter.AUTO_FLOOR;
  const SLOW_MOTION = 0.9;     // below this share of real time, the readout says "slow motion"

  // The legend's words for a panel's readings: what an edge's colour is (the membrane's tension
  // strain, or the seed's |diff|; cloth/measure.py), the fabric, and how far the solver's last
  // step left its forces from balance (cloth/vbd.py `imbalance`: the RMS unbalanced force over
  // the RMS weight of a vertex): at rest and balanced within the core's rest bound
  // (cloth/sleep.py SLEEP_IMBALANCE), the colours are the fabric's strain field (the field
  // then matches the exact statics within a few per cent: `python -m bench`).
  function legendOf(snap, mode) {
    const core = clothCore, seed = snap.scene.solver === core.schema().seedSolver;
    const what = mode === 'stress' ? 'node stress Q' : seed ? 'edge |diff|' : 'tension strain';
    if (seed) return { name: what, note: 'the seed\'s rigid edges' };
    const s = clothScenes, name = s.materialOf(snap.scene.stretch, snap.scene.shear, snap.scene.density);
    const fabric = name === 'custom' ? snap.scene.stretch + ' N/m' : s.MATERIALS[name].label.split(' (')[0].toLowerCase();
    const off = snap.imbalance;
    // A solver that does not measure its balance (XPBD) is not said to be balanced.
    if (core.schema().measured.indexOf(snap.scene.solver) < 0) {
      return { name: what, note: fabric + ' · balance not measured by this solver' };
    }
    if (!isFinite(off)) return { name: what, note: fabric + ' · not finite: the solve blew up' };
    // Past a vertex's weight (a fluttering flag, a hard drag) a percentage reads as noise
    // (7859%): the legend says in motion, and by how many weights.
    const balance = !(off > 0) ? 'balanced' : off <= core.schema().restImbalance ? 'balanced to ' + fmtPct(off)
      : off < 1 ? 'settling: ' + fmtPct(off) + ' off balance'
      : 'in motion: ' + (off < 10 ? off.toFixed(1) : String(Math.round(off))) + '× its weight off balance';
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

  function create(ui, compareUI) {
    const runner = clothRunner;
    ui.setAutoFloor(AUTO_FLOOR);
    // The readouts for `now`: {reads (the panels' readings), simMs (each panel's ms a frame,
    // NaN at rest), rects (the panels' rectangles), paused, speed (simulated over wall-clock
    // time), renderMs, fps, scale, scaleMode, mode, away (the first panel whose cloth is out of
    // its view, or -1)}; asleep: every panel is at rest.
    function show(now, asleep) {
      const c = now.reads[0], n = now.reads.length;
      const slow = !now.paused && now.speed < SLOW_MOTION;
      let simMs = 0;
      now.simMs.forEach(function (ms) { if (Number.isFinite(ms)) simMs += ms; });
      ui.setReadouts({
        simMs: asleep ? NaN : simMs, renderMs: now.renderMs, fps: now.fps, rms: c.rms_strain, max: c.max_strain,
        size: c.cols + '×' + c.rows + ' · ' + c.springs + (c.springs === 1 ? ' edge' : ' edges') +
          (c.broken > 0 ? ' left of ' + (c.springs + c.broken) : '') +
          (n > 1 ? ' · ' + n + ' panels' : '') + (asleep ? ' · at rest' : '') +
          (slow ? ' · slow motion ×' + now.speed.toFixed(2) : '') +
          (now.away < 0 ? '' : ' · ' + (n > 1 ? 'panel ' + (now.away + 1) + '’s cloth' : 'the cloth') +
            ' has left the view (R resets it)'),
      });
      const legend = legendOf(c, now.mode);
      ui.setLegend(now.scale, now.scaleMode === 'fixed' ? 'fixed'
        : clothPainter.frameMax(now.reads, now.mode) <= AUTO_FLOOR ? 'floor' : now.mode === 'stress' ? 'max' : 'high',
        legend.name, legend.note);
      if (n > 1) {
        now.reads.forEach(function (p, i) {
          // A narrow panel (a phone, four panels) gets the short label: the solver and its
          // steps; the RMS strain and the cost. The numbers come first on their line and are
          // never cut (compare.js).
          const r = now.rects[i], small = !r || r.w < 340, ms = now.simMs[i];
          const label = small ? runner.headline(p) : runner.label(p);
          const cost = Number.isFinite(ms) ? ms.toFixed(2) + (small ? ' ms' : ' ms/frame') : 'at rest';
          compareUI.setLabel(i, (i + 1) + ' · ' + label,
            small ? 'rms ' + fmt(p.rms_strain) + ' · ' + cost
                  : 'strain rms ' + fmt(p.rms_strain) + ' · max ' + fmt(p.max_strain) + ' · ' + cost);
        });
      }
    }

    return { show: show };
  }

  return { AUTO_FLOOR: AUTO_FLOOR, legendOf: legendOf, create: create, frameClock: frameClock, replayNote: replayNote,
           FPS_WINDOW: FPS_WINDOW, FPS_MIN_GAPS: FPS_MIN_GAPS };
})();
