"""The membrane's edges, who touches whom, and what tearing and cutting take away.

Edges: the grid's structural edges (rest = spacing, stiffness = the fabric's stretch), then both
diagonals of every cell (rest = spacing sqrt 2, stiffness = the fabric's shear). Why both, and
why each pulls only when longer than at rest (cloth/vbd.py's energy): a net of structural edges
alone has no shear stiffness, and hung from two points its top row alone carries the weight,
with a strain that grows with the grid and no converged limit (measured on the exact statics:
the field changed 12% and then 19% per doubling of the grid; with both diagonals at 0.03 of
the stretch, 3.2% and then 1.1%). Diagonals that also resisted compression would fold cells
in a slack hang (an X-braced cell's mirror image has the same edge lengths: 2 folded cells at
30x30, 18 at 60x60); tension-only ones fold none, and a 2D cloth under compression wrinkles out
of its plane at almost no energy anyway. The structural edges come first (n_struct of them):
they are what the seed's method relaxes and what the page draws and colours.

Stiffness and mass follow the area each edge and vertex stands for: a structural edge on the
border of a grid of two or more rows and columns stands for the half cell inside it (half the
stretch), as a border vertex weighs half a cell (cloth/step.py set_masses); the border's hem
(cloth/fabrics.py) adds its line stiffness there. A grid of one row or column is a strip one
spacing wide: its edges keep the whole stretch and have no hem.

Each edge knows the slot of its far end in its near end's 9-point stencil (multigrid.py), and
the adjacency lists (CSR) give each vertex its edges for the sweeps.
"""

import math

from cloth.host import f64, i32
from cloth.fabrics import HEM_LAYERS, HEM_WIDTH


def count_edges(cols, rows):
    """[structural edges, all edges] of an intact cols x rows grid."""
    s = (cols - 1) * rows + cols * (rows - 1)
    return [s, s + 2 * (cols - 1) * (rows - 1)]


def build(cloth, stretch, shear):
    cols = cloth.cols
    rows = cloth.rows
    h = cloth.spacing
    counts = count_edges(cols, rows)
    m = counts[1]
    cloth.n_struct = counts[0]
    cloth.n_edges = m
    cloth.edge_a = i32(m)
    cloth.edge_b = i32(m)
    cloth.rest = f64(m)
    cloth.stiff = f64(m)
    cloth.slot = i32(m)
    e = 0
    for r in range(rows):
        for c in range(cols):
            k = r * cols + c
            if c + 1 < cols:
                e = set_edge(cloth, e, k, k + 1, h, 0.0, 5)
            if r + 1 < rows:
                e = set_edge(cloth, e, k, k + cols, h, 0.0, 7)
    diagonal = h * math.sqrt(2.0)
    for r in range(rows - 1):
        for c in range(cols - 1):
            k = r * cols + c
            e = set_edge(cloth, e, k, k + cols + 1, diagonal, 0.0, 8)
            e = set_edge(cloth, e, k + 1, k + cols, diagonal, 0.0, 6)
    n = cloth.n_verts
    cloth.degree = i32(n)           # structural edges at each vertex (the seed's stress mean)
    cloth.adj_start = i32(n + 1)
    cloth.adj_fill = i32(n)
    cloth.adj_other = i32(2 * m)
    cloth.adj_edge = i32(2 * m)
    cloth.adj_rest = f64(2 * m)
    cloth.adj_k = f64(2 * m)
    restiffen(cloth, stretch, shear)


def set_edge(cloth, e, a, b, rest, k, slot):
    cloth.edge_a[e] = a
    cloth.edge_b[e] = b
    cloth.rest[e] = rest
    cloth.stiff[e] = k
    cloth.slot[e] = slot
    return e + 1


def restiffen(cloth, stretch, shear):
    """The fabric's stiffness on the edges there are: the shear on the diagonals, the stretch
    on the structural edges, half of it and the hem's line stiffness over the spacing on the
    border's."""
    hem = HEM_LAYERS * HEM_WIDTH / cloth.spacing
    for e in range(cloth.n_edges):
        if e >= cloth.n_struct:
            cloth.stiff[e] = shear
        elif along_border(cloth, cloth.edge_a[e], cloth.edge_b[e]):
            cloth.stiff[e] = stretch * (0.5 + hem)
        else:
            cloth.stiff[e] = stretch
    adjacency(cloth)


def along_border(cloth, a, b):
    """Whether the structural edge a-b lies along the border of a grid of two or more rows and
    columns (in its top or bottom row, or its first or last column)."""
    if cloth.rows < 2 or cloth.cols < 2:
        return False
    ra = a // cloth.cols
    rb = b // cloth.cols
    if ra == rb:
        return ra == 0 or ra == cloth.rows - 1
    ca = a - ra * cloth.cols
    return ca == b - rb * cloth.cols and (ca == 0 or ca == cloth.cols - 1)


def on_border(cloth, k):
    """Whether vertex k is on the border of a grid of two or more rows and columns."""
    if cloth.rows < 2 or cloth.cols < 2:
        return False
    r = k // cloth.cols
    c = k - r * cloth.cols
    return r == 0 or r == cloth.rows - 1 or c == 0 or c == cloth.cols - 1


def adjacency(cloth):
    """degree[] and the CSR lists (adj_start, adj_other, adj_edge, adj_rest, adj_k) of the edges there
    are now, in the arrays made for the whole grid (edges only ever go)."""
    n = cloth.n_verts
    m = cloth.n_edges
    start = cloth.adj_start
    fill = cloth.adj_fill
    degree = cloth.degree
    for k in range(n):
        fill[k] = 0
        degree[k] = 0
    for e in range(m):
        fill[cloth.edge_a[e]] += 1
        fill[cloth.edge_b[e]] += 1
        if e < cloth.n_struct:
            degree[cloth.edge_a[e]] += 1
            degree[cloth.edge_b[e]] += 1
    start[0] = 0
    for k in range(n):
        start[k + 1] = start[k] + fill[k]
        fill[k] = 0
    for e in range(m):
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        q = start[a] + fill[a]
        fill[a] += 1
        cloth.adj_other[q] = b
        cloth.adj_edge[q] = e
        cloth.adj_rest[q] = cloth.rest[e]
        cloth.adj_k[q] = cloth.stiff[e]
        q = start[b] + fill[b]
        fill[b] += 1
        cloth.adj_other[q] = a
        cloth.adj_edge[q] = e
        cloth.adj_rest[q] = cloth.rest[e]
        cloth.adj_k[q] = cloth.stiff[e]


def mark_crossed(pos, edge_a, edge_b, rest, m, px, py, qx, qy):
    """Mark (rest = -1) every edge whose segment crosses the blade P -> Q, where the cloth is
    now; returns how many. Crossing is decided by the signs of four orientations (exact
    + - * on the same doubles in both runtimes): the edge's ends strictly on either side of the
    blade's line, and the blade's ends on either side of the edge's line, or one on it (a blade
    that stops on an edge cuts it). So an edge that only touches the blade, or lies along it,
    is not crossed, and a blade of no length crosses nothing."""
    ux = qx - px
    uy = qy - py
    count = 0
    for e in range(m):
        ia = edge_a[e] + edge_a[e]
        ib = edge_b[e] + edge_b[e]
        ax = pos[ia]
        ay = pos[ia + 1]
        bx = pos[ib]
        by = pos[ib + 1]
        d1 = ux * (ay - py) - uy * (ax - px)
        d2 = ux * (by - py) - uy * (bx - px)
        if not ((d1 > 0.0 and d2 < 0.0) or (d1 < 0.0 and d2 > 0.0)):
            continue
        vx = bx - ax
        vy = by - ay
        d3 = vx * (py - ay) - vy * (px - ax)
        d4 = vx * (qy - ay) - vy * (qx - ax)
        if (d3 > 0.0 and d4 > 0.0) or (d3 < 0.0 and d4 < 0.0):
            continue
        rest[e] = -1.0
        count += 1
    return count


def remove_marked(cloth):
    """Remove the edges marked broken (rest < 0), keeping the others in their order (the
    structural ones first), and rebuild the adjacency. Returns how many went."""
    m = cloth.n_edges
    kept = 0
    struct = 0
    for e in range(m):
        if cloth.rest[e] < 0.0:
            continue
        if e < cloth.n_struct:
            struct += 1
        cloth.edge_a[kept] = cloth.edge_a[e]
        cloth.edge_b[kept] = cloth.edge_b[e]
        cloth.rest[kept] = cloth.rest[e]
        cloth.stiff[kept] = cloth.stiff[e]
        cloth.slot[kept] = cloth.slot[e]
        kept += 1
    cloth.n_struct = struct
    cloth.n_edges = kept
    adjacency(cloth)
    return m - kept


def walk_grip(cloth, k, radius, dist, found):
    """The vertices within `radius` of k along the edges (shortest paths, so a grip never
    reaches across a cut), listed in `found`; returns how many. `dist` is -1 everywhere on
    entry and is left so."""
    dist[k] = 0.0
    found[0] = k
    count = 1
    i = 0
    start = cloth.adj_start
    while i < count:
        v = found[i]
        i += 1
        for q in range(start[v], start[v + 1]):
            u = cloth.adj_other[q]
            d = dist[v] + cloth.adj_rest[q]
            if d <= radius and (dist[u] < 0.0 or d < dist[u]):
                if dist[u] < 0.0:
                    found[count] = u
                    count += 1
                dist[u] = d
    for j in range(count):
        dist[found[j]] = -1.0
    return count


def label_pieces(cloth):
    """cloth.piece[k]: the connected piece k belongs to (0, 1, ... in order of their lowest
    vertex), over the edges there are now; returns how many pieces."""
    n = cloth.n_verts
    piece = cloth.piece
    stack = cloth.stack
    start = cloth.adj_start
    other = cloth.adj_other
    for k in range(n):
        piece[k] = -1
    count = 0
    for k in range(n):
        if piece[k] >= 0:
            continue
        piece[k] = count
        top = 0
        stack[0] = k
        top = 1
        while top > 0:
            top -= 1
            v = stack[top]
            for q in range(start[v], start[v + 1]):
                u = other[q]
                if piece[u] < 0:
                    piece[u] = count
                    stack[top] = u
                    top += 1
        count += 1
    return count
