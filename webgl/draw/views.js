// The panels as the canvas shows them: each panel's snapshot (sim/panels.js) with its renderer
// panel (renderer.js), their rectangles in the canvas (stage.js), and what a pointer there
// points at (the vertex or obstacle under it, as the snapshot has them: gestures.js's view).
// Made anew for every scene loaded; laid out again on every change of size.
import { clothStage } from './stage.js';

export const clothViews = (function () {
  const stage = clothStage;

  // canvas, renderer (renderer.js), band() (the CSS px the overlays take below the panels),
  // panels (sim/panels.js or remote.js).
  function create(canvas, renderer, band, panels) {
    let list = [], rects = [], view = null;

    // The panels' snapshots, shown in the world box `shown` ({x0, x1, y0, y1}).
    function open(given, shown) {
      list = []; view = shown;
      for (let i = 0; i < given.length; i++) list.push({ snap: given[i], draw: renderer.ok ? renderer.panel(i) : null });
      if (!renderer.ok) return;
      list.forEach(function (v) { v.draw.setScene(v.snap); v.draw.setView(view); });
      layout();
    }

    // The rectangles for the canvas's size now.
    function layout() {
      if (renderer.ok && list.length) rects = stage.layout(list, view, renderer.cssWidth, renderer.cssHeight - band());
    }

    function heldPoints(visit) { return stage.heldPoints(list, visit); }

    return {
      open: open, layout: layout, heldPoints: heldPoints,
      count: function () { return list.length; },
      list: function () { return list; },
      rects: function () { return rects; },
      // The WebGL context came back: every panel's buffers made again.
      restored: function () { list.forEach(function (v) { v.draw.setScene(v.snap); }); },
      // A pointer at client px -> {panel (-1: none), x, y (world metres there)}.
      locate: function (x, y) { return renderer.ok ? stage.locate(canvas, list, x, y) : { panel: -1, x: NaN, y: NaN }; },
      toWorld: function (i, x, y) { return stage.toWorld(canvas, list[Math.min(i, list.length - 1)], x, y); },
      // The same, the point kept inside panel i's rectangle (stage.toWorldWithin).
      toWorldWithin: function (i, x, y) { return stage.toWorldWithin(canvas, list[Math.min(i, list.length - 1)], x, y); },
      // The vertex of panel i nearest world (x, y) within radiusCss CSS px, or -1.
      pick: function (i, x, y, radiusCss) {
        return !list.length || !renderer.ok || i < 0 ? -1 : panels.nearest(i, x, y, radiusCss / list[i].draw.pixelsPerMetre());
      },
      positionOf: function (i, k) {
        const pos = list[Math.min(i, list.length - 1)].snap.pos;
        return [pos[2 * k], pos[2 * k + 1]];
      },
      // The obstacle under world (x, y) in panel i (-1: none), and where obstacle j is going.
      obstacleAt: function (i, x, y) { return list.length ? panels.obstacleUnder(i, x, y) : -1; },
      centreOf: function (j) { const at = list[0].snap.obstacle_at; return [at[2 * j], at[2 * j + 1]]; },
      // The first panel whose every vertex is outside its rectangle (a cloth that nothing
      // holds has fallen out of sight), or -1. Read with the readouts, not every frame.
      away: function () {
        if (!renderer.ok) return -1;
        for (let i = 0; i < list.length && i < rects.length; i++) {
          const d = list[i].draw, b = rects[i], pos = list[i].snap.pos, n = 2 * list[i].snap.n_verts;
          const x0 = d.toWorld(b.x, b.y + b.h), x1 = d.toWorld(b.x + b.w, b.y);
          let inside = false;
          for (let k = 0; k < n && !inside; k += 2) {
            inside = pos[k] >= x0[0] && pos[k] <= x1[0] && pos[k + 1] >= x0[1] && pos[k + 1] <= x1[1];
          }
          if (!inside) return i;
        }
        return -1;
      },
      // A world point of panel i in canvas CSS px.
      toCanvas: function (i, x, y) { return list[i].draw.toCanvas(x, y); },
    };
  }

  return { create: create };
})();
