"""Recordings made before the core took the session over (issue #23) replay identically: each
file in tests/recordings/ is a recording in the page's format (every op, five presets, a
material set live, compare mode with a hand that moves `by`), and expected.json holds the
hash of the positions the code before the change gave at the recording's end (the commit it
names). The page's side: tests/browser/test_recordings_page.py."""
import hashlib
import json
from pathlib import Path

import pytest

from cloth.api import run

HERE = Path(__file__).parent / 'recordings'
EXPECTED = json.loads((HERE / 'expected.json').read_text())
CASES = sorted(k for k in EXPECTED if not k.startswith('_'))


def recording(case):
    name = case.split('/')[0]
    panel = int(case.split('/')[1]) - 1 if '/' in case else -1
    return (HERE / (name + '.json')).read_text(), panel


def digest(positions):
    # As floats, -0.0 as 0.0: the CLI's JSON text writes -0.0 as 0, the page's numbers keep it.
    flat = [[float(x) + 0.0, float(y) + 0.0] for x, y in positions]
    return hashlib.sha256(json.dumps(flat).encode()).hexdigest()


def test_every_recording_is_covered():
    files = sorted(p.stem for p in HERE.glob('*.json') if p.name != 'expected.json')
    assert sorted({c.split('/')[0] for c in CASES}) == files
    assert any('/' in c for c in CASES)                 # compare mode, per panel


@pytest.mark.parametrize('case', CASES)
def test_a_recording_made_before_replays_to_the_same_positions(case):
    text, panel = recording(case)
    scene = json.loads(text)
    ops = {a['op'] for a in scene['actions']}
    assert {'grab', 'move', 'release', 'set'} <= ops
    result = json.loads(run(text, None, False, panel))
    assert result['frames'] == scene['frames']
    assert digest(result['positions']) == EXPECTED[case]
