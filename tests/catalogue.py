"""One scene catalogue: every scene the parity suite (tests/browser/test_parity.py and, in
Firefox and WebKit, tests/browser/engines/test_engines.py) runs in CPython and in the page's
JS and compares bit for bit. Plain data and CPython only: no browser is needed to read it.

- scenes made for parity: every solver, fabric, feature and action, and both models (scenes
  made before the membrane, model 1, whose keys the two runtimes must map alike);
- every preset (cloth/presets.py), on a small grid of its own shape, under each solver;
- the hard cases (tests/hard_cases.py: huge steps, one sweep, 100 g, teleports), whose physics
  the CPython tests prove and whose doubles the page must then give too;
- a 40x30 grid under each solver;
- the recordings made before the membrane (tests/recordings/: every op, five presets, a
  material set live), through RECORDED frames, by which every op each holds has happened.
  They are also replayed through the page's own loop, compare mode's panels included, by
  tests/browser/test_recordings_page.py, and their panels in CPython by tests/test_recordings.py.

CATALOGUE: {name: (scene object, frames)}; frames None runs a scene's own `frames`.
"""

import json
from pathlib import Path

from cloth.fabrics import FABRICS
from cloth.keys import MODEL
from cloth.presets import PRESETS, preset_scene
from cloth.keys import SOLVERS

from hard_cases import HARD, BOUNDED


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
# The hard cases, as tests/test_robustness.py runs them.
for _name, _case in list(HARD.items()) + list(BOUNDED.items()):
    SCENES['hard-' + _name] = (_case[0], _case[1])
# A larger grid, many frames, under each solver.
for _solver in SOLVERS:
    SCENES['grid-40x30-' + _solver] = (grid(40, 30, pins=[0, 13, 26, 39], solver=_solver), 20)
# The recordings made before the membrane, as a person made them in the page.
RECORDINGS_DIR = Path(__file__).parent / 'recordings'
RECORDINGS = {p.stem: json.loads(p.read_text()) for p in sorted(RECORDINGS_DIR.glob('*.json'))}
RECORDED = 160


def played(scene):
    """The frames of a recording the parity suite, tests/test_recordings.py and
    tests/browser/test_recordings_page.py compare: the first RECORDED, or all of a shorter one.
    The same runs, so CPython computes each once a suite run (tests/conftest.py cli_run; a
    frame of 30x30 takes it about 0.1 s)."""
    return min(RECORDED, scene['frames'])


for _name, _scene in RECORDINGS.items():
    SCENES['recording-' + _name] = (_scene, played(_scene))

CATALOGUE = SCENES
