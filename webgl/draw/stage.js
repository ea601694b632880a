// The stage: the panels' rectangles in the canvas, the panel and the world point under a
// pointer, the held vertices' places on the canvas, and the canvas's size as the browser
// reports it. Geometry only: the app decides what a new size redraws.

export const clothStage = (function () {
  const LABEL_HEIGHT = 44;    // CSS px: a panel label's two lines, its padding and offset
  const GAP = 4;              // CSS px between panels

  // Rectangles for n panels in a w x h canvas (CSS px): the grid of columns x rows that
  // gives each panel's view box (aspect bw / bh) the most pixels per metre; side by side on
  // a wide screen, stacked on a tall or narrow one, 2 x 2 for four on a square one.
  function grid(n, w, h, bw, bh) {
    let best = null;
    for (let cols = 1; cols <= n; cols++) {
      const rows = Math.ceil(n / cols);
      if ((cols - 1) * rows >= n) continue;   // an empty column
      const pw = (w - GAP * (cols - 1)) / cols, ph = (h - GAP * (rows - 1)) / rows;
      const scale = Math.min(pw / bw, ph / bh);
      if (!best || scale > best.scale + 1e-9) best = { cols: cols, rows: rows, pw: pw, ph: ph, scale: scale };
    }
    const out = [];
    for (let i = 0; i < n; i++) {
      const c = i % best.cols, r = Math.floor(i / best.cols);
      out.push({ x: c * (best.pw + GAP), y: r * (best.ph + GAP), w: best.pw, h: best.ph });
    }
    return out;
  }

  // Lay the panels ({draw}: renderer panels) out in a w x h CSS px box (the canvas above the
  // overlays' band) for a view {x0, y0, x1, y1}; one panel takes all of it, its view fitted.
  // Returns the rectangles [{x, y, w, h}].
  function layout(panels, view, w, h) {
    const n = panels.length;
    const rects = n > 1
      ? grid(n, w, h, view.x1 - view.x0, view.y1 - view.y0)
      : [{ x: 0, y: 0, w: w, h: h }];
    panels.forEach(function (p, i) {
      const r = rects[i];
      // A panel's cloth is fitted below its label (two lines, compare.js), where there is room.
      const top = n > 1 && r.h > 3 * LABEL_HEIGHT ? LABEL_HEIGHT : 0;
      if (n > 1) p.draw.setRect(r.x, r.y, r.w, r.h);
      else p.draw.setRect();
      p.draw.setFit(r.x, r.y + top, r.w, r.h - top);
    });
    return rects;
  }

  // The panel under a point of the canvas (CSS px), or -1.
  function panelAt(panels, cx, cy) {
    for (let i = 0; i < panels.length; i++) if (panels[i].draw.contains(cx, cy)) return i;
    return -1;
  }

  // A pointer at (clientX, clientY) -> {panel, x, y}: the panel under it (-1: none) and the
  // world point there, metres.
  function locate(canvas, panels, clientX, clientY) {
    const r = canvas.getBoundingClientRect(), cx = clientX - r.left, cy = clientY - r.top;
    const i = panelAt(panels, cx, cy);
    const w = i >= 0 ? panels[i].draw.toWorld(cx, cy) : [NaN, NaN];
    return { panel: i, x: w[0], y: w[1] };
  }

  // The world point of one panel at (clientX, clientY), metres (a drag goes on outside it).
  function toWorld(canvas, panel, clientX, clientY) {
    const r = canvas.getBoundingClientRect();
    return panel.draw.toWorld(clientX - r.left, clientY - r.top);
  }

  // The same, the point first brought INSET px inside the panel's rectangle: where a hand or
  // a dragged obstacle goes, so that what a person leaves anywhere can be reached again (a pin
  // dragged up off the stage could no longer be clicked to unpin; in compare mode, a pin
  // dragged out of its panel was clipped away).
  const INSET = 8;
  function toWorldWithin(canvas, panel, clientX, clientY) {
    const r = canvas.getBoundingClientRect(), b = panel.draw.box();
    const inset = Math.min(INSET, b.w / 4, b.h / 4);
    const cx = Math.min(Math.max(clientX - r.left, b.x + inset), b.x + b.w - inset);
    const cy = Math.min(Math.max(clientY - r.top, b.y + inset), b.y + b.h - inset);
    return panel.draw.toWorld(cx, cy);
  }

  // Every held vertex of every panel ({snap, draw}: its snapshot's held, pos and target), and
  // its hand (which a hand of finite strength's vertex may lag behind or stop short of), in
  // canvas CSS px, to `visit` until it says stop.
  function heldPoints(panels, visit) {
    for (let j = 0; j < panels.length; j++) {
      const c = panels[j].snap, d = panels[j].draw;
      for (let k = 0; k < c.n_verts; k++) {
        if (c.held[k] === 0) continue;
        const p = d.toCanvas(c.pos[2 * k], c.pos[2 * k + 1]);
        if (visit(p[0], p[1])) return true;
        const q = d.toCanvas(c.target[2 * k], c.target[2 * k + 1]);
        if (visit(q[0], q[1])) return true;
      }
    }
    return false;
  }

  // Calls sized(cssWidth, cssHeight, deviceWidth, deviceHeight, observed) now and on every
  // change of the canvas's size (device sizes 0 where the browser does not give them;
  // observed: from a ResizeObserver, in the task that will paint the new size).
  function watch(canvas, sized) {
    const r0 = canvas.getBoundingClientRect();
    sized(r0.width, r0.height, 0, 0, false);
    window.addEventListener('resize', function () {
      const r = canvas.getBoundingClientRect();
      sized(r.width, r.height, 0, 0, false);
    });
    if (!window.ResizeObserver) return;
    // device-pixel-content-box gives the exact drawing-buffer size (sharp at fractional
    // devicePixelRatio); where unsupported, round CSS size * dpr.
    const ro = new ResizeObserver(function (entries) {
      const e = entries[entries.length - 1];
      const css = e.contentBoxSize && e.contentBoxSize[0];
      let dev = e.devicePixelContentBoxSize && e.devicePixelContentBoxSize[0];
      const w = css ? css.inlineSize : e.contentRect.width;
      const h = css ? css.blockSize : e.contentRect.height;
      // Emulated device scale factors (devtools, test drivers) are not reflected in the
      // device-pixel box: trust it only when it agrees with CSS size * dpr.
      const dpr = window.devicePixelRatio || 1;
      if (dev && (Math.abs(dev.inlineSize - w * dpr) > 1 || Math.abs(dev.blockSize - h * dpr) > 1)) dev = null;
      sized(w, h, dev ? dev.inlineSize : 0, dev ? dev.blockSize : 0, true);
    });
    try { ro.observe(canvas, { box: 'device-pixel-content-box' }); } catch (e) { ro.observe(canvas); }
  }

  return { layout: layout, locate: locate, toWorld: toWorld, toWorldWithin: toWorldWithin, heldPoints: heldPoints,
           watch: watch };
})();
