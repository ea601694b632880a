"""The hard cases in the page: the same scenes as tests/test_robustness.py, run by the shipped
JS. CPython proves their physics (finite, no energy gain, back to rest); here the page must
return the very same doubles, which carries those proofs over, and stay finite."""

import json
import math
import sys
from pathlib import Path

import pytest

from cloth.api import run

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from hard_cases import HARD, BOUNDED  # noqa: E402
from cloth.keys import MODEL  # noqa: E402

from conftest import DIST  # noqa: E402


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


CASES = dict({name: (case[0], case[1]) for name, case in HARD.items()}, **BOUNDED)


@pytest.mark.parametrize('name', sorted(CASES))
def test_hard_case_in_the_page_matches_cpython(page, name):
    scene, frames = CASES[name]
    text = json.dumps(scene)
    js = json.loads(page.evaluate('([t, f]) => clothCore.run(t, f)', [text, frames]))
    py = json.loads(run(text, frames))
    for key in ['positions', 'edge_value', 'node_stress']:
        flat_js = [v for item in js[key] for v in (item if isinstance(item, list) else [item])]
        flat_py = [v for item in py[key] for v in (item if isinstance(item, list) else [item])]
        assert all(math.isfinite(v) for v in flat_js)
        assert [float(v) for v in flat_js] == [float(v) for v in flat_py], key


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
