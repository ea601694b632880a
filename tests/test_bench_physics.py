"""The physics benchmark's own arithmetic (bench/physics.py): strains of a grid, the
field sampled at the same points of the cloth on another grid, the plot."""
import math

from bench import physics as bp


def grid(cols, rows, stretch):
    """Positions of a cols x rows grid of spacing 1 / (rows - 1) whose column links below depth
    v are stretched by stretch(v) (rows at rest)."""
    h = 1.0 / (rows - 1)
    pos, y = [], [0.0]
    for r in range(rows - 1):
        y.append(y[-1] - h * (1 + stretch((r + 0.5) / (rows - 1))))
    for r in range(rows):
        for c in range(cols):
            pos += [c * h, y[r]]
    return pos, h


def test_a_linear_field_is_the_same_on_two_grids():
    field = lambda v: 0.01 * (1 - v)
    coarse, hc = grid(5, 5, field)
    fine, hf = grid(9, 9, field)
    fc = bp.edge_strains(coarse, 5, 5, hc)
    ff = bp.edge_strains(fine, 9, 9, hf)
    assert math.isclose(fc[(0, 2, 'down')], field(0.125), rel_tol=1e-9)
    assert fc[(1, 1, 'right')] == 0.0 or abs(fc[(1, 1, 'right')]) < 1e-12
    got = [bp.sample(ff, 9, 9, c / 4, (r + 0.5) / 4, 'down') for r in range(4) for c in range(5)]
    want = [fc[(r, c, 'down')] for r in range(4) for c in range(5)]
    assert bp.relative_rms(got, want) < 1e-9
    # and a different field is told apart
    other = bp.edge_strains(grid(9, 9, lambda v: 0.01)[0], 9, 9, hf)
    got = [bp.sample(other, 9, 9, c / 4, (r + 0.5) / 4, 'down') for r in range(4) for c in range(5)]
    assert bp.relative_rms(got, want) > 0.3


def test_the_release_plot_draws_every_preset_and_the_target():
    rows = [{'preset': p, 'n': n, 'config': c, 'distance': 0.5, 'fastest': 1.0 + n / 100}
            for p in bp.RELEASE_PRESETS for n in (10, 30) for c, _ in bp.CONFIGS]
    svg = bp.svg_release({'release': rows})
    assert svg.count('<polyline') == len(bp.RELEASE_PRESETS) * len(bp.CONFIGS)
    assert 'target 5 m/s' in svg
