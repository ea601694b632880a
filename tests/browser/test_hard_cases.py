"""The page on a 200x200 grid. (The hard cases of tests/test_robustness.py, whose physics CPython
proves, are in the scene catalogue, tests/catalogue.py: the parity suite checks that the page
returns the very same doubles, which carries those proofs over.)"""

import json
import math

import pytest

from cloth.keys import MODEL

from conftest import DIST


@pytest.fixture(scope='module')
def page(browser):
    context = browser.new_context()
    pg = context.new_page()
    errors = []
    pg.on('pageerror', lambda e: errors.append(str(e)))
    pg.goto(DIST.as_uri())
    pg.wait_for_function('() => !!(window.clothCore && window.clothApp)')
    pg.evaluate('clothApp.setPaused(true)')
    yield pg
    context.close()
    assert errors == []


def test_200x200_grid_runs_in_the_page(page):
    n = 200
    scene = dict(model=MODEL, cols=n, rows=n, spacing=1.0 / (n - 1), pins=[0, n // 2, n - 1])
    page.evaluate('(t) => clothApp.loadScene(t)', json.dumps(scene))
    page.evaluate('clothApp.advance(20)')
    positions = page.evaluate('clothApp.state().positions')
    assert len(positions) == n * n
    assert all(math.isfinite(v) for p in positions for v in p)
    # The page really simulated the large grid: the unpinned top row has sagged.
    h = 1.0 / (n - 1)
    assert positions[n // 4][1] < -0.01
    assert positions[n // 4][0] == pytest.approx((n // 4) * h, abs=0.05)
