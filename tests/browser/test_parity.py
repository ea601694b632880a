"""The shipped JS is the tested Python: `clothCore.run` in dist/index.html and `run` in
CPython return the same text, so the same doubles, for every solver, fabric, feature and
action, on the current model (cloth/keys.py MODEL) and on scenes made before it (model 1, run
as a membrane: the legacy mapping must be the same in both runtimes too)."""

import json
import math
import shutil
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from cloth.api import run
from cloth.fabrics import FABRICS
from cloth.keys import MODEL
from cloth.presets import PRESETS, preset_scene
from cloth.scene import SceneError
from cloth.solvers import SOLVERS, DEFAULT_SOLVER

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


def grid(cols, rows, **keys):
    """A scene of the current model, 1 m wide."""
    s = dict(model=MODEL, cols=cols, rows=rows, spacing=1.0 / max(cols - 1, 1))
    s.update(keys)
    return s


def legacy(cols, rows, **keys):
    """A scene made before the membrane (no `model` key): model 1."""
    s = grid(cols, rows, **keys)
    del s['model']
    return s


DRAG = [{'frame': 2, 'op': 'grab', 'vertex': 5, 'to': [0.4, -0.3]},
        {'frame': 4, 'op': 'move', 'vertex': 5, 'to': [0.9, 0.2]},
        {'frame': 5, 'op': 'grab', 'vertex': 0},
        {'frame': 6, 'op': 'move', 'vertex': 0, 'to': [-0.3, 0.1]},
        {'frame': 8, 'op': 'release', 'vertex': 0},
        {'frame': 9, 'op': 'release', 'vertex': 5},
        {'frame': 10, 'op': 'unpin', 'vertex': 3},
        {'frame': 10, 'op': 'pin', 'vertex': 9}]

# Pulled far beyond reach and let go: a hand's capped pull (cloth/hands.py), whose step the
# default solver stops short of the aim (cloth/vbd.py sweep), then the release.
OVERPULL = [{'frame': 30, 'op': 'grab', 'vertex': 45},
            {'frame': 40, 'op': 'move', 'vertex': 45, 'to': [0.9, -1.6]},
            {'frame': 60, 'op': 'release', 'vertex': 45}]

SCENES = {
    # Every solver on a curtain, with a script of hands and pins, and at its extremes of steps.
    'seed-curtain': (grid(10, 10, pins=list(range(10)), solver='jakobsen'), 60),
    'seed-corners-substeps-damping': (
        grid(12, 9, pins=[0, 11], solver='jakobsen', substeps=3, iterations=7, damping=0.7), 40),
    'seed-actions': (grid(4, 4, pins=[0, 3], solver='jakobsen', actions=DRAG), 30),
    'seed-zero-iterations': (grid(5, 5, pins=[2], solver='jakobsen', iterations=0), 20),
    'default-curtain': (grid(16, 12, pins=list(range(16))), 60),
    'default-actions': (grid(4, 4, pins=[0, 3], actions=DRAG), 30),
    'default-zero-iterations': (grid(6, 6, pins=[0, 5], iterations=0), 20),
    'default-no-correction-substeps': (grid(9, 7, pins=[0, 8], iterations=3, corrections=0, substeps=2), 40),
    'default-three-corrections': (grid(12, 10, pins=[0, 11], iterations=4, corrections=3), 40),
    'xpbd-curtain': (grid(10, 8, pins=list(range(10)), solver='xpbd'), 40),
    'xpbd-actions': (grid(4, 4, pins=[0, 3], solver='xpbd', actions=DRAG), 30),
    'xpbd-one-substep-gravity': (grid(9, 7, pins=[0, 8], solver='xpbd', substeps=1, iterations=3,
                                      gravity=[2.0, -20.0]), 50),
    'xpbd-no-pins': (grid(6, 3, solver='xpbd', gravity=[0.5, -3.0], damping=5.0), 30),
    # Fabrics of a scene's own beside the named ones (below): soft without shear, and stiffest.
    'spandex-xpbd': (grid(8, 8, pins=[0, 7], solver='xpbd', stretch=150.0, shear=30.0, density=0.2), 60),
    'soft-no-shear': (grid(8, 8, pins=[0, 7], stretch=10.0, shear=0.0, density=1.0), 60),
    'stiffest': (grid(8, 8, pins=[0, 7], stretch=1e6, shear=1e6, density=0.1), 60),
    'chain-1x40': (dict(model=MODEL, cols=1, rows=40, spacing=0.05, pins=[0], dt=0.01), 80),
    'one-vertex': (dict(model=MODEL, cols=1, rows=1, spacing=1.0, gravity=[1.0, -9.81]), 30),
    'large-dt-gravity': (grid(6, 6, pins=[0, 5], dt=0.25, gravity=[0, -981.0]), 20),
    'collapsed-pins': (grid(4, 3, pins=[0, 1], actions=[
        {'frame': 0, 'op': 'grab', 'vertex': 0, 'to': [0.5, 0.5]},
        {'frame': 0, 'op': 'grab', 'vertex': 1, 'to': [0.5, 0.5]}]), 20),
    # Sleeps after a second at rest, is woken by a drag, and rests again.
    'default-sleep-and-wake': (grid(6, 5, pins=list(range(6)), damping=3.0, actions=[
        {'frame': 100, 'op': 'grab', 'vertex': 27, 'to': [0.7, -0.9]},
        {'frame': 110, 'op': 'release', 'vertex': 27}]), 700),
    'default-overpull-release': (grid(7, 7, pins=[0, 3, 6], actions=OVERPULL), 80),
    'seed-overpull-release': (grid(7, 7, pins=[0, 3, 6], solver='jakobsen', actions=OVERPULL), 80),
    'xpbd-overpull-release': (grid(7, 7, pins=[0, 3, 6], solver='xpbd', actions=OVERPULL), 80),
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
    # them): the steps, every solver in turn, gravity, the time step and the fabric; and a
    # recording's own `frames` (run with frames None).
    'set-settings-mid-run': (grid(8, 6, pins=[0, 7], actions=DRAG + [
        {'frame': 3, 'op': 'set', 'scene': {'substeps': 3, 'damping': 2}},
        {'frame': 7, 'op': 'set', 'scene': {'solver': 'jakobsen'}},
        {'frame': 9, 'op': 'set', 'scene': {'gravity': [1, -4], 'iterations': 5}},
        {'frame': 12, 'op': 'set', 'scene': {'solver': 'xpbd', 'dt': 0.02, 'stretch': 5000, 'shear': 150}},
        {'frame': 18, 'op': 'set', 'scene': {'solver': 'vbd', 'density': 0.4, 'corrections': 2}}]), 30),
    # The air: a steady wind on a soft curtain, gusts on a free cloth with a hand and a cut,
    # and the wind set live and taken away again.
    'wind-steady': (grid(8, 6, pins=list(range(8)), density=0.2, stretch=500.0, wind=[6.0, 0.5],
                         drag=0.3), 90),
    'wind-gusts-hand-cut': (grid(7, 7, pins=[0, 6], wind=[-3.0, 2.0], drag=2.5, gust=[0.8, 0.37],
                                 actions=[
        {'frame': 10, 'op': 'grab', 'vertex': 45},
        {'frame': 14, 'op': 'move', 'vertex': 45, 'to': [0.4, -1.2]},
        {'frame': 20, 'op': 'cut', 'from': [0.1, -0.3], 'to': [0.9, -0.35]},
        {'frame': 30, 'op': 'release', 'vertex': 45}]), 80),
    'wind-set-live': (grid(6, 5, pins=[0, 5], solver='jakobsen', actions=[
        {'frame': 5, 'op': 'set', 'scene': {'wind': [8, 0], 'drag': 1.0}},
        {'frame': 25, 'op': 'set', 'scene': {'gust': [1.5, 0.5], 'solver': 'xpbd'}},
        {'frame': 45, 'op': 'set', 'scene': {'wind': [0, 0], 'solver': 'vbd'}}]), 70),
    # Obstacles: a cloth dropped on a peg and a box with friction; a box swept 1 m through a
    # hanging curtain in one frame and back; the seed's method over a circle in wind, with a
    # cut and a hand.
    'obstacles-drop': (grid(8, 8, pins=[], damping=1, obstacles=[
        {'circle': [0.7, -2.0, 0.3], 'friction': 0.4}, {'box': [-0.2, -2.6, 0.4, -2.3]}]), 120),
    'obstacles-drop-xpbd': (grid(8, 8, pins=[], damping=1, solver='xpbd', obstacles=[
        {'circle': [0.7, -2.0, 0.3], 'friction': 0.4}, {'box': [-0.2, -2.6, 0.4, -2.3]}]), 80),
    'obstacles-swept-box': (grid(8, 6, pins=list(range(8)), obstacles=[
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
    # cut off falls free).
    'tear-pulled-beyond-reach': (grid(10, 8, pins=[0, 3, 6, 9], tear=0.25, stretch=50.0, actions=[
        {'frame': 10, 'op': 'grab', 'vertex': 75},
        {'frame': 11, 'op': 'move', 'vertex': 75, 'to': [0.6, -4.0]},
        {'frame': 50, 'op': 'release', 'vertex': 75}]), 90),
    'cuts-and-falling-pieces': (grid(9, 9, pins=[0, 4, 8], actions=[
        {'frame': 20, 'op': 'cut', 'from': [-0.2, -0.43], 'to': [1.2, -0.47]},
        {'frame': 25, 'op': 'cut', 'from': [0.55, 0.2], 'to': [0.55, -1.5]},
        {'frame': 30, 'op': 'grab', 'vertex': 40},
        {'frame': 31, 'op': 'cut', 'from': [0.3, -0.6], 'to': [0.7, -0.2]},
        {'frame': 40, 'op': 'release', 'vertex': 40}]), 80),
    'seed-tear-and-cut': (grid(8, 8, pins=[0, 7], solver='jakobsen', tear=0.05, actions=[
        {'frame': 15, 'op': 'cut', 'from': [0.2, 0.1], 'to': [0.25, -1.2]}]), 60),
    # Every edge cut, the pinned pair 0-1 apart too: a dust of particles, each in free fall
    # (the curtain hangs within a fraction of a per cent of its rest grid, so blades between
    # the rows and columns cut it all).
    'cut-every-edge': (grid(6, 6, pins=[0, 1, 2, 3, 4, 5], actions=[
        {'frame': 60, 'op': 'cut', 'from': [(c + 0.5) * 0.2, 0.5], 'to': [(c + 0.5) * 0.2, -1.5]}
        for c in range(5)] + [
        {'frame': 60, 'op': 'cut', 'from': [-0.5, -(r + 0.5) * 0.2], 'to': [1.5, -(r + 0.5) * 0.2]}
        for r in range(5)]), 100),
    # Scenes made before the membrane: their old keys mapped (compliance to a stretch, the old
    # XPBD to the default with its own steps) or left out, identically in both runtimes.
    'model-1-xpbd-compliance-shear': (
        legacy(9, 7, pins=[0, 8], solver='xpbd', compliance=1e-3, shear=True, gravity=[2.0, -20.0]), 50),
    'model-1-tethers-tolerance-speed': (
        legacy(8, 8, pins=[0, 7], solver='xpbd', tethers=False, cells=False, lines=True, tolerance=1e-3,
               max_speed=3.0, iterations=6, substeps=2), 50),
    'model-1-seed-set-compliance': (legacy(6, 5, pins=[0, 5], solver='jakobsen', actions=[
        {'frame': 10, 'op': 'set', 'scene': {'solver': 'xpbd', 'compliance': 1e-4}}]), 30),
}
# Every named fabric (cloth/fabrics.py), hung from two corners.
for _f in FABRICS:
    SCENES['fabric-' + _f[0]] = (grid(10, 10, pins=[0, 9], stretch=_f[2], shear=_f[3], density=_f[4]), 60)
# Every preset, as the page makes it (cloth/presets.py), on a small grid of its own shape,
# under each solver: the Two corners' carried clamp, the Towel's peg, the Flag's gusts and the
# Tearable's tearing.
for _name, _label, _cols, _rows, _size in PRESETS:
    for _solver in SOLVERS:
        _c, _r = min(10, max(2, _cols // 5)), min(10, max(1, _rows // 5))
        SCENES['preset-%s-%s' % (_name, _solver)] = (dict(preset_scene(_name, _c, _r), solver=_solver), 70)


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


@pytest.mark.parametrize('solver', SOLVERS)
def test_larger_grid_many_frames(core, solver):
    text = json.dumps(grid(40, 30, pins=[0, 13, 26, 39], solver=solver))
    assert_identical(run(text, 20), core(text, 20)['ok'])


def test_the_scenes_cover_every_solver_fabric_and_model():
    """The scenes above are no proof for a solver, a fabric or a model they leave out."""
    current = [s for s, _ in SCENES.values() if s.get('model') == MODEL]
    assert {s.get('solver', DEFAULT_SOLVER) for s in current} == set(SOLVERS)
    assert {(s.get('stretch'), s.get('shear'), s.get('density')) for s in current} >= \
        {tuple(f[2:5]) for f in FABRICS}
    assert any('model' not in s for s, _ in SCENES.values())


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
                          ('tear', st.sampled_from([0.01, 0.1, 0.5, 2.0])),
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
