// The overlays over the canvas (the legend, the readouts, the charts): the band at the
// stage's foot that they take, and fading one out while a held vertex or its hand is under it.
// Boxes are measured on a resize and with each readout, never per frame.

export const clothOverlays = (function () {
  const PAD = 24;   // CSS px: a finger's width around a held vertex
  // The most of the canvas's height the overlays' band takes from the views: a phone's stage
  // (384 px at 360x640) needs 43% for the readouts and a legend note on two lines.
  const BAND_SHARE = 0.5;

  // canvas: the view's canvas; els: the overlay elements; band: the element around them all.
  function create(canvas, els, band) {
    const box = new Float64Array(4 * els.length);   // left, top, right, bottom each (client px)
    const under = els.map(function () { return false; });
    const origin = new Float64Array(2);             // the canvas's corner (client px)
    let i = 0;
    // Whether a point of the canvas (CSS px) is under overlay i: the visitor of heldPoints.
    function covers(cx, cy) {
      const x = origin[0] + cx, y = origin[1] + cy;
      return x > box[4 * i] - PAD && x < box[4 * i + 2] + PAD && y > box[4 * i + 1] - PAD && y < box[4 * i + 3] + PAD;
    }

    return {
      measure: function () {
        for (let j = 0; j < els.length; j++) {
          const r = els[j].getBoundingClientRect();
          box[4 * j] = r.left; box[4 * j + 1] = r.top; box[4 * j + 2] = r.right; box[4 * j + 3] = r.bottom;
        }
        const c = canvas.getBoundingClientRect();
        origin[0] = c.left; origin[1] = c.top;
      },
      // heldPoints(visit): calls visit(cx, cy) for each held vertex and each hand (canvas CSS
      // px) until one returns true, and returns whether one did. Only while dragging.
      fade: function (dragging, heldPoints) {
        for (i = 0; i < els.length; i++) {
          const now = dragging && heldPoints(covers);
          if (now !== under[i]) { under[i] = now; els[i].classList.toggle('under', now); }
        }
      },
      // The band's height at the canvas's foot (CSS px), that views are fitted above so that
      // the overlays do not cover a cloth at rest. At most half the canvas: on a small
      // stage a cloth too small to see would be worse. Measured when the layout changes (a
      // resize, compare mode, the charts shown or hidden), not as the readouts' numbers
      // change, so the view never jumps under a hand.
      band: function () {
        const o = band.getBoundingClientRect(), c = canvas.getBoundingClientRect();
        if (!(o.height > 0) || !(c.height > 0)) return 0;
        return Math.max(0, Math.min(c.bottom - o.top + 4, BAND_SHARE * c.height));
      },
    };
  }

  return { create: create };
})();
