"""The benchmark's own arithmetic (bench/front.py, bench/fabrics.py, bench/releases.py): the
front, the targets, the errors against the exact statics, the field of one grid sampled on
another, and what a release is held to."""
import json
import math

import numpy as np

from bench import fabrics as bfab
from bench import front as bf
from bench import releases as brel
from cloth.api import load


def row(config, ms, field, scene='corners', n=60, ratio=1.0):
    return {'scene': scene, 'n': n, 'config': config, 'ms': ms, 'field': field,
            'ratio': ratio, 'ratio_lo': ratio, 'ratio_hi': ratio}


def test_the_front_holds_what_no_other_beats_on_both():
    rows = [row('a', 1.0, 0.5), row('b', 2.0, 0.1), row('c', 3.0, 0.2), row('d', 0.5, 0.9),
            row('e', 2.5, 0.05, n=120)]
    bf.mark_front(rows)
    assert [r['front'] for r in rows] == [True, True, False, True, True]


def test_the_targets_fail_when_the_default_is_off_the_front_or_too_slow():
    # The ratio is the side-by-side measurement's (round by round), not ms over ms.
    rows = [row(bf.DEFAULT, 2.0, 0.1, ratio=1.9), row(bf.SEED, 1.0, 0.5), row('x', 1.5, 0.05)]
    bf.mark_front(rows)
    out = dict(bf.checks(rows))
    assert list(out.values()) == [False, True]          # off the front; 1.9x the seed's time
    rows[0]['ms'] = 4.0
    rows[0]['ratio'] = 2.1
    rows[2]['field'] = 0.2
    bf.mark_front(rows)
    assert list(dict(bf.checks(rows)).values()) == [True, False]   # on it, but 2.1x the seed's


def test_the_median_of_the_rounds():
    assert bf.median([3.0, 1.0, 2.0]) == 2.0 and bf.median([4.0, 1.0, 2.0, 3.0]) == 2.5


def test_the_errors_of_the_exact_statics_are_zero_and_grow_with_a_displacement():
    text = bf.scene_text('curtain', 8, {})
    cloth = load(text)
    start = list(cloth.pos)
    exact, info = bf.exact_of(text, start)
    assert info['residual'] < 1e-6
    field, shape = bf.errors_of(text, exact.reshape(-1).tolist(), exact)
    assert field == 0.0 and shape == 0.0
    moved = exact.copy()
    moved[cloth.n_verts - 1, 1] -= 0.01                  # a bottom corner 1 cm lower
    field, shape = bf.errors_of(text, moved.reshape(-1).tolist(), exact)
    assert field > 0.05 and 0.0 < shape < 0.01


def test_a_smooth_field_sampled_on_another_grid_is_itself():
    def field(n):
        t = np.linspace(0.0, 1.0, n)
        return np.add.outer(2.0 * t, 3.0 * t)            # linear: bilinear sampling is exact
    got = bfab.sample(field(17), 17, 5)
    assert np.allclose(got, field(5), atol=1e-12)
    assert not np.allclose(bfab.sample(field(17)[::-1], 17, 5), field(5))



def test_a_field_restricted_to_a_coarser_grid_keeps_each_patch_mean_and_the_force_across_it():
    """bench/fabrics.restrict: a grid's edge field on a coarser grid's edges, each the mean over
    the patch the coarse edge stands for (its length by a spacing across it, half a spacing at a
    border)."""
    fine, coarse = 13, 4                                   # 12 cells and 3: not nested
    u_edge = (np.arange(fine - 1) + 0.5) / (fine - 1)      # where the fine edges' middles are
    # Along rows, a field linear along the edges and anything across them: each coarse edge gets
    # the line's value at its middle (the fine edges tile it exactly).
    along_rows = np.tile(2.0 + 3.0 * u_edge, (fine, 1))
    along_cols = np.ones((fine - 1, fine))
    r, c = bfab.restrict((along_rows, along_cols), fine, coarse)
    u_coarse = (np.arange(coarse - 1) + 0.5) / (coarse - 1)
    assert r.shape == (coarse, coarse - 1) and c.shape == (coarse - 1, coarse)
    assert np.allclose(r, 2.0 + 3.0 * u_coarse[None, :]) and np.allclose(c, 1.0)
    # A grid restricted to itself is itself.
    noise = np.random.default_rng(1).random((fine, fine - 1))
    r, c = bfab.restrict((noise, noise.T), fine, fine)
    assert np.allclose(r, noise) and np.allclose(c, noise.T)
    # One fine column of strain, the rest none: the force across a row (strain times the width
    # each edge stands for) is kept, spread over the coarse edge whose patch holds it.
    band = np.zeros((fine - 1, fine))
    band[:, 5] = 1.0
    width_fine = np.full(fine, 1.0 / (fine - 1))
    width_fine[[0, -1]] *= 0.5
    width_coarse = np.full(coarse, 1.0 / (coarse - 1))
    width_coarse[[0, -1]] *= 0.5
    c = bfab.restrict((np.zeros((fine, fine - 1)), band), fine, coarse)[1]
    assert np.allclose(c @ width_coarse, (band @ width_fine)[0])
    assert np.count_nonzero(c[0]) == 1

def test_the_exact_pendulum_period_tends_to_the_small_swing_one():
    from cloth.reference import pendulum_period
    assert math.isclose(pendulum_period(1.0, 1e-6), 2 * math.pi / math.sqrt(9.81), rel_tol=1e-9)
    # 90 degrees: K(1/2) = 1.8540746773013719
    assert math.isclose(pendulum_period(1.0, math.pi / 2), 4 / math.sqrt(9.81) * 1.8540746773013719,
                        rel_tol=1e-12)


def release_row(cols, rows, pull, p95, rise, gain=-0.1, stretch=1.0):
    return {'cols': cols, 'rows': rows, 'pull': pull, 'p95': p95, 'rise': rise, 'gain': gain,
            'scale': 1.0, 'finite': True, 'stretch': stretch, 'tap': None}


def test_a_release_is_held_to_the_speed_limits_but_a_strip_to_its_own_stretch():
    limit = brel.LIMITS[0.2]
    assert brel.verdict(release_row(30, 30, 0.2, 0.9 * limit, -0.1)) == []
    # a cloth over the limit or above its pins fails, whatever its stretch stored
    assert len(brel.verdict(release_row(30, 30, 0.2, 1.1 * limit, 0.01, stretch=10.0))) == 2
    # a strip springing back with its stretch passes, and fails on energy gained or a rise
    # higher than its stretch could lift it (v^2 / 2g: 6 m/s lifts 1.83 m)
    assert brel.verdict(release_row(30, 1, 0.2, 6.3, 0.05, stretch=6.0)) == []
    assert len(brel.verdict(release_row(30, 1, 0.2, 6.3, 1.9, stretch=6.0))) == 1
    assert len(brel.verdict(release_row(1, 30, 0.2, 6.3, 0.05, gain=0.5, stretch=6.0))) == 1
