// The settings the panel shows (params: the Scene section's fields, cloth/keys.py
// SCENE_FIELDS, and the solver and fabric): read from a cloth's scene, written into a
// scene object, and the scene keys a change of them sets; and the page's limits for a scene
// and its panels. Pure: data in, data out (the app applies them through the session).
import { clothCore } from './core.js';
import { clothOptions } from './options.js';
import { clothScenes } from './scenes.js';

export const clothParams = (function () {
  const scenes = clothScenes, own = clothOptions.own;
  const KEYS = clothCore.schema().keys;

  // The params as a cloth's scene has them now (the scene it runs, settings set live included).
  function of(scene) {
    const p = { solver: scene.solver, material: scenes.materialOf(scene.stretch, scene.shear, scene.density) };
    scenes.SCENE_FIELDS.forEach(function (key) { p[key] = scenes.fieldOf(scene, key); });
    return p;
  }

  // The scene object with params p written into it (the grid's keys are the caller's).
  function written(obj, p) {
    return scenes.writeParams(Object.assign({}, obj), p);
  }

  // The scene keys that take a running cloth from params `was` to `p` (a `set` action's
  // `scene`); scene: the running scene (a point key keeps the component the panel does not show).
  function changed(was, p, scene) {
    const keys = {};
    scenes.SCENE_FIELDS.forEach(function (key) {
      if (KEYS[key].live && p[key] !== was[key]) keys[key] = scenes.fieldValue(key, p[key], scene[scenes.otherOf(key)], false);
    });
    if (p.solver !== was.solver) keys.solver = p.solver;
    if (p.material !== was.material && own(scenes.MATERIALS, p.material)) {
      keys.stretch = scenes.MATERIALS[p.material].stretch;
      // (a scene of an older model keeps its own `shear`: scenes.ofModel)
      if (scenes.ofModel(scene.model)) keys.shear = scenes.MATERIALS[p.material].shear;
      keys.density = scenes.MATERIALS[p.material].density;
    }
    return keys;
  }

  // The compare list as the panels run it: each entry's keys read from its panel's scene
  // (`scenes`, one per entry). A `set` (the Scene section's or a script's) is written into
  // every panel, the keys a panel has of its own included, as the recording replays it; the
  // editor and a later grid change follow what runs rather than what the panels began with.
  function running(list, panelScenes) {
    return list.map(function (entry, i) {
      const out = {};
      Object.keys(entry).forEach(function (key) {
        const v = panelScenes[i][key];
        // A key whose 0 means none (tearing, a density) is null for none, as the editor writes it.
        out[key] = v === 0 && own(scenes.LIMITS, key) && scenes.LIMITS[key].off ? null : v;
      });
      return out;
    });
  }

  // The page's limits for a scene object and each of its panels (a panel costs what its
  // scene does, and N panels N times one); '' when it can run.
  function limitOf(obj) {
    const list = Array.isArray(obj.compare) ? obj.compare : [];
    if (list.length === 0) return scenes.pageLimit(obj);
    let work = 0;
    for (let i = 0; i < list.length; i++) {
      const one = Object.assign({}, obj, list[i]);
      delete one.compare;
      const limit = scenes.pageLimit(one);
      if (limit) return 'panel ' + (i + 1) + ': ' + limit;
      work += scenes.workOf(one);
    }
    if (work > scenes.PAGE_LIMITS.work) {
      return 'its ' + list.length + ' panels need about ' + work.toExponential(1) + ' edge updates a frame, ' +
        'and the page takes at most ' + scenes.PAGE_LIMITS.work.toExponential(0) + ' (fewer panels, substeps or iterations)';
    }
    return '';
  }

  return { of: of, written: written, changed: changed, running: running, limitOf: limitOf };
})();
