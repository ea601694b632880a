// A 2D canvas over the stage (the live charts, the blade's trail): its drawing buffer sized to
// its CSS box times devicePixelRatio, so lines stay sharp, and a context that draws in CSS px.

export const clothCanvas2d = (function () {
  // Size canvas for its box now; returns {ctx, w, h} (CSS px), the transform set for them.
  function fit(canvas, ctx) {
    const r = canvas.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, r.width), h = Math.max(1, r.height);
    const dw = Math.round(w * dpr), dh = Math.round(h * dpr);
    if (canvas.width !== dw) canvas.width = dw;
    if (canvas.height !== dh) canvas.height = dh;
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return { w: w, h: h };
  }

  return { fit: fit };
})();
