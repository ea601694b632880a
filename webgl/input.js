// Pointer input: mouse, touch and pen through Pointer Events.
//
// Press on or near a vertex: it is grabbed where it is, and from then on keeps
// its offset from the pointer until release (a press never snaps it to the
// pointer, so a tap or a pin toggle moves nothing); each pointer holds its own
// vertex, so two fingers can pull two corners. Through a resize of the view the
// held vertex stays at the same place under the pointer. Right-click (or a pen's
// barrel button), Shift+click, or a double-tap with a finger or pen toggles a pin.
// The canvas has CSS `touch-action: none`, otherwise the browser claims a touch
// for scrolling and sends pointercancel on the first move.
'use strict';

window.clothInput = (function () {
  // How close (CSS pixels) a press must be to a vertex to grab it.
  const PICK_RADIUS = { mouse: 18, pen: 22, touch: 30 };
  const DOUBLE_TAP_MS = 350;
  const DOUBLE_TAP_PX = 30;
  const TAP_MOVE_PX = 10;

  // app: {toWorld(clientX, clientY) -> [x, y], pick(x, y, radiusCss) -> k, positionOf(k) -> [x, y],
  //       grab(k, x, y), move(k, x, y), release(k), togglePin(k), isHeld(k)}
  function attach(canvas, app) {
    // pointerId -> {k, x0, y0 (press, client px), cx, cy (latest), ox, oy (vertex - pointer, m), moved}
    const drags = new Map();
    let lastTap = null;         // {t, x, y, k}

    function radius(e) { return PICK_RADIUS[e.pointerType] || PICK_RADIUS.mouse; }

    function pickAt(e) {
      const w = app.toWorld(e.clientX, e.clientY);
      return { k: app.pick(w[0], w[1], radius(e)), w: w };
    }

    canvas.addEventListener('contextmenu', function (e) { e.preventDefault(); });
    // A sideways wheel or two-finger swipe would go back in history (Chromium's overscroll
    // navigation, which CSS overscroll-behavior does not stop over a canvas): nothing here
    // scrolls sideways, so sideways wheels are dropped.
    window.addEventListener('wheel', function (e) {
      if (Math.abs(e.deltaX) > Math.abs(e.deltaY)) e.preventDefault();
    }, { passive: false });

    canvas.addEventListener('pointerdown', function (e) {
      const hit = pickAt(e);
      // Right button (mouse, or a pen's barrel button) or Shift+click: toggle a pin.
      if (e.button === 2 || (e.button === 0 && e.shiftKey && e.pointerType === 'mouse')) {
        e.preventDefault();
        if (hit.k >= 0) app.togglePin(hit.k);
        return;
      }
      if (e.button !== 0 || hit.k < 0 || app.isHeld(hit.k)) return;
      e.preventDefault();
      try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* untrusted event */ }
      const v = app.positionOf(hit.k);
      drags.set(e.pointerId, { k: hit.k, x0: e.clientX, y0: e.clientY, cx: e.clientX, cy: e.clientY,
                               ox: v[0] - hit.w[0], oy: v[1] - hit.w[1], moved: false });
      app.grab(hit.k, v[0], v[1]);
      canvas.classList.add('dragging');
    });

    canvas.addEventListener('pointermove', function (e) {
      const d = drags.get(e.pointerId);
      if (!d) {
        if (e.pointerType === 'mouse' && drags.size === 0) {
          canvas.classList.toggle('can-grab', pickAt(e).k >= 0);
        }
        return;
      }
      if (Math.abs(e.clientX - d.x0) + Math.abs(e.clientY - d.y0) > TAP_MOVE_PX) d.moved = true;
      follow(d, e.clientX, e.clientY);
    });

    function follow(d, clientX, clientY) {
      d.cx = clientX; d.cy = clientY;
      const w = app.toWorld(clientX, clientY);
      app.move(d.k, w[0] + d.ox, w[1] + d.oy);
    }

    function end(e) {
      const d = drags.get(e.pointerId);
      if (!d) return;
      drags.delete(e.pointerId);
      if (drags.size === 0) canvas.classList.remove('dragging');
      // Land exactly where the pointer was let go (a tap that did not move moves nothing).
      if (e.type === 'pointerup') follow(d, e.clientX, e.clientY);
      app.release(d.k);
      if (e.type === 'pointerup' && e.pointerType !== 'mouse' && !d.moved) {
        const now = e.timeStamp;
        if (lastTap && now - lastTap.t < DOUBLE_TAP_MS && lastTap.k === d.k &&
            Math.abs(e.clientX - lastTap.x) + Math.abs(e.clientY - lastTap.y) < DOUBLE_TAP_PX) {
          app.togglePin(d.k);
          lastTap = null;
        } else {
          lastTap = { t: now, x: e.clientX, y: e.clientY, k: d.k };
        }
      }
    }
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('lostpointercapture', end);

    return {
      // Let go of everything (a scene change invalidates vertex indices).
      releaseAll: function () { drags.clear(); canvas.classList.remove('dragging'); },
      dragging: function () { return drags.size; },
      // The view changed (a resize): put each held vertex back under its pointer.
      reproject: function () { drags.forEach(function (d) { follow(d, d.cx, d.cy); }); },
    };
  }

  return { attach: attach, PICK_RADIUS: PICK_RADIUS };
})();
