// The page's side of a scene: the presets, the fields' limits and the one reading of a typed
// number, the solvers and fabrics the menus offer (all from the core's schema), the panel's
// settings written into a scene object, the page's limits on a scene's work, and the view
// that fits a scene.
//
// A preset turns the panel's settings (grid size, solver and steps, the live fields, the
// fabric) into the scene JSON the core reads, so a preset and a hand-written scene go through
// the same session.open(). View hints live beside the scene, never in it: the core rejects
// keys it does not know.
import { clothCore } from './core.js';
import { clothOptions } from './options.js';

export const clothScenes = (function () {
  const own = clothOptions.own;
  // The scene's keys, declared once in the core (cloth/scene.py KEYS): each field's label,
  // unit and the range a person may type (the page's, within the core's own). Anything
  // outside is clamped with a visible note. `off`: the key's 0 means none (tearing, a
  // density), so an empty field or `off` is 0 too.
  const SCHEMA = clothCore.schema();
  const LIMITS = {};
  SCHEMA.order.forEach(function (key) {
    const k = SCHEMA.keys[key], f = k.field;
    if (f.max <= f.min) return;   // not a number a person types
    LIMITS[key] = { min: f.min, max: f.max, int: f.int, step: f.step, label: k.label, unit: k.unit,
                    off: k.minOpen && k.fallback === 0 };
  });
  // The page's own: the colour scale's full scale (a strain), not a scene key.
  LIMITS.fullScale = { min: 0.0001, max: 1, int: false, step: 0.001, label: 'Full scale', unit: '', off: false };

  // The one reading of a number typed into any field (the panel's, the compare editor's, the
  // Tear field, the full scale): a plain decimal number -> {value, read}, anything else ->
  // {value: null, why}. A typographic minus and a decimal comma are read as a person means
  // them, and `read` says so; whatever a browser or a parser would otherwise guess at
  // (5,500, 0x10, 1_000, 1e-400 that rounds to 0, Infinity) is refused, never rewritten.
  const PLAIN_NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
  function readNumber(raw) {
    const typed = raw === null || raw === undefined ? '' : String(raw).trim();
    let text = typed.replace(/[\u2212\u2013\uFE63\uFF0D]/g, '-');    // minus signs and an en dash
    const comma = /^([+-]?\d*),(\d+)$/.exec(text);                     // one comma, no point
    if (comma) {
      if (comma[2].length === 3 && comma[1].replace(/[+-]/, '') !== '' && comma[1].replace(/[+-]/, '') !== '0') {
        return { value: null, why: 'a comma before three digits could be a decimal comma or a thousands ' +
          'separator (write ' + comma[1] + '.' + comma[2] + ' or ' + comma[1] + comma[2] + ')' };
      }
      text = comma[1] + '.' + comma[2];
    }
    if (!PLAIN_NUMBER.test(text)) return { value: null, why: 'not a number' };
    const v = Number(text);
    if (!Number.isFinite(v)) return { value: null, why: 'not a finite number' };
    if (v === 0 && /[1-9]/.test(text.split(/[eE]/)[0])) return { value: null, why: 'too small: it rounds to 0' };
    return { value: v, read: text === typed ? '' : 'read "' + typed.slice(0, 24) + '" as ' + v };
  }

  // Each solver's label and own substeps and iterations (cloth/scene.py SOLVER_LABELS and
  // Keys, by solver): picking a solver in the UI starts from these.
  const SOLVERS = {};
  SCHEMA.solvers.forEach(function (name, i) {
    SOLVERS[name] = { label: SCHEMA.solverLabels[i], substeps: SCHEMA.keys.substeps.bySolver[i],
                      iterations: SCHEMA.keys.iterations.bySolver[i] };
  });
  // The Material control's fabrics (cloth/fabrics.py FABRICS): name -> {label, stretch N/m,
  // shear N/m, density kg/m^2, strength N/m, what}. The presets hang in the core's preset fabric.
  const MATERIALS = {};
  const fabrics = clothCore.fabrics();
  fabrics.list.forEach(function (f) {
    MATERIALS[f[0]] = { label: f[1], stretch: f[2], shear: f[3], density: f[4], strength: f[5], what: f[6] };
  });
  // A panel starts with the core's default solver and its steps; a preset's own settings
  // (its damping, tearing, wind) come from its scene (cloth/presets.py).
  const DEFAULT_PARAMS = { solver: SCHEMA.defaultSolver, substeps: SOLVERS[SCHEMA.defaultSolver].substeps,
                           iterations: SOLVERS[SCHEMA.defaultSolver].iterations,
                           damping: 1, strength: 0, material: fabrics.preset };

  // The named fabric a scene's stretch, shear and density are, or 'custom' (a scene's own).
  function materialOf(stretch, shear, density) {
    for (const name in MATERIALS) {
      const f = MATERIALS[name];
      if (own(MATERIALS, name) && f.stretch === stretch && f.shear === shear && f.density === density) return name;
    }
    return 'custom';
  }

  // The Scene section's number fields (cloth/scene.py SCENE_FIELDS), in order.
  const SCENE_FIELDS = SCHEMA.sceneFields.map(function (f) { return f.key; });

  // A key of two numbers has a field for one of them (SCENE_FIELDS' axis): the Scene
  // attribute that holds it, and the other one's.
  const AXIS = {}, PARTS = {};
  SCHEMA.sceneFields.forEach(function (f) { AXIS[f.key] = f.axis; PARTS[f.key] = f.parts; });
  function pair(key) { return PARTS[key].length === 2; }
  function shown(key) { return PARTS[key][AXIS[key]]; }
  function other(key) { return PARTS[key][1 - AXIS[key]]; }
  // The other live fields start from their keys' defaults (gravity down, still air).
  SCHEMA.sceneFields.forEach(function (f) {
    const k = SCHEMA.keys[f.key];
    if (k.live && !own(DEFAULT_PARAMS, f.key)) DEFAULT_PARAMS[f.key] = pair(f.key) ? k.fallback[f.axis] : k.fallback;
  });

  // A Scene-section field's value in a scene as the core holds it (a cloth's `scene`).
  function fieldOf(scene, key) {
    return pair(key) ? scene[shown(key)] : scene[key];
  }

  // The value a scene object takes for field `key` at value v (a point keeps its other
  // component, `rest`; a key whose 0 means none takes null); undefined for none where `omit`
  // (a scene written whole).
  function fieldValue(key, v, rest, omit) {
    if (pair(key)) return AXIS[key] ? [rest, v] : [v, rest];
    if (LIMITS[key].off && !(v > 0)) return omit ? undefined : null;
    return v;
  }

  // The scene object `obj` with the panel's settings p written in: the live Scene-section
  // fields (those that are not live make the grid, and the caller writes them), the solver
  // and the fabric's three numbers.
  function writeParams(obj, p) {
    SCENE_FIELDS.forEach(function (key) {
      if (!SCHEMA.keys[key].live) return;
      const rest = !pair(key) ? 0 : Array.isArray(obj[key]) ? obj[key][1 - AXIS[key]] : SCHEMA.keys[key].fallback[1 - AXIS[key]];
      const v = fieldValue(key, p[key], rest, true);
      if (v === undefined) delete obj[key]; else obj[key] = v;
    });
    obj.solver = p.solver;
    if (own(MATERIALS, p.material)) {
      obj.stretch = MATERIALS[p.material].stretch;
      if (ofModel(obj.model)) obj.shear = MATERIALS[p.material].shear;
      obj.density = MATERIALS[p.material].density;
    }
    return obj;
  }

  // Whether a scene of model `model` (its `model` key) reads the fabric's shear stiffness. A
  // scene made before the membrane (no `model`, or an older one) has a `shear` of its own, a
  // boolean the membrane leaves out, and the core refuses a number there: its shear stiffness
  // is the default fabric's, and the page writes only its stretch and density.
  function ofModel(model) { return model === SCHEMA.model; }

  // The presets (cloth/presets.py, in menu order): name -> {label, params: {cols, rows}}.
  // Their scenes are the core's, a function of the grid (make).
  const PRESETS = {};
  clothCore.presets().forEach(function (p) {
    PRESETS[p[0]] = { label: p[1], params: { cols: p[2], rows: p[3] } };
  });

  // The panel's settings a preset starts with: the page's defaults, then the preset's grid
  // and what its scene sets of the Scene section's fields and the fabric.
  function defaults(name) {
    if (!own(PRESETS, name)) throw new Error('unknown preset: ' + name);
    const p = Object.assign({}, DEFAULT_PARAMS, PRESETS[name].params);
    const obj = clothCore.preset(name, p.cols, p.rows).scene;
    SCENE_FIELDS.forEach(function (key) {
      if (!SCHEMA.keys[key].live || !own(obj, key)) return;
      p[key] = pair(key) ? obj[key][AXIS[key]] : (obj[key] === null ? 0 : obj[key]);
    });
    p.material = materialOf(obj.stretch, obj.shear, obj.density);
    return p;
  }

  // Returns {scene, view}; params must already be clamped.
  function make(name, params) {
    if (!own(PRESETS, name)) throw new Error('unknown preset: ' + name);
    const p = Object.assign({}, defaults(name), params || {});
    const made = clothCore.preset(name, p.cols, p.rows);
    const scene = writeParams(made.scene, p);
    const view = made.view.length === 4 ? { x0: made.view[0], x1: made.view[1], y0: made.view[2], y1: made.view[3] }
      : viewFor(scene);
    return { scene: scene, view: view };
  }

  // The world box to fit for any scene: the flat grid (x right, y up, row 0 at
  // y = 0), room below for it to sag, and a margin.
  function viewFor(scene, sag) {
    const cols = scene.cols | 0, rows = scene.rows | 0, s = +scene.spacing || 1;
    const w = Math.max(cols - 1, 0) * s, h = Math.max(rows - 1, 0) * s;
    const big = Math.max(w, h, s);
    const margin = 0.08 * big;
    const below = (sag === undefined ? 0.2 : sag) * big;
    const v = { x0: -margin, x1: w + margin, y0: -h - below - margin, y1: margin };
    // A wind leans the cloth downwind, up to its height: room for it on that side.
    const wind = Array.isArray(scene.wind) && Number.isFinite(scene.wind[0]) ? scene.wind[0] : 0;
    if (wind > 0) v.x1 += h + below; else if (wind < 0) v.x0 -= h + below;
    // Obstacles near the cloth are in view too (up to a cloth's size around it: a floor
    // 10 km wide would shrink the cloth to a dot).
    const near = { x0: v.x0 - big, x1: v.x1 + big, y0: v.y0 - big, y1: v.y1 + big };
    (Array.isArray(scene.obstacles) ? scene.obstacles : []).forEach(function (o) {
      const c = o && Array.isArray(o.circle) ? o.circle : null, b = o && Array.isArray(o.box) ? o.box : null;
      const e = c ? [c[0] - c[2], c[1] - c[2], c[0] + c[2], c[1] + c[2]] : b;
      if (!e || !e.every(Number.isFinite)) return;
      v.x0 = Math.min(v.x0, Math.max(e[0] - margin, near.x0));
      v.y0 = Math.min(v.y0, Math.max(e[1] - margin, near.y0));
      v.x1 = Math.max(v.x1, Math.min(e[2] + margin, near.x1));
      v.y1 = Math.max(v.y1, Math.min(e[3] + margin, near.y1));
    });
    return v;
  }

  // What the page runs at most, for every scene it loads (panel, preset, JSON box, link):
  // a frame is one task that cannot be split, so a scene beyond these would stop the page
  // answering a person (1000x1000 took 25-40 s a frame). The CLI has its own, larger limits.
  const PAGE_LIMITS = { vertices: LIMITS.cols.max * LIMITS.rows.max, work: 4e6 };
  // A frame's work estimated before loading, in edge updates (an edge's force and stiffness
  // worked out once): per step, the seed's sweeps over the structural edges; XPBD's over all;
  // a vertex-descent sweep reaches each edge from both ends, and a coarse correction costs
  // about eight passes over the edges (assembly, the Galerkin products amortised, the line
  // search). Above REAL_TIME_WORK a frame takes more than its 1/60 s on an ordinary machine.
  const REAL_TIME_WORK = 1e6;
  function slowNote(work) {
    return 'This scene needs about ' + work.toExponential(1) + ' edge updates a frame: ' +
      'expect slow motion on an ordinary machine';
  }

  function workOf(scene) {
    const cols = Math.max(scene.cols | 0, 1), rows = Math.max(scene.rows | 0, 1);
    const solver = own(SOLVERS, scene.solver) ? scene.solver : SCHEMA.defaultSolver;
    const index = SCHEMA.solvers.indexOf(solver);
    function budget(key) {
      return Number.isFinite(scene[key]) ? Math.max(scene[key], 0) : SCHEMA.keys[key].bySolver[index];
    }
    const edges = clothCore.edgesOf(cols, rows);
    const substeps = budget('substeps'), iterations = budget('iterations');
    if (solver === SCHEMA.seedSolver) return substeps * iterations * edges[0];
    if (solver === SCHEMA.defaultSolver) return substeps * (2 * iterations + 8 * budget('corrections')) * edges[1];
    return substeps * iterations * edges[1];
  }

  // '' when the page can run the scene object; otherwise why not, in one sentence.
  function pageLimit(scene) {
    if (!scene || typeof scene !== 'object' || !Number.isFinite(scene.cols) || !Number.isFinite(scene.rows)) {
      return '';   // the core says what is wrong with it
    }
    const n = scene.cols * scene.rows;
    if (n > PAGE_LIMITS.vertices) {
      return 'the page runs at most ' + PAGE_LIMITS.vertices + ' vertices (' + LIMITS.cols.max + '×' +
        LIMITS.rows.max + '), and this scene has ' + scene.cols + '×' + scene.rows + ' = ' + n +
        ' (python -m cloth run takes up to ' + SCHEMA.maxVertices + ')';
    }
    const work = workOf(scene);
    if (work > PAGE_LIMITS.work) {
      return 'a frame of this scene needs about ' + work.toExponential(1) + ' edge updates, and the page ' +
        'takes at most ' + PAGE_LIMITS.work.toExponential(0) + ' (lower the substeps, the iterations or the grid)';
    }
    return '';
  }

  // Clamp a UI value: returns {value, note} (note is '' when in range; value null when the
  // text is refused, and the note says why).
  function clamp(key, raw) {
    if (!own(LIMITS, key)) throw new Error('unknown parameter: ' + key);
    const lim = LIMITS[key];
    const text = raw === null || raw === undefined ? '' : String(raw).trim();
    if (lim.off && (text === '' || text.toLowerCase() === 'off')) return { value: 0, note: '' };
    const r = readNumber(text);
    if (r.value === null) {
      const shown = text === '' ? '' : ' ("' + text.slice(0, 24) + '")';
      return { value: null, note: lim.label + ': ' + r.why + shown + '; the old value is kept' };
    }
    let v = r.value;
    const notes = r.read ? [lim.label + ': ' + r.read] : [];
    if (lim.off && v === 0) return { value: 0, note: notes.join('; ') };
    // A field where empty means off takes no negative value: a limit below zero is a slip of
    // the hand, and its minimum (the most that tearing can do) would shred the cloth.
    if (lim.off && v < 0) {
      return { value: null, note: lim.label + ': ' + text.slice(0, 24) + ' is below 0 (0 or empty: off); the old value is kept' };
    }
    if (lim.int && v !== Math.round(v)) { v = Math.round(v); notes.push(lim.label + ' rounded to ' + v); }
    if (v < lim.min) { v = lim.min; notes.push(lim.label + ' clamped to its minimum ' + v); }
    if (v > lim.max) { v = lim.max; notes.push(lim.label + ' clamped to its maximum ' + v); }
    return { value: v, note: notes.join('; ') };
  }

  return { SCENE_FIELDS: SCENE_FIELDS, fieldOf: fieldOf, fieldValue: fieldValue, otherOf: other, writeParams: writeParams,
           PRESETS: PRESETS, LIMITS: LIMITS, SOLVERS: SOLVERS, MATERIALS: MATERIALS, materialOf: materialOf,
           PAGE_LIMITS: PAGE_LIMITS,
           REAL_TIME_WORK: REAL_TIME_WORK, slowNote: slowNote, defaults: defaults, make: make, viewFor: viewFor,
           clamp: clamp, readNumber: readNumber, workOf: workOf, pageLimit: pageLimit, ofModel: ofModel };
})();
