"""Issue #21 in the page: the Material menu (recorded as a `set`, replayed by the CLI), strain
colours that are the material's field at rest, and a release that flings nothing, through
real pointer input. The core's side: tests/test_release.py and tests/test_physics.py; the
presets and sizes of the benchmark: `python -m bench --physics`."""
import json
import math
import subprocess
import sys

import pytest

from browser_helpers import ROOT, free_vertex

COLS, ROWS = 40, 30      # the Curtain preset


def cli_positions(text):
    done = subprocess.run([sys.executable, '-m', 'cloth', 'run', '-'], cwd=ROOT,
                          input=text.encode(), capture_output=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)['positions']


def test_the_material_menu_lists_the_cores_fabrics_and_records_a_set(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    fabrics = pg.js('clothCore.materials()')
    options = pg.js("Array.from(document.querySelectorAll('#material option')).map(o => [o.value, o.disabled])")
    assert [o[0] for o in options] == [m[0] for m in fabrics['list']] + ['custom']
    assert options[-1][1] and not any(d for _, d in options[:-1])
    assert pg.locator('#material').input_value() == fabrics['preset'] == 'jersey'
    # the help names each with its density and stiffness
    rows = pg.js("Array.from(document.querySelectorAll('#help-materials tr')).map(r => r.textContent)")
    assert len(rows) == len(fabrics['list']) and any('500 N/m' in r for r in rows)
    scene = pg.js('JSON.parse(clothApp.info().scene)')
    assert scene['density'] == 0.2 and scene['compliance'] == 1 / 500
    pg.js('clothApp.advance(20)')
    at = pg.info()['frames']
    pg.select_option('#material', 'spandex')
    assert pg.js('clothApp.cloth().scene.compliance') == 1 / 100
    pg.js('clothApp.advance(20)')
    rec = json.loads(pg.js('clothApp.recording()'))
    assert [a for a in rec['actions'] if a['op'] == 'set'] == [
        {'frame': at, 'op': 'set', 'scene': {'density': 0.2, 'compliance': 0.01}}]
    assert cli_positions(json.dumps(rec)) == pg.state()['positions']
    # a scene of its own (no density) shows as Custom, and the menu takes it back to a fabric
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'cols': 5, 'rows': 5, 'spacing': 0.1, 'pins': [0, 4]}))
    assert pg.locator('#material').input_value() == 'custom'
    pg.select_option('#material', 'cotton')
    assert pg.js('clothApp.cloth().scene.density') == 0.15


def test_the_page_says_when_the_solver_leaves_the_material_unused(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.select_option('#solver', 'jakobsen')
    assert 'a material has no effect under it' in pg.info()['note'], pg.info()['note']
    pg.select_option('#material', 'spandex')            # a fabric picked under it: said again
    assert 'a material has no effect under it' in pg.info()['note']
    pg.select_option('#solver', 'xpbd')
    assert 'no effect' not in pg.info()['note']
    pg.select_option('#material', 'cotton')
    assert 'no effect' not in pg.info()['note']


def test_at_rest_the_colours_are_the_curtains_exact_strain(open_page):
    # The Curtain hangs from a rod in jersey: the link below row r carries the rows under it,
    # strain (rows - 1 - r) m g compliance / spacing, from 0 at the hem to 0.58% at the rod.
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(600)')
    scene = pg.js('JSON.parse(clothApp.info().scene)')
    pos = pg.state()['positions']
    h, m = scene['spacing'], scene['density'] * scene['spacing'] ** 2
    got, want = [], []
    for r in range(ROWS - 1):
        for c in range(COLS):
            a, b = pos[r * COLS + c], pos[(r + 1) * COLS + c]
            got.append(math.dist(a, b) / h - 1)
            want.append((ROWS - 1 - r) * m * 9.81 * scene['compliance'] / h)
    top = max(want)
    assert 0.003 < top < 0.01
    err = math.sqrt(sum((x - y) ** 2 for x, y in zip(got, want)) / len(got)) / top
    assert err < 0.1, err
    # Auto scales to that field: its top is the frame's largest |diff|, above the floor, and
    # the rod's row is drawn brighter than the hem's.
    info = pg.info()
    assert info['scaleMode'] == 'auto' and info['scale'] > info['autoFloor']
    st = pg.state()
    k_top, k_hem = COLS // 2, (ROWS - 2) * COLS + COLS // 2
    mid = lambda k: [(st['screen'][k][i] + st['screen'][k + COLS][i]) / 2 for i in (0, 1)]
    top_px, hem_px = pg.js('(p) => clothApp.pixels(p)', [mid(k_top), mid(k_hem)])
    assert top_px[0] > hem_px[0] + 60, (top_px, hem_px)


@pytest.mark.parametrize('preset, material', [('curtain', 'jersey'), ('curtain', 'inextensible'),
                                              ('corners', 'inextensible')])
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
    fastest, top = 0.0, -1e9
    before = pg.state()['positions']
    for f in range(60):
        pg.js('clothApp.advance(1)')
        now = pg.state()['positions']
        if f < 3:
            fastest = max(fastest, max(math.dist(a, b) for a, b in zip(before, now)) * 60)
        top = max(top, max(p[1] for p in now))
        before = now
    assert fastest < 5.0, fastest
    assert top < max(pins) + 1e-3, (top, max(pins))
