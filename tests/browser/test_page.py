"""The built page: offline, up to date, and the core's seam (clothCore) in a real browser."""
import json
import re
import subprocess
import sys

from browser_helpers import DIST, ROOT

SMALL = {'cols': 6, 'rows': 5, 'spacing': 0.1, 'pins': [0, 5], 'solver': 'jakobsen'}


def test_dist_is_up_to_date():
    # build.py --check transpiles into a temporary folder and compares bytes.
    proc = subprocess.run([sys.executable, 'build.py', '--check'], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_dist_is_one_classic_page():
    html = DIST.read_text(encoding='utf-8')
    assert 'type="module"' not in html
    assert not re.search(r'^\s*(import|export)\b', html, re.M), 'an ES import/export survived linking'
    assert not re.search(r'<(script|link|img)[^>]+(src|href)=', html), 'the page loads another file'
    assert "Transcrypt'ed from Python" not in html and 'sourceMappingURL' not in html


def test_loads_offline_and_animates(open_page):
    pg = open_page()
    pg.wait_for_function('clothApp.info().frames > 5')
    info = pg.info()
    assert info['webgl'] == 2 and not info['lost']
    assert info['drawCalls'] == 2  # every edge in one call, the pins in another
    assert info['error'] == '' and pg.locator('#fatal').is_hidden()
    st = pg.state()
    assert len(st['positions']) == 40 * 30 == len(st['screen']) == len(st['pinned'])
    assert all(v == v and abs(v) < 1e6 for p in st['positions'] for v in p)
    assert pg.requests == []


def test_core_run_matches_cpython(open_page):
    sys.path.insert(0, str(ROOT))
    try:
        from cloth import api
    finally:
        sys.path.pop(0)
    text = json.dumps(SMALL)
    expected = api.run(text, 40)
    pg = open_page('?paused=1')
    got = pg.js('([t, n]) => clothCore.run(t, n)', [text, 40])
    # Bit for bit (same operation order in both runtimes); compared as parsed JSON
    # because integral floats print as 0.0 in CPython and 0 in JS.
    assert json.loads(got) == json.loads(expected)
    assert json.loads(got)['frames'] == 40


def test_core_errors_are_js_errors_with_the_message(open_page):
    pg = open_page('?paused=1')
    res = pg.js('''() => {
        const out = [];
        for (const t of ['{', '[]', '{"cols": 3, "rows": 2, "spacing": 0.1, "colour": 1}']) {
            try { clothCore.run(t, 1); out.push(null); }
            catch (e) { out.push([e instanceof Error, e.message]); }
        }
        try { clothCore.load('{"cols": 0, "rows": 2, "spacing": 0.1}'); out.push(null); }
        catch (e) { out.push([e instanceof Error, e.message]); }
        return out;
    }''')
    assert all(r is not None and r[0] for r in res), res
    assert res[0][1].startswith('scene:')
    assert res[2][1].startswith('colour:')
    assert res[3][1].startswith('cols:')


# Issue #7 point 3: every malformed scene gets the same one-line message in the page
# as in CPython (the CLI), as a real Error, and loadScene shows it.
MALFORMED = [
    'not json', '[1, 2]', '"text"', '{}',
    '{"cols": "3", "rows": 2, "spacing": 0.1}',
    '{"cols": 3, "rows": 2, "spacing": 0}',
    '{"cols": 3, "rows": -2, "spacing": 0.1}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "dt": 0}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "dt": 1e999}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "iterations": -1}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "solver": "magic"}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "pins": [6]}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "gravity": [0, "down"]}',
    '{"cols": 100000, "rows": 100000, "spacing": 0.1}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "breeze": [1, 0]}',
    '{"cols": 3, "rows": 2, "spacing": 0.1, "actions": [{"frame": 0, "op": "grab", "vertex": 9}]}',
]


def test_bad_scenes_give_the_cli_message_in_the_page(open_page):
    sys.path.insert(0, str(ROOT))
    try:
        from cloth import api
        from cloth.scene import SceneError
    finally:
        sys.path.pop(0)
    expected = []
    for text in MALFORMED:
        try:
            api.run(text, 1)
            expected.append(None)
        except SceneError as e:
            expected.append(str(e))
    assert None not in expected
    pg = open_page()
    got = pg.js('''(texts) => texts.map((t) => {
        let run = null, shown = null;
        try { clothCore.run(t, 1); } catch (e) { run = e instanceof Error ? e.message : 'not an Error'; }
        try { clothApp.loadScene(t); } catch (e) {
            shown = document.getElementById('banner-text').textContent; }
        return [run, shown];
    })''', MALFORMED)
    for text, want, (run, shown) in zip(MALFORMED, expected, got):
        assert run == want, text
        assert '\n' not in want and shown is not None and want in shown, text
    info = pg.info()
    assert info['preset'] == 'curtain'  # the first scene is still the one running
