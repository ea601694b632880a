"""Internal forces never move the centre of mass: a free cloth (no pins, no hand, no gravity),
deformed and let go, keeps the momentum it had, whatever its springs do to its shape, and its
centre of mass moves exactly as that momentum says. The springs' forces come in equal and
opposite pairs (cloth/vbd.py's energy depends on differences of positions only), so a step's
exact answer conserves momentum; a solver keeps it exactly when each of its moves does
(XPBD's projections move an edge's two ends in inverse proportion to their inertia), and
otherwise to within what it leaves unbalanced. A projection that holds one end still (a solve
that treats some vertices as fixed to converge faster) breaks it and makes the cloth propel
itself: such a solve was tried for the Two corners hang (docs/design-notes.md, "Columns hung
from the top row") and rose released cloths above their pins.

Momentum here is each solver's own: the membrane's masses are density times the area each
vertex stands for (corners a quarter, edges a half); the seed's method moves every vertex
alike (its relaxation weighs them equally, cloth/jakobsen.py), so its momentum is that of
equal masses, and its centre the plain mean of the positions."""
import math
import random

import pytest
from hypothesis import given, settings, strategies as st, HealthCheck

from helpers import load, scene, frame


def free_cloth(n, seed, jitter, drift, **keys):
    """An n x n free cloth in zero gravity, each vertex moved by up to `jitter` of the spacing
    and then all given the velocity `drift` (m/s), with the history of that uniform motion
    (BDF2's prev and vel_prev; the seed's Verlet reads vel)."""
    h = 1.0 / (n - 1)
    cloth = load(scene(cols=n, rows=n, spacing=h, pins=[], gravity=[0.0, 0.0], damping=0.0,
                       sleep=False, **keys))
    rng = random.Random(seed)
    for k in range(cloth.n_verts):
        cloth.pos[2 * k] += rng.uniform(-jitter, jitter) * h
        cloth.pos[2 * k + 1] += rng.uniform(-jitter, jitter) * h
        for a in (0, 1):
            cloth.vel[2 * k + a] = drift[a]
            cloth.vel_prev[2 * k + a] = drift[a]
            cloth.prev[2 * k + a] = cloth.pos[2 * k + a] - drift[a] * cloth.h
    return cloth


def weights(cloth):
    return [1.0] * cloth.n_verts if cloth.seed else list(cloth.mass)


def centre(cloth):
    m = weights(cloth)
    total = sum(m)
    return [sum(m[k] * cloth.pos[2 * k + a] for k in range(cloth.n_verts)) / total for a in (0, 1)]


def velocity(cloth):
    """The momentum over the mass: the centre of mass's velocity."""
    m = weights(cloth)
    total = sum(m)
    return [sum(m[k] * cloth.vel[2 * k + a] for k in range(cloth.n_verts)) / total for a in (0, 1)]


def run(cloth, frames):
    x0 = centre(cloth)
    for _ in range(frames):
        frame(cloth)
    return x0, centre(cloth)


# XPBD's fabric of every stiffness (a stiff one too: a 2D grid, where it is stable), and the
# seed's rigid edges. (No shear at all, 0 N/m, crashes XPBD: tests/test_robustness.py.)
FABRICS = [{}, {'stretch': 1e4, 'shear': 170.0, 'density': 0.4}, {'shear': 1e-3},
           {'stretch': 10.0, 'shear': 1.0}]


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(n=st.integers(3, 14), seed=st.integers(0, 10 ** 6), jitter=st.floats(0.0, 0.4),
       vx=st.floats(-2.0, 2.0), vy=st.floats(-2.0, 2.0),
       keys=st.sampled_from([dict(f, solver='xpbd') for f in FABRICS] + [{'solver': 'jakobsen'}]))
def test_a_free_cloth_keeps_its_momentum_whatever_its_shape(n, seed, jitter, vx, vy, keys):
    cloth = free_cloth(n, seed, jitter, (vx, vy), **keys)
    frames = 30
    x0, x1 = run(cloth, frames)
    t = frames * cloth.dt
    # Rounding only: the momentum is what it was, and the centre moved at that velocity.
    v = velocity(cloth)
    assert abs(v[0] - vx) < 1e-9 and abs(v[1] - vy) < 1e-9, (v[0] - vx, v[1] - vy)
    assert abs(x1[0] - x0[0] - vx * t) < 1e-9 and abs(x1[1] - x0[1] - vy * t) < 1e-9, (
        x1[0] - x0[0] - vx * t, x1[1] - x0[1] - vy * t)


CASES = [(3, 1, 0.3), (6, 2, 0.4), (10, 3, 0.3), (14, 4, 0.4)]


# The default solver (vertex block descent: one vertex moves at a time, its neighbours held)
# conserves momentum only as far as its solve converges, and at its budget a deformed free
# cloth is far from converged (the cases below: 0.010-0.75 m/s off in 0.5 s without help; a
# 10x10 jittered by 0.3 of its spacing, at rest, drifted 0.32 m in 4 s). The exact step keeps
# a free piece's momentum, so the solver moves each free piece as a whole to where it does
# (cloth/vbd.py keep_momentum): to rounding.
@pytest.mark.parametrize('n,seed,jitter', CASES)
def test_the_default_solver_keeps_a_free_clothes_momentum(n, seed, jitter):
    cloth = free_cloth(n, seed, jitter, (1.0, -0.5))
    x0, x1 = run(cloth, 30)
    v = velocity(cloth)
    assert math.hypot(v[0] - 1.0, v[1] + 0.5) < 1e-9
    assert math.hypot(x1[0] - x0[0] - 0.5, x1[1] - x0[1] + 0.25) < 1e-9


@pytest.mark.parametrize('n,seed,jitter', CASES)
def test_the_default_solver_drifts_no_more_than_its_residual_allows(n, seed, jitter):
    """What the default solver keeps to at its budget. A step's momentum changes by h' times
    the net force its solve left unbalanced (the springs' forces cancel in pairs), and the net
    force of n vertices is at most sqrt(n) times their RMS force, which the solver reports as
    its imbalance times the RMS weight (cloth.imbalance, against 1 g in zero gravity): the
    drift over a run is at most the sum of that over its steps. (The imbalance is the force
    each vertex found before its move in the step's last sweep: an upper estimate of what is
    left after it.)"""
    cloth = free_cloth(n, seed, jitter, (1.0, -0.5))
    mass = sum(cloth.mass)
    allowed = 0.0
    for _ in range(30):
        frame(cloth)
        allowed += cloth.h_bdf * math.sqrt(cloth.n_verts) * cloth.imbalance * math.sqrt(cloth.load2) / mass
    v = velocity(cloth)
    assert math.hypot(v[0] - 1.0, v[1] + 0.5) <= allowed


def test_the_default_solver_keeps_the_momentum_once_converged():
    """Solved to convergence (400 sweeps a step on a 3x3), the default solver's step is the
    exact minimum, which conserves momentum: to rounding."""
    cloth = free_cloth(3, 1, 0.3, (1.0, -0.5), iterations=400)
    x0, x1 = run(cloth, 30)
    v = velocity(cloth)
    assert math.hypot(v[0] - 1.0, v[1] + 0.5) < 1e-9
    assert math.hypot(x1[0] - x0[0] - 0.5, x1[1] - x0[1] + 0.25) < 1e-9
