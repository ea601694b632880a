// Gestures: what a pointer's press, drag and lift mean for the cloth. input.js reports
// pointers in client pixels; this turns them into hands on vertices and blade strokes, and
// hands those to the app's actions (which apply them to every panel and record them).
//
// A press on or near a vertex takes it where it is, and from then on the vertex keeps its
// offset from the pointer until the lift (a press never snaps it to the pointer, so a tap or
// a pin toggle moves nothing); each pointer holds its own vertex, so two fingers can pull two
// corners. A pointer works in the panel it pressed in (compare mode draws several): its vertex
// stays under it there, and the app moves the same vertex to the same place in every panel.
// Through a resize of the view the held vertex stays at the same place under the pointer.
// A press inside an obstacle takes the obstacle instead: it keeps its offset from the pointer,
// and the app sends it there (an `obstacle` action) in every panel.

export const clothGestures = (function () {
  // view: {locate(clientX, clientY) -> {panel, x, y} (the panel under the point, -1 for none,
  //        and world metres there), toWorld(panel, clientX, clientY) -> [x, y], toWorldWithin (the
  //        same, the point kept inside the panel: where hands and obstacles go),
  //        pick(panel, x, y, radiusCss) -> k, positionOf(panel, k) -> [x, y], isHeld(k),
  //        obstacleAt(panel, x, y) -> the obstacle there or -1, centreOf(j) -> [x, y],
  //        bladeOn() -> whether the Cut tool is on, trail(clientX, clientY, start) (where the
  //        blade went, to draw it)}
  // act:  {grab(k, x, y), move(k, x, y), release(k), togglePin(k), cut(x0, y0, x1, y1),
  //        obstacle(j, x, y) (its centre to (x, y))}
  function create(view, act) {
    // pointerId -> {panel, k, cx, cy (latest, client px), ox, oy (vertex - pointer, m), fresh}
    const hands = new Map();
    // pointerId -> {panel, x, y (the blade's last point, world metres)}
    const blades = new Map();
    // pointerId -> {panel, j, ox, oy (centre - pointer, m)}: pointers that move an obstacle
    const movers = new Map();
    let lastMoved = -1;     // the obstacle a pointer last took and still moves (-1: none)

    function pickAt(clientX, clientY, radiusCss) {
      const at = view.locate(clientX, clientY);
      return { k: at.panel < 0 ? -1 : view.pick(at.panel, at.x, at.y, radiusCss), panel: at.panel,
               w: [at.x, at.y] };
    }

    function follow(h, clientX, clientY) {
      h.cx = clientX; h.cy = clientY;
      const w = view.toWorldWithin(h.panel, clientX, clientY);     // never out of reach
      act.move(h.k, w[0] + h.ox, w[1] + h.oy);
    }

    return {
      // ---- what input.js reports --------------------------------------------------------
      // A press: takes the vertex near it unless someone else holds it. Whether it took one.
      press: function (id, clientX, clientY, radiusCss) {
        const at = view.locate(clientX, clientY);
        const j = at.panel < 0 ? -1 : view.obstacleAt(at.panel, at.x, at.y);
        if (j >= 0) {
          let taken = false;
          movers.forEach(function (m) { if (m.j === j) taken = true; });
          if (taken) return false;
          const c = view.centreOf(j);
          movers.set(id, { panel: at.panel, j: j, ox: c[0] - at.x, oy: c[1] - at.y });
          lastMoved = j;
          return true;
        }
        const hit = pickAt(clientX, clientY, radiusCss);
        if (hit.k < 0 || view.isHeld(hit.k)) return false;
        const v = view.positionOf(hit.panel, hit.k);
        hands.set(id, { panel: hit.panel, k: hit.k, cx: clientX, cy: clientY,
                        ox: v[0] - hit.w[0], oy: v[1] - hit.w[1], fresh: false });
        act.grab(hit.k, v[0], v[1]);
        return true;
      },
      // Whether the pointer still holds a vertex (a new scene or the script may have taken it).
      drag: function (id, clientX, clientY) {
        const m = movers.get(id);
        if (m) {
          const w = view.toWorldWithin(m.panel, clientX, clientY);
          act.obstacle(m.j, w[0] + m.ox, w[1] + m.oy);
          return true;
        }
        const h = hands.get(id);
        if (!h) return false;
        follow(h, clientX, clientY);
        return true;
      },
      // The pointer lets go, landing exactly where it was lifted when `landed` (a cancelled
      // pointer lets go where it last was). The vertex it let go, or -1.
      lift: function (id, clientX, clientY, landed) {
        const m = movers.get(id);
        if (m) {
          if (landed) { const w = view.toWorldWithin(m.panel, clientX, clientY); act.obstacle(m.j, w[0] + m.ox, w[1] + m.oy); }
          movers.delete(id);
          if (m.j === lastMoved) lastMoved = -1;
          return -1;
        }
        const h = hands.get(id);
        if (!h) return -1;
        hands.delete(id);
        if (landed) follow(h, clientX, clientY);
        act.release(h.k);
        return h.k;
      },
      pinAt: function (clientX, clientY, radiusCss) {
        const hit = pickAt(clientX, clientY, radiusCss);
        if (hit.k >= 0) act.togglePin(hit.k);
      },
      togglePin: function (k) { act.togglePin(k); },
      canGrab: function (clientX, clientY, radiusCss) {
        const at = view.locate(clientX, clientY);
        if (at.panel >= 0 && view.obstacleAt(at.panel, at.x, at.y) >= 0) return true;
        return pickAt(clientX, clientY, radiusCss).k >= 0;
      },
      bladeOn: function () { return view.bladeOn(); },
      // A blade stroke starts on a panel; whether it did.
      bladeStart: function (id, clientX, clientY) {
        const at = view.locate(clientX, clientY);
        if (at.panel < 0) return false;
        blades.set(id, { panel: at.panel, x: at.x, y: at.y });
        view.trail(clientX, clientY, true);
        return true;
      },
      bladeTo: function (id, clientX, clientY) {
        const b = blades.get(id);
        if (!b) return;
        const w = view.toWorld(b.panel, clientX, clientY);
        act.cut(b.x, b.y, w[0], w[1]);
        b.x = w[0]; b.y = w[1];
        view.trail(clientX, clientY, false);
      },
      bladeEnd: function (id) { blades.delete(id); },

      // ---- what the app asks ------------------------------------------------------------
      // A new cloth: every hand lets go, but those in `keep` ([{id, k}], k >= 0), which go
      // on with vertex k of the new cloth (regrab holds it).
      releaseAll: function (keep) {
        const next = new Map();
        keep.forEach(function (kept) {
          const h = hands.get(kept.id);
          if (h && kept.k >= 0) { h.k = kept.k; h.fresh = true; next.set(kept.id, h); }
        });
        hands.clear();
        movers.clear();
        lastMoved = -1;
        next.forEach(function (h, id) { hands.set(id, h); });
      },
      // The kept hands hold their vertex of the new cloth where it is, with their offset to
      // it from here on.
      regrab: function () {
        hands.forEach(function (h) {
          if (!h.fresh) return;
          h.fresh = false;
          const v = view.positionOf(h.panel, h.k), w = view.toWorldWithin(h.panel, h.cx, h.cy);
          h.ox = v[0] - w[0]; h.oy = v[1] - w[1];
          act.grab(h.k, v[0], v[1]);
        });
      },
      // [{id, k}] for every pointer holding a vertex.
      held: function () {
        const out = [];
        hands.forEach(function (h, id) { out.push({ id: id, k: h.k }); });
        return out;
      },
      count: function () { return hands.size; },
      // The obstacle a pointer moves, or -1 (the overlay draws it lit; read every drawing, so
      // a variable, not a walk of the pointers).
      moving: function () { return lastMoved; },
      // The view changed (a resize): put each held vertex back under its pointer.
      reproject: function () { hands.forEach(function (h) { follow(h, h.cx, h.cy); }); },
      // Does a pointer hold vertex k?
      holds: function (k) {
        let found = false;
        hands.forEach(function (h) { if (h.k === k) found = true; });
        return found;
      },
      // Vertex k is no longer a pointer's (a scene's script took it): its pointer stops moving
      // it and will not release it.
      forget: function (k) {
        hands.forEach(function (h, id) { if (h.k === k) hands.delete(id); });
      },
    };
  }

  return { create: create };
})();
