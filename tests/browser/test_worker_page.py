"""The session in a Web Worker (issue #42; webgl/sim/remote.js and worker.js), as the page runs
by default: the page's thread turns input into messages and draws what the Worker posted.
The rest of the suite drives the page with ?worker=0 (browser_helpers.page_url), where the test
seam is synchronous; here advance() returns a Promise, which Playwright awaits."""
import json

from cloth.api import run
from cloth.presets import preset_scene

from browser_helpers import DIST, page_url


def open_worker_page(browser, query='', init=None):
    context = browser.new_context(viewport={'width': 1000, 'height': 700})
    page = context.new_page()
    errors = []
    page.on('pageerror', lambda e: errors.append(str(e)))
    page.on('console', lambda m: errors.append(m.text) if m.type == 'error' else None)
    if init:
        page.add_init_script(init)
    page.goto(DIST.as_uri() + query)
    page.wait_for_function('() => window.clothApp && clothApp.info().frames >= 0')
    return context, page, errors


def test_by_default_the_session_runs_in_a_worker_and_the_page_draws_it(browser):
    context, page, errors = open_worker_page(browser)
    try:
        assert page.evaluate('clothApp.info().worker')
        page.wait_for_function('() => clothApp.info().frames > 30')
        page.evaluate('clothApp.setPaused(true)')
        page.evaluate('clothApp.advance(0)')                       # the frames asked for, back
        info = page.evaluate('clothApp.info()')
        assert info['renders'] > 5 and info['error'] == '' and info['note'] == ''
        # What the page shows is the preset's cloth at the frame it says, as CPython runs it.
        shown = page.evaluate('clothApp.state().positions')
        assert json.loads(run(info['scene'], info['frames'], False, -1))['positions'] == shown
        assert errors == []
    finally:
        context.close()


def test_a_recording_made_in_the_worker_replays_bit_for_bit_in_cpython(browser):
    context, page, errors = open_worker_page(browser)
    try:
        scene = preset_scene('corners', 12, 12)
        page.evaluate('(t) => { clothApp.loadScene(t); clothApp.setPaused(true); }', json.dumps(scene))
        page.evaluate('clothApp.advance(70)')
        k = 12 * 12 - 1
        x, y = page.evaluate('(k) => clothApp.state().screen[k]', k)
        page.mouse.move(x, y)
        page.mouse.down()
        for i in range(1, 9):
            page.mouse.move(x + 6 * i, y - 4 * i)
            page.evaluate('clothApp.advance(2)')
        page.mouse.up()
        page.evaluate('clothApp.advance(20)')
        text = page.evaluate('clothApp.recording()')
        shown = page.evaluate('clothApp.state().positions')
        recorded = json.loads(text)
        assert recorded['frames'] == page.evaluate('clothApp.info().frames') == 70 + 16 + 20
        assert {a['op'] for a in recorded['actions']} >= {'grab', 'move', 'release'}
        cpython = json.loads(run(text, None, False, -1))['positions']
        assert cpython == shown
        assert errors == []
    finally:
        context.close()


def test_input_is_taken_while_the_worker_steps_a_large_cloth(browser):
    """The page's thread is not the simulation's: a press on a 200x200 cloth is taken (the
    vertex held, recorded) while the Worker is still busy with frames asked for before it."""
    context, page, errors = open_worker_page(browser)
    try:
        scene = preset_scene('large', 200, 200)
        page.evaluate('(t) => { clothApp.loadScene(t); clothApp.setPaused(true); }', json.dumps(scene))
        page.evaluate('clothApp.advance(1)')
        k = 200 * 200 - 100
        x, y = page.evaluate('(k) => clothApp.state().screen[k]', k)
        page.evaluate('() => { clothApp.advance(20, true); }')     # not awaited: the Worker is busy
        assert not page.evaluate('clothApp.info().idle')
        page.mouse.move(x, y)
        page.mouse.down()
        busy = not page.evaluate('clothApp.info().idle')
        held = page.evaluate('(k) => clothApp.state().held[k]', k)
        page.mouse.up()
        assert held and busy
        page.wait_for_function('() => clothApp.info().idle', timeout=120_000)
        assert page.evaluate('clothApp.info().frames') == 21
        assert errors == []
    finally:
        context.close()


def test_where_a_worker_cannot_start_the_page_runs_as_before_and_says_so(browser):
    context, page, errors = open_worker_page(browser, init='delete window.Worker;')
    try:
        info = page.evaluate('clothApp.info()')
        assert not info['worker']
        assert 'could not start a Web Worker' in info['note']
        page.evaluate('clothApp.setPaused(true)')
        frames = page.evaluate('clothApp.info().frames')
        assert page.evaluate('clothApp.advance(10)') == frames + 10      # on the page's thread
        assert errors == []
    finally:
        context.close()


def test_worker_0_runs_the_session_on_the_pages_thread(browser):
    context, page, errors = open_worker_page(browser, query='?worker=0')
    try:
        assert not page.evaluate('clothApp.info().worker')
        assert page.evaluate('clothApp.info().note') == ''
        assert page.url == page_url()
    finally:
        context.close()


def test_a_person_takes_over_a_replay_the_worker_plays(browser):
    context, page, errors = open_worker_page(browser)
    try:
        scene = preset_scene('corners', 12, 12)
        scene['frames'] = 600
        page.evaluate('(t) => clothApp.loadScene(t)', json.dumps(scene))
        # Pressed where the vertex was read a moment before, while the cloth runs: the bottom
        # row's middle once the carried corner has settled (0.03 m/s from frame 80 on; the
        # corner itself, at 0.7 m/s in frames 20-60, was a press on nothing under load).
        page.wait_for_function('() => clothApp.info().frames > 100')
        assert page.evaluate('clothApp.info().replay.playing')
        k = 11 * 12 + 6
        x, y = page.evaluate('(k) => clothApp.state().screen[k]', k)
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + 20, y + 10)
        page.mouse.up()
        assert 'took over the replay' in page.evaluate('clothApp.info().note')
        page.evaluate('clothApp.setPaused(true)')
        page.evaluate('clothApp.advance(0)')
        info = page.evaluate('clothApp.info()')
        assert not info['replay']['playing'] and info['frames'] < 600
        # The recording is cut where the person took over, and replays what the Worker ran.
        text = page.evaluate('clothApp.recording()')
        assert json.loads(text)['frames'] == info['frames']
        assert json.loads(run(text, None, False, -1))['positions'] == page.evaluate('clothApp.state().positions')
        assert errors == []
    finally:
        context.close()


def test_the_readouts_read_the_workers_cloth(browser):
    """What the readouts say comes from the arrays the Worker posted: a cloth with nothing to
    hold it, falling in the Worker, is said to have left the view."""
    context, page, errors = open_worker_page(browser)
    try:
        obj = json.loads(page.evaluate('clothApp.info().scene'))
        obj.update({'cols': 20, 'rows': 12, 'pins': []})
        obj.pop('actions', None)
        page.evaluate('(t) => clothApp.loadScene(t)', json.dumps(obj))
        page.wait_for_function('() => clothApp.info().frames > 120 && '
                               'document.getElementById("r-size").textContent.indexOf("left the view") >= 0',
                               timeout=30000)
        assert errors == []
    finally:
        context.close()


def test_the_clock_owes_the_frames_the_wall_clock_has_passed_and_drops_a_backlog(browser):
    """The simulation's own clock (webgl/sim/clock.js), driven with times of the test's own:
    the frames due follow the wall clock whatever the rate it is asked at; a backlog past
    MAX_BEHIND is dropped (slow motion), never owed; the rate says simulated seconds per
    second; a start again owes nothing for the time before it."""
    context, page, errors = open_worker_page(browser, '?paused=1')
    try:
        r = page.evaluate('''() => {
          const C = clothClock, c = C.create(1 / 60), out = {};
          C.start(c, 100, 1 / 60);
          // Asked 10 times a second (a slow drawing): 6 frames each time, 60 a second.
          let total = 0;
          for (let i = 1; i <= 20; i++) { const n = C.due(c, 100 + i / 10); C.ran(c, n, 100 + i / 10); total += n; }
          out.total = total; out.rate = c.rate;
          // Asked at 60.5 frames' worth after a frame: none due until the next frame's time.
          out.none = C.due(c, 102 + 0.5 / 60);
          out.wait = C.wait(c, 102 + 0.5 / 60);
          // A 5 s stall: only MAX_BEHIND's worth is due; the rest is dropped.
          out.stall = C.due(c, 107);
          C.ran(c, out.stall, 107);
          out.after = C.due(c, 107 + 1 / 60);
          out.cap = Math.ceil(C.MAX_BEHIND * 60);
          // A machine that runs one frame of each 4 due: the rate falls to about a quarter.
          C.start(c, 200, 1 / 60);
          for (let i = 1; i <= 120; i++) { const t = 200 + i / 60, n = C.due(c, t); C.ran(c, Math.min(n, 1) * (i % 4 === 0 ? 1 : 0), t); }
          out.slow = c.rate;
          C.start(c, 500, 1 / 30);
          out.restart = C.due(c, 500);
          out.later = C.due(c, 500 + 0.1);
          return out;
        }''')
        assert r['total'] == 120 and abs(r['rate'] - 1) < 1e-9, r
        assert r['none'] == 0 and abs(r['wait'] - 0.5 / 60) < 1e-9, r
        assert r['stall'] == r['cap'] and r['after'] == 1, r
        assert 0.2 < r['slow'] < 0.3, r
        assert r['restart'] == 0 and r['later'] == 3, r
        assert errors == []
    finally:
        context.close()


def test_the_worker_keeps_time_while_the_page_draws_nothing(browser):
    """The Worker steps on its own clock: with no animation frame on the page (a drawing
    stalled), the simulation still moves on; paused, it stops."""
    stop_frames = 'window.requestAnimationFrame = function () { return 0; };'
    context, page, errors = open_worker_page(browser, '?preset=corners')
    try:
        page.evaluate(stop_frames)
        page.evaluate('clothApp.advance(0)')
        before = page.evaluate('clothApp.info().frames')
        page.wait_for_function('(f) => clothApp.info().frames > f + 30', arg=before)
        page.evaluate('clothApp.setPaused(true)')
        page.evaluate('clothApp.advance(0)')
        paused = page.evaluate('clothApp.info().frames')
        page.wait_for_timeout(300)
        page.evaluate('clothApp.advance(0)')
        assert page.evaluate('clothApp.info().frames') == paused
        assert errors == []
    finally:
        context.close()
