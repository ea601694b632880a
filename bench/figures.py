"""The docs' other figures (`python -m bench --figures`), each measured in the shipped page:
- the pendulum: a 1 m cotton pendulum released horizontally, its period against the exact
  elliptic one and the height it loses a swing, per solver;
- sleep: when each preset, as shipped, is put to sleep (s), and what a frame costs then;
- the world: a dragged 120x120 curtain with wind and four obstacles, against the same without;
- compare mode: N panels of one scene stepped as the page steps them, against one;
- drawing: a frame drawn under software WebGL (SwiftShader), waited for.
"""

import json
import math

from cloth.presets import PRESETS, preset_scene
from cloth.reference import pendulum_period
from cloth.keys import SOLVERS
from bench.page import page_of, HARNESS

PENDULUM_FRAMES = 900
SLEEP_SIZES = [10, 30, 60, 120, 200]
QUICK_SLEEP_SIZES = [10, 20]
SLEEP_CAP = 1800
DRAW = [('curtain', 30), ('curtain', 120), ('curtain', 200), ('large', 200)]
DRAW_FRAMES = 10
PANELS = [1, 2, 3, 4]


def pendulum(page, solver):
    text = json.dumps({'model': 2, 'cols': 2, 'rows': 1, 'spacing': 1.0, 'pins': [0], 'solver': solver,
                       'stretch': 5000.0, 'density': 0.15})
    track = page.evaluate('''([t, frames]) => {
      const cl = clothCore.load(t), r = clothRunner.run(cl), out = [];
      for (let f = 0; f < frames; f++) { clothRunner.step(r, 1, 0); out.push([cl.pos[2], cl.pos[3]]); }
      return out;
    }''', [text, PENDULUM_FRAMES])
    dt = 1.0 / 60.0
    crossings, heights, side = [], [[0.0]], None
    px = 1.0
    for f, (x, y) in enumerate(track, 1):
        if px > 0 >= x or px < 0 <= x:
            crossings.append((f - 1 + px / (px - x)) * dt)
        s = 1 if x > 0 else -1
        if side is not None and s != side:
            heights.append([])
        side = s
        heights[-1].append(y)
        px = x
    periods = [crossings[i + 2] - crossings[i] for i in range(len(crossings) - 2)]
    tops = [max(h) for h in heights]
    lost = [(a - b) / (1 + a) for a, b in zip(tops[:-1], tops[1:-1])]
    exact = pendulum_period(1.0, math.pi / 2)
    return {'solver': solver, 'period': sum(periods) / len(periods), 'exact': exact,
            'lost': max(lost) if lost else float('nan')}


def asleep_at(page, text):
    return page.evaluate('''([t, cap]) => {
      const cl = clothCore.load(t), r = clothRunner.run(cl);
      for (let f = 1; f <= cap; f++) { clothRunner.step(r, 1, 0); if (cl.asleep) {
        const t0 = performance.now(); clothRunner.step(r, 600, 0);
        return [f * cl.dt, (performance.now() - t0) / 600]; } }
      return [-1, 0];
    }''', [text, SLEEP_CAP])


def world(page):
    base = preset_scene('curtain', 120, 120)
    base['sleep'] = False
    windy = dict(base)
    windy.update({'wind': [8.0, 0.0], 'drag': 0.4, 'gust': [0.5, 1.7],
                  'obstacles': [{'circle': [0.5, -1.2, 0.1]}, {'circle': [1.5, -1.2, 0.1]},
                                {'box': [0.8, -2.6, 1.2, -2.4]}, {'box': [-0.4, -0.5, -0.2, -0.3]}]})
    ms = page.evaluate('([a, b]) => __bench.timeSide([a, b], 60, 7)', [json.dumps(base), json.dumps(windy)])
    return {'still': ms[0], 'world': ms[1]}


def panels(page):
    obj = preset_scene('curtain', 60, 60)
    obj['sleep'] = False
    one = json.dumps(obj)
    out = []
    for count in PANELS:
        ms = page.evaluate('([t, n]) => __bench.timeSide(Array(n).fill(t), 60, 5)', [one, count])
        out.append({'panels': count, 'ms': sum(ms)})
    return out


def draw(browser_page_factory):
    rows = []
    for name, n in DRAW:
        page = browser_page_factory()
        try:
            text = json.dumps(preset_scene(name, n, n))
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
            }''', [text, DRAW_FRAMES])
        finally:
            page.close()
        rows.append({'scene': name, 'n': n, 'ms': ms})
    return rows


def run(page, quick, progress):
    out = {'pendulum': [], 'sleep': [], 'world': None, 'panels': [], 'draw': []}
    for solver in SOLVERS:
        progress('pendulum, ' + solver)
        out['pendulum'].append(pendulum(page, solver))
    for p in PRESETS:
        for n in (QUICK_SLEEP_SIZES if quick else SLEEP_SIZES):
            cols, rows = (n, 1) if p[3] == 1 else (n, n)
            progress('sleep, %s %dx%d' % (p[0], cols, rows))
            at, ms = asleep_at(page, json.dumps(preset_scene(p[0], cols, rows)))
            out['sleep'].append({'preset': p[0], 'cols': cols, 'rows': rows, 'asleep': at, 'ms': ms})
    if not quick:
        progress('world')
        out['world'] = world(page)
        progress('compare panels')
        out['panels'] = panels(page)
        progress('drawing')
        browser = page.context.browser
        out['draw'] = draw(lambda: fresh(browser))
    return out


def fresh(browser):
    page = page_of(browser, [])
    page.add_script_tag(path=HARNESS)
    return page


def markdown(res, meta):
    lines = ['# Figures', '', '`python -m bench --figures` on %s, %s.' % (meta['date'], meta['machine']), '',
             '## The pendulum', '',
             'A 1 m cotton pendulum released horizontally, 15 s; exact period %.4f s.' % res['pendulum'][0]['exact'], '',
             '| solver | period (s) | error | height lost a swing (most) |', '|---|---|---|---|']
    for r in res['pendulum']:
        lines.append('| %s | %.4f | %.2g%% | %.2g%% |' % (r['solver'], r['period'],
                                                          100 * (r['period'] - r['exact']) / r['exact'], 100 * r['lost']))
    lines += ['', '## Sleep', '', 'Each preset as shipped, from its start: when it is put to sleep (s; '
              'never within %d s: -) and the time a frame costs after.' % (SLEEP_CAP // 60), '',
              '| preset | grid | asleep at (s) | ms/frame after |', '|---|---|---|---|']
    for r in res['sleep']:
        lines.append('| %s | %dx%d | %s | %.3g |' % (r['preset'], r['cols'], r['rows'],
                                                    '%.1f' % r['asleep'] if r['asleep'] >= 0 else '-', r['ms']))
    if res['world']:
        w = res['world']
        lines += ['', '## Wind and obstacles', '', 'A 120x120 curtain, settling, with wind, gusts and four '
                  'obstacles against the same without: %.3g against %.3g ms a frame (%.2fx).' % (
                      w['world'], w['still'], w['world'] / w['still'])]
    if res['panels']:
        one = res['panels'][0]['ms']
        lines += ['', '## Compare mode', '', 'A 60x60 curtain in N panels, stepped one after another:', '',
                  '| panels | ms/frame | x one |', '|---|---|---|']
        for r in res['panels']:
            lines.append('| %d | %.3g | %.2f |' % (r['panels'], r['ms'], r['ms'] / one))
    if res['draw']:
        lines += ['', '## Drawing', '', 'A frame drawn under software WebGL (SwiftShader), waited for '
                  '(readPixels):', '', '| scene | ms a frame |', '|---|---|']
        for r in res['draw']:
            lines.append('| %s %dx%d | %.3g |' % (r['scene'], r['n'], r['n'], r['ms']))
    return '\n'.join(lines) + '\n'
