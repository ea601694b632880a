"""The timing readouts say what a person's frames do (issue #41): `fps` is frames counted over
time (1 / the mean gap over the last second, webgl/ui/readouts.js frameClock), and `render` is a
drawing timed until WebGL's finish() returns, so on a slow scene the two account for the frames'
time instead of reading 4-9x the real rate and a fraction of a millisecond."""
import json

import pytest

from cloth.presets import PRESETS, preset_scene

# The frames the test counts itself, in the page: every animation frame's timestamp (s).
COUNT = '''() => { const started = !!window.__frames; window.__frames = [];
  if (!started) (function f(t) { __frames.push(t / 1000); requestAnimationFrame(f); })(performance.now()); }'''
# The rate of the frames the test counted, by the readout's rule, up to the readout's frame.
COUNTED = '''(at) => { const r = clothReadouts, t = __frames.filter(function (x) { return x <= at + 1e-9; });
  let i = t.length - 1, gaps = 0;
  while (i > 0 && (t[t.length - 1] - t[i] < r.FPS_WINDOW || gaps < r.FPS_MIN_GAPS)) { i--; gaps++; }
  return { rate: gaps / (t[t.length - 1] - t[i]), gaps: gaps }; }'''


def rate_of(pg, times):
    return pg.js('''(ts) => { const c = clothReadouts.frameClock();
      for (let i = 0; i < ts.length; i++) c.push(ts[i]); return c.rate(); }''', times)


def test_fps_is_frames_over_time_not_a_mean_of_one_over_gap(open_page):
    pg = open_page('?paused=1')
    # A slow page: a 0.3 s stall, then a burst of five 10 ms frames, over and over (the
    # pattern the issue measured: an average of 1 / gap read 4-9x the real rate).
    times, t = [0.0], 0.0
    for _ in range(12):
        t += 0.3
        times.append(t)
        for _ in range(5):
            t += 0.01
            times.append(t)
    real = 6 / 0.35
    assert rate_of(pg, times) == pytest.approx(real, rel=0.01)
    # Steady frames, slow and fast, past the ring's length.
    assert rate_of(pg, [0.5 * i for i in range(10)]) == pytest.approx(2.0)
    assert rate_of(pg, [i / 60 for i in range(1000)]) == pytest.approx(60.0)
    # One frame is no rate (NaN, asked in the page: a driver's JSON makes it null).
    assert pg.js('() => { const c = clothReadouts.frameClock(); c.push(0); return Number.isNaN(c.rate()); }')


# Every preset, at 10, 60 or 200 columns in turn, and the two heaviest at 200 (a frame a second
# under software WebGL: the rate the old readout misread most).
SIZES = [10, 60, 200]
CASES = sorted(set([(p[0], SIZES[i % 3]) for i, p in enumerate(PRESETS)] + [('large', 200), ('curtain', 200)]))


def rates_match(pg, cases):
    """Each (preset, size) of `cases` runs on the open page until its readout has counted 1.5 s
    of frames: the readout is the rate of the frames the page counted itself (any engine)."""
    for name, size in cases:
        cols, rows = (size, 1) if name == 'chain' else (size, size)
        pg.js('(t) => clothApp.loadScene(t)', json.dumps(preset_scene(name, cols, rows)))
        pg.js('clothApp.setPaused(false)')
        pg.js(COUNT)
        start = pg.js('performance.now() / 1000')
        pg.wait_for_function('() => clothApp.info().fpsAt > %r + 1.5 && __frames.length > 6' % start)
        # The readout's value, its frame and the text shown, read together (in one task).
        fps, at, shown = pg.js('() => [clothApp.info().fps, clothApp.info().fpsAt,'
                               ' document.getElementById("r-fps").textContent]')
        counted = pg.js(COUNTED, at)
        assert counted['gaps'] >= 4, (name, counted)
        assert fps == pytest.approx(counted['rate'], rel=0.25), (name, size, fps, counted)
        assert float(shown) == pytest.approx(fps, abs=0.51), (name, shown, fps)
        pg.js('clothApp.setPaused(true)')


@pytest.mark.parametrize('size', [10, 60, 200])
def test_fps_readout_is_the_rate_of_frames_counted_in_the_page(open_page, size):
    rates_match(open_page('?paused=1'), [c for c in CASES if c[1] == size])


def test_render_is_a_finished_drawing_and_says_so(open_page):
    """`render` is one frame's drawing timed until WebGL has executed it (gl.finish), sampled
    once a readout; the browser's compositing of the page is not in it (fps counts it), and
    the readout's title says so."""
    pg = open_page('?paused=1')
    scene = preset_scene('large', 100, 100)
    scene['sleep'] = False                  # drawn every frame: a cloth at rest is not redrawn
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(scene))
    pg.js('clothApp.setPaused(false)')
    start = pg.js('performance.now() / 1000')
    pg.wait_for_function('(s) => clothApp.info().fpsAt > s + 1', arg=start, timeout=60000)
    render = pg.info()['renderMs']
    # performance.now() ticks in 0.1 ms here: a drawing may time as 0.3 ms twice, or as 0
    assert 0 <= render < 1e4, render
    title = pg.get_attribute('#r-render', 'title') or pg.js(
        '() => document.getElementById("r-render").parentElement.title')
    assert 'finish' in title and 'compositing' in title, title
    assert 'counted over the last second' in pg.js('() => document.getElementById("r-fps").parentElement.title')


@pytest.mark.parametrize('size', [(1, 1), (30, 20)])
def test_a_cloth_that_has_left_the_view_is_said_to_have(open_page, size):
    """A cloth with nothing to hold it falls for good, out of the view: the grid readout says
    so (the stage was empty under normal readouts), and says nothing while it is in view."""
    from browser_helpers import wait_until
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    obj = json.loads(pg.info()['scene'])
    obj.update({'cols': size[0], 'rows': size[1], 'pins': []})
    obj.pop('actions', None)
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(obj))
    away = 'document.getElementById("r-size").textContent.indexOf("left the view") >= 0'
    pg.wait_for_timeout(400)
    assert not pg.js(away) and pg.info()['frames'] == 0
    pg.js('clothApp.advance(180)')                  # 3 s: 20 m down in the scene's still air
    wait_until(pg, away)
    pg.keyboard.press('r')
    wait_until(pg, '!(' + away + ')')
    # Two panels, the first in thick air (0.1 m/s at most): the readout names the second.
    obj = json.loads(pg.info()['scene'])
    obj.update({'cols': 30, 'rows': 20, 'compare': [{'damping': 100}, {}]})
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(obj))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(180)')
    wait_until(pg, away)
    assert "panel 2’s cloth has left the view" in pg.locator('#r-size').inner_text()
