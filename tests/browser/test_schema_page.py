"""The page takes every scene key from the core's one declaration (cloth/scene.py KEYS, issue
#23): the panel's fields (caption, range, step), the compare editor's fields, each solver's
starting substeps and iterations, the action ops and limits and the page's grid limit. Held
against the CPython declarations, so that neither side can drift. CPython's own side:
tests/test_schema.py."""
import json

from browser_helpers import near  # noqa: F401  (the helpers' import sets the path)

from cloth.scene import KEYS, OPS, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES, COMPARE_KEYS, SOLVERS, \
    solver_defaults
from cloth.sim import count_edges

from cloth.scene import SCENE_FIELDS

PANEL_FIELDS = [f[0] for f in SCENE_FIELDS]


def caption(k):
    return k.label + (' (' + k.unit + ')' if k.unit else '')


def test_the_page_reads_the_cores_declarations(open_page):
    pg = open_page()
    got = pg.js('''(() => {
      const s = clothCore.schema(), L = clothScenes.LIMITS;
      return {order: s.order, keys: s.keys, limits: L, ops: s.ops, maxActions: s.maxActions,
              maxPanels: s.maxPanels, maxVertices: s.maxVertices, solvers: clothScenes.SOLVERS,
              pageVertices: clothScenes.PAGE_LIMITS.vertices,
              edges: [[1, 1, false], [7, 5, false], [7, 5, true], [200, 3, true]].map(
                (a) => clothCore.edgesOf(a[0], a[1], a[2]))};
    })()''')
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
    assert got['limits']['tear']['off'] and got['limits']['density']['off']
    assert not got['limits']['damping']['off']
    for i, name in enumerate(SOLVERS):
        d = solver_defaults(name)
        assert (got['solvers'][name]['substeps'], got['solvers'][name]['iterations']) == \
            (d['substeps'], d['iterations'])
    k = {k.key: k for k in KEYS}
    assert got['pageVertices'] == k['cols'].field_hi * k['rows'].field_hi
    assert got['edges'] == [count_edges(1, 1, False), count_edges(7, 5, False),
                            count_edges(7, 5, True), count_edges(200, 3, True)]


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
    # Typing past a field's end clamps to the declared end, and says so.
    pg.js('clothApp.setPaused(true)')
    pg.fill('#substeps', '1e9')
    pg.press('#substeps', 'Enter')
    assert pg.js('clothApp.info().params.substeps') == k['substeps'].field_hi
    assert 'Substeps clamped to its maximum %d' % k['substeps'].field_hi in pg.info()['note']
    # Each field is read from and written to its key: typed in, it is what the cloth runs
    # (a point key's field is its y component; a grid key makes a new grid).
    typed = {'iterations': '3', 'substeps': '5', 'gravity': '-4.5', 'damping': '0.5', 'tear': '0.7',
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
    # Every field it offers makes a scene the core takes: a panel with Tear and Density off
    # (null: none) runs, and its scene says so.
    pg.js('clothApp.setPaused(true)')
    pg.locator('#compare-list summary >> nth=1').click()     # panel 2's "more"
    for key in ('tear', 'density'):
        sel = '#compare-list input[data-key=%s] >> nth=1' % key
        pg.fill(sel, 'off')
        pg.press(sel, 'Enter')
        scene = json.loads(pg.js('clothApp.panels()')[1]['scene'])
        assert key in scene and scene[key] is None, (key, scene.get(key))
    pg.js('clothApp.advance(5)')
    assert pg.js('clothApp.info().frames') >= 5


def test_the_menus_are_the_declared_solvers_and_presets(open_page):
    """The Solver menu is cloth/scene.py SOLVERS with their SOLVER_LABELS, and the Preset menu
    and the number keys are webgl/scenes.js PRESETS in order: neither is written in the HTML."""
    from cloth.scene import SOLVER_LABELS, DEFAULT_SOLVER
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
    # Each number key picks its preset; the menu shows it.
    pg.js('clothApp.setPaused(true)')
    for i, (name, _label) in enumerate(got['presets']):
        pg.locator('body').press(str(i + 1))
        assert pg.info()['preset'] == name and pg.input_value('#preset') == name
    # A scene that says its solver shows it in the menu, by the declared name.
    for name in SOLVERS:
        pg.js('(n) => clothApp.loadScene({cols: 3, rows: 3, spacing: 0.1, pins: [0], solver: n})', name)
        assert pg.input_value('#solver') == name
