"""Issue #22, items 4 and 9: text pasted into the Scene JSON box decodes as a file of the same
bytes does (one byte-order mark is not content), and every focusable control shows the page's
focus ring, the Scene JSON summary included."""
import json


SCENE = {'cols': 4, 'rows': 3, 'spacing': 0.1, 'pins': [0, 3]}


def load_box(pg, text):
    if not pg.js("document.getElementById('json-box').open"):
        pg.locator('#json-box summary').click()
    pg.locator('#scene-json').fill(text)
    pg.locator('#btn-load-json').click()


def test_a_byte_order_mark_pasted_in_the_box_is_read_as_from_a_file(open_page):
    pg = open_page()
    load_box(pg, '\ufeff' + json.dumps(SCENE))
    assert pg.info()['params']['cols'] == 4 and not pg.js("document.getElementById('banner').hidden === false")
    # Two marks are one too many for a file (Python's utf-8-sig strips one) and for the box.
    load_box(pg, '\ufeff\ufeff' + json.dumps(dict(SCENE, cols=5)))
    assert pg.info()['params']['cols'] == 4
    assert 'not valid JSON' in pg.js("document.getElementById('banner-text').textContent")


def test_every_focusable_control_shows_the_pages_focus_ring(open_page):
    pg = open_page()
    pg.js("document.getElementById('json-box').open = true")
    pg.keyboard.press('Tab')                 # keyboard modality: :focus-visible applies
    rings = {}
    for sel in ['#btn-pause', '#preset', '#material', '#cols', '#json-box summary', '#scene-json']:
        pg.locator(sel).focus()
        rings[sel] = pg.js('''(s) => { const e = document.querySelector(s);
            const c = getComputedStyle(e); return [e.matches(':focus-visible'), c.outlineStyle,
            c.outlineColor, c.outlineWidth]; }''', sel)
    want = rings['#btn-pause']
    assert want[0] and want[1] == 'solid' and want[3] == '2px', want
    for sel, ring in rings.items():
        assert ring == want, (sel, ring, want)
