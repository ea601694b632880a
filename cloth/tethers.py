"""Anchors for long-range tethers: for every vertex, the nearest pinned vertex along the cloth,
and the tether's length, the length of that shortest path over the edges.

"Nearest along the cloth" is the shortest path over the scene's edges weighted by rest
length (multi-source Dijkstra), so a vertex is tied to a pin it hangs from, not to one across a
cut. The length is that path, not the straight-line distance in the rest grid: a grid of
structural edges is a mechanism (every cell can shear into a rhombus), and its true hang puts
vertices farther from a pin than they lie in the flat grid. Measured on the slack two-corner
hang, the straight-line bound was broken by 87% of the vertices, by 17% on average, in the
exact equilibrium: such tethers pulled the cloth 13-15% of its width away from where the
physics hangs it, and walled a folded cloth in. The path length can never be exceeded without
stretching an edge, so these tethers only ever remove stretch; where the path is straight
(a curtain hanging below its pins) it is the straight distance and they are as tight as before.
Run only when the set of pins changes (pin, unpin), not per frame.
"""

import math

from cloth.host import f64, i32
from cloth.solve import K_SPACING


def find_anchors(n, adj_start, adj_vertex, adj_rest, pinned, anchor, tether):
    """Fill anchor[k] (the nearest pinned vertex along the edges, or -1 if none is reachable)
    and tether[k] (the rest length of the shortest path to it); Dijkstra with a binary heap
    of (distance, vertex) and lazy deletion. Pins only: a hand (sim.HAND_FORCE) is held back by
    the cloth, so it must not hold the cloth with tethers of its own."""
    total = adj_start[n] + n + 1
    heap_d = f64(total)
    heap_v = i32(total)
    size = 0
    for k in range(n):
        anchor[k] = -1
        tether[k] = 0.0
        if pinned[k] == 1:
            anchor[k] = k
            heap_d[size] = 0.0
            heap_v[size] = k
            size += 1
    # Every pin starts at distance 0, so the initial heap is already ordered.
    done = i32(n)
    while size > 0:
        d = heap_d[0]
        v = heap_v[0]
        size -= 1
        heap_d[0] = heap_d[size]
        heap_v[0] = heap_v[size]
        sift_down(heap_d, heap_v, size, 0)
        if done[v] == 1:
            continue
        done[v] = 1
        for j in range(adj_start[v], adj_start[v + 1]):
            u = adj_vertex[j]
            nd = d + adj_rest[j]
            if done[u] == 0 and (anchor[u] < 0 or nd < tether[u]):
                anchor[u] = anchor[v]
                tether[u] = nd
                heap_d[size] = nd
                heap_v[size] = u
                sift_up(heap_d, heap_v, size)
                size += 1


def list_fixed(inv_mass, n, fixed):
    """Fill fixed[] with the fixed vertices (pinned or held); return how many."""
    count = 0
    for k in range(n):
        if inv_mass[k] == 0.0:
            fixed[count] = k
            count += 1
    return count


def over_reach(pos, held, pinned, hands_give, fixed, n_fixed, cols, consts, intact, piece, out):
    """How far the hands have pulled the cloth beyond its reach (in out[0]): the largest ratio,
    at least 1, of a held vertex's distance from another fixed vertex to the two's rest
    distance. Only held vertices moved where the hand is count: all of them for the seed's
    method, held pins for the default (`hands_give`), whose other hands give way instead.

    The tethers are scaled by it while anything is held. Unscaled, a vertex pulled beyond
    reach leaves the vertices tied to it and those tied to the pins each within their own
    tethers, and all of the stretch gathers in the few edges where the two groups meet
    (measured: max strain 3.2 for a 0.3 m over-pull of a 1 m curtain, against 0.74 for the
    seed's method); scaled, the edges share it out as an untethered cloth would."""
    worst = 1.0
    spacing = consts[K_SPACING]
    h2 = spacing * spacing
    for j in range(n_fixed):            # a held vertex is fixed: it is in the list
        k = fixed[j]
        if held[k] == 0 or (hands_give and pinned[k] == 0):
            continue
        row = k // cols
        col = k % cols
        x = pos[k + k]
        y = pos[k + k + 1]
        for i in range(n_fixed):
            f = fixed[i]
            if f == k or (not intact and piece[f] != piece[k]):
                continue    # a fixed vertex of another piece is not in this one's reach
            dr = f // cols - row
            dc = f % cols - col
            rest2 = (dr * dr + dc * dc) * h2
            dx = pos[f + f] - x
            dy = pos[f + f + 1] - y
            d2 = dx * dx + dy * dy
            if d2 > worst * worst * rest2:
                worst = math.sqrt(d2 / rest2)
    out[0] = worst


def label_pieces(n, adj_start, adj_vertex, piece, stack):
    """piece[k]: the connected piece of vertex k over the remaining edges (numbered from 0 in
    vertex order); returns how many. A depth-first walk with an explicit stack."""
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
            for j in range(adj_start[v], adj_start[v + 1]):
                u = adj_vertex[j]
                if piece[u] < 0:
                    piece[u] = count
                    stack[top] = u
                    top += 1
        count += 1
    return count


def sift_up(heap_d, heap_v, i):
    while i > 0:
        parent = (i - 1) >> 1
        if heap_d[parent] <= heap_d[i]:
            return
        swap(heap_d, heap_v, i, parent)
        i = parent


def sift_down(heap_d, heap_v, size, i):
    while True:
        left = i + i + 1
        if left >= size:
            return
        child = left
        if left + 1 < size and heap_d[left + 1] < heap_d[left]:
            child = left + 1
        if heap_d[i] <= heap_d[child]:
            return
        swap(heap_d, heap_v, i, child)
        i = child


def swap(heap_d, heap_v, i, j):
    d = heap_d[i]
    heap_d[i] = heap_d[j]
    heap_d[j] = d
    v = heap_v[i]
    heap_v[i] = heap_v[j]
    heap_v[j] = v
