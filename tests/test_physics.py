"""Physics against exact references: free fall, pins, a pendulum's period, a chain's statics."""

import json
import math

import numpy as np
import pytest

from cloth.reference import pendulum_period, statics, tension_strain
from cloth.keys import SOLVERS
from helpers import scene, curtain, load, step, xy, all_finite, frame, unpin, pin, grab, \
    release, move


@pytest.mark.parametrize('solver', SOLVERS)
@pytest.mark.parametrize('substeps', [1, 3])
def test_free_fall_is_exact(solver, substeps):
    # A free vertex (no edges) must follow x0 + a t^2 / 2 to rounding, at every frame.
    cloth = load(scene(cols=1, rows=1, spacing=1.0, gravity=[1.5, -9.81], dt=0.02,
                       substeps=substeps, solver=solver))
    for f in range(1, 121):
        frame(cloth)
        t = f * 0.02
        x, y = xy(cloth, 0)
        assert x == pytest.approx(0.5 * 1.5 * t * t, rel=1e-12, abs=1e-15)
        assert y == pytest.approx(-0.5 * 9.81 * t * t, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize('solver', SOLVERS)
def test_a_free_cloth_falls_exactly(solver):
    # Every vertex of a cloth with nothing holding it falls as a point does: its edges, at
    # their rest lengths, pull on nothing (the solvers must not add motion of their own).
    cloth = load(scene(cols=6, rows=4, spacing=0.1, solver=solver))
    start = list(cloth.pos)
    step(cloth, 60)
    for k in range(cloth.n_verts):
        assert cloth.pos[2 * k] == pytest.approx(start[2 * k], abs=1e-9)
        assert cloth.pos[2 * k + 1] == pytest.approx(start[2 * k + 1] - 0.5 * 9.81, rel=1e-9)


@pytest.mark.parametrize('solver', SOLVERS)
def test_unpinned_vertex_falls_exactly_from_rest(solver):
    cloth = load(scene(cols=1, rows=1, spacing=1.0, pins=[0], solver=solver))
    step(cloth, 5)
    assert xy(cloth, 0) == (0.0, 0.0)
    unpin(cloth, 0)
    step(cloth, 60)
    # (XPBD's 16 substeps make 960 BDF2 steps of rounding: 8e-12 of the drop)
    assert xy(cloth, 0)[1] == pytest.approx(-0.5 * 9.81, rel=1e-10)


@pytest.mark.parametrize('solver', SOLVERS)
def test_pins_stay_bit_exact(solver):
    n = 8
    cloth = load(curtain(n, solver=solver, gravity=[3.0, -30.0]))
    step(cloth, 200)
    h = 1.0 / (n - 1)
    for c in range(n):
        assert xy(cloth, c) == (c * h, 0.0)
    assert all_finite(cloth.pos)


def pendulum_swings(solver, frames=600, **keys):
    """A 1 m pendulum of cotton (its one edge stretches 0.1 mm under the swing's pull) released
    horizontally; returns (crossing times, the heights of its turning points)."""
    cloth = load(scene(cols=2, rows=1, spacing=1.0, pins=[0], solver=solver, stretch=5000.0,
                       density=0.15, **keys))
    dt = 1 / 60
    crossings, heights = [], [[0.0]]
    px = xy(cloth, 1)[0]
    lowest_side = None
    for f in range(1, frames + 1):
        frame(cloth)
        x, y = xy(cloth, 1)
        assert math.isfinite(x) and math.isfinite(y)
        if px > 0 >= x or px < 0 <= x:
            crossings.append((f - 1 + px / (px - x)) * dt)
        side = 1 if x > 0 else -1
        if lowest_side is not None and side != lowest_side:
            heights.append([])
        lowest_side = side
        heights[-1].append(y)
        px = x
    return crossings, [max(h) for h in heights]


def test_pendulum_period_matches_elliptic_integral():
    # T = 4 sqrt(L/g) K(sin^2(theta0/2)), theta0 = 90 degrees, L = 1 m: the default's BDF2
    # keeps the period within 2% and loses at most 2% of the swing's height per swing (backward
    # Euler would lose 30%).
    exact = pendulum_period(1.0, math.pi / 2)
    crossings, heights = pendulum_swings('vbd')
    assert len(crossings) >= 6
    periods = [crossings[i + 2] - crossings[i] for i in range(len(crossings) - 2)]
    mean = sum(periods) / len(periods)
    assert abs(mean - exact) / exact < 0.02
    lost = [(a - b) / (1 + a) for a, b in zip(heights[:-1], heights[1:-1])]
    assert max(lost) < 0.02


@pytest.mark.parametrize('solver', SOLVERS)
def test_pendulum_never_gains_energy(solver):
    # Height above the lowest point is the energy (kinetic 0 at the turning points): no solver
    # may ever swing it higher than it was released.
    _, heights = pendulum_swings(solver, frames=900)
    assert len(heights) > 10
    assert max(heights) <= 1e-9


def test_chain_settles_on_its_exact_statics():
    # A chain of 10 cotton links carried in to 0.7 of its length and pinned there: once at rest
    # (asleep: its forces balanced to 1% of its weight) it is within 0.1 mm of where the exact
    # statics put it (Newton on the same energy, cloth/reference.py) and its links' strain
    # within 2% of the exact one (a 1-D chain has no corner to concentrate strain).
    n_links, link = 10, 0.1
    actions = [{'frame': 0, 'op': 'grab', 'vertex': n_links, 'to': [n_links * link, 0.0]}]
    for f in range(1, 31):
        actions.append({'frame': f, 'op': 'move', 'vertex': n_links,
                        'to': [n_links * link * (1 - 0.3 * f / 30), 0.0]})
    actions += [{'frame': 30, 'op': 'pin', 'vertex': n_links},
                {'frame': 30, 'op': 'release', 'vertex': n_links}]
    text = scene(cols=n_links + 1, rows=1, spacing=link, pins=[0], damping=2.0,
                 stretch=5000.0, density=0.15, actions=actions)
    cloth = load(text)
    from cloth.api import simulate
    simulate(cloth, 900, None)
    assert cloth.asleep
    x = np.array(cloth.pos).reshape(-1, 2)
    exact, info = statics(cloth)
    assert info['residual'] < 1e-8
    assert np.abs(x - exact).max() < 1e-4
    strain = tension_strain(cloth, x)
    ref = tension_strain(cloth, exact)
    assert np.abs(strain - ref).max() < 0.02 * ref.max()
