"""Pulls, releases and taps on every preset (`python -m bench --releases`): does letting go add
energy, or throw the cloth?

Each preset, as shipped but in still air (the flag's wind does work of its own), settles for
SETTLE frames; a hand takes its bottom-middle vertex (the
chain's free end) where it is, moves it PULL metres down, aside or up over half a second, holds
it half a second and lets go. Then for RELEASE_FRAMES: the most the total energy (kinetic +
elastic + gravitational) rose above what it was just before the release (a release removes
the hand's springs and nothing else, so it must never rise: backward-Euler and BDF2 steps only
take energy away); the speed 95% of the vertices stay under and the fastest; how far any free
vertex rose above the highest fixed one. And a tap (a hand taking hold and letting go with no
frame between) against the same run untouched.
Targets (issue #40): no energy gain; 95% of the vertices under 3 m/s after a 0.2 m pull and
5 m/s after 0.5 m; nothing above the pins; a tap changes nothing.

Beside them, the stretch's speed sqrt(2 E / m): the speed the elastic energy E the pull left
would give the free mass m if all of it became motion. A cloth pulled at a point stores its
stretch near the hand, far under the limits. A strip held at one end (the chain) and pulled
along itself is stretched along its whole length, by e = 0.2 m / 1.6 m = 12.5% or 31% in
jersey, and an elastic strip let go springs back at e sqrt(stretch / density) (the speed behind
its unloading wave), 6.3 and 16 m/s for jersey's 50 m/s: no model of that fabric meets the
limits there. For a strip (one row or column) the release is held to its energy
(no gain; nothing higher than that energy lifts it) and its speeds are reported against the
stretch's: the stretch coming back as motion, no more (tests/test_release.py measures that).
"""

import json

from cloth.presets import PRESETS, preset_scene
from cloth.keys import spec

SETTLE = 180
PULL_FRAMES = 30
HOLD_FRAMES = 30
RELEASE_FRAMES = 120
SIZES = [10, 30, 60, 120, 200]
QUICK_SIZES = [10, 20]
PULLS = [[0.2, 'down', 0.0, -1.0], [0.5, 'down', 0.0, -1.0], [0.2, 'aside', 1.0, 0.0],
         [0.5, 'aside', 1.0, 0.0], [0.2, 'up', 0.0, 1.0]]
LIMITS = {0.2: 3.0, 0.5: 5.0}
# The energy may rise by rounding and by what a step's unfinished solve leaves (the solver
# balances forces to cloth.imbalance of the weight): this share of the energy before, at most.
GAIN = 1e-3
# The scenes' gravity (the schema's default; the presets keep it), m/s^2.
GRAVITY = -spec('gravity').fallback[1]


def held_vertex(name, cols, rows):
    if rows == 1:
        return cols - 1
    return (rows - 1) * cols + cols // 2


def run(page, quick, progress):
    rows = []
    for p in PRESETS:
        name = p[0]
        for n in (QUICK_SIZES if quick else SIZES):
            cols, rows_ = (n, 1) if p[3] == 1 else (n, n)
            obj = preset_scene(name, cols, rows_)
            obj.pop('wind', None)         # the air does work of its own (the flag's wind):
            obj.pop('gust', None)         # what a release adds is measured in still air
            text = json.dumps(obj)
            k = held_vertex(name, cols, rows_)
            for size, way, ux, uy in PULLS:
                progress('%s %dx%d: %g m %s' % (name, cols, rows_, size, way))
                r = page.evaluate('([t, s, k, dx, dy, p, h, a]) => __bench.pull(t, s, k, dx, dy, p, h, a)',
                                  [text, SETTLE, k, ux * size, uy * size, PULL_FRAMES, HOLD_FRAMES, RELEASE_FRAMES])
                total = sum(abs(e) for e in r['before'])
                rows.append({'preset': name, 'cols': cols, 'rows': rows_, 'pull': size, 'way': way,
                             'p95': r['p95'], 'fastest': r['fastest'], 'rise': r['rise'],
                             'gain': r['gain'], 'scale': total, 'finite': r['finite'],
                             'stretch': (2.0 * r['before'][1] / r['free']) ** 0.5,
                             'reached': (r['reached'][0] ** 2 + r['reached'][1] ** 2) ** 0.5,
                             'tap': None})
            rows[-1]['tap'] = page.evaluate('([t, s, k, a]) => __bench.tap(t, s, k, a)',
                                            [text, SETTLE, k, RELEASE_FRAMES])
    return rows


def verdict(r):
    fails = []
    if not r['finite']:
        fails.append('not finite')
    if r['gain'] > GAIN * r['scale']:
        fails.append('energy rose %.3g J' % r['gain'])
    limit = LIMITS[r['pull']]
    if r['rows'] > 1 and r['cols'] > 1:
        if r['p95'] > limit:
            fails.append('95%% of vertices under %.3g m/s' % r['p95'])
        if r['rise'] > 0.0:
            fails.append('%.3g m above the pins' % r['rise'])
    elif r['rise'] > r['stretch'] ** 2 / (2.0 * GRAVITY):
        fails.append('%.3g m above the pins, higher than its stretch lifts it' % r['rise'])
    if r['tap'] is not None and r['tap'] != 0.0:
        fails.append('a tap moved it %.3g m' % r['tap'])
    return fails


def markdown(rows, meta):
    lines = ['# Letting go', '', '`python -m bench --releases` on %s, %s.' % (meta['date'], meta['machine']), '',
             'Every preset as shipped, in still air, settles %d frames; a hand takes its bottom-middle vertex (the chain\'s '
             'end) and moves it over %d frames, holds %d and lets go; %d frames follow. **reached**: how far '
             'the held vertex went (the hand stops where the fabric, stretched by its force, lets it); '
             '**gain**: the most the total energy rose above its value just before the release; **p95**: the '
             'speed 95%% of the vertices stayed under; **rise**: the highest free vertex above the highest '
             'fixed one (negative: below); **stretch**: sqrt(2 E / m), the speed the elastic energy E '
             'the pull left would give the free mass m if all of it became motion; **tap**: a grab and '
             'release with no frame between, against the run untouched.' % (SETTLE, PULL_FRAMES, HOLD_FRAMES, RELEASE_FRAMES), '',
             'Targets (issue #40): no energy gain; 95%% of the vertices under %g m/s after a 0.2 m pull '
             'and %g m/s after 0.5 m; nothing above the pins; a tap changes nothing. For a strip (the '
             'chain: held at one end and pulled along itself, it is stretched along its whole length, '
             'and an elastic strip let go springs back at its strain times the fabric\'s wave speed: '
             'in jersey 6.3 m/s after 0.2 m, 16 m/s after 0.5 m), the release is held to its energy: no gain, '
             'and nothing lifted higher than stretch^2 / 2g; its p95 is reported against the '
             'stretch\'s speed.' % (LIMITS[0.2], LIMITS[0.5]), '']
    bad = [(r, verdict(r)) for r in rows if verdict(r)]
    lines.append('Targets: ' + ('PASS, every one' if not bad else 'FAIL: ' + '; '.join(
        '%s %dx%d %g m %s: %s' % (r['preset'], r['cols'], r['rows'], r['pull'], r['way'], ', '.join(v)) for r, v in bad)))
    lines.append('')
    lines.append('| preset | grid | pull | reached (m) | gain (J) | p95 (m/s) | fastest (m/s) | stretch (m/s) | rise (m) | tap (m) |')
    lines.append('|---|---|---|---|---|---|---|---|---|---|')
    for r in rows:
        lines.append('| %s | %dx%d | %g m %s | %.3g | %.2g | %.3g | %.3g | %.3g | %.3g | %s |' % (
            r['preset'], r['cols'], r['rows'], r['pull'], r['way'], r['reached'], r['gain'], r['p95'],
            r['fastest'], r['stretch'], r['rise'], '' if r['tap'] is None else '%.2g' % r['tap']))
    return '\n'.join(lines) + '\n'
