"""Continuous collision: how the cloth moves while an obstacle is near, so that no edge of it is
ever inside one. A vertex moving from P0 to P1 while its neighbours stay sweeps each of its
edges over the triangle between the neighbour and its path; the move crosses no obstacle iff
every such triangle is clear of every obstacle (geometry.clear), and a move that is not goes
only the largest half, quarter, ... of its way that is (move_clear). Every solver moves the
cloth by these rules when the scene has obstacles (cloth/obstacles.py, cloth/vbd.py), so a
hand, a flick, a fast fall or a coarse correction can carry no edge through an obstacle,
however far it moves in a step.

An edge already through an obstacle when a step begins (a scene or a pin put it there) is left
out of the rules and of the contact until it is out (mark_through); a vertex inside one is
pushed out (contact.push_out).
"""

from math import sqrt

from cloth.host import f64, i32
from cloth.geometry import distance, clear

# The contact's reach (m): a fabric's thickness. The barrier (cloth/contact.py) acts within
# it, and every obstacle's box is grown by it to find what may be near. Far below a pixel of
# any preset's view, and far above rounding at any coordinate the scene format allows.
CONTACT_GAP = 1e-3
# A move that would cross an obstacle (or, in a solver's descent, raise G) is halved up to
# this many times (to 1/4096 of itself), then not taken.
HALVINGS = 12


def prepare(cloth):
    """The arrays of the moves (once per cloth with obstacles)."""
    if len(cloth.ring) == 4:
        return
    cloth.through = i32(len(cloth.edge_a))  # 1: an edge already through an obstacle
    cloth.inside = i32(cloth.n_verts)       # 1: a free vertex inside an obstacle
    cloth.ring = f64(4)
    cloth.geo = f64(4)
    cloth.zone = i32(cloth.n_verts)         # zone: 1 where a move is tested
    cloth.zone_list = i32(cloth.n_verts)
    cloth.anchor = f64(2 * cloth.n_verts)   # and where each vertex's leash is tied
    # A leash of half a spacing (and a few contact reaches on a grid finer than that).
    cloth.leash = 0.5 * cloth.spacing if cloth.spacing > 16.0 * CONTACT_GAP else 8.0 * CONTACT_GAP


def meets(cloth, j, lox, hix, loy, hiy):
    """Whether the box [lox, hix] x [loy, hiy] meets obstacle j's, grown by CONTACT_GAP."""
    b = cloth.obstacle_bounds
    o = 4 * j
    return not (hix < b[o] or lox > b[o + 1] or hiy < b[o + 2] or loy > b[o + 3])


def bounds(cloth):
    """Each obstacle's box where it is (`at`), grown by CONTACT_GAP: obstacle_bounds."""
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    b = cloth.obstacle_bounds
    for j in range(cloth.n_obstacles):
        jj = j + j
        b[4 * j] = at[jj] - half[jj] - CONTACT_GAP
        b[4 * j + 1] = at[jj] + half[jj] + CONTACT_GAP
        b[4 * j + 2] = at[jj + 1] - half[jj + 1] - CONTACT_GAP
        b[4 * j + 3] = at[jj + 1] + half[jj + 1] + CONTACT_GAP


def zone(cloth):
    """Before a step with obstacles (obstacles.advance, with obstacle_bounds the boxes they
    sweep in the step): anchor each vertex where it is, and list (zone, zone_list) those whose
    box grown by the longest edge and the step's leash meets an obstacle's. While every vertex
    stays within the leash of its anchor (per axis), an edge of a vertex out of the zone stays
    out of every obstacle's reach (both its ends do, and a segment is convex), so such a
    vertex's moves need no test, and the contact's terms need only the zone (most of a towel,
    far below its peg, is out of it). The leash: cloth.leash, and twice the way the fastest
    vertex goes in the step at its speed. The first move beyond a leash lets every leash go
    for the rest of the step (cloth.loose)."""
    pos = cloth.pos
    vel = cloth.vel
    anchor = cloth.anchor
    longest = 0.0
    for e in range(cloth.n_edges):
        a = cloth.edge_a[e] + cloth.edge_a[e]
        b = cloth.edge_b[e] + cloth.edge_b[e]
        dx = pos[b] - pos[a]
        dy = pos[b + 1] - pos[a + 1]
        if dx * dx + dy * dy > longest:
            longest = dx * dx + dy * dy
    fastest = 0.0
    for k in range(cloth.n_verts):
        v2 = vel[k + k] * vel[k + k] + vel[k + k + 1] * vel[k + k + 1]
        if v2 > fastest:
            fastest = v2
    cloth.leash_now = cloth.leash + 2.0 * cloth.h * sqrt(fastest)
    reach = sqrt(longest) + cloth.leash_now
    count = 0
    for i in range(cloth.n_verts):
        ii = i + i
        x = pos[ii]
        y = pos[ii + 1]
        anchor[ii] = x
        anchor[ii + 1] = y
        cloth.zone[i] = 0
        for o in range(cloth.n_obstacles):
            if meets(cloth, o, x - reach, x + reach, y - reach, y + reach):
                cloth.zone[i] = 1
                cloth.zone_list[count] = i
                count += 1
                break
    cloth.n_zone = count
    cloth.loose = 0


def zone_size(cloth):
    """How many vertices the contact's loops visit: the zone's, or all once loose."""
    return cloth.n_verts if cloth.loose != 0 else cloth.n_zone


def zone_vertex(cloth, k):
    """The k-th of them."""
    return k if cloth.loose != 0 else cloth.zone_list[k]


def zone_edge(cloth, i, q):
    """Whether the contact's loops over the zone's vertices take the edge at i's adjacency
    slot q here: once, from its lower end (or from i if its other end is out of the zone)."""
    j = cloth.adj_other[q]
    return i < j or (cloth.loose == 0 and cloth.zone[j] == 0)


def on_leash(cloth, i, x, y):
    """Whether vertex i may go to (x, y) with no test (zone): it is out of the zone and (x, y)
    within the leash of its anchor; a move beyond it lets every leash go (cloth.loose)."""
    if cloth.loose != 0 or cloth.zone[i] != 0:
        return False
    dx = x - cloth.anchor[i + i]
    dy = y - cloth.anchor[i + i + 1]
    reach = cloth.leash_now
    if dx <= reach and dx >= -reach and dy <= reach and dy >= -reach:
        return True
    cloth.loose = 1
    return False


def ring_near(cloth, i, x, y):
    """Whether vertex i, at (x, y) or where it is, or an edge of it may be within CONTACT_GAP of
    an obstacle: it is not on its leash (zone), and the box round them and its neighbours
    (cloth.ring) meets an obstacle's."""
    pos = cloth.pos
    ii = i + i
    if on_leash(cloth, i, x, y) and on_leash(cloth, i, pos[ii], pos[ii + 1]):
        return False
    lox = pos[ii] if pos[ii] < x else x
    hix = pos[ii] if pos[ii] > x else x
    loy = pos[ii + 1] if pos[ii + 1] < y else y
    hiy = pos[ii + 1] if pos[ii + 1] > y else y
    other = cloth.adj_other
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        j = other[q] + other[q]
        if pos[j] < lox:
            lox = pos[j]
        elif pos[j] > hix:
            hix = pos[j]
        if pos[j + 1] < loy:
            loy = pos[j + 1]
        elif pos[j + 1] > hiy:
            hiy = pos[j + 1]
    r = cloth.ring
    r[0] = lox
    r[1] = hix
    r[2] = loy
    r[3] = hiy
    for j in range(cloth.n_obstacles):
        if meets(cloth, j, lox, hix, loy, hiy):
            return True
    return False


def clearance(cloth, i):
    """How far vertex i's edges (or the vertex, if it has none) are from the nearest obstacle
    within its ring's box (ring_near must have filled cloth.ring; CONTACT_GAP if none is
    nearer)."""
    pos = cloth.pos
    g = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    other = cloth.adj_other
    start = cloth.adj_start[i]
    end = cloth.adj_start[i + 1]
    x = pos[i + i]
    y = pos[i + i + 1]
    r = cloth.ring
    least = CONTACT_GAP
    for o in range(cloth.n_obstacles):
        if not meets(cloth, o, r[0], r[1], r[2], r[3]):
            continue
        oo = o + o
        for q in range(start, end + 1):
            j = i
            if q < end:
                if cloth.through[cloth.adj_edge[q]] != 0:
                    continue
                j = other[q]
            elif start != end:
                continue
            distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y,
                     pos[j + j], pos[j + j + 1], g)
            if g[0] < least:
                least = g[0]
    return least


def path_clear(cloth, i, x0, y0, x1, y1, margin):
    """Whether vertex i may go from (x0, y0) to (x1, y1) with the rest where it is: every edge
    of it sweeps a triangle at least `margin` from every obstacle (the vertex's own path, if it
    has no edge), so it ends no nearer than that either (ring_near must have filled cloth.ring
    for this move)."""
    pos = cloth.pos
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    shape = cloth.obstacle_shape
    other = cloth.adj_other
    start = cloth.adj_start[i]
    end = cloth.adj_start[i + 1]
    r = cloth.ring
    for o in range(cloth.n_obstacles):
        if not meets(cloth, o, r[0], r[1], r[2], r[3]):
            continue
        oo = o + o
        cx = at[oo]
        cy = at[oo + 1]
        hx = half[oo] + margin
        hy = half[oo + 1] + margin
        if start == end or cloth.inside[i] != 0:
            if cloth.inside[i] == 0 and not clear(shape[o], cx, cy, hx, hy, x0, y0, x0, y0, x1, y1):
                return False
            continue
        for q in range(start, end):
            if cloth.through[cloth.adj_edge[q]] != 0:
                continue
            j = other[q] + other[q]
            if not clear(shape[o], cx, cy, hx, hy, pos[j], pos[j + 1], x0, y0, x1, y1):
                return False
    return True


def margin_of(cloth, i):
    """How near an obstacle a move of vertex i may take its edges: a quarter of how near they
    are, and no nearer than a quarter of the barrier's reach unless they are already (a
    quarter: where the barrier alone, without a hand's push, holds the cloth's weight; the barrier's
    curvature grows as 1 / d^3: a move left unchecked to a hair from an obstacle, which a first
    guess or a coarse correction is, made a 2x2 step's determinant cancel to 0)."""
    m = 0.25 * clearance(cloth, i)
    return m if m < 0.25 * CONTACT_GAP else 0.25 * CONTACT_GAP


def move_clear(cloth, i, x, y):
    """Vertex i toward (x, y): all the way if its edges sweep no obstacle (nor come nearer one
    than margin_of), else the largest half, quarter, ... of the way that they do not (none
    after HALVINGS)."""
    pos = cloth.pos
    ii = i + i
    x0 = pos[ii]
    y0 = pos[ii + 1]
    if not ring_near(cloth, i, x, y):
        pos[ii] = x
        pos[ii + 1] = y
        return
    margin = margin_of(cloth, i)
    f = 1.0
    for k in range(HALVINGS):
        px = x0 + f * (x - x0)
        py = y0 + f * (y - y0)
        if path_clear(cloth, i, x0, y0, px, py, margin):
            pos[ii] = px
            pos[ii + 1] = py
            return
        f *= 0.5


def mark_through(cloth):
    """cloth.through: the edges that meet an obstacle where the cloth is now (a scene or a pin
    put them there; moves keep every other edge out), left out of the contact until they are
    out; cloth.inside: the free vertices inside an obstacle, pushed out (push_out). Only the
    zone's can be (zone)."""
    pos = cloth.pos
    g = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for e in range(cloth.n_edges):
        cloth.through[e] = 0
    for k in range(cloth.n_verts):
        cloth.inside[k] = 0
    for z in range(zone_size(cloth)):
        i = zone_vertex(cloth, z)
        xa = pos[i + i]
        ya = pos[i + i + 1]
        for o in range(cloth.n_obstacles):
            if cloth.fixed[i] != 0 or not meets(cloth, o, xa, xa, ya, ya):
                continue
            oo = o + o
            distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], xa, ya, xa, ya, g)
            if g[0] <= 0.0:
                cloth.inside[i] = 1
                break
        for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
            if not zone_edge(cloth, i, q):
                continue
            j = cloth.adj_other[q]
            xb = pos[j + j]
            yb = pos[j + j + 1]
            for o in range(cloth.n_obstacles):
                if not meets(cloth, o, xa if xa < xb else xb, xa if xa > xb else xb,
                             ya if ya < yb else yb, ya if ya > yb else yb):
                    continue
                oo = o + o
                distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], xa, ya, xb, yb, g)
                if g[0] <= 0.0:
                    cloth.through[cloth.adj_edge[q]] = 1
                    break


def near_pieces(cloth, near):
    """near[p] = 1 for each piece p that may come within CONTACT_GAP of an obstacle in the
    step: one of its free vertices, or a point of an edge with a free end other than a fixed
    end, is nearer one (grown by how far the obstacle goes in the step: obstacle_bounds) than
    the distance its velocity carries it in the step. Only the zone's can (zone). Returns
    whether any piece is."""
    pos = cloth.pos
    vel = cloth.vel
    g = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    fixed = cloth.fixed
    h = cloth.h
    for p in range(cloth.n_pieces):
        near[p] = 0
    found = False
    for z in range(zone_size(cloth)):
        a = zone_vertex(cloth, z)
        for q in range(cloth.adj_start[a], cloth.adj_start[a + 1] + 1):
            b = a
            if q < cloth.adj_start[a + 1]:
                if not zone_edge(cloth, a, q):
                    continue
                b = cloth.adj_other[q]
            if (fixed[a] != 0 and fixed[b] != 0) or near[cloth.piece[a]] != 0:
                continue
            reach = CONTACT_GAP + h * (speed(vel, a) if speed(vel, a) > speed(vel, b) else speed(vel, b))
            xa = pos[a + a]
            ya = pos[a + a + 1]
            xb = pos[b + b]
            yb = pos[b + b + 1]
            lox = (xa if xa < xb else xb) - reach
            hix = (xa if xa > xb else xb) + reach
            loy = (ya if ya < yb else yb) - reach
            hiy = (ya if ya > yb else yb) + reach
            for o in range(cloth.n_obstacles):
                if not meets(cloth, o, lox, hix, loy, hiy):
                    continue
                oo = o + o
                distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], xa, ya, xb, yb, g)
                # Nearest at a fixed end: that end's distance, which no step changes.
                if g[0] < reach and not ((g[1] == 0.0 and fixed[a] != 0) or (g[1] == 1.0 and fixed[b] != 0)):
                    near[cloth.piece[a]] = 1
                    found = True
                    break
    return found


def speed(vel, k):
    vx = vel[k + k]
    vy = vel[k + k + 1]
    return sqrt(vx * vx + vy * vy)
