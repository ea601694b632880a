"""Issue #21 in the page: the Material menu, the fabrics of cloth/fabrics.py (recorded as a `set`
of their stretch, shear and density, replayed by the CLI), strain colours that are the fabric's
exact field at rest (cloth/reference.py), and a release that flings nothing, through real
pointer input. The core's side: tests/test_release.py and tests/test_physics.py; every fabric's
convergence: `python -m bench --fabrics`."""
import json
import math
import subprocess
import sys

import numpy as np
import pytest

from browser_helpers import ROOT, WATCH, free_vertex

from cloth.fabrics import FABRICS, DEFAULT_FABRIC
from cloth.keys import MODEL
from cloth.reference import exact_rest, tension_strain, away_from_fixed, field_error
from cloth.sleep import SLEEP_IMBALANCE

COLS, ROWS = 40, 30      # the Curtain preset
FABRIC = {f[0]: f for f in FABRICS}


def cli_positions(text):
    done = subprocess.run([sys.executable, '-m', 'cloth', 'run', '-'], cwd=ROOT,
                          input=text.encode(), capture_output=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)['positions']


def fabric_keys(name):
    f = FABRIC[name]
    return {'stretch': f[2], 'shear': f[3], 'density': f[4]}


def test_the_material_menu_lists_the_cores_fabrics_and_records_a_set(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    fabrics = pg.js('clothCore.fabrics()')
    assert fabrics == {'list': FABRICS, 'preset': DEFAULT_FABRIC}
    options = pg.js("Array.from(document.querySelectorAll('#material option')).map(o => [o.value, o.textContent, o.disabled])")
    assert [o[:2] for o in options] == [[f[0], f[1]] for f in FABRICS] + [['custom', 'Custom (scene)']]
    assert options[-1][2] and not any(d for _, _, d in options[:-1])
    assert pg.locator('#material').input_value() == fabrics['preset'] == 'jersey'
    # the help names each with its stretch, shear and density
    rows = pg.js("Array.from(document.querySelectorAll('#help-materials tr')).map(r => r.textContent)")
    assert len(rows) == len(FABRICS)
    for row, f in zip(rows, FABRICS):
        assert row.startswith(f[1]) and 'stretch %g N/m, shear %g N/m, %g kg/m\u00b2' % tuple(f[2:5]) in row, row
    scene = pg.js('JSON.parse(clothApp.info().scene)')
    assert {k: scene[k] for k in ('stretch', 'shear', 'density')} == fabric_keys('jersey')
    pg.js('clothApp.advance(20)')
    at = pg.info()['frames']
    pg.select_option('#material', 'spandex')
    running = pg.js('clothApp.cloth().scene')
    assert {k: running[k] for k in ('stretch', 'shear', 'density')} == fabric_keys('spandex')
    pg.js('clothApp.advance(20)')
    rec = json.loads(pg.js('clothApp.recording()'))
    assert [a for a in rec['actions'] if a['op'] == 'set'] == [
        {'frame': at, 'op': 'set', 'scene': fabric_keys('spandex')}]
    assert cli_positions(json.dumps(rec)) == pg.state()['positions']
    # a fabric of the scene's own shows as Custom, and the menu takes it back to a named one
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'model': MODEL, 'cols': 5, 'rows': 5, 'spacing': 0.1,
                                                       'pins': [0, 4], 'stretch': 1234}))
    assert pg.locator('#material').input_value() == 'custom'
    pg.select_option('#material', 'cotton')
    running = pg.js('clothApp.cloth().scene')
    assert {k: running[k] for k in ('stretch', 'shear', 'density')} == fabric_keys('cotton')
    assert pg.locator('#material').input_value() == 'cotton'
    # A scene made before the membrane has a `shear` of its own (a boolean the core leaves
    # out): a fabric picked for it sets its stretch and density, and its shear stiffness stays
    # the default fabric's; no error, and the menu says the fabric is now the scene's own.
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'cols': 5, 'rows': 5, 'spacing': 0.1, 'pins': [0, 4],
                                                       'shear': True}))
    pg.select_option('#material', 'cotton')
    running = pg.js('clothApp.cloth().scene')
    assert pg.info()['error'] == '', pg.info()['error']
    assert (running['stretch'], running['density']) == (FABRIC['cotton'][2], FABRIC['cotton'][4])
    assert running['shear'] == FABRIC[DEFAULT_FABRIC][3]
    assert pg.locator('#material').input_value() == 'custom'


def test_the_page_says_when_the_solver_leaves_the_material_unused(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    unused = 'change nothing under it'       # cloth/scene.py unused_settings
    pg.select_option('#solver', 'jakobsen')
    assert unused in pg.info()['note'], pg.info()['note']
    pg.select_option('#material', 'spandex')            # a fabric picked under it: said again
    assert unused in pg.info()['note']
    pg.select_option('#solver', 'xpbd')
    assert unused not in pg.info()['note']
    pg.select_option('#material', 'cotton')
    assert unused not in pg.info()['note']


def test_at_rest_the_colours_are_the_curtains_exact_strain(open_page):
    # The Curtain hangs from a rod in jersey: its exact statics (Newton on the same energy,
    # cloth/reference.py) put the rod's strain at density g height / stretch, 0.57%, and 0 at
    # the hem. At rest (asleep: its forces balanced within SLEEP_IMBALANCE of its weight) the
    # page's strain field is that one (measured: within 0.1% of it).
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    # at rest within 20 s, the fabrics' target (the 40x30 curtain: 5.6 s, measured)
    for _ in range(20):
        pg.js('clothApp.advance(60)')
        if pg.info()['asleep']:
            break
    assert pg.info()['asleep'] and pg.js('clothApp.cloth().imbalance') <= SLEEP_IMBALANCE
    text = pg.info()['scene']
    cloth, x, info = exact_rest(text)
    exact = tension_strain(cloth, x)
    assert info['residual'] < 1e-9 and 0.004 < exact.max() < 0.008
    got = np.array(pg.js('Array.from(clothApp.cloth().edge_value)'))
    pos = np.array(pg.state()['positions'])
    assert np.array_equal(got, tension_strain(cloth, pos))       # the colours' values are the strain
    err = field_error(got, exact, away_from_fixed(cloth, pos, 0.0))
    assert err < 0.02, err
    # Auto scales to that field: its top is the value 99% of the edges are at or below, above
    # the floor, and the rod's row is drawn brighter than the hem's.
    info = pg.info()
    assert info['scaleMode'] == 'auto' and info['scale'] > info['autoFloor']
    assert info['scale'] == pg.js('clothApp.cloth().high_value')
    st = pg.state()
    k_top, k_hem = COLS // 2, (ROWS - 2) * COLS + COLS // 2
    mid = lambda k: [(st['screen'][k][i] + st['screen'][k + COLS][i]) / 2 for i in (0, 1)]
    top_px, hem_px = pg.js('(p) => clothApp.pixels(p)', [mid(k_top), mid(k_hem)])
    assert top_px[0] > hem_px[0] + 60, (top_px, hem_px)


# The presets' fabric and the stiffest one (measured in CPython: the fastest vertex 4.7 m/s in
# jersey, 0.7-1.0 m/s in denim, in the first frames after the release; spandex, the stretchiest,
# snaps back at 7-9 m/s, as an elastic band does, and is left out).
@pytest.mark.parametrize('preset, material', [('curtain', 'jersey'), ('curtain', 'denim'),
                                              ('corners', 'denim')])
def test_a_pull_beyond_reach_let_go_flings_nothing(open_page, preset, material):
    pg = open_page()
    pg.js('(p) => clothApp.usePreset(p)', preset)
    pg.select_option('#material', material)
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(240)')
    st = pg.state()
    cols = pg.info()['params']['cols']
    rows = pg.info()['params']['rows']
    k = free_vertex(st, cols, rows)
    x, y = st['screen'][k]
    # screen pixels per metre (the view is a uniform scale): from two vertices
    span = math.dist(st['screen'][k], st['screen'][0]) / math.dist(st['positions'][k], st['positions'][0])
    # 0.5 m down and aside, far past the cloth's reach, over 40 frames; held half a second
    pg.mouse.move(x, y)
    pg.mouse.down()
    for f in range(1, 41):
        pg.mouse.move(x + 0.3 * span * f / 40, y + 0.4 * span * f / 40)
        pg.js('clothApp.advance(1)')
    pg.js('clothApp.advance(30)')
    pins = [p[1] for p, pinned in zip(pg.state()['positions'], st['pinned']) if pinned]
    pg.mouse.up()
    seen = pg.js(WATCH, 60)
    fastest, top = max(seen['fastest'][:3]), seen['top']
    assert fastest < 5.0, fastest
    assert top < max(pins) + 1e-3, (top, max(pins))
