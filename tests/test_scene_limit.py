"""Issue #22, items 1 and 2: one byte limit for every scene (cloth/keys.py MAX_SCENE_BYTES),
here in the core and the CLI; tests/browser/test_scene_limit_page.py: links (decompression
bombs), files, the Scene JSON box."""
import json
import os
import subprocess
import sys

import pytest

from cloth.api import load
from cloth.keys import MAX_SCENE_BYTES, MODEL
from cloth.scene import too_large
from cloth.values import SceneError

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

SMALL = {'model': MODEL, 'cols': 2, 'rows': 2, 'spacing': 0.1}


def padded(size):
    """A valid scene of exactly `size` bytes (its name is the padding)."""
    text = json.dumps(dict(SMALL, name=''))
    return text.replace('"name": ""', '"name": "' + 'a' * (size - len(text)) + '"')


def cli(args, data):
    return subprocess.run([sys.executable, '-m', 'cloth', 'run', *args], cwd=ROOT, input=data,
                          capture_output=True)


def test_the_core_refuses_a_scene_past_the_limit_and_takes_one_at_it():
    assert len(padded(MAX_SCENE_BYTES).encode()) == MAX_SCENE_BYTES
    load(padded(MAX_SCENE_BYTES))
    with pytest.raises(SceneError, match='too large: more than %d bytes' % MAX_SCENE_BYTES):
        load(padded(MAX_SCENE_BYTES + 1))


@pytest.mark.parametrize('where', ['file', 'stdin'])
def test_the_cli_reads_no_more_than_the_limit(tmp_path, where):
    over = padded(MAX_SCENE_BYTES + 1).encode()
    if where == 'file':
        path = tmp_path / 'big.json'
        path.write_bytes(over)
        done = cli([str(path), '--frames', '0'], b'')
    else:
        done = cli(['-', '--frames', '0'], over)
    assert done.returncode == 2
    assert done.stderr.decode().strip() == 'error: ' + too_large()
    # one byte less is a scene (a byte-order mark counts: it is part of what was read)
    done = cli(['-', '--frames', '0'], padded(MAX_SCENE_BYTES).encode())
    assert done.returncode == 0, done.stderr
