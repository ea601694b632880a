"""Recordings made before the membrane model (model 1: tests/recordings/, every op, five
presets, a material set live, compare mode with a hand that moves `by`) open in the page, say
that they run as a membrane, play every frame to their end and stop there, and give the page
the positions CPython gives them, bit for bit (the old core's positions are no longer expected:
the membrane moves the cloth differently). The recordings come from the scene catalogue
(tests/catalogue.py RECORDINGS); CPython's side: tests/test_recordings.py."""
import json
import math

import pytest

from catalogue import RECORDINGS, played

FILES = sorted(RECORDINGS)


@pytest.mark.parametrize('name', FILES)
def test_a_recording_made_before_plays_in_the_page_as_in_cpython_and_says_so(open_page, cli_run, name):
    pg = open_page('?paused=1')
    scene = RECORDINGS[name]
    text = json.dumps(scene)
    assert 'model' not in scene                                   # model 1
    frames = scene['frames']
    pg.js('(t) => { clothApp.loadScene(t); clothApp.setPaused(true); }', text)
    note = pg.info()['note']
    assert 'made before the membrane model (model 1)' in note, note
    first = played(scene)
    assert pg.js('(n) => clothApp.advance(n, true)', first) == first
    panels = pg.js('clothApp.panels()')
    assert len(panels) == max(1, len(scene.get('compare', [])))
    for i, p in enumerate(panels):
        cpython = json.loads(cli_run(text, first, False, i if len(panels) > 1 else -1))['positions']
        assert p['positions'] == cpython, (name, i)
    # the rest of it plays, and a replay stops at its last frame (a recording compared whole,
    # the compare one, has ended with the comparison: a step after a replay's end steps on)
    if first < frames:
        assert pg.js('(n) => clothApp.advance(n, true)', frames - first + 5) == frames
    assert pg.info()['replay']['ended']
    for p in pg.js('clothApp.panels()'):
        assert all(math.isfinite(v) for q in p['positions'] for v in q)
