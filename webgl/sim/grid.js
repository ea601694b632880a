// A scene moved onto a new grid (the panel's Columns and Rows): pins keep their meaning, row
// and column. A custom scene's own pins and scripted actions move to the same row and column;
// the pins a person set or removed (edits: vertex -> pinned, kept over any number of grid
// changes) are written over the new scene's pins; a hand's vertex moves with it. What falls
// outside the new grid is dropped and named. Pure: data in, data out.

export const clothGrid = (function () {
  // oldCols: the grid's columns now; cols, rows: the new grid's.
  function mover(oldCols, cols, rows) {
    return {
      // vertex k of the old grid -> the same row and column of the new one, or -1
      moved: function (k) {
        const r = Math.floor(k / oldCols), c = k - r * oldCols;
        return r < rows && c < cols ? r * cols + c : -1;
      },
      place: function (k) { return 'row ' + Math.floor(k / oldCols) + ' column ' + (k % oldCols); },
    };
  }

  // A custom scene object (settings already written in) on the new grid: its pins (the
  // running cloth's, `pins`) and its scripted actions moved; without `frames` (a new grid is
  // a new scene, not the recording it came from). Adds what it drops to `dropped`.
  function moveScene(obj, pins, m, cols, rows, dropped) {
    const out = Object.assign({}, obj, { cols: cols, rows: rows, pins: [] });
    delete out.frames;
    pins.forEach(function (k) {
      const to = m.moved(k);
      if (to >= 0) out.pins.push(to); else dropped.push('pin at ' + m.place(k));
    });
    if (Array.isArray(obj.actions)) {
      let lost = 0;
      out.actions = [];
      obj.actions.forEach(function (a) {
        // a set has no vertex, and a cut is a blade in the world: both stay as they are
        if (a.op === 'set' || a.op === 'cut') { out.actions.push(a); return; }
        const to = m.moved(a.vertex);
        if (to >= 0) out.actions.push(Object.assign({}, a, { vertex: to })); else lost++;
      });
      if (lost) dropped.push(lost + ' scripted action' + (lost > 1 ? 's' : ''));
    }
    return out;
  }

  // The person's pin edits written over obj.pins (sorted, once each); returns the edits on
  // the new grid. Adds the pins it drops to `dropped`.
  function applyEdits(obj, edits, m, dropped) {
    const pins = {}, next = {};
    obj.pins.forEach(function (k) { pins[k] = true; });
    Object.keys(edits).forEach(function (key) {
      const k = Number(key), to = m.moved(k), pinned = edits[key];
      if (to < 0) { if (pinned) dropped.push('your pin at ' + m.place(k)); return; }
      next[to] = pinned;
      if (pinned) pins[to] = true; else delete pins[to];
    });
    obj.pins = Object.keys(pins).map(Number).sort(function (x, y) { return x - y; });
    return next;
  }

  // The note for what was dropped ('' for nothing).
  function droppedNote(dropped, cols, rows) {
    if (!dropped.length) return '';
    return 'outside the ' + cols + '×' + rows + ' grid, dropped: ' +
      dropped.slice(0, 6).join(', ') + (dropped.length > 6 ? ', …' : '');
  }

  return { mover: mover, moveScene: moveScene, applyEdits: applyEdits, droppedNote: droppedNote };
})();
