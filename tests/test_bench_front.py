"""The benchmark's own arithmetic (bench/front.py, bench/fabrics.py): the front, the targets,
the errors against the exact statics, and the field of one grid sampled on another."""
import json
import math

import numpy as np

from bench import fabrics as bfab
from bench import front as bf
from cloth.api import load


def row(config, ms, field, scene='corners', n=60):
    return {'scene': scene, 'n': n, 'config': config, 'ms': ms, 'field': field}


def test_the_front_holds_what_no_other_beats_on_both():
    rows = [row('a', 1.0, 0.5), row('b', 2.0, 0.1), row('c', 3.0, 0.2), row('d', 0.5, 0.9),
            row('e', 2.5, 0.05, n=120)]
    bf.mark_front(rows)
    assert [r['front'] for r in rows] == [True, True, False, True, True]


def test_the_targets_fail_when_the_default_is_off_the_front_or_too_slow():
    rows = [row(bf.DEFAULT, 2.0, 0.1), row(bf.SEED, 1.0, 0.5), row('x', 1.5, 0.05)]
    bf.mark_front(rows)
    out = dict(bf.checks(rows))
    assert list(out.values()) == [False, True]          # off the front; 2x the seed's time
    rows[0]['ms'] = 4.0
    rows[2]['field'] = 0.2
    bf.mark_front(rows)
    assert list(dict(bf.checks(rows)).values()) == [True, False]   # on it, but 4x the seed's


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


def test_the_exact_pendulum_period_tends_to_the_small_swing_one():
    from cloth.reference import pendulum_period
    assert math.isclose(pendulum_period(1.0, 1e-6), 2 * math.pi / math.sqrt(9.81), rel_tol=1e-9)
    # 90 degrees: K(1/2) = 1.8540746773013719
    assert math.isclose(pendulum_period(1.0, math.pi / 2), 4 / math.sqrt(9.81) * 1.8540746773013719,
                        rel_tol=1e-12)
