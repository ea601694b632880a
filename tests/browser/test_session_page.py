"""The session (cloth/session.py) in the page and in CPython, call for call: the same gestures
and settings on the same scene give the same recording, character for character, and the same
positions, bit for bit, in one panel and in compare mode (issue #23)."""
import json

import pytest

from browser_helpers import near  # noqa: F401  (the helpers' import sets the path)

from cloth import session as ses
from cloth.keys import MODEL

SCENE = {'model': MODEL, 'cols': 9, 'rows': 7, 'spacing': 0.1, 'pins': [0, 8], 'damping': 1, 'density': 0.2,
         'stretch': 500, 'shear': 50}
# Every solver: the seed's, the default tearing, XPBD in a stiffer fabric.
PAIR = [{'solver': 'jakobsen', 'substeps': 1, 'iterations': 20}, {'solver': 'vbd', 'strength': 50.0},
        {'solver': 'xpbd', 'stretch': 5000, 'shear': 150}]


def calls():
    out = [['advance', 7], ['grab', 58, 0.45, -0.55]]
    for f in range(15):
        out += [['move', 58, 0.45 + 0.031 * f, -0.55 - 0.043 * f], ['move', 58, 0.46 + 0.031 * f, -0.6],
                ['advance', 1]]
    out += [['change', json.dumps({'gravity': [1.5, -7], 'substeps': 4})], ['advance', 4],
            ['togglePin', 4], ['cut', 0.33, 0.05, 0.37, -0.3], ['advance', 2], ['release', 58],
            ['togglePin', 4], ['advance', 25]]
    return out


PY = {'grab': ses.gesture_grab, 'move': ses.gesture_move, 'release': ses.gesture_release,
      'togglePin': ses.gesture_toggle_pin, 'cut': ses.gesture_cut, 'change': ses.change,
      'advance': ses.advance}

IN_PAGE = '''([text, calls]) => {
  const S = clothCore.session, s = S.open(text);
  for (const c of calls) {
    if (c[0] === 'advance') {
      const start = s.script_next[0];
      for (let i = 0; i < s.panels.length; i++) {
        for (let f = s.frame + 1; f <= s.frame + c[1]; f++) S.stepPanel(s, i, f);
      }
      S.framesRan(s, c[1], start);
    } else {
      S[c[0]].apply(null, [s].concat(c.slice(1)));
    }
  }
  return { text: S.recordingText(s), frame: s.frame,
           positions: s.panels.map((p) => Array.from(p.pos)) };
}'''


@pytest.mark.parametrize('compare', [False, True], ids=['one panel', 'compare'])
def test_the_session_is_the_same_in_the_page_and_in_cpython(open_page, compare):
    scene = dict(SCENE, compare=PAIR) if compare else SCENE
    text = json.dumps(scene)
    s = ses.open_session(text)
    for c in calls():
        PY[c[0]](s, *c[1:])
    page = open_page().js(IN_PAGE, [text, calls()])
    assert page['frame'] == s.frame == 7 + 15 + 4 + 2 + 25
    assert page['text'] == ses.recording_text(s)
    assert page['positions'] == [[p.pos[i] for i in range(2 * p.n_verts)] for p in s.panels]
    acts = json.loads(page['text'])['actions']
    assert [a['op'] for a in acts].count('move') == 15 and acts[-1]['op'] == 'unpin'
