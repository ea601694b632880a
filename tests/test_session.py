"""The page's session, in CPython (cloth/session.py, issue #23): the panels under one pair of
hands, every gesture and setting applied to every panel and then recorded, the recording that
replays bit for bit, and a person taking over a replay. The page drives the same functions
(tests/browser/test_recording_page.py, test_compare_page.py)."""

import json

import pytest

from cloth.api import run
from cloth.keys import MAX_ACTIONS, MODEL
from cloth.keys import DEFAULT_SOLVER, SEED_SOLVER
from cloth.values import SceneError
from cloth import session as ses

SCENE = {'model': MODEL, 'cols': 8, 'rows': 6, 'spacing': 0.1, 'pins': [0, 7], 'damping': 1}
PAIR = [{'solver': SEED_SOLVER, 'substeps': 1, 'iterations': 20}, {'solver': DEFAULT_SOLVER}]


def positions(cloth):
    return [cloth.pos[i] for i in range(2 * cloth.n_verts)]


def replayed(text, panel=-1):
    out = json.loads(run(text, None, False, panel))
    return [c for p in out['positions'] for c in p]


def play(s):
    """A person's minute in a few frames: a drag, a setting, a pin, a cut, a release."""
    k = 45
    ses.advance(s, 10)
    ses.gesture_grab(s, k, 0.5, -0.5)
    for f in range(12):
        ses.gesture_move(s, k, 0.5 + 0.02 * f, -0.5 - 0.03 * f)
        ses.gesture_move(s, k, 0.5 + 0.02 * f + 0.01, -0.5 - 0.03 * f)   # two moves a frame
        ses.advance(s, 1)
    ses.change(s, json.dumps({'damping': 3, 'gravity': [0, -5]}))
    ses.advance(s, 5)
    ses.gesture_toggle_pin(s, 3)
    ses.gesture_cut(s, 0.25, 0.05, 0.25, -0.2)
    ses.advance(s, 3)
    ses.gesture_release(s, k)
    ses.advance(s, 20)


def test_a_recording_replays_to_where_the_cloth_is():
    s = ses.open_session(json.dumps(SCENE))
    play(s)
    text = ses.recording_text(s)
    rec = json.loads(text)
    assert rec['frames'] == s.frame == 50
    assert [a['op'] for a in rec['actions']].count('move') == 12     # coalesced: one a frame
    assert replayed(text) == positions(s.panels[0])


def test_a_recording_carries_the_model_it_was_made_under():
    """A recording of a current scene says model 2; one of a scene made before the membrane
    (no `model`, model 1's keys) stays model 1 with its keys, and replays bit for bit all the
    same."""
    s = ses.open_session(json.dumps(SCENE))
    ses.advance(s, 2)
    assert json.loads(ses.recording_text(s))['model'] == MODEL
    old = {k: v for k, v in SCENE.items() if k != 'model'}
    old.update(tethers=True, tolerance=1e-4, compliance=0.002, solver='xpbd')
    s = ses.open_session(json.dumps(old))
    play(s)
    text = ses.recording_text(s)
    rec = json.loads(text)
    assert 'model' not in rec and rec['tethers'] is True and rec['compliance'] == 0.002
    assert replayed(text) == positions(s.panels[0])


def test_compare_mode_applies_every_gesture_to_every_panel_and_replays_each():
    s = ses.open_session(json.dumps(dict(SCENE, compare=PAIR)))
    assert s.n_panels == 2 and s.base is not s.panels[0]
    play(s)
    text = ses.recording_text(s)
    acts = json.loads(text)['actions']
    assert {'frame': 10, 'op': 'grab', 'vertex': 45} in acts                # held where it is
    assert any(a['op'] == 'move' and 'by' in a for a in acts)
    for i in range(2):
        assert replayed(text, i) == positions(s.panels[i]), i
    assert positions(s.panels[0]) != positions(s.panels[1])               # the solvers differ


def test_moves_within_a_frame_are_one_move_and_a_return_to_the_start_keeps_one():
    s = ses.open_session(json.dumps(SCENE))
    ses.gesture_grab(s, 45, 0.5, -0.5)
    ses.gesture_move(s, 45, 0.6, -0.5)
    ses.gesture_move(s, 45, 0.7, -0.5)
    ses.gesture_move(s, 45, 0.5, -0.5)      # back where the hand took hold
    acts = json.loads(ses.recording_text(s))['actions']
    assert [(a['op'], a.get('to')) for a in acts] == [('grab', [0.5, -0.5]), ('move', [0.7, -0.5]),
                                                    ('move', [0.5, -0.5])]
    ses.gesture_move(s, 45, 0.5, -0.5)      # held still: nothing
    assert len(json.loads(ses.recording_text(s))['actions']) == 3


def test_a_person_takes_over_a_replay_where_it_is():
    s = ses.open_session(json.dumps(SCENE))
    ses.advance(s, 5)
    ses.gesture_grab(s, 44, 0.4, -0.6)
    ses.advance(s, 30)                       # held to the end: the script holds 44
    replay = ses.open_session(ses.recording_text(s))
    assert ses.advance(replay, 1000) == 35 and ses.at_replay_end(replay)
    replay = ses.open_session(ses.recording_text(s))
    ses.advance(replay, 12)
    assert replay.panels[0].held[44] != 0
    ses.gesture_toggle_pin(replay, 2)        # a person acts at frame 12
    assert replay.replay_end == -1 and replay.panels[0].held[44] == 0    # the script let go
    ses.advance(replay, 10)
    acts = json.loads(ses.recording_text(replay))['actions']
    assert [a['op'] for a in acts] == ['grab', 'release', 'pin']
    assert replayed(ses.recording_text(replay)) == positions(replay.panels[0])


def test_acting_after_a_replay_ended_runs_it_again():
    s = ses.open_session(json.dumps(dict(SCENE, frames=3)))
    ses.advance(s, 10)
    assert s.frame == 3 and ses.at_replay_end(s) and not s.resumed
    ses.gesture_toggle_pin(s, 2)
    assert s.resumed


def test_a_scripted_grab_takes_the_vertex_from_a_persons_hand():
    scene = dict(SCENE, actions=[{'frame': 3, 'op': 'grab', 'vertex': 45, 'to': [0.2, -0.9]}])
    s = ses.open_session(json.dumps(scene))
    ses.gesture_grab(s, 45, 0.45, -0.5)
    ses.advance(s, 5)
    assert s.person[45] == 0
    assert not ses.gesture_move(s, 45, 1.0, 1.0)       # the pointer no longer moves it
    assert not ses.gesture_release(s, 45)              # nor lets go of the script's hold
    assert s.panels[0].held[45] != 0


def test_bad_settings_change_nothing_and_are_not_recorded():
    s = ses.open_session(json.dumps(dict(SCENE, compare=PAIR)))
    before = ses.recording_text(s)
    for keys in ({'damping': -1}, {'cols': 3}, {'substeps': 1.5}):
        with pytest.raises(SceneError):
            ses.change(s, json.dumps(keys))
    assert ses.recording_text(s) == before
    assert s.panels[1].scene.damping == 1 and s.base.scene.damping == 1


def test_the_recording_stops_where_it_is_complete_at_the_scene_formats_limit():
    # A 3x2 cloth: the 100,000 pins and unpins, recorded and then run again, cost CPython per
    # vertex (an 8x6 cloth took 26 s of the suite).
    s = ses.open_session(json.dumps(dict(SCENE, cols=3, rows=2, pins=[0, 2])))
    for f in range(MAX_ACTIONS // 100 + 2):
        for _ in range(100):
            ses.gesture_toggle_pin(s, 4)
        ses.advance(s, 1)
    frames, count, full = ses.recording_complete(s), ses.recording_count(s), ses.recording_full(s)
    assert full and count == MAX_ACTIONS
    rec = json.loads(ses.recording_text(s))
    assert len(rec['actions']) == MAX_ACTIONS and rec['frames'] == frames < s.frame
    assert all(a['frame'] <= frames for a in rec['actions'])
    run(ses.recording_text(s))               # a scene the core takes


def test_the_recordings_codes_are_the_scene_formats_ops():
    from cloth.keys import OPS
    for name in OPS:
        assert OPS[getattr(ses, name.upper())] == name
    assert min(ses.GRAB_HERE, ses.MOVE_BY) >= len(OPS)
