"""Issue #16: the page in Firefox ESR and WebKitGTK (Safari's engine) as it is in Chromium.

Every test runs once per engine (the `engine` fixture, conftest.py). Where a Chromium test of
tests/browser/ needs nothing but the seam, a mouse and element text, it runs here unchanged
(engine_page.Page is that much of Playwright's Page); the rest is written for WebDriver:
integer pointer coordinates (so "under the pointer" means within 1 px), the page paused
while a press lands, one tab per engine.

What the drivers cannot synthesise is dispatched in the page as Pointer Events, and each test
says so: a pen in both (Firefox: "Unimplemented pointerMove for pointerType pen"; WebKit: a
pen's press arrives, its later moves and release do not), touch in WebKit (its driver sends
pointerType "touch" actions as mouse events). Dispatched events are untrusted, so the page's
setPointerCapture throws and is skipped (input.js); everything after the event is the same code.
"""
import json
import sys
import time

from browser_helpers import DIST, ROOT, free_vertex, default_preset_at, load_paused, page_url, png_rgb
import test_page
import test_recording_page as rec
import test_render
import test_obstacles_page as obstacles_page
import test_capture_page as capture_page
import test_layout_page as layout_page
import test_notes_page as notes_page
import test_readouts_page as readouts_page
from catalogue import CATALOGUE
from test_compare_page import PAIR

sys.path.insert(0, str(ROOT))
from cloth import api  # noqa: E402
from cloth.keys import MODEL  # noqa: E402
from cloth.scene import SceneError  # noqa: E402
sys.path.pop(0)

COLS, ROWS = 40, 30      # the default preset (curtain)
PX = 1.0                 # integer pointer coordinates: a held vertex is within 1 px of the pointer


def near(a, b, tol=PX):
    return abs(a[0] - b[0]) <= tol and abs(a[1] - b[1]) <= tol


def canvas_size(pg):
    return pg.js('''() => { const c = document.getElementById('view'); const r = c.getBoundingClientRect();
                          return {width: c.width, height: c.height, css: [r.width, r.height], dpr: devicePixelRatio,
                                  box: r.toJSON()}; }''')


def assert_sharp(pg):
    c = canvas_size(pg)
    assert c['width'] == round(c['css'][0] * c['dpr']) and c['height'] == round(c['css'][1] * c['dpr']), c
    return c


def wait_sharp(pg):
    """The drawing buffer follows the canvas's size at the next rendering update (the resize
    event and the ResizeObserver), not at once: wait for that, then assert_sharp."""
    pg.wait_for_function('''() => { const c = document.getElementById('view'); const r = c.getBoundingClientRect();
        return c.width === Math.round(r.width * devicePixelRatio) && c.height === Math.round(r.height * devicePixelRatio); }''',
                         timeout=5)


# ---- opens from file://, no error, no request -------------------------------------------------

def test_opens_from_file_with_no_error_and_no_request(open_page, tmp_path):
    """The shipped page, and a copy with the error hooks inlined before its own scripts (so an
    error or a blocked request while it loads is caught too; WebKit's driver has no log)."""
    from engine_page import HOOKS
    html = DIST.read_text(encoding='utf-8')
    csp = html.index('<meta http-equiv="Content-Security-Policy"')
    after = html.index('>', csp) + 1
    copy = tmp_path / 'index.html'
    copy.write_text(html[:after] + '<script>' + HOOKS + '</script>' + html[after:], encoding='utf-8')
    for pg in [open_page(url=copy.as_uri()), open_page(), open_page('?webgl=1&preset=chain')]:
        pg.wait_for_function('clothApp.info().frames > 5')
        info = pg.info()
        assert info['webgl'] in (1, 2) and not info['lost'] and info['drawCalls'] == 2, info
        assert info['error'] == '' and info['note'] == '' and pg.locator('#fatal').is_hidden()
        assert pg.errors() == [] and pg.requests() == []
    assert info['webgl'] == 1 and info['preset'] == 'chain'
    st = open_page().state()
    assert len(st['positions']) == COLS * ROWS == len(st['screen'])


def test_the_harness_sees_what_goes_wrong_in_the_page(open_page, engine):
    """The checks every test's teardown makes are not blind: a console.error, an uncaught
    error, an unhandled rejection and a request (which the page's CSP blocks) all show."""
    pg = open_page('?paused=1', expect_errors=True)
    pg.js('''() => {
        console.error('one console error');
        setTimeout(() => { throw new Error('one uncaught error'); }, 0);
        Promise.reject(new Error('one rejection'));
        new Image().src = 'https://example.invalid/pixel.png';
    }''')
    errors = pg.wait_for_function('window.__engineErrors.length >= 4 && window.__engineErrors')
    assert any(e.startswith('console.error: one console error') for e in errors), errors
    # WebKit mutes the message of every uncaught error of a file:// page, the page's own
    # scripts' too (tried: "Script error. (:0)"); the hook still sees that one happened.
    assert any(e.startswith('error: ') and ('one uncaught error' in e or engine.name == 'webkit') for e in errors), errors
    assert any(e.startswith('unhandledrejection: ') and 'one rejection' in e for e in errors), errors
    assert any(e.startswith('csp: img-src') and 'example.invalid' in e for e in errors), errors
    if engine.name == 'firefox':
        # Firefox writes its log when it gets to it: 200 ms was not always enough on a busy
        # machine (CI, one run of several), so wait for the line, up to 10 s.
        end = time.time() + 10
        while not ('JavaScript error: file://' in engine.log_text() and 'one uncaught error' in engine.log_text()) \
                and time.time() < end:
            pg.wait_for_timeout(50)
        assert 'JavaScript error: file://' in engine.log_text() and 'one uncaught error' in engine.log_text()


# ---- clothCore.run: the CLI's text, character for character ----------------------------------

BAD = test_page.MALFORMED + ['{"cols": 2, "rows": 2, "spacing": 1, "a\\nb": 1}',
                             '{"cols": 2, "rows": 2, "spacing": 1, "\\ud800\\ud83d\\ude00": 1}']


def cli_cases(cli_run):
    """[(scene text, frames, what the CLI gives: {'ok': text} or {'error': message})]: each
    CPython run made once a suite run (tests/conftest.py cli_run)."""
    cases = [(json.dumps(CATALOGUE[name][0]), CATALOGUE[name][1]) for name in sorted(CATALOGUE)]
    cases += [(text, 1) for text in BAD]
    cli_run.ahead(cases)
    out = []
    for text, frames in cases:
        try:
            out.append((text, frames, {'ok': cli_run(text, frames)}))
        except SceneError as e:
            out.append((text, frames, {'error': str(e)}))
    return out


def test_core_run_is_the_cli_character_for_character(open_page, cli_run):
    cases = cli_cases(cli_run)
    pg = open_page('?paused=1')
    got = pg.js('''(cases) => cases.map(([t, f]) => {
        try { return {ok: clothCore.run(t, f)}; }
        catch (e) { return {error: e instanceof Error ? e.message : 'not an Error: ' + String(e)}; } })''',
                [[text, frames] for text, frames, _ in cases])
    names = sorted(CATALOGUE) + BAD
    for name, (_, _, want), have in zip(names, cases, got):
        assert have == want, name
    assert sum('ok' in want for _, _, want in cases) == len(CATALOGUE)


def test_bad_scenes_give_the_cli_message_in_the_page(open_page):
    test_page.test_bad_scenes_give_the_cli_message_in_the_page(open_page)


# ---- drawing: both colour modes, pixels from the engine's own WebGL ----------------------------

def test_strain_mode_brightness_grows_with_strain(open_page):
    test_render.test_strain_mode_brightness_grows_with_strain(open_page)


def test_stress_mode_goes_from_blue_to_red(open_page):
    test_render.test_stress_mode_goes_from_blue_to_red(open_page)


def test_default_scene_draws_both_modes(open_page):
    test_render.test_default_scene_draws_both_modes(open_page)


def test_webgl1_path_and_no_webgl_message(open_page):
    test_render.test_webgl1_path(open_page)
    test_render.test_no_webgl_shows_a_clear_message(open_page)


def test_webgl2_and_webgl1_draw_the_same_picture(open_page):
    test_render.test_webgl2_and_webgl1_draw_the_same_picture(open_page, (60, 60))


def test_context_loss_and_restore(open_page):
    test_render.test_context_loss_and_restore(open_page)


def test_a_screenshot_shows_what_the_page_drew(open_page):
    """The composited window, not only readPixels: the canvas reaches the screen."""
    pg = open_page('?paused=1')
    pg.js('clothApp.advance(60)')
    pg.js("clothApp.setColorMode('stress')")
    st = pg.state()
    pts = [[round(x), round(y)] for i, (x, y) in enumerate(st['screen']) if i % 7 == 0]
    drawn = pg.js('(p) => clothApp.pixels(p)', pts)
    lit = [i for i, c in enumerate(drawn) if c[0] + c[2] > 120]
    assert len(lit) > len(pts) // 2
    for _ in range(10):       # the window shows a draw a frame or two after it was made
        pg.js('new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => done())))')
        width, height, bpp, rows = png_rgb(pg.engine.screenshot())
        assert (width, height) == (1000, 700)
        shot = [tuple(rows[y][x * bpp:x * bpp + 3]) for x, y in pts]
        same = sum(1 for i in lit if max(abs(a - b) for a, b in zip(shot[i], drawn[i][:3])) <= 8)
        if same >= 0.9 * len(lit):
            break
    assert same >= 0.9 * len(lit), (same, len(lit), [(shot[i], drawn[i]) for i in lit[:5]])


# ---- input: a real mouse ---------------------------------------------------------------------

def test_a_mouse_drag_keeps_the_vertex_under_the_pointer(open_page):
    pg = open_page('?paused=1')
    pg.js('clothApp.advance(240)')
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    x, y = pg.at(k)
    pg.mouse.move(x, y)
    pg.mouse.down()
    held = [i for i, h in enumerate(pg.state()['held']) if h]
    d2 = [(sx - x) ** 2 + (sy - y) ** 2 for sx, sy in st['screen']]
    assert len(held) == 1 and d2[held[0]] == min(d2), (held, k)
    k = held[0]
    assert pg.state()['positions'] == st['positions']          # a press moves nothing
    for px, py in [(x + 80, y + 40), (x - 150, y + 60), (x - 20, y - 200)]:
        pg.mouse.move(px, py, steps=4)
        pg.js('clothApp.advance(3)')                             # paused: frames run now
        s = pg.state()
        assert s['held'][k] and near(s['hands'][k], (px, py)), (s['hands'][k], (px, py))
    pg.js('clothApp.setPaused(false)')                           # and with the loop running
    pg.mouse.move(x + 30, y - 60, steps=4)
    pg.wait_for_timeout(150)
    s = pg.state()
    assert s['held'][k] and near(s['hands'][k], (x + 30, y - 60)), s['hands'][k]
    # pointer capture: off the canvas, over the panel, the pointer still drives the vertex,
    # along the stage's edge (a hand stays a few px inside its panel, so that what it leaves
    # can be reached again), and letting go there releases it
    pg.js('clothApp.setPaused(true)')
    box = canvas_size(pg)['box']
    out = (round(box['right']) + 60, y - 60)
    pg.mouse.move(*out, steps=4)
    pg.js('clothApp.advance(2)')
    s = pg.state()
    edge = (box['right'] - 8, y - 60)
    assert s['held'][k] and near(s['hands'][k], edge), (s['hands'][k], edge)
    pg.mouse.up()
    s = pg.state()
    assert not s['held'][k] and not s['pinned'][k]
    pg.js('clothApp.advance(30)')
    assert pg.state()['positions'][k] != s['positions'][k]      # free again: it falls


def test_right_click_pins_and_unpins(open_page, engine):
    """A free vertex right-clicked is pinned and holds still; a pinned one right-clicked is
    free and falls. In WebKit each right-click needs a session of its own (WebKit.pressed)."""
    pg = open_page('?paused=1')
    pg.js('clothApp.advance(240)')
    st = pg.state()
    k = 15 * COLS + 18
    pg.mouse.click(*pg.at(k), button='right')
    after = pg.state()
    changed = [i for i, (p, q) in enumerate(zip(st['pinned'], after['pinned'])) if p != q]
    assert changed == [k] and after['pinned'][k]
    assert after['positions'] == st['positions']            # a pin toggle moves nothing
    pg.js('clothApp.setPaused(false)')
    pg.wait_for_timeout(300)                                # the loop runs
    pg.js('clothApp.advance(120)')
    assert pg.state()['positions'][k] == after['positions'][k]

    engine.restart()
    pg = open_page('?paused=1')
    pg.js('clothApp.advance(240)')
    st = pg.state()
    assert st['pinned'][0]                                  # the curtain's corner
    pg.mouse.click(*pg.at(0), button='right')
    after = pg.state()
    assert not after['pinned'][0] and sum(after['pinned']) == sum(st['pinned']) - 1
    pg.js('clothApp.advance(30)')
    assert pg.state()['positions'][0] != st['positions'][0]     # free: it falls


def test_a_resize_keeps_the_canvas_sharp_and_the_held_vertex_under_the_pointer(open_page):
    pg = open_page('?paused=1')
    pg.js('clothApp.advance(60)')
    assert_sharp(pg)
    for size in [(1300, 800), (640, 480), (1000, 700)]:
        # nothing held: the canvas follows the window, sharp, and the cloth is refitted into it
        pg.window_size(*size)
        wait_sharp(pg)
        pg.js('clothApp.advance(1)')
        box = assert_sharp(pg)['box']
        for sx, sy in pg.state()['screen']:
            assert box['left'] <= sx <= box['right'] and box['top'] <= sy <= box['bottom'], (size, sx, sy)
    for size in [(800, 600), (1000, 700)]:
        # held through a resize: the vertex stays under the pointer
        k = free_vertex(pg.state(), COLS, ROWS)
        x, y = pg.at(k)
        pg.mouse.move(x, y)
        pg.mouse.down()
        k = pg.state()['held'].index(True)
        px, py = x + 20, y - 30
        pg.mouse.move(px, py)
        pg.window_size(*size)
        wait_sharp(pg)
        pg.js('clothApp.advance(3)')
        box = assert_sharp(pg)['box']
        assert box['left'] <= px <= box['right'] and box['top'] <= py <= box['bottom']
        assert near(pg.state()['hands'][k], (px, py)), (size, pg.state()['hands'][k], (px, py))
        pg.mouse.up()
        pg.js('clothApp.advance(60)')


def test_device_pixel_ratio_2_is_sharp_and_a_drag_exact(open_page, engine):
    """devicePixelRatio 2: Firefox's layout.css.devPixelsPerPx, WebKitGTK's GDK_SCALE (a new
    MiniBrowser)."""
    engine.device_scale(2)
    try:
        pg = open_page('?paused=1', size=(600, 450))
        assert pg.js('devicePixelRatio') == 2
        wait_sharp(pg)
        c = assert_sharp(pg)
        assert c['width'] >= 2 * int(c['css'][0])
        pg.js('clothApp.advance(240)')
        k = free_vertex(pg.state(), COLS, ROWS)
        x, y = pg.at(k)
        pg.mouse.move(x, y)
        pg.mouse.down()
        k = pg.state()['held'].index(True)
        # A press near a vertex grabs it where it is, keeping its offset from the pointer (the
        # press lands where state() said the vertex was; a layout that moved the canvas after
        # that, as a loaded machine once showed, leaves the press 10 px off it): the drag is
        # exact when the hand keeps that offset from the pointer, to a pixel.
        hx, hy = pg.state()['hands'][k]
        dx, dy = hx - x, hy - y
        assert abs(dx) < 30 and abs(dy) < 30, (dx, dy)
        for px, py in [(x + 33, y - 41), (x - 60, y + 20)]:
            pg.mouse.move(px, py)
            pg.js('clothApp.advance(2)')
            assert near(pg.state()['hands'][k], (px + dx, py + dy)), (pg.state()['hands'][k], (px + dx, py + dy))
        pg.mouse.up()
        px = pg.js('(p) => clothApp.pixels(p)', [[round(a), round(b)] for a, b in pg.state()['screen'][::9]])
        assert sum(1 for c in px if c[0] > 60) > len(px) // 2       # drawn at this scale too
    finally:
        engine.device_scale(1)


# ---- input: touch and pen ------------------------------------------------------------------

DISPATCH = '''([type, kind, id, x, y]) => {
    const down = type === 'pointerdown', up = type === 'pointerup';
    document.getElementById('view').dispatchEvent(new PointerEvent(type, {
        pointerId: id, pointerType: kind, isPrimary: true, button: type === 'pointermove' ? -1 : 0,
        buttons: up ? 0 : 1, clientX: x, clientY: y, bubbles: true, cancelable: true,
        pressure: up ? 0 : 0.5, width: 10, height: 10}));
}'''


class Finger:
    """A finger: WebDriver touch actions where the driver has them (Firefox), else Pointer
    Events dispatched in the page (WebKitGTK's driver sends touch actions as mouse events)."""

    def __init__(self, pg):
        self.pg, self.real = pg, pg.name == 'firefox'

    def _act(self, actions):
        self.pg.engine.actions([{'type': 'pointer', 'id': 'finger1', 'parameters': {'pointerType': 'touch'},
                                 'actions': actions}])

    def down(self, x, y):
        if self.real:
            self._act([{'type': 'pointerMove', 'x': x, 'y': y, 'origin': 'viewport', 'duration': 0},
                       {'type': 'pointerDown', 'button': 0}])
        else:
            self.pg.js(DISPATCH, ['pointerdown', 'touch', 21, x, y])
        self.x, self.y = x, y

    def move(self, x, y):
        if self.real:
            self._act([{'type': 'pointerMove', 'x': x, 'y': y, 'origin': 'viewport', 'duration': 0}])
        else:
            self.pg.js(DISPATCH, ['pointermove', 'touch', 21, x, y])
        self.x, self.y = x, y

    def up(self):
        if self.real:
            self._act([{'type': 'pointerUp', 'button': 0}])
        else:
            self.pg.js(DISPATCH, ['pointerup', 'touch', 21, self.x, self.y])

    def double_tap(self, x, y):
        if self.real:       # one action chain: the two taps land well within 350 ms
            tap = [{'type': 'pointerDown', 'button': 0}, {'type': 'pointerUp', 'button': 0}]
            self._act([{'type': 'pointerMove', 'x': x, 'y': y, 'origin': 'viewport', 'duration': 0}] + tap + tap)
        else:
            for _ in range(2):
                self.down(x, y)
                self.up()


def test_a_touch_drag_and_a_double_tap_pin(open_page):
    """Touch actions in Firefox, Pointer Events dispatched in the page in WebKit (Finger);
    the recording of both replays in the CLI bit for bit."""
    pg = open_page()
    rec.load_small(pg)                       # 12x9: the CLI replays it in a moment
    pg.js('clothApp.advance(120)')
    finger = Finger(pg)
    layouts = pg.info()['relayouts']
    x, y = pg.at(8 * 12 + 6)
    before = pg.state()
    finger.down(x, y)
    held = [i for i, h in enumerate(pg.state()['held']) if h]
    assert held == [8 * 12 + 6] and pg.state()['positions'] == before['positions']
    k = held[0]
    # The hand keeps its grip's offset and follows the finger from there. Measured from where
    # it took hold, not from the vertex's position read before the touch: in one CI run of
    # WebKit under load the hand was 12 px above the finger from the first move on, as when
    # the views are laid out again between that read and the touch (the vertex is then taken
    # with an offset, which is right); `relayouts` says whether that happened.
    hand = pg.state()['hands'][k]
    for i in range(1, 9):
        finger.move(x + 12 * i, y - 9 * i)
        pg.js('clothApp.advance(1)')
        s = pg.state()
        assert s['held'][k] and near(s['hands'][k], (hand[0] + 12 * i, hand[1] - 9 * i)), (
            s['hands'][k], hand, i, pg.info()['relayouts'] - layouts)
    finger.up()
    assert not pg.state()['held'][k]
    pg.js('clothApp.advance(60)')
    before = pg.state()
    x, y = pg.at(6 * 12 + 3)
    finger.double_tap(x, y)
    after = pg.state()
    changed = [i for i, (a, b) in enumerate(zip(before['pinned'], after['pinned'])) if a != b]
    assert len(changed) == 1 and after['pinned'][changed[0]]
    assert after['positions'] == before['positions']       # a tap moves nothing
    pg.js('clothApp.advance(10)')
    rec.assert_replays(pg)


def test_a_pen_drag_replays_exactly(open_page):
    """The pen's events are dispatched in the page in both engines (see the module's doc)."""
    rec.test_a_pen_drag_replays_exactly(open_page)


# ---- record, export, link, replay -------------------------------------------------------------

def test_record_export_link_and_replay_give_the_same_positions(open_page):
    """A real mouse drag and a right-click pin, recorded; the CLI runs the recording to the
    page's positions bit for bit; the Export button's download is the recording; the link,
    opened in a fresh page of the same engine, replays to the same doubles; so does Replay."""
    pg = open_page()
    end, text = rec.make_recording(pg)
    x, y = pg.at(5 * 12 + 4)
    pg.mouse.click(x, y, button='right')
    pg.js('clothApp.advance(20)')
    end, text = pg.state()['positions'], pg.js('clothApp.recording()')
    recording = rec.assert_replays(pg)
    ops = [a['op'] for a in recording['actions']]
    assert ops.count('grab') == 1 and ops.count('release') == 1 and ops.count('pin') == 1 and 'move' in ops

    assert pg.js('clothApp.recording()') == text               # the seam
    pg.key('e')          # Export, a real key (in WebKit no press may follow the right-click)
    saved = pg.wait_for_function('''() => /^Recording saved as cloth-custom-\\d+f\\.json/.test(clothApp.info().note)
                                         && clothApp.info().note''')
    name = saved.split('saved as ')[1].split(' ')[0]
    path = pg.engine.downloads / name
    for _ in range(100):
        if path.exists() and path.stat().st_size == len(text.encode()):
            break
        pg.wait_for_timeout(50)
    assert path.read_text(encoding='utf-8') == text, 'the %s download' % pg.name

    url = pg.js('clothApp.link()')
    assert url.startswith(page_url('#scene='))            # deflate-raw: CompressionStream
    other = open_page(url=url)
    other.wait_for_function('clothApp.info().replay.ended', timeout=60)
    assert other.info()['paused'] and other.info()['frames'] == recording['frames']
    assert other.state()['positions'] == end
    assert other.js('clothApp.recording()') == text

    other.js('clothApp.replay()')
    other.wait_for_function('clothApp.info().replay.ended', timeout=60)
    assert other.state()['positions'] == end
    assert other.js('clothApp.recording()') == text


def test_link_copies_the_address_from_a_key_and_from_the_button(open_page, engine, request):
    """The Link button (L) copies an address that replays the recording. Found here:
    writeText once the link was made, after CompressionStream's promise, was refused in WebKit
    (NotAllowedError: no longer the key press or click) and the page fell back to a prompt
    every time. share.copyLater writes a ClipboardItem whose text is a Promise of the link, in
    the handler itself, which all three engines allow."""
    outcomes = []
    for press in ['key', 'button']:
        pg = open_page('?paused=1')
        pg.js('clothApp.advance(5)')
        assert pg.info()['note'] == ''
        if press == 'key':
            pg.key('l')
        else:
            x, y = pg.locator('#btn-link').centre()
            pg.engine.actions([{'type': 'pointer', 'id': 'mouse1', 'parameters': {'pointerType': 'mouse'},
                                'actions': [{'type': 'pointerMove', 'x': x, 'y': y, 'origin': 'viewport', 'duration': 0},
                                            {'type': 'pointerDown', 'button': 0}, {'type': 'pointerUp', 'button': 0}]}])
        outcome = None
        for _ in range(60):
            pg.wait_for_timeout(50)
            text = pg.engine.prompt()
            if text is not None:
                outcome = 'a prompt: ' + text
                break
            note = pg.info()['note']
            if note.startswith('Link copied'):
                outcome = 'copied'
                break
        outcomes.append((press, outcome))
    assert outcomes == [('key', 'copied'), ('button', 'copied')], outcomes


def test_a_broken_or_truncated_link_says_so_and_shows_the_default(open_page):
    """A link cut short where base64url still decodes reaches the engine's DecompressionStream,
    which must reject it; the others are refused before it."""
    pg = open_page()
    rec.make_recording(pg)
    url = pg.js('clothApp.link()')
    data = url.split('#scene=')[1]
    cut = len(data) // 2
    while cut % 4 == 1:
        cut += 1
    for bad, words in [(url.split('#')[0] + '#scene=' + data[:cut], 'does not decompress'),
                       (url.split('#')[0] + '#scene=' + data[:4 * (len(data) // 8) + 1], 'cut short'),
                       (page_url('#scene=@@@'), 'base64url'),
                       (page_url('#scene-json=' + 'e30'), 'cols: missing')]:
        other = open_page(url=bad)
        other.wait_for_function('!clothApp.info().linkPending')
        info = other.info()
        assert words in info['error'] and 'link could not be opened' in info['error'], (words, info['error'])
        assert info['preset'] == 'curtain'


def test_open_a_file_by_the_picker_and_by_a_drop(open_page, tmp_path):
    """The picker through WebDriver's file input; the drop as a DragEvent dispatched in the page
    (neither driver drags files from outside the browser)."""
    rec.test_open_a_file_by_the_picker_and_by_a_drop(open_page, tmp_path)


# ---- compare mode (#14) and the blade (#15) ----------------------------------------------------

def test_compare_mode(open_page):
    """The Seed vs default pair: a real mouse drag in panel 2 holds the hand under the pointer
    there, and panel 1's hand moves by the same displacement (the seed's method puts the vertex
    at it); the recording replays each panel in the CLI. The default preset at 20x15 (CPython's
    replay of it at 40x30 took 10 s an engine)."""
    pg = open_page('?paused=1')
    load_paused(pg, default_preset_at(20, 15))
    assert pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.js('clothApp.advance(30)')
    k = 14 * 20 + 10
    x, y = (round(v) for v in pg.js('(k) => clothApp.panels()[1].screen[k]', k))
    pg.mouse.move(x, y)
    pg.mouse.down()
    for px, py in [(x + 40, y - 30), (x + 70, y - 80)]:
        pg.mouse.move(px, py, steps=3)
        pg.js('clothApp.advance(2)')
        ps = pg.js('clothApp.panels()')
        assert near(ps[1]['hands'][k], (px, py)), (ps[1]['hands'][k], (px, py))
        # the same hand in both panels: the seed's method puts its vertex there exactly
        assert near(ps[0]['screen'][k], ps[0]['hands'][k])
    pg.mouse.up()
    pg.js('clothApp.advance(10)')
    text = pg.js('clothApp.recording()')
    ps = pg.js('clothApp.panels()')
    assert json.loads(text)['compare'] == PAIR
    for i in range(2):
        assert json.loads(api.run(text, None, False, i))['positions'] == ps[i]['positions'], i
    assert pg.js('clothApp.compare([])') and pg.info()['panels'] == 1


def test_the_blade_cuts(open_page):
    """The Cut tool (the X key) and a real mouse drag: the edges the pointer's path crosses
    break, the cuts are recorded, and the recording replays in CPython (Alt+drag is the same
    code with the tool off; WebDriver's modifier keys are not needed for it)."""
    pg = open_page('?paused=1')
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 14, 'rows': 10, 'spacing': 0.1, 'pins': [0, 4, 9, 13], 'damping': 1}))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(30)')
    pg.key('x')
    assert pg.info()['cutTool']
    st = pg.state()['screen']
    y = round((st[4 * 14][1] + st[5 * 14][1]) / 2)
    x0, x1 = round(st[4 * 14][0]) - 30, round(st[4 * 14 + 13][0]) + 30
    pg.mouse.move(x0, y)
    pg.mouse.down()
    pg.mouse.move(x1, y, steps=6)
    pg.mouse.up()
    # every edge between rows 4 and 5: 14 structural ones and both diagonals of 13 cells
    assert pg.info()['broken'] == 14 + 2 * 13 and not any(pg.state()['held'])
    pg.js('clothApp.advance(20)')
    text = pg.js('clothApp.recording()')
    assert [a['op'] for a in json.loads(text)['actions']].count('cut') >= 1
    assert json.loads(api.run(text))['positions'] == pg.state()['positions']
    pg.key('r')
    assert pg.info()['broken'] == 0



def test_an_obstacle_is_drawn_dragged_through_the_cloth_and_replays(open_page):
    obstacles_page.test_an_obstacle_is_drawn_dragged_through_the_cloth_and_replays(open_page)


def test_picture_is_the_stage_at_device_pixels(open_page):
    capture_page.test_picture_is_the_stage_at_device_pixels(open_page)


def test_video_records_the_stage_or_says_why_not(open_page):
    capture_page.test_video_records_the_stage_or_says_why_not(open_page)


def test_the_wind_and_gusts_fields_set_the_air_live_and_record_it(open_page):
    obstacles_page.test_the_wind_and_gusts_fields_set_the_air_live_and_record_it(open_page)


# ---- issue #41: honest readouts, limits at once, true notes, every control on screen -----------

def test_fps_is_frames_over_time_not_a_mean_of_one_over_gap(open_page):
    readouts_page.test_fps_is_frames_over_time_not_a_mean_of_one_over_gap(open_page)


def test_fps_readout_is_the_rate_of_frames_counted_in_the_page(open_page):
    readouts_page.rates_match(open_page('?paused=1'), [('chain', 10), ('large', 200)])


def test_the_replay_note_reads_true_for_any_frames_a_scene_holds(open_page):
    notes_page.test_the_replay_note_reads_true_for_any_frames_a_scene_holds(open_page)
    notes_page.test_a_link_whose_scene_holds_no_frames_says_it_runs_live(open_page)


# A laptop's size; the other laptop's and the phones' run in Chromium
# (tests/browser/test_layout_page.py: a Firefox or WebKit window here stays wider than a phone,
# 500 and 447 px at least). The Scene JSON box's paste and drop run there too: these drivers
# give a page no clipboard or drag data.
def test_every_control_and_readout_is_on_screen_and_uncovered(open_page):
    size = layout_page.SIZES[0]
    layout_page.walk(open_page('?paused=1', size=size), size)
