"""Sleep: a cloth at rest stops being stepped until an operation changes it, and nothing
that still moves visibly is put to sleep."""
import math

import pytest

from cloth.sim import frame, grab, move, release, pin, unpin
from cloth.reference import rest_grid
from helpers import curtain, load, scene, step


def frames_until_asleep(cloth, limit):
    for f in range(limit):
        frame(cloth)
        if cloth.asleep:
            return f + 1
    return None


def test_a_curtain_at_rest_sleeps_after_a_second_and_then_costs_nothing():
    cloth = load(curtain(10, damping=1.0))
    slept = frames_until_asleep(cloth, 200)
    assert slept is not None and 60 <= slept <= 70, slept
    work = cloth.projections
    pos = list(cloth.pos)
    step(cloth, 500)
    assert cloth.asleep
    assert cloth.projections == work
    assert list(cloth.pos) == pos


@pytest.mark.parametrize('op', ['grab', 'release', 'pin', 'unpin'])
def test_every_operation_wakes_it(op):
    cloth = load(curtain(6, damping=1.0))
    assert frames_until_asleep(cloth, 200)
    k = 33                                  # bottom row, not pinned
    if op == 'grab':
        grab(cloth, k, 0.3, -1.5)
    elif op == 'release':
        grab(cloth, k, cloth.pos[2 * k], cloth.pos[2 * k + 1])
        assert frames_until_asleep(cloth, 200)   # held still, it sleeps again
        release(cloth, k)
    elif op == 'pin':
        pin(cloth, k)
    else:
        unpin(cloth, 0)
    assert not cloth.asleep
    work = cloth.projections
    frame(cloth)
    assert cloth.projections > work


def test_a_drag_wakes_it_and_the_cloth_follows_then_rests_again():
    cloth = load(curtain(6, damping=2.0))
    assert frames_until_asleep(cloth, 200)
    k = 32
    x, y = cloth.pos[2 * k], cloth.pos[2 * k + 1]
    nx = cloth.pos[2 * (k + 1)]             # its neighbour in the row
    grab(cloth, k, x, y)
    for i in range(30):
        move(cloth, k, x + 0.01 * i, y + 0.005 * i)
        frame(cloth)
        assert not cloth.asleep
    assert cloth.pos[2 * (k + 1)] - nx > 0.1   # dragged 0.29 m to the right, it followed
    release(cloth, k)
    slept = frames_until_asleep(cloth, 2000)
    assert slept is not None and slept > 60, slept
    # Asleep where it rests: a curtain hangs as its rest grid (cloth/reference.py).
    worst = max(math.hypot(cloth.pos[2 * j] - x0, cloth.pos[2 * j + 1] - y0)
                for j, (x0, y0) in enumerate(rest_grid(cloth.cols, cloth.rows, cloth.spacing)))
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
    # Released horizontally: the bob swings through 180 degrees.
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


def test_sleep_off_and_the_seed_method_never_sleep():
    for text in [curtain(6, damping=1.0, sleep=False),
                 curtain(6, solver='jakobsen', damping=1.0)]:
        cloth = load(text)
        assert frames_until_asleep(cloth, 300) is None


def test_sleeping_leaves_a_settled_cloth_where_it_would_have_been():
    # Two corners, slack: the hang settles slowly and keeps a tiny limit cycle of the solver.
    keys = dict(cols=16, rows=16, spacing=1 / 15, pins=[0, 15], damping=1.0,
                actions=[{'frame': 0, 'op': 'grab', 'vertex': 15, 'to': [0.8, 0.0]},
                         {'frame': 0, 'op': 'pin', 'vertex': 15},
                         {'frame': 0, 'op': 'release', 'vertex': 15}])
    asleep = load(scene(**keys))
    awake = load(scene(sleep=False, **keys))
    from cloth.script import apply_action
    for c in (asleep, awake):
        for a in c.scene.actions:
            apply_action(c, a)
    slept = frames_until_asleep(asleep, 3000)
    assert slept is not None
    step(awake, slept)
    step(asleep, 600)
    step(awake, 600)
    worst = max(math.hypot(asleep.pos[2 * k] - awake.pos[2 * k],
                           asleep.pos[2 * k + 1] - awake.pos[2 * k + 1])
                for k in range(asleep.n_verts))
    assert worst < 2e-3, worst                # metres, on a 1 m cloth: 2 px at 1000 px/m
