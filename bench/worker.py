"""The page's thread with the session in a Web Worker and without it (`python -m bench
--worker`): does input wait for the simulation?

For each mode (the Worker, the page's default; ?worker=0, the session on the page's thread) and
each size of Large cloth (71x71, and 200x200: about 8x the vertices and the work a frame), the
shipped page runs the cloth live for a warm-up, then a pointer drags a vertex for RUN_SECONDS,
one move an animation frame. Measured in the page:
- **latency**: from a pointer event (its timeStamp) to the start of the next animation frame
  after the page handled it (the frame that draws what the move did), median and 95th
  percentile, ms;
- **busy**: the share of the run the page's thread spent in tasks longer than 50 ms (the Long
  Tasks API): time in which input and drawing wait;
- **fps**: frames drawn per second; **sim/s**: simulated seconds per second (below 1: slow
  motion).

**The simulation's clock**: every preset at its default size, as the page opens it (the
session in its Worker, which keeps the simulation's own clock), on a large stage (1600x1000:
software WebGL fills its pixels slowly, so the drawing is slow), for CLOCK_SECONDS after a
warm-up: simulated seconds per second (target: at least 0.95), frames drawn per second, and the
simulation's own ms a frame (the readout's).
"""

import json

from cloth.presets import PRESETS, preset_scene
from bench.page import DIST

SIZES = [71, 200]
QUICK_SIZES = [30, 85]
RUN_SECONDS = 4.0
QUICK_RUN_SECONDS = 1.5
WARM_SECONDS = 1.5
# A small stage: software WebGL (headless Chromium's SwiftShader) fills pixels on the page's
# thread, and at 1000x700 filling them took most of it at every grid size, hiding the
# simulation's share (71x71 drew 4.6 frames a second, 200x200, whose cells are filled, 18.5).
VIEWPORT = {'width': 480, 'height': 360}
CLOCK_VIEWPORT = {'width': 1600, 'height': 1000}
CLOCK_SECONDS = 6.0
QUICK_CLOCK_SECONDS = 2.0
CLOCK_TARGET = 0.95

PROBE = '''() => {
  const out = window.__probe = { lat: [], longMs: 0, frames: 0, t0: performance.now(), f0: clothApp.info().frames };
  let pending = [];
  window.addEventListener('pointermove', (e) => { pending.push(e.timeStamp); }, true);
  new PerformanceObserver((list) => { for (const e of list.getEntries()) out.longMs += e.duration; })
    .observe({ type: 'longtask' });
  function frame(t) {
    for (const s of pending) out.lat.push(t - s);
    pending = [];
    out.frames++;
    requestAnimationFrame(frame);
  }
  requestAnimationFrame(frame);
}'''


def measure(browser, worker, n, seconds):
    page = browser.new_page(viewport=VIEWPORT)
    errors = []
    page.on('pageerror', lambda e: errors.append(str(e)))
    page.goto('file://%s?worker=%d' % (DIST, 1 if worker else 0))
    page.wait_for_function('() => window.clothApp && clothApp.info().frames >= 0')
    page.evaluate('(t) => clothApp.loadScene(t)', json.dumps(preset_scene('large', n, n)))
    page.wait_for_timeout(WARM_SECONDS * 1000)
    k = n * n - n // 2 - 1
    x, y = page.evaluate('(k) => clothApp.state().screen[k]', k)
    page.mouse.move(x, y)
    page.mouse.down()
    page.evaluate(PROBE)
    steps = int(seconds * 60)
    for i in range(steps):
        page.mouse.move(x + 120 * i / steps, y + 60 * i / steps)
        page.evaluate('() => new Promise((r) => requestAnimationFrame(() => r()))')
    page.mouse.up()
    p = page.evaluate('''() => { const p = window.__probe, t = performance.now() - p.t0;
        return { lat: p.lat, longMs: p.longMs, ms: t, frames: p.frames,
                 simulated: (clothApp.info().frames - p.f0) / 60, worker: clothApp.info().worker }; }''')
    page.close()
    lat = sorted(p['lat'])
    pick = (lambda q: lat[min(len(lat) - 1, int(q * len(lat)))] if lat else float('nan'))
    return {'mode': 'worker' if p['worker'] else 'page thread', 'n': n, 'median': pick(0.5), 'p95': pick(0.95),
            'busy': p['longMs'] / p['ms'], 'fps': 1000 * p['frames'] / p['ms'],
            'speed': p['simulated'] / (p['ms'] / 1000), 'moves': len(lat), 'seconds': seconds, 'errors': errors}


def clock(browser, name, seconds):
    """A preset at its default size, opened as a person opens it, run `seconds`."""
    page = browser.new_page(viewport=CLOCK_VIEWPORT)
    errors = []
    page.on('pageerror', lambda e: errors.append(str(e)))
    page.goto('file://%s?preset=%s' % (DIST, name))
    page.wait_for_function('() => window.clothApp && clothApp.info().frames >= 0')
    page.wait_for_timeout(WARM_SECONDS * 1000)
    start = page.evaluate('() => { window.__drawn = 0; (function f() { window.__drawn++; requestAnimationFrame(f); })();'
                          ' return [performance.now(), clothApp.info().frames]; }')
    page.wait_for_timeout(seconds * 1000)
    end = page.evaluate('() => [performance.now(), clothApp.info().frames, window.__drawn, clothApp.info().simMs,'
                        ' clothApp.info().worker, clothApp.state().positions.length, clothApp.info().params]')
    page.close()
    wall = (end[0] - start[0]) / 1000
    return {'kind': 'clock', 'preset': name, 'grid': str(end[6]), 'verts': end[5], 'speed': (end[1] - start[1]) / 60 / wall,
            'fps': end[2] / wall, 'simMs': end[3], 'worker': end[4], 'seconds': seconds, 'errors': errors}


def run(page, quick, progress):
    browser = page.context.browser
    sizes = QUICK_SIZES if quick else SIZES
    seconds = QUICK_RUN_SECONDS if quick else RUN_SECONDS
    rows = []
    for p in PRESETS:
        progress('the clock: %s at its default size' % p[0])
        rows.append(clock(browser, p[0], QUICK_CLOCK_SECONDS if quick else CLOCK_SECONDS))
    for worker in (True, False):
        for n in sizes:
            progress('%s, Large cloth %dx%d' % ('worker' if worker else 'page thread', n, n))
            rows.append(measure(browser, worker, n, seconds))
    return rows


def ceiling(r):
    """The most simulated seconds a second a simulation whose frame takes r['simMs'] can step."""
    ms = r['simMs']
    return 1.0 if ms is None or not ms > 1000.0 / 60 else (1000.0 / 60) / ms


def markdown(rows, meta):
    clocks = [r for r in rows if r.get('kind') == 'clock']
    rows = [r for r in rows if r.get('kind') != 'clock']
    slow = ['%s %.2f (its ceiling %.2f)' % (r['preset'], r['speed'], ceiling(r)) for r in clocks
            if r['speed'] < CLOCK_TARGET * ceiling(r)]
    lines = ['# Input and the simulation\'s thread', '',
             '`python -m bench --worker` on %s, %s.' % (meta['date'], meta['machine']), '',
             '**The simulation\'s clock**: every preset at its default size, opened as a person opens it '
             '(the session in its Worker) on a %dx%d stage, run %g s: simulated seconds per second '
             '(target: at least %.2f of its ceiling, the most a simulation whose frame takes its ms can '
             'step: 1 while that is under 1/60 s), frames drawn per second, and the simulation\'s ms a frame.' % (
                 CLOCK_VIEWPORT['width'], CLOCK_VIEWPORT['height'], clocks[0]['seconds'] if clocks and 'seconds' in clocks[0] else CLOCK_SECONDS,
                 CLOCK_TARGET), '',
             'Target: ' + ('PASS, every one' if not slow else 'FAIL: ' + ', '.join(slow)), '',
             '| preset | size | sim/s | ceiling | fps (drawn) | sim ms a frame |', '|---|---|---|---|---|---|']
    for r in clocks:
        lines.append('| %s | %d vertices | %.3f | %.2f | %.1f | %s |' % (
            r['preset'], r['verts'], r['speed'], ceiling(r), r['fps'],
            '%.2f' % r['simMs'] if r['simMs'] is not None and r['simMs'] == r['simMs'] else 'at rest'))
    lines += ['',
             'Large cloth dragged for %g s, one pointer move an animation frame, with the session in a '
             'Web Worker (the page\'s default) and on the page\'s thread (?worker=0). **latency**: a '
             'pointer event to the next animation frame after it was handled (ms, median and 95th '
             'percentile); **busy**: the share of the run in tasks over 50 ms on the page\'s thread; '
             '**sim/s**: simulated seconds per second (slow motion below 1).' % rows[0]['seconds'], '',
             '| mode | grid | latency median (ms) | latency p95 (ms) | busy | fps | sim/s | moves |',
             '|---|---|---|---|---|---|---|---|']
    for r in rows:
        lines.append('| %s | %dx%d | %.1f | %.1f | %.0f%% | %.1f | %.2f | %d |' % (
            r['mode'], r['n'], r['n'], r['median'], r['p95'], 100 * r['busy'], r['fps'], r['speed'], r['moves']))
    by = {(r['mode'], r['n']): r for r in rows}
    sizes = sorted({r['n'] for r in rows})
    lines.append('')
    for mode in ('worker', 'page thread'):
        a, b = by.get((mode, sizes[0])), by.get((mode, sizes[-1]))
        if a and b:
            lines.append('- %s: %dx%d against %dx%d (%.1fx the vertices): latency p95 %.1f -> %.1f ms, busy %.0f%% -> %.0f%%, '
                         'fps %.1f -> %.1f.' % (mode, b['n'], b['n'], a['n'], a['n'], (b['n'] / a['n']) ** 2,
                                                a['p95'], b['p95'], 100 * a['busy'], 100 * b['busy'], a['fps'], b['fps']))
    return '\n'.join(lines) + '\n'
