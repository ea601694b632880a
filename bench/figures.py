"""python -m bench --figures: the README's figures that the speed and physics tables do
not print, each measured on the page's presets (or, for the pendulum, at several lengths) and
at several sizes, in Chromium on dist/index.html like the other tables (CPython only).

- Sleep: how soon each preset at rest stops being stepped, how still it was, and how far that
  is from the same cloth kept awake; a pendulum undamped and damped.
- Pendulum: period and energy of the default against the seed's projection.
- The seed's method at rest: how far its 20 sweeps leave each preset stretched.
- One sweep per step: which settings are unstable, and what the max_speed net catches.
- The Two corners preset's corner carried in over a second against put there at once.
- Tethers: how much longer than the straight rest distance the exact two-corner hang puts
  the vertices from their pin (why the tethers use the path).
- Drawing: what a frame costs to draw under this Chromium's WebGL (software on a machine with
  no GPU).
"""
import json
import math
import os
import time

from bench.page import HARNESS, page_of, open_page
from bench.physics import edge_strains
from cloth.reference import pendulum_period, slack_hang
from cloth.scene import Scene, SEED_SOLVER, solver_defaults, spec

# Large cloth and Tearable are the Curtain at other default grids (and Tearable with a tear
# limit): at the same size they are the same scene at rest, measured once as the Curtain.
PRESETS = ['curtain', 'corners', 'chain']
SLEEP_SIZES = [10, 30, 60, 120, 200]
SLEEP_CAP = 1800               # 30 s: a preset not asleep by then is reported as awake
AWAKE_MORE = 600               # the same cloth kept awake 10 s longer
PENDULUM_LENGTHS = [0.25, 1.0, 4.0]
PENDULUM_PERIODS = 3
# The seed's method with its own steps (cloth/scene.py's declarations).
SEED = dict({'solver': SEED_SOLVER}, **{k: solver_defaults(SEED_SOLVER)[k] for k in ('substeps', 'iterations')})
DT = spec('dt').fallback
STRETCH_SIZES = [30, 60, 120]
SETTLE = 600
SWEEP_SIZES = [30, 60, 120]
SWEEP_FRAMES = 600
CORNER_SIZES = [10, 30, 60, 120]
TETHER_SIZES = [10, 30, 60, 120]
DRAW = [('curtain', 30), ('curtain', 120), ('curtain', 200), ('large', 200)]
DRAW_FRAMES = 10
# The core's defaults, not restated: gravity, and the speed past which max_speed slows a vertex.
G = -Scene().gravity_y
NET = Scene().max_speed


def preset(page, name, n, **params):
    cols, rows = (n, 1) if name == 'chain' else (n, n)
    keys = dict(params, cols=cols, rows=rows)
    return json.loads(page.evaluate('([n, p]) => __bench.preset(n, p)', [name, keys]))


def extent(scene):
    return max(scene['cols'] - 1, scene['rows'] - 1, 1) * scene['spacing']


def farthest(a, b):
    return max(math.hypot(a[2 * k] - b[2 * k], a[2 * k + 1] - b[2 * k + 1]) for k in range(len(a) // 2))


def pendulum(length, **keys):
    scene = {'cols': 2, 'rows': 1, 'spacing': length, 'pins': [0], 'gravity': [0, -G],
             'dt': DT, 'damping': 0}
    scene.update(keys)
    return scene


# ---- sleep -----------------------------------------------------------------------------------

def sleep_table(page, quick, progress):
    rows = []
    cases = [(name, n, preset(page, name, n)) for name in PRESETS
             for n in ([10, 30] if quick else SLEEP_SIZES)]
    cases += [('pendulum 1 m, undamped', 2, pendulum(1.0)),
              ('pendulum 1 m, damping 0.2/s', 2, pendulum(1.0, damping=0.2))]
    for name, n, scene in cases:
        t0 = time.time()
        cap = 12000 if name.startswith('pendulum') else SLEEP_CAP
        r = page.evaluate('([t, c]) => __bench.sleep(t, c)', [json.dumps(scene), cap])
        row = {'scene': name, 'n': n, 'frames': r['frames'], 'cap': cap, 'swing': r['swing'],
               'jump': r['jump'], 'extent': extent(scene), 'awake_gap': None}
        if r['frames'] >= 0:
            awake = dict(scene, sleep=False)
            far = page.evaluate('([t, f]) => __bench.rest(t, f)',
                                [json.dumps(awake), r['frames'] + AWAKE_MORE])
            row['awake_gap'] = farthest(r['pos'], far['pos'])
        rows.append(row)
        progress('sleep %s %s: %s frames, swing %.2g m, awake gap %s (%.0f s)' % (
            name, n, r['frames'], r['swing'],
            '-' if row['awake_gap'] is None else '%.2g m' % row['awake_gap'], time.time() - t0))
    return rows


CHATTER_SIZE = 120
CHATTER = [('default', {}), ('2 sweeps a step', {'iterations': 2}), ('16 substeps', {'substeps': 16}),
           ('no line solves', {'lines': False})]


def chatter_table(page, quick, progress):
    """The Two corners hang at 120x120 after 30 s, awake, under settings that might calm its
    top row: how far any vertex was over the last second from where it ended, and the largest
    step in a frame."""
    rows = []
    if quick:
        return rows
    for label, keys in CHATTER:
        scene = dict(preset(page, 'corners', CHATTER_SIZE), sleep=False, **keys)
        r = page.evaluate('([t, c]) => __bench.sleep(t, c)', [json.dumps(scene), SLEEP_CAP])
        rows.append({'config': label, 'n': CHATTER_SIZE, 'swing': r['swing'], 'jump': r['jump']})
        progress('chatter %s: swing %.2g m, step %.2g m' % (label, r['swing'], r['jump']))
    return rows


# ---- pendulum --------------------------------------------------------------------------------

def swings(track, length, dt):
    """(crossing times, turning heights above the lowest point) of the bob's track."""
    crossings, heights, current, side = [], [], [], None
    px = track[0]
    for f in range(len(track) // 2):
        x, y = track[2 * f], track[2 * f + 1]
        if f > 0 and (px > 0 >= x or px < 0 <= x):
            crossings.append((f - 1 + px / (px - x)) * dt + dt)
        s = 1 if x > 0 else -1
        if side is not None and s != side:
            heights.append(max(current))
            current = []
        side = s
        current.append(length + y)
        px = x
    return crossings, heights


def pendulum_table(page, progress):
    rows = []
    for length in PENDULUM_LENGTHS:
        exact = pendulum_period(length, math.pi / 2, G)
        frames = int(math.ceil((PENDULUM_PERIODS + 0.6) * exact * 60))
        for label, keys in (('default', {}), ('seed', SEED)):
            scene = pendulum(length, **keys)
            track = page.evaluate('([t, f, k]) => __bench.track(t, f, k)',
                                  [json.dumps(scene), frames, 1])
            crossings, heights = swings(track, length, DT)
            # Periods from every other crossing; heights: the first turning point after the
            # release at the horizontal (height = length), then one per half period.
            periods = [b - a for a, b in zip(crossings, crossings[2:])]
            row = {'length': length, 'solver': label, 'exact': exact,
                   'period': sum(periods) / len(periods) if periods else None,
                   'first_swing': 1 - heights[1] / length if len(heights) > 1 else None,
                   'per_period': None}
            n = min(2 * PENDULUM_PERIODS, len(heights) - 1)
            if n >= 2 and heights[n] > 0:
                row['per_period'] = 1 - (heights[n] / length) ** (2.0 / n)
            row['period_error'] = (row['period'] - exact) / exact if row['period'] else None
            rows.append(row)
            progress('pendulum %g m %s: period %s (exact %.4f s), first swing -%s, per period -%s' % (
                length, label, row['period'], exact, row['first_swing'], row['per_period']))
    return rows


# ---- the seed's method at rest ---------------------------------------------------------------

def strain_stats(pos, scene):
    field = edge_strains(pos, scene['cols'], scene['rows'], scene['spacing'])
    vals = [abs(v) for v in field.values()]
    return math.sqrt(sum(v * v for v in vals) / len(vals)), max(vals)


def stretch_table(page, quick, progress):
    rows = []
    for name in ['curtain', 'corners']:
        for n in ([30] if quick else STRETCH_SIZES):
            row = {'scene': name, 'n': n}
            for label, keys in (('seed', SEED), ('default', {})):
                scene = preset(page, name, n, **keys)
                r = page.evaluate('([t, f]) => __bench.rest(t, f)', [json.dumps(scene), SETTLE])
                row[label + '_rms'], row[label + '_max'] = strain_stats(r['pos'], scene)
            rows.append(row)
            progress('at rest %s %d: seed RMS %.3g max %.3g, default RMS %.3g max %.3g' % (
                name, n, row['seed_rms'], row['seed_max'], row['default_rms'], row['default_max']))
    return rows


# ---- one sweep per step ----------------------------------------------------------------------

SWEEP_CONFIGS = [
    ('seed, 1 sweep, undamped', {'solver': 'jakobsen', 'substeps': 1, 'iterations': 1, 'damping': 0}),
    ('seed, 1 sweep, damping 1/s', {'solver': 'jakobsen', 'substeps': 1, 'iterations': 1, 'damping': 1}),
    ('seed, 1 sweep, shear, undamped', {'solver': 'jakobsen', 'substeps': 1, 'iterations': 1,
                                        'damping': 0, 'shear': True}),
    ('seed, 2 sweeps, undamped', {'solver': 'jakobsen', 'substeps': 1, 'iterations': 2, 'damping': 0}),
    ('default, no cells, no lines, undamped', {'cells': False, 'lines': False, 'damping': 0}),
    ('default, undamped', {'damping': 0}),
]


def sweep_table(page, quick, progress):
    rows = []
    for n in ([30] if quick else SWEEP_SIZES):
        for label, keys in SWEEP_CONFIGS:
            scene = {'cols': n, 'rows': n, 'spacing': 1.0 / (n - 1), 'pins': [0],
                     'gravity': [0, -G], 'dt': DT}
            scene.update(keys)
            r = page.evaluate('([t, f]) => __bench.motion(t, f)', [json.dumps(scene), SWEEP_FRAMES])
            rows.append(dict(r, n=n, config=label))
            progress('one corner %d %s: fastest %.3g m/s, clamped %d' % (n, label, r['fastest'], r['clamped']))
    return rows


# ---- the corner carried in or put there at once ----------------------------------------------

def corner_table(page, quick, progress):
    rows = []
    for n in ([10, 30] if quick else CORNER_SIZES):
        carried = preset(page, 'corners', n)
        acts = carried['actions']
        k, x1 = acts[-1]['vertex'], acts[-3]['to'][0]
        put = dict(carried, actions=[acts[0], {'frame': 1, 'op': 'move', 'vertex': k, 'to': [x1, 0]},
                                     {'frame': 1, 'op': 'pin', 'vertex': k},
                                     {'frame': 1, 'op': 'release', 'vertex': k}])
        row = {'n': n}
        for label, scene in (('carried', carried), ('put', put)):
            r = page.evaluate('([t, f]) => __bench.motion(t, f)', [json.dumps(scene), 120])
            row[label + '_fastest'], row[label + '_above'] = r['fastest'], r['top']
        rows.append(row)
        progress('corner %d: carried %.2f m/s, %.3f m; put %.2f m/s, %.3f m' % (
            n, row['carried_fastest'], row['carried_above'], row['put_fastest'], row['put_above']))
    return rows


# ---- tethers against the exact hang ----------------------------------------------------------

def tether_table(quick):
    """In the exact two-corner hang (corners 0.8 of the width apart), the distance of each free
    vertex from its anchor (the pin nearer along the cloth) against the straight-line rest
    distance a Euclidean tether allows: the share of vertices beyond it, and by how much."""
    rows = []
    for n in ([10, 30] if quick else TETHER_SIZES):
        h = 1.0 / (n - 1)
        span = 0.8 * (n - 1) * h
        pos = slack_hang(n, n, h, span)
        beyond, excess, free = 0, [], 0
        for r in range(n):
            for c in range(n):
                if r == 0 and c in (0, n - 1):
                    continue
                free += 1
                left = c <= (n - 1) - c
                px = 0.0 if left else span
                dc = c if left else (n - 1) - c
                straight = h * math.hypot(dc, r)
                x, y = pos[r * n + c]
                d = math.hypot(x - px, y)
                if d > straight * (1 + 1e-9):
                    beyond += 1
                    excess.append(d / straight - 1)
        rows.append({'n': n, 'beyond': beyond / free,
                     'mean_excess': sum(excess) / len(excess) if excess else 0.0,
                     'max_excess': max(excess) if excess else 0.0})
    return rows


# ---- drawing ---------------------------------------------------------------------------------

def draw_table(browser, progress):
    """Each scene in a tab of its own, the app running as a person sees it (open_page's tab
    has its loop stopped)."""
    rows = []
    for name, n in DRAW:
        page = page_of(browser, [])
        page.add_script_tag(path=HARNESS)
        try:
            scene = preset(page, name, n)
            ms = page.evaluate('''([text, frames]) => {
              const app = window.clothApp;
              app.loadScene(text);
              app.setPaused(true);
              const canvas = document.getElementById('view');
              const gl = canvas.getContext('webgl2') || canvas.getContext('webgl');
              const px = new Uint8Array(4);
              app.advance(0);
              gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
              const t0 = performance.now();
              for (let i = 0; i < frames; i++) {
                app.advance(0);
                gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);   // waits for the draw
              }
              return (performance.now() - t0) / frames;
            }''', [json.dumps(scene), DRAW_FRAMES])
        finally:
            page.close()
        rows.append({'scene': name, 'n': n, 'ms': ms})
        progress('draw %s %d: %.1f ms a frame' % (name, n, ms))
    return rows


# ---- report ----------------------------------------------------------------------------------

def g(x, spec='%.2g'):
    return '-' if x is None else spec % x


def markdown(res):
    meta = res['meta']
    out = ['# Other figures', '',
           '`%s`, %s, Chromium %s, %d CPUs, %.0f s. %s' % (
               meta['command'], meta['date'], meta['chromium'], meta['cpus'], meta['seconds'],
               ' '.join(__doc__.split('\n\n')[0].split())), '']
    out += ['## Sleep', '',
            'Each preset as the page makes it (its material, default solver), from its start; '
            'frames until it is asleep (not within %d: still moving), how far any vertex was '
            'over the last second from where it ended (asleep or not), the largest distance '
            'a vertex moved in one frame over that second, and how far the same cloth kept awake '
            '%d frames longer is from it (m and of the extent). Large cloth and Tearable are '
            'the Curtain at other default grids: at the same size, the same scene at rest.'
            % (SLEEP_CAP, AWAKE_MORE), '',
            '| scene | size | asleep after (frames) | last second: swing (m) | largest step in a frame (m) | from the cloth kept awake (m) | of the extent |',
            '|---|---|---|---|---|---|---|']
    for r in res['sleep']:
        gap = r['awake_gap']
        out.append('| %s | %s | %s | %s | %s | %s | %s |' % (
            r['scene'], '%dx%d' % (r['n'], 1 if r['scene'] == 'chain' else r['n'])
            if not r['scene'].startswith('pendulum') else '-',
            r['frames'] if r['frames'] >= 0 else 'not within %d' % r['cap'],
            g(r['swing']), g(r['jump']), g(gap),
            g(gap / r['extent']) if gap is not None else '-'))
    if res.get('chatter'):
        out += ['', 'The Two corners hang at %dx%d, kept awake, after %d frames, under other '
                'settings: the last second\'s swing and the largest step in a frame.'
                % (CHATTER_SIZE, CHATTER_SIZE, SLEEP_CAP), '',
                '| settings | swing (m) | largest step in a frame (m) |', '|---|---|---|']
        for r in res['chatter']:
            out.append('| %s | %s | %s |' % (r['config'], g(r['swing']), g(r['jump'])))
    out += ['', '## Pendulum', '',
            'Released horizontally, undamped, 60 Hz: the period against the exact '
            '4 sqrt(L/g) K(1/2), the height lost in the first swing and the energy lost per '
            'period (over the first %d).' % PENDULUM_PERIODS, '',
            '| length (m) | solver | period (s) | exact (s) | period error | lost in the first swing | lost per period |',
            '|---|---|---|---|---|---|---|']
    for r in res['pendulum']:
        out.append('| %g | %s | %s | %.4f | %s | %s | %s |' % (
            r['length'], r['solver'], g(r['period'], '%.4f'), r['exact'], g(r['period_error'], '%.2g'),
            g(r['first_swing'], '%.3g'), g(r['per_period'], '%.3g')))
    out += ['', '## The seed\'s method at rest', '',
            'Each preset after %d frames (10 s): RMS and largest |strain| of the structural edges, '
            'the seed\'s 20 sweeps against the default (the preset\'s material; Large cloth '
            'and Tearable: the Curtain).' % SETTLE, '',
            '| preset | size | seed RMS | seed max | default RMS | default max |', '|---|---|---|---|---|---|']
    for r in res['stretch']:
        out.append('| %s | %dx%d | %.3g | %.3g | %.3g | %.3g |' % (
            r['scene'], r['n'], r['n'], r['seed_rms'], r['seed_max'], r['default_rms'], r['default_max']))
    out += ['', '## One sweep per step', '',
            'A cloth 1 m wide of structural edges (no shear unless said) hung from one corner, '
            '%d frames: the fastest free vertex, the vertex-steps the max_speed net (%g m/s) '
            'slowed, and whether every position stayed finite.' % (SWEEP_FRAMES, NET), '',
            '| size | settings | fastest (m/s) | slowed vertex-steps | finite |', '|---|---|---|---|---|']
    for r in res['sweeps']:
        out.append('| %dx%d | %s | %.3g | %d | %s |' % (r['n'], r['n'], r['config'], r['fastest'],
                                                      r['clamped'], 'yes' if r['finite'] else 'no'))
    out += ['', '## The Two corners preset\'s corner', '',
            'Carried in to 80% of the width over a second (the preset) or put there in one frame: '
            'the fastest free vertex and the highest free vertex (the pins are at 0) over 2 s.', '',
            '| size | carried: fastest (m/s) | carried: highest (m) | put: fastest (m/s) | put: highest (m) |',
            '|---|---|---|---|---|']
    for r in res['corner']:
        out.append('| %dx%d | %.2f | %.3f | %.2f | %.3f |' % (
            r['n'], r['n'], r['carried_fastest'], r['carried_above'], r['put_fastest'], r['put_above']))
    out += ['', '## Tethers and the exact two-corner hang', '',
            'In the exact hang (`cloth/reference.py`, corners 0.8 of the width apart), the free '
            'vertices farther from their pin than the straight-line rest distance (a Euclidean '
            'tether\'s length), and by how much.', '',
            '| size | share beyond | mean excess | largest excess |', '|---|---|---|---|']
    for r in res['tethers']:
        out.append('| %dx%d | %.0f%% | %.1f%% | %.1f%% |' % (r['n'], r['n'], 100 * r['beyond'],
                                                        100 * r['mean_excess'], 100 * r['max_excess']))
    out += ['', '## Drawing', '',
            'One frame drawn by the page\'s renderer and waited for (a one-pixel readback), '
            'averaged over %d; this Chromium\'s WebGL (SwiftShader, software, on a machine '
            'with no GPU).' % DRAW_FRAMES, '',
            '| preset | size | ms a frame |', '|---|---|---|']
    for r in res['draw']:
        out.append('| %s | %dx%d | %.0f |' % (r['scene'], r['n'], r['n'], r['ms']))
    return '\n'.join(out) + '\n'


def run(quick, progress):
    from playwright.sync_api import sync_playwright
    t0 = time.time()
    res = {'tethers': tether_table(quick)}
    with sync_playwright() as p:
        browser, page = open_page(p, progress)
        try:
            chromium = browser.version
            res['pendulum'] = pendulum_table(page, progress)
            res['corner'] = corner_table(page, quick, progress)
            res['sweeps'] = sweep_table(page, quick, progress)
            res['stretch'] = stretch_table(page, quick, progress)
            res['sleep'] = sleep_table(page, quick, progress)
            res['chatter'] = chatter_table(page, quick, progress)
            res['draw'] = draw_table(browser, progress) if not quick else []
        finally:
            browser.close()
    res['meta'] = {'command': 'python -m bench --figures' + (' --quick' if quick else ''),
                   'date': time.strftime('%Y-%m-%d %H:%M:%S %Z'), 'chromium': chromium,
                   'cpus': os.cpu_count() or 0, 'seconds': time.time() - t0}
    return markdown(res), res

