"""What the page says stays true (found by a fresh try of the page, 2026-12-04): a refused
setting's banner ends with the next setting that applies; a person who takes over a replay is
told so, and the replay's note goes; the note about a scene's older model does not hide every
other note."""
import base64
import json

from browser_helpers import load_paused


def test_a_refused_settings_banner_ends_with_the_next_setting_that_applies(open_page):
    pg = open_page()
    load_paused(pg, json.dumps({'cols': 200, 'rows': 200, 'spacing': 0.01, 'pins': [0, 199]}))
    pg.js("clothApp.setParam('iterations', '200')")
    assert pg.info()['error'].startswith('Setting not applied')
    pg.js("clothApp.setParam('damping', '2')")
    assert pg.info()['error'] == ''
    assert pg.info()['params']['damping'] == 2


def test_taking_over_a_replay_says_so(open_page):
    pg = open_page()
    load_paused(pg, json.dumps({'cols': 10, 'rows': 8, 'spacing': 0.1, 'pins': [0, 9], 'frames': 200}))
    pg.js('clothApp.setPaused(false)')
    assert pg.info()['replay']['playing']
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(20)')
    x, y = pg.state()['screen'][45]
    pg.page.mouse.click(x, y, button='right')
    info = pg.info()
    assert not info['replay']['playing']
    assert 'took over the replay at frame' in info['note'], info['note']


def test_the_older_models_note_does_not_hide_a_refused_field(open_page):
    # Model 1's max_speed net, whose note was said every frame it capped, is gone with the
    # membrane; a scene made before it is said to be so once, at load (with what became of
    # its max_speed), and a refused field's note still shows after it.
    pg = open_page()
    load_paused(pg, json.dumps({'cols': 10, 'rows': 8, 'spacing': 0.1, 'pins': [0], 'max_speed': 0.01}))
    pg.js('clothApp.advance(10)')
    said = pg.info()['note']
    assert 'made before the membrane model' in said and 'max_speed left out' in said, said
    pg.js("clothApp.setParam('iterations', 'abc')")
    pg.js('clothApp.advance(10)')
    assert 'Iterations: not a number' in pg.info()['note'], pg.info()['note']


def test_the_replay_note_reads_true_for_any_frames_a_scene_holds(open_page):
    """The note of a replay is built from the scene's optional `frames` (the session's replay
    end: -1 when the scene has none): it never shows -1, NaN or undefined, and counts right."""
    pg = open_page('?paused=1')
    for frames in (-1, 0, 1, 2, 123456, float('nan'), None):
        for source in ('the link', ''):
            note = pg.js('([f, s]) => clothReadouts.replayNote(f === null ? undefined : f, s)', [frames, source])
            assert not any(w in note for w in ('-1', 'NaN', 'undefined', 'null')), (frames, note)
            if frames in (1, 2, 123456):
                assert '(%d frame%s)' % (frames, '' if frames == 1 else 's') in note, note
            else:
                assert 'replaying' not in note.lower(), note


def test_a_link_whose_scene_holds_no_frames_says_it_runs_live(open_page):
    text = json.dumps({'model': 2, 'cols': 6, 'rows': 5, 'spacing': 0.1, 'pins': [0, 5]})
    link = base64.urlsafe_b64encode(text.encode()).decode().rstrip('=')
    pg = open_page('?paused=1#scene-json=' + link)
    pg.wait_for_function('() => !clothApp.info().linkPending && clothApp.info().note !== ""')
    note = pg.info()['note']
    assert 'holds no recorded frames' in note and '-1' not in note, note
    assert len(pg.state()['positions']) == 30


def test_every_way_a_scene_comes_in_says_it_was_made_before_the_membrane(open_page, tmp_path):
    """An older model's note is the scene's, whatever brought it: the Scene JSON box, a file
    opened, a file dropped, a link (the file's, the drop's and the link's own words replaced it).
    Each says its own words too."""
    old = json.dumps({'cols': 6, 'rows': 5, 'spacing': 0.1, 'pins': [0, 5], 'frames': 3})
    path = tmp_path / 'old.json'
    path.write_text(old)
    pg = open_page('?paused=1')
    said = {}
    pg.js("document.getElementById('json-box').open = true")
    pg.js('''(t) => { const box = document.getElementById('scene-json'); box.value = t;
      box.dispatchEvent(new Event('input', {bubbles: true})); }''', old)
    pg.locator('#btn-load-json').click()
    said['box'] = pg.info()['note']
    pg.locator('#file-input').set_input_files(str(path))
    pg.page.wait_for_function("() => clothApp.info().note.indexOf('Opened old.json') >= 0")
    said['file'] = pg.info()['note']
    pg.js('''(t) => { const dt = new DataTransfer(); dt.items.add(new File([t], 'dropped.json', {type: 'application/json'}));
      document.getElementById('view').dispatchEvent(new DragEvent('drop', {dataTransfer: dt, bubbles: true, cancelable: true})); }''', old)
    pg.page.wait_for_function("() => clothApp.info().note.indexOf('Opened dropped.json') >= 0")
    said['drop'] = pg.info()['note']
    # A link: the recording of the scene the box loaded (it keeps the scene's older model).
    pg.locator('#btn-load-json').click()
    url = pg.js('clothApp.link()')
    other = open_page()
    other.goto(url)
    other.page.wait_for_function("() => clothApp.info().note.indexOf('from the link') >= 0")
    said['link'] = other.info()['note']
    for how, note in said.items():
        assert 'made before the membrane model' in note, (how, note)
    assert 'Opened old.json' in said['file'] and 'Opened dropped.json' in said['drop']
