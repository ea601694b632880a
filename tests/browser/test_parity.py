"""The shipped JS is the tested Python: `clothCore.run` in dist/index.html and `run` in
CPython return the same text, so the same doubles, for every solver, feature and action."""

import json
import math
import shutil
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from cloth.api import run
from cloth.scene import SceneError

from conftest import DIST, ROOT


@pytest.fixture(scope='module')
def core(browser):
    """One page for the whole module: parity runs are pure, so they can share it."""
    context = browser.new_context()
    page = context.new_page()
    page.goto(DIST.as_uri())
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
    for key in ['positions', 'edge_diff', 'node_stress']:
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


def grid(cols, rows, **keys):
    s = dict(cols=cols, rows=rows, spacing=1.0 / max(cols - 1, 1))
    s.update(keys)
    return s


DRAG = [{'frame': 2, 'op': 'grab', 'vertex': 5, 'to': [0.4, -0.3]},
        {'frame': 4, 'op': 'move', 'vertex': 5, 'to': [0.9, 0.2]},
        {'frame': 5, 'op': 'grab', 'vertex': 0},
        {'frame': 6, 'op': 'move', 'vertex': 0, 'to': [-0.3, 0.1]},
        {'frame': 8, 'op': 'release', 'vertex': 0},
        {'frame': 9, 'op': 'release', 'vertex': 5},
        {'frame': 10, 'op': 'unpin', 'vertex': 3},
        {'frame': 10, 'op': 'pin', 'vertex': 9}]

SCENES = {
    'seed-curtain': (grid(10, 10, pins=list(range(10)), solver='jakobsen'), 60),
    'seed-corners-substeps-damping': (
        grid(12, 9, pins=[0, 11], solver='jakobsen', substeps=3, iterations=7, damping=0.7), 40),
    'seed-actions': (grid(4, 4, pins=[0, 3], solver='jakobsen', actions=DRAG), 30),
    'seed-zero-iterations': (grid(5, 5, pins=[2], solver='jakobsen', iterations=0), 20),
    'default-curtain': (grid(16, 12, pins=list(range(16))), 60),
    'default-actions': (grid(4, 4, pins=[0, 3], actions=DRAG), 30),
    'xpbd-compliance-shear': (
        grid(9, 7, pins=[0, 8], solver='xpbd', compliance=1e-3, shear=True,
             gravity=[2.0, -20.0]), 50),
    'xpbd-no-tethers-tolerance': (
        grid(8, 8, pins=[0, 7], solver='xpbd', tethers=False, tolerance=1e-3,
             iterations=6, substeps=2), 50),
    'xpbd-no-pins': (grid(6, 3, solver='xpbd', gravity=[0.5, -3.0], damping=5.0), 30),
    'chain-1x40': (dict(cols=1, rows=40, spacing=0.05, pins=[0], dt=0.01), 80),
    'one-vertex': (dict(cols=1, rows=1, spacing=1.0, gravity=[1.0, -9.81]), 30),
    'large-dt-gravity': (grid(6, 6, pins=[0, 5], dt=0.25, gravity=[0, -981.0]), 20),
    'collapsed-pins': (grid(4, 3, pins=[0, 1], actions=[
        {'frame': 0, 'op': 'grab', 'vertex': 0, 'to': [0.5, 0.5]},
        {'frame': 0, 'op': 'grab', 'vertex': 1, 'to': [0.5, 0.5]}]), 20),
    # Sleeps after a second at rest, is woken by a drag, and rests again.
    'default-sleep-and-wake': (grid(6, 5, pins=list(range(6)), damping=3.0, actions=[
        {'frame': 100, 'op': 'grab', 'vertex': 27, 'to': [0.7, -0.9]},
        {'frame': 110, 'op': 'release', 'vertex': 27}]), 700),
    # Pulled beyond its reach and let go: the release relieves the stretch (solve.relieve).
    'default-overpull-release': (grid(7, 7, pins=[0, 3, 6], actions=[
        {'frame': 30, 'op': 'grab', 'vertex': 45},
        {'frame': 40, 'op': 'move', 'vertex': 45, 'to': [0.9, -1.6]},
        {'frame': 60, 'op': 'release', 'vertex': 45}]), 80),
    # Compare mode's hands: held where they are, moved by a displacement (a pin too).
    'hands-moved-by': (grid(7, 6, pins=[0, 6], actions=[
        {'frame': 5, 'op': 'grab', 'vertex': 38},
        {'frame': 5, 'op': 'grab', 'vertex': 6},
        {'frame': 9, 'op': 'move', 'vertex': 38, 'by': [0.2, -0.35]},
        {'frame': 12, 'op': 'move', 'vertex': 6, 'by': [0.1, 0.05]},
        {'frame': 15, 'op': 'move', 'vertex': 38, 'by': [-0.1, 0.3]},
        {'frame': 20, 'op': 'release', 'vertex': 38},
        {'frame': 21, 'op': 'release', 'vertex': 6}]), 40),
    'teleport': (grid(5, 5, pins=[0, 4], actions=[
        {'frame': 1, 'op': 'grab', 'vertex': 22, 'to': [100.0, -100.0]},
        {'frame': 2, 'op': 'release', 'vertex': 22}]), 40),
    # Settings changed on the running cloth (what the page records when a person changes
    # them), and a recording's own `frames` (run with frames None).
    'set-settings-mid-run': (grid(8, 6, pins=[0, 7], actions=DRAG + [
        {'frame': 3, 'op': 'set', 'scene': {'substeps': 3, 'damping': 2}},
        {'frame': 7, 'op': 'set', 'scene': {'solver': 'jakobsen'}},
        {'frame': 9, 'op': 'set', 'scene': {'gravity': [1, -4], 'iterations': 5}},
        {'frame': 12, 'op': 'set', 'scene': {'solver': 'xpbd', 'dt': 0.02, 'compliance': 1e-4}}]), 30),
    # The air (issue #24): a steady wind on a compliant curtain, gusts on a free cloth with a
    # hand and a cut, and the wind set live and taken away again.
    'wind-steady': (grid(8, 6, pins=list(range(8)), density=0.2, compliance=0.002, wind=[6.0, 0.5],
                         drag=0.3), 90),
    'wind-gusts-hand-cut': (grid(7, 7, pins=[0, 6], wind=[-3.0, 2.0], drag=2.5, gust=[0.8, 0.37],
                                 shear=True, actions=[
        {'frame': 10, 'op': 'grab', 'vertex': 45},
        {'frame': 14, 'op': 'move', 'vertex': 45, 'to': [0.4, -1.2]},
        {'frame': 20, 'op': 'cut', 'from': [0.1, -0.3], 'to': [0.9, -0.35]},
        {'frame': 30, 'op': 'release', 'vertex': 45}]), 80),
    'wind-set-live': (grid(6, 5, pins=[0, 5], solver='jakobsen', actions=[
        {'frame': 5, 'op': 'set', 'scene': {'wind': [8, 0], 'drag': 1.0}},
        {'frame': 25, 'op': 'set', 'scene': {'gust': [1.5, 0.5], 'solver': 'xpbd'}},
        {'frame': 45, 'op': 'set', 'scene': {'wind': [0, 0]}}]), 70),
    # Obstacles (issue #24): a cloth dropped on a peg and a box with friction; a box swept 1 m
    # through a hanging curtain in one frame and back; the seed's method over a circle in wind,
    # with a cut and a hand.
    'obstacles-drop': (grid(8, 8, pins=[], damping=1, obstacles=[
        {'circle': [0.7, -2.0, 0.3], 'friction': 0.4}, {'box': [-0.2, -2.6, 0.4, -2.3]}]), 120),
    'obstacles-swept-box': (grid(8, 6, pins=list(range(8)), shear=True, obstacles=[
        {'box': [-0.8, -0.9, -0.5, -0.3], 'friction': 1.0}], actions=[
        {'frame': 20, 'op': 'obstacle', 'index': 0, 'to': [0.35, -0.6]},
        {'frame': 21, 'op': 'obstacle', 'index': 0, 'to': [1.95, -0.6]},
        {'frame': 50, 'op': 'obstacle', 'index': 0, 'to': [-0.65, -0.6]}]), 80),
    'obstacles-seed-wind-cut': (grid(9, 7, pins=[0, 8], solver='jakobsen', wind=[4, 1], drag=0.5,
                                     tear=0.4, obstacles=[{'circle': [0.8, -1.0, 0.25], 'friction': 0.2}],
                                     actions=[
        {'frame': 10, 'op': 'grab', 'vertex': 58},
        {'frame': 12, 'op': 'move', 'vertex': 58, 'to': [0.8, -0.6]},
        {'frame': 20, 'op': 'cut', 'from': [0.1, -0.5], 'to': [0.5, -0.55]},
        {'frame': 30, 'op': 'release', 'vertex': 58},
        {'frame': 35, 'op': 'set', 'scene': {'solver': 'xpbd'}}]), 70),
    'recording-frames-key': (grid(6, 5, pins=[0, 5], frames=33, actions=[
        {'frame': 33, 'op': 'grab', 'vertex': 20, 'to': [0.1, 0.2]}]), None),
    # Tearing past a limit while pulled far beyond reach, and blades through the cloth (a piece
    # cut off falls free; the tethers, cells and lines work on what remains).
    'tear-pulled-beyond-reach': (grid(10, 8, pins=[0, 3, 6, 9], tear=0.25, actions=[
        {'frame': 10, 'op': 'grab', 'vertex': 75},
        {'frame': 11, 'op': 'move', 'vertex': 75, 'to': [0.6, -4.0]},
        {'frame': 50, 'op': 'release', 'vertex': 75}]), 90),
    'cuts-and-falling-pieces': (grid(9, 9, pins=[0, 4, 8], shear=True, actions=[
        {'frame': 20, 'op': 'cut', 'from': [-0.2, -0.43], 'to': [1.2, -0.47]},
        {'frame': 25, 'op': 'cut', 'from': [0.55, 0.2], 'to': [0.55, -1.5]},
        {'frame': 30, 'op': 'grab', 'vertex': 40},
        {'frame': 31, 'op': 'cut', 'from': [0.3, -0.6], 'to': [0.7, -0.2]},
        {'frame': 40, 'op': 'release', 'vertex': 40}]), 80),
    'seed-tear-and-cut': (grid(8, 8, pins=[0, 7], solver='jakobsen', tear=0.05, actions=[
        {'frame': 15, 'op': 'cut', 'from': [0.2, 0.1], 'to': [0.25, -1.2]}]), 60),
    # Every edge cut, the pinned pair 0-1 apart too: a dust of particles, each in free fall
    # (the curtain hangs at its rest grid, so blades between the rows and columns cut it all).
    'cut-every-edge': (grid(6, 6, pins=[0, 1, 2, 3, 4, 5], actions=[
        {'frame': 60, 'op': 'cut', 'from': [(c + 0.5) * 0.2, 0.5], 'to': [(c + 0.5) * 0.2, -1.5]}
        for c in range(5)] + [
        {'frame': 60, 'op': 'cut', 'from': [-0.5, -(r + 0.5) * 0.2], 'to': [1.5, -(r + 0.5) * 0.2]}
        for r in range(5)]), 100),
}


def test_cut_every_edge_leaves_a_dust_in_free_fall(core):
    scene, frames = SCENES['cut-every-edge']
    out = json.loads(core(json.dumps(scene), frames)['ok'])
    assert out['edges'] == [] and all(q == 0 for q in out['node_stress'])
    assert out['positions'][1] == [0.2, 0]              # the pinned pair, cut apart, stays


@pytest.mark.parametrize('name', sorted(SCENES))
def test_bit_identical_results(core, name):
    scene, frames = SCENES[name]
    text = json.dumps(scene)
    js = core(text, frames)
    assert 'ok' in js, js
    assert_identical(run(text, frames), js['ok'])


def test_larger_grid_many_frames(core):
    text = json.dumps(grid(40, 30, pins=[0, 13, 26, 39]))
    assert_identical(run(text, 20), core(text, 20)['ok'])


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
    s = {'cols': cols, 'rows': rows, 'spacing': draw(st.sampled_from([0.05, 0.1, 0.25, 1.0])),
         'pins': draw(st.lists(vertex, max_size=3))}
    if draw(st.booleans()):
        s['solver'] = draw(st.sampled_from(['jakobsen', 'xpbd']))
    for key, strategy in [('substeps', st.integers(1, 4)), ('iterations', st.integers(0, 8)),
                          ('damping', st.floats(0, 3)), ('tethers', st.booleans()),
                          ('shear', st.booleans()), ('compliance', st.sampled_from([0, 1e-4, 0.01])),
                          ('tolerance', st.sampled_from([0, 1e-3])), ('sleep', st.booleans()),
                          ('dt', st.sampled_from([1 / 60, 0.25])),
                          ('tear', st.sampled_from([0.01, 0.1, 0.5, 2.0])),
                          ('gravity', st.tuples(coord, st.floats(-30, 30)).map(list)),
                          ('wind', st.tuples(st.floats(-40, 40), st.floats(-40, 40)).map(list)),
                          ('drag', st.sampled_from([0, 0.05, 1.0, 50.0])),
                          ('gust', st.tuples(st.floats(0, 3), st.floats(0.01, 2)).map(list))]:
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
                                  ('solver', st.sampled_from(['jakobsen', 'xpbd'])),
                                  ('damping', st.floats(0, 3)), ('tethers', st.booleans()),
                                  ('gravity', st.tuples(coord, coord).map(list)),
                                  ('wind', st.tuples(coord, coord).map(list)),
                                  ('drag', st.floats(0, 5))]:
                if draw(st.booleans()):
                    keys[key] = draw(strategy)
            actions.append({'frame': frame, 'op': 'set', 'scene': keys})
            continue
        k = draw(vertex)
        if op in ('move', 'release') and held:
            k = draw(st.sampled_from(sorted(held)))
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
