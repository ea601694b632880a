// The core's public face in the page: clothCore.
//
// `clothTranscrypt.api` is the transpiled cloth/api.py (linked by build.py).
// Transcrypt exceptions are not JS Error instances (the message sits in
// e.__args__[0]), so every entry point turns them into a plain Error carrying
// the same one-line message the CLI prints.

export const clothCore = (function (api) {
  function message(e) {
    if (e instanceof Error) return e.message;
    if (e && e.__args__ && e.__args__.length > 0) return String(e.__args__[0]);
    return String(e);
  }

  function wrap(fn) {
    return function () {
      try {
        return fn.apply(null, arguments);
      } catch (e) {
        if (e instanceof Error) throw e;
        const err = new Error(message(e));
        err.cause = e;
        throw err;
      }
    };
  }

  const SCHEMA = (function () {
    const given = api.schema();
    const keys = {}, order = [];
    given[0].forEach(function (k) {
      keys[k.key] = {
        kind: k.kind, min: k.lo, max: k.hi, minOpen: k.lo_open, words: k.words, label: k.label,
        unit: k.unit, live: k.live, panel: k.panel, fallback: k.fallback, bySolver: k.by_solver,
        field: { min: k.field_lo, max: k.field_hi, step: k.step, int: k.kind === 'int' },
      };
      order.push(k.key);
    });
    return { keys: keys, order: order, solvers: given[1].slice(), defaultSolver: given[2], ops: given[3].slice(),
             maxActions: given[4], maxPanels: given[5], maxVertices: given[6],
             sceneFields: given[7].map(function (f) { return { key: f[0], hint: f[1], axis: f[2], parts: f[3].slice() }; }),
             solverLabels: given[8].slice(), seedSolver: given[9], handForce: given[10],
             handRadius: given[11], model: given[12], restImbalance: given[13], measured: given[14].slice() };
  })();

  const core = {
    // applyDue(cloth, next, frame) -> next: the scene's actions due at frames up to `frame`
    // (cloth/api.py apply_due, the CLI's own loop).
    applyDue: function (cloth, next, f) { return api.apply_due(cloth, next, f); },
    // run(sceneJsonText[, frames[, panel]]) -> JSON text, as the CLI prints it (frames
    // omitted: the scene's own `frames`; panel, from 0: that panel of its `compare` list).
    run: wrap(function (text, frames, panel) {
      return api.run(text, frames === undefined ? null : frames, false, panel === undefined ? -1 : panel);
    }),
    // load(sceneJsonText) -> a live Cloth (typed arrays, frame(), measure(), grab()...).
    load: wrap(function (text) { return api.load(text); }),
    // notes(cloth) -> {unused: what of its settings its solver does not use, legacy: what
    // running a scene of an older model under the membrane did} in words ('' for none).
    notes: function (cloth) { const n = api.notes(cloth); return { unused: n[0], legacy: n[1] }; },
    // fabrics() -> {list: [[name, label, stretch N/m, shear N/m, density kg/m^2, what], ...],
    // preset: name} (cloth/fabrics.py: the Fabric menu's fabrics, declared there once).
    fabrics: function () { const f = api.fabrics(); return { list: f[0], preset: f[1] }; },
    // presets() -> [[name, label, cols, rows, size m], ...] (cloth/presets.py, in menu order);
    // preset(name, cols, rows) -> {scene: the scene object, view: [x0, x1, y0, y1] or []}.
    presets: function () { return api.presets(); },
    preset: function (name, cols, rows) { const p = api.preset(name, cols, rows); return { scene: p[0], view: p[1] }; },
    // schema() -> the scene's keys and the limits the page checks against, declared once in
    // cloth/scene.py (KEYS) and read here (cloth/api.py schema): {keys: {name: {kind, min,
    // max, minOpen, words, label, unit, live, panel, fallback, bySolver, field: {min, max,
    // step, int}}}, order: [names], solvers, defaultSolver, ops, maxActions, maxPanels,
    // maxVertices, sceneFields: [{key, hint, axis, parts}] (the Scene section's number fields;
    // a key of two numbers: parts, the Scene attributes that hold them, and axis, the field's),
    // solverLabels (by solvers' index), seedSolver, handForce (a hand's most pull, N),
    // handRadius (its grip, m), model (the one scenes run under), restImbalance (the most
    // unbalanced force a cloth at rest has, over its weight), measured (the solvers whose solve
    // measures that imbalance)}. Made once; callers must not change it.
    schema: function () { return SCHEMA; },
    // edgesOf(cols, rows) -> [structural edges, all edges] of such a grid (cloth/topology.py).
    edgesOf: function (cols, rows) { return api.edges_of(cols, rows); },
    // sceneLimit() -> {bytes, message}: the most bytes any scene may have and what to say past
    // it (cloth/scene.py MAX_SCENE_BYTES).
    sceneLimit: function () { const l = api.scene_limit(); return { bytes: l[0], message: l[1] }; },
    message: message,
  };
  // What the renderer draws of a cloth, and all it reads: positions, the structural edges'
  // ends, one value per edge (what the colours show: cloth/measure.py) and per vertex (the
  // seed's node stress), and the markers' flags.
  // Views of the core's own arrays, put into `out` (made once per panel: no allocation a
  // frame) before each draw; a worker hosting the core would post these arrays instead.
  core.snapshot = function (cloth, out) {
    out = out || {};
    out.n_edges = cloth.n_struct;
    out.n_verts = cloth.n_verts;
    out.spacing = cloth.spacing;
    out.cols = cloth.cols;
    out.rows = cloth.rows;
    out.pos = cloth.pos;
    out.edge_a = cloth.edge_a;
    out.edge_b = cloth.edge_b;
    out.edge_value = cloth.edge_value;
    out.vertex_value = cloth.stress;
    out.pinned = cloth.pinned;
    out.held = cloth.held;
    // The obstacles, where they are going (an `obstacle` action's `to`: where the person put
    // them), each a shape (0 circle, 1 box) and its half width and height.
    out.n_obstacles = cloth.n_obstacles;
    out.obstacle_shape = cloth.obstacle_shape;
    out.obstacle_half = cloth.obstacle_half;
    out.obstacle_at = cloth.obstacle_to;
    // Where each held vertex's hand is (a hand of finite strength's vertex may lag it).
    out.target = cloth.target;
    return out;
  };
  // What a Worker posts of each panel's cloth after a message (sim/worker.js) and the page copies
  // into its mirror of it (sim/remote.js): the arrays the drawing and the picking read, the
  // edges when they changed (a tear, a cut), and the numbers the readings hold.
  core.MIRRORED = ['pos', 'edge_value', 'stress', 'pinned', 'fixed', 'held', 'target', 'obstacle_at', 'obstacle_to'];
  core.MIRRORED_EDGES = ['edge_a', 'edge_b', 'degree'];
  core.MIRRORED_NUMBERS = ['rms_strain', 'max_strain', 'high_value', 'max_value', 'max_stress', 'imbalance', 'n_struct',
                           'n_edges', 'broken', 'substeps', 'iterations', 'corrections', 'asleep'];
  // What the readouts, the legend and the loop read of a cloth: cloth/measure.py's measures,
  // the solver's balance, the grid, the step and what runs, copied into `out` (made once per
  // panel: numbers and the scene's words, no allocation). Apart from the snapshot, whose shape
  // the renderer's hot path is compiled for.
  core.readings = function (cloth, out) {
    out = out || {};
    out.cols = cloth.cols;
    out.rows = cloth.rows;
    out.rms_strain = cloth.rms_strain;
    out.max_strain = cloth.max_strain;
    out.high_value = cloth.high_value;
    out.max_stress = cloth.max_stress;
    out.imbalance = cloth.imbalance;
    out.springs = cloth.n_edges;
    out.broken = cloth.broken;
    out.asleep = cloth.asleep;
    out.dt = cloth.dt;
    out.substeps = cloth.substeps;
    out.iterations = cloth.iterations;
    out.corrections = cloth.corrections;
    const sc = out.scene || (out.scene = {});
    sc.solver = cloth.scene.solver;
    sc.stretch = cloth.scene.stretch;
    sc.shear = cloth.scene.shear;
    sc.density = cloth.scene.density;
    sc.strength = cloth.scene.strength;
    return out;
  };
  // parseScene(sceneJsonText[, panel]) -> the checked scene, nothing built (cloth/api.py
  // check); with a panel index (from 0), the scene of that panel of its `compare` list.
  core.parseScene = wrap(function (text, panel) { return api.check(text, panel === undefined ? -1 : panel); });

  // session: a scene's panels under one pair of hands, their scripts, the recording and the
  // replay (cloth/session.py; its functions take the session first). open(text) -> a session
  // (throws Error on a bad scene); change(s, keysJsonText) throws, changing nothing, on bad
  // keys. The rest cannot throw and are called as they are (the loop calls them every frame:
  // no wrapper's allocation).
  const THROWS = { open: true, change: true };
  core.session = {};
  api.session_functions().forEach(function (entry) {
    core.session[entry[0]] = THROWS[entry[0]] ? wrap(entry[1]) : entry[1];
  });

  // ops(cloth): the per-frame operations (cloth/api.py operations: the core's module
  // functions) as closures over one cloth, made once per scene. Errors stay Transcrypt's here;
  // callers that need messages use core.message(e).
  const OPERATIONS = api.operations();
  core.ops = function (cloth) {
    const ops = {};
    OPERATIONS.forEach(function (entry) {
      const fn = entry[1];
      ops[entry[0]] = function (a, b, c, d) { return fn(cloth, a, b, c, d); };
    });
    return ops;
  };
  return core;
})(clothTranscrypt.api);
