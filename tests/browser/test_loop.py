"""The loop: fixed dt, an accumulator, and a cap on catch-up (Playwright's fake clock)."""


def test_a_long_gap_never_injects_a_big_step(open_page):
    pg = open_page()
    pg.clock.install(time=0)
    pg.reload()
    pg.wait_for_function('window.clothApp !== undefined')
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
