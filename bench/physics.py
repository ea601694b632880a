"""python -m bench --physics [--quick]: what a person sees, measured on the page's own
presets (issue #21). CPython only, like bench/speed.py, on the page bench/page.py opens: every frame runs
in Chromium in dist/index.html, the presets made by the page's webgl/scenes.js.

- Release table: on every preset, at grid sizes from 10x10 to 200x200, in the presets' material
  (jersey; two corners: inextensible) and inextensible with the default solver, and with the seed's method: a vertex (the
  bottom middle, a bottom corner, a middle one) grabbed where it rests, carried 0.2, 0.5 or 1 m
  down, up or aside over 40 frames, held half a second and let go. Reported: the fastest
  vertex over the 3 frames after (frame displacement / dt), the highest point over the next
  second above the highest pin, and the largest strain while held; and a tap (grab, let go).
  Targets: under 3 m/s after 0.2 m, under 5 m/s after 0.5 m, nothing above the pins.
- Strain-field table: scenes at rest whose strain is a physical field (their material), at 30, 60 and
  120: RMS over edges of (strain - reference), relative to the largest reference strain,
  against the exact profile where one exists (cloth/reference.py), the same scene at 8x the
  substeps, and the same scene at 120x120 (the field compared at the same points of the cloth).
"""
import json
import math
import time

from bench.page import open_page
from cloth.reference import hanging_column_strains, elastic_chain
from cloth.scene import SEED_SOLVER, solver_defaults

RELEASE_PRESETS = ['curtain', 'corners', 'chain', 'large', 'tearable']
SIZES = [10, 30, 60, 120, 200]
BIG = 120                      # from this size on, a reduced set of pulls (time)
SETTLE = 150                   # frames before a pull (the corners preset is carried in 60)
HOLD = 30
DISTANCES = [0.2, 0.5, 1.0]
LIMITS = {0.2: 3.0, 0.5: 5.0}  # m/s, issue #21
DIRECTIONS = [('down', 0.0, -1.0), ('up', 0.0, 1.0), ('aside', 1.0, 0.0)]
# The preset's own material (jersey; two corners: inextensible), inextensible, and the seed's
# method (which ignores the stiffness).
CONFIGS = [('default, its material', {}),
           ('default, inextensible', {'material': 'inextensible'}),
           ('seed', dict({'solver': SEED_SOLVER},
                         **{k: solver_defaults(SEED_SOLVER)[k] for k in ('substeps', 'iterations')}))]
FIELD_SIZES = [30, 60, 120]
FIELD_SETTLE = 600             # 10 s at damping 1/s
FINE = 8                       # the converged run: 8x the substeps


def grid_of(name, n):
    """(cols, rows) of a preset at size n: the chain is one row."""
    return (n, 1) if name == 'chain' else (n, n)


def vertices(cols, rows):
    """The grabbed vertices: bottom middle, bottom right corner, one in the middle."""
    out = [('bottom', (rows - 1) * cols + cols // 2), ('corner', rows * cols - 1)]
    if rows > 2:
        out.append(('middle', (rows // 2) * cols + cols // 4))
    return out


def release_table(page, quick, progress):
    sizes = [10, 30] if quick else SIZES
    rows = []
    for name in RELEASE_PRESETS:
        for n in sizes:
            cols, nrows = grid_of(name, n)
            for label, params in CONFIGS:
                p = dict(params, cols=cols, rows=nrows)
                if 'solver' not in p:
                    p.update(solver='xpbd', substeps=8, iterations=1)
                text = page.evaluate('([n, p]) => __bench.preset(n, p)', [name, p])
                worst = {d: {'fastest': 0.0, 'above': -1e9, 'held': 0.0, 'where': ''} for d in DISTANCES}
                for which, k in vertices(cols, nrows):
                    if n >= BIG and which == 'middle':
                        continue
                    for dname, ux, uy in DIRECTIONS:
                        if n >= BIG and dname == 'up':
                            continue
                        for d in DISTANCES:
                            r = page.evaluate('([t, s, k, x, y, h]) => __bench.pull(t, s, k, x, y, h)',
                                              [text, SETTLE, k, ux * d, uy * d, HOLD])
                            w = worst[d]
                            if not r['finite']:
                                r['fastest'], r['above'] = float('inf'), float('inf')
                            if r['fastest'] > w['fastest']:
                                w['fastest'], w['where'] = r['fastest'], '%s %s' % (which, dname)
                            w['above'] = max(w['above'], r['above'])
                            w['held'] = max(w['held'], r['held'])
                tap = page.evaluate('([t, s, k]) => __bench.tap(t, s, k)',
                                    [text, SETTLE, vertices(cols, nrows)[0][1]])
                for d in DISTANCES:
                    w = worst[d]
                    rows.append({'preset': name, 'n': n, 'cols': cols, 'rows': nrows, 'config': label,
                                 'distance': d, 'fastest': w['fastest'], 'where': w['where'],
                                 'above': w['above'], 'held_max_strain': w['held'], 'tap': tap})
                progress('release %s %dx%d %s: fastest %s m/s (0.2 / 0.5 / 1 m), above pins %.3f m' % (
                    name, cols, nrows, label,
                    ' / '.join('%.2f' % worst[d]['fastest'] for d in DISTANCES),
                    max(worst[d]['above'] for d in DISTANCES)))
    return rows


# ---- strain fields at rest -------------------------------------------------------------------

def edge_strains(pos, cols, rows, spacing):
    """{(r, c, 'down' | 'right'): signed strain} of the structural edges."""
    out = {}
    for r in range(rows):
        for c in range(cols):
            k = r * cols + c
            for dr, dc, what in ((1, 0, 'down'), (0, 1, 'right')):
                if r + dr < rows and c + dc < cols:
                    j = (r + dr) * cols + c + dc
                    length = math.hypot(pos[2 * j] - pos[2 * k], pos[2 * j + 1] - pos[2 * k + 1])
                    out[(r, c, what)] = length / spacing - 1.0
    return out


def sample(field, cols, rows, u, v, what):
    """The field of one edge direction at material point (u, v) in [0, 1]^2 (u across, v down),
    interpolated linearly between the edge midpoints around it."""
    if what == 'down':
        nr, nc = rows - 1, cols          # midpoints at rows r + 1/2, columns c
        fr, fc = v * (rows - 1) - 0.5, u * (cols - 1)
    else:
        nr, nc = rows, cols - 1
        fr, fc = v * (rows - 1), u * (cols - 1) - 0.5
    fr = min(max(fr, 0.0), nr - 1.0)
    fc = min(max(fc, 0.0), nc - 1.0)
    r0, c0 = int(fr), int(fc)
    r1, c1 = min(r0 + 1, nr - 1), min(c0 + 1, nc - 1)
    a, b = fr - r0, fc - c0
    f = lambda r, c: field[(r, c, what)]
    return ((1 - a) * ((1 - b) * f(r0, c0) + b * f(r0, c1)) + a * ((1 - b) * f(r1, c0) + b * f(r1, c1)))


def relative_rms(values, refs):
    scale = max(abs(x) for x in refs) or 1.0
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(values, refs)) / len(values)) / scale


FIELD_SCENES = ['curtain', 'column', 'chain', 'corners', 'large']


def field_scene(page, name, n, substeps):
    """Scene JSON text of a field scene at size n: the presets, a hanging column (one column of
    the curtain) and a chain pinned at both ends (the chain preset's 40 links, its far end
    pinned 80% of its length away), in jersey; two corners in cotton (the preset itself is
    inextensible: a material hung from two points is a known limit, and this row measures it)."""
    p = {'solver': 'xpbd', 'substeps': substeps, 'iterations': 1}
    if name == 'corners':
        p['material'] = 'cotton'
    if name in ('curtain', 'corners', 'large'):
        return page.evaluate('([n, p]) => __bench.preset(n, p)', [name, dict(p, cols=n, rows=n)])
    if name == 'column':
        scene = json.loads(page.evaluate('([n, p]) => __bench.preset(n, p)',
                                         ['curtain', dict(p, cols=n, rows=n)]))
        scene.update(cols=1, pins=[0])
        return json.dumps(scene)
    scene = json.loads(page.evaluate('([n, p]) => __bench.preset(n, p)', ['chain', dict(p, cols=n, rows=1)]))
    k = n - 1
    scene['actions'] = ([{'frame': 0, 'op': 'grab', 'vertex': k, 'to': [k * scene['spacing'], 0]}] +
                        [{'frame': f, 'op': 'move', 'vertex': k,
                          'to': [(k - (k - 0.8 * k) * (0.5 - 0.5 * math.cos(math.pi * f / 60))) * scene['spacing'], 0]}
                         for f in range(1, 61)] +
                        [{'frame': 60, 'op': 'pin', 'vertex': k}, {'frame': 60, 'op': 'release', 'vertex': k}])
    scene['pins'] = [0]
    return json.dumps(scene)


def exact_field(name, scene):
    """{edge: strain} of the exact equilibrium, or None where there is none in closed form."""
    cols, rows, h = scene['cols'], scene['rows'], scene['spacing']
    mass = scene['density'] * h * h
    a = scene['compliance']
    if name in ('curtain', 'column', 'large'):
        col = hanging_column_strains(rows, h, mass, a)
        out = {}
        for r in range(rows):
            for c in range(cols):
                if r + 1 < rows:
                    out[(r, c, 'down')] = col[r]
                if c + 1 < cols:
                    out[(r, c, 'right')] = 0.0
        return out
    if name == 'chain':
        n = cols - 1
        _, tensions = elastic_chain(n, h, 0.8 * n * h, mass * 9.81, a)
        return {(0, c, 'right'): tensions[c] * a / h for c in range(n)}
    return None


def field_table(page, quick, progress):
    sizes = [30] if quick else FIELD_SIZES
    top = sizes[-1]
    rows = []
    for name in FIELD_SCENES:
        fields = {}
        for n in sizes:
            text = field_scene(page, name, n, 8)
            scene = json.loads(text)
            cols, nrows = scene['cols'], scene['rows']
            t0 = time.time()
            r = page.evaluate('([t, f]) => __bench.rest(t, f)', [text, FIELD_SETTLE])
            fine = page.evaluate('([t, f]) => __bench.rest(t, f)',
                                 [field_scene(page, name, n, 8 * FINE), FIELD_SETTLE])
            field = edge_strains(r['pos'], cols, nrows, scene['spacing'])
            conv = edge_strains(fine['pos'], cols, nrows, scene['spacing'])
            keys = sorted(field)
            exact = exact_field(name, scene)
            row = {'scene': name, 'n': n, 'cols': cols, 'rows': nrows,
                   'max_strain': max(abs(field[e]) for e in keys),
                   'vs_exact': relative_rms([field[e] for e in keys], [exact[e] for e in keys]) if exact else None,
                   'vs_fine': relative_rms([field[e] for e in keys], [conv[e] for e in keys]),
                   'speed': r['speed']}
            fields[n] = (field, cols, nrows)
            rows.append(row)
            progress('field %s %dx%d: max %.4f, vs exact %s, vs 8x substeps %.3f (%.0f s)' % (
                name, cols, nrows, row['max_strain'],
                '-' if row['vs_exact'] is None else '%.3f' % row['vs_exact'], row['vs_fine'],
                time.time() - t0))
        # The same points of the cloth on each grid: the edge midpoints of the coarsest grid.
        f_top, c_top, r_top = fields[top]
        for row in rows:
            if row['scene'] != name:
                continue
            f, cols, nrows = fields[row['n']]
            vals, refs = [], []
            for (r, c, what) in sorted(f):
                if what == 'down':
                    u, v = (c / (cols - 1) if cols > 1 else 0.0), (r + 0.5) / (nrows - 1)
                else:
                    u, v = (c + 0.5) / (cols - 1), (r / (nrows - 1) if nrows > 1 else 0.0)
                vals.append(f[(r, c, what)])
                refs.append(sample(f_top, c_top, r_top, u, v, what))
            row['vs_%d' % top] = relative_rms(vals, refs)
    return rows


def fmt(x, spec='%.3f'):
    if x is None:
        return '-'
    if isinstance(x, float) and math.isinf(x):
        return 'inf'
    return spec % x


def markdown(release, fields, meta):
    out = ['# Release and strain fields', '',
           '`%s`, %s, Chromium %s, %d CPUs, %.0f s. %s' % (
               meta['command'], meta['date'], meta['chromium'], meta['cpus'], meta['seconds'],
               __doc__.split('\n\n')[0].split(':', 1)[1].strip().replace('\n', ' ')), '',
           '## Release: fastest vertex (m/s) in the 3 frames after letting go, highest point above '
           'the pins (or the highest point at the release) within a second (m), largest strain while held', '',
           'Worst over the pulls of each distance (bottom middle, bottom corner, middle vertex; down, '
           'up, aside; from %dx%d on the middle vertex and the upward pulls are left out). Targets: '
           '< 3 m/s after 0.2 m, < 5 m/s after 0.5 m, nothing above the pins.' % (BIG, BIG), '',
           '| preset | grid | solver, material | 0.2 m: fastest | 0.5 m: fastest | 1 m: fastest | '
           'above pins | held max strain | tap moves |', '|---|---|---|---|---|---|---|---|---|']
    groups = {}
    for r in release:
        groups.setdefault((r['preset'], r['n'], r['config']), {})[r['distance']] = r
    for (name, n, config), by in groups.items():
        any_r = by[DISTANCES[0]]
        out.append('| %s | %dx%d | %s | %s | %s | %s | %s | %s | %s |' % (
            name, any_r['cols'], any_r['rows'], config,
            fmt(by[0.2]['fastest'], '%.2f'), fmt(by[0.5]['fastest'], '%.2f'), fmt(by[1.0]['fastest'], '%.2f'),
            fmt(max(by[d]['above'] for d in DISTANCES), '%.3f'),
            fmt(max(by[d]['held_max_strain'] for d in DISTANCES), '%.2f'),
            fmt(any_r['tap'], '%.1e')))
    top = max(r['n'] for r in fields)
    out += ['', '## Strain at rest: RMS over edges of the difference, relative to the '
            'largest strain', '',
            'curtain and large: the presets (hung from a rod, jersey); column: one column of the curtain; '
            'chain: the chain preset with its far end carried in to 80%% of its length and pinned; '
            'corners: the preset in cotton (the page hangs it inextensible). Exact: cloth/reference.py (no closed form for a compliant '
            'two-corner hang). 8x: the same scene at %d substeps. vs %dx%d: the field at the same '
            'points of the cloth. Target: each within 0.10.' % (8 * FINE, top, top), '',
            '| scene | grid | max strain | vs exact | vs 8x substeps | vs %dx%d | fastest vertex (m/s) |' % (top, top),
            '|---|---|---|---|---|---|---|']
    for r in fields:
        out.append('| %s | %dx%d | %.4f | %s | %s | %s | %.1e |' % (
            r['scene'], r['cols'], r['rows'], r['max_strain'], fmt(r['vs_exact']), fmt(r['vs_fine']),
            fmt(r.get('vs_%d' % top)) if r['n'] != top else '-', r['speed']))
    return '\n'.join(out) + '\n'


def run(quick, progress):
    """Both tables in one page; returns (markdown, result)."""
    from playwright.sync_api import sync_playwright
    t0 = time.time()
    with sync_playwright() as p:
        browser, page = open_page(p, progress)
        try:
            chromium = browser.version
            fields = field_table(page, quick, progress)
            release = release_table(page, quick, progress)
        finally:
            browser.close()
    import os
    meta = {'command': 'python -m bench --physics' + (' --quick' if quick else ''),
            'date': time.strftime('%Y-%m-%d %H:%M:%S %Z'), 'chromium': chromium,
            'cpus': os.cpu_count() or 0, 'seconds': time.time() - t0}
    result = {'meta': meta, 'release': release, 'fields': fields}
    return markdown(release, fields, meta), result


def svg_release(result, distance=0.5):
    """A log plot of the release table: the fastest vertex after a `distance` pull against the
    grid size, one line per preset and configuration (the default solid, the seed dashed), and
    the target (5 m/s after 0.5 m, 3 after 0.2 m) as a grey line."""
    rows = [r for r in result['release'] if r['distance'] == distance]
    width, height, left, right, top, bottom = 720, 420, 60, 220, 30, 50
    sizes = sorted(set(r['n'] for r in rows))
    lo, hi = 0.1, 100.0

    def x(n):
        i = sizes.index(n)
        return left + (width - left - right) * (i / max(1, len(sizes) - 1))

    def y(v):
        v = min(max(v, lo), hi)
        return top + (height - top - bottom) * (math.log10(hi) - math.log10(v)) / (math.log10(hi) - math.log10(lo))

    colours = {'curtain': '#e6194b', 'corners': '#3cb44b', 'chain': '#4363d8', 'large': '#f58231',
               'tearable': '#911eb4'}
    dashes = {CONFIGS[0][0]: '', CONFIGS[1][0]: '2,3', CONFIGS[2][0]: '8,4'}
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
           'font-size="12">' % (width, height),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="18">Fastest vertex (m/s, log) in the 3 frames after letting go of a %g m '
           'pull</text>' % (left, distance)]
    for v in (0.1, 1, 10, 100):
        out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/>' % (left, width - right, y(v), y(v)))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>' % (left - 6, y(v) + 4, v))
    limit = LIMITS.get(distance)
    if limit:
        out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#888" stroke-width="2"/>' % (
            left, width - right, y(limit), y(limit)))
        out.append('<text x="%d" y="%.1f" fill="#888">target %g m/s</text>' % (left + 4, y(limit) - 4, limit))
    for n in sizes:
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (x(n), height - bottom + 18, n))
    out.append('<text x="%d" y="%d" text-anchor="middle">grid size N (N x N; the chain N x 1)</text>' % (
        (left + width - right) // 2, height - 10))
    legend = 0
    for name in RELEASE_PRESETS:
        for label, _ in CONFIGS:
            pts = sorted((r['n'], r['fastest']) for r in rows if r['preset'] == name and r['config'] == label)
            if not pts:
                continue
            path = ' '.join('%.1f,%.1f' % (x(n), y(v)) for n, v in pts)
            out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="1.5" stroke-dasharray="%s"/>'
                       % (path, colours[name], dashes[label]))
            ly = top + 14 * legend
            out.append('<line x1="%d" x2="%d" y1="%d" y2="%d" stroke="%s" stroke-dasharray="%s"/>' % (
                width - right + 10, width - right + 34, ly, ly, colours[name], dashes[label]))
            out.append('<text x="%d" y="%d">%s, %s</text>' % (width - right + 38, ly + 4, name, esc(label)))
            legend += 1
    out.append('</svg>')
    return '\n'.join(out) + '\n'


def esc(text):
    return text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
