"""Obstacles (issue #24.1): `obstacles` (circles and boxes, with friction) and the `obstacle`
action. No free vertex ends a frame inside one or passes through one between frames, however
fast the cloth or the obstacle moves; a chain hung over a frictionless circle is symmetric with
catenaries for its free parts; a cloth dropped on a box settles on it; friction holds what a
frictionless surface lets slide; a move is recorded and replays exactly; bad scenes are
refused. The page's side: tests/browser/test_parity.py (obstacle scenes, bit for bit)."""
import json
import math

import pytest

from cloth.api import load, run
from cloth.scene import SceneError, MAX_OBSTACLES
from cloth.session import open_session, gesture_obstacle, gesture_grab, gesture_move, \
    gesture_release, recording_text, advance
from cloth.sim import frame, grab, move, release, move_obstacle


def depth(cl):
    """How far the deepest free vertex is inside an obstacle (<= 0: none is)."""
    worst = -math.inf
    for j in range(cl.n_obstacles):
        cx, cy = cl.obstacle_at[2 * j], cl.obstacle_at[2 * j + 1]
        hx, hy = cl.obstacle_half[2 * j], cl.obstacle_half[2 * j + 1]
        for k in range(cl.n_verts):
            if cl.inv_mass[k] == 0:
                continue
            x, y = cl.pos[2 * k] - cx, cl.pos[2 * k + 1] - cy
            d = hx - math.hypot(x, y) if cl.obstacle_shape[j] == 0 else min(hx - abs(x), hy - abs(y))
            worst = max(worst, d)
    return worst


def speed(cl):
    return max(math.hypot(cl.pos[2 * k] - cl.prev[2 * k], cl.pos[2 * k + 1] - cl.prev[2 * k + 1])
               for k in range(cl.n_verts)) / cl.h


@pytest.mark.parametrize('solver', ['xpbd', 'jakobsen'])
@pytest.mark.parametrize('cols', [10, 24])
def test_a_cloth_dropped_on_a_box_settles_on_it_never_inside(solver, cols):
    spacing = 1.0 / (cols - 1)
    cl = load(json.dumps({'cols': cols, 'rows': cols, 'spacing': spacing, 'pins': [], 'solver': solver,
                          'damping': 2, 'obstacles': [{'box': [0.1, -1.8, 0.9, -1.4], 'friction': 0.5}]}))
    for f in range(480):
        frame(cl)
        assert depth(cl) <= 1e-9, f
    # It rests on the box's top (y = -1.4), none of it below where it can hang past the sides.
    lowest = min(cl.pos[2 * k + 1] for k in range(cl.n_verts))
    assert lowest > -1.8 and speed(cl) < 0.05


def test_an_obstacle_moved_one_metre_in_one_frame_pushes_the_cloth_never_through_it():
    cols = 12
    scene = {'cols': cols, 'rows': 10, 'spacing': 0.1, 'pins': list(range(cols)), 'damping': 1,
             'obstacles': [{'box': [-0.6, -0.8, -0.4, -0.2]}]}
    for solver in ('xpbd', 'jakobsen'):
        scene['solver'] = solver
        cl = load(json.dumps(scene))
        for _ in range(60):
            frame(cl)
        # Which free vertices lie in the box's path (its height, between where it is and 1 m on).
        path = [k for k in range(cl.n_verts) if cl.inv_mass[k] > 0 and -0.8 < cl.pos[2 * k + 1] < -0.2
                and cl.pos[2 * k] < 0.6]
        assert len(path) > 20
        move_obstacle(cl, 0, 0.5, -0.5)       # its right side from x = -0.4 to x = 0.6
        frame(cl)
        assert depth(cl) <= 1e-9
        # Every vertex in its path was carried ahead of it: none is left behind it.
        behind = [k for k in path if cl.pos[2 * k] < 0.4 and -0.8 < cl.pos[2 * k + 1] < -0.2]
        assert behind == [], (solver, behind)
        for _ in range(120):
            frame(cl)
            assert depth(cl) <= 1e-9


def test_a_cloth_falling_far_in_one_step_does_not_pass_through_a_thin_box():
    # 2000 m/s^2 for a 1/60 s step: 0.55 m a step, against a box 1 mm thick.
    cl = load(json.dumps({'cols': 8, 'rows': 2, 'spacing': 0.1, 'pins': [], 'solver': 'jakobsen',
                          'gravity': [0, -2000], 'max_speed': 1e6,
                          'obstacles': [{'box': [-0.5, -1.001, 1.2, -1.0]}]}))
    for _ in range(10):
        frame(cl)
        assert depth(cl) <= 1e-9
    assert min(cl.pos[2 * k + 1] for k in range(cl.n_verts)) >= -1.0 - 1e-9


def hang_chain(friction, frames=900):
    """A chain 2 m long carried in from its rest span to pins 1.6 m apart, over a circle
    between them that it wraps."""
    n = 41
    cl = load(json.dumps({'cols': n, 'rows': 1, 'spacing': 2.0 / (n - 1), 'pins': [0, n - 1],
                          'damping': 2, 'density': 0.2,
                          'obstacles': [{'circle': [0.8, -0.45, 0.3], 'friction': friction}]}))
    k = n - 1
    grab(cl, k, 2.0, 0.0)
    for f in range(60):
        t = 0.5 - 0.5 * math.cos(math.pi * (f + 1) / 60)
        move(cl, k, 2.0 - 0.4 * t, 0.0)
        frame(cl)
        assert depth(cl) <= 1e-9
    release(cl, k)
    for _ in range(frames):
        frame(cl)
    return cl, [(cl.pos[2 * i], cl.pos[2 * i + 1]) for i in range(n)]


def test_a_chain_over_a_frictionless_circle_is_symmetric_and_its_free_parts_are_catenaries():
    cl, p = hang_chain(0.0)
    n = len(p)
    assert depth(cl) <= 1e-9
    # Mirror-symmetric about the circle's axis (it was carried in from one side only).
    assert max(math.hypot(p[i][0] - (1.6 - p[n - 1 - i][0]), p[i][1] - p[n - 1 - i][1])
               for i in range(n)) < 3e-3
    # It wraps the circle's top...
    on = [i for i in range(n) if math.hypot(p[i][0] - 0.8, p[i][1] + 0.45) < 0.3 + 1e-6]
    assert len(on) >= 5 and on == list(range(on[0], on[-1] + 1))
    # ...and each free part is a discrete catenary: equal weights at the joints and one
    # horizontal tension make the links' slopes step by the same amount at every free joint.
    slope = [(p[i + 1][1] - p[i][1]) / (p[i + 1][0] - p[i][0]) for i in range(n - 1)]
    for free in (range(2, on[0] - 1), range(on[-1] + 2, n - 2)):
        steps = [slope[i] - slope[i - 1] for i in free]
        assert len(steps) >= 8
        mean = sum(steps) / len(steps)
        assert max(abs(s - mean) for s in steps) < 0.03 * mean


def test_friction_holds_a_chain_that_a_frictionless_circle_lets_slide():
    def drop(friction):
        # A chain laid over a circle off its centre: more of it on the right.
        n = 30
        cl = load(json.dumps({'cols': n, 'rows': 1, 'spacing': 0.05, 'pins': [], 'damping': 0.5,
                              'obstacles': [{'circle': [0.55, -0.5, 0.3], 'friction': friction}]}))
        for _ in range(300):
            frame(cl)
            assert depth(cl) <= 1e-9
        return max(cl.pos[2 * k + 1] for k in range(n))
    assert drop(0.0) < -0.5 - 0.3          # slid off: all of it below the circle
    assert drop(1.0) > -0.5                # held on its top


@pytest.mark.parametrize('solver', ['xpbd', 'jakobsen'])
def test_tearing_starts_at_a_sharp_box_corner(solver):
    """A box pushed sideways into a tearable curtain: the cloth wraps its top corner, and the
    first edge to break is at that corner (within a spacing)."""
    cols = 15
    cl = load(json.dumps({'cols': cols, 'rows': 12, 'spacing': 0.1, 'pins': list(range(cols)),
                          'solver': solver, 'tear': 0.1, 'obstacles': [{'box': [-0.6, -1.5, -0.1, -0.5]}]}))
    for f in range(200):
        move_obstacle(cl, 0, -0.35 + 1.6 * min(1.0, (f + 1) / 90), -1.0)
        before = {(cl.edge_a[e], cl.edge_b[e]) for e in range(cl.n_edges)}
        frame(cl)
        assert depth(cl) <= 1e-9
        gone = before - {(cl.edge_a[e], cl.edge_b[e]) for e in range(cl.n_edges)}
        if gone:
            break
    assert gone
    corner = (cl.obstacle_at[0] + 0.25, -0.5)
    for a, b in gone:
        mid = ((cl.pos[2 * a] + cl.pos[2 * b]) / 2, (cl.pos[2 * a + 1] + cl.pos[2 * b + 1]) / 2)
        assert math.hypot(mid[0] - corner[0], mid[1] - corner[1]) < 0.1


def test_an_obstacle_drag_is_recorded_and_replays_bit_for_bit():
    scene = {'cols': 8, 'rows': 6, 'spacing': 0.1, 'pins': list(range(8)),
             'obstacles': [{'circle': [-0.5, -0.3, 0.15], 'friction': 0.3}, {'box': [1.0, -1.0, 1.2, -0.8]}]}
    s = open_session(json.dumps(scene))
    advance(s, 10)
    for i in range(1, 8):
        assert gesture_obstacle(s, 0, -0.5 + 0.15 * i, -0.3)      # several moves in one frame
    assert not gesture_obstacle(s, 0, -0.5 + 0.15 * 7, -0.3)      # where it already goes
    advance(s, 5)
    gesture_grab(s, 42, s.panels[0].pos[84], s.panels[0].pos[85])
    gesture_move(s, 42, 0.4, -0.9)
    advance(s, 3)
    gesture_obstacle(s, 1, 0.2, -0.9)
    advance(s, 20)
    gesture_release(s, 42)
    advance(s, 30)
    text = recording_text(s)
    actions = json.loads(text)['actions']
    assert [a['op'] for a in actions] == ['obstacle', 'grab', 'move', 'obstacle', 'release']
    assert actions[0] == {'frame': 10, 'op': 'obstacle', 'index': 0, 'to': [-0.5 + 0.15 * 7, -0.3]}
    got = json.loads(run(text))['positions']
    cl = s.panels[0]
    assert got == [[cl.pos[2 * k], cl.pos[2 * k + 1]] for k in range(cl.n_verts)]


def test_a_set_leaves_the_obstacles_where_they_were_moved():
    scene = {'cols': 6, 'rows': 5, 'spacing': 0.1, 'pins': [0, 5], 'obstacles': [{'circle': [0, -2, 0.2]}],
             'actions': [{'frame': 2, 'op': 'obstacle', 'index': 0, 'to': [0.25, -0.3]},
                         {'frame': 5, 'op': 'set', 'scene': {'substeps': 3, 'wind': [2, 0]}}]}
    cl = load(json.dumps(scene))
    from cloth.script import apply_due
    nxt = apply_due(cl, 0, 0)
    for f in range(1, 12):
        frame(cl)
        nxt = apply_due(cl, nxt, f)
    assert (cl.obstacle_at[0], cl.obstacle_at[1]) == (0.25, -0.3) and cl.substeps == 3
    assert depth(cl) <= 1e-9


def test_no_obstacles_is_the_same_cloth_as_no_key():
    scene = {'cols': 7, 'rows': 6, 'spacing': 0.1, 'pins': [0, 6]}
    a = run(json.dumps(scene), 60)
    scene['obstacles'] = []
    assert run(json.dumps(scene), 60) == a


@pytest.mark.parametrize('obstacles,words', [
    ('{"circle": [0, 0, 1]}', 'obstacles: must be a list'),
    ('[{"circle": [0, 0]}]', 'obstacles[0].circle: must be a list of three numbers'),
    ('[{"circle": [0, 0, 0]}]', 'obstacles[0].circle: must be a radius in (0'),
    ('[{"circle": [0, 0, -1]}]', 'obstacles[0].circle: must be a radius'),
    ('[{"circle": [1e300, 0, 1]}]', 'obstacles[0].circle: must be within 1000000 m'),
    ('[{"box": [1, 0, 0, 1]}]', 'obstacles[0].box: must have x1 > x0 and y1 > y0'),
    ('[{"box": [0, 0, 1]}]', 'obstacles[0].box: must be a list of four numbers'),
    ('[{"box": [0, 0, 20000, 1]}]', 'obstacles[0].box: at most 10000 m a side'),
    ('[{"circle": [0, 0, 1], "box": [0, 0, 1, 1]}]', 'obstacles[0]: needs one shape'),
    ('[{}]', 'obstacles[0]: needs one shape'),
    ('[{"circle": [0, 0, 1], "friction": 2}]', 'obstacles[0].friction: must be from 0 to 1'),
    ('[{"circle": [0, 0, 1], "bounce": 1}]', 'obstacles[0].bounce: unknown key'),
    ('[7]', 'obstacles[0]: must be an object'),
    ('[' + ','.join(['{"circle": [0, 0, 1]}'] * (MAX_OBSTACLES + 1)) + ']', 'obstacles: at most'),
])
def test_bad_obstacles_are_refused_by_name(obstacles, words):
    text = '{"cols": 2, "rows": 2, "spacing": 0.1, "obstacles": ' + obstacles + '}'
    with pytest.raises(SceneError) as e:
        load(text)
    assert str(e.value).startswith(words), str(e.value)


@pytest.mark.parametrize('action,words', [
    ({'frame': 1, 'op': 'obstacle', 'index': 1, 'to': [0, 0]}, 'actions[0].index: must be an obstacle index'),
    ({'frame': 1, 'op': 'obstacle', 'to': [0, 0]}, 'actions[0].index: missing'),
    ({'frame': 1, 'op': 'obstacle', 'index': 0}, 'actions[0].to: missing'),
    ({'frame': 1, 'op': 'obstacle', 'index': 0, 'vertex': 0, 'to': [0, 0]}, 'actions[0].vertex: an obstacle'),
    ({'frame': 1, 'op': 'obstacle', 'index': 0, 'to': [2e6, 0]}, 'actions[0].to: must be within'),
    ({'frame': 1, 'op': 'grab', 'vertex': 0, 'index': 0}, 'actions[0].index: only obstacle'),
])
def test_bad_obstacle_actions_are_refused_by_name(action, words):
    scene = {'cols': 2, 'rows': 2, 'spacing': 0.1, 'obstacles': [{'circle': [0, -1, 0.1]}], 'actions': [action]}
    with pytest.raises(SceneError) as e:
        load(json.dumps(scene))
    assert str(e.value).startswith(words), str(e.value)
    scene.pop('obstacles')
    if 'obstacle index' in words:      # a good action, in a scene without obstacles
        with pytest.raises(SceneError) as e:
            load(json.dumps(scene))
        assert 'the scene has no obstacles' in str(e.value)


def test_a_strip_falls_onto_a_peg_five_times_thinner_than_its_spacing_and_stays_on_it():
    """Edges are held out of circles too (solve.shield_edges): the peg fits between two
    vertices, and without it the strip fell through (its vertices miss the peg)."""
    n = 40
    cl = load(json.dumps({'cols': n, 'rows': 2, 'spacing': 0.05, 'pins': [], 'damping': 1,
                          'obstacles': [{'circle': [0.987, -0.4, 0.01], 'friction': 0.8}]}))
    for _ in range(240):
        frame(cl)
        assert depth(cl) <= 1e-9
    assert max(cl.pos[2 * k + 1] for k in range(cl.n_verts)) > -0.4       # over the peg


def test_the_seeds_method_lands_a_towel_on_its_peg_without_passing_through():
    """The Towel on a peg preset's scene at 30 columns under the seed's method, which stretches
    it several times over as it lands: its edges, longer than the peg, are kept on their side
    of it (swept: an edge that passed the peg's centre within the step goes back)."""
    n = 30
    spacing = 2.0 / (n - 1)
    cl = load(json.dumps({'cols': n, 'rows': 3, 'spacing': spacing, 'pins': [], 'solver': 'jakobsen',
                          'damping': 1, 'density': 0.2, 'compliance': 0.002,
                          'obstacles': [{'circle': [1.0, -0.7, max(0.08, spacing)], 'friction': 0.6}]}))
    for _ in range(300):
        frame(cl)
    assert max(cl.pos[2 * k + 1] for k in range(cl.n_verts)) > -0.7
