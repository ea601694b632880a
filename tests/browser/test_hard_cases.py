"""The page on a 200x200 grid. (The hard cases of tests/test_robustness.py, whose physics CPython
proves, are in the scene catalogue, tests/catalogue.py: the parity suite checks that the page
returns the very same doubles, which carries those proofs over.)"""

import json
import math

import pytest

from cloth.keys import MODEL
from cloth.presets import preset_scene

from browser_helpers import page_url


@pytest.fixture(scope='module')
def page(browser):
    context = browser.new_context()
    pg = context.new_page()
    errors = []
    pg.on('pageerror', lambda e: errors.append(str(e)))
    pg.goto(page_url())
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


@pytest.mark.parametrize('solver', ['vbd', pytest.param('xpbd', marks=pytest.mark.xfail(strict=True, reason=(
    'core bug: XPBD at its own 16 substeps, one sweep each, blows up on Two corners at 200x200 '
    '(positions from 2.2 m to 251 m between frames 30 and 32, with or without the carried clamp; '
    'fine at 160x160): a zigzag along the hem next to the left clamp, its vertices 8-12 moving '
    'alternately up and down, grows 20-50 times a frame from frame 29; its unfinished solve gains '
    'energy, the class of tests/test_robustness.py\'s XPBD hard cases'))), 'jakobsen'])
def test_every_solver_keeps_a_200x200_two_corners_hang_bounded(page, solver):
    """Every solver of the menu, at its own budget, on the largest preset grid the page offers:
    the cloth stays within a few metres of its clamps (it hangs 1.6 m)."""
    scene = dict(preset_scene('corners', 200, 200), solver=solver)
    page.evaluate('(t) => clothApp.loadScene(t)', json.dumps(scene))
    page.evaluate('clothApp.advance(35)')   # 0.58 s: the clamps' pull has reached the hem
    positions = page.evaluate('clothApp.state().positions')
    assert all(math.isfinite(v) for p in positions for v in p)
    assert max(abs(v) for p in positions for v in p) < 5.0
