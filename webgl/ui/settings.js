// The panel's settings applied to what runs: a setting that leaves the grid as it is goes to
// the session as a `set` (every panel, recorded); Columns and Rows make a new grid (grid.js)
// and load it. Compare mode follows what the panels run. Reads what the app runs through its
// getters; changes it only through the app's own functions (followed, retuned, load).
import { clothCore } from '../sim/core.js';
import { clothGrid } from '../sim/grid.js';
import { clothOptions } from '../sim/options.js';
import { clothParams } from '../sim/params.js';
import { clothScenes } from '../sim/scenes.js';

export const clothSettings = (function () {
  const scenes = clothScenes, params = clothParams, core = clothCore;
  const own = clothOptions.own;
  const limitOf = params.limitOf, withSettings = params.written, KEYS = core.schema().keys;

  // What the settings panel shows of a scene's keys.
  function paramsOf(scene) { return params.of(scene); }

  // app: {panels (sim/panels.js), params() (what the panel shows), compare() (the compare
  // list), sceneObj(), preset(), pinEdits() (vertex -> pinned: the pins a person set or
  // removed), loadNote() (what the last load said), load(text, preset, view, holds, pinEdits),
  // acted(), followed(compareList) (the panels run this list now), retuned(sceneObj) (the scene
  // object the running cloth now is), ui, gestures}. What the getters return is read only.
  function create(app) {
    const ui = app.ui, panels = app.panels;

    // A set (the Scene section's or a script's) is written into every panel, the keys a panel
    // has of its own included: the compare list, its editor and a later grid change follow what
    // the panels run (params.running). Returns whether the list changed.
    function followSets() {
      const compare = app.compare();
      if (!compare.length) return false;
      const scenesRun = [];
      for (let i = 0; i < panels.count(); i++) scenesRun.push(panels.scene(i));
      const now = params.running(compare, scenesRun);
      if (JSON.stringify(now) === JSON.stringify(compare)) return false;
      app.followed(now);
      return true;
    }

    // A Scene-section field (scenes.SCENE_FIELDS) typed in. A key that may be set live applies
    // to the running cloth (the session's `set`): its positions, speeds, pins and held
    // vertices stay. The others (columns, rows) make a new grid.
    function setParam(key, raw) {
      if (scenes.SCENE_FIELDS.indexOf(key) < 0) throw new Error('not a field of the Scene section: ' + key);
      const c = scenes.clamp(key, raw);
      if (c.value === null) { ui.note(c.note); ui.setParams(app.params()); return; }
      const p = Object.assign({}, app.params());
      p[key] = c.value;
      if (!KEYS[key].live) regrid(p, c.note);
      else retune(p, c.note);
    }

    // A solver starts from its own substeps and iterations.
    function setSolver(name) {
      const d = own(scenes.SOLVERS, name) ? scenes.SOLVERS[name] : null;
      if (!d) throw new Error('unknown solver: ' + name);
      retune(Object.assign({}, app.params(), { solver: name, substeps: d.substeps, iterations: d.iterations }), '');
    }

    // A named fabric: its stretch, shear and density, and its strength where the cloth tears
    // (a cloth that does not tear is left so), set like every setting (recorded as a `set`).
    function setMaterial(name) {
      if (!own(scenes.MATERIALS, name)) { ui.setParams(app.params()); return; }
      const p = app.params();
      const change = { material: name };
      if (p.strength > 0) change.strength = scenes.MATERIALS[name].strength;
      retune(Object.assign({}, p, change), '');
    }

    // New settings for the running cloth (the session's change: cloth/session.py, what a
    // recorded `set` action replays), in every panel: keys a panel has of its own are set too,
    // as the recording's `set` sets them; a rejected one leaves everything as it was.
    function retune(p, note) {
      const keys = params.changed(app.params(), p, panels.baseScene());
      const obj = withSettings(app.sceneObj(), p);
      try {
        const limit = limitOf(obj);
        if (limit) throw new Error(limit);
        if (Object.keys(keys).length) {
          panels.change(JSON.stringify(keys));
          app.acted();
        }
      } catch (e) {
        ui.error('Setting not applied: ' + e.message + ' (the cloth runs on as it was)', 'setting');
        ui.setParams(app.params());
        ui.setSolver(app.params().solver);
        ui.note(note);   // what was typed became (a clamped value), not an older setting's note
        return;
      }
      if (followSets()) {
        obj.compare = app.compare();
        note = (note ? note + '; ' : '') + 'set in every panel, over the panels\' own values (the compare editor shows what each runs)';
      }
      // A Solver or Material change that leaves the fabric unused says so (cloth/scene.py).
      const unused = keys.solver !== undefined || keys.stretch !== undefined ? panels.unusedNote() : '';
      if (unused) note = (note ? note + '; ' : '') + unused.charAt(0).toUpperCase() + unused.slice(1);
      app.retuned(obj);
      ui.clearError('setting');     // a refused setting's banner ends with one that applies
      ui.note(note);
    }

    // A new grid (grid.js): pins keep their meaning, row and column; the pins a person set or
    // removed are written over the new scene's, and the vertices a hand holds held again. What
    // falls outside the new grid is dropped, and the note says so.
    function regrid(p, note) {
      const m = clothGrid.mover(panels.snap(0).cols, p.cols, p.rows);
      const dropped = [], compare = app.compare();
      let obj, view, preset = app.preset();
      if (preset !== 'custom') {
        const made = scenes.make(preset, p);
        obj = made.scene; view = made.view;
        if (compare.length) obj.compare = compare;
      } else {
        obj = clothGrid.moveScene(withSettings(app.sceneObj(), p), panels.scene(0).pins, m, p.cols, p.rows, dropped);
        if (compare.length) obj.compare = compare;   // as the panels run (followSets)
        view = scenes.viewFor(obj);
      }
      const edits = clothGrid.applyEdits(obj, app.pinEdits(), m, dropped);
      const holds = app.gestures.held().map(function (h) { return { k: m.moved(h.k), was: h.k, id: h.id }; });
      try {
        app.load(JSON.stringify(obj), preset, view, holds, edits);
      } catch (e) {
        ui.setParams(app.params());  // the banner shows why; the old scene runs on
        ui.note(note);
        return;
      }
      holds.forEach(function (h) { if (h.k < 0) dropped.push('the held vertex at ' + m.place(h.was)); });
      const notes = [note, app.loadNote(), clothGrid.droppedNote(dropped, p.cols, p.rows)];
      ui.note(notes.filter(function (t) { return !!t; }).join('; '));
    }

    return { setParam: setParam, setSolver: setSolver, setMaterial: setMaterial, followSets: followSets };
  }

  return { create: create, paramsOf: paramsOf };
})();
