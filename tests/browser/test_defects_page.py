"""Issue #12 in the page, each defect as a class tried on more than the case reported:
fields that hold no number, scenes beyond what the page can run, URL options, live settings,
shortcuts wherever focus is, a held vertex through a resize, catch-up within a budget, a
grab that keeps its offset, overlays that never collide, and a scale that says what it shows."""
import json
import math
import random

import pytest

from browser_helpers import DIST, free_vertex, near, load_paused, page_url

from cloth.keys import MODEL, spec
from cloth.measure import BINS_PER_DECADE
from cloth.sleep import SLEEP_IMBALANCE as REST_IMBALANCE

COLS, ROWS = 40, 30      # the default preset (curtain)


def set_input(pg, selector, text):
    pg.fill(selector, '')
    pg.type(selector, text) if text else None
    pg.press(selector, 'Enter')
    pg.locator(selector).blur()


def note(pg):
    return pg.info()['note']


# ---- 1: a field that holds no number ---------------------------------------------------------

def test_a_field_without_a_number_changes_nothing_and_says_so(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(5)')
    before = pg.info()
    for field in ['#cols', '#iterations', '#gravity', '#damping', '#substeps']:
        for text in ['', 'abc', 'NaN', '1e309', '-', '  ']:
            set_input(pg, field, text)
            info = pg.info()
            assert 'not a number' in info['note'] or 'not a finite number' in info['note'], (field, text, info['note'])
            assert info['params'] == before['params'] and info['frames'] == before['frames'], (field, text)
            assert pg.input_value(field) == str(before['params'][field[1:]]), (field, text)
    # the full-scale field too
    pg.js("clothApp.setScaleMode('fixed')")
    set_input(pg, '#full-scale', 'abc')
    assert 'not a number' in note(pg) and pg.info()['fullScale'] == 0.05


def test_a_field_where_empty_means_off_tells_letters_from_empty(open_page):
    """Strength is off (the cloth does not tear) when empty; letters typed into it are not
    "empty" (a number field reports them as '' and tearing went off without a word), and a
    negative strength is a slip, not the minimum that shreds the cloth."""
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    set_input(pg, '#strength', '50')
    assert pg.info()['params']['strength'] == 50
    for text in ['abc', 'Infinity', '1e400', 'NaN', '-', '50x']:
        set_input(pg, '#strength', text)
        assert 'not a' in note(pg), (text, note(pg))
        assert pg.info()['params']['strength'] == 50 and pg.input_value('#strength') == '50', text
    set_input(pg, '#strength', '-1')
    assert 'below 0' in note(pg) and pg.info()['params']['strength'] == 50
    set_input(pg, '#strength', '0.5')
    assert 'clamped to its minimum 1' in note(pg) and pg.info()['params']['strength'] == 1
    set_input(pg, '#strength', '')
    assert pg.info()['params']['strength'] == 0 and pg.input_value('#strength') == ''


def test_a_drag_faster_than_the_cloth_can_follow_is_no_error(open_page):
    # Model 1's max_speed net and its notes ("A very fast drag", "Unstable settings") are gone
    # by design: a scene of the membrane has no speed limit, a hand's finite force is what
    # bounds a drag (cloth/hands.py HAND_FORCE). A pin yanked 300 px in one frame is followed
    # as far as that force takes it: nothing is said to be wrong, nothing blows up.
    pg = open_page()
    load_paused(pg, json.dumps(
        {'model': MODEL, 'cols': 20, 'rows': 20, 'spacing': 0.05, 'pins': [0, 19, 19 * 20 + 10], 'damping': 1}))
    k = 19 * 20 + 10
    st = pg.state()
    x, y = st['screen'][k]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(x + 300, y + 200)
    pg.js('clothApp.advance(3)')
    after = pg.state()
    hand = after['hands'][k]
    assert near(hand, (x + 300, y + 200), 0.01)
    # The held pin goes toward the pointer as the hand's force takes the cloth: 20 N on its
    # 0.2 kg, 0.1 m in these 3 frames (1/20 s) if it pulled the whole cloth as one; it moves
    # the cloth near it first (measured: 0.13 m). And the cloth is finite.
    moved = [b - a for a, b in zip(st['positions'][k], after['positions'][k])]
    toward = [hand[0] - x, -(hand[1] - y)]                   # screen y is down, the world's up
    along = (moved[0] * toward[0] + moved[1] * toward[1]) / math.hypot(*toward)
    assert along > 0.05, (moved, along)
    assert all(math.isfinite(v) for p in after['positions'] for v in p)
    pg.mouse.up()
    pg.js('clothApp.advance(30)')
    assert note(pg) == '' and pg.info()['error'] == '', (note(pg), pg.info()['error'])
    assert pg.state()['pinned'][k]                   # a dragged pin stays a pin, where it was left


# ---- 2: one size limit for everything the page loads ---------------------------------------

BEYOND = [
    {'cols': 1000, 'rows': 1000, 'spacing': 0.001},
    {'cols': 201, 'rows': 200, 'spacing': 0.01},
    {'cols': 40000, 'rows': 2, 'spacing': 0.01},
    {'cols': 200, 'rows': 200, 'spacing': 0.01, 'iterations': 1000},
    {'cols': 100, 'rows': 100, 'spacing': 0.01, 'substeps': 200, 'solver': 'jakobsen'},
]


def test_a_scene_beyond_the_page_limits_is_refused_at_once(open_page):
    pg = open_page()
    for scene in BEYOND:
        pg.js('(t) => { try { clothApp.loadScene(t); } catch (e) {} }', json.dumps(scene))
        info = pg.info()
        # refused by the page's limits (scenes.pageLimit), checked before anything is built
        assert info['preset'] == 'curtain' and 'page' in info['error'], (scene, info['error'])
        assert 'the page runs at most' in info['error'] or 'the page takes at most' in info['error'], \
            info['error']
    # the page still answers
    pg.keyboard.press('Space')
    assert pg.info()['paused']


def test_panel_settings_that_would_freeze_the_page_are_refused(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    set_input(pg, '#cols', '200')
    set_input(pg, '#rows', '200')
    assert pg.info()['params']['cols'] == 200
    set_input(pg, '#iterations', '200')
    set_input(pg, '#substeps', '16')
    info = pg.info()
    assert 'page' in info['error'] and info['params']['substeps'] * info['params']['iterations'] <= 200
    assert pg.input_value('#substeps') == str(info['params']['substeps'])


def test_a_heavy_scene_says_before_it_runs_slowly(open_page):
    pg = open_page()
    # A scene made before the membrane (no `model`) is said to be so too: both, in one note
    # (the second once replaced the first).
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'cols': 150, 'rows': 150, 'spacing': 0.01, 'pins': [0, 149], 'solver': 'jakobsen',
         'iterations': 60}))
    assert 'slow motion' in note(pg) and 'made before the membrane model' in note(pg), note(pg)
    # A new grid of it says so again, beside what the regrid itself reports.
    pg.js('clothApp.setPaused(true)')
    set_input(pg, '#cols', '160')
    assert pg.info()['params']['cols'] == 160 and 'slow motion' in note(pg), note(pg)


# ---- 3: many actions, any order --------------------------------------------------------------

def test_100000_shuffled_actions_load_in_the_page_and_match_the_cli(open_page):
    from cloth.api import run
    acts = [{'frame': f // 10, 'op': 'pin' if f % 2 else 'unpin', 'vertex': f % 12}
            for f in range(100000)]
    random.Random(2).shuffle(acts)
    text = json.dumps({'cols': 4, 'rows': 3, 'spacing': 0.1, 'actions': acts})
    pg = open_page('?paused=1')
    out = pg.js('(t) => { const t0 = performance.now(); const r = clothCore.run(t, 30);'
                ' return [r, performance.now() - t0]; }', text)
    assert out[0] == run(text, 30)
    pg.js('(t) => clothApp.loadScene(t)', text)
    assert pg.info()['error'] == ''


# ---- 5: URL options --------------------------------------------------------------------------

def test_an_unknown_url_option_gets_a_note_and_the_defaults(open_page):
    pg = open_page()
    for query, expect in [('?preset=toString', 'preset'), ('?preset=constructor', 'preset'),
                          ('?preset=__proto__', 'preset'), ('?preset=bogus', 'preset'),
                          ('?paused=maybe', 'paused'), ('?webgl=9', 'webgl'), ('?colour=red', 'colour')]:
        pg.goto(page_url(query))
        pg.wait_for_function('() => !!window.clothApp')
        info = pg.info()
        assert info['preset'] == 'curtain' and not info['paused'] and info['webgl'] > 0, query
        assert expect in info['note'], (query, info['note'])
        assert pg.locator('#fatal').is_hidden()
        pg.select_option('#preset', 'chain')
        assert pg.info()['preset'] == 'chain' and pg.locator('#fatal').is_hidden()
    # a value in another case is the same value; an option given twice says so; a flood of
    # unknown options gives a few notes, not a wall of text
    pg.goto(page_url('?preset=Chain&paused=TRUE'))
    pg.wait_for_function('() => !!window.clothApp')
    assert pg.info()['preset'] == 'chain' and pg.info()['paused'] and pg.info()['note'] == ''
    pg.goto(page_url('?preset=chain&preset=corners'))
    pg.wait_for_function('() => !!window.clothApp')
    assert pg.info()['preset'] == 'corners' and 'more than once' in pg.info()['note']
    pg.goto(page_url('?' + '&'.join('x%d=1' % i for i in range(300))))
    pg.wait_for_function('() => !!window.clothApp')
    assert 'and 296 more' in pg.info()['note'] and len(pg.info()['note']) < 600
    for query in ['?paused=true', '?paused=1', '?paused=yes']:
        pg.goto(page_url(query))
        pg.wait_for_function('() => !!window.clothApp')
        assert pg.info()['paused'] and pg.info()['note'] == '', query


def test_webgl_0_says_the_url_turned_drawing_off(open_page):
    pg = open_page('?webgl=0')
    text = pg.locator('#fatal').inner_text()
    assert 'webgl=0' in text and 'cannot create' not in text


# ---- 6: the same message for deep nesting in both runtimes ----------------------------------

@pytest.mark.parametrize('text', ['[' * 5000 + ']' * 5000, '{"cols": ' + '[' * 40 + ']' * 40 + '}',
                                  '{"a":' * 3000])
def test_deep_nesting_gives_the_cli_message_in_the_page(open_page, text):
    from cloth.api import run
    from cloth.scene import SceneError
    with pytest.raises(SceneError) as err:
        run(text, 1)
    pg = open_page('?paused=1')
    got = pg.js('(t) => { try { clothCore.run(t, 1); return ""; } catch (e) { return e.message; } }', text)
    assert got == str(err.value)
    pg.js('(t) => { try { clothApp.loadScene(t); } catch (e) {} }', text)
    assert str(err.value) in pg.info()['error']


# ---- 8: live settings ------------------------------------------------------------------------

def held_and_pinned(pg):
    st = pg.state()
    return st, [i for i, h in enumerate(st['held']) if h], [i for i, p in enumerate(st['pinned']) if p]


def test_a_setting_applies_to_the_running_cloth(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(20)')
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    pg.mouse.move(*st['screen'][k])
    pg.mouse.down()
    pg.mouse.move(st['screen'][k][0] + 60, st['screen'][k][1] + 30)
    pg.mouse.click(*st['screen'][5 * COLS + 7], button='right')      # a person's pin
    for field, text in [('#gravity', '-3'), ('#iterations', '3'), ('#substeps', '2'), ('#damping', '5')]:
        st1, held, pins = held_and_pinned(pg)
        frames = pg.info()['frames']
        set_input(pg, field, text)
        st2, held2, pins2 = held_and_pinned(pg)
        info = pg.info()
        assert info['frames'] == frames and held2 == held and pins2 == pins, field
        assert st2['positions'] == st1['positions'], field
        assert info['params'][field[1:]] == float(text), field
        assert json.loads(info['scene'])[field[1:]] in (float(text), [0, float(text)])
        pg.js('clothApp.advance(30)')
        assert pg.state()['held'][k]
    pg.mouse.up()


def test_the_solver_applies_to_the_running_cloth(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    frames = pg.js('clothApp.advance(40)')
    before = pg.state()['positions']
    pg.select_option('#solver', 'jakobsen')
    info = pg.info()
    assert info['frames'] == frames and info['params']['solver'] == 'jakobsen'
    assert info['params']['iterations'] == 20 and info['params']['substeps'] == 1
    assert pg.state()['positions'] == before


def test_a_grid_change_keeps_pins_at_their_row_and_column(open_page):
    pg = open_page()
    scene = {'cols': 20, 'rows': 10, 'spacing': 0.05, 'pins': [0, 19, 45, 199],
             'actions': [{'frame': 5, 'op': 'grab', 'vertex': 145, 'to': [0.3, -0.2]},
                         {'frame': 9, 'op': 'release', 'vertex': 145},
                         {'frame': 2, 'op': 'pin', 'vertex': 18}]}
    load_paused(pg, json.dumps(scene))
    pg.mouse.click(*pg.state()['screen'][3 * 20 + 4], button='right')   # a person's pin at (3, 4)
    set_input(pg, '#cols', '10')
    info = pg.info()
    assert info['error'] == '' and info['params']['cols'] == 10
    obj = json.loads(info['scene'])
    # (0,0) stays, (0,19) and (9,19) fall outside, (2,5) -> 25, and the person's (3,4) -> 34
    assert obj['pins'] == [0, 25, 34]
    # (7,5) -> 75 for the grab and its release; the pin of (0,18) falls outside
    assert [a['vertex'] for a in obj['actions']] == [75, 75]
    note = info['note']
    assert 'dropped' in note and 'pin at row 0 column 19' in note and 'pin at row 9 column 19' in note
    assert '1 scripted action' in note
    assert pg.state()['pinned'][34]


def test_a_persons_pin_changes_survive_any_number_of_grid_changes(open_page):
    pg = open_page()                                    # the curtain: its top row pinned (a rod)
    pg.js('clothApp.setPaused(true)')
    st = pg.state()
    pg.mouse.click(*st['screen'][4], button='right')              # unpin (0, 4)
    pg.mouse.click(*st['screen'][10 * 40 + 2], button='right')    # pin (10, 2)
    pg.mouse.click(*st['screen'][29 * 40 + 30], button='right')   # pin (29, 30)
    set_input(pg, '#rows', '29')
    # the pin at row 29 falls outside a 29-row grid, and the note says so
    assert 'your pin at row 29 column 30' in pg.info()['note']
    for cols, rows in [(20, 29), (24, 29), (40, 29), (40, 12), (33, 30)]:
        set_input(pg, '#cols', str(cols))
        set_input(pg, '#rows', str(rows))
        pinned = pg.state()['pinned']
        assert not pinned[4] and pinned[10 * cols + 2], (cols, rows)
        assert sum(pinned) == cols, (cols, rows)       # the rod but (0, 4), and (10, 2)


def test_scripted_pins_are_not_taken_for_a_persons(open_page):
    pg = open_page()
    scene = {'cols': 20, 'rows': 15, 'spacing': 0.05, 'pins': [0, 5, 10, 14, 19],
             'actions': [{'frame': 20, 'op': 'unpin', 'vertex': 5}, {'frame': 25, 'op': 'pin', 'vertex': 22}]}
    load_paused(pg, json.dumps(scene))
    pg.js('clothApp.advance(40)')
    set_input(pg, '#cols', '10')
    obj = json.loads(pg.info()['scene'])
    assert obj['pins'] == [0, 5]
    assert obj['actions'] == [{'frame': 20, 'op': 'unpin', 'vertex': 5}, {'frame': 25, 'op': 'pin', 'vertex': 12}]
    set_input(pg, '#cols', '20')
    assert json.loads(pg.info()['scene'])['pins'] == [0, 5]


def test_a_held_vertex_stays_held_through_a_grid_change(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    k = 29 * 40 + 20
    x, y = pg.state()['screen'][k]
    pg.mouse.move(x, y)
    pg.mouse.down()
    set_input(pg, '#cols', '30')
    st = pg.state()
    k2 = 29 * 30 + 20
    assert st['held'][k2] and sum(st['held']) == 1
    x0, y0 = st['screen'][k2]
    pg.mouse.move(x + 40, y - 30)
    st = pg.state()
    assert abs(st['hands'][k2][0] - (x0 + 40)) < 0.01 and abs(st['hands'][k2][1] - (y0 - 30)) < 0.01
    pg.mouse.up()
    assert not any(pg.state()['held'])
    # the new recording holds it from frame 0
    rec = json.loads(pg.js('clothApp.recording()'))
    assert rec['actions'][0] == {'frame': 0, 'op': 'grab', 'vertex': k2, 'to': st['positions'][k2]} or \
        rec['actions'][0]['op'] == 'grab'


# ---- 9: shortcuts wherever focus is ----------------------------------------------------------

def test_shortcuts_work_after_a_toggle_or_a_menu(open_page):
    pg = open_page()
    pg.locator('label:has(input[value=stress])').click()
    pg.keyboard.press('c')
    assert pg.info()['mode'] == 'strain'
    pg.keyboard.press('a')
    assert pg.info()['scaleMode'] == 'fixed'
    pg.select_option('#preset', 'corners')
    pg.keyboard.press('1')
    assert pg.info()['preset'] == 'curtain'
    pg.select_option('#solver', 'jakobsen')
    pg.keyboard.press('Space')
    assert pg.info()['paused']
    pg.locator('#btn-step').click()
    pg.keyboard.press('h')
    assert pg.locator('#help').is_visible()


def test_shortcuts_work_after_pressing_the_cloth_from_a_field(open_page):
    # The canvas's pointerdown calls preventDefault, which kept focus in a field clicked
    # before: the shortcuts stayed dead until a click elsewhere.
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.locator('#cols').click()
    x, y = pg.state()['screen'][29 * 40 + 20]
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.up()
    pg.keyboard.press('Space')
    assert not pg.info()['paused']
    pg.keyboard.press('c')
    assert pg.info()['mode'] == 'stress'


def test_a_button_clicked_with_the_mouse_leaves_space_to_the_shortcuts(open_page):
    pg = open_page()
    for button in ['#btn-reset', '#btn-step', '#btn-show-json', '#btn-help']:
        if button == '#btn-show-json':
            pg.locator('#json-box summary').click()
        pg.locator(button).click()
        if button == '#btn-help':
            pg.keyboard.press('Escape')
        paused = pg.info()['paused']
        frames = pg.info()['frames']
        pg.keyboard.press('Space')
        info = pg.info()
        assert info['paused'] != paused, button            # Space paused or resumed ...
        assert info['frames'] >= frames, button            # ... and did not reset the scene
        assert pg.locator('#help').is_hidden(), button
    # a keyboard user who tabs to a button still works it with Space
    pg.locator('#btn-reset').focus()
    pg.js('clothApp.setPaused(true)')     # no frame runs between the key and the reading
    pg.js('clothApp.advance(30)')
    pg.keyboard.press('Space')
    assert pg.info()['frames'] == 0


def test_the_help_is_modal(open_page):
    pg = open_page()
    pg.keyboard.press('h')
    for key in ['4', 'r', 'c', 's', 'a', 'ArrowRight']:
        pg.keyboard.press(key)
    info = pg.info()
    assert not info['paused'] and info['preset'] == 'curtain' and info['mode'] == 'strain'
    assert info['scaleMode'] == 'auto' and pg.locator('#help').is_visible()
    pg.keyboard.press('Tab')
    assert pg.js('document.activeElement.id') == 'help-close'
    # Space works the focused Close button, as on any button: the help closes, nothing
    # behind it pauses
    pg.keyboard.press('Space')
    assert pg.locator('#help').is_hidden() and not pg.info()['paused']
    pg.keyboard.press('?')
    pg.keyboard.press('Escape')
    assert pg.locator('#help').is_hidden()


@pytest.mark.parametrize('size', [(360, 640), (800, 400)])
def test_the_help_opens_at_its_title_on_a_small_screen(open_page, size):
    # Focus goes to Close, at the end of a card that scrolls on a small screen: focus()
    # scrolled the card to its last lines, the title and the keys out of view.
    pg = open_page(viewport={'width': size[0], 'height': size[1]}, has_touch=size[0] < 400)
    pg.keyboard.press('h')
    assert pg.js('document.activeElement.id') == 'help-close'
    assert pg.js("document.querySelector('#help .card').scrollTop") == 0
    title = pg.js("""() => { const c = document.querySelector('#help .card').getBoundingClientRect();
        const t = document.querySelector('#help h2').getBoundingClientRect();
        return t.top >= c.top && t.bottom <= c.bottom; }""")
    assert title


@pytest.mark.parametrize('size', [(1280, 800), (390, 844), (360, 640), (800, 400)])
def test_a_dialogs_close_is_on_screen_when_it_opens_and_as_it_scrolls(open_page, size):
    # The help's Close was the card's last line: at 1280x800 it opened at y = 1854, scrolled
    # out of the dialog. It stays at the top of the card, scrolled to its end too.
    pg = open_page(viewport={'width': size[0], 'height': size[1]}, has_touch=size[0] < 400)
    pg.keyboard.press('h')
    for scroll in ('0', 'c.scrollHeight')[:2]:
        seen = pg.js("""() => { const c = document.querySelector('#help .card');
            c.scrollTop = %s;
            const card = c.getBoundingClientRect(), b = document.getElementById('help-close').getBoundingClientRect();
            const x = b.left + b.width / 2, y = b.top + b.height / 2;
            return b.top >= card.top && b.bottom <= card.bottom && b.top >= 0 && b.bottom <= innerHeight &&
                   b.left >= 0 && b.right <= innerWidth && document.elementFromPoint(x, y) === document.getElementById('help-close'); }""" % scroll)
        assert seen, (size, scroll)
    pg.locator('#help-close').click()
    assert pg.locator('#help').is_hidden()


TAP_TARGETS = """() => { const out = [];
  for (const e of document.querySelectorAll('button, input, select, summary, a[href], textarea, [role=button]')) {
    if (e.offsetParent === null && getComputedStyle(e).position !== 'fixed') continue;
    let r = e.getBoundingClientRect();
    const label = e.closest('label');           // a checkbox's target is its label
    if (label && (e.type === 'checkbox' || e.type === 'radio')) r = label.getBoundingClientRect();
    if (r.width > 0 && r.height > 0 && (r.width < 24 || r.height < 24))
      out.push([e.tagName, e.id || e.name || e.textContent.trim().slice(0, 20), Math.round(r.width), Math.round(r.height)]);
  }
  return out; }"""


@pytest.mark.parametrize('size', [(390, 844), (360, 640), (1280, 800)])
def test_every_tap_target_is_at_least_24_px(open_page, size):
    # WCAG 2.2's minimum target size: the Live charts box (19 px) and the Scene JSON summary
    # (17 px) were under it on phones and on a laptop.
    pg = open_page(viewport={'width': size[0], 'height': size[1]}, has_touch=size[0] < 400)
    pg.js("document.getElementById('json-box').open = true")
    assert pg.js(TAP_TARGETS) == []


def test_a_key_right_after_closing_an_overlay_is_a_shortcut(open_page):
    # Hiding a focused control leaves focus on it until the browser's next rendering update:
    # a Space pressed at once went to the hidden Close button and paused nothing. Each overlay
    # closed from the keyboard, then a shortcut with no pause in between, many times over.
    pg = open_page()
    for _ in range(5):
        pg.keyboard.press('h')
        pg.keyboard.press('Escape')
        paused = pg.info()['paused']
        pg.keyboard.press('Space')
        assert pg.info()['paused'] != paused
    for _ in range(5):
        pg.js("document.getElementById('banner-text').textContent = 'x';"
              "document.getElementById('banner').hidden = false;"
              "document.getElementById('banner-close').focus()")
        paused = pg.info()['paused']
        pg.keyboard.press('Enter')
        pg.keyboard.press('Space')
        assert pg.locator('#banner').is_hidden() and pg.info()['paused'] != paused


def test_space_on_the_scene_json_summary_opens_it(open_page):
    pg = open_page()
    pg.locator('#json-box summary').focus()
    pg.keyboard.press('Space')
    assert pg.js('document.getElementById("json-box").open') and not pg.info()['paused']
    pg.locator('#scene-json').fill('')
    pg.locator('#scene-json').type('rs c1')       # typing in a text field is typing
    info = pg.info()
    assert info['frames'] > 0 and not info['paused'] and info['mode'] == 'strain'


# ---- 10: a held vertex through a resize ------------------------------------------------------

def test_the_held_vertex_stays_under_the_pointer_through_a_resize(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(60)')
    for size in [(600, 400), (1400, 900), (360, 640), (1000, 700)]:
        st = pg.state()
        k = free_vertex(st, COLS, ROWS)
        x, y = st['screen'][k]
        pg.mouse.move(x, y)
        pg.mouse.down()
        px, py = x + 20, y - 30
        pg.mouse.move(px, py)
        pg.set_viewport_size({'width': size[0], 'height': size[1]})
        pg.wait_for_function('(w) => document.getElementById("view").getBoundingClientRect().width < w + 1 &&'
                             ' clothApp.info().canvas[0] > 0', arg=size[0])
        pg.wait_for_timeout(100)
        pg.js('clothApp.advance(3)')
        box = pg.js('() => document.getElementById("view").getBoundingClientRect().toJSON()')
        if box['left'] <= px <= box['right'] and box['top'] <= py <= box['bottom']:
            assert near(pg.state()['hands'][k], (px, py), 0.01), (size, pg.state()['hands'][k], (px, py))
        pg.mouse.up()
        pg.js('clothApp.advance(60)')


# ---- 11: catch-up within a time budget -------------------------------------------------------

def test_catch_up_stops_at_the_frame_budget(open_page):
    """A frame of 120x120 seed at 100 sweeps takes tens of ms: one animation frame runs one of
    them, not four, so input waits for one frame at most, and the readout says slow motion.
    (At 40 sweeps a frame took 12-14 ms on a faster machine: one under the 12 ms budget let a
    second run, as it should; the scene must be well over the budget to test the cap.)"""
    pg = open_page()
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'cols': 120, 'rows': 120, 'spacing': 0.01, 'pins': [0, 119], 'solver': 'jakobsen',
         'iterations': 100}))
    pg.wait_for_timeout(300)
    per_tick = pg.js('''() => new Promise((done) => {
        const counts = []; let last = clothApp.info().frames, n = 0, ms = clothApp.info();
        function tick() {
          const f = clothApp.info().frames; counts.push(f - last); last = f;
          if (++n < 12) requestAnimationFrame(tick); else done(counts);
        }
        requestAnimationFrame(tick);
      })''')
    sim_ms = pg.js("parseFloat(document.getElementById('r-sim').textContent)")
    assert sim_ms > 24, sim_ms            # the budget is 12 ms: twice over it, every frame
    assert max(per_tick) <= 1, (per_tick, sim_ms)
    pg.wait_for_function('() => document.getElementById("r-size").textContent.includes("slow motion")')


# ---- 12: a grab keeps its offset -------------------------------------------------------------

@pytest.mark.parametrize('pointer,offset', [('mouse', (9, -7)), ('touch', (-14, 12))])
def test_a_press_near_a_vertex_does_not_move_it(open_page, pointer, offset):
    pg = open_page(has_touch=pointer == 'touch')
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(120)')
    st = pg.state()
    k = free_vertex(st, COLS, ROWS) - 2 * COLS
    x, y = st['screen'][k][0] + offset[0], st['screen'][k][1] + offset[1]
    if pointer == 'mouse':
        pg.mouse.move(x, y)
        pg.mouse.down()
        held = pg.state()['held'].index(True)
        assert pg.state()['positions'] == st['positions']     # nothing moved
        pg.mouse.move(x + 50, y + 20, steps=3)
        sx, sy = pg.state()['hands'][held]
        assert near((sx - 50, sy - 20), st['screen'][held], 0.01)   # the offset is kept
        pg.mouse.up()
    else:
        for _ in range(2):     # a double tap pins it where it is
            pg.touchscreen.tap(x, y)
        after = pg.state()
        changed = [i for i in range(len(after['pinned'])) if after['pinned'][i] != st['pinned'][i]]
        assert len(changed) == 1 and after['positions'] == st['positions']


# ---- 13: overlays never collide --------------------------------------------------------------

def boxes(pg):
    return pg.js('''() => ['legend', 'hud', 'legend-lo', 'legend-mid', 'legend-hi'].map((id) =>
        document.getElementById(id).getBoundingClientRect().toJSON())''')


def overlap(a, b):
    return a['left'] < b['right'] and b['left'] < a['right'] and a['top'] < b['bottom'] and b['top'] < a['bottom']


def test_overlays_never_collide(open_page):
    pg = open_page('?paused=1')
    pg.js("clothApp.setColorMode('stress')")
    for size in [(320, 480), (360, 640), (500, 700), (720, 900), (721, 500), (1000, 700), (1920, 1080)]:
        pg.set_viewport_size({'width': size[0], 'height': size[1]})
        pg.wait_for_timeout(400)
        legend, hud, lo, mid, hi = boxes(pg)
        assert not overlap(legend, hud), (size, legend, hud)
        assert lo['right'] <= mid['left'] and mid['right'] <= hi['left'], (size, lo, mid, hi)
        stage = pg.js('() => document.getElementById("stage").getBoundingClientRect().toJSON()')
        for b in (legend, hud):
            assert stage['left'] <= b['left'] and b['right'] <= stage['right'] + 0.5, size
        pg.keyboard.press('h')
        card = pg.js('() => document.querySelector("#help .card").getBoundingClientRect().toJSON()')
        assert 0 <= card['left'] and card['right'] <= size[0], size
        sw = pg.js('() => { const c = document.querySelector("#help .card"); return [c.scrollWidth, c.clientWidth]; }')
        assert sw[0] <= sw[1], (size, sw)        # nothing cut off sideways
        pg.keyboard.press('Escape')


def test_an_overlay_over_the_held_vertex_fades(open_page):
    pg = open_page(viewport={'width': 700, 'height': 500})
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(60)')
    st = pg.state()
    k = free_vertex(st, COLS, ROWS)
    hud = boxes(pg)[1]
    pg.mouse.move(*st['screen'][k])
    pg.mouse.down()
    pg.mouse.move((hud['left'] + hud['right']) / 2, (hud['top'] + hud['bottom']) / 2, steps=5)
    pg.js('clothApp.advance(1)')
    assert pg.js('document.getElementById("hud").classList.contains("under")')
    pg.mouse.up()
    pg.js('clothApp.advance(1)')
    assert not pg.js('document.getElementById("hud").classList.contains("under")')


# ---- 14, 15: the scale, the readouts and the notes say what they show -------------------------

def test_auto_scale_has_a_floor_that_keeps_noise_dark(open_page):
    pg = open_page()
    pg.js('clothApp.setPaused(true)')
    # The stiffest fabric a scene may have, hung from a rod: its strain at rest (density g
    # height / stretch, 2e-6) is far below the floor, and the colours stay dark.
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 30, 'rows': 20, 'spacing': 0.05, 'pins': list(range(30)), 'damping': 1,
         'stretch': spec('stretch').hi}))
    pg.js('clothApp.advance(300)')
    info = pg.info()
    high = pg.js('clothApp.cloth().high_value')
    assert 0 < high < info['autoFloor'] and info['scale'] == info['autoFloor']
    assert pg.locator('#auto-floor').text_content() == str(info['autoFloor'])     # the help says it
    pg.wait_for_timeout(400)
    assert 'floor' in pg.locator('#legend-title').inner_text()
    # above the floor, Auto is the value 99% of the edges are at or below (cloth/measure.py
    # HIGH_SHARE): the seed's cloth, stretched by its two sweeps
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 10, 'rows': 10, 'spacing': 0.1, 'pins': [0, 9], 'solver': 'jakobsen',
         'iterations': 2}))
    pg.js('clothApp.advance(30)')
    c = pg.js('({high: clothApp.cloth().high_value, max: clothApp.cloth().max_value})')
    # (the upper edge of the histogram's bin it falls in: at most a bin, 10^(1/32), above the
    # largest value)
    assert c['high'] > pg.info()['autoFloor'] and pg.info()['scale'] == c['high']
    assert c['high'] <= c['max'] * 10 ** (1 / BINS_PER_DECADE)
    pg.wait_for_timeout(400)
    assert '99%' in pg.locator('#legend-title').inner_text()


def test_the_strain_readout_is_strain_and_the_stress_legend_is_q(open_page):
    pg = open_page()
    # Squashed under the seed's method, whose edge value is its |diff| = |len - rest| / len:
    # that passes 1, while the tension strain max(0, len / rest - 1) the readout shows cannot.
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'model': MODEL, 'cols': 3, 'rows': 1, 'spacing': 0.5, 'pins': [0, 1, 2], 'gravity': [0, 0],
         'solver': 'jakobsen', 'actions': [{'frame': 0, 'op': 'grab', 'vertex': 1, 'to': [0.05, 0]}]}))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(2)')
    pg.wait_for_timeout(400)
    c = pg.js('({s: clothApp.cloth().max_strain, d: clothApp.cloth().max_value})')
    assert c['d'] > 1 and 0 < c['s'] < 1
    shown = float(pg.locator('#r-max').inner_text())
    assert shown == pytest.approx(c['s'], rel=1e-3)
    assert pg.locator('#legend-title').inner_text().startswith('edge |diff|')
    pg.js("clothApp.setColorMode('stress')")
    pg.js("clothApp.setScaleMode('fixed', 0.5)")
    pg.wait_for_timeout(400)
    assert pg.locator('#legend-title').inner_text().startswith('node stress Q')
    assert pg.locator('#legend-hi').inner_text() == '0.5000'


def test_sim_readout_is_the_new_scenes_own_and_no_noise_at_rest(open_page):
    pg = open_page()
    pg.wait_for_timeout(600)
    pg.js('(t) => clothApp.loadScene(t)', json.dumps({'cols': 4, 'rows': 3, 'spacing': 0.1,
                                                       'pins': [0, 1, 2, 3]}))
    pg.wait_for_function('() => clothApp.cloth().asleep', timeout=15000)
    pg.wait_for_timeout(600)
    assert pg.locator('#r-sim').inner_text() == '–'
    assert 'at rest' in pg.locator('#r-size').inner_text()


def test_the_legend_says_how_far_the_solver_is_from_balance(open_page):
    # Model 1's "Unstable settings" note is gone with its max_speed net; what the page says of
    # the solver's work now is the legend's note: the fabric, and how far the last step left
    # the forces from balance (RMS unbalanced force over a vertex's weight, cloth.imbalance).
    pg = open_page()
    load_paused(pg, json.dumps({'model': MODEL, 'cols': 12, 'rows': 10, 'spacing': 0.1,
                                'pins': list(range(12)), 'damping': 1}))
    pg.js('clothApp.advance(2)')
    pg.wait_for_timeout(400)
    off = pg.js('clothApp.cloth().imbalance')
    assert off > REST_IMBALANCE
    said = pg.locator('#legend-note').inner_text()
    assert said.startswith('jersey · settling: ') and said.endswith('% off balance'), said
    assert float(said.split(': ')[1].split('%')[0]) == pytest.approx(100 * off, rel=0.01), (said, off)
    pg.js('clothApp.advance(600)')
    pg.wait_for_timeout(400)
    off = pg.js('clothApp.cloth().imbalance')
    said = pg.locator('#legend-note').inner_text()
    assert off <= REST_IMBALANCE and said.startswith('jersey · balanced'), (said, off)
    # Off by more than a weight (a cloth yanked: the flag in its wind once read "7858.98%"),
    # the legend says in motion, by how many weights.
    ops = 'clothCore.ops(clothApp.cloth())'
    pg.js('%s.grab(60, 1.0, -1.0); %s.move(60, 1.0, -2.0)' % (ops, ops))
    pg.js('clothApp.advance(1)')
    pg.wait_for_timeout(400)
    off = pg.js('clothApp.cloth().imbalance')
    said = pg.locator('#legend-note').inner_text()
    assert off >= 2 and said == 'jersey · in motion: %d× its weight off balance' % round(off), (said, off)
    pg.js('%s.release(60)' % ops)
    # XPBD does not measure its balance (its imbalance stays 0): the legend does not call it
    # balanced (it did, in motion and blown up alike)
    pg.select_option('#solver', 'xpbd')
    pg.js('clothApp.advance(2)')
    pg.wait_for_timeout(400)
    assert pg.locator('#legend-note').inner_text() == 'jersey · balance not measured by this solver'
    # the seed's method has no fabric and no balance to speak of: the legend says so
    pg.select_option('#solver', 'jakobsen')
    pg.wait_for_timeout(400)
    assert pg.locator('#legend-note').inner_text() == "the seed's rigid edges"
    # and the help explains each solver the menu offers
    help_text = pg.locator('#help').inner_text()
    assert 'Jakobsen' in help_text and 'vertex block descent' in help_text and 'XPBD' in help_text


def test_sideways_wheels_never_leave_the_page(open_page):
    """Two sideways wheels (a trackpad swipe) were Chromium's "back" gesture: the page was
    gone, found by the pointer fuzzing of test_soak.py."""
    pg = open_page('?paused=1')
    for x, y, dx, dy in [(67, 288, -269, -25), (773, 690, 137, 104), (900, 300, -300, 5), (500, 200, 300, 0)]:
        pg.mouse.move(x, y)
        pg.mouse.wheel(dx, dy)
        pg.wait_for_timeout(150)
    assert pg.url.startswith(DIST.as_uri()) and pg.js('typeof clothApp') == 'object'


@pytest.mark.parametrize('where', ['above the stage', 'beyond its right edge'])
def test_a_pin_dragged_off_the_stage_can_still_be_reached_and_unpinned(open_page, where):
    # A pin dragged up off the stage, or past its edge toward the side panel, stayed there,
    # out of reach: it could not be clicked to unpin. A hand goes no farther than the panel's
    # rectangle (a few px inside it), so what a person leaves can always be taken again.
    pg = open_page('?paused=1')
    load_paused(pg, json.dumps({'model': MODEL, 'cols': 8, 'rows': 6, 'spacing': 0.1, 'pins': [0, 7],
                                'gravity': [0, 0]}))
    x, y = pg.state()['screen'][7]
    rect = pg.js("(() => { const r = document.getElementById('view').getBoundingClientRect(); "
                 "return [r.left, r.top, r.right, r.bottom]; })()")
    to = (x, rect[1] - 300) if where == 'above the stage' else (rect[2] + 300, y)
    pg.mouse.move(x, y)
    pg.mouse.down()
    pg.mouse.move(to[0], to[1], steps=8)
    pg.js('clothApp.advance(30)')
    pg.mouse.up()
    pg.js('clothApp.advance(5)')
    px, py = pg.state()['screen'][7]
    assert rect[0] <= px <= rect[2] and rect[1] <= py <= rect[3], (px, py, rect)
    assert pg.state()['pinned'][7]
    pg.mouse.click(px, py, button='right')
    assert not pg.state()['pinned'][7]
