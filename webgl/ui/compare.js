// Compare mode's own parts: the label over each panel and the editor of each panel's settings in the side panel. Holds no simulation state: the
// app owns the panels' cloths and tells this what to show.
//
// A comparison is the scene's `compare` list (cloth/scene.py): 2 to 4 objects of scene keys,
// one per panel, each written into the scene for that panel. The same hands act on every
// panel (app.js), so the panels differ only by these settings.
import { clothCharts } from '../draw/charts.js';
import { clothCore } from '../sim/core.js';
import { clothFields } from './fields.js';
import { clothScenes } from '../sim/scenes.js';

export const clothCompare = (function () {
  const SCHEMA = clothCore.schema();
  const MAX_PANELS = SCHEMA.maxPanels;      // cloth/scene.py MAX_PANELS
  // The one-click pair: the seed's method against the default, each spelled out so that a
  // scene that set its own solver does not make them the same.
  const SEED_VS_DEFAULT = [SCHEMA.seedSolver, SCHEMA.defaultSolver].map(function (name) {
    const d = clothScenes.SOLVERS[name];
    return { solver: name, substeps: d.substeps, iterations: d.iterations };
  });
  // The editor's fields: every key a panel may have of its own (cloth/scene.py Keys with a
  // `panel`: 2 shown at once, 1 under "more"), the choices first. Number fields take their
  // ranges, labels and the reading of what is typed from the panel's (scenes.js LIMITS).
  const LIMITS = clothScenes.LIMITS;
  function isChoice(key) { const k = SCHEMA.keys[key].kind; return k === 'choice' || k === 'bool'; }
  function panelKeys(level) {
    const keys = SCHEMA.order.filter(function (key) { return SCHEMA.keys[key].panel === level; });
    return keys.filter(isChoice).concat(keys.filter(function (key) { return !isChoice(key); }));
  }
  const MAIN_KEYS = panelKeys(2), MORE_KEYS = panelKeys(1);
  // A choice's options: [value, shown]; '' is the scene's (or, where the solver decides, the
  // solver's) own.
  function optionsOf(key) {
    const k = SCHEMA.keys[key];
    const own = ['', k.bySolver ? 'solver\'s' : 'scene\'s'];
    if (key === 'solver') {
      return [own].concat(SCHEMA.solvers.map(function (name) {
        return [name, clothScenes.SOLVERS[name].label];
      }));
    }
    return [own, ['true', 'on'], ['false', 'off']];
  }

  function $(id) { return document.getElementById(id); }

  // h: {change(list, note) (a new compare list, [] leaves compare mode; note: what was
  //     clamped), note(text), running(i, key) (what panel i runs for key, for its editor)}
  function create(h) {
    const labels = $('panel-labels');
    const list = $('compare-list');
    let current = [];
    const labelEls = [];

    $('btn-compare-pair').addEventListener('click', function () { h.change(SEED_VS_DEFAULT.map(copy)); });
    $('btn-compare-add').addEventListener('click', function () {
      if (current.length >= MAX_PANELS) { h.note('Compare: at most ' + MAX_PANELS + ' panels'); return; }
      const next = current.length ? current.map(copy) : [{}];
      next.push(copy(next[next.length - 1]));
      h.change(next);
    });
    $('btn-compare-off').addEventListener('click', function () { h.change([]); });

    function copy(o) { return Object.assign({}, o); }

    // A field's text -> its value for panel i's key, or a note and no change.
    function edit(i, key, raw) {
      const next = current.map(copy);
      if (isChoice(key)) {
        if (raw === '') delete next[i][key];
        else next[i][key] = SCHEMA.keys[key].kind === 'bool' ? raw === 'true' : raw;
        h.change(next);
        return;
      }
      const text = String(raw).trim();
      if (text === '') { delete next[i][key]; h.change(next); return; }
      const c = clothScenes.clamp(key, text);
      const note = c.note ? 'Panel ' + (i + 1) + ' ' + c.note : '';
      if (c.value === null) {
        h.note(note);
        render(current);
        return;
      }
      // A key whose 0 means none (tearing, a density) takes null for none.
      next[i][key] = LIMITS[key].off && c.value === 0 ? null : c.value;
      h.change(next, note);
    }

    function field(i, key, value) {
      const f = LIMITS[key];
      const input = document.createElement('input');
      // Empty means "the scene's" (clothFields: text fields, read one way).
      // An arrow key in an empty field steps from what the panel runs.
      clothFields.attach(input, key, function (text) { edit(i, key, text); },
                                function () { return h.running(i, key); });
      input.placeholder = 'scene';
      input.value = value === undefined ? '' : String(value);
      input.setAttribute('aria-label', 'Panel ' + (i + 1) + ' ' + f.label);
      input.dataset.key = key;
      const label = document.createElement('label');
      label.textContent = clothFields.caption(key) + ' ';
      label.appendChild(input);
      return label;
    }

    function choice(i, key, value, options, title) {
      const sel = document.createElement('select');
      sel.setAttribute('aria-label', 'Panel ' + (i + 1) + ' ' + title);
      sel.dataset.key = key;
      options.forEach(function (o) {
        const opt = document.createElement('option');
        opt.value = o[0]; opt.textContent = o[1];
        sel.appendChild(opt);
      });
      sel.value = value === undefined ? '' : String(value);
      sel.addEventListener('change', function () { edit(i, key, sel.value); });
      const label = document.createElement('label');
      label.textContent = title + ' ';
      label.appendChild(sel);
      return label;
    }

    // Panel i's fields for `keys`, two to a row.
    function fields(i, o, keys) {
      const grid = document.createElement('div');
      grid.className = 'grid2';
      keys.forEach(function (key) {
        const value = o[key] === null ? 'off' : o[key];
        grid.appendChild(isChoice(key) ? choice(i, key, value, optionsOf(key), SCHEMA.keys[key].label)
                                       : field(i, key, value));
      });
      return grid;
    }

    // The editor: one block per panel (solver, substeps, iterations; the rest folded).
    function render(overrides) {
      current = overrides.map(copy);
      list.textContent = '';
      current.forEach(function (o, i) {
        const box = document.createElement('div');
        box.className = 'compare-panel';
        box.style.borderLeftColor = clothCharts.COLORS[i];
        const head = document.createElement('div');
        head.className = 'compare-head';
        const name = document.createElement('b');
        name.textContent = 'Panel ' + (i + 1);
        const remove = document.createElement('button');
        remove.type = 'button';
        remove.textContent = '×';
        remove.title = 'Remove panel ' + (i + 1);
        remove.addEventListener('click', function () {
          const next = current.filter(function (_, j) { return j !== i; });
          h.change(next.length >= 2 ? next : []);
        });
        head.appendChild(name);
        head.appendChild(remove);
        box.appendChild(head);
        box.appendChild(fields(i, o, MAIN_KEYS));
        const more = document.createElement('details');
        const sum = document.createElement('summary');
        sum.textContent = 'more';
        more.appendChild(sum);
        more.appendChild(fields(i, o, MORE_KEYS));
        if (MORE_KEYS.some(function (key) { return o[key] !== undefined; })) more.open = true;
        box.appendChild(more);
        list.appendChild(box);
      });
      $('btn-compare-off').disabled = current.length === 0;
      $('btn-compare-add').disabled = current.length >= MAX_PANELS;
    }

    // Labels over the panels: number, setting, and the readouts (at the readout rate).
    function placeLabels(rects) {
      while (labelEls.length < rects.length) {
        // Two lines: what the panel runs (cut short with an ellipsis where the panel is
        // narrow) and the numbers, RMS strain first, never cut: the number being compared.
        const el = document.createElement('div');
        el.className = 'panel-label';
        const head = document.createElement('div'), numbers = document.createElement('div');
        head.className = 'panel-label-head';
        numbers.className = 'panel-label-numbers';
        el.appendChild(head);
        el.appendChild(numbers);
        labels.appendChild(el);
        labelEls.push(el);
      }
      for (let i = 0; i < labelEls.length; i++) {
        const el = labelEls[i];
        el.hidden = i >= rects.length || rects.length < 2;
        if (el.hidden) continue;
        const r = rects[i];
        el.style.left = (r.x + 6) + 'px';      // the canvas fills the stage from its corner
        el.style.top = (r.y + 6) + 'px';
        el.firstChild.style.maxWidth = Math.max(60, r.w - 30) + 'px';  // 12 of margins, 18 of padding and border
        el.style.borderLeftColor = clothCharts.COLORS[i];
      }
    }

    function setLabel(i, head, numbers) {
      if (i >= labelEls.length) return;
      const h = labelEls[i].firstChild, n = labelEls[i].lastChild;
      if (h.textContent !== head) h.textContent = head;
      if (n.textContent !== numbers) n.textContent = numbers;
    }

    return { render: render, placeLabels: placeLabels, setLabel: setLabel };
  }

  return { create: create };
})();
