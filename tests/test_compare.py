"""Compare mode's scene key (issue #14), in CPython: `compare` lists 2 to 4 panels, each a few
scene keys of its own; the physics ignores it unless a run asks for a panel, which is then the
scene with those keys written in. The page's side: tests/browser/test_compare_page.py."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from cloth.api import run
from cloth.keys import MODEL, solver_index
from cloth.keys import SOLVER_BUDGETS, DEFAULT_SOLVER, SEED_SOLVER
from cloth.values import SceneError

ROOT = Path(__file__).resolve().parent.parent
BASE = {'model': MODEL, 'cols': 6, 'rows': 5, 'spacing': 0.1, 'pins': [0, 5], 'damping': 1,
        'actions': [{'frame': 2, 'op': 'grab', 'vertex': 27, 'to': [0.3, -0.6]},
                    {'frame': 9, 'op': 'release', 'vertex': 27}]}


def own_steps(solver):
    b = SOLVER_BUDGETS[solver_index(solver)]
    return {'solver': solver, 'substeps': b[0], 'iterations': b[1]}


# The seed's solver beside the default, each with its own declared steps.
PAIR = [own_steps(SEED_SOLVER), own_steps(DEFAULT_SOLVER)]


def text(**keys):
    s = dict(BASE)
    s.update(keys)
    return json.dumps(s)


def test_the_physics_ignores_compare_but_for_a_panel():
    assert run(text(compare=PAIR), 20) == run(text(), 20)
    for i, own in enumerate(PAIR):
        assert run(text(compare=PAIR), 20, False, i) == run(text(**own), 20)


def test_a_panel_keeps_the_scenes_script_and_grid():
    own = {'shear': 10, 'stretch': 2000, 'density': 0.4, 'damping': 4, 'corrections': 2}
    three = PAIR + [own]
    out = json.loads(run(text(compare=three), 15, False, 2))
    assert out == json.loads(run(text(**own), 15))
    assert out['edges'] == json.loads(run(text(), 1))['edges']             # the scene's grid
    # the script's hand is in it: without the script the panel's cloth is elsewhere
    bare = dict(BASE, **own)
    del bare['actions']
    assert out['positions'] != json.loads(run(json.dumps(bare), 15))['positions']


@pytest.mark.parametrize('compare, message', [
    ([{}], r'^compare: must be a list of 2 to 4'),
    ([{}] * 5, r'^compare: must be a list of 2 to 4'),
    ({'solver': 'xpbd'}, r'^compare: must be a list'),
    ([{}, {'tethers': False}], r'^compare\[1\]\.tethers: not a key a panel can have'),
    ([{}, {'shear': True}], r'^compare\[1\]\.shear: must be a number'),
    ([{'model': 1}, {}], r'^compare\[0\]\.model: not a key a panel can have'),
    ([{}, 3], r'^compare\[1\]: must be an object'),
    ([{}, {'cols': 3}], r'^compare\[1\]\.cols: not a key a panel can have'),
    ([{}, {'gravity': [0, 1]}], r'^compare\[1\]\.gravity: not a key a panel can have'),
    ([{'substeps': 0}, {}], r'^compare\[0\]\.substeps: must be'),
    ([{}, {'solver': 'magic'}], r'^compare\[1\]\.solver: must be one of'),
    ([{}, {'a\nb': 1}], r'^compare\[1\]\.a\\u000ab: not a key'),
])
def test_a_bad_compare_names_the_key(compare, message):
    with pytest.raises(SceneError, match=message):
        run(text(compare=compare), 1)


def test_a_panel_that_is_not_there_names_the_panel():
    with pytest.raises(SceneError, match=r'^panel: the scene has no "compare" panels'):
        run(text(), 1, False, 0)
    with pytest.raises(SceneError, match=r'^panel: must be from 1 to 2'):
        run(text(compare=PAIR), 1, False, 2)


def test_cli_panel_counts_from_one(tmp_path):
    path = tmp_path / 'cmp.json'
    path.write_text(text(compare=PAIR, frames=12))
    for n in (1, 2):
        done = subprocess.run([sys.executable, '-m', 'cloth', 'run', str(path), '--panel', str(n)],
                              cwd=ROOT, capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        assert done.stdout.strip() == run(text(**PAIR[n - 1], frames=12))
    for bad in ('0', '3', '-1'):
        done = subprocess.run([sys.executable, '-m', 'cloth', 'run', str(path), '--panel', bad],
                              cwd=ROOT, capture_output=True, text=True)
        assert done.returncode == 2 and done.stderr.startswith('error: panel: must be from 1 to 2')
