"""The other-figures benchmark's own arithmetic (bench/figures.py): the pendulum's
period and energy read from a track, the tethers' excess in the exact hang, and the report."""
import math

from bench import figures as bf
from cloth.reference import pendulum_period


def track(length, period, amplitude, decay, frames, dt=1 / 60):
    """A bob on a circle whose angle is amplitude * decay^(t / period) * cos(2 pi t / period)."""
    out = []
    for f in range(1, frames + 1):
        t = f * dt
        a = amplitude * decay ** (t / period) * math.cos(2 * math.pi * t / period)
        out += [length * math.sin(a), -length * math.cos(a)]
    return out


def test_a_known_swing_reads_its_period_and_its_loss():
    length, period = 1.0, 2.0
    crossings, heights = bf.swings(track(length, period, math.pi / 2, 1.0, 400), length, 1 / 60)
    periods = [b - a for a, b in zip(crossings, crossings[2:])]
    assert abs(sum(periods) / len(periods) - period) < 1e-3
    assert all(abs(h - length) < 1e-3 for h in heights[1:4])
    # A swing that loses amplitude is told apart: the turning heights fall.
    _, lossy = bf.swings(track(length, period, math.pi / 2, 0.5, 400), length, 1 / 60)
    assert lossy[2] < lossy[1] < length


def test_the_exact_period_tends_to_the_small_swing_one():
    assert math.isclose(pendulum_period(1.0, 1e-6), 2 * math.pi / math.sqrt(9.81), rel_tol=1e-9)
    # 90 degrees: K(1/2) = 1.8540746773013719
    assert math.isclose(pendulum_period(1.0, math.pi / 2), 4 / math.sqrt(9.81) * 1.8540746773013719,
                        rel_tol=1e-12)


def test_the_exact_hang_puts_most_vertices_beyond_a_straight_tether():
    for row in bf.tether_table(quick=True):
        # Straight columns under a sagging top row: every vertex below an inner top node is
        # farther from its pin than the straight rest distance, and never by more than the
        # path allows (the path from the pin is at most (c + r) h against hypot(c, r) h).
        assert 0.5 < row['beyond'] <= 1.0
        assert 0.0 < row['mean_excess'] <= row['max_excess'] < math.sqrt(2) - 1 + 1e-9


def test_the_report_has_every_table():
    res = {'meta': {'command': 'python -m bench --figures', 'date': 'd', 'chromium': 'c',
                    'cpus': 2, 'seconds': 1.0},
           'sleep': [{'scene': 'curtain', 'n': 10, 'frames': 160, 'cap': 1800, 'swing': 3e-4,
                      'jump': 1e-5, 'extent': 2.0, 'awake_gap': 1e-5},
                     {'scene': 'pendulum 1 m, undamped', 'n': 2, 'frames': -1, 'cap': 12000,
                      'swing': 0.5, 'jump': 0.1, 'extent': 1.0, 'awake_gap': None}],
           'pendulum': [{'length': 1.0, 'solver': 'seed', 'exact': 2.3678, 'period': 2.1,
                         'period_error': -0.11, 'first_swing': 0.3, 'per_period': 0.41}],
           'stretch': [{'scene': 'curtain', 'n': 30, 'seed_rms': 0.02, 'seed_max': 0.05,
                        'default_rms': 0.003, 'default_max': 0.008}],
           'sweeps': [{'n': 30, 'config': 'seed, 1 sweep, undamped', 'fastest': 4e3,
                       'clamped': 5, 'finite': True}],
           'corner': [{'n': 30, 'carried_fastest': 1.2, 'carried_above': -0.001,
                       'put_fastest': 28.0, 'put_above': 0.05}],
           'tethers': bf.tether_table(quick=True),
           'draw': [{'scene': 'curtain', 'n': 200, 'ms': 500.0}]}
    md = bf.markdown(res)
    for title in ('## Sleep', '## Pendulum', "## The seed's method at rest", '## One sweep per step',
                  "## The Two corners preset's corner", '## Tethers', '## Drawing'):
        assert title in md
    assert '| curtain | 10x10 | 160 |' in md
    assert 'not within 12000' in md
    assert '| 30x30 | seed, 1 sweep, undamped | 4e+03 | 5 | yes |' in md
