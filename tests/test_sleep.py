"""Sleep (cloth/sleep.py): a cloth at rest stops being stepped until an operation changes it, a
sleeping cloth costs nothing (cloth.steps and cloth.sweeps stop growing), and nothing that still
moves visibly is put to sleep."""
import math

import pytest

from cloth.sleep import SLEEP_MOTION, SLEEP_DRIFT, SLEEP_TIME, SLEEP_IMBALANCE
from cloth.reference import statics
from cloth.script import apply_due
from helpers import curtain, preset, load, scene, step, frame, grab, move, release, pin, unpin


def frames_until_asleep(cloth, limit):
    for f in range(limit):
        frame(cloth)
        if cloth.asleep:
            return f + 1
    return None


def extent(cloth):
    return max(max(cloth.cols, cloth.rows) - 1, 1) * cloth.spacing


@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_cloth_in_balance_sleeps_after_exactly_its_window(solver):
    """A curtain without gravity is in balance on its rest grid from the start: nothing moves,
    so it sleeps once SLEEP_TIME of still frames have passed (the frame after the window)."""
    cloth = load(curtain(6, solver=solver, gravity=[0.0, 0.0]))
    window = math.ceil(SLEEP_TIME / cloth.dt)
    assert frames_until_asleep(cloth, 200) == window + 1


@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_curtain_at_rest_sleeps_and_then_costs_nothing(solver):
    """A hanging curtain settles (its fabric stretches under its weight and sways, damped), and
    sleeps only after a window in which no vertex moved more than SLEEP_MOTION of the cloth's
    extent a frame; asleep, it is not stepped: no step, no sweep, not a bit of it moves."""
    cloth = load(curtain(10, solver=solver, damping=1.0))
    bound = SLEEP_MOTION * extent(cloth)
    window = math.ceil(SLEEP_TIME / cloth.dt)
    moved = []
    for f in range(600):
        before = list(cloth.pos)
        frame(cloth)
        moved.append(max(math.hypot(cloth.pos[2 * k] - before[2 * k], cloth.pos[2 * k + 1] - before[2 * k + 1])
                         for k in range(cloth.n_verts)))
        if cloth.asleep:
            break
    assert cloth.asleep
    assert len(moved) > window and max(moved[-window:]) <= bound
    assert cloth.imbalance <= SLEEP_IMBALANCE
    steps, sweeps = cloth.steps, cloth.sweeps
    pos = list(cloth.pos)
    step(cloth, 500)
    assert cloth.asleep
    assert (cloth.steps, cloth.sweeps) == (steps, sweeps)
    assert list(cloth.pos) == pos


@pytest.mark.parametrize('op', ['grab', 'release', 'pin', 'unpin'])
def test_every_operation_wakes_it(op):
    cloth = load(curtain(6, damping=1.0))
    assert frames_until_asleep(cloth, 400)
    k = 33                                  # bottom row, not pinned
    if op == 'grab':
        grab(cloth, k, 0.3, -1.5)
    elif op == 'release':
        grab(cloth, k, cloth.pos[2 * k], cloth.pos[2 * k + 1])
        assert frames_until_asleep(cloth, 400)   # held still, it sleeps again
        release(cloth, k)
    elif op == 'pin':
        pin(cloth, k)
    else:
        unpin(cloth, 0)
    assert not cloth.asleep
    steps, sweeps = cloth.steps, cloth.sweeps
    frame(cloth)
    assert cloth.steps > steps and cloth.sweeps > sweeps


def test_a_drag_wakes_it_and_the_cloth_follows_then_rests_again():
    cloth = load(curtain(6, damping=2.0))
    assert frames_until_asleep(cloth, 400)
    k = 32
    x, y = cloth.pos[2 * k], cloth.pos[2 * k + 1]
    nx = cloth.pos[2 * (k - 1)]             # its neighbour in the row, behind it
    grab(cloth, k, x, y)
    for i in range(30):
        move(cloth, k, x + 0.01 * i, y + 0.005 * i)
        frame(cloth)
        assert not cloth.asleep
    # dragged 0.29 m to the right, the neighbour it pulls followed (the one ahead of it is
    # pushed by nothing: the fabric's springs pull only)
    assert cloth.pos[2 * (k - 1)] - nx > 0.1
    release(cloth, k)
    slept = frames_until_asleep(cloth, 2000)
    assert slept is not None and slept > 60, slept
    # Asleep where it rests: at the curtain's exact equilibrium (cloth/reference.py statics),
    # to a millimetre (measured: 0.13 mm).
    ref, info = statics(cloth)
    assert info['residual'] < 1e-8
    worst = max(math.hypot(cloth.pos[2 * j] - ref[j][0], cloth.pos[2 * j + 1] - ref[j][1])
                for j in range(cloth.n_verts))
    assert worst < 1e-3, worst


def test_a_hand_held_still_lets_the_cloth_sleep():
    # The page calls move() with the same point every frame while the pointer rests; that
    # changes nothing and must not keep the cloth awake.
    cloth = load(curtain(6, damping=2.0))
    k = 32
    x, y = cloth.pos[2 * k] + 0.1, cloth.pos[2 * k + 1] + 0.1
    grab(cloth, k, x, y)
    for f in range(1000):
        move(cloth, k, x, y)
        frame(cloth)
        if cloth.asleep:
            break
    assert cloth.asleep and cloth.held[k] == 1


def pendulum(length, damping=0.0, **extra):
    # Released horizontally: the bob swings through 180 degrees (its spring, the default
    # fabric's, stretches by 0.4 mm at the bottom of the swing).
    return load(scene(cols=2, rows=1, spacing=length, pins=[0], damping=damping, **extra))


def test_a_swinging_pendulum_never_sleeps():
    # L = 0.25 m has a period of about 1 s (1.18 s at this amplitude), close to the sleep
    # window: it comes back near its start, but moves far within the window.
    cloth = pendulum(0.25)
    assert frames_until_asleep(cloth, 3600) is None


def test_a_damped_pendulum_sleeps_only_once_its_swing_is_invisible():
    cloth = pendulum(0.25, damping=0.2)
    biggest = []
    slept = None
    for f in range(12000):
        frame(cloth)
        biggest.append(abs(cloth.pos[2]))     # the bob's horizontal distance from the pin
        if cloth.asleep:
            slept = f
            break
    assert slept is not None, 'a damped pendulum comes to rest'
    last_second = max(biggest[-60:])
    # Asleep only when its swing is below a thousandth of its size (a fraction of a pixel).
    assert last_second < 1e-3 * 0.25, last_second
    assert slept > 60 * 20


@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_sleep_off_never_sleeps_and_sleep_on_sleeps_under_every_solver(solver):
    """`sleep` is every solver's (the seed's method too, since the membrane): off, a cloth at
    rest is stepped for ever; on, it sleeps."""
    cloth = load(curtain(6, solver=solver, damping=1.0, sleep=False))
    assert frames_until_asleep(cloth, 600) is None
    assert frames_until_asleep(load(curtain(6, solver=solver, damping=1.0)), 600) is not None


def test_sleeping_leaves_a_settled_cloth_where_it_would_have_been():
    """The Two corners preset, its right clamp carried in (the top edge sags slack): asleep,
    it stays within the sleep's bounds of where it would have gone on to, awake, which is the
    exact equilibrium (cloth/reference.py statics)."""
    asleep = load(preset('corners', 10))
    awake = load(preset('corners', 10, sleep=False))
    nxt = apply_due(asleep, 0, 0)
    slept = None
    for f in range(1, 3001):
        frame(asleep)
        nxt = apply_due(asleep, nxt, f)
        if asleep.asleep:
            slept = f
            break
    assert slept is not None and slept > 60      # after the carry (60 frames)
    nxt = apply_due(awake, 0, 0)
    for f in range(1, slept + 601):
        frame(awake)
        nxt = apply_due(awake, nxt, f)
    step(asleep, 600)
    worst = max(math.hypot(asleep.pos[2 * k] - awake.pos[2 * k],
                           asleep.pos[2 * k + 1] - awake.pos[2 * k + 1])
                for k in range(asleep.n_verts))
    assert worst < 2e-3, worst                # metres, on a 1.6 m cloth: 2 px at 1000 px/m
    ref, info = statics(awake)
    assert info['residual'] < 1e-8
    assert max(math.hypot(awake.pos[2 * k] - ref[k][0], awake.pos[2 * k + 1] - ref[k][1])
               for k in range(awake.n_verts)) < 1e-5


# An obstacle's reaction is not unbalanced force: under the default solver it is a term of the
# step's energy (cloth/contact.py), so a strip lying still on a box is balanced. (Counted as
# unbalanced, a strip lying still on a box had an imbalance of 1, its whole weight, 100 times
# SLEEP_IMBALANCE, and never slept.)
@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_cloth_lying_on_a_box_sleeps(solver):
    cloth = load(scene(cols=6, rows=1, spacing=0.1, pins=[], damping=2, solver=solver,
                       obstacles=[{'box': [-1, -0.6, 2, -0.1]}]))
    assert frames_until_asleep(cloth, 600) is not None
    assert min(cloth.pos[2 * k + 1] for k in range(6)) > -0.1


# The default solver's strip slid off (9 mm/s after 10 s, and speeding up) while its sweeps'
# contact had no friction; friction is a term of its step now (cloth/contact.py).
@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_cloth_lying_on_a_curved_obstacle_with_friction_sleeps(solver):
    cloth = load(scene(cols=3, rows=1, spacing=0.1, pins=[], damping=2, solver=solver,
                       obstacles=[{'circle': [0.1, -2.1, 2.0], 'friction': 0.5}]))
    assert frames_until_asleep(cloth, 600) is not None
    assert abs(cloth.pos[2] - 0.1) < 1e-3          # the middle stays on the top


def test_the_drift_bound_is_a_fraction_of_the_extent():
    """The bounds are fractions of the cloth's extent (the page fits it to the screen): a
    cloth ten times the size may move ten times as far a frame and still sleep."""
    assert SLEEP_MOTION < SLEEP_DRIFT < 1e-2
    small = load(curtain(6, damping=1.0))
    big = load(scene(cols=6, rows=6, spacing=2.0, pins=list(range(6)), damping=1.0))
    assert big.still_motion2 == pytest.approx(small.still_motion2 * 100.0)
    assert big.drift2 == pytest.approx(small.drift2 * 100.0)
