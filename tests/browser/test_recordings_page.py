"""Recordings made before issue #23 replay in the page to the positions the code before the
change gave, bit for bit (tests/recordings/expected.json; CPython's side:
tests/test_recordings.py)."""
import hashlib
import json
from pathlib import Path

import pytest

from browser_helpers import ROOT

HERE = Path(ROOT) / 'tests' / 'recordings'
EXPECTED = json.loads((HERE / 'expected.json').read_text())
FILES = sorted({k.split('/')[0] for k in EXPECTED if not k.startswith('_')})


def digest(positions):
    # As floats, -0.0 as 0.0: the CLI's JSON text writes -0.0 as 0, the page's numbers keep it.
    flat = [[float(x) + 0.0, float(y) + 0.0] for x, y in positions]
    return hashlib.sha256(json.dumps(flat).encode()).hexdigest()


@pytest.mark.parametrize('name', FILES)
def test_a_recording_made_before_replays_in_the_page_bit_for_bit(open_page, name):
    pg = open_page('?paused=1')
    text = (HERE / (name + '.json')).read_text()
    frames = json.loads(text)['frames']
    pg.js('(t) => { clothApp.loadScene(t); clothApp.setPaused(true); }', text)
    assert pg.js('(n) => clothApp.advance(n, true)', frames + 5) == frames   # a replay stops at its end
    panels = pg.js('clothApp.panels()')
    if len(panels) == 1:
        assert digest(panels[0]['positions']) == EXPECTED[name]
    else:
        for i, p in enumerate(panels):
            assert digest(p['positions']) == EXPECTED['%s/%d' % (name, i + 1)], i
