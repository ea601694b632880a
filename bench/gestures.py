"""python -m bench --gestures: pulling beyond reach, letting go and flicking, in the page."""

import json
import time

from bench.page import open_page
from bench.speed import WIDTH

GESTURE_N = 30


def gestures(progress):
    """Pulling beyond reach, letting go, flicking, on a 1 m 30x30 curtain pinned at every
    third top vertex (damping 0.5/s), default against the seed's method; in the page."""
    from playwright.sync_api import sync_playwright
    n = GESTURE_N
    h = WIDTH / (n - 1)
    pins = list(range(0, n, 3)) + ([n - 1] if (n - 1) % 3 else [])
    k = (n - 1) * n + n // 2
    rows = []
    with sync_playwright() as p:
        browser, page = open_page(p, progress)
        try:
            for label, over in [('default', {}), ('jakobsen', {'solver': 'jakobsen'})]:
                scene = dict({'cols': n, 'rows': n, 'spacing': h, 'pins': pins,
                              'damping': 0.5}, **over)
                for dx, dy in [(0.0, -0.3), (1.0, -1.5)]:
                    r = page.evaluate('([t, k, x, y]) => __bench.overpull(t, k, x, y)',
                                      [json.dumps(scene), k, dx, dy])
                    rows.append(('%s: pull (%g, %g) m beyond, hold, let go' % (label, dx, dy),
                                 'held max strain %.2f; then fastest %.1f m/s, at most %d '
                                 'vertices above 5 m/s' % (r['held_max_strain'],
                                                            r['after_fastest'],
                                                            r['after_over_5'])))
                free = dict({'cols': n, 'rows': n, 'spacing': h, 'gravity': [0, 0]}, **over)
                for speed in [1.0, 3.0, 10.0]:
                    v = page.evaluate('([t, k, s]) => __bench.flick(t, k, s)',
                                      [json.dumps(free), (n // 2) * n + n // 2, speed])
                    rows.append(('%s: flick at %g m/s, let go' % (label, speed),
                                 'centre of mass then moves at %.2f m/s' % v))
                progress('gestures: %s done' % label)
        finally:
            browser.close()
    lines = ['# Gestures', '', '`python -m bench --gestures`, %s: %s' % (
        time.strftime('%Y-%m-%d %H:%M:%S %Z'), gestures.__doc__.split('\n')[0].strip() + ' ' +
        ' '.join(x.strip() for x in gestures.__doc__.split('\n')[1:]).strip()), '',
        '| gesture | result |', '|---|---|']
    lines += ['| %s | %s |' % r for r in rows]
    return '\n'.join(lines) + '\n'
