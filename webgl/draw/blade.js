// The blade's trail: where a cutting stroke went in the last TRAIL_MS, drawn fading on a 2D
// canvas over the stage. Points go into a ring buffer made once (x, y in CSS px of the stage,
// the time, and NaN where a stroke starts), so neither a stroke nor its drawing allocates.
import { clothCanvas2d } from './canvas2d.js';

export const clothBlade = (function () {
  const TRAIL_MS = 450;
  const N = 256;                 // points kept (a stroke's last ones)

  function create(canvas) {
    const ctx = canvas.getContext('2d');
    const pts = new Float64Array(3 * N);
    let head = 0, count = 0, shown = false;

    // A point of a stroke at time t (ms); `start`: a new stroke (not joined to the last).
    function add(x, y, t, start) {
      if (start) {
        pts[3 * head] = NaN; pts[3 * head + 1] = NaN; pts[3 * head + 2] = t;
        head = (head + 1) % N;
        if (count < N) count++;
      }
      pts[3 * head] = x; pts[3 * head + 1] = y; pts[3 * head + 2] = t;
      head = (head + 1) % N;
      if (count < N) count++;
    }

    // Draw the trail as it is at time `now` (ms); returns whether anything is left to fade.
    function draw(now) {
      if (!ctx) return false;
      let live = false;
      for (let j = 0; j < count && !live; j++) {
        const i = (head - 1 - j + N) % N;
        live = now - pts[3 * i + 2] < TRAIL_MS;
      }
      if (!live && !shown) return false;
      const box = clothCanvas2d.fit(canvas, ctx);
      ctx.clearRect(0, 0, box.w, box.h);
      shown = live;
      if (!live) return false;
      ctx.lineCap = 'round';
      ctx.lineWidth = 2.5;
      let px = NaN, py = NaN;
      for (let j = count - 1; j >= 0; j--) {
        const i = (head - 1 - j + N) % N;
        const x = pts[3 * i], y = pts[3 * i + 1], age = now - pts[3 * i + 2];
        if (x === x && px === px && age < TRAIL_MS) {
          ctx.strokeStyle = 'rgba(120, 230, 255, ' + (1 - age / TRAIL_MS).toFixed(3) + ')';
          ctx.beginPath();
          ctx.moveTo(px, py);
          ctx.lineTo(x, y);
          ctx.stroke();
        }
        px = x; py = y;
      }
      return true;
    }

    return { add: add, draw: draw };
  }

  return { create: create };
})();
