"""Issue #13 in the page: what a person does becomes a scene that replays bit for bit.

Every test drives the page through real input (Playwright's mouse and keyboard, touch through
CDP) or, where thousands of events are needed, through pointer events dispatched in the page,
then exports the recording and runs it in CPython (the CLI): its positions must be the doubles
`clothApp.state()` shows, with and without --frames. The core's side of it (the `frames` key,
the `set` action, the state at frame F) is in tests/test_recording.py.
"""
import json
import re
import math
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from browser_helpers import DIST, ROOT, bytes_under, default_preset_at, wait_until, load_paused, page_url

from cloth.hands import HAND_FORCE, HAND_STIFFNESS

SMALL = {'cols': 12, 'rows': 9, 'spacing': 0.1, 'pins': [0, 11], 'damping': 1}


def cli(text, *args):
    done = subprocess.run([sys.executable, '-m', 'cloth', 'run', '-', *args], cwd=ROOT,
                          input=text.encode(), capture_output=True)
    return done


def assert_replays(pg, with_frames=False):
    """The recording, run by the CLI with its own frames (and, with_frames, with --frames too),
    gives the page's positions bit for bit; returns the recording (a dict)."""
    text = pg.js('clothApp.recording()')
    rec = json.loads(text)
    shown = pg.state()['positions']
    assert rec['frames'] == pg.info()['frames']
    own = cli(text)
    assert own.returncode == 0, own.stderr
    assert json.loads(own.stdout)['positions'] == shown
    if with_frames:
        given_ = cli(text, '--frames', str(rec['frames']))
        assert json.loads(given_.stdout)['positions'] == shown
    return rec


def load_small(pg, **keys):
    scene = dict(SMALL, **keys)
    load_paused(pg, json.dumps(scene))
    return scene


def screen(pg, k):
    x, y = pg.state()['screen'][k]
    return x, y


def touch(cdp, kind, points):
    cdp.send('Input.dispatchTouchEvent',
             {'type': kind, 'touchPoints': [{'x': x, 'y': y, 'id': i} for i, (x, y) in enumerate(points)]})


# ---- the paths a page can take ---------------------------------------------------------------

def test_mouse_drag_paused_and_running_replays_exactly(open_page):
    pg = open_page()
    # The default preset at a quarter of its vertices: the CLI replays every frame the running
    # part lasts (about 200 on a busy machine).
    load_paused(pg, default_preset_at(20, 15))
    k = 14 * 20 + 10
    x, y = screen(pg, k)
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 12):                   # paused: single steps between the moves
        pg.mouse.move(x + 7 * i, y - 4 * i)
        pg.js('clothApp.advance(1)')
    pg.js('clothApp.setPaused(false)')       # running: real-time frames, catch-up included
    pg.mouse.move(x + 120, y + 30, steps=8)
    pg.wait_for_timeout(250)
    pg.mouse.move(x - 60, y - 90, steps=8)
    pg.wait_for_timeout(150)
    pg.mouse.up()
    pg.wait_for_timeout(200)
    pg.js('clothApp.setPaused(true)')
    rec = assert_replays(pg)
    ops = [a['op'] for a in rec['actions']]
    assert ops[0] == 'grab' and ops[-1] == 'release' and 'move' in ops
    # the export button saves the same text as a file
    with pg.expect_download() as got:
        pg.locator('#btn-export').click()
    path = got.value.path()
    assert open(path, encoding='utf-8').read() == pg.js('clothApp.recording()')
    assert got.value.suggested_filename.endswith('.json')


def test_pins_by_right_click_shift_click_and_a_dragged_pin(open_page):
    pg = open_page()
    load_small(pg)
    pg.js('clothApp.advance(20)')
    x, y = screen(pg, 5 * 12 + 4)
    pg.mouse.click(x, y, button='right')                   # pin
    pg.js('clothApp.advance(5)')
    x, y = screen(pg, 8 * 12 + 9)
    pg.keyboard.down('Shift')
    pg.mouse.click(x, y)                                   # pin by Shift+click
    pg.keyboard.up('Shift')
    pg.js('clothApp.advance(5)')
    x, y = screen(pg, 0)                                   # a pinned corner, dragged
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 50, y + 40, steps=4)
    pg.js('clothApp.advance(3)')
    pg.mouse.up()
    pg.js('clothApp.advance(10)')
    x, y = screen(pg, 5 * 12 + 4)
    pg.mouse.click(x, y, button='right')                   # unpin
    pg.js('clothApp.advance(30)')
    rec = assert_replays(pg, with_frames=True)
    ops = [a['op'] for a in rec['actions']]
    assert ops.count('pin') == 2 and ops.count('unpin') == 1


def test_two_fingers_a_double_tap_and_a_pin_toggled_on_a_held_vertex(open_page):
    pg = open_page(has_touch=True)
    load_small(pg)
    pg.js('clothApp.advance(30)')
    cdp = pg.context.new_cdp_session(pg.page)
    a, b = screen(pg, 8 * 12 + 2), screen(pg, 8 * 12 + 9)
    touch(cdp, 'touchStart', [a, b])                       # two fingers, two vertices
    for i in range(1, 8):
        touch(cdp, 'touchMove', [(a[0] - 6 * i, a[1] + 5 * i), (b[0] + 6 * i, b[1] - 3 * i)])
        pg.js('clothApp.advance(1)')
    # a right-click on a vertex a finger holds pins it under the finger
    held = [k for k, h in enumerate(pg.state()['held']) if h]
    assert len(held) == 2
    x, y = screen(pg, held[0])
    pg.mouse.click(x, y, button='right')
    pg.js('clothApp.advance(2)')
    touch(cdp, 'touchEnd', [])
    pg.js('clothApp.advance(10)')
    assert pg.state()['pinned'][held[0]]
    # a double tap toggles a pin
    x, y = screen(pg, 4 * 12 + 6)
    pg.touchscreen.tap(x, y)
    pg.touchscreen.tap(x, y)
    pg.js('clothApp.advance(20)')
    assert pg.state()['pinned'][4 * 12 + 6]
    assert_replays(pg)


def test_a_pen_drag_replays_exactly(open_page):
    pg = open_page()
    load_small(pg)
    pg.js('clothApp.advance(10)')
    x, y = screen(pg, 8 * 12 + 5)
    # A pen through the page's own Pointer Events (the driver has no pen input).
    pg.js('''([x, y]) => {
        const c = document.getElementById('view');
        const ev = (type, px, py, buttons) => c.dispatchEvent(new PointerEvent(type, {
            pointerId: 3, pointerType: 'pen', isPrimary: true, button: type === 'pointermove' ? -1 : 0,
            buttons: buttons, clientX: px, clientY: py, bubbles: true, pressure: 0.5}));
        ev('pointerdown', x, y, 1);
        for (let i = 1; i <= 20; i++) { ev('pointermove', x + 3 * i, y - 2 * i, 1); clothApp.advance(1, true); }
        ev('pointerup', x + 60, y - 40, 0);
    }''', [x, y])
    pg.js('clothApp.advance(15)')
    rec = assert_replays(pg)
    assert [a['op'] for a in rec['actions']].count('move') >= 20


def test_sleep_and_a_live_setting_change_replay_exactly(open_page):
    pg = open_page()
    load_small(pg, pins=list(range(12)))
    pg.js('clothApp.advance(600)')
    assert pg.info()['asleep']
    x, y = screen(pg, 8 * 12 + 6)
    pg.mouse.move(x, y)
    pg.mouse.down()                       # wakes it
    pg.mouse.move(x + 30, y + 10, steps=3)
    pg.js('clothApp.advance(5)')
    pg.mouse.up()
    pg.js('clothApp.advance(20)')
    for key, value in [('gravity', '-4'), ('substeps', '5'), ('damping', '2.5'), ('iterations', '3')]:
        pg.locator('#' + key).fill(value)
        pg.locator('#' + key).press('Enter')
        pg.js('clothApp.advance(7)')
    pg.select_option('#solver', 'jakobsen')
    pg.js('clothApp.advance(30)')
    rec = assert_replays(pg)
    sets = [a['scene'] for a in rec['actions'] if a['op'] == 'set']
    assert {'gravity': [0, -4]} in sets and {'substeps': 5} in sets and len(sets) == 5


def test_a_scene_with_scripted_actions_and_a_persons_gestures(open_page):
    pg = open_page()
    readme = {'cols': 20, 'rows': 15, 'spacing': 0.05, 'pins': [0, 5, 10, 14, 19], 'damping': 0.5,
              'actions': [{'frame': 30, 'op': 'grab', 'vertex': 299},
                          {'frame': 60, 'op': 'move', 'vertex': 299, 'to': [1.4, -0.3]},
                          {'frame': 90, 'op': 'release', 'vertex': 299}]}
    load_paused(pg, json.dumps(readme))
    pg.js('clothApp.advance(40)')
    x, y = screen(pg, 290)
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x - 40, y + 20, steps=3)
    pg.js('clothApp.advance(30)')
    pg.mouse.up()
    pg.js('clothApp.advance(50)')
    rec = assert_replays(pg)
    # the script's own actions are in the recording, in place
    assert {'frame': 60, 'op': 'move', 'vertex': 299, 'to': [1.4, -0.3]} in rec['actions']


def test_the_readme_scene_matches_the_cli_at_every_frame(open_page):
    pg = open_page()
    readme = ('{"cols": 20, "rows": 15, "spacing": 0.05, "pins": [0, 5, 10, 14, 19], "damping": 0.5,'
              ' "actions": [{"frame": 30, "op": "grab", "vertex": 299},'
              ' {"frame": 60, "op": "move", "vertex": 299, "to": [1.4, -0.3]},'
              ' {"frame": 90, "op": "release", "vertex": 299}]}')
    pg.js('clothApp.setPaused(true)')
    pg.locator('#json-box summary').click()
    pg.locator('#scene-json').fill(readme)
    pg.locator('#btn-load-json').click()
    pg.js('clothApp.setPaused(true)')
    trace = json.loads(cli(readme, '--frames', '120', '--trace').stdout)['trace']
    for f in range(120):
        pg.js('clothApp.advance(1)')
        assert pg.state()['positions'] == trace[f], 'frame %d' % (f + 1)
    # The hand (of finite strength) has taken the corner there, within the cloth's reach: from
    # ten frames after the move until the release it holds it within the reach of its spring,
    # HAND_FORCE / HAND_STIFFNESS = 5 mm (pulling with less than its full force; measured:
    # 1.7-4.2 mm, settling at 2.1 mm against the stretched jersey).
    reach = HAND_FORCE / HAND_STIFFNESS
    off = [math.dist(trace[f][299], (1.4, -0.3)) for f in range(70, 90)]
    assert max(off) < reach, (off, reach)


def test_a_move_every_frame_for_10000_frames_replays_exactly(open_page):
    pg = open_page()
    # Three by two: CPython replays the 10,000 frames too (6x4 took it 76 s, this 16 s).
    load_small(pg, cols=3, rows=2, pins=[0, 2])
    x, y = screen(pg, 1 * 3 + 1)
    pg.js('''([x, y]) => {
        const c = document.getElementById('view');
        const ev = (type, px, py) => c.dispatchEvent(new PointerEvent(type, {pointerId: 9,
            pointerType: 'mouse', button: type === 'pointermove' ? -1 : 0, buttons: type === 'pointerup' ? 0 : 1,
            clientX: px, clientY: py, bubbles: true}));
        ev('pointerdown', x, y);
        for (let i = 1; i <= 10000; i++) {
            ev('pointermove', x + 60 * Math.sin(i / 40), y + 40 * Math.sin(i / 23));
            clothApp.advance(1, true);
        }
        ev('pointerup', x, y + 40 * Math.sin(10000 / 23));
    }''', [x, y])
    rec = assert_replays(pg)
    assert rec['frames'] >= 10000 and len(rec['actions']) >= 10000


def test_a_full_recording_says_so_and_exports_what_it_kept(open_page):
    """The recording holds at most the scene format's 100,000 actions: a scene that brings
    them all has no room for a person's gesture, which the panel says, and the export stops at
    the last frame it holds whole."""
    pg = open_page()
    acts = [{'frame': f // 2, 'op': 'pin' if f % 2 == 0 else 'unpin', 'vertex': 0} for f in range(100000)]
    pg.js('clothApp.setPaused(true)')       # paused first: no frame runs while it loads
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(dict(SMALL, pins=[11], actions=acts)))
    pg.js('clothApp.advance(10)')
    x, y = screen(pg, 5 * 12 + 5)
    pg.mouse.click(x, y, button='right')
    info = pg.info()
    assert info['recordingFull'] and info['recorded'] == 100000
    pg.wait_for_timeout(300)
    assert 'recording full at frame 9' in pg.locator('#rec-status').inner_text()
    rec = json.loads(pg.js('clothApp.recording()'))
    assert rec['frames'] == 9 and len(rec['actions']) == 100000


def test_idle_frames_record_nothing(open_page):
    pg = open_page()
    load_small(pg)
    x, y = screen(pg, 8 * 12 + 6)
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 20, y, steps=2)
    n = pg.info()['recorded']
    pg.js('clothApp.advance(100)')          # a hand held still
    pg.mouse.move(x + 20, y)                # a move to where it already is
    pg.js('clothApp.advance(1)')
    assert pg.info()['recorded'] == n
    pg.mouse.up()
    pg.js('clothApp.advance(100)')          # nobody touches it
    assert pg.info()['recorded'] == n + 1   # the release


def test_the_idle_recording_path_allocates_nothing_per_frame(open_page):
    pg = open_page()
    load_small(pg, cols=40, rows=30)
    x, y = screen(pg, 29 * 40 + 20)
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 30, y - 20, steps=3)
    pg.js('clothApp.advance(3000)')          # warm, with a recording going and a hand held still
    cdp = pg.context.new_cdp_session(pg.page)
    cdp.send('HeapProfiler.enable')
    cdp.send('HeapProfiler.startSampling', {'samplingInterval': 256})
    frames = 3000
    pg.js('(n) => clothApp.advance(n)', frames)
    profile = cdp.send('HeapProfiler.stopSampling')['profile']
    assert bytes_under(profile['head'], 'advance') / frames < 2
    pg.mouse.up()


# ---- replay, links, files ---------------------------------------------------------------------

def make_recording(pg):
    load_small(pg)
    pg.js('clothApp.advance(15)')
    x, y = screen(pg, 8 * 12 + 6)
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 15):
        pg.mouse.move(x + 9 * i, y - 6 * i)
        pg.js('clothApp.advance(2)')
    pg.mouse.up()
    pg.js('clothApp.advance(40)')
    return pg.state()['positions'], pg.js('clothApp.recording()')


def test_replay_shows_progress_pauses_steps_and_stops_at_the_end(open_page):
    pg = open_page()
    end_positions, text = make_recording(pg)
    frames = json.loads(text)['frames']
    # The key and the reading in one task, so that no animation frame runs between them (on a
    # loaded machine ten did): P restarts the recording at frame 0, playing.
    info = pg.js("() => { window.dispatchEvent(new KeyboardEvent('keydown', {key: 'p'}));"
                 " return clothApp.info(); }")
    assert info['replay']['playing'] and info['frames'] == 0 and not info['paused']
    pg.js('clothApp.setPaused(true)')
    f = pg.js('clothApp.advance(10)')
    wait_until(pg, "document.getElementById('r-replay').textContent.replace(/\\s+/g, ' ')"
                   " === 'replay frame %d of %d'" % (f, frames))
    assert pg.locator('#r-replay').is_visible()
    pg.keyboard.press('s')
    assert pg.info()['frames'] == f + 1
    pg.js('clothApp.setPaused(false)')
    wait_until(pg, 'clothApp.info().replay.ended')
    info = pg.info()
    assert info['paused'] and info['frames'] == frames
    assert pg.state()['positions'] == end_positions
    assert pg.js('clothApp.recording()') == text     # nothing happened since: the same recording
    pg.js('clothApp.advance(5)')                     # stepping on after the end is allowed
    assert pg.info()['frames'] == frames + 5


def test_a_gesture_during_a_replay_takes_over_and_is_recorded(open_page):
    pg = open_page()
    make_recording(pg)
    # Paused in the same task as the replay starts: no animation frame runs between (on a
    # loaded machine one did, and the person's act came later than frame 20).
    pg.js('() => { clothApp.replay(); clothApp.setPaused(true); }')
    pg.js('clothApp.advance(20)')            # the scripted hand holds vertex 102 now
    frame = pg.info()['frames']
    assert frame == 20
    held = [k for k, h in enumerate(pg.state()['held']) if h]
    assert held
    x, y = screen(pg, 2 * 12 + 3)
    pg.mouse.click(x, y, button='right')      # a person acts at frame 20
    info = pg.info()
    assert not info['replay']['playing'] and not any(pg.state()['held'])   # the script let go
    pg.js('clothApp.advance(30)')
    rec = assert_replays(pg)
    assert all(a['frame'] <= frame for a in rec['actions'])
    assert rec['actions'][-2:] == [{'frame': frame, 'op': 'release', 'vertex': held[0]},
                                   {'frame': frame, 'op': 'pin', 'vertex': 2 * 12 + 3}]


def test_a_link_opened_in_a_new_page_stops_at_the_same_positions(open_page):
    pg = open_page()
    end_positions, text = make_recording(pg)
    url = pg.js('clothApp.link()')
    assert url.startswith(page_url('#scene='))
    other = open_page()
    other.goto(url)
    wait_until(other, 'window.clothApp && clothApp.info().replay.ended')
    assert other.state()['positions'] == end_positions
    assert other.info()['paused']
    assert other.js('clothApp.recording()') == text


def test_a_broken_or_truncated_link_says_so_and_shows_the_default(open_page):
    pg = open_page()
    _, text = make_recording(pg)
    url = pg.js('clothApp.link()')
    half = url[:len(url) // 2]
    # half a link: cut short where base64url cannot end, or damaged where it decodes
    for bad, words in [(half, 'cut short' if len(half.split('#scene=')[1]) % 4 == 1 else 'does not decompress'),
                       (page_url('#scene=@@@'), 'base64url'),
                       (page_url('#scene-json=' + 'e30'), 'cols: missing')]:
        other = open_page()
        other.goto(bad)
        wait_until(other, '!clothApp.info().linkPending')
        info = other.info()
        assert words in info['error'] and 'link could not be opened' in info['error'], info['error']
        assert info['preset'] == 'curtain'
        assert 'showing the Curtain preset' in info['error'], info['error']
        other.close()           # its curtain would run beside the next ones (its errors are kept)
    # the URL's preset, named; a bad link pasted over a person's own scene leaves it running
    other = open_page('?preset=chain#scene=@@@')
    wait_until(other, '!clothApp.info().linkPending')
    info = other.info()
    assert info['preset'] == 'chain' and 'showing the Chain preset' in info['error'], info['error']
    load_small(other)
    before = other.info()['scene']
    other.js("location.hash = '#scene=%%%'")
    wait_until(other, "clothApp.info().error.indexOf('link') >= 0 && !clothApp.info().linkPending")
    info = other.info()
    assert info['scene'] == before and 'the scene shown runs on' in info['error'], info['error']


def test_an_over_long_link_offers_the_file(open_page):
    pg = open_page()
    load_small(pg)
    x, y = screen(pg, 8 * 12 + 6)
    pg.js('''([x, y]) => {
        const c = document.getElementById('view');
        const ev = (type, px, py) => c.dispatchEvent(new PointerEvent(type, {pointerId: 9,
            pointerType: 'mouse', button: 0, buttons: 1, clientX: px, clientY: py, bubbles: true}));
        ev('pointerdown', x, y);
        for (let i = 1; i <= 14000; i++) { ev('pointermove', x + 8 * Math.sin(i * 1.7), y + 0.001 * i); clothApp.advance(1, true); }
    }''', [x, y])
    pg.locator('#btn-link').click()
    wait_until(pg, "clothApp.info().note.indexOf('longer than') >= 0")
    assert 'Export' in pg.info()['note']


def test_open_a_file_by_the_picker_and_by_a_drop(open_page, tmp_path):
    pg = open_page()
    end_positions, text = make_recording(pg)
    path = tmp_path / 'rec.json'
    path.write_bytes(b'\xef\xbb\xbf' + text.encode())          # with a byte-order mark, as some editors save
    pg.js('clothApp.usePreset("chain")')
    pg.set_input_files('#file-input', str(path))
    wait_until(pg, 'clothApp.info().replay.ended')
    assert pg.state()['positions'] == end_positions
    pg.js('clothApp.usePreset("chain")')
    pg.js('''(text) => {
        const dt = new DataTransfer();
        dt.items.add(new File([text], 'dropped.json', {type: 'application/json'}));
        const stage = document.getElementById('view');
        stage.dispatchEvent(new DragEvent('dragover', {dataTransfer: dt, bubbles: true, cancelable: true}));
        stage.dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true}));
    }''', text)
    wait_until(pg, 'clothApp.info().replay.ended')
    assert pg.state()['positions'] == end_positions


@pytest.mark.parametrize('data', [
    b'{"cols": 3, "rows": 2, "spacing": 0.1, "name": "caf\xe9"}',       # Latin-1
    b'\xef\xbb\xbf{"cols": 3,\xff "rows": 2}',
    b'\x89PNG\r\n\x1a\n\x00\x00',
    b'{"cols": 3, "rows": 2, "spacing": 0.1, "name": "\xed\xa0\x80"}',  # an encoded surrogate
    b'{"cols": 3, "rows": 2, "spacing": 0.1, "name": "ab\xe2\x82',      # cut short
    b'not json at all',
    b'{"cols": 3, "rows": 2}',
    b'{"cols": 3, "rows": 2, "spacing": 0.1, "actions": [{"frame": 1, "op": "set", "scene": {"cols": 4}}]}',
])
def test_a_bad_file_gets_the_clis_message_and_the_old_scene_runs_on(open_page, tmp_path, data):
    pg = open_page('?paused=1')
    path = tmp_path / 'bad.json'
    path.write_bytes(data)
    expected = subprocess.run([sys.executable, '-m', 'cloth', 'run', str(path), '--frames', '1'],
                              cwd=ROOT, capture_output=True, text=True).stderr.strip()
    assert expected.startswith('error: ')
    before = pg.info()['frames']
    pg.set_input_files('#file-input', str(path))
    wait_until(pg, "clothApp.info().error !== ''")
    error = pg.info()['error']
    # The CLI says where JSON fails to parse (its line and column: Python's parser's); the
    # page says the core's words, which both share.
    core_words = re.sub(r' at line \d+, column \d+: .*$| \([^()]* is not JSON\)$', '', expected[len('error: '):])
    assert core_words in error and 'previous scene keeps running' in error
    pg.js('clothApp.setPaused(false)')
    wait_until(pg, 'clothApp.info().frames > %d' % (before + 5))
    assert pg.info()['preset'] == 'curtain'


# ---- random gestures --------------------------------------------------------------------------

@st.composite
def gestures(draw):
    out = []
    for _ in range(draw(st.integers(1, 5))):
        out.append((draw(st.sampled_from(['drag', 'right', 'shift', 'steps', 'run', 'set'])),
                    draw(st.integers(0, 12 * 9 - 1)), draw(st.integers(-80, 80)),
                    draw(st.integers(-80, 80)), draw(st.integers(0, 8))))
    return out


@settings(max_examples=5, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(script=gestures())
def test_random_gestures_replay_bit_exactly(open_page, script):
    pg = open_page()
    load_small(pg)
    for kind, k, dx, dy, n in script:
        x, y = screen(pg, k)
        if kind == 'drag':
            pg.mouse.move(x, y)
            pg.mouse.down()
            for i in range(1, n + 2):
                pg.mouse.move(x + dx * i / (n + 1), y + dy * i / (n + 1))
                pg.js('clothApp.advance(1)')
            pg.mouse.up()
        elif kind == 'right':
            pg.mouse.click(x, y, button='right')
        elif kind == 'shift':
            pg.keyboard.down('Shift')
            pg.mouse.click(x, y)
            pg.keyboard.up('Shift')
        elif kind == 'steps':
            pg.js('(n) => clothApp.advance(n)', 10 * n)
        elif kind == 'run':
            pg.js('clothApp.setPaused(false)')
            pg.wait_for_timeout(20 * n + 20)
            pg.js('clothApp.setPaused(true)')
        else:
            pg.locator('#substeps').fill(str(1 + n))
            pg.locator('#substeps').press('Enter')
    pg.js('clothApp.advance(5)')
    assert_replays(pg)
