"""Obstacles against hands, carries, drags and falls (`python -m bench --contact`): does anything
of the cloth ever go through an obstacle, and does a cloth on one come to rest?

- The issue's carry (#60): Towel on a peg, its clamp's middle vertex carried by a hand down
  and right 0.5 m in 5 frames, then up and left 0.7 m in 5 (over the peg), let go; and its
  bottom-left corner flung up over the peg and let go. The most edges through the peg while
  held and over the 2 s after.
- The peg dragged 1 m down, aside and up, in one frame or ten: edges through it, how far it
  got (its share of the way), how far the clamp fastened to it strayed from its move.
- Every preset with a disc (a tenth of its size across) below it, dragged up through it by 1.5
  times its height over half a second: edges through the disc, how far it got (a rod, a clamp
  or a pole stops it).
- Piles: a square cloth 1 m wide dropped flat on a box 0.8 m wide with friction 0.5, and a
  strip laid on a circle with friction (slopes of up to 3 degrees at its ends): when it rests.
Targets (issue #60): no edge through an obstacle, ever; a pile at rest within 20 s.
"""

import json

from cloth.keys import MODEL
from cloth.presets import PRESETS, preset_scene

SIZES = [10, 60, 200]
QUICK_SIZES = [10, 20]
SETTLE = 60
REST_FRAMES = 1200


def carry_path():
    """[dx, dy] a frame: down and right 0.5 m in 5 frames, then up and left 0.7 m in 5."""
    out = [[0.1 * f, -0.1 * f] for f in range(1, 6)]
    out += [[0.5 - 0.14 * f, -0.5 + 0.14 * f] for f in range(1, 6)]
    return out


def fling_path(w, h):
    """The towel's bottom-left corner flung up over its peg (its top edge at y = 0)."""
    return [[0.3 * w, 0.4 * h], [0.45 * w, 0.8 * h], [0.5 * w, 1.3 * h], [0.6 * w, 1.5 * h],
            [0.9 * w, 1.4 * h]]


def run(page, quick, progress):
    rows = []
    for n in (QUICK_SIZES if quick else SIZES):
        obj = preset_scene('towel', n, n)
        text = json.dumps(obj)
        w = (n - 1) * obj['spacing']
        progress('towel %dx%d: the carry and the fling' % (n, n))
        r = page.evaluate('([t, s, k, p, a]) => __bench.carry(t, s, k, p, a)',
                          [text, SETTLE, n // 2, carry_path(), 120])
        rows.append(dict(r, kind='carry', preset='towel', cols=n, rows=n, what='clamp carried 0.5 m down-right, 0.7 m up-left'))
        r = page.evaluate('([t, s, k, p, a]) => __bench.carry(t, s, k, p, a)',
                          [text, SETTLE, (n - 1) * n, fling_path(w, w), 180])
        rows.append(dict(r, kind='carry', preset='towel', cols=n, rows=n, what='corner flung over the peg'))
        for dx, dy, frames, what in [(0, -1, 1, 'peg 1 m down in 1 frame'), (0, -1, 10, 'peg 1 m down in 10'),
                                     (1, 0, 10, 'peg 1 m aside in 10'), (0, 1, 1, 'peg 1 m up in 1 frame')]:
            progress('towel %dx%d: %s' % (n, n, what))
            r = page.evaluate('([t, s, j, dx, dy, f, a]) => __bench.drag(t, s, j, dx, dy, f, a)',
                              [text, SETTLE, 0, dx, dy, frames, 60])
            rows.append(dict(r, kind='drag', preset='towel', cols=n, rows=n, what=what))
        for p in PRESETS:
            name = p[0]
            cols, rows_ = (n, 1) if p[3] == 1 else (n, n)
            obj = preset_scene(name, cols, rows_)
            size = p[4]
            h = (rows_ - 1) * obj['spacing'] if rows_ > 1 else size
            x = 0.5 * (cols - 1) * obj['spacing'] if cols > 1 else 0.0
            obj['obstacles'] = obj.get('obstacles', []) + [
                {'circle': [x, -h - 0.15 * size, 0.05 * size], 'friction': 0.3}]
            progress('%s %dx%d: a disc dragged up through it' % (name, cols, rows_))
            r = page.evaluate('([t, s, j, dx, dy, f, a]) => __bench.drag(t, s, j, dx, dy, f, a)',
                              [json.dumps(obj), SETTLE, len(obj['obstacles']) - 1, 0, 1.5 * h + 0.15 * size, 30, 60])
            rows.append(dict(r, kind='drag', preset=name, cols=cols, rows=rows_, what='disc up through it'))
    for n in ([10] if quick else [10, 20, 40, 60]):
        progress('pile %dx%d on a box' % (n, n))
        obj = {'model': MODEL, 'cols': n, 'rows': n, 'spacing': 1.0 / (n - 1), 'pins': [], 'damping': 1,
               'obstacles': [{'box': [0.1, -1.8, 0.9, -1.4], 'friction': 0.5}]}
        r = page.evaluate('([t, f]) => __bench.rest(t, f)', [json.dumps(obj), REST_FRAMES])
        rows.append(dict(r, kind='rest', preset='pile on a box', cols=n, rows=n, what='dropped flat on a box'))
        obj = {'model': MODEL, 'cols': n, 'rows': 1, 'spacing': 0.2 / (n - 1), 'pins': [], 'damping': 2,
               'obstacles': [{'circle': [0.1, -2.1, 2.0], 'friction': 0.5}]}
        r = page.evaluate('([t, f]) => __bench.rest(t, f)', [json.dumps(obj), REST_FRAMES])
        rows.append(dict(r, kind='rest', preset='strip on a circle', cols=n, rows=1, what='laid on a circle, friction 0.5'))
    return rows


def verdict(r):
    fails = []
    if not r.get('finite', True):
        fails.append('not finite')
    through = r.get('through', max(r.get('held', 0), r.get('after', 0)))
    if through > 0:
        fails.append('%d edges through' % through)
    if r['kind'] == 'rest' and not (0 <= r['restAt'] <= 20.0):
        fails.append('not at rest in 20 s')
    return fails


def markdown(rows, meta):
    lines = ['# Contact', '', '`python -m bench --contact` on %s, %s.' % (meta['date'], meta['machine']), '',
             __doc__.split('\n\n', 1)[1].strip(), '']
    bad = [(r, verdict(r)) for r in rows if verdict(r)]
    lines.append('Targets: ' + ('PASS, every one' if not bad else 'FAIL: ' + '; '.join(
        '%s %dx%d %s: %s' % (r['preset'], r['cols'], r['rows'], r['what'], ', '.join(v)) for r, v in bad)))
    lines += ['', '| preset | grid | what | edges through (held / after) | got | clamp strayed (m) | fastest after (m/s) | strain | at rest (s) |',
              '|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        if r['kind'] == 'carry':
            cells = ['%d / %d' % (r['held'], r['after']), '', '', '%.3g' % r['fastest'], '%.3g' % r['strain'], '']
        elif r['kind'] == 'drag':
            cells = ['%d' % r['through'], '%.2f' % r['got'], '%.2g' % r['stray'] if r['fastened'] else '',
                     '%.3g' % r['fastest'], '', '']
        else:
            cells = ['%d' % r['through'], '', '', '', '', '%.1f' % r['restAt'] if r['restAt'] >= 0 else 'no']
        lines.append('| %s | %dx%d | %s | %s |' % (r['preset'], r['cols'], r['rows'], r['what'], ' | '.join(cells)))
    return '\n'.join(lines) + '\n'
