// Live charts, hand-written on a 2D canvas: RMS strain (log axis) and simulation ms/frame
// of each panel over the last WINDOW seconds, one colour per panel, with axis labels and the
// current values. Samples go into ring buffers (typed arrays made once), one sample every
// SAMPLE_MS of wall clock while the simulation runs; drawing only strokes paths, so neither
// allocates per frame.
import { clothCanvas2d } from './canvas2d.js';

export const clothCharts = (function () {
  const WINDOW = 20;                  // seconds shown
  const SAMPLE_MS = 100;              // one sample per 100 ms
  const N = Math.round(WINDOW * 1000 / SAMPLE_MS);
  const MAX_SERIES = 4;
  const COLORS = ['#ffbf33', '#5ec8ff', '#9cff70', '#ff7ad9'];
  const STRAIN_LO = -8, STRAIN_HI = 1;   // log10 bounds of the strain axis

  function create(canvas) {
    const ctx = canvas.getContext('2d');
    const strain = [], ms = [];
    for (let i = 0; i < MAX_SERIES; i++) { strain.push(new Float64Array(N)); ms.push(new Float64Array(N)); }
    let head = 0, count = 0, series = 1, lastT = -1;

    function reset(n) {
      series = Math.max(1, Math.min(n, MAX_SERIES));
      head = 0; count = 0; lastT = -1;
    }

    // Offer a sample at wall-clock time t (ms): kept when SAMPLE_MS have passed since the
    // last one, or always when `every` (a frame stepped by hand is an event of its own).
    // rms(i) and simMs(i) give panel i's values. Returns whether it was kept.
    function sample(t, rms, simMs, every) {
      if (!every && lastT >= 0 && t - lastT < SAMPLE_MS) return false;
      lastT = t;
      for (let i = 0; i < series; i++) { strain[i][head] = rms(i); ms[i][head] = simMs(i); }
      head = (head + 1) % N;
      if (count < N) count++;
      return true;
    }

    // What the last draw wrote: [text, x, y, width, box x, y, w, h] CSS px (the tests hold
    // every text inside its chart).
    const written = [];
    const LINE = 12;                 // px a line of text takes (10 px font, top baseline)
    let box = [0, 0, 0, 0];
    function text(t, x, y) {
      ctx.fillText(t, x, y);
      written.push([t, x, y, ctx.measureText(t).width].concat(box));
    }

    // One chart in the box (x, y, w, h), CSS px. value(i, j): series i's j-th oldest sample
    // mapped to [0, 1] of the axis (NaN: no point).
    function plot(x, y, w, h, title, lo, hi, map, now) {
      ctx.strokeStyle = '#2c313b';
      ctx.lineWidth = 1;
      ctx.strokeRect(x + 0.5, y + 0.5, w - 1, h - 1);
      box = [x, y, w, h];
      ctx.fillStyle = '#8b93a3';
      ctx.font = '10px ui-monospace, Menlo, Consolas, monospace';
      ctx.textBaseline = 'top';
      ctx.save();                        // nothing drawn past the chart's box
      ctx.beginPath();
      ctx.rect(x, y, w, h);
      ctx.clip();
      text(title, x + 3, y + 2);
      // The current values, one per panel in its colour, after the title; a value that would
      // run past the box starts a line of its own (four panels in a narrow box).
      let tx = x + 6 + ctx.measureText(title).width, ty = y + 2;
      for (let i = 0; i < series && count > 0; i++) {
        const value = now(i), vw = ctx.measureText(value).width;
        if (tx + vw > x + w - 3 && tx > x + 3) { tx = x + 3; ty += LINE; }
        ctx.fillStyle = COLORS[i];
        text(value, tx, ty);
        tx += vw + 6;
      }
      ctx.fillStyle = '#8b93a3';
      // The axis' top label: at the right of the values' last line, or below it where they
      // reach it.
      const hiW = ctx.measureText(hi).width;
      text(hi, x + w - hiW - 3, tx - 6 > x + w - hiW - 6 ? ty + LINE : ty);
      text(lo, x + w - ctx.measureText(lo).width - 3, y + h - LINE);
      text('−' + WINDOW + ' s', x + 3, y + h - LINE);
      for (let i = 0; i < series; i++) {
        ctx.strokeStyle = COLORS[i];
        ctx.lineWidth = 1.25;
        ctx.beginPath();
        let pen = false;
        for (let j = 0; j < count; j++) {
          const idx = (head - count + j + N) % N;
          const v = map(i, idx);
          if (!(v === v)) { pen = false; continue; }   // NaN: a gap (at rest, nothing timed)
          const px = x + 1 + (w - 2) * (N - count + j) / (N - 1);
          const py = y + h - 1 - (h - 16) * Math.max(0, Math.min(1, v));
          if (pen) ctx.lineTo(px, py); else ctx.moveTo(px, py);
          pen = true;
        }
        ctx.stroke();
      }
      ctx.restore();
    }

    let msTop = 1;    // the ms axis' top: a round number above the largest sample shown
    function niceTop(v) {
      if (!(v > 0)) return 1;
      const base = Math.pow(10, Math.floor(Math.log(v) / Math.LN10));
      const steps = [1, 2, 5, 10];
      for (let i = 0; i < steps.length; i++) if (steps[i] * base >= v) return +(steps[i] * base).toPrecision(1);
      return 10 * base;
    }
    function mapStrain(i, idx) {
      const v = strain[i][idx];
      if (!(v > 0)) return v === 0 ? 0 : NaN;
      return (Math.log(v) / Math.LN10 - STRAIN_LO) / (STRAIN_HI - STRAIN_LO);
    }
    function mapMs(i, idx) { return ms[i][idx] / msTop; }
    function at(arr, i) { return arr[i][(head - 1 + N) % N]; }
    function nowStrain(i) { const v = at(strain, i); return v === v ? v.toExponential(1) : '–'; }
    function nowMs(i) { const v = at(ms, i); return v === v ? v.toFixed(2) : 'at rest'; }

    function draw() {
      if (!ctx) return;
      const box = clothCanvas2d.fit(canvas, ctx);
      const cssW = box.w, cssH = box.h;
      ctx.clearRect(0, 0, cssW, cssH);
      written.length = 0;
      let top = 0;
      for (let i = 0; i < series; i++) {
        for (let j = 0; j < count; j++) { const v = ms[i][j]; if (v > top) top = v; }
      }
      msTop = niceTop(top);
      const half = Math.floor(cssH / 2) - 2;
      plot(0, 0, cssW, half, 'RMS strain (log)', '1e' + STRAIN_LO, '1e' + STRAIN_HI, mapStrain, nowStrain);
      plot(0, half + 4, cssW, half, 'sim ms/frame', '0', String(msTop), mapMs, nowMs);
    }

    // The latest sample of series i: [rms strain, sim ms] (NaN before the first).
    function latest(i) {
      if (count === 0) return [NaN, NaN];
      const idx = (head - 1 + N) % N;
      return [strain[i][idx], ms[i][idx]];
    }

    return { reset: reset, sample: sample, draw: draw, latest: latest, color: function (i) { return COLORS[i]; },
             count: function () { return count; }, written: function () { return written.slice(); } };
  }

  return { create: create, COLORS: COLORS };
})();
