// The page's side of a scene: the presets, the fields' limits and the one reading of a typed
// number, the solvers and fabrics the menus offer (all from the core's schema), the panel's
// settings written into a scene object, the page's limits on a scene's work, and the view
// that fits a scene.
//
// A preset turns the panel's settings (grid size, solver and steps, the live fields, the
// fabric) into the scene JSON the core reads, so a preset and a hand-written scene go through
// the same session.open(). View hints live beside the scene, never in it: the core rejects
// keys it does not know.
'use strict';

window.clothScenes = (function () {
  const own = window.clothOptions.own;
  // The scene's keys, declared once in the core (cloth/scene.py KEYS): each field's label,
  // unit and the range a person may type (the page's, within the core's own). Anything
  // outside is clamped with a visible note. `off`: the key's 0 means none (tearing, a
  // density), so an empty field or `off` is 0 too.
  const SCHEMA = window.clothCore.schema();
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
  // The Material control's fabrics (cloth/scene.py MATERIALS): name -> {label, density kg/m^2,
  // stiffness N/m, compliance m/N}. The presets hang in the core's preset fabric (jersey),
  // whose stretch under its own weight is visible in the colours.
  const MATERIALS = {};
  const fabrics = window.clothCore.materials();
  fabrics.list.forEach(function (m) {
    MATERIALS[m[0]] = { label: m[1], density: m[2], stiffness: m[3], compliance: m[3] > 0 ? 1 / m[3] : 0 };
  });
  // The presets start with the core's default solver and its steps. Damping 1/s, still air's:
  // a released cloth comes to rest within a few seconds, as fabric does (its velocity loses
  // 1/s of itself per second); the core's default, 0, swings for minutes.
  const DEFAULT_PARAMS = { solver: SCHEMA.defaultSolver, substeps: SOLVERS[SCHEMA.defaultSolver].substeps,
                           iterations: SOLVERS[SCHEMA.defaultSolver].iterations,
                           damping: 1, tear: 0, material: fabrics.preset };

  // The named fabric a scene's density and compliance are, or 'custom' (a scene of its own,
  // or one without a density: every vertex 1 kg, as scenes were before materials).
  function materialOf(density, compliance) {
    for (const name in MATERIALS) {
      if (own(MATERIALS, name) && MATERIALS[name].density === density && MATERIALS[name].compliance === compliance) {
        return name;
      }
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
  // and the material's density and stiffness.
  function writeParams(obj, p) {
    SCENE_FIELDS.forEach(function (key) {
      if (!SCHEMA.keys[key].live) return;
      const rest = !pair(key) ? 0 : Array.isArray(obj[key]) ? obj[key][1 - AXIS[key]] : SCHEMA.keys[key].fallback[1 - AXIS[key]];
      const v = fieldValue(key, p[key], rest, true);
      if (v === undefined) delete obj[key]; else obj[key] = v;
    });
    obj.solver = p.solver;
    if (own(MATERIALS, p.material)) {
      obj.density = MATERIALS[p.material].density;
      obj.compliance = MATERIALS[p.material].compliance;
    }
    return obj;
  }

  function topRow(cols, every) {
    const pins = [];
    for (let c = 0; c < cols; c += every) pins.push(c);
    if (pins[pins.length - 1] !== cols - 1) pins.push(cols - 1);
    return pins;
  }

  // size: the cloth's larger side in metres; the spacing follows from the grid.
  const CARRY_FRAMES = 60;   // the Two corners preset carries its corner in over 1 s
  const PRESETS = {
    // Hung from a rod: every vertex of the top row pinned, so the strain is the curtain's own
    // (zero at the hem, growing to density g height / stiffness at the rod) at every grid
    // size. Pins a few columns apart at the rest spacing made a top row that must carry the
    // columns while straight: an inextensible cloth has no equilibrium there, and the colours
    // showed how far the solver got.
    curtain: {
      label: 'Curtain',
      params: { cols: 40, rows: 30 },
      size: 2.0,
      pins: function (cols) { return topRow(cols, 1); },
    },
    // Inextensible: its exact hang is known (cloth/reference.py), and the default meets it. A
    // material hung from two points is not yet something the solver does well: a grid of
    // structural edges carries the whole weight in its top row (no shear stiffness spreads it
    // into the rows below), whose strain then grows as the grid refines and whose line solves
    // keep a limit cycle (the README's "Known limits", measured by the strain table of
    // `python -m bench --physics`).
    corners: {
      label: 'Two corners',
      params: { cols: 30, rows: 30, material: 'inextensible' },
      size: 1.6,
      pins: function (cols) { return cols > 1 ? [0, cols - 1] : [0]; },
      // Slack: the right corner is carried in to 80% of the width over the first second (a
      // smooth start and stop) and pinned there, so the cloth hangs with its top row sagging
      // (the scene where shape shows). Carried, not put there at frame 0: a corner moved there
      // in one frame flings the cloth (`python -m bench --figures`, the corner table).
      actions: function (cols, rows, spacing) {
        if (cols < 2) return [];
        const k = cols - 1, x0 = (cols - 1) * spacing, x1 = 0.8 * x0, frames = CARRY_FRAMES;
        const out = [{ frame: 0, op: 'grab', vertex: k, to: [x0, 0] }];
        for (let f = 1; f <= frames; f++) {
          const t = 0.5 - 0.5 * Math.cos(Math.PI * f / frames);
          out.push({ frame: f, op: 'move', vertex: k, to: [x0 + (x1 - x0) * t, 0] });
        }
        out.push({ frame: frames, op: 'pin', vertex: k }, { frame: frames, op: 'release', vertex: k });
        return out;
      },
      sag: 0.6,
    },
    chain: {
      label: 'Chain',
      params: { cols: 40, rows: 1 },
      size: 1.6,
      pins: function () { return [0]; },
      // A pendulum: it swings through the half-disc below its pin.
      view: function (w, h) { const r = w + h; return { x0: -r, x1: r, y0: -r, y1: 0.15 * r }; },
    },
    // Hung from a rod too: five point pins at the rest spacing made a top row that an
    // inextensible cloth cannot hang from (it never came to rest: 0.5 m/s after 10 s) and
    // concentrated a jersey's load in the links at each pin (35% strain, growing with the grid).
    large: {
      label: 'Large cloth',
      params: { cols: 100, rows: 100 },
      size: 2.0,
      pins: function (cols) { return topRow(cols, 1); },
    },
    // Made to be torn: pull a vertex well past where the cloth can reach (its edges break
    // past 30% strain), or cut it (Alt+drag, or the Cut tool).
    tearable: {
      label: 'Tearable',
      params: { cols: 60, rows: 40, tear: 0.3 },
      size: 2.0,
      pins: function (cols) { return topRow(cols, 1); },
    },
    // A towel over a peg, seen from its side: a strip dropped on a round peg (an obstacle with
    // friction) drapes over it in two hanging halves. Drag the peg (or the towel) about.
    peg: {
      label: 'Towel on a peg',
      params: { cols: 60, rows: 3 },
      size: 2.0,
      pins: function () { return []; },
      // The peg at least a spacing in radius: a thinner one fits between two vertices, and a
      // coarse towel (10 columns) slid off it through the edge over it (measured: free fall).
      keys: function (cols, rows, spacing) {
        const w = (cols - 1) * spacing;
        return { obstacles: [{ circle: [0.5 * w, -0.35 * w, Math.max(0.04 * w, spacing)], friction: 0.6 }] };
      },
      view: function (w) { return { x0: 0.2 * w, x1: 0.8 * w, y0: -0.95 * w, y1: 0.05 * w }; },
    },
    // A flag on its pole (the left column pinned) in a gusty wind from the left.
    flag: {
      label: 'Flag in the wind',
      params: { cols: 45, rows: 30, wind: 10 },
      size: 1.8,
      pins: function (cols, rows) {
        const pins = [];
        for (let r = 0; r < rows; r++) pins.push(r * cols);
        return pins;
      },
      // Shear edges: a flag holds its shape (without them, each row hangs from its own pin and
      // the cloth shears flat along the pole).
      keys: function () { return { shear: true, drag: 0.4, gust: [0.5, 1.7] }; },
      view: function (w, h) { return { x0: -0.15 * w, x1: 1.15 * w, y0: -h - 0.6 * w, y1: 0.1 * w }; },
    },
  };

  function spacingFor(preset, cols, rows) {
    const cells = Math.max(cols - 1, rows - 1, 1);
    return preset.size / cells;
  }

  // Returns {scene, view}; params must already be clamped.
  function make(name, params) {
    const preset = own(PRESETS, name) ? PRESETS[name] : null;
    if (!preset) throw new Error('unknown preset: ' + name);
    const p = Object.assign({}, DEFAULT_PARAMS, preset.params, params || {});
    const spacing = spacingFor(preset, p.cols, p.rows);
    const scene = writeParams({ cols: p.cols, rows: p.rows, spacing: spacing, pins: preset.pins(p.cols, p.rows),
                                dt: SCHEMA.keys.dt.fallback }, p);
    if (preset.actions) scene.actions = preset.actions(p.cols, p.rows, spacing);
    if (preset.keys) Object.assign(scene, preset.keys(p.cols, p.rows, spacing));
    const w = (p.cols - 1) * spacing, h = (p.rows - 1) * spacing;
    const view = preset.view ? preset.view(w, h) : viewFor(scene, preset.sag);
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
  // A frame's work estimated before loading, in edge updates: per step the sweeps, plus, where
  // they run, tethers, cells and line solves (about 6 per vertex, measured by projections).
  // Above REAL_TIME_WORK a frame takes more than its 1/60 s on an ordinary machine.
  const REAL_TIME_WORK = 1e6;
  function slowNote(work) {
    return 'This scene needs about ' + work.toExponential(1) + ' edge updates a frame: ' +
      'expect slow motion on an ordinary machine';
  }

  function workOf(scene) {
    const cols = scene.cols | 0, rows = scene.rows | 0;
    const solver = own(SOLVERS, scene.solver) ? scene.solver : SCHEMA.defaultSolver;
    const d = SOLVERS[solver];
    const substeps = Number.isFinite(scene.substeps) ? scene.substeps : d.substeps;
    const iterations = Number.isFinite(scene.iterations) ? scene.iterations : d.iterations;
    const n = cols * rows;
    const m = window.clothCore.edgesOf(Math.max(cols, 1), Math.max(rows, 1), scene.shear === true);
    const index = SCHEMA.solvers.indexOf(solver);
    const extras = ['tethers', 'cells', 'lines'].some(function (key) {
      return typeof scene[key] === 'boolean' ? scene[key] : SCHEMA.keys[key].bySolver[index];
    });
    return substeps * (Math.max(iterations, 0) * m + (extras ? 6 * n : 0));
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

  function defaults(name) {
    if (!own(PRESETS, name)) throw new Error('unknown preset: ' + name);
    return Object.assign({}, DEFAULT_PARAMS, PRESETS[name].params);
  }

  return { SCENE_FIELDS: SCENE_FIELDS, fieldOf: fieldOf, fieldValue: fieldValue, otherOf: other, writeParams: writeParams,
           PRESETS: PRESETS, LIMITS: LIMITS, SOLVERS: SOLVERS, MATERIALS: MATERIALS, materialOf: materialOf,
           PAGE_LIMITS: PAGE_LIMITS,
           REAL_TIME_WORK: REAL_TIME_WORK, slowNote: slowNote, defaults: defaults, make: make, viewFor: viewFor,
           clamp: clamp, readNumber: readNumber, workOf: workOf, pageLimit: pageLimit };
})();
