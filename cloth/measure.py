"""Queries on the current state: what the colours show, the energies, picking.

What the colours show. Under the membrane (the default and XPBD) an edge's value is its
tension strain, max(0, L / L0 - 1): an edge shorter than at rest is wrinkled out of the plane,
not strained, and the fabric's strain there is 0 (painting |L - L0| would show every wrinkled
region of a slack hang as if stretched). Under the seed's method it is the seed's own |diff| =
|L - L0| / L. Per vertex, the seed's node stress Q: the mean of its structural edges' values.
Only structural edges are drawn and measured: the diagonals stand for the shear between them.
Computed when asked for: the page asks every frame, a headless run once at the end.
"""

import math

from cloth.host import f64, i32
from cloth.energy import by_piece

# The colours' automatic full scale (the page's Auto) is the value HIGH_SHARE of the drawn
# edges are at or below, not the largest: where a clamp ends, or at a point pin, a continuum's
# strain has a corner singularity that grows as the grid refines (the largest strain of a
# two-corner hang: 5.6% at 30x30, 19% at 120x120, 0.3% RMS), so a scale by the largest value
# would darken the whole cloth more the finer the grid. Found on a histogram of BINS_PER_DECADE
# bins a decade from 10^LOWEST_DECADE up (no sort, nothing allocated): within 8% of the exact
# quantile. (Display only: log and pow may differ in the last place between runtimes, which
# moves the scale by a bin at most; no position or edge value depends on it.)
HIGH_SHARE = 0.99
BINS_PER_DECADE = 32
LOWEST_DECADE = -8
DECADES = 10


def prepare(cloth):
    cloth.edge_value = f64(cloth.n_struct if cloth.n_struct > 0 else 1)
    cloth.stress = f64(cloth.n_verts)
    cloth.histogram = i32(BINS_PER_DECADE * DECADES + 1)
    cloth.high_value = 0.0
    cloth.max_value = 0.0
    cloth.max_stress = 0.0
    cloth.max_strain = 0.0
    cloth.rms_strain = 0.0


def measure(cloth):
    """Fill `edge_value` (per structural edge) and `stress` (per vertex), and the summaries:
    max_value, max_stress, and the tension strain's max_strain and rms_strain."""
    pos = cloth.pos
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    value = cloth.edge_value
    stress = cloth.stress
    degree = cloth.degree
    n = cloth.n_verts
    m = cloth.n_struct
    seed = cloth.seed
    sqrt = math.sqrt
    for k in range(n):
        stress[k] = 0.0
    max_value = 0.0
    max_strain = 0.0
    sum2 = 0.0
    for e in range(m):
        a = ea[e]
        b = eb[e]
        dx = pos[b + b] - pos[a + a]
        dy = pos[b + b + 1] - pos[a + a + 1]
        length = sqrt(dx * dx + dy * dy)
        strain = length / rest[e] - 1.0
        if strain < 0.0:
            strain = 0.0
        if seed:
            v = 1.0
            if length > 1e-15:
                v = (length - rest[e]) / length
            if v < 0.0:
                v = -v
        else:
            v = strain
        value[e] = v
        stress[a] += v
        stress[b] += v
        if v > max_value:
            max_value = v
        if strain > max_strain:
            max_strain = strain
        sum2 += strain * strain
    max_q = 0.0
    for k in range(n):
        if degree[k] > 0:
            q = stress[k] / degree[k]
            stress[k] = q
            if q > max_q:
                max_q = q
    cloth.max_value = max_value
    cloth.max_stress = max_q
    high_value(cloth)
    cloth.max_strain = max_strain
    cloth.rms_strain = sqrt(sum2 / m) if m > 0 else 0.0


def energies(cloth):
    """[kinetic, elastic, gravitational] energy now, in joules (energy.by_piece, summed)."""
    by_piece(cloth)
    e = cloth.piece_energy
    out = [0.0, 0.0, 0.0]
    for p in range(cloth.n_pieces):
        out[0] += e[3 * p]
        out[1] += e[3 * p + 1]
        out[2] += e[3 * p + 2]
    return out


def nearest(cloth, x, y, radius):
    """The vertex nearest to (x, y) within `radius`, or -1."""
    best = -1
    best_d2 = radius * radius
    pos = cloth.pos
    for k in range(cloth.n_verts):
        dx = pos[k + k] - x
        dy = pos[k + k + 1] - y
        d2 = dx * dx + dy * dy
        if d2 <= best_d2:
            best_d2 = d2
            best = k
    return best


def high_value(cloth):
    """cloth.high_value: the HIGH_SHARE quantile of edge_value, from its histogram (the upper
    edge of the bin it falls in; 0 when that many edges are 0)."""
    hist = cloth.histogram
    bins = len(hist)
    for b in range(bins):
        hist[b] = 0
    value = cloth.edge_value
    m = cloth.n_struct
    scale = BINS_PER_DECADE / math.log(10.0)
    for e in range(m):
        v = value[e]
        b = 0
        if v > 0.0:
            # math.floor, not int(): Transcrypt makes int() a parseFloat, a string a call.
            b = 1 + math.floor((math.log(v) * scale) - LOWEST_DECADE * BINS_PER_DECADE)
            if b < 1:
                b = 1
            if b >= bins:
                b = bins - 1
        hist[b] += 1
    want = HIGH_SHARE * m
    seen = 0
    cloth.high_value = 0.0
    for b in range(bins):
        seen += hist[b]
        if seen >= want:
            if b > 0:
                cloth.high_value = math.pow(10.0, LOWEST_DECADE + b / BINS_PER_DECADE)
            return
