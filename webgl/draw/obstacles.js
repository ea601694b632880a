// The obstacles (scene key `obstacles`): drawn on a 2D canvas over the cloth, each panel's in
// its own rectangle and scale, from the panel's snapshot (clothCore.snapshot: shapes, half
// sizes, centres). A vertex is never inside one, so the fill hides no cloth; an edge that
// crosses a shape narrower than the spacing shows through it. Nothing is drawn, or cleared
// again, in a scene without obstacles.
import { clothCanvas2d } from './canvas2d.js';

export const clothObstacles = (function () {
  const FILL = 'rgba(150, 160, 175, 0.55)';
  const LINE = 'rgba(225, 232, 240, 0.9)';
  const HELD = 'rgba(120, 230, 255, 0.95)';

  function create(canvas) {
    const ctx = canvas.getContext('2d');
    let shown = false;

    // panels: [{draw (renderer panel), snap}]; rects: their rectangles (CSS px; [] for one
    // panel: all the canvas); held: the index of the obstacle a pointer drags, or -1.
    function draw(panels, rects, held) {
      if (!ctx) return;
      let any = false;
      for (let i = 0; i < panels.length; i++) if (panels[i].snap.n_obstacles > 0) any = true;
      if (!any && !shown) return;
      const box = clothCanvas2d.fit(canvas, ctx);
      ctx.clearRect(0, 0, box.w, box.h);
      shown = any;
      for (let i = 0; i < panels.length; i++) {
        const snap = panels[i].snap, d = panels[i].draw, r = rects.length > 1 ? rects[i] : null;
        if (!d || snap.n_obstacles === 0) continue;
        ctx.save();
        if (r) { ctx.beginPath(); ctx.rect(r.x, r.y, r.w, r.h); ctx.clip(); }
        const s = d.pixelsPerMetre();
        for (let j = 0; j < snap.n_obstacles; j++) {
          const x = d.canvasX(snap.obstacle_at[2 * j]), y = d.canvasY(snap.obstacle_at[2 * j + 1]);
          const hx = snap.obstacle_half[2 * j] * s, hy = snap.obstacle_half[2 * j + 1] * s;
          ctx.beginPath();
          if (snap.obstacle_shape[j] === 0) ctx.arc(x, y, hx, 0, 2 * Math.PI);
          else ctx.rect(x - hx, y - hy, 2 * hx, 2 * hy);
          ctx.fillStyle = FILL;
          ctx.fill();
          ctx.lineWidth = j === held ? 2.5 : 1.5;
          ctx.strokeStyle = j === held ? HELD : LINE;
          ctx.stroke();
        }
        ctx.restore();
      }
    }

    return { draw: draw };
  }

  return { create: create };
})();
