// A drawing of every panel: the colour scale it is drawn with, the cloth of each panel from its
// snapshot (renderer.js), the obstacles over them, and the render readout's timing.
//
// Auto's scale: in the stress mode the seed's normalisation by the frame's maximum; in the
// strain mode the value 99% of the edges are at or below (cloth/measure.py HIGH_SHARE: where a
// clamp ends the strain peaks more the finer the grid, and a scale by the largest would darken
// the rest of the cloth with it). Above a floor: a stiff fabric's own strain (cotton hung 1 m:
// 0.03% at the rod) still fills the scale, a cloth that does not pull at all stays dark. One
// scale for every panel: the largest of them, so a colour means one strain everywhere.
export const clothPainter = (function () {
  const AUTO_FLOOR = 1e-4;

  // The top of the scale over the panels' readings (clothCore.readings): the edges' high value
  // (strain mode) or the largest node stress (stress mode).
  function frameMax(reads, mode) {
    let top = 0;
    for (let i = 0; i < reads.length; i++) {
      const v = mode === 'stress' ? reads[i].max_stress : reads[i].high_value;
      if (v > top) top = v;
    }
    return top;
  }

  // The full scale of the colours: the fixed one, or Auto's (above).
  function scaleOf(reads, mode, scaleMode, fullScale) {
    if (scaleMode === 'fixed') return fullScale;
    return Math.max(frameMax(reads, mode), AUTO_FLOOR);
  }

  // renderer (renderer.js), obstacles (obstacles.js), capture (capture.js: told of each drawing).
  function create(renderer, obstacles, capture) {
    let renders = 0, renderMs = NaN, timeNext = true, scale = 0;

    // views: [{snap, draw (its renderer panel)}]; reads: their readings; colours: {mode(),
    // scaleMode(), fullScale()}; rects: the panels' rectangles; held: the obstacle a pointer
    // moves (-1: none).
    function draw(views, reads, colours, rects, held) {
      const t0 = performance.now();
      const mode = colours.mode();
      scale = scaleOf(reads, mode, colours.scaleMode(), colours.fullScale());
      renderer.begin();
      for (let i = 0; i < views.length; i++) views[i].draw.draw(views[i].snap, mode, scale);
      obstacles.draw(views, rects, held);
      capture.drawn();
      // The render readout: one drawing a readout period, timed until WebGL's finish() returns
      // (one wait a readout period, not one a frame: a wait a frame would stall the pipeline).
      if (timeNext) {
        renderer.finish();
        renderMs = performance.now() - t0;
        timeNext = false;
      }
      renders++;
    }

    return {
      draw: draw,
      // Time the next drawing (once a readout period).
      timeNext: function () { timeNext = true; },
      renders: function () { return renders; },
      renderMs: function () { return renderMs; },
      scale: function () { return scale; },
    };
  }

  return { AUTO_FLOOR: AUTO_FLOOR, frameMax: frameMax, scaleOf: scaleOf, create: create };
})();
