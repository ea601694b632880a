"""The shape of a settled cloth against the exact statics, and recovery after disturbances
(tests/shape.py has the gestures). The same disturbances run in the page in
tests/browser/test_shape_page.py."""
import json

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st, HealthCheck

import shape
from cloth.api import run, load, simulate
from cloth.fabrics import FABRICS
from cloth.presets import preset_scene
from bench.fabrics import across
from cloth.reference import statics, tension_strain, away_from_fixed, field_error, at_rest_of
from cloth.step import frame


def positions(scene, frames):
    return [tuple(p) for p in json.loads(run(json.dumps(scene), frames))['positions']]


@pytest.mark.parametrize('fabric', [f[0] for f in FABRICS])
@pytest.mark.parametrize('name', ['corners', 'curtain', 'towel'])
def test_every_fabric_comes_to_rest_on_its_exact_statics(name, fabric):
    """Issue #39's claim at a size CPython runs in seconds (the benchmark measures 30 to 200 in
    the page): the preset in each fabric of the menu comes to rest (asleep: every vertex still
    and its forces balanced) within 20 s, and there its strain field away from the clamps is
    within 1% of the exact statics' (Newton on the same energy, from where it rests) and its
    shape within 0.5% of the width."""
    n = 10
    f = next(f for f in FABRICS if f[0] == fabric)
    obj = preset_scene(name, n, n)
    obj['stretch'], obj['shear'], obj['density'] = f[2], f[3], f[4]
    cloth = load(json.dumps(obj))
    frames = 0
    while not cloth.asleep and frames < 1200:
        frame(cloth)
        frames += 1
    assert cloth.asleep, frames
    x = np.array(cloth.pos, dtype=float).reshape(-1, 2)
    exact, info = statics(cloth)
    assert info['residual'] < 1e-6
    mask = away_from_fixed(cloth, exact, 0.1)
    assert mask.sum() > 0.8 * len(mask)
    error = field_error(tension_strain(cloth, x), tension_strain(cloth, exact), mask)
    width = (cloth.cols - 1) * cloth.spacing
    shape_off = float(np.sqrt(((x - exact) ** 2).sum(1).mean())) / width
    assert error < 0.01 and shape_off < 0.005, (error, shape_off)



def test_a_woven_towels_exact_field_converges_as_its_cells_halve():
    """Issue #39's "the same fabric's field on every grid", on the exact statics (no solver in
    it): the towel on its peg in cotton (woven: its shear a thirtieth of its stretch, so the
    strain under the peg's ends is a narrow wedge) on 9, 18 and 36 cells, halved twice so the
    peg holds the same stretch of the edge on each. Each grid's field, restricted to the
    coarsest grid's edges (every edge the mean over the patch it stands for: bench/fabrics.py),
    differs from the finest's by less each halving, by half or more, and under the issue's 25%
    (7.6% and 1.8%, measured). As point samples (each vertex's mean strain, at the coarsest
    grid's vertices) the same fields differ 47% and 25%: a value at a point in the wedge is not
    what a coarse spring carries."""
    f = next(f for f in FABRICS if f[0] == 'cotton')
    runs = {}
    for n in (10, 19, 37):
        obj = preset_scene('towel', n, n)
        obj['stretch'], obj['shear'], obj['density'] = f[2], f[3], f[4]
        cloth = at_rest_of(json.dumps(obj))
        x, info = statics(cloth, tol=1e-7)
        assert info['residual'] < 1e-6
        runs[('towel', 'cotton', n)] = (cloth, x)
    d = across(runs, 'towel', 'cotton', [10, 19, 37])
    patches = [d[10][0], d[19][0]]
    assert patches[0] < 0.25 and patches[1] < 0.5 * patches[0], d

def test_a_cloth_stopped_short_of_its_statics_is_told_apart():
    """The check above can fail: the same curtain stopped after a few frames, still falling
    into its hang, is far from the exact field."""
    cloth = load(json.dumps(preset_scene('curtain', 10, 10)))
    for _ in range(3):
        frame(cloth)
    x = np.array(cloth.pos, dtype=float).reshape(-1, 2)
    exact, _ = statics(cloth)
    mask = away_from_fixed(cloth, exact, 0.1)
    assert field_error(tension_strain(cloth, x), tension_strain(cloth, exact), mask) > 0.1


# The hang with no gesture, stepped once a process and kept frame by frame: every recovery test
# takes its gesture's start from it and compares with it at its own last frame.
HANG_RUN = {'cloth': None, 'trace': []}


def undisturbed(frames):
    """The positions of the hang with no gesture after `frames` frames."""
    if HANG_RUN['cloth'] is None:
        HANG_RUN['cloth'] = load(json.dumps(shape.hang_scene()))
    trace = HANG_RUN['trace']
    if frames > len(trace):
        simulate(HANG_RUN['cloth'], frames - len(trace), trace)
    return [tuple(p) for p in trace[frames - 1]]


def hung_at(frame):
    """The hang's positions after `frame` frames, as a flat [x0, y0, x1, y1, ...]."""
    return [c for p in undisturbed(frame) for c in p]


def disturbed_scene(vertex, path, fixture=True, **keys):
    scene = shape.hang_scene(**keys)
    scene['actions'] = shape.gesture_actions(vertex, path, fixture=fixture)
    return scene


def gesture(name, pos):
    vertex, dx, dy, frames = shape.DISTURBANCES[name]
    x0, y0 = pos[2 * vertex], pos[2 * vertex + 1]
    return vertex, shape.straight_path(x0, y0, dx, dy, frames)


def check_recovery(scene):
    frames = scene['actions'][-1]['frame'] + 1 + shape.SETTLE
    got = positions(scene, frames)
    rms, worst, above = shape.recovery(got, undisturbed(frames), scene['pins'])
    assert rms < 0.03 and above == 0, (rms, worst, above)
    return rms


@pytest.mark.parametrize('name', sorted(shape.DISTURBANCES))
def test_the_cloth_comes_back_after_a_disturbance(name):
    vertex, path = gesture(name, hung_at(shape.HANG))
    check_recovery(disturbed_scene(vertex, path))


def test_the_cloth_comes_back_after_a_zigzag_drag():
    pos = hung_at(shape.HANG)
    v = shape.BOTTOM_MIDDLE
    path = shape.zigzag_path(pos[2 * v], pos[2 * v + 1], 0.6, 20, 4)
    check_recovery(disturbed_scene(v, path))


@settings(max_examples=3, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(vertex=st.integers(shape.COLS, shape.COLS * shape.ROWS - 1),
       dx=st.floats(-2.0, 2.0), dy=st.floats(-2.0, 2.0), frames=st.integers(1, 30),
       fixture=st.booleans())
def test_the_cloth_comes_back_after_random_throws(vertex, dx, dy, frames, fixture):
    pos = hung_at(shape.HANG)
    x0, y0 = pos[2 * vertex], pos[2 * vertex + 1]
    check_recovery(disturbed_scene(vertex, shape.straight_path(x0, y0, dx, dy, frames),
                                   fixture=fixture))
