"""The loop: fixed dt, an accumulator, and a cap on catch-up (Playwright's fake clock)."""


def test_a_long_gap_never_injects_a_big_step(open_page):
    pg = open_page()
    pg.clock.install()
    pg.reload()
    pg.wait_for_function('window.clothApp !== undefined')
    f0 = pg.info()['frames']
    pg.clock.run_for(1000)              # one second of 60 Hz animation frames
    f1 = pg.info()['frames']
    assert 50 <= f1 - f0 <= 75, (f0, f1)  # about dt = 1/60 s of simulation per 1/60 s of clock
    pg.clock.fast_forward(10000)        # a tab switch: one animation frame, 10 s later
    pg.clock.run_for(20)
    f2 = pg.info()['frames']
    assert f2 - f1 <= 8, (f1, f2)       # at most MAX_CATCHUP frames per animation frame
    st = pg.state()
    assert all(v == v and abs(v) < 1e3 for p in st['positions'] for v in p)
