"""Pointer input in a real browser: mouse, right-click pins, touch, devicePixelRatio 2."""
import json
import math
import time

import pytest

from browser_helpers import free_vertex, load_paused, near

from cloth.presets import PRESETS

COLS, ROWS = 40, 30      # the default preset (curtain)
TOL = 0.01               # CSS pixels: the held vertex sits exactly under the pointer


def settle(pg, frames=240):
    """Let the scene come to rest so that a vertex stays where state() saw it."""
    pg.js('(n) => clothApp.advance(n)', frames)


def drag_and_check(pg, k, path):
    """Press on vertex k (paused, so that it is where state() says), check that the
    nearest vertex was grabbed, then resume and move along path (client coords): after
    each move, with the simulation running, the held vertex must sit under the pointer."""
    was_paused = pg.info()['paused']
    pg.js('clothApp.setPaused(true)')
    st = pg.state()
    start = st['screen'][k]
    pg.mouse.move(start[0], start[1])
    pg.mouse.down()
    held = [i for i, h in enumerate(pg.state()['held']) if h]
    d2 = [(sx - start[0]) ** 2 + (sy - start[1]) ** 2 for sx, sy in st['screen']]
    assert len(held) == 1 and d2[held[0]] == min(d2), (held, k)
    k = held[0]
    pg.js('(p) => clothApp.setPaused(p)', was_paused)
    for x, y in path:
        pg.mouse.move(x, y, steps=4)
        pg.wait_for_timeout(60)  # a few animation frames of simulation while held
        st = pg.state()
        assert st['held'][k]
        assert near(st['hands'][k], (x, y), TOL), (st['hands'][k], (x, y))
    pg.mouse.up()
    return k


def test_mouse_drag_holds_vertex_under_cursor_then_releases(open_page):
    pg = open_page()
    settle(pg)
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    x, y = st['screen'][k]
    k = drag_and_check(pg, k, [(x + 80, y + 40), (x - 150, y + 60), (x - 20, y - 200)])
    st = pg.state()
    assert not st['held'][k] and not st['pinned'][k]
    pg.wait_for_function('clothApp.info().frames > 0')
    before = st['positions'][k]
    pg.js('clothApp.advance(30)')
    assert pg.state()['positions'][k] != before  # free again: it falls


def test_a_hand_takes_its_vertex_to_the_pointer_within_reach_and_not_beyond(open_page):
    # A drag is a hand of finite strength (cloth/hands.py HAND_FORCE): held still within the
    # cloth's reach the vertex comes to rest under the pointer; pulled down past where the
    # hanging cloth can reach, it stops short of the pointer: the fabric stretches only as far
    # as the hand's force takes it.
    pg = open_page()
    settle(pg)
    pg.js('clothApp.setPaused(true)')
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    x, y = st['screen'][k]
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 11):
        pg.mouse.move(x + 6 * i, y - 4 * i)
        pg.js('clothApp.advance(2)')
    pg.js('clothApp.advance(60)')
    st = pg.state()
    assert near(st['hands'][k], (x + 60, y - 40), TOL)
    assert near(st['screen'][k], (x + 60, y - 40), 1.0), (st['screen'][k], (x + 60, y - 40))
    pg.mouse.up()
    # Beyond reach, on the stiffest fabric of the Material menu (denim): the bottom of a
    # curtain hung from a rod is as far from the rod as the fabric lets it be, and a hand of at
    # most HAND_FORCE stretches it by centimetres, not to the pointer 1.2 m below (measured:
    # 3.4 cm from a curtain hung in denim from the start, 5-14 cm after a drag and the change
    # of fabric, each a balance of the same strain field: a tension-only cloth's slack parts
    # can rest in more than one place), its strain 3.5% at most.
    pg.select_option('#material', 'denim')
    pg.js('clothApp.advance(240)')
    st = pg.state()
    x, y = st['screen'][k]
    before = st['positions'][k]
    per_metre = math.dist(st['screen'][k], st['screen'][0]) / math.dist(before, st['positions'][0])
    # Down to 300 px below, or to the stage's bottom (a hand goes no farther than a few px
    # inside its panel).
    bottom = pg.js("document.getElementById('view').getBoundingClientRect().bottom")
    reach = min(300, bottom - 10 - y)
    assert reach > 100, (y, bottom)
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 11):
        pg.mouse.move(x, y + reach * i / 10)
        pg.js('clothApp.advance(2)')
    pg.js('clothApp.advance(60)')
    st = pg.state()
    assert near(st['hands'][k], (x, y + reach), TOL)
    drop = before[1] - st['positions'][k][1]
    assert 0 < drop < min(0.2, 0.5 * reach / per_metre), (drop, reach / per_metre)
    assert pg.js('clothApp.cloth().max_strain') < 0.05          # measured every frame the page runs
    pg.mouse.up()


def test_right_click_pins_and_the_vertex_holds_still(open_page):
    pg = open_page()
    settle(pg)
    pg.js('clothApp.setPaused(true)')
    st = pg.state()
    x, y = st['screen'][15 * COLS + 18]
    pg.mouse.click(x, y, button='right')
    after = pg.state()
    changed = [i for i, (p, q) in enumerate(zip(st['pinned'], after['pinned'])) if p != q]
    assert len(changed) == 1 and after['pinned'][changed[0]]
    k = changed[0]
    where = after['positions'][k]
    pg.js('clothApp.setPaused(false)')
    pg.wait_for_timeout(300)  # the loop runs
    pg.js('clothApp.advance(120)')
    assert pg.state()['positions'][k] == where
    # a second right-click unpins it
    x, y = pg.state()['screen'][k]
    pg.mouse.click(x, y, button='right')
    assert not pg.state()['pinned'][k]


def test_pinned_vertex_dragged_elsewhere_stays_there(open_page):
    # A hand on a pin moves it with the hand's finite force and leaves it fixed where it lets
    # go (cloth/hands.py). The Chain's clamp holds nothing but the chain: it goes where the
    # pointer takes it (its spring holds it within the chain's weight / HAND_STIFFNESS, 0.03 mm).
    pg = open_page('?preset=chain')
    st = pg.state()
    k = 0  # the clamp
    assert st['pinned'][k]
    x, y = st['screen'][k]
    target = (x + 120, y + 90)
    drag_and_check(pg, k, [target])
    pg.js('clothApp.advance(120)')
    st = pg.state()
    assert st['pinned'][k] and not st['held'][k]
    assert near(st['screen'][k], target, 0.1), (st['screen'][k], target)
    # The curtain's corner is held by the rod beside it: the hand's force takes it only part
    # of the way; let go, it stays exactly where the hand left it.
    pg.js("clothApp.usePreset('curtain')")
    st = pg.state()
    x, y = st['screen'][k]
    target = (x + 120, y + 90)
    drag_and_check(pg, k, [target])
    left = pg.state()['positions'][k]
    pg.js('clothApp.advance(120)')
    st = pg.state()
    assert st['pinned'][k] and not st['held'][k] and st['positions'][k] == left
    sx, sy = st['screen'][k]
    # it moved toward the pointer, along the drag
    along = ((sx - x) * 120 + (sy - y) * 90) / 150
    assert 10 < along < 150, (along, (sx, sy), (x, y))


def touch(cdp, kind, points, timestamp=None):
    event = {'type': kind, 'touchPoints': [{'x': x, 'y': y} for x, y in points]}
    if timestamp is not None:       # seconds; sets the events' timeStamp, whatever the load
        event['timestamp'] = timestamp
    cdp.send('Input.dispatchTouchEvent', event)


def test_touch_drag_and_double_tap_pin(open_page):
    pg = open_page(has_touch=True)
    settle(pg)
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    x, y = st['screen'][k]
    cdp = pg.context.new_cdp_session(pg.page)
    pg.js('clothApp.setPaused(true)')
    touch(cdp, 'touchStart', [(x, y)])
    held = [i for i, h in enumerate(pg.state()['held']) if h]
    assert len(held) == 1
    k = held[0]
    pg.js('clothApp.setPaused(false)')
    for i in range(1, 9):
        px, py = x + 12 * i, y - 9 * i
        touch(cdp, 'touchMove', [(px, py)])
    # Touch moves are handled at the page's next animation frame (Chromium aligns them to it),
    # which a busy machine can hold back past a fixed wait (CI, one run of many: the hand one
    # move behind): wait for the last one to arrive, up to 10 s.
    end = time.time() + 10
    st = pg.state()
    while not near(st['hands'][k] or (0, 0), (px, py), TOL) and time.time() < end:
        pg.wait_for_timeout(20)
        st = pg.state()
    assert st['held'][k] and near(st['hands'][k], (px, py), TOL)
    touch(cdp, 'touchEnd', [])
    assert not pg.state()['held'][k]

    # double-tap toggles the pin of the vertex under the finger
    pg.js('clothApp.setPaused(true)')
    before = pg.state()['pinned']
    x, y = pg.state()['screen'][free_vertex(pg.state(), COLS, ROWS) - 3]
    t0 = time.time()
    for i, kind in enumerate(('touchStart', 'touchEnd', 'touchStart', 'touchEnd')):
        # 50 ms apart in event time, however slow the machine is at delivering them
        touch(cdp, kind, [(x, y)] if kind == 'touchStart' else [], t0 + 0.05 * i)
    changed = [i for i, (a, b) in enumerate(zip(before, pg.state()['pinned'])) if a != b]
    assert len(changed) == 1 and pg.state()['pinned'][changed[0]]


def test_device_pixel_ratio_2_is_sharp_and_exact(open_page):
    pg = open_page(device_scale_factor=2)
    settle(pg)
    size = pg.js('() => { const c = document.getElementById("view");'
                 ' const r = c.getBoundingClientRect(); return [c.width, c.height, r.width, r.height]; }')
    assert size[0] == round(2 * size[2]) and size[1] == round(2 * size[3])
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    x, y = st['screen'][k]
    drag_and_check(pg, k, [(x + 33.5, y - 41.5), (x - 60, y + 20)])


def test_window_resize_resizes_the_canvas_and_refits(open_page):
    pg = open_page()
    w0 = pg.js('document.getElementById("view").width')
    pg.set_viewport_size({'width': 1300, 'height': 800})
    pg.wait_for_function('(w) => document.getElementById("view").width !== w', arg=w0)
    size = pg.js('() => { const c = document.getElementById("view");'
                 ' return [c.width, c.getBoundingClientRect().width]; }')
    assert size[0] == round(size[1])
    # the cloth still lies inside the canvas
    box = pg.js('() => document.getElementById("view").getBoundingClientRect().toJSON()')
    for sx, sy in pg.state()['screen']:
        assert box['left'] <= sx <= box['right'] and box['top'] <= sy <= box['bottom']


def test_keyboard_shortcuts(open_page):
    pg = open_page()
    pg.locator('#view').click(position={'x': 5, 'y': 5})
    pg.keyboard.press('Space')
    assert pg.info()['paused'] and pg.locator('#r-paused').is_visible()
    f = pg.info()['frames']
    pg.keyboard.press('s')
    assert pg.info()['frames'] == f + 1
    pg.keyboard.press('c')
    assert pg.info()['mode'] == 'stress'
    pg.keyboard.press('a')
    assert pg.info()['scaleMode'] == 'fixed'
    pg.keyboard.press(str([p[0] for p in PRESETS].index('chain') + 1))      # the presets' keys, in order
    assert pg.info()['preset'] == 'chain'
    pg.keyboard.press('r')
    assert pg.info()['frames'] == 0
    pg.keyboard.press('h')
    assert pg.locator('#help').is_visible()
    pg.keyboard.press('Escape')
    assert pg.locator('#help').is_hidden()
    pg.keyboard.press('Space')
    assert not pg.info()['paused']


# A drag through the page's own Pointer Events, one pointer type at a time (the drivers have
# no pen, and their touch and mouse go through the same handlers): from the held vertex's
# place the pointer rises to a circle above it and goes round, a frame between moves; after
# every frame, how far the held vertex is from the pointer (CSS px). Above the vertex is
# toward slack, within reach on every preset.
FOLLOW = '''([k, kind, path]) => {
  const c = document.getElementById('view'), st = clothApp.state(), at = st.screen[k];
  const ev = (type, px, py, buttons) => c.dispatchEvent(new PointerEvent(type, {
    pointerId: 7, pointerType: kind, isPrimary: true, button: type === 'pointermove' ? -1 : 0,
    buttons: buttons, clientX: px, clientY: py, bubbles: true, pressure: 0.5}));
  ev('pointerdown', at[0], at[1], 1);
  if (!clothApp.state().held[k]) return -1;
  let worst = 0;
  for (const [dx, dy] of path) {
    const px = at[0] + dx, py = at[1] + dy;
    ev('pointermove', px, py, 1);
    clothApp.advance(1, true);
    const s = clothApp.state().screen[k];
    worst = Math.max(worst, Math.hypot(s[0] - px, s[1] - py));
  }
  ev('pointerup', at[0] + path[path.length - 1][0], at[1] + path[path.length - 1][1], 0);
  return worst; }'''


def circle_path(radius, speed, laps=1):
    """Up from the start to a circle of `radius` px centred 1.25 radii above it, then round it
    `laps` times, `speed` px a frame all along."""
    rise = 0.25 * radius
    path = [(0.0, -rise * i / max(1, int(rise / speed))) for i in range(1, max(1, int(rise / speed)) + 1)]
    step = speed / radius
    angle = math.pi / 2
    for _ in range(int(laps * 2 * math.pi / step)):
        angle += step
        path.append((radius * math.cos(angle), -1.25 * radius + radius * math.sin(angle)))
    return path


def worst_lag(pg, kind, speed, cases=('curtain', 'chain', 'corners', 'towel')):
    """{case: the farthest the held vertex was from the pointer after a frame} for each case:
    a preset at its own grid, or (preset, n) on an n x n grid (the page's Columns and Rows)."""
    out = {}
    for case in cases:
        name, n = (case, None) if isinstance(case, str) else case
        pg.select_option('#preset', name)
        if n:
            pg.js('(n) => { clothApp.setParam("cols", n); clothApp.setParam("rows", n); }', n)
        # A second after the start (the cloth still swings from its fall, as when a person grabs
        # it at once): the lags are those after 240 frames within 0.1 px at 8 px a frame.
        pg.js('clothApp.setPaused(true)')
        pg.js('clothApp.advance(60)')
        cols, rows = pg.js('[clothApp.cloth().cols, clothApp.cloth().rows]')
        k = (rows - 1) * cols + cols // 2 if rows > 1 else cols - 1
        out[case] = pg.js(FOLLOW, [k, kind, circle_path(40.0, speed)])
    return out


@pytest.mark.parametrize('kind', ['mouse', 'touch', 'pen'])
def test_within_reach_the_held_vertex_is_under_the_pointer_after_every_frame(open_page, kind):
    """Issue #40: a hand is a stiff, damped attachment of its grip to the pointer; within reach
    the held vertex is under the pointer after every frame, within 1.5 px: round a circle of
    40 px above its place at 8 px a frame (480 px/s), on a curtain's hem, a chain's end
    (which a flick toward slack once left 175 px behind), Two corners' and the towel's."""
    lags = worst_lag(open_page(), kind, 8.0)
    assert all(0 <= v <= 1.5 for v in lags.values()), (kind, lags)


def test_within_reach_the_held_vertex_follows_on_finer_grids(open_page):
    """The same at 8 px a frame on finer grids, where one coarse correction a step must carry
    the hand's pull through the cloth: it trailed 31.6 px on Two corners at 120x120 while the
    correction's Hessian held a far hand's patch as by a stiff spring (cloth/vbd.py, assemble),
    and 1.6 px at a 200x200 chain's free corner before the sweeps near a hand (NEAR_SWEEPS)."""
    lags = worst_lag(open_page(), 'mouse', 8.0, (('towel', 60), ('curtain', 120), ('corners', 120),
                                                 ('chain', 200)))
    assert all(0 <= v <= 1.5 for v in lags.values()), lags


def test_a_fast_flick_within_reach_is_followed_within_a_pixel_and_a_half(open_page):
    """At 20 px a frame (1,200 px/s, 4-6 m/s at the presets' scales) round the same circle. A
    hand that starts or turns this fast leaves the step's first guess centimetres from its aim:
    it trailed 1.4 px on the curtain, 1.7 px on Two corners and 2.9 px on the towel at 60x60
    before each grip's guess went where its own terms of the step are least (cloth/hands.py).
    Not the flag: at this speed its wind and the flick together pull harder than the hand's
    20 N, and on the exact steps its held vertex trails 2.6 px (beyond reach, as it should be)."""
    lags = worst_lag(open_page(), 'mouse', 20.0, ('curtain', 'chain', 'corners', ('towel', 60)))
    assert all(0 <= v <= 1.5 for v in lags.values()), lags


def test_a_fast_flick_on_a_fine_grid_is_followed_within_a_pixel_and_a_half(open_page):
    """The same flick on 120x120 grids, where the scene's budget leaves the cloth between the
    grip and the coarse grid's scale behind: 2.9 px on the curtain, 6.1 px on Two corners and
    5.5 px on the towel before a held cloth's steps got one more correction and the sweeps near
    the hand (cloth/vbd.py, NEAR_SWEEPS); and the towel at 200x200, whose window's reach of 30
    vertices 40 sweeps left 1.66 px behind (now two sweeps a vertex of reach)."""
    lags = worst_lag(open_page(), 'mouse', 20.0, (('curtain', 120), ('corners', 120), ('towel', 120),
                                                  ('towel', 200)))
    assert all(0 <= v <= 1.5 for v in lags.values()), lags
