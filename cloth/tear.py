"""Tearing: the fabric's strength, the same on every grid.

A structural edge stands for a strip of yarns one spacing wide along it; its tension per width
is T = k e (k the fabric's stretch stiffness, N/m; e = max(0, L / L0 - 1)). A line of yarns
fails when T, averaged over TEAR_LENGTH across the yarns (along the line a crack through them
would run), passes the fabric's strength S (N/m, the scene's `strength`): the average-stress
criterion (Whitney and Nuismer 1974) whose characteristic length makes the strength a
property of the fabric and not of the cell (crack band regularisation: Bazant and Oh 1983).
A strain limit on each spring is the grid's instead: next to a point-like grip a 2D membrane's
strain grows as 1 / r, so a finer grid's edge there breaks at a smaller pull (measured, the
Tearable preset pulled slowly by a hand: 13.1, 3.9, 1.8, 1.6 and 0.9 N at 10, 30, 60, 120 and
240 columns), and the cells' shear diagonals beside the grip went first.

The average: each edge's strip, h wide, counts by how much of it lies within TEAR_LENGTH / 2
of the edge's middle across the yarns, over the edges parallel to it that are intact (a crack
carries nothing). A grid coarser than TEAR_LENGTH cannot resolve it: its edge's own strip, h
wide, is the finest average it has, and it takes that.

Only yarns break; shear alone never tears. A cell's diagonals go once the crack crosses the
cell (two of its structural edges are broken): both, if they are opposite; the one that joins
the corner they cut off, if they meet there. A crack's tip inside a cell leaves them.
"""

from math import sqrt, floor

from cloth.host import f64, i32
from cloth.fabrics import TEAR_LENGTH



def prepare(cloth):
    """The criterion's work arrays (a scene that tears: cloth.strength > 0)."""
    n = cloth.n_verts
    if len(cloth.tear_t) == 2 * n:
        return
    cloth.tear_t = f64(2 * n)     # per structural slot (horizontal ones first): its tension
    cloth.tear_e = i32(2 * n)     # and its edge (-1: broken)
    longest = cloth.cols if cloth.cols > cloth.rows else cloth.rows
    cloth.tear_sw = f64(longest + 1)
    cloth.tear_st = f64(longest + 1)
    cells = (cloth.cols - 1) * (cloth.rows - 1)
    cloth.tear_d = i32(2 * cells if cells > 0 else 1)


def mark(cloth):
    """Mark (rest = -1) what breaks where the cloth is now: every structural edge whose
    averaged tension passes the strength, and the diagonals of the cells the crack crosses.
    Returns how many structural edges (step.tear then takes them away)."""
    found = mark_weak(cloth)
    if found > 0:
        mark_cells(cloth)
    return found


def mark_weak(cloth):
    """Mark (rest = -1) the structural edges whose tension averaged over TEAR_LENGTH across
    them passes the strength; returns how many."""
    cols = cloth.cols
    rows = cloth.rows
    n = cloth.n_verts
    pos = cloth.pos
    ten = cloth.tear_t
    edge = cloth.tear_e
    k = cloth.scene.stretch
    for t in range(n + n):
        ten[t] = 0.0
        edge[t] = -1
    for e in range(cloth.n_struct):
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        dx = pos[b + b] - pos[a + a]
        dy = pos[b + b + 1] - pos[a + a + 1]
        strain = sqrt(dx * dx + dy * dy) / cloth.rest[e] - 1.0
        # Slot (5: the edge to the right of a, 7: the edge below it) in its grid: horizontal
        # edges at a's index, vertical ones n after.
        s = a if cloth.slot[e] == 5 else n + a
        edge[s] = e
        ten[s] = k * strain if strain > 0.0 else 0.0
    half = 0.5 * TEAR_LENGTH / cloth.spacing
    found = 0
    # Horizontal edges (yarns along x): averaged over the rows of their column.
    for c in range(cols - 1):
        found += line(cloth, c, cols, rows, half)
    # Vertical edges: over the columns of their row.
    for r in range(rows - 1):
        found += line(cloth, n + r * cols, 1, cols, half)
    return found


def line(cloth, first, stride, count, half):
    """mark_weak along one line of parallel slots (first, first + stride, ...; count of them),
    each averaged over its neighbours within `half` spacings."""
    ten = cloth.tear_t
    edge = cloth.tear_e
    sw = cloth.tear_sw
    st = cloth.tear_st
    strength = cloth.strength
    sw[0] = 0.0
    st[0] = 0.0
    for i in range(count):
        s = first + i * stride
        w = 1.0 if edge[s] >= 0 else 0.0
        sw[i + 1] = sw[i] + w
        st[i + 1] = st[i] + w * ten[s]
    # Strips wholly within the window: |j - i| <= full; the next ones by their overlap.
    full = -1
    part = 0.0
    if half >= 0.5:
        full = floor(half - 0.5)
        part = half + 0.5 - (full + 1)
    found = 0
    for i in range(count):
        s = first + i * stride
        e = edge[s]
        if e < 0:
            continue
        mean = ten[s]
        if full >= 0:
            lo = i - full if i - full > 0 else 0
            hi = i + full + 1 if i + full + 1 < count else count
            w = sw[hi] - sw[lo]
            t = st[hi] - st[lo]
            for side in range(2):
                j = i - full - 1 if side == 0 else i + full + 1
                if j >= 0 and j < count and edge[first + j * stride] >= 0:
                    w += part
                    t += part * ten[first + j * stride]
            mean = t / w
        if mean > strength:
            cloth.rest[e] = -1.0
            found += 1
    return found


def mark_cells(cloth):
    """Mark the diagonals of each cell the crack crosses (the module's comment)."""
    cols = cloth.cols
    rows = cloth.rows
    n = cloth.n_verts
    d = cloth.tear_d
    cells = (cols - 1) * (rows - 1)
    for t in range(2 * cells):
        d[t] = -1
    for e in range(cloth.n_struct, cloth.n_edges):
        a = cloth.edge_a[e]
        if cloth.slot[e] == 8:           # from the cell's top-left corner to its bottom-right
            r = a // cols
            d[2 * (r * (cols - 1) + a - r * cols)] = e
        else:                            # from its top-right corner to its bottom-left
            r = (a - 1) // cols
            d[2 * (r * (cols - 1) + a - 1 - r * cols) + 1] = e
    for r in range(rows - 1):
        for c in range(cols - 1):
            k = r * cols + c
            top = broken(cloth, k)
            bottom = broken(cloth, k + cols)
            left = broken(cloth, n + k)
            right = broken(cloth, n + k + 1)
            count = (1 if top else 0) + (1 if bottom else 0) + (1 if left else 0) + (1 if right else 0)
            if count < 2:
                continue
            cell = 2 * (r * (cols - 1) + c)
            # The diagonal from the top-left corner joins the corners cut off by top and left,
            # or by bottom and right; the other, top and right or bottom and left.
            main = count > 2 or (top and bottom) or (left and right) or (top and left) or \
                (bottom and right)
            anti = count > 2 or (top and bottom) or (left and right) or (top and right) or \
                (bottom and left)
            if main and d[cell] >= 0:
                cloth.rest[d[cell]] = -1.0
            if anti and d[cell + 1] >= 0:
                cloth.rest[d[cell + 1]] = -1.0


def broken(cloth, s):
    """Whether structural slot s has no edge, or its edge is marked broken."""
    e = cloth.tear_e[s]
    return e < 0 or cloth.rest[e] < 0.0
