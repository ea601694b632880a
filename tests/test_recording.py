"""What a recording needs from the core (issue #13), in CPython: the `frames` key, the `set`
action (settings changed on the running cloth at a frame), and the state at frame F holding
what was done at frame F. The page's side is in tests/browser/test_recording_page.py."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from cloth.api import load, run, set_settings, simulate
from cloth.hands import grab, move, release
from cloth.keys import MODEL, spec, solver_index
from cloth.keys import SOLVERS, SOLVER_BUDGETS, DEFAULT_SOLVER, SEED_SOLVER
from cloth.step import frame
from cloth.values import SceneError

ROOT = Path(__file__).resolve().parent.parent
GOOD = {'model': MODEL, 'cols': 4, 'rows': 3, 'spacing': 0.1, 'pins': [0, 3], 'damping': 1}


def text(**keys):
    s = dict(GOOD)
    s.update(keys)
    return json.dumps(s)


def cli(*args, stdin=None):
    return subprocess.run([sys.executable, '-m', 'cloth', *args], cwd=ROOT, input=stdin,
                          capture_output=True)


# ---- frames -----------------------------------------------------------------------------------

def test_frames_key_is_the_default_run_length():
    assert run(text(frames=25)) == run(text(frames=25), 25) == run(text(), 25)
    assert json.loads(run(text(frames=0)))['frames'] == 0


def test_frames_argument_wins_over_the_key():
    assert run(text(frames=25), 7) == run(text(), 7)


def test_frames_from_neither_is_an_error_naming_frames():
    with pytest.raises(SceneError, match='^frames: missing'):
        run(text())


@pytest.mark.parametrize('value', [-1, 1.5, '3', None, True, 1e8, [3]])
def test_a_bad_frames_key_names_frames(value):
    with pytest.raises(SceneError, match='^frames: must be'):
        run(text(frames=value), 3)


def test_cli_runs_the_scenes_frames_and_frames_wins(tmp_path):
    path = tmp_path / 'rec.json'
    path.write_text(text(frames=12))
    own = cli('run', str(path))
    assert own.returncode == 0 and json.loads(own.stdout)['frames'] == 12
    assert own.stdout.decode().strip() == run(text(frames=12))
    given = cli('run', str(path), '--frames', '4')
    assert json.loads(given.stdout)['frames'] == 4
    path.write_text(text())
    neither = cli('run', str(path))
    assert neither.returncode == 2 and neither.stderr.decode().startswith('error: frames: missing')


# ---- the state at frame F holds what was done at frame F ---------------------------------------

@pytest.mark.parametrize('solver', [SEED_SOLVER, DEFAULT_SOLVER])
def test_actions_of_the_last_frame_apply_after_it(solver):
    """A recording ends with what a person did at its last frame: a pin, a grab and a move
    made while the page was paused at frame 10 are in the state of frame 10 (the pin held, the
    hand where the move sent it); the hand takes the pinned vertex there over the next frame
    (hands.move), the seed's exactly."""
    acts = [{'frame': 10, 'op': 'pin', 'vertex': 5},
            {'frame': 10, 'op': 'grab', 'vertex': 5, 'to': [0.3, 0.2]},
            {'frame': 10, 'op': 'move', 'vertex': 5, 'to': [0.35, 0.25]}]
    cloth = load(text(solver=solver, actions=acts))
    simulate(cloth, 10, None)
    assert cloth.pinned[5] == 1 and cloth.held[5] == 1 and cloth.fixed[5] == 0
    assert (cloth.target[10], cloth.target[11]) == (0.35, 0.25)
    assert (cloth.hold_from[10], cloth.hold_from[11]) == (0.3, 0.2)
    # ... the frames before are not touched by them, nor are the positions of frame 10 ...
    assert json.loads(run(text(solver=solver, actions=acts), 9))['positions'] == \
        json.loads(run(text(solver=solver), 9))['positions']
    assert json.loads(run(text(solver=solver, actions=acts), 10))['positions'] == \
        json.loads(run(text(solver=solver), 10))['positions']
    # ... and the next frame moves it towards the hand.
    then = json.loads(run(text(solver=solver, actions=acts), 11))['positions'][5]
    if solver == SEED_SOLVER:
        assert then == [0.35, 0.25]
    else:
        assert then != json.loads(run(text(solver=solver), 11))['positions'][5]


def test_the_step_loop_of_the_page_is_the_run():
    """The page applies what is due at frame f right after frame f (and frame 0's at load),
    then a person's gestures: the same sequence as `simulate`."""
    acts = [{'frame': 0, 'op': 'grab', 'vertex': 7, 'to': [0.2, -0.3]},
            {'frame': 4, 'op': 'move', 'vertex': 7, 'to': [0.25, -0.35]},
            {'frame': 9, 'op': 'release', 'vertex': 7}]
    ran = load(text(actions=acts))
    simulate(ran, 15, None)
    by_hand = load(text())
    grab(by_hand, 7, 0.2, -0.3)
    for f in range(1, 16):
        frame(by_hand)
        if f == 4:
            move(by_hand, 7, 0.25, -0.35)
        if f == 9:
            release(by_hand, 7)
    assert list(ran.pos) == list(by_hand.pos)


# ---- set --------------------------------------------------------------------------------------

CHANGES = [{'gravity': [0, -3]}, {'iterations': 7}, {'substeps': 3}, {'solver': 'jakobsen'},
           {'solver': 'xpbd'}, {'damping': 4}, {'stretch': 2000}, {'sleep': False}, {'shear': 5},
           {'dt': 0.01}, {'density': 0.5, 'corrections': 3}, {'tear': 0.05},
           {'wind': [3, 0], 'drag': 0.5, 'gust': [0.5, 0.7]},
           {'solver': 'jakobsen', 'substeps': 2, 'iterations': 30}, {}]


@pytest.mark.parametrize('change', CHANGES)
def test_a_set_action_is_a_live_change_at_its_frame(change):
    """A set at frame 12 gives, bit for bit, what a person changing the setting at frame 12 of
    the running cloth gets (the page records its changes so)."""
    acts = [{'frame': 3, 'op': 'grab', 'vertex': 6, 'to': [0.15, -0.05]},
            {'frame': 12, 'op': 'set', 'scene': change},
            {'frame': 20, 'op': 'release', 'vertex': 6}]
    recorded = json.loads(run(text(actions=acts), 40))
    live = load(text(actions=[a for a in acts if a['op'] != 'set']))
    simulate(live, 12, None)
    set_settings(live, json.dumps(change))
    for f in range(13, 41):
        frame(live)
        if f == 20:
            release(live, 6)
    assert recorded['positions'] == [[live.pos[2 * k], live.pos[2 * k + 1]] for k in range(12)]


def test_a_set_is_the_scene_with_those_keys_written_into_it():
    """Settings a scene left to its solver's defaults follow the solver a set chooses."""
    cloth = load(text(actions=[{'frame': 0, 'op': 'set', 'scene': {'solver': 'jakobsen'}}]))
    before = [cloth.substeps, cloth.iterations, cloth.corrections]
    assert before == SOLVER_BUDGETS[solver_index(DEFAULT_SOLVER)]
    simulate(cloth, 0, None)
    seed = SOLVER_BUDGETS[solver_index(SEED_SOLVER)]
    assert seed != before and [cloth.substeps, cloth.iterations, cloth.corrections] == seed
    assert cloth.scene.pins == [0, 3]          # the grid's own keys stay
    # a key the scene gave itself stays given
    cloth = load(text(substeps=5, actions=[{'frame': 0, 'op': 'set', 'scene': {'solver': 'jakobsen'}}]))
    simulate(cloth, 0, None)
    assert cloth.substeps == 5
    # sets accumulate
    acts = [{'frame': 0, 'op': 'set', 'scene': {'damping': 3}},
            {'frame': 1, 'op': 'set', 'scene': {'iterations': 4}}]
    cloth = load(text(actions=acts))
    simulate(cloth, 1, None)
    assert (cloth.scene.damping, cloth.iterations) == (3, 4)


@pytest.mark.parametrize('act, message', [
    ({'frame': 1, 'op': 'set'}, r'^actions\[0\]\.scene: missing'),
    ({'frame': 1, 'op': 'set', 'scene': 3}, r'^actions\[0\]\.scene: must be an object'),
    ({'frame': 1, 'op': 'set', 'scene': {'cols': 5}}, r'^actions\[0\]\.scene\.cols: cannot be set'),
    ({'frame': 1, 'op': 'set', 'scene': {'pins': []}}, r'^actions\[0\]\.scene\.pins: cannot be set'),
    ({'frame': 1, 'op': 'set', 'scene': {'frames': 3}}, r'^actions\[0\]\.scene\.frames: cannot'),
    ({'frame': 1, 'op': 'set', 'scene': {'bogus': 3}}, r'^actions\[0\]\.scene\.bogus: cannot'),
    ({'frame': 1, 'op': 'set', 'scene': {'tethers': False}}, r'^actions\[0\]\.scene\.tethers: cannot'),
    ({'frame': 1, 'op': 'set', 'scene': {'model': 1}}, r'^actions\[0\]\.scene\.model: cannot'),
    ({'frame': 1, 'op': 'set', 'scene': {'shear': True}}, r'^actions\[0\]\.scene\.shear: must be a number'),
    ({'frame': 1, 'op': 'set', 'scene': {'substeps': 0}}, r'^actions\[0\]\.scene\.substeps: must be'),
    ({'frame': 1, 'op': 'set', 'scene': {'solver': 'magic'}}, r'^actions\[0\]\.scene\.solver: must be'),
    ({'frame': 1, 'op': 'set', 'scene': {'gravity': [0]}}, r'^actions\[0\]\.scene\.gravity: must be'),
    ({'frame': 1, 'op': 'set', 'vertex': 2, 'scene': {}}, r'^actions\[0\]\.vertex: a set takes no'),
    ({'frame': 1, 'op': 'set', 'to': [0, 0], 'scene': {}}, r'^actions\[0\]\.to: a set takes no'),
    ({'frame': 1, 'op': 'pin', 'vertex': 2, 'scene': {}}, r'^actions\[0\]\.scene: only set'),
    ({'frame': 1, 'op': 'pin'}, r'^actions\[0\]\.vertex: missing'),
])
def test_set_errors_name_the_key(act, message):
    with pytest.raises(SceneError, match=message):
        run(text(actions=[act]), 2)


def test_set_settings_refuses_bad_keys_and_changes_nothing():
    cloth = load(text())
    simulate(cloth, 5, None)
    pos = list(cloth.pos)
    substeps = spec('substeps').by_solver[solver_index(DEFAULT_SOLVER)]     # the default's own
    assert cloth.substeps == substeps
    for bad in ['{"substeps": 0}', '{"cols": 2}', '[1]', 'nope', '{"tethers": false}']:
        with pytest.raises(SceneError):
            set_settings(cloth, bad)
        assert list(cloth.pos) == pos and cloth.substeps == substeps


# ---- compare mode's hands: a grab where the vertex is, moves `by` a displacement -------------

def test_a_move_by_is_the_move_to_where_the_hand_took_hold_plus_the_displacement():
    """Compare mode records a grab with no `to` and moves `by` [dx, dy]: each panel's hand goes
    the same displacement from where its own vertex was. On one cloth that is, bit for bit, the
    move `to` that point, on both solvers and on a pinned vertex."""
    for solver in SOLVERS:
        for k in [10, 3]:                     # free, and pinned
            base = json.loads(text(solver=solver, rows=5))
            cloth = load(json.dumps(base))
            simulate(cloth, 12, None)
            x0, y0 = cloth.pos[2 * k], cloth.pos[2 * k + 1]
            d = [(0.13, -0.21), (-0.05, 0.4), (0.0, 0.0)]
            by = dict(base, actions=[{'frame': 12, 'op': 'grab', 'vertex': k}] +
                      [{'frame': 14 + 3 * i, 'op': 'move', 'vertex': k, 'by': list(v)} for i, v in enumerate(d)] +
                      [{'frame': 30, 'op': 'release', 'vertex': k}])
            to = dict(base, actions=[{'frame': 12, 'op': 'grab', 'vertex': k, 'to': [x0, y0]}] +
                      [{'frame': 14 + 3 * i, 'op': 'move', 'vertex': k, 'to': [x0 + v[0], y0 + v[1]]}
                       for i, v in enumerate(d)] +
                      [{'frame': 30, 'op': 'release', 'vertex': k}])
            assert run(json.dumps(by), 40) == run(json.dumps(to), 40), (solver, k)


@pytest.mark.parametrize('solver', SOLVERS)
def test_a_grab_and_release_with_no_move_leaves_the_cloth_as_it_was(solver):
    """A tap: a hand that takes hold where the vertex is and lets go in the same frame, before
    any step, moves nothing: a cloth in motion goes on bit for bit as if untouched (letting go
    removes the springs and nothing else, and no step ran with them; the default's coarse
    operators stay those of the same fixed vertices and grips)."""
    base = json.loads(text(rows=6, cols=6, pins=[0], solver=solver))     # swinging from a corner
    tap = dict(base, actions=[{'frame': 20, 'op': 'grab', 'vertex': 35},
                              {'frame': 20, 'op': 'release', 'vertex': 35}])
    assert run(json.dumps(tap), 20) == run(json.dumps(base), 20)
    assert run(json.dumps(tap), 50) == run(json.dumps(base), 50)


@pytest.mark.parametrize('act, message', [
    ({'frame': 1, 'op': 'move', 'vertex': 5, 'by': [0, 1], 'to': [0, 0]}, r'^actions\[1\]\.by: a move takes "to" or "by", not both'),
    ({'frame': 1, 'op': 'grab', 'vertex': 5, 'by': [0, 1]}, r'^actions\[1\]\.by: only move takes "by"'),
    ({'frame': 1, 'op': 'release', 'vertex': 5, 'by': [0, 1]}, r'^actions\[1\]\.by: only move takes "by"'),
    ({'frame': 1, 'op': 'cut', 'from': [0, 0], 'to': [1, 1], 'by': [0, 1]}, r'^actions\[1\]\.by: only move takes "by"'),
    ({'frame': 1, 'op': 'set', 'scene': {}, 'by': [0, 1]}, r'^actions\[1\]\.by: a set takes no by'),
    ({'frame': 1, 'op': 'move', 'vertex': 5, 'by': [0]}, r'^actions\[1\]\.by: must be a list of two numbers'),
    ({'frame': 1, 'op': 'move', 'vertex': 5, 'by': [0, 'x']}, r'^actions\[1\]\.by: must be a number'),
    ({'frame': 1, 'op': 'move', 'vertex': 5}, r'^actions\[1\]\.to: missing \(move needs a target "to": \[x, y\], or "by"'),
])
def test_by_errors_name_the_key(act, message):
    with pytest.raises(SceneError, match=message):
        run(text(actions=[{'frame': 0, 'op': 'grab', 'vertex': 5}, act]), 2)


def test_a_move_by_needs_a_held_vertex():
    with pytest.raises(SceneError, match=r'^actions: move of vertex 5 at frame 1 which is not held'):
        run(text(actions=[{'frame': 1, 'op': 'move', 'vertex': 5, 'by': [0, 1]}]), 2)
