"""The controls: clamped inputs with a visible note, bad scenes shown while the old
one keeps running, buttons and the scene-JSON box."""
import json

import pytest
from playwright.sync_api import Error as PlaywrightError

from cloth.keys import spec
from cloth.keys import SOLVERS, SOLVER_BUDGETS, DEFAULT_SOLVER


def set_input(pg, selector, value):
    pg.fill(selector, str(value))
    pg.press(selector, 'Enter')
    pg.locator(selector).blur()


# Each field's ends are its key's (cloth/keys.py field_lo, field_hi); the grid is made one row
# high first, so that the most substeps are within what the page runs.
CLAMPS = [('#cols', 999, spec('cols').field_hi), ('#rows', 0, 1), ('#iterations', -5, 0),
          ('#substeps', 1000, spec('substeps').field_hi), ('#gravity', -1e6, spec('gravity').field_lo),
          ('#cols', 12.6, 13), ('#damping', 500, spec('damping').field_hi), ('#damping', -1, 0)]


def test_out_of_range_input_is_clamped_with_a_note(open_page):
    pg = open_page('?paused=1')
    for field, value, expect in CLAMPS:
        set_input(pg, field, value)
        note = pg.locator('#note')
        assert note.is_visible(), field
        assert ('clamped' in note.inner_text()) or ('rounded' in note.inner_text())
        assert float(pg.input_value(field)) == expect
        assert pg.info()['params'][field[1:]] == expect
        assert pg.info()['error'] == ''
    # a value that is not a number is refused with a note, the old value stays
    pg.js("clothApp.setScaleMode('fixed', 'abc')")
    assert 'not a number' in pg.locator('#note').inner_text()
    assert pg.info()['fullScale'] == 0.05
    pg.js("clothApp.setScaleMode('fixed', 7)")
    assert pg.info()['fullScale'] == 1 and 'clamped' in pg.locator('#note').inner_text()


def test_grid_size_change_rebuilds_the_scene(open_page):
    pg = open_page('?paused=1')
    set_input(pg, '#cols', 12)
    set_input(pg, '#rows', 9)
    st = pg.state()
    assert len(st['positions']) == 12 * 9
    assert pg.locator('#note').is_hidden()
    assert '12×9' in pg.locator('#r-size').inner_text() or pg.wait_for_function(
        '() => document.getElementById("r-size").textContent.includes("12×9")')


def test_bad_scene_shows_the_error_and_the_old_scene_keeps_running(open_page):
    pg = open_page()
    before = pg.info()
    for text, key in [('{"cols": 3,', 'scene'), ('{"cols": 3, "rows": 2, "spacing": -1}', 'spacing'),
                      ('{"cols": 3, "rows": 2, "spacing": 1, "wind": 2}', 'wind'),
                      ('{"cols": 3, "rows": 2, "spacing": 1, "pins": [6]}', 'pins')]:
        with pytest.raises(PlaywrightError) as err:
            pg.js('(t) => clothApp.loadScene(t)', text)
        assert key + ':' in str(err.value)
        banner = pg.locator('#banner')
        assert banner.is_visible() and key + ':' in banner.inner_text()
        assert 'previous scene keeps running' in banner.inner_text()
    info = pg.info()
    assert info['scene'] == before['scene'] and info['preset'] == 'curtain'
    pg.wait_for_function('(f) => clothApp.info().frames > f + 10', arg=info['frames'])
    # a good scene clears the banner
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'cols': 5, 'rows': 4, 'spacing': 0.2, 'pins': [0, 4]}))
    assert pg.locator('#banner').is_hidden() and pg.info()['preset'] == 'custom'
    assert len(pg.state()['positions']) == 20


def test_scene_json_box_loads_and_reports(open_page):
    pg = open_page('?paused=1')
    pg.click('#json-box summary')
    pg.click('#btn-show-json')
    shown = json.loads(pg.input_value('#scene-json'))
    assert shown['cols'] == 40 and shown['rows'] == 30
    pg.fill('#scene-json', 'not json')
    pg.click('#btn-load-json')
    assert pg.locator('#banner').is_visible() and 'scene:' in pg.locator('#banner').inner_text()
    shown['cols'] = 7
    pg.fill('#scene-json', json.dumps(shown))
    pg.click('#btn-load-json')
    assert pg.locator('#banner').is_hidden() and len(pg.state()['positions']) == 7 * 30


def test_buttons_pause_step_reset_and_solver(open_page):
    pg = open_page()
    pg.click('#btn-pause')
    assert pg.info()['paused'] and pg.inner_text('#btn-pause') == 'Resume'
    f = pg.info()['frames']
    pg.click('#btn-step')
    assert pg.info()['frames'] == f + 1
    p0 = pg.state()['positions']
    pg.js('clothApp.advance(20)')
    pg.click('#btn-reset')
    assert pg.info()['frames'] == 0 and pg.state()['positions'] != p0
    assert pg.info()['params']['solver'] == DEFAULT_SOLVER
    pg.select_option('#solver', 'jakobsen')     # a solver starts from its own steps
    info = pg.info()
    substeps, iterations = SOLVER_BUDGETS[SOLVERS.index('jakobsen')][:2]
    assert info['params']['solver'] == 'jakobsen' and info['params']['iterations'] == iterations
    assert info['params']['substeps'] == substeps and json.loads(info['scene'])['solver'] == 'jakobsen'
    pg.select_option('#preset', 'chain')
    assert pg.info()['preset'] == 'chain' and len(pg.state()['positions']) == 40


def test_readouts_update(open_page):
    pg = open_page()
    pg.wait_for_function('() => /\\d/.test(document.getElementById("r-fps").textContent)')
    for rid in ('#r-sim', '#r-render', '#r-rms', '#r-max'):
        txt = pg.inner_text(rid)
        assert txt != '–' and float(txt) >= 0, (rid, txt)
    assert '(top: ' in pg.inner_text('#legend-title')
