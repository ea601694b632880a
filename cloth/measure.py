"""Queries on the current state: deformation as the seed defines it, and picking.

Computed only when asked for: the page asks every frame, a headless run once at the end.
"""

import math


def deformation(pos, edge_a, edge_b, rest, m, degree, n, diff, stress, stats):
    """Per edge diff = (len - rest) / len (the seed's deformation coefficient); per vertex
    Q = the mean of |diff| over its edges. Fills `diff` and `stress`, and `stats` with
    [max |diff|, RMS diff, max Q, max strain, RMS strain], strain = len / rest - 1.

    An edge squeezed to a point has no finite diff; it is reported as -1 (fully compressed)."""
    sqrt = math.sqrt
    for k in range(n):
        stress[k] = 0.0
    max_diff = 0.0
    sum_diff2 = 0.0
    max_strain = 0.0
    sum_strain2 = 0.0
    for e in range(m):
        a = edge_a[e]
        b = edge_b[e]
        ia = a + a
        ib = b + b
        dx = pos[ib] - pos[ia]
        dy = pos[ib + 1] - pos[ia + 1]
        length = sqrt(dx * dx + dy * dy)
        d = -1.0
        if length > 1e-15:
            d = (length - rest[e]) / length
        strain = length / rest[e] - 1.0
        diff[e] = d
        ad = d if d >= 0.0 else -d
        stress[a] += ad
        stress[b] += ad
        if ad > max_diff:
            max_diff = ad
        sum_diff2 += d * d
        astrain = strain if strain >= 0.0 else -strain
        if astrain > max_strain:
            max_strain = astrain
        sum_strain2 += strain * strain
    max_q = 0.0
    for k in range(n):
        if degree[k] > 0:
            q = stress[k] / degree[k]
            stress[k] = q
            if q > max_q:
                max_q = q
    stats[0] = max_diff
    stats[1] = sqrt(sum_diff2 / m) if m > 0 else 0.0
    stats[2] = max_q
    stats[3] = max_strain
    stats[4] = sqrt(sum_strain2 / m) if m > 0 else 0.0


def nearest_vertex(pos, n, x, y, radius):
    """The vertex nearest to (x, y) within `radius`, or -1."""
    best = -1
    best_d2 = radius * radius
    for k in range(n):
        dx = pos[k + k] - x
        dy = pos[k + k + 1] - y
        d2 = dx * dx + dy * dy
        if d2 <= best_d2:
            best_d2 = d2
            best = k
    return best
