"""Presets model air and the two-corner preset hangs slack; a scene's scripted actions play in
the page at their frames, as the CLI plays them."""
import json

from cloth.api import run

README_EXAMPLE = {"cols": 20, "rows": 15, "spacing": 0.05, "pins": [0, 5, 10, 14, 19],
                  "damping": 0.5,
                  "actions": [{"frame": 30, "op": "grab", "vertex": 299},
                              {"frame": 60, "op": "move", "vertex": 299, "to": [1.4, -0.3]},
                              {"frame": 90, "op": "release", "vertex": 299}]}


def test_scripted_actions_play_in_the_page_as_in_the_cli(open_page):
    pg = open_page('?paused=1')
    text = json.dumps(README_EXAMPLE)
    pg.js('(t) => clothApp.loadScene(t)', text)
    for frames in (75, 45, 30):       # through the move, the release and after it
        pg.js('(n) => clothApp.advance(n)', frames)
        done = pg.info()['frames']
        expect = json.loads(run(text, done))['positions']
        assert pg.state()['positions'] == expect, done
    assert pg.info()['frames'] == 150


def test_presets_damp_like_air_and_two_corners_hangs_slack(open_page):
    pg = open_page('?preset=corners&paused=1')
    scene = json.loads(pg.info()['scene'])
    assert scene['damping'] == 1
    cols = scene['cols']
    width = (cols - 1) * scene['spacing']
    # the corner is carried in over a second, gently: nothing flung, nothing over the pins
    fastest, highest = 0.0, -1.0
    last = pg.state()['positions']
    for _ in range(120):
        pg.js('clothApp.advance(1)')
        pos = pg.state()['positions']
        fastest = max(fastest, max(((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5 * 60
                                   for a, b in zip(pos, last)))
        highest = max(highest, max(p[1] for p in pos))
        last = pos
    assert abs(pos[cols - 1][0] - 0.8 * width) < 1e-12 and pos[cols - 1][1] == 0
    assert pg.state()['pinned'][cols - 1]
    assert fastest < 3.0 and highest < 0.01 * width, (fastest, highest)
    pg.js('clothApp.advance(480)')
    top = pg.state()['positions'][cols // 2]
    assert top[1] < -0.1 * width          # the top row sags in the middle


def test_damping_applies_to_the_cloth(open_page):
    pg = open_page('?paused=1')
    pg.fill('#damping', '2.5')
    pg.press('#damping', 'Enter')
    assert pg.js('clothApp.cloth().scene.damping') == 2.5
    assert pg.info()['params']['damping'] == 2.5
