// Pointer input: mouse, touch and pen through Pointer Events.
//
// The blade: Alt+drag with a mouse, or any drag while the Cut tool is on (touch, pen),
// cuts every edge the pointer's path crosses, segment by segment as it moves.
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

  // app: {locate(clientX, clientY) -> {panel, x, y} (the panel under the point, -1 for none,
  //       and world metres there), toWorld(panel, clientX, clientY) -> [x, y],
  //       pick(panel, x, y, radiusCss) -> k, positionOf(panel, k) -> [x, y],
  //       grab(k, x, y), move(k, x, y), release(k), togglePin(k), isHeld(k),
  //       bladeMode() -> whether the Cut tool is on, cut(x0, y0, x1, y1) (world metres),
  //       trail(clientX, clientY, start) (where the blade went, to draw it)}
  // A pointer works in the panel it pressed in (compare mode draws several): its vertex stays
  // under it there, and the app moves the same vertex to the same place in every panel.
  function attach(canvas, app) {
    // pointerId -> {panel, k, x0, y0 (press, client px), cx, cy (latest), ox, oy (vertex -
    // pointer, m), moved}
    const drags = new Map();
    // pointerId -> {panel, x, y (the blade's last point, world metres)}
    const blades = new Map();
    let lastTap = null;         // {t, x, y, k}

    function radius(e) { return PICK_RADIUS[e.pointerType] || PICK_RADIUS.mouse; }

    function pickAt(e) {
      const at = app.locate(e.clientX, e.clientY);
      return { k: at.panel < 0 ? -1 : app.pick(at.panel, at.x, at.y, radius(e)), panel: at.panel,
               w: [at.x, at.y] };
    }

    canvas.addEventListener('contextmenu', function (e) { e.preventDefault(); });
    // A sideways wheel or two-finger swipe would go back in history (Chromium's overscroll
    // navigation, which CSS overscroll-behavior does not stop over a canvas): nothing here
    // scrolls sideways, so sideways wheels are dropped.
    window.addEventListener('wheel', function (e) {
      if (Math.abs(e.deltaX) > Math.abs(e.deltaY)) e.preventDefault();
    }, { passive: false });

    canvas.addEventListener('pointerdown', function (e) {
      // preventDefault below keeps focus where it was: a field clicked before would go on
      // taking the keys, and the shortcuts would stay dead. Pressing the cloth leaves it.
      const focused = document.activeElement;
      if (focused && focused !== document.body && focused.blur) focused.blur();
      const hit = pickAt(e);
      // Right button (mouse, or a pen's barrel button) or Shift+click: toggle a pin.
      if (e.button === 2 || (e.button === 0 && e.shiftKey && e.pointerType === 'mouse')) {
        e.preventDefault();
        if (hit.k >= 0) app.togglePin(hit.k);
        return;
      }
      // The blade: Alt+drag (a mouse), or the Cut tool for any pointer.
      if (e.button === 0 && hit.panel >= 0 && (app.bladeMode() || (e.altKey && e.pointerType === 'mouse'))) {
        e.preventDefault();
        try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* untrusted event */ }
        blades.set(e.pointerId, { panel: hit.panel, x: hit.w[0], y: hit.w[1] });
        app.trail(e.clientX, e.clientY, true);
        return;
      }
      if (e.button !== 0 || hit.k < 0 || app.isHeld(hit.k)) return;
      e.preventDefault();
      try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* untrusted event */ }
      const v = app.positionOf(hit.panel, hit.k);
      drags.set(e.pointerId, { panel: hit.panel, k: hit.k, x0: e.clientX, y0: e.clientY, cx: e.clientX,
                               cy: e.clientY, ox: v[0] - hit.w[0], oy: v[1] - hit.w[1], moved: false });
      app.grab(hit.k, v[0], v[1]);
      canvas.classList.add('dragging');
    });

    canvas.addEventListener('pointermove', function (e) {
      const b = blades.get(e.pointerId);
      if (b) {
        const w = app.toWorld(b.panel, e.clientX, e.clientY);
        app.cut(b.x, b.y, w[0], w[1]);
        b.x = w[0]; b.y = w[1];
        app.trail(e.clientX, e.clientY, false);
        return;
      }
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
      const w = app.toWorld(d.panel, clientX, clientY);
      app.move(d.k, w[0] + d.ox, w[1] + d.oy);
    }

    function end(e) {
      if (blades.delete(e.pointerId)) return;
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
      // A new cloth: every pointer lets go, but those in `keep` ([{id, k}], k >= 0), which go
      // on with vertex k of the new cloth (regrab holds it).
      releaseAll: function (keep) {
        const next = new Map();
        keep.forEach(function (h) {
          const d = drags.get(h.id);
          if (d && h.k >= 0) { d.k = h.k; d.fresh = true; next.set(h.id, d); }
        });
        drags.clear();
        next.forEach(function (d, id) { drags.set(id, d); });
        if (drags.size === 0) canvas.classList.remove('dragging');
      },
      // The kept pointers hold their vertex of the new cloth where it is, with their offset
      // to it from here on.
      regrab: function () {
        drags.forEach(function (d) {
          if (!d.fresh) return;
          d.fresh = false;
          const v = app.positionOf(d.panel, d.k), w = app.toWorld(d.panel, d.cx, d.cy);
          d.ox = v[0] - w[0]; d.oy = v[1] - w[1];
          app.grab(d.k, v[0], v[1]);
        });
      },
      // [{id, k}] for every pointer holding a vertex.
      held: function () {
        const out = [];
        drags.forEach(function (d, id) { out.push({ id: id, k: d.k }); });
        return out;
      },
      dragging: function () { return drags.size; },
      // The view changed (a resize): put each held vertex back under its pointer.
      reproject: function () { drags.forEach(function (d) { follow(d, d.cx, d.cy); }); },
      // Does a pointer hold vertex k?
      holds: function (k) {
        let found = false;
        drags.forEach(function (d) { if (d.k === k) found = true; });
        return found;
      },
      // Vertex k is no longer this input's (a scene's script took it): its pointer stops
      // moving it and will not release it.
      forget: function (k) {
        drags.forEach(function (d, id) { if (d.k === k) drags.delete(id); });
        if (drags.size === 0) canvas.classList.remove('dragging');
      },
    };
  }

  return { attach: attach };
})();
