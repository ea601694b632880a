// Pointer input: mouse, touch and pen through Pointer Events, reported as gestures in client
// pixels to `to` (gestures.js), which says what they do to the cloth. This file knows pointers,
// buttons, taps and the cursor; nothing of vertices beyond the one a lift reports.
//
// A press with the left button (or a finger, a pen) grabs; the blade: Alt+drag with a mouse,
// or any drag while the Cut tool is on (touch, pen). Right-click (or a pen's barrel button),
// Shift+click, or a double-tap with a finger or pen on the same vertex toggles a pin.
// The canvas has CSS `touch-action: none`, otherwise the browser claims a touch for scrolling
// and sends pointercancel on the first move.

export const clothInput = (function () {
  // How close (CSS pixels) a press must be to a vertex to grab it.
  const PICK_RADIUS = { mouse: 18, pen: 22, touch: 30 };
  const DOUBLE_TAP_MS = 350;
  const DOUBLE_TAP_PX = 30;
  const TAP_MOVE_PX = 10;

  // to: {press(id, clientX, clientY, radiusCss) -> whether it took a vertex,
  //      drag(id, clientX, clientY) -> whether the pointer still holds one,
  //      lift(id, clientX, clientY, landed) -> the vertex let go or -1, pinAt(clientX, clientY,
  //      radiusCss), togglePin(k), canGrab(clientX, clientY, radiusCss), bladeOn(),
  //      bladeStart(id, clientX, clientY) -> whether it started, bladeTo(id, clientX, clientY),
  //      bladeEnd(id)}
  function attach(canvas, to) {
    // pointerId -> {x0, y0 (the press, client px), moved}: pointers that hold a vertex
    const drags = new Map();
    // pointerIds of blade strokes
    const blades = new Set();
    let lastTap = null;         // {t, x, y, k}

    function radius(e) { return PICK_RADIUS[e.pointerType] || PICK_RADIUS.mouse; }

    function drop(id) {
      drags.delete(id);
      if (drags.size === 0) canvas.classList.remove('dragging');
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
      // Right button (mouse, or a pen's barrel button) or Shift+click: toggle a pin.
      if (e.button === 2 || (e.button === 0 && e.shiftKey && e.pointerType === 'mouse')) {
        e.preventDefault();
        to.pinAt(e.clientX, e.clientY, radius(e));
        return;
      }
      if (e.button !== 0) return;
      // The blade: Alt+drag (a mouse), or the Cut tool for any pointer.
      if (to.bladeOn() || (e.altKey && e.pointerType === 'mouse')) {
        if (to.bladeStart(e.pointerId, e.clientX, e.clientY)) {
          e.preventDefault();
          try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* untrusted event */ }
          blades.add(e.pointerId);
          return;
        }
      }
      if (!to.press(e.pointerId, e.clientX, e.clientY, radius(e))) return;
      e.preventDefault();
      try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* untrusted event */ }
      drags.set(e.pointerId, { x0: e.clientX, y0: e.clientY, moved: false });
      canvas.classList.add('dragging');
    });

    canvas.addEventListener('pointermove', function (e) {
      if (blades.has(e.pointerId)) {
        to.bladeTo(e.pointerId, e.clientX, e.clientY);
        return;
      }
      const d = drags.get(e.pointerId);
      if (!d) {
        if (e.pointerType === 'mouse' && drags.size === 0) {
          canvas.classList.toggle('can-grab', to.canGrab(e.clientX, e.clientY, radius(e)));
        }
        return;
      }
      if (Math.abs(e.clientX - d.x0) + Math.abs(e.clientY - d.y0) > TAP_MOVE_PX) d.moved = true;
      if (!to.drag(e.pointerId, e.clientX, e.clientY)) drop(e.pointerId);
    });

    function end(e) {
      if (blades.delete(e.pointerId)) {
        to.bladeEnd(e.pointerId);
        return;
      }
      const d = drags.get(e.pointerId);
      if (!d) return;
      drop(e.pointerId);
      // Land exactly where the pointer was let go (a tap that did not move moves nothing).
      const k = to.lift(e.pointerId, e.clientX, e.clientY, e.type === 'pointerup');
      if (k >= 0 && e.type === 'pointerup' && e.pointerType !== 'mouse' && !d.moved) {
        const now = e.timeStamp;
        if (lastTap && now - lastTap.t < DOUBLE_TAP_MS && lastTap.k === k &&
            Math.abs(e.clientX - lastTap.x) + Math.abs(e.clientY - lastTap.y) < DOUBLE_TAP_PX) {
          to.togglePin(k);
          lastTap = null;
        } else {
          lastTap = { t: now, x: e.clientX, y: e.clientY, k: k };
        }
      }
    }
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('lostpointercapture', end);
  }

  return { attach: attach };
})();
