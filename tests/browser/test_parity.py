"""The shipped JS is the tested Python: `clothCore.run` in dist/index.html and `run` in
CPython return the same text, so the same doubles, for every scene of the catalogue
(tests/catalogue.py: every solver, fabric, feature and action, every preset, the hard cases,
on the current model, cloth/keys.py MODEL, and on scenes made before it, model 1, run as a
membrane: the legacy mapping must be the same in both runtimes too). Firefox and WebKit run
the same catalogue (tests/browser/engines/test_engines.py)."""

import json
import math
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from cloth.api import run
from cloth.fabrics import FABRICS
from cloth.keys import MODEL
from cloth.scene import SceneError
from cloth.keys import SOLVERS, DEFAULT_SOLVER

from catalogue import CATALOGUE
from conftest import ROOT
from browser_helpers import page_url


@pytest.fixture(scope='module')
def core(browser):
    """One page for the whole module: parity runs are pure, so they can share it."""
    context = browser.new_context()
    page = context.new_page()
    page.goto(page_url())
    page.wait_for_function('() => !!(window.clothCore && window.clothApp)')
    page.evaluate('clothApp.setPaused(true)')

    def js_run(text, frames):
        return page.evaluate(
            '([t, f]) => { try { return {ok: clothCore.run(t, f)} }'
            ' catch (e) { return {error: e instanceof Error ? e.message : String(e)} } }',
            [text, frames])
    yield js_run
    context.close()


def assert_identical(py_text, js_text):
    """The two runtimes print the same characters (cloth/host.py writes numbers as JS does).
    On a difference, say where it is: in the doubles, or only in how they were written."""
    if py_text == js_text:
        return
    py, js = json.loads(py_text), json.loads(js_text)
    assert py.keys() == js.keys()
    assert py['frames'] == js['frames']
    assert py['edges'] == js['edges']
    for key in ['positions', 'edge_value', 'node_stress']:
        a = flatten(py[key])
        b = flatten(js[key])
        assert len(a) == len(b), key
        for i, (x, y) in enumerate(zip(a, b)):
            assert math.isfinite(x) and float(x) == float(y), (key, i, x, y)
    assert py_text == js_text, 'the same numbers, written differently'


def flatten(values):
    out = []
    for v in values:
        if isinstance(v, list):
            out.extend(flatten(v))
        else:
            out.append(v)
    return out


def test_cut_every_edge_leaves_a_dust_in_free_fall(core):
    scene, frames = CATALOGUE['cut-every-edge']
    out = json.loads(core(json.dumps(scene), frames)['ok'])
    assert out['edges'] == [] and all(q == 0 for q in out['node_stress'])
    assert out['positions'][1] == [0.2, 0]              # the pinned pair, cut apart, stays


@pytest.mark.parametrize('name', sorted(CATALOGUE))
def test_bit_identical_results(core, cli_run, name):
    scene, frames = CATALOGUE[name]
    text = json.dumps(scene)
    js = core(text, frames)
    assert 'ok' in js, js
    assert_identical(cli_run(text, frames), js['ok'])


def test_the_scenes_cover_every_solver_fabric_and_model():
    """The catalogue is no proof for a solver, a fabric or a model it leaves out."""
    current = [s for s, _ in CATALOGUE.values() if s.get('model') == MODEL]
    assert {s.get('solver', DEFAULT_SOLVER) for s in current} == set(SOLVERS)
    assert {(s.get('stretch'), s.get('shear'), s.get('density')) for s in current} >= \
        {tuple(f[2:5]) for f in FABRICS}
    assert any('model' not in s for s, _ in CATALOGUE.values())


@pytest.mark.parametrize('text,frames', [
    ('{"cols": 3', 1), ('[]', 1), ('{"cols": 2, "rows": 2, "spacing": 0}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "pins": [9]}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "solver": "magic"}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1}', -1),
    ('{"cols": 2, "rows": 2, "spacing": 1}', None),
    ('{"cols": 2, "rows": 2, "spacing": 1, "dt": 1e-300}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "a\\nb": 1}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "\\ud800\\ud83d\\ude00": 1}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "actions": [{"frame": 0, "op": "set", "scene": {"rows": 3}}]}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "frames": 2.5}', None),
    ('{"cols": 2, "rows": 2, "spacing": 1, "tear": 0}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "tear": "0.3"}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "actions": [{"frame": 0, "op": "cut", "from": [0, 0]}]}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "actions": [{"frame": 0, "op": "cut", "vertex": 1, "from": [0, 0], "to": [1, 1]}]}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "compare": [{}]}', 1),
    ('{"cols": 2, "rows": 2, "spacing": 1, "compare": [{}, {"rows": 3}]}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1, "shear": true}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1, "tethers": false}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1, "stretch": 0.5}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1e-4, "density": 1e-5}', 1),
    ('{"model": 3, "cols": 2, "rows": 2, "spacing": 1}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1, "solver": "vbd", "corrections": 101}', 1),
    ('{"model": 2, "cols": 2, "rows": 2, "spacing": 1, "actions": [{"frame": 0, "op": "set", "scene": {"compliance": 1}}]}', 1),
])
def test_same_error_message_in_both_runtimes(core, text, frames):
    with pytest.raises(SceneError) as err:
        run(text, frames)
    assert core(text, frames) == {'error': str(err.value)}


# ---- property-based: random small scenes and action sequences -------------------------------

@st.composite
def scenes(draw):
    cols = draw(st.integers(1, 6))
    rows = draw(st.integers(1, 6))
    n = cols * rows
    vertex = st.integers(0, n - 1)
    coord = st.floats(-3, 3, allow_nan=False, width=64)
    s = {'model': MODEL, 'cols': cols, 'rows': rows,
         'spacing': draw(st.sampled_from([0.05, 0.1, 0.25, 1.0])),
         'pins': draw(st.lists(vertex, max_size=3))}
    if draw(st.booleans()):
        s['solver'] = draw(st.sampled_from(SOLVERS))
    fabric = [('stretch', st.sampled_from([1.0, 10.0, 150.0, 500.0, 1e4, 1e6])),
              ('shear', st.sampled_from([0.0, 1.0, 50.0, 170.0, 1e4])),
              ('density', st.sampled_from([0.05, 0.2, 2.0]))]
    for key, strategy in [('substeps', st.integers(1, 4)), ('iterations', st.integers(0, 8)),
                          ('corrections', st.integers(0, 3)), ('damping', st.floats(0, 3)),
                          ('sleep', st.booleans()), ('dt', st.sampled_from([1 / 60, 0.25])),
                          ('strength', st.sampled_from([5.0, 50.0, 250.0, 1000.0])),
                          ('gravity', st.tuples(coord, st.floats(-30, 30)).map(list)),
                          ('wind', st.tuples(st.floats(-40, 40), st.floats(-40, 40)).map(list)),
                          ('drag', st.sampled_from([0, 0.05, 1.0, 50.0])),
                          ('gust', st.tuples(st.floats(0, 3), st.floats(0.01, 2)).map(list))] + fabric:
        if draw(st.booleans()):
            s[key] = draw(strategy)
    size = st.floats(0.01, 2, allow_nan=False, width=64)
    obstacles = []
    for _ in range(draw(st.integers(0, 3))):
        if draw(st.booleans()):
            o = {'circle': [draw(coord), draw(coord), draw(size)]}
        else:
            x0, y0 = draw(coord), draw(coord)
            o = {'box': [x0, y0, x0 + draw(size), y0 + draw(size)]}
        if draw(st.booleans()):
            o['friction'] = draw(st.floats(0, 1))
        obstacles.append(o)
    if obstacles:
        s['obstacles'] = obstacles
    actions, held = [], set()
    for _ in range(draw(st.integers(0, 8))):
        frame = draw(st.integers(0, 12))
        op = draw(st.sampled_from(['grab', 'move', 'release', 'pin', 'unpin', 'set', 'cut', 'obstacle']))
        if op == 'obstacle':
            if obstacles:
                actions.append({'frame': frame, 'op': 'obstacle', 'index': draw(st.integers(0, len(obstacles) - 1)),
                                'to': [draw(coord), draw(coord)]})
            continue
        if op == 'cut':
            actions.append({'frame': frame, 'op': 'cut', 'from': [draw(coord), draw(coord)],
                            'to': [draw(coord), draw(coord)]})
            continue
        if op == 'set':
            keys = {}
            for key, strategy in [('substeps', st.integers(1, 4)), ('iterations', st.integers(0, 8)),
                                  ('corrections', st.integers(0, 3)),
                                  ('solver', st.sampled_from(SOLVERS)),
                                  ('damping', st.floats(0, 3)),
                                  ('gravity', st.tuples(coord, coord).map(list)),
                                  ('wind', st.tuples(coord, coord).map(list)),
                                  ('drag', st.floats(0, 5))] + fabric:
                if draw(st.booleans()):
                    keys[key] = draw(strategy)
            actions.append({'frame': frame, 'op': 'set', 'scene': keys})
            continue
        k = draw(vertex)
        if op in ('move', 'release') and held:
            k = draw(st.sampled_from(sorted(held)))
        if op == 'grab':
            held.add(k)
        a = {'frame': frame, 'op': op, 'vertex': k}
        if op == 'move' and draw(st.booleans()):
            a['by'] = [draw(coord), draw(coord)]   # compare mode's form: from where it took hold
        elif op == 'move' or (op == 'grab' and draw(st.booleans())):
            a['to'] = [draw(coord), draw(coord)]
        actions.append(a)
    s['actions'] = actions
    return s


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(scene=scenes(), frames=st.one_of(st.integers(0, 15), st.none()))
def test_random_scenes_are_bit_identical(core, scene, frames):
    if frames is None:
        scene['frames'] = 9          # a recording runs its own frames
    text = json.dumps(scene)
    try:
        py = run(text, frames)
    except SceneError as err:       # e.g. a random move of a vertex nobody holds
        assert core(text, frames) == {'error': str(err)}
        return
    js = core(text, frames)
    assert 'ok' in js, js
    assert_identical(py, js['ok'])


# ---- the shipped dist/ is reproducible from a clean clone ----------------------------------

def test_clean_clone_rebuilds_byte_identical_dist(tmp_path):
    if not (ROOT / '.git').exists():
        pytest.fail('not a git checkout: cannot make a clean clone')
    clone = tmp_path / 'clone'
    subprocess.run(['git', 'clone', '-q', str(ROOT), str(clone)], check=True, timeout=120)
    committed = (clone / 'dist' / 'index.html').read_bytes()
    subprocess.run([sys.executable, 'build.py'], cwd=clone, check=True, timeout=300,
                   capture_output=True)
    assert (clone / 'dist' / 'index.html').read_bytes() == committed
