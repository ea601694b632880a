"""Every validation error: a SceneError whose one-line message starts with the key."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from cloth.api import run
from cloth.hands import grab, move, pin
from cloth.keys import MODEL, LEGACY_KEYS
from cloth.values import SceneError

ROOT = Path(__file__).resolve().parent.parent
GOOD = {'model': MODEL, 'cols': 3, 'rows': 2, 'spacing': 0.1}


def with_keys(**keys):
    s = dict(GOOD)
    s.update(keys)
    return json.dumps(s)


def old_with_keys(**keys):
    """A scene made before the membrane (model 1: no `model` key)."""
    s = dict(GOOD)
    del s['model']
    s.update(keys)
    return json.dumps(s)


def without(key):
    s = dict(GOOD)
    del s[key]
    return json.dumps(s)


def action(**keys):
    a = {'frame': 0, 'op': 'grab', 'vertex': 0}
    a.update(keys)
    return with_keys(actions=[a])


BAD = [
    ('not json', 'scene:'),
    ('', 'scene:'),
    ('{"cols": 3, "rows": 2, "spacing": NaN}', 'scene:'),
    ('{"cols": 3, "rows": 2, "spacing": Infinity}', 'scene:'),
    ('{"cols": 3, "rows": 2, "spacing": 1e999}', 'spacing:'),
    ('[1, 2]', 'scene:'),
    ('"cloth"', 'scene:'),
    ('null', 'scene:'),
    (without('cols'), 'cols:'),
    (without('rows'), 'rows:'),
    (without('spacing'), 'spacing:'),
    (with_keys(cols='3'), 'cols:'),
    (with_keys(cols=2.5), 'cols:'),
    (with_keys(cols=0), 'cols:'),
    (with_keys(rows=-1), 'rows:'),
    (with_keys(cols=True), 'cols:'),
    (with_keys(cols=2000, rows=2000), 'cols:'),
    (with_keys(spacing=0), 'spacing:'),
    (with_keys(spacing=-0.1), 'spacing:'),
    (with_keys(spacing=[1]), 'spacing:'),
    (with_keys(pins=3), 'pins:'),
    (with_keys(pins=[6]), 'pins:'),
    (with_keys(pins=[-1]), 'pins:'),
    (with_keys(pins=[0.5]), 'pins:'),
    (with_keys(gravity=[0]), 'gravity:'),
    (with_keys(gravity=[0, 'down']), 'gravity:'),
    (with_keys(gravity=[0, 1e6]), 'gravity:'),
    (with_keys(dt=0), 'dt:'),
    (with_keys(dt=-0.01), 'dt:'),
    (with_keys(dt=2), 'dt:'),
    (with_keys(substeps=0), 'substeps:'),
    (with_keys(substeps=1.5), 'substeps:'),
    (with_keys(iterations=-1), 'iterations:'),
    (with_keys(iterations=100000), 'iterations:'),
    (with_keys(damping=-1), 'damping:'),
    (with_keys(solver='verlet'), 'solver:'),
    (with_keys(solver=3), 'solver:'),
    (with_keys(sleep=1), 'sleep:'),
    (with_keys(shear=True), 'shear:'),
    (with_keys(shear=-1), 'shear:'),
    (with_keys(stretch=0.5), 'stretch:'),
    (with_keys(density=0), 'density:'),
    (with_keys(density=None), 'density:'),
    (with_keys(corrections=-1), 'corrections:'),
    (with_keys(tear=0), 'tear:'),
    (with_keys(drag=-1), 'drag:'),
    (with_keys(wind=[0]), 'wind:'),
    (with_keys(gust=[1, 0]), 'gust:'),
    (with_keys(name=5), 'name:'),
    (with_keys(model=0), 'model:'),
    (with_keys(model=MODEL + 1), 'model:'),
    (with_keys(model=1.5), 'model:'),
    (with_keys(model='2'), 'model:'),
    (with_keys(colour='red'), 'colour:'),
    # Model 1's keys are no keys of model 2's.
    (with_keys(tethers=True), 'tethers: unknown key'),
    (with_keys(cells=False), 'cells: unknown key'),
    (with_keys(lines=False), 'lines: unknown key'),
    (with_keys(tolerance=0), 'tolerance: unknown key'),
    (with_keys(max_speed=50), 'max_speed: unknown key'),
    (with_keys(compliance=1e-3), 'compliance: unknown key'),
    # A scene of model 1 still has them checked as they were.
    (old_with_keys(tethers='yes'), 'tethers:'),
    (old_with_keys(cells=1), 'cells:'),
    (old_with_keys(lines=None), 'lines:'),
    (old_with_keys(shear=1), 'shear:'),
    (old_with_keys(compliance=-1e-6), 'compliance:'),
    (old_with_keys(compliance=2e3), 'compliance:'),
    (old_with_keys(tolerance=-1), 'tolerance:'),
    (old_with_keys(max_speed=-1), 'max_speed:'),
    (old_with_keys(max_speed=1e7), 'max_speed:'),
    (old_with_keys(colour='red'), 'colour:'),
    (old_with_keys(solver='verlet'), 'solver:'),
    # As they were in model 1: 0 <= tolerance <= 1, max_speed > 0.
    (old_with_keys(tolerance=2), 'tolerance:'),
    (old_with_keys(max_speed=0), 'max_speed:'),
    (with_keys(actions={}), 'actions:'),
    (with_keys(actions=[3]), 'actions[0]:'),
    (action(frame=-1), 'actions[0].frame:'),
    (action(op='drag'), 'actions[0].op:'),
    (action(vertex=6), 'actions[0].vertex:'),
    (action(vertex='0'), 'actions[0].vertex:'),
    (action(to=[1]), 'actions[0].to:'),
    (action(to=[1, None]), 'actions[0].to:'),
    (action(when=3), 'actions[0].when:'),
    (action(op='move'), 'actions[0].to:'),
    (action(op='pin', to=[0, 0]), 'actions[0].to:'),
    (json.dumps(dict(GOOD, actions=[{'op': 'pin', 'vertex': 0}])), 'actions[0].frame:'),
    (action(op='move', to=[0, 0]), 'actions:'),        # move of a vertex nobody holds
    (action(op='release'), 'actions:'),
]


@pytest.mark.parametrize('text,key', BAD)
def test_bad_scene_is_a_one_line_error_naming_the_key(text, key):
    with pytest.raises(SceneError) as err:
        run(text, 1)
    message = str(err.value)
    assert message.startswith(key)
    assert '\n' not in message


@pytest.mark.parametrize('frames', [-1, 2.5, 'ten', None, float('nan'), 10 ** 9])
def test_bad_frame_count(frames):
    with pytest.raises(SceneError, match='^frames:'):
        run(json.dumps(GOOD), frames)


@pytest.mark.parametrize('key', LEGACY_KEYS)
def test_a_legacy_key_in_a_current_scene_is_an_unknown_key_naming_it(key):
    value = {'tethers': True, 'cells': True, 'lines': True}.get(key, 0.001)
    with pytest.raises(SceneError) as err:
        run(with_keys(**{key: value}), 1)
    message = str(err.value)
    assert message.startswith(key + ': unknown key (known: ') and '\n' not in message
    # the keys it lists are the current ones, and none of model 1's
    known = message[len(key + ': unknown key (known: '):-1].split(', ')
    assert 'model' in known and 'stretch' in known and not set(LEGACY_KEYS) & set(known)
    run(old_with_keys(**{key: value}), 1)       # a scene of model 1 has it


def test_bad_vertex_in_a_direct_call():
    from cloth.api import load
    cloth = load(json.dumps(GOOD))
    for k in [-1, 6, 2.5]:
        with pytest.raises(SceneError, match='^vertex:'):
            pin(cloth, k)
    grab(cloth, 0, 0, 0)
    with pytest.raises(SceneError, match='^to:'):
        move(cloth, 0, float('nan'), 0)
    with pytest.raises(SceneError, match='^vertex:'):
        move(cloth, 1, 0, 0)


def cli(*args, stdin=None):
    return subprocess.run([sys.executable, '-m', 'cloth', *args], cwd=ROOT, input=stdin,
                          capture_output=True, text=True, timeout=60)


def test_cli_prints_exactly_what_run_returns(tmp_path):
    path = tmp_path / 'scene.json'
    text = json.dumps(dict(GOOD, pins=[0, 2]))
    path.write_text(text)
    done = cli('run', str(path), '--frames', '7')
    assert done.returncode == 0 and done.stderr == ''
    assert done.stdout == run(text, 7) + '\n'
    traced = cli('run', str(path), '--frames', '3', '--trace')
    assert len(json.loads(traced.stdout)['trace']) == 3
    piped = cli('run', '-', '--frames', '7', stdin=text)
    assert piped.stdout == done.stdout


@pytest.mark.parametrize('args,stdin,key', [
    (['run', '-', '--frames', '-3'], json.dumps(GOOD), 'frames:'),
    (['run', '-', '--frames', '5'], '{"cols": 3}', 'rows:'),
    (['run', '-', '--frames', '5'], '{oops', 'scene:'),
    (['run', '/no/such/scene.json', '--frames', '5'], None, 'scene:'),
    (['run', '-', '--frames', 'x'], json.dumps(GOOD), 'argument --frames'),
    (['run', '-'], json.dumps(GOOD), 'frames: missing'),
    (['jump'], None, 'argument command'),
])
def test_cli_bad_input_is_one_line_and_nonzero(args, stdin, key):
    done = cli(*args, stdin=stdin)
    assert done.returncode == 2
    assert done.stdout == ''
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert 'Traceback' not in done.stderr
    assert key in lines[0]


@pytest.mark.parametrize('stdin,said', [
    ('', 'scene: empty'), (' \n\t\r\n', 'scene: empty'),
    ('{"cols": 3,\n "rows": 2,, }', 'scene: not valid JSON at line 2, column 12: Expecting property name'),
    ('[1, 2', 'scene: not valid JSON at line 1, column 6'),
    ('{"cols": NaN}', 'scene: not valid JSON (NaN is not JSON)'),
])
def test_cli_says_an_empty_scene_is_empty_and_where_json_fails(stdin, said):
    done = cli('run', '-', '--frames', '1', stdin=stdin)
    assert done.returncode == 2 and done.stdout == ''
    assert done.stderr.startswith('error: ' + said) and len(done.stderr.splitlines()) == 1, done.stderr


def test_a_long_cli_run_shows_its_progress_and_ctrl_c_ends_it_with_status_130(tmp_path):
    """A run that takes longer than a second says how far it is on standard error (a line now
    and then where that is not a terminal); SIGINT (Ctrl+C) ends it with one line saying where,
    no traceback, no partial JSON, status 130. (A 1000x1000 run printed nothing for minutes.)"""
    import signal
    from cloth.presets import preset_scene
    path = tmp_path / 'large.json'
    path.write_text(json.dumps(preset_scene('large', 60, 60)))
    proc = subprocess.Popen([sys.executable, '-m', 'cloth', 'run', str(path), '--frames', '1000000'], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        first = proc.stderr.readline()          # waits for the first progress line
        assert first.startswith('frame ') and 'of 1000000' in first and 'left' in first, first
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 130 and out == ''
    assert err.startswith('interrupted at frame ') and err.endswith(': no result written\n'), err
    assert 'Traceback' not in err


def test_every_preset_opens_at_the_grids_the_page_allows():
    """Each preset's scene is valid at the page's smallest and largest grids, a single row or
    column included (a towel one vertex wide once had a peg of no width: "obstacles[0].box:
    must have x1 > x0"), and its cloth stays finite through its first frames."""
    from cloth.api import load
    from cloth.keys import spec
    from cloth.presets import PRESETS, preset_scene
    from cloth.step import frame
    lo, hi = spec('cols').field_lo, spec('cols').field_hi
    assert (lo, hi) == (spec('rows').field_lo, spec('rows').field_hi)
    for p in PRESETS:
        for cols, rows in [(lo, lo), (lo, 2), (2, lo), (lo, hi), (hi, lo), (2, 2)]:
            cloth = load(json.dumps(preset_scene(p[0], cols, rows)))
            for _ in range(3):
                frame(cloth)
            assert all(v == v and abs(v) < 1e3 for v in cloth.pos), (p[0], cols, rows)
