"""The loop: fixed dt, an accumulator, and a cap on catch-up (Playwright's fake clock)."""
import json

from cloth.keys import MODEL

from browser_helpers import default_preset_at


def test_a_long_gap_never_injects_a_big_step(open_page):
    pg = open_page()
    pg.clock.install(time=0)
    pg.reload()
    pg.wait_for_function('window.clothApp !== undefined')
    # The default preset at a quarter of its vertices: the CLI replays the whole recording.
    pg.js('(t) => clothApp.loadScene(t)', default_preset_at(20, 15))
    pg.clock.pause_at(5000)             # from here time moves only when the test says
    f0 = pg.info()['frames']
    pg.clock.run_for(1000)              # one second of 60 Hz animation frames
    f1 = pg.info()['frames']
    assert 58 <= f1 - f0 <= 62, (f0, f1)  # dt = 1/60 s of simulation per 1/60 s of clock
    pg.clock.fast_forward(10000)        # a tab switch: one animation frame, 10 s later
    pg.clock.run_for(20)
    f2 = pg.info()['frames']
    assert f2 - f1 <= 4 + 2, (f1, f2)   # MAX_CATCHUP, then one frame per 1/60 s
    st = pg.state()
    assert all(v == v and abs(v) < 1e3 for p in st['positions'] for v in p)
    # a drag across the gap and the catch-up frames: the recording replays it exactly
    x, y = st['screen'][14 * 20 + 10]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 50, y - 40, steps=4)
    pg.clock.run_for(100)
    pg.clock.fast_forward(3000)             # another stall, with the vertex held
    pg.mouse.move(x - 30, y - 80, steps=4)
    pg.clock.run_for(200)
    pg.mouse.up()
    pg.clock.run_for(100)
    from test_recording_page import assert_replays
    assert_replays(pg)


def test_a_cloth_at_rest_sleeps_until_touched(open_page):
    # No work where nothing changes: once the core puts a settled cloth to sleep, the page
    # neither steps, measures nor redraws it, and says so; a drag wakes it.
    pg = open_page()
    pg.clock.install(time=0)
    pg.reload()
    pg.wait_for_function('window.clothApp !== undefined')
    scene = dict(model=MODEL, cols=12, rows=10, spacing=0.1, pins=list(range(12)), damping=2.0)
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(scene))
    pg.clock.pause_at(5000)
    # 5 s: the membrane curtain (jersey) is within the core's rest bounds after about 2.7 s and
    # sleeps 1 s later (cloth/sleep.py SLEEP_TIME; 224 frames in CPython, the same in the page)
    pg.clock.run_for(5000)
    info = pg.info()
    assert info['asleep'], info
    pg.wait_for_function('/at rest/.test(document.getElementById("r-size").textContent)')
    renders, frames = info['renders'], info['frames']
    pg.clock.run_for(1000)
    info = pg.info()
    assert info['frames'] >= frames + 58      # time still passes ...
    assert info['renders'] == renders         # ... but nothing is drawn again
    st = pg.state()
    x, y = st['screen'][9 * 12 + 5]           # the bottom row, middle
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 60, y + 30, steps=3)
    pg.clock.run_for(200)
    info = pg.info()
    assert not info['asleep'] and info['renders'] > renders
    assert pg.state()['positions'] != st['positions']
    pg.mouse.up()
