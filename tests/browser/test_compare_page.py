"""Issue #14 in the page: solvers side by side under the same hands, one colour scale, live
charts, compare mode recorded and replayed per panel. Real pointer input (Playwright's mouse,
touch through CDP); the CLI's `--panel N` replays each panel."""
import json
import subprocess
import sys

import pytest

from browser_helpers import ROOT, load_paused, wait_until

from cloth.api import run
from cloth.keys import MODEL, spec
from cloth.presets import preset_scene
from cloth.keys import SOLVERS, SOLVER_BUDGETS, DEFAULT_SOLVER, SEED_SOLVER


def budget(name):
    return SOLVER_BUDGETS[SOLVERS.index(name)]


# The Seed vs default pair, each solver with its own steps (the button's pair).
PAIR = [{'solver': SEED_SOLVER, 'substeps': budget(SEED_SOLVER)[0], 'iterations': budget(SEED_SOLVER)[1]},
        {'solver': DEFAULT_SOLVER, 'substeps': budget(DEFAULT_SOLVER)[0], 'iterations': budget(DEFAULT_SOLVER)[1]}]
COLS, ROWS = 40, 30           # the curtain preset
BOTTOM = 29 * 40 + 20


def panels(pg):
    return json.loads(pg.js('JSON.stringify(clothApp.panels())'))     # (as text: see conftest.Page.state)


def cli(text, *args):
    done = subprocess.run([sys.executable, '-m', 'cloth', 'run', '-', *args], cwd=ROOT,
                          input=text.encode(), capture_output=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_seed_vs_default_in_one_click_and_back(open_page):
    pg = open_page()
    single = pg.state()['positions']
    pg.locator('#btn-compare-pair').click()
    ps = panels(pg)
    # Each panel says its solver and steps (and, where the solver honours it, the fabric: the
    # presets hang in jersey); the seed's method ignores the fabric, so its label leaves it out.
    seed, default = budget(SEED_SOLVER), budget(DEFAULT_SOLVER)
    assert [p['label'] for p in ps] == ['jakobsen S%d x %d' % (seed[0], seed[1]),
                                        'vbd S%d x %d +%d, jersey' % tuple(default)]
    assert json.loads(ps[0]['scene'])['iterations'] == seed[1] and 'compare' not in json.loads(ps[0]['scene'])
    assert pg.info()['panels'] == 2 and len(pg.locator('.panel-label:visible').all()) == 2
    # side by side or stacked, whichever fits the stage better: the cloths do not overlap
    def box(p):
        xs, ys = [x for x, _ in p['screen']], [y for _, y in p['screen']]
        return min(xs), min(ys), max(xs), max(ys)
    a, b = box(ps[0]), box(ps[1])
    assert a[2] < b[0] or a[3] < b[1]
    pg.locator('#btn-compare-off').click()
    assert pg.info()['panels'] == 1 and len(pg.state()['positions']) == len(single)
    assert len(pg.locator('.panel-label:visible').all()) == 0


def test_a_drag_in_panel_2_moves_the_same_vertex_by_the_same_displacement_in_panel_1(open_page):
    pg = open_page()
    pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(60)')
    start = panels(pg)
    x, y = start[1]['screen'][BOTTOM]
    x0, y0 = start[0]['screen'][BOTTOM]
    # the seed's cloth hangs lower: a hand that took panel 2's point would jump panel 1's vertex
    assert abs(y0 - start[0]['screen'][0][1] - (y - start[1]['screen'][0][1])) > 3
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.js('clothApp.setPaused(false)')
    seed, default = [], []
    for i in range(1, 12):
        pg.mouse.move(x + 6 * i, y - 4 * i)
        pg.wait_for_timeout(40)
        ps = panels(pg)
        # One hand in every panel: under the pointer in the panel pressed, and the same
        # displacement from where its vertex was in the other (the panels share one scale).
        # The seed's method puts the vertex at the hand; the default's hand of finite strength
        # takes it there as its cloth lets it.
        assert abs(ps[1]['hands'][BOTTOM][0] - (x + 6 * i)) < 0.01
        assert abs(ps[1]['hands'][BOTTOM][1] - (y - 4 * i)) < 0.01
        assert abs(ps[0]['hands'][BOTTOM][0] - (x0 + 6 * i)) < 0.01
        assert abs(ps[0]['hands'][BOTTOM][1] - (y0 - 4 * i)) < 0.01
        assert abs(ps[0]['screen'][BOTTOM][0] - ps[0]['hands'][BOTTOM][0]) < 0.01
        assert abs(ps[0]['screen'][BOTTOM][1] - ps[0]['hands'][BOTTOM][1]) < 0.01
        seed.append(ps[0]['rms_strain'])
        default.append(ps[1]['rms_strain'])
    # over the drag the seed's 20 sweeps stretch more than the default (measured on this
    # curtain: about 0.034 against 0.014; at the first frames of a fast jerk the default's
    # strain can spike above the seed's, so the mean over the drag is what is compared)
    assert sum(seed) > 1.5 * sum(default), (seed, default)
    pg.mouse.up()
    rec = json.loads(pg.js('clothApp.recording()'))
    ops = [a for a in rec['actions'] if a.get('vertex') == BOTTOM]
    assert ops[0] == {'frame': ops[0]['frame'], 'op': 'grab', 'vertex': BOTTOM}
    assert all('by' in a and 'to' not in a for a in ops if a['op'] == 'move') and ops[-1]['op'] == 'release'


def untouched(text):
    """A recording without its gestures: the same scene and frames, nobody's hands."""
    rec = json.loads(text)
    rec.pop('actions', None)
    return json.dumps(rec)


@pytest.mark.parametrize('hold_frames', [0, 1, 20])
def test_a_tap_in_one_panel_moves_nothing_in_any_panel(open_page, hold_frames):
    """A press and a release with no motion, let go at once or after a hand held still, in
    the third of three panels that hang differently: the default's panels go on bit for bit as
    if untouched; the seed's (a kinematic hold) moves nothing but catches the vertex."""
    pg = open_page()
    # the Curtain on a 16x12 grid: the CLI replays its three panels in seconds
    load_paused(pg, json.dumps(dict(preset_scene('curtain', 16, 12), compare=PAIR + [{'solver': 'xpbd'}])))
    bottom = 11 * 16 + 8
    pg.js('clothApp.advance(40)')          # still settling: every panel's cloth is moving
    x, y = panels(pg)[2]['screen'][bottom]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.js('(n) => clothApp.advance(n)', hold_frames)
    pg.mouse.up()
    pg.js('clothApp.advance(40)')
    text = pg.js('clothApp.recording()')
    assert [a['op'] for a in json.loads(text)['actions']] == ['grab', 'release']
    ps = panels(pg)
    for i in range(3):
        alone = json.loads(run(untouched(text), None, False, i))['positions']     # the CLI's --panel
        worst = max(abs(a - b) for p, q in zip(ps[i]['positions'], alone) for a, b in zip(p, q))
        # Let go at once: a touch restarts the default's sleep countdown, so a cloth about to
        # sleep settles a few frames longer (measured 1.7e-10 m); the seed's tap stops its
        # vertex (1.4e-5 m). A hand held still holds its vertex still for those frames.
        # Before the fix every panel's vertex went to the pressed panel's point: 0.1-0.2 m.
        assert worst < (1e-3 if hold_frames == 0 else 0.02), (i, worst)
        if i == 1 and hold_frames == 0:
            assert ps[i]['positions'] == alone       # moving, far from sleep: to the bit


def test_one_scale_is_the_largest_over_the_panels(open_page):
    pg = open_page()
    pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.js('clothApp.setPaused(true)')
    x, y = panels(pg)[0]['screen'][BOTTOM]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 60, y + 80, steps=4)      # pulled beyond reach: both strain
    pg.js('clothApp.advance(5)')
    # Auto's top: the edges' 99% value in the strain mode (cloth/measure.py HIGH_SHARE), the
    # largest node stress in the stress mode; over the panels, the largest.
    for mode, key in [('strain', 'high_value'), ('stress', 'max_stress')]:
        pg.js('(m) => clothApp.setColorMode(m)', mode)
        pg.js('clothApp.advance(1)')
        ps = panels(pg)
        assert ps[0][key] != ps[1][key]
        assert pg.info()['scale'] == max(ps[0][key], ps[1][key], pg.info()['autoFloor']), mode
    pg.mouse.up()


def test_a_pin_toggled_in_one_panel_shows_in_all(open_page):
    pg = open_page()
    pg.js('(l) => clothApp.compare(l.concat([{"substeps": 2}]))', PAIR)
    pg.js('clothApp.setPaused(true)')
    k = 15 * COLS + 18
    x, y = panels(pg)[2]['screen'][k]
    pg.mouse.click(x, y, button='right')
    ps = panels(pg)
    assert [p['pinned'][k] for p in ps] == [True, True, True]
    before = [p['positions'][k] for p in ps]
    pg.js('clothApp.advance(60)')
    assert [p['positions'][k] for p in panels(pg)] == before   # it holds still in every panel
    x, y = panels(pg)[0]['screen'][k]
    pg.mouse.click(x, y, button='right')
    assert [p['pinned'][k] for p in panels(pg)] == [False, False, False]


def test_the_charts_draw(open_page):
    pg = open_page()
    pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.wait_for_timeout(1500)                 # samples every 100 ms while running
    lit = pg.js('''() => { const c = document.getElementById('charts');
        const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
        const seen = {};
        for (let i = 0; i < d.length; i += 4) {
          if (d[i + 3] === 0) continue;
          const key = d[i] + ',' + d[i + 1] + ',' + d[i + 2];
          seen[key] = (seen[key] || 0) + 1;
        }
        return seen; }''')
    # each panel's colour is drawn (line pixels in the panel's colour, from the chart code)
    def near(rgb, hexcolor):
        r, g, b = (int(hexcolor[i:i + 2], 16) for i in (1, 3, 5))
        return abs(rgb[0] - r) + abs(rgb[1] - g) + abs(rgb[2] - b) < 40
    colours = pg.js('[0, 1].map(i => window.clothCharts.COLORS[i])')
    for colour in colours:
        hits = sum(n for key, n in lit.items() if near([int(v) for v in key.split(',')], colour))
        assert hits > 20, colour
    # a frame stepped by hand while paused is charted at once (the titles show it)
    pg.js('clothApp.setPaused(true)')
    pg.locator('#gravity').fill('-60')
    pg.locator('#gravity').press('Enter')
    pg.locator('#view').click(position={'x': 5, 'y': 5})
    for _ in range(5):
        pg.keyboard.press('s')
        got = pg.info()['chartLatest']
        rms = [p['rms_strain'] for p in pg.js('clothApp.panels()')]
        assert got[0] == rms[0], (got, rms)
    # shown for a single cloth too
    pg.js('clothApp.compare([])')
    assert pg.locator('#charts').is_visible()
    pg.locator('#charts-on').uncheck()
    assert pg.locator('#charts').is_hidden()


@pytest.mark.parametrize('size', [(800, 600), (1366, 768), (430, 932)])
def test_every_chart_text_stays_inside_its_chart_with_four_panels(open_page, size):
    pg = open_page(viewport={'width': size[0], 'height': size[1]})
    pg.js("clothApp.compare([{solver: 'jakobsen'}, {solver: 'xpbd'}, {substeps: 3}, {iterations: 3}])")
    pg.locator('#charts-on').check()
    pg.js('clothApp.setPaused(true)')
    pg.locator('#view').click(position={'x': 5, 'y': 5})
    for _ in range(3):
        pg.keyboard.press('s')                  # a frame stepped by hand is charted and drawn
    texts = pg.js('clothApp.chartTexts()')
    values = [t for t in texts if 'e-' in t[0] or t[0].replace('.', '').isdigit()]
    assert len(values) >= 8, texts               # four panels' values in each chart
    for t, x, y, w, bx, by, bw, bh in texts:
        assert bx <= x and x + w <= bx + bw + 0.5 and by <= y and y + 10 <= by + bh, (t, x, y, w, bx, by, bw, bh)


def test_compare_mode_recording_replays_per_panel_and_a_link_reopens_it(open_page):
    pg = open_page()
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'model': MODEL, 'cols': 20, 'rows': 15, 'spacing': 0.1,
                                                       'pins': list(range(0, 20, 4)) + [19], 'damping': 1}))
    pg.js('(l) => clothApp.compare(l.concat([{"solver": "xpbd", "stretch": 5000}]))', PAIR)
    pg.js('clothApp.setPaused(true)')
    x, y = panels(pg)[0]['screen'][14 * 20 + 10]
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 10):
        pg.mouse.move(x - 8 * i, y - 11 * i)
        pg.js('clothApp.advance(2)')
    pg.mouse.up()
    pg.locator('#gravity').fill('-5')
    pg.locator('#gravity').press('Enter')
    pg.js('clothApp.advance(20)')
    text = pg.js('clothApp.recording()')
    rec = json.loads(text)
    assert len(rec['compare']) == 3
    ps = panels(pg)
    for i in range(3):
        assert cli(text, '--panel', str(i + 1))['positions'] == ps[i]['positions'], i
    url = pg.js('clothApp.link()')
    other = open_page()
    other.goto(url)
    wait_until(other, 'window.clothApp && clothApp.info().replay.ended')
    assert other.info()['panels'] == 3
    assert [p['positions'] for p in panels(other)] == [p['positions'] for p in ps]


def test_a_resize_mid_drag_keeps_the_vertex_under_the_pointer_in_its_panel(open_page):
    pg = open_page()
    pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.js('clothApp.setPaused(true)')
    x, y = panels(pg)[1]['screen'][BOTTOM]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 20, y - 30)
    for w, h in [(700, 900), (1200, 600), (900, 700)]:
        pg.set_viewport_size({'width': w, 'height': h})
        wait_until(pg, '(() => { const c = document.getElementById("view");'
                       ' return Math.abs(c.getBoundingClientRect().width - (%d - (%d > 720 ? 280 : 0))) < 2; })()' % (w, w))
        pg.wait_for_timeout(50)
        sx, sy = panels(pg)[1]['hands'][BOTTOM]
        assert abs(sx - (x + 20)) < 0.5 and abs(sy - (y - 30)) < 0.5, (w, h, sx, sy)
    pg.mouse.up()


def test_panel_settings_in_the_editor(open_page):
    pg = open_page()
    pg.locator('#btn-compare-pair').click()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(30)')
    sub = pg.locator('#compare-list input[data-key=substeps]').nth(1)
    sub.fill('4')
    sub.press('Enter')
    assert json.loads(panels(pg)[1]['scene'])['substeps'] == 4
    assert pg.info()['frames'] == 0                  # the comparison restarted
    # Past a field's end: clamped to the declared end, and said (damping: a panel's own key
    # whose largest value the page can still run).
    top = spec('damping').field_hi
    damp = pg.locator('#compare-list input[data-key=damping]').nth(1)
    damp.fill(str(10 * top))
    damp.press('Enter')
    assert 'Panel 2 Damping clamped to its maximum %g' % top in pg.info()['note']
    assert json.loads(panels(pg)[1]['scene'])['damping'] == top
    assert json.loads(panels(pg)[1]['scene'])['substeps'] == 4
    # letters are not "empty" (empty means the scene's value): a note, nothing changed
    for text in ['abc', 'Infinity', '-']:
        sub = pg.locator('#compare-list input[data-key=substeps]').nth(1)
        sub.fill('')
        sub.type(text)
        sub.press('Enter')
        assert 'not a number' in pg.info()['note'], text
        assert json.loads(panels(pg)[1]['scene'])['substeps'] == 4
    pg.locator('#btn-compare-add').click()
    pg.locator('#btn-compare-add').click()
    assert pg.info()['panels'] == 4 and pg.locator('#btn-compare-add').is_disabled()
    pg.locator('#compare-list .compare-head button').nth(0).click()     # remove panel 1
    assert pg.info()['panels'] == 3
    pg.locator('#compare-list details summary').nth(0).click()         # the folded settings
    sel = pg.locator('#compare-list select[data-key=sleep]').nth(0)
    sel.select_option('false')
    assert json.loads(panels(pg)[0]['scene'])['sleep'] is False
    assert pg.js('clothApp.cloth().scene.sleep') is False          # what panel 1 runs


def editor_values(pg, key):
    return pg.js('(k) => Array.from(document.querySelectorAll(`#compare-list [data-key=${k}]`)).map((e) => e.value)', key)


def test_a_scene_setting_in_compare_mode_shows_in_the_editor_and_survives_a_grid_change(open_page):
    # A Scene-section setting is a `set`, written into every panel over the panels' own values
    # (as the recording replays it): the editor shows what each panel runs, and a grid change,
    # a Reset and a replay's own `set` keep to that rule instead of restoring the old values.
    pg = open_page()
    pg.js('(l) => clothApp.compare(l)', PAIR)
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(10)')
    field = pg.locator('#iterations')
    field.fill('7')
    field.press('Enter')
    assert [json.loads(p['scene'])['iterations'] for p in panels(pg)] == [7, 7]
    assert editor_values(pg, 'iterations') == ['7', '7']
    assert 'every panel' in pg.info()['note']
    recorded = pg.js('clothApp.recording()')
    field = pg.locator('#cols')
    field.fill('24')
    field.press('Enter')
    ps = panels(pg)
    assert len(ps[0]['positions']) == 24 * 30
    assert [json.loads(p['scene'])['iterations'] for p in ps] == [7, 7]
    assert [json.loads(p['scene'])['solver'] for p in ps] == [SEED_SOLVER, DEFAULT_SOLVER]   # untouched keys stay
    assert editor_values(pg, 'iterations') == ['7', '7']
    pg.js('clothApp.reset()')
    assert [json.loads(p['scene'])['iterations'] for p in panels(pg)] == [7, 7]
    # The recording made before the grid change: its `set`, replayed, moves the editor at its
    # frame, not before.
    at = [a['frame'] for a in json.loads(recorded)['actions'] if a['op'] == 'set'][0]
    load_paused(pg, recorded)
    assert editor_values(pg, 'iterations') == [str(p['iterations']) for p in PAIR]
    pg.js('(n) => clothApp.advance(n)', at - 1)
    assert editor_values(pg, 'iterations') == [str(p['iterations']) for p in PAIR]
    pg.js('clothApp.advance(1)')
    assert editor_values(pg, 'iterations') == ['7', '7']


# Issue #22.6: the number being compared stays in sight at every size and panel count.
LONGEST = {'solver': 'xpbd', 'substeps': 12, 'iterations': 3, 'stretch': 1234.5, 'shear': 67.8,
           'density': 0.123, 'strength': 25.5}
LABEL_RMS = '''(i) => {
  const el = document.querySelectorAll('.panel-label')[i], line = el.lastChild;
  const text = line.textContent, at = text.indexOf('rms ');
  const end = text.indexOf(' ', at + 4) < 0 ? text.length : text.indexOf(' ', at + 4);
  const range = document.createRange();
  range.setStart(line.firstChild, at);
  range.setEnd(line.firstChild, end);
  const box = (e) => e.getBoundingClientRect().toJSON();
  const covers = ['legend', 'hud', 'charts', 'banner', 'panel'].map((id) => document.getElementById(id))
    .filter((e) => e.offsetParent !== null || getComputedStyle(e).position === 'fixed')
    .filter((e) => getComputedStyle(e).display !== 'none' && getComputedStyle(e).visibility !== 'hidden')
    .map((e) => [e.id, box(e)]);
  return {text: text.slice(at + 4, end), rms: range.getBoundingClientRect().toJSON(), label: box(el),
          stage: box(document.getElementById('stage')), covers: covers};
}'''


@pytest.mark.parametrize('size', [(800, 600), (360, 640), (390, 844), (640, 480), (1366, 768)])
def test_every_panel_label_keeps_its_rms_strain_in_sight(open_page, size):
    pg = open_page(viewport={'width': size[0], 'height': size[1]})
    for n in (2, 3, 4):
        pg.js('(l) => clothApp.compare(l)', ([{'solver': 'jakobsen', 'substeps': 1, 'iterations': 20}] + [LONGEST] * 3)[:n])
        pg.js('clothApp.setPaused(true)')
        pg.js('clothApp.advance(20)')
        pg.wait_for_timeout(600)                       # a readout (250 ms) or two
        ps = panels(pg)
        assert pg.locator('.panel-label:visible').count() == n
        for i in range(n):
            got = pg.js(LABEL_RMS, i)
            where = (size, n, i, got)
            assert abs(float(got['text']) - ps[i]['rms_strain']) <= half_a_last_digit(got['text']), where
            r, lab, st = got['rms'], got['label'], got['stage']
            assert r['width'] > 10, where
            assert lab['left'] <= r['left'] and r['right'] <= lab['right'], where      # not cut off
            assert st['left'] <= r['left'] and r['right'] <= st['right'] and 0 <= r['top'] and r['bottom'] <= st['bottom'], where
            for name, c in got['covers']:
                if name == 'panel' and c['left'] >= st['right']:
                    continue                            # the panel beside the stage
                assert not overlap(r, c), (name, where)


def overlap(a, b):
    return a['left'] < b['right'] and b['left'] < a['right'] and a['top'] < b['bottom'] and b['top'] < a['bottom']


def half_a_last_digit(text):
    """0.0012 -> 5e-5, 1.23e-5 -> 5e-8: how far a shown number can be from what it rounds."""
    mantissa, _, exponent = text.partition('e')
    decimals = len(mantissa.partition('.')[2])
    return 0.5 * 10.0 ** (-decimals + int(exponent or 0)) * 1.0000001
