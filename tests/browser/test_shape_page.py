"""Shape in the page: the disturbance scenes of tests/shape.py, run by the shipped core in
Chromium (clothCore.run), come back to their undisturbed hang, with the same doubles as CPython."""
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..'))
import shape  # noqa: E402
from cloth.api import run  # noqa: E402
from test_shape import hung_at, gesture, disturbed_scene  # noqa: E402


@pytest.mark.parametrize('name', ['flick-up-1.4m', 'corner-over-the-cloth'])
def test_the_page_recovers_from_a_disturbance_as_cpython_does(open_page, name):
    vertex, path = gesture(name, hung_at(shape.HANG))
    scene = json.dumps(disturbed_scene(vertex, path))
    frames = len(path) + shape.HANG + 2 + shape.SETTLE
    page = open_page('?paused=1')
    got = page.js('([t, f]) => clothCore.run(t, f)', [scene, frames])
    undisturbed = page.js('([t, f]) => clothCore.run(t, f)',
                          [json.dumps(shape.hang_scene()), frames])
    assert got == run(scene, frames)
    pos = [tuple(p) for p in json.loads(got)['positions']]
    ref = [tuple(p) for p in json.loads(undisturbed)['positions']]
    rms, worst, above = shape.recovery(pos, ref, shape.hang_scene()['pins'])
    assert rms < 0.03 and above == 0, (rms, worst, above)
