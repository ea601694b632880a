"""Obstacles in the page (issue #24.1): drawn, dragged with a real mouse through the cloth,
recorded and replayed. Runs in Chromium here and in Firefox and WebKit (tests/engines/)."""
import json
import sys

from browser_helpers import ROOT, default_preset_at, load_paused, wait_settled

sys.path.insert(0, str(ROOT))
from cloth import api  # noqa: E402
from cloth.keys import MODEL  # noqa: E402
sys.path.pop(0)


def test_an_obstacle_is_drawn_dragged_through_the_cloth_and_replays(open_page):
    """Obstacles (issue #24): a box drawn over the stage, dragged by a real mouse through the
    hanging cloth in a few large steps; no free vertex ends inside it, the drags are recorded
    as `obstacle` actions, and the recording replays in CPython to the page's positions."""
    pg = open_page('?paused=1')
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 14, 'rows': 10, 'spacing': 0.1, 'pins': list(range(14)), 'damping': 1,
         'obstacles': [{'box': [-0.5, -0.8, -0.2, -0.4], 'friction': 0.5}, {'circle': [0.6, -1.5, 0.15]}]}))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(30)')
    wait_settled(pg)
    # Drawn and sampled in one task: a layout change between would move the view.
    x, y, lit = pg.js('''() => { clothApp.advance(0); const p = clothApp.clientOf(-0.35, -0.6);
        const c = document.getElementById('obstacles'), r = c.getBoundingClientRect();
        const px = c.getContext('2d').getImageData(Math.round((p[0] - r.left) * c.width / r.width),
                                                   Math.round((p[1] - r.top) * c.height / r.height), 1, 1).data;
        return [Math.round(p[0]), Math.round(p[1]), px[3]]; }''')
    assert lit > 0                                           # the box is drawn where it is
    x1, _ = pg.js('clothApp.clientOf(1.0, -0.6)')
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 4):
        pg.mouse.move(round(x + (x1 - x) * i / 3), y, steps=2)
        pg.js('clothApp.advance(2)')
    pg.mouse.up()
    pg.js('clothApp.advance(20)')
    box = pg.js('clothApp.obstacles()')[0]
    assert box['at'][0] > 0.8                                # it went where the mouse took it
    st = pg.state()
    inside = [p for p, pinned in zip(st['positions'], st['pinned']) if not pinned and
              abs(p[0] - box['at'][0]) < box['half'][0] - 1e-9 and abs(p[1] - box['at'][1]) < box['half'][1] - 1e-9]
    assert inside == []
    text = pg.js('clothApp.recording()')
    assert [a['op'] for a in json.loads(text)['actions']].count('obstacle') >= 3
    assert json.loads(api.run(text))['positions'] == st['positions']


RELEASE = '''([preset, cols, rows, d]) => {
  const made = clothScenes.make(preset, Object.assign(clothScenes.defaults(preset), {cols: cols, rows: rows}));
  const c = clothCore.load(JSON.stringify(made.scene)), ops = clothCore.ops(c);
  let next = clothCore.applyDue(c, 0, 0);
  for (let f = 1; f <= 150; f++) { ops.frame(); next = clothCore.applyDue(c, next, f); }
  const k = c.n_verts - 1, x0 = c.pos[2 * k], y0 = c.pos[2 * k + 1];
  if (d > 0) ops.grab(k, x0, y0);
  for (let f = 0; f < 30; f++) { if (d > 0) ops.move(k, x0, y0 - d * (f + 1) / 30); ops.frame(); }
  for (let f = 0; f < 30; f++) ops.frame();
  // The largest strain the pull left: what the release lets go as speed, up to its strain
  // times the fabric's wave speed sqrt(stretch / density).
  let strain = 0;
  for (let e = 0; e < c.n_struct; e++) {
    const a = c.edge_a[e], b = c.edge_b[e];
    strain = Math.max(strain, Math.hypot(c.pos[2 * b] - c.pos[2 * a], c.pos[2 * b + 1] - c.pos[2 * a + 1]) / c.rest[e] - 1);
  }
  const snap = strain * Math.sqrt(c.scene.stretch / c.scene.density);
  if (d > 0) ops.release(k);
  // After the release: the fastest free vertex, the highest, and how far the kinetic energy
  // ever rises above what it could come from (the kinetic and elastic energy held at the
  // release, and what gravity has done since: tests/test_release.py).
  const e0 = ops.energies();
  let most = 0, top = -Infinity, rise = -Infinity;
  for (let f = 0; f < 240; f++) {
    ops.frame();
    const e = ops.energies();
    rise = Math.max(rise, e[0] - (e0[0] + e0[1] + e0[2] - e[2]));
    for (let i = 0; i < c.n_verts; i++) {
      if (c.fixed[i] !== 0) continue;
      const v = Math.hypot(c.vel[2 * i], c.vel[2 * i + 1]);
      if (v > most) most = v;
      top = Math.max(top, c.pos[2 * i + 1]);
    }
  }
  let held = true;
  for (let i = 0; i < c.n_verts; i++) if (c.pinned[i] !== 0 && c.fixed[i] === 0) held = false;
  return {speed: most, top: top, held: held, rise: rise, moving: e0[0] + e0[1], snap: snap,
          peg: c.n_obstacles ? [c.obstacle_at[1] - c.obstacle_half[1], c.obstacle_at[1] + c.obstacle_half[1]] : null}; }'''

# An unfinished solve may leave a little energy, at most this share of what was moving
# (tests/test_release.py GAIN).
GAIN = 1e-3


def test_the_new_presets_at_every_size_keep_what_they_hold_and_do_not_fling(open_page):
    """Towel on a peg and Flag in the wind (issue #24), 10 to 60 columns: the towel hangs from
    under its peg (a bar whose underside holds the middle of its top edge, cloth/presets.py),
    its pins stay pins, and letting go of a 0.5 m or 1 m pull of the towel's or the flag's
    corner flings nothing. The towel, which nothing drives: the release adds no energy (issue
    #40: the stretch the hand left comes back as motion, the corner snapping back at 6-7 m/s,
    and no more), and nothing is thrown up past its peg. The flag, driven by gusts: no free
    vertex faster than what the same cloth does untouched plus 3 m/s (issue #21's limit) or,
    where more, plus the speed the pull's largest strain gives back (strain times the wave
    speed: the flag at 10x7, calmer untouched since the air is a term of the step, 2.5 m/s,
    snaps back at 6.1 m/s from a 0.5 m pull)."""
    pg = open_page('?paused=1')
    for preset, sizes in (('towel', [(10, 10), (30, 30), (60, 60)]), ('flag', [(10, 7), (30, 20), (60, 40)])):
        for cols, rows in sizes:
            still = pg.js(RELEASE, [preset, cols, rows, 0.0])
            for d in (0.5, 1.0):
                got = pg.js(RELEASE, [preset, cols, rows, d])
                assert got['held'], (preset, cols, d, got)
                if preset == 'towel':
                    assert got['rise'] <= GAIN * got['moving'], (cols, d, got)
                    assert got['top'] <= got['peg'][0] + 1e-9, (cols, d, got)     # under its peg
                else:
                    assert got['speed'] < still['speed'] + max(3.0, got['snap']), (cols, d, got, still)
            if preset == 'towel':
                assert still['top'] <= still['peg'][0] + 1e-9, (cols, still)


def test_the_wind_and_gusts_fields_set_the_air_live_and_record_it(open_page):
    """The air's controls (issue #24.2) in the panel: a value typed into Wind and Gusts (the
    field's change event, what a person's Enter or leaving the field sends) sets the running
    cloth's air, is recorded as a `set`, and the recording replays in CPython to the page's
    positions; nonsense keeps the old value and says why. The default preset at 16x12: CPython's
    replay of it at 40x30 took 11 s in each engine's run."""
    pg = open_page('?paused=1')
    load_paused(pg, default_preset_at(16, 12))
    pg.js('clothApp.advance(30)')
    typed = '''([id, text]) => { const el = document.getElementById(id); el.value = text;
                                  el.dispatchEvent(new Event('change')); }'''
    pg.js(typed, ['wind', '6'])
    pg.js(typed, ['gust', '0.5'])
    scene = pg.js('clothApp.cloth().scene')
    assert (scene['wind_x'], scene['gust_amplitude']) == (6, 0.5)
    pg.js(typed, ['wind', 'abc'])
    assert pg.js('clothApp.cloth().scene')['wind_x'] == 6 and 'Wind' in pg.info()['note']
    pg.js('clothApp.advance(40)')
    text = pg.js('clothApp.recording()')
    sets = [a['scene'] for a in json.loads(text)['actions'] if a['op'] == 'set']
    assert {'wind': [6, 0]} in sets and any('gust' in s for s in sets), sets
    assert json.loads(api.run(text))['positions'] == pg.state()['positions']


def test_a_scene_that_starts_its_cloth_inside_an_obstacle_says_so(open_page):
    pg = open_page('?paused=1')
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 10, 'rows': 10, 'spacing': 0.1, 'pins': [0, 9],
         'obstacles': [{'circle': [0.45, -0.45, 0.2]}]}))
    inside = sum(1 for x, y in pg.state()['positions'] if (x - 0.45) ** 2 + (y + 0.45) ** 2 < 0.04)
    assert inside > 0 and pg.info()['note'].startswith('%d vertices start inside an obstacle' % inside)
    pg.js("clothApp.usePreset('towel')")                      # one that starts clear says nothing
    assert pg.info()['note'] == ''
