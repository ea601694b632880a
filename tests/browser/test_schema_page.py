"""The page takes every scene key from the core's one declaration (cloth/keys.py KEYS, issue
#23): the panel's fields (caption, range, step), the compare editor's fields, each solver's
starting substeps and iterations (cloth/solvers.py), the fabrics (cloth/fabrics.py), the
presets (cloth/presets.py), the action ops and limits and the page's grid limit. Held against
the CPython declarations, so that neither side can drift. CPython's own side:
tests/test_schema.py."""
import json

from browser_helpers import near  # noqa: F401  (the helpers' import sets the path)

from cloth.keys import KEYS, OPS, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES, COMPARE_KEYS, MODEL, \
    SCENE_FIELDS
from cloth.keys import SOLVERS, SOLVER_BUDGETS, SOLVER_LABELS, DEFAULT_SOLVER
from cloth.fabrics import FABRICS, DEFAULT_FABRIC
from cloth.presets import PRESETS
from cloth.topology import count_edges

PANEL_FIELDS = [f[0] for f in SCENE_FIELDS]
GRIDS = [[1, 1], [7, 5], [200, 3], [1, 40]]


def caption(k):
    return k.label + (' (' + k.unit + ')' if k.unit else '')


def test_the_page_reads_the_cores_declarations(open_page):
    pg = open_page()
    got = pg.js('''(() => {
      const s = clothCore.schema(), L = clothScenes.LIMITS;
      return {order: s.order, keys: s.keys, limits: L, ops: s.ops, maxActions: s.maxActions,
              maxPanels: s.maxPanels, maxVertices: s.maxVertices, solvers: clothScenes.SOLVERS,
              pageVertices: clothScenes.PAGE_LIMITS.vertices, model: s.model,
              fabrics: clothCore.fabrics(), materials: clothScenes.MATERIALS,
              edges: %s.map((a) => clothCore.edgesOf(a[0], a[1]))};
    })()''' % json.dumps(GRIDS))
    assert got['order'] == [k.key for k in KEYS]
    assert got['ops'] == OPS and got['maxActions'] == MAX_ACTIONS
    assert got['maxPanels'] == MAX_PANELS and got['maxVertices'] == MAX_VERTICES
    for k in KEYS:
        page = got['keys'][k.key]
        assert (page['kind'], page['label'], page['unit'], page['live'], page['panel']) == \
            (k.kind, k.label, k.unit, k.live, k.panel), k.key
        if k.field_hi > k.field_lo:
            lim = got['limits'][k.key]
            assert (lim['min'], lim['max'], lim['step'], lim['label'], lim['int']) == \
                (k.field_lo, k.field_hi, k.step, k.label, k.kind == 'int'), k.key
        else:
            assert k.key not in got['limits'], k.key
    # Only the strength's 0 means none (an empty field, `off`: it does not tear); a cloth
    # always has a density.
    assert got['limits']['strength']['off']
    assert not got['limits']['density']['off'] and not got['limits']['damping']['off']
    for i, name in enumerate(SOLVERS):
        assert (got['solvers'][name]['label'], got['solvers'][name]['substeps'],
                got['solvers'][name]['iterations']) == (SOLVER_LABELS[i],) + tuple(SOLVER_BUDGETS[i][:2])
    k = {k.key: k for k in KEYS}
    assert got['pageVertices'] == k['cols'].field_hi * k['rows'].field_hi
    assert got['edges'] == [count_edges(c, r) for c, r in GRIDS]
    assert got['model'] == MODEL
    # The fabrics: the core's list, read once, and the page's Material menu made of it.
    assert got['fabrics'] == {'list': FABRICS, 'preset': DEFAULT_FABRIC}
    assert {n: [m['label'], m['stretch'], m['shear'], m['density']] for n, m in got['materials'].items()} == \
        {f[0]: f[1:5] for f in FABRICS}


def test_the_panels_fields_are_captioned_and_bounded_by_their_keys(open_page):
    pg = open_page()
    k = {k.key: k for k in KEYS}
    # The Scene section's fields are the core's list, in its order, with its hints.
    shown = pg.js('''[...document.querySelectorAll('#scene-fields input')].map(
        (el) => [el.id, el.parentNode.title])''')
    assert [s[0] for s in shown] == PANEL_FIELDS
    for (key, title), (_, hint, _axis, _parts) in zip(shown, SCENE_FIELDS):
        assert title.lower() == hint.lower(), key
    for key in PANEL_FIELDS:
        text = pg.js('(id) => document.getElementById(id).parentNode.textContent.trim()', key)
        assert text == caption(k[key]), key
        title = pg.js('(id) => document.getElementById(id).title', key)
        assert title == '%s: %s to %s' % (k[key].label, fmt(k[key].field_lo), fmt(k[key].field_hi)), key
    # Typing past a field's end clamps to the declared end, and says so (Iterations: whose end
    # the page still runs on the curtain).
    pg.js('clothApp.setPaused(true)')
    pg.fill('#iterations', '1e9')
    pg.press('#iterations', 'Enter')
    assert pg.js('clothApp.info().params.iterations') == k['iterations'].field_hi
    assert 'Iterations clamped to its maximum %d' % k['iterations'].field_hi in pg.info()['note']
    # Each field is read from and written to its key: typed in, it is what the cloth runs
    # (a point key's field is its y component; a grid key makes a new grid).
    typed = {'iterations': '3', 'substeps': '5', 'gravity': '-4.5', 'damping': '0.5', 'strength': '70',
             'cols': '9', 'rows': '8', 'wind': '3', 'gust': '0.5'}
    assert set(typed) == set(PANEL_FIELDS)
    for key in PANEL_FIELDS:
        pg.fill('#' + key, typed[key])
        pg.press('#' + key, 'Enter')
    scene = pg.js('clothApp.cloth().scene')
    for key in PANEL_FIELDS:
        axis, parts = [(f[2], f[3]) for f in SCENE_FIELDS if f[0] == key][0]
        got = scene[parts[axis]] if parts else scene[key]
        assert got == float(typed[key]), key
        assert pg.input_value('#' + key) == typed[key], key


def fmt(x):
    return str(int(x)) if x == int(x) else repr(x)


def test_the_compare_editor_offers_exactly_the_keys_a_panel_may_have(open_page):
    pg = open_page()
    pg.locator('#btn-compare-pair').click()
    shown = pg.js('''[...document.querySelectorAll('#compare-list .compare-panel')].map(
        (p) => [...p.querySelectorAll('[data-key]')].map((el) => el.dataset.key))''')
    assert len(shown) == 2
    for keys in shown:
        assert sorted(keys) == sorted(COMPARE_KEYS)
    # Every field it offers makes a scene the core takes: a panel with Strength off (null: none)
    # and a fabric of its own runs, and its scene says so.
    pg.js('clothApp.setPaused(true)')
    pg.locator('#compare-list summary >> nth=1').click()     # panel 2's "more"
    for key, text, value in [('strength', 'off', None), ('stretch', '5000', 5000), ('shear', '0', 0),
                             ('density', '0.4', 0.4), ('corrections', '3', 3)]:
        sel = '#compare-list input[data-key=%s] >> nth=1' % key
        pg.fill(sel, text)
        pg.press(sel, 'Enter')
        scene = json.loads(pg.js('clothApp.panels()')[1]['scene'])
        assert key in scene and scene[key] == value, (key, scene.get(key))
        assert pg.info()['error'] == '', pg.info()['error']
    # and what panel 2 runs is that fabric
    assert '5000/0 N/m 0.4 kg/m\u00b2' in pg.js('clothApp.panels()[1].label')
    pg.js('clothApp.advance(5)')
    assert pg.js('clothApp.info().frames') >= 5


def test_the_menus_are_the_declared_solvers_and_presets(open_page):
    """The Solver menu is cloth/solvers.py SOLVERS with their SOLVER_LABELS, and the Preset menu
    and the number keys are cloth/presets.py PRESETS in order: neither is written in the HTML."""
    pg = open_page()
    got = pg.js('''(() => ({
      solver: [...document.querySelectorAll('#solver option')].map((o) => [o.value, o.textContent, o.title]),
      preset: [...document.querySelectorAll('#preset option')].map((o) => [o.value, o.textContent, o.disabled]),
      presets: Object.keys(clothScenes.PRESETS).map((n) => [n, clothScenes.PRESETS[n].label]),
    }))()''')
    assert [v for v, _, _ in got['solver']] == SOLVERS
    for (value, text, title), label in zip(got['solver'], SOLVER_LABELS):
        assert text == label and (title.startswith('The default') == (value == DEFAULT_SOLVER)), title
    assert [[n, label, False] for n, label in got['presets']] + [['custom', 'Custom (JSON)', True]] == \
        got['preset']
    assert got['presets'] == [[p[0], p[1]] for p in PRESETS]
    # Each number key picks its preset; the menu shows it.
    pg.js('clothApp.setPaused(true)')
    for i, (name, _label) in enumerate(got['presets']):
        pg.locator('body').press(str(i + 1))
        assert pg.info()['preset'] == name and pg.input_value('#preset') == name
    # A scene that says its solver shows it in the menu, by the declared name.
    for name in SOLVERS:
        pg.js('([n, m]) => clothApp.loadScene({model: m, cols: 3, rows: 3, spacing: 0.1, pins: [0], solver: n})',
              [name, MODEL])
        assert pg.input_value('#solver') == name
