"""Obstacles in the page (issue #24.1): drawn, dragged with a real mouse through the cloth,
recorded and replayed. Runs in Chromium here and in Firefox and WebKit (tests/engines/)."""
import json
import sys

from browser_helpers import ROOT, wait_settled

sys.path.insert(0, str(ROOT))
from cloth import api  # noqa: E402
sys.path.pop(0)


def test_an_obstacle_is_drawn_dragged_through_the_cloth_and_replays(open_page):
    """Obstacles (issue #24): a box drawn over the stage, dragged by a real mouse through the
    hanging cloth in a few large steps; no free vertex ends inside it, the drags are recorded
    as `obstacle` actions, and the recording replays in CPython to the page's positions."""
    pg = open_page('?paused=1')
    pg.js('(t) => clothApp.loadScene(t)', json.dumps(
        {'cols': 14, 'rows': 10, 'spacing': 0.1, 'pins': list(range(14)), 'damping': 1,
         'obstacles': [{'box': [-0.5, -0.8, -0.2, -0.4], 'friction': 0.5}, {'circle': [0.6, -1.5, 0.15]}]}))
    pg.js('clothApp.setPaused(true)')
    pg.js('clothApp.advance(30)')
    wait_settled(pg)
    # Drawn and sampled in one task: a layout change between would move the view.
    x, y, lit = pg.js('''() => { clothApp.advance(0); const p = clothApp.clientOf(-0.35, -0.6);
        const c = document.getElementById('obstacles'), r = c.getBoundingClientRect();
        const px = c.getContext('2d').getImageData(Math.round((p[0] - r.left) * c.width / r.width),
                                                   Math.round((p[1] - r.top) * c.height / r.height), 1, 1).data;
        return [Math.round(p[0]), Math.round(p[1]), px[3]]; }''')
    assert lit > 0                                           # the box is drawn where it is
    x1, _ = pg.js('clothApp.clientOf(1.0, -0.6)')
    pg.mouse.move(x, y)
    pg.mouse.down()
    for i in range(1, 4):
        pg.mouse.move(round(x + (x1 - x) * i / 3), y, steps=2)
        pg.js('clothApp.advance(2)')
    pg.mouse.up()
    pg.js('clothApp.advance(20)')
    box = pg.js('clothApp.obstacles()')[0]
    assert box['at'][0] > 0.8                                # it went where the mouse took it
    st = pg.state()
    inside = [p for p, pinned in zip(st['positions'], st['pinned']) if not pinned and
              abs(p[0] - box['at'][0]) < box['half'][0] - 1e-9 and abs(p[1] - box['at'][1]) < box['half'][1] - 1e-9]
    assert inside == []
    text = pg.js('clothApp.recording()')
    assert [a['op'] for a in json.loads(text)['actions']].count('obstacle') >= 3
    assert json.loads(api.run(text))['positions'] == st['positions']
