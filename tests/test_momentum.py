"""Internal forces never move the centre of mass: a free cloth (no pins, no hand, no gravity),
deformed and let go, keeps the momentum it had, whatever its edges, cells and line solves do
to its shape. Every projection of the default solver moves an edge's two ends by amounts in
inverse proportion to their masses, which is what keeps this exact; a projection that holds one
end still (a solve that treats some vertices as fixed to converge faster) breaks it and makes
the cloth propel itself. Such a solve was tried for the Two corners hang (docs/design-notes.md,
"Columns hung from the top row") and rose released cloths above their pins."""
import random

from hypothesis import given, settings, strategies as st, HealthCheck

from cloth.sim import frame
from helpers import load, scene


def centre(cloth):
    n = cloth.n_verts
    return sum(cloth.pos[0::2]) / n, sum(cloth.pos[1::2]) / n


def free_cloth(n, seed, jitter, drift, **keys):
    """An n x n free cloth in zero gravity, each vertex moved by up to `jitter` of the spacing
    (pos and prev alike: from rest) and then all given the velocity `drift` (m/s)."""
    h = 1.0 / (n - 1)
    cloth = load(scene(cols=n, rows=n, spacing=h, pins=[], gravity=[0.0, 0.0], damping=0.0,
                       sleep=False, **keys))
    rng = random.Random(seed)
    h_step = cloth.h
    for k in range(cloth.n_verts):
        dx = rng.uniform(-jitter, jitter) * h
        dy = rng.uniform(-jitter, jitter) * h
        cloth.pos[2 * k] += dx
        cloth.pos[2 * k + 1] += dy
        cloth.prev[2 * k] = cloth.pos[2 * k] - drift[0] * h_step
        cloth.prev[2 * k + 1] = cloth.pos[2 * k + 1] - drift[1] * h_step
    return cloth


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(n=st.integers(3, 14), seed=st.integers(0, 10 ** 6), jitter=st.floats(0.0, 0.4),
       vx=st.floats(-2.0, 2.0), vy=st.floats(-2.0, 2.0),
       keys=st.sampled_from([{}, {'shear': True}, {'density': 0.2, 'compliance': 0.002},
                             {'cells': False}, {'tolerance': 0.0}]))
def test_a_free_cloth_keeps_its_momentum_whatever_its_shape(n, seed, jitter, vx, vy, keys):
    cloth = free_cloth(n, seed, jitter, (vx, vy), **keys)
    x0, y0 = centre(cloth)
    frames = 30
    for _ in range(frames):
        frame(cloth)
    x1, y1 = centre(cloth)
    t = frames * cloth.dt
    # Rounding only: the centre moves at the velocity it started with.
    assert abs(x1 - x0 - vx * t) < 1e-9 and abs(y1 - y0 - vy * t) < 1e-9, (
        x1 - x0 - vx * t, y1 - y0 - vy * t)
