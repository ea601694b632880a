"""Pixels from the real WebGL renderer (SwiftShader colours are exact), context loss,
the WebGL 1 path and the no-WebGL message."""
import json
import time

import pytest

from browser_helpers import BACKGROUND_MAX, load_paused

from cloth.keys import MODEL
from cloth.measure import BINS_PER_DECADE
from cloth.presets import PRESETS, preset_scene

# Four vertices in a row, 1 m apart, all pinned, no gravity: nothing moves unless dragged.
ROW = {'model': MODEL, 'cols': 4, 'rows': 1, 'spacing': 1.0, 'pins': [0, 1, 2, 3], 'gravity': [0, 0],
       'solver': 'jakobsen'}


def stretched_row(pg, lift_px=60, drag_px=0):
    """Load ROW, then drag the pinned end vertex 3 up (and right) for a frame (the seed's hand
    puts what it grips where it holds it) and let go, leaving it pinned there: edge 2-3
    stretches, edges 0-1 and 1-2 keep their rest length. Returns state()."""
    load_paused(pg, json.dumps(ROW))
    x, y = pg.state()['screen'][3]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + drag_px, y - lift_px, steps=3)
    pg.js('clothApp.advance(1)')
    pg.mouse.up()
    return pg.state()


def along(st, a, b, t):
    (xa, ya), (xb, yb) = st['screen'][a], st['screen'][b]
    return xa + t * (xb - xa), ya + t * (yb - ya)


def brightest(pg, centre, r=3):
    """The pixel with the largest channel sum in a (2r+1)^2 window: the line's core,
    where the antialiasing coverage is 1."""
    cx, cy = centre
    pts = [[cx + dx, cy + dy] for dx in range(-r, r + 1) for dy in range(-r, r + 1)]
    px = pg.js('(p) => clothApp.pixels(p)', pts)
    return max(px, key=lambda c: (c[0] + c[1] + c[2], c[0]))


def test_strain_mode_brightness_grows_with_strain(open_page):
    pg = open_page()
    st = stretched_row(pg, lift_px=60)
    diff = pg.js('() => Array.from(clothApp.cloth().edge_value)')     # the seed's |diff|
    assert diff[0] == 0 and diff[1] == 0 and diff[2] > 0.01
    pg.js("clothApp.setColorMode('strain')")
    # auto scale: the most strained edge is (nearly) full red, an unstrained one the dim base
    # red. Auto's top is the upper edge of the histogram bin the edges' 99% value falls in
    # (cloth/measure.py): here the largest value's, at most a bin (10^(1/32)) above it.
    pg.js("clothApp.setScaleMode('auto')")
    rest = brightest(pg, along(st, 0, 1, 0.5))
    hot = brightest(pg, along(st, 2, 3, 0.5))
    base = pg.js('() => clothRenderer.STRAIN_BASE')   # the red of an unstrained edge
    scale = pg.info()['scale']
    assert 0 < base < 0.5
    assert diff[2] <= scale <= diff[2] * 10 ** (1 / BINS_PER_DECADE), (diff[2], scale)
    assert hot[1] == hot[2] == 0 and rest[1] == rest[2] == 0, (hot, rest)
    assert abs(hot[0] - round(255 * (base + (1 - base) * diff[2] / scale))) <= 1, (hot, scale)
    assert abs(rest[0] - round(255 * base)) <= 1
    # fixed scale: red = base + (1 - base) * |diff| / full_scale, linear in |diff|
    full = diff[2] * 2
    pg.js('(f) => clothApp.setScaleMode("fixed", f)', full)
    half = brightest(pg, along(st, 2, 3, 0.5))
    assert abs(half[0] - round(255 * (base + (1 - base) * 0.5))) <= 2, half
    # drag further: the more stretched edge is brighter still
    st2 = stretched_row(pg, lift_px=60, drag_px=120)
    pg.js('(f) => clothApp.setScaleMode("fixed", f)', full)
    diff2 = pg.js('() => Array.from(clothApp.cloth().edge_value)')[2]
    assert diff2 > diff[2]
    more = brightest(pg, along(st2, 2, 3, 0.5))
    assert more[0] > half[0]


def test_stress_mode_goes_from_blue_to_red(open_page):
    pg = open_page()
    st = stretched_row(pg, lift_px=80)
    pg.js("clothApp.setScaleMode('auto')")
    pg.js("clothApp.setColorMode('stress')")
    # node Q: 0 at vertices 0 and 1, half the max at 2, the max at 3
    cold = brightest(pg, along(st, 0, 1, 0.5))
    warm = brightest(pg, along(st, 2, 3, 0.85))
    mid = brightest(pg, along(st, 1, 2, 0.5))
    assert cold[2] >= 250 and cold[0] <= 2, cold                 # pure blue
    assert warm[0] > 200 and warm[2] < 50, warm                  # nearly red
    assert 0 < mid[0] < mid[2] and abs(mid[0] + mid[2] - 255) <= 2, mid  # on the blue-red line
    # the legend says so at its next refresh (the readouts', every 250 ms)
    pg.wait_for_function('() => /stress/.test(document.getElementById("legend-title").textContent)')


def test_default_scene_draws_both_modes(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(60)')
    pts = [p for i, p in enumerate(pg.state()['screen']) if i % 7 == 0]
    reds = pg.js('(p) => clothApp.pixels(p)', pts)
    assert sum(1 for c in reds if c[0] > 60 and c[2] == 0) > len(pts) // 2
    pg.js("clothApp.setColorMode('stress')")
    cols = pg.js('(p) => clothApp.pixels(p)', pts)
    assert any(c[2] > 100 for c in cols)


def lose_context(pg):
    """Lose the page's WebGL context (window.__lose restores it)."""
    pg.js('''() => {
        const gl = document.getElementById('view').getContext('webgl2');
        window.__lose = gl.getExtension('WEBGL_lose_context');
        window.__lose.loseContext();
    }''')


def test_context_loss_and_restore(open_page):
    pg = open_page()
    lose_context(pg)
    pg.wait_for_function('clothApp.info().lost')
    assert 'context was lost' in pg.locator('#banner').inner_text()
    frames = pg.info()['frames']
    pg.wait_for_function('(f) => clothApp.info().frames > f', arg=frames)  # the loop survives
    pg.js('window.__lose.restoreContext()')
    pg.wait_for_function('!clothApp.info().lost && clothApp.info().restores === 1')
    assert pg.locator('#banner').is_hidden()
    pg.js('clothApp.setPaused(true)')
    pts = pg.state()['screen'][::5]
    px = pg.js('(p) => clothApp.pixels(p)', pts)
    assert sum(1 for c in px if c[0] > 60) > len(pts) // 2, 'nothing drawn after the restore'



def test_a_restored_context_clears_only_its_own_error(open_page):
    """The restore clears the banner that said the context was lost, and not an error shown
    since (the page keeps what its banner is about; it never reads the banner's text)."""
    pg = open_page()
    lose_context(pg)
    pg.wait_for_function('clothApp.info().lost')
    pg.js("() => { try { clothApp.loadScene('{\"cols\": -3}'); } catch (e) {} }")
    shown = pg.locator('#banner').inner_text()
    assert 'context was lost' not in shown and 'Scene not loaded' in shown, shown
    pg.js('window.__lose.restoreContext()')
    pg.wait_for_function('!clothApp.info().lost && clothApp.info().restores === 1')
    assert pg.locator('#banner').inner_text() == shown

def test_nothing_drawn_outlives_its_scene_while_the_context_is_lost(open_page):
    """The obstacles' layer (a 2D canvas over the cloth's) was cleared only by a drawing, and a
    lost WebGL context draws nothing: after Towel on a peg, the peg stayed over every preset
    loaded until the context came back, and the first load hid the lost context's banner.
    Lost, nothing of the old scene shows, and the banner stays until the context is back."""
    pg = open_page()
    pg.js("clothApp.usePreset('towel')")
    lit = """() => { const c = document.getElementById('obstacles'), d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        let n = 0; for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++; return n; }"""
    pg.js('clothApp.advance(1)')
    assert pg.js(lit) > 100
    lose_context(pg)
    pg.wait_for_function('clothApp.info().lost')
    for name in ('chain', 'large', 'flag'):
        pg.js('(n) => clothApp.usePreset(n)', name)
        assert pg.js('clothApp.obstacles(0)') == [] and pg.js(lit) == 0, name
        assert 'context was lost' in pg.locator('#banner').inner_text(), name
    pg.js('window.__lose.restoreContext()')
    pg.wait_for_function('!clothApp.info().lost && clothApp.info().restores === 1')
    assert pg.js(lit) == 0 and pg.locator('#banner').is_hidden()


def test_webgl1_path(open_page):
    pg = open_page('?webgl=1')
    info = pg.info()
    assert info['webgl'] == 1 and info['drawCalls'] == 2
    pg.js('clothApp.setPaused(true)')
    pts = pg.state()['screen'][::5]
    px = pg.js('(p) => clothApp.pixels(p)', pts)
    assert sum(1 for c in px if c[0] > 60) > len(pts) // 2


@pytest.mark.parametrize('size', [(12, 9), (60, 60)])
def test_webgl2_and_webgl1_draw_the_same_picture(open_page, size):
    """WebGL 2 draws the edges from a texture by gl_VertexID, WebGL 1 by instances
    (webgl/draw/renderer.js): the same quads, so the same pixels, read from the drawing buffer in
    the task that drew it (a canvas's toDataURL in Firefox gave the last frame composited, under
    load an older one) at the middle of every structural edge and every cell. At 60x60 the
    edges fill several of the texture's rows; the scene is pulled aside, so every edge has its
    own strain."""
    cols, rows = size
    scene = json.dumps(dict(model=MODEL, cols=cols, rows=rows, spacing=1.0 / (cols - 1), pins=[0, cols - 1],
                            actions=[{'frame': 1, 'op': 'grab', 'vertex': cols * rows - 1, 'to': [1.3, -0.4]}]))
    seen = []
    points = None
    for query in ('?paused=1', '?paused=1&webgl=1'):
        pg = open_page(query)
        # The view is fitted above the overlays' band as it is when a scene opens: after the
        # readouts have been written twice it is the same in both pages (before, under load,
        # one page had fitted the cloth 66 px to the side of the other).
        readouts = {pg.info()['fpsAt']}
        end = time.time() + 30
        while len(readouts) < 3 and time.time() < end:
            time.sleep(0.05)
            readouts.add(pg.info()['fpsAt'])
        load_paused(pg, scene)
        pg.js('clothApp.advance(20)')
        info = pg.info()
        assert info['webgl'] == (2 if query == '?paused=1' else 1) and info['drawCalls'] == 2, info
        if points is None:   # one view of one scene: the same points of the canvas in both
            at = pg.state()['screen']
            def mid(a, b, c=None, d=None):
                q = [at[a], at[b]] + ([at[c], at[d]] if c is not None else [])
                return [sum(p[0] for p in q) / len(q), sum(p[1] for p in q) / len(q)]
            points = ([mid(k, k + 1) for k in range(cols * rows) if (k + 1) % cols]
                      + [mid(k, k + cols) for k in range(cols * (rows - 1))]
                      + [mid(k, k + 1, k + cols, k + cols + 1) for k in range(cols * (rows - 1)) if (k + 1) % cols])
        seen.append(pg.js('(p) => clothApp.pixels(p)', points))
    a, b = seen
    assert sum(1 for c in a if c[0] > 40) > len(points) // 2     # the cloth is drawn there
    differ = [(p, x, y) for p, x, y in zip(points, a, b) if any(abs(u - v) > 2 for u, v in zip(x, y))]
    assert differ == [], (len(differ), differ[:5])


def test_no_webgl_shows_a_clear_message(open_page):
    pg = open_page('?webgl=0')
    assert pg.info()['webgl'] == 0
    msg = pg.locator('#fatal')
    assert msg.is_visible() and 'WebGL' in msg.inner_text()
    # the core still works without a renderer
    assert json.loads(pg.js('clothCore.run(\'{"cols":2,"rows":2,"spacing":1}\', 3)'))['frames'] == 3


@pytest.mark.parametrize('preset', [p[0] for p in PRESETS])
def test_presets_load_run_and_fit_the_view(open_page, preset):
    pg = open_page('?paused=1&preset=' + preset)
    pg.js('clothApp.advance(30)')
    info = pg.info()
    assert info['preset'] == preset and info['error'] == ''
    st = pg.state()
    assert all(v == v and abs(v) < 1e3 for p in st['positions'] for v in p)
    box = pg.js('() => document.getElementById("view").getBoundingClientRect().toJSON()')
    inside = sum(1 for sx, sy in st['screen']
                 if box['left'] <= sx <= box['right'] and box['top'] <= sy <= box['bottom'])
    assert inside == len(st['screen'])


def test_a_dense_cloth_shows_its_smooth_field_without_bands(open_page, n=150):
    """A curtain's strain falls smoothly from its rod to its hem (a column carries the weight
    below it). Drawn as edges thinner than a pixel and closer than two, the rows aliased with
    the pixel grid into bands every dozen rows; a dense grid is drawn as filled cells, so the
    red down the middle of the cloth falls row after row with no band, and it is as bright
    at the rod as the brightest edges there are (the Auto scale's 99%)."""
    from cloth.presets import preset_scene
    from cloth.fabrics import fabric
    obj = preset_scene('curtain', n, n)
    f = fabric('denim')
    obj['stretch'], obj['shear'], obj['density'] = f[2], f[3], f[4]
    pg = open_page(viewport={'width': 1000, 'height': 700})
    load_paused(pg, json.dumps(obj))
    pg.js('clothApp.advance(1500)')
    st = pg.state()
    x = st['screen'][n // 2][0]
    top, bottom = st['screen'][n // 2][1], st['screen'][(n - 1) * n + n // 2][1]
    assert bottom - top < 4 * n, 'the grid is not dense here'
    ys = list(range(int(top) + 8, int(bottom) - 3))   # below the pins' markers
    reds = [c[0] for c in pg.js('(p) => clothApp.pixels(p)', [[x + 0.5, y + 0.5] for y in ys])]
    rises = [(ys[i], reds[i], reds[i + 1]) for i in range(len(reds) - 1) if reds[i + 1] > reds[i] + 2]
    assert not rises, rises                       # down the cloth the red never comes back up
    assert reds[0] - reds[-1] > 40, (reds[0], reds[-1])


def test_a_cloth_folded_narrower_than_a_pixel_still_shows_its_strain(open_page):
    """Nothing of the cloth ever vanishes: the Chain on a 120x120 grid hangs from its 2 cm clamp
    and folds into a strip a few pixels wide whose filled cells, sheared flat, cover almost no
    pixel's centre: the strip showed as a faint line of the unstrained colour (as at 200x200;
    at 60x60 it was not drawn at all) though its top carries the whole weight. The filled
    cloth's outline is drawn as edges: down its upper half the strip shows its strain, brighter
    than an unstrained edge."""
    cols = 120
    pg = open_page('?paused=1')
    load_paused(pg, json.dumps(dict(preset_scene('chain', cols, cols), sleep=False)))
    pg.js('clothApp.advance(600)')
    st = pg.state()
    xs = [p[0] for p in st['screen']]
    assert max(xs) - min(xs) < 12, max(xs) - min(xs)        # folded: a few pixels wide
    unstrained = 255 * pg.js('() => clothRenderer.STRAIN_BASE')
    for r in range(cols // 13, cols // 2, cols // 13):
        x, y = st['screen'][r * cols]
        scan = pg.js('(p) => clothApp.pixels(p)', [[x + d, y] for d in range(-6, 7)])
        assert max(max(c[:3]) for c in scan) > unstrained + 30, (r, scan)
