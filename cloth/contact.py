"""Contact with the obstacles, inside the step's energy: a barrier that keeps every edge of the
cloth out of every obstacle and friction along them, terms of G (cloth/terms.py) with their
force and 2x2 block; and the rule every solver moves the cloth by while an obstacle is near it:
a vertex goes only as far as its edges sweep no obstacle (continuous collision: each edge of
the vertex sweeps the triangle between its other end and the vertex's path, cloth/geometry.py),
so no edge of the cloth is ever inside an obstacle, whatever a hand, a flick or a drag does.

The barrier (after IPC: Li et al., "Incremental Potential Contact", SIGGRAPH 2020; a rational
function in place of its logarithm, whose last bits differ between the runtimes): an edge, or
a vertex left with no edge, at a distance d from an obstacle adds
    b(d) = kappa (g - d)^3 / (d g)      for 0 < d < g = CONTACT_GAP, 0 beyond, infinite at 0,
twice differentiable at g, convex and unbounded as d -> 0: no finite force brings the cloth to
an obstacle, so a hand (20 N) cannot pull it through one. Its pairs are IPC's: each vertex
against each obstacle, and each edge against each obstacle's point features (a circle's centre,
its radius away; a box's corners), whose distances are continuously differentiable where they
are positive (taking an edge's nearest point to a box's flat side instead, a strip lying on it
had its weight on one end of each edge and then the other, and never balanced). An edge's
gradient at its ends is b'(d) (1 - s) u and b'(d) s u (s: its nearest point's place along it,
u: the direction from the feature to it), its block the Gauss-Newton b''(d) (1 - s)^2 u u^T
(the distance's own curvature, of the wrong sign for a descent, left out). kappa: the
barrier's curvature halfway in, b''(g / 2) = 14 kappa / g, is the fabric's stretch stiffness,
so that a vertex's Newton step against an obstacle is conditioned as against a spring of the
fabric; the cloth's weight rests most of the way out (a strip over a peg 5 times thinner than
its spacing, its weight on two edges, 0.3 mm from it; with kappa the weight of an edge's ends,
0.02 mm, and the sweeps left its balance 160 weights off).

Friction (IPC's lagged form): a vertex the barrier pushed with a force lambda along n where
the step began resists sliding along the tangent t, relative to the obstacle, by
    D(x) = mu lambda f0(|t . (x - x_n - o)|)    (x_n where it began, o the obstacle's move)
f0 being |.| rounded within eps = FRICTION_SLIP h (f0(y) = -y^3 / (3 eps^2) + y^2 / eps + eps / 3
there): static within eps, a tangential spring of stiffness 2 mu lambda / eps about where the
step began, and beyond it a force of mu lambda against the slide. Convex; its block is the
secant mu lambda f0'(y) / y t t^T, a majoriser of its curvature.
"""

from math import sqrt

from cloth.host import f64, i32
from cloth.geometry import point, corner, corners
from cloth.multigrid import DIAG
from cloth.ccd import CONTACT_GAP, meets, ring_near, zone_size, zone_vertex
from cloth import ccd

# Friction's creep (m/s): within this speed of the obstacle a contact holds as static friction.
FRICTION_SLIP = 1e-3
# A pin this close to an obstacle is fastened to it: it moves with the obstacle (a towel's
# clamp on its peg). Twice the barrier's reach.
FASTEN = 2.0 * CONTACT_GAP
# G where an edge would be at or inside an obstacle.
BLOCKED = 1e300


def prepare(cloth):
    """The contact's arrays (once per cloth: an obstacle's scene has them all its life)."""
    n = cloth.n_verts
    if cloth.n_obstacles == 0 or len(cloth.guess) == 2 * n:
        return
    cloth.guess = f64(2 * n)        # the solver's first guess, while the start is made clear
    cloth.start_pos = f64(2 * n)    # where the solve started (accept)
    cloth.carry_from = f64(2 * n)   # where an obstacle's push started (obstacles.carry)
    cloth.carried = f64(n)          # how much of an obstacle's move a vertex goes with
    cloth.fric_w = f64(n)           # friction: mu lambda, the tangent, the obstacle
    cloth.fric_t = f64(2 * n)
    cloth.fric_o = i32(n)
    cloth.fastened = i32(n)         # a pin's obstacle + 1 (0: none)
    cloth.near_piece = i32(n)       # per piece: 1 if an obstacle may be near it (advance)
    cloth.pressed = i32(n)          # 1: the barrier pushes it and no spring pulls it
    cloth.bar = f64(4)
    cloth.sum = f64(4)
    ccd.prepare(cloth)


def barrier(d, kappa, b):
    """b[0..2] = b(d), b'(d), b''(d) for 0 < d < CONTACT_GAP (the module's comment)."""
    g = CONTACT_GAP
    u = g - d
    b[0] = kappa * u * u * u / (d * g)
    b[1] = -kappa * u * u * (2.0 * d + g) / (d * d * g)
    b[2] = kappa / g * (6.0 * u / d + 2.0 * u * u * (2.0 * d + g) / (d * d * d))


def friction(y, eps, b):
    """b[0..2] = f0(y), f0'(y), f0'(y) / y for y >= 0 (the module's comment)."""
    if y >= eps:
        b[0] = y
        b[1] = 1.0
        b[2] = 1.0 / y
        return
    b[0] = -y * y * y / (3.0 * eps * eps) + y * y / eps + eps / 3.0
    b[1] = -y * y / (eps * eps) + 2.0 * y / eps
    b[2] = -y / (eps * eps) + 2.0 / eps


def point_terms(cloth, i, x, y, only, acc):
    """acc[0..4] += vertex i's own barrier at (x, y) against every obstacle near it (obstacle
    `only` alone, if it is not -1). A vertex that began the step inside an
    obstacle is pushed out instead (push_out)."""
    if cloth.inside[i] != 0:
        push_out(cloth, i, x, y, acc)
        return
    g = cloth.geo
    b = cloth.bar
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    kappa = cloth.kappa
    for o in range(cloth.n_obstacles):
        if (only >= 0 and o != only) or not meets(cloth, o, x, x, y, y):
            continue
        oo = o + o
        point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, g)
        d = g[0]
        if d >= CONTACT_GAP or d <= 0.0:
            continue
        barrier(d, kappa, b)
        add_force(acc, -b[1], b[2], g[2], g[3])


def edge_terms(cloth, i, xi, yi, j, xj, yj, only, acc):
    """acc[0..4] += the barrier at vertex i, at (xi, yi), of its edge to vertex j at (xj, yj)
    against the point features (geometry.corner) of every obstacle near it (obstacle `only`
    alone, if it is not -1)."""
    g = cloth.geo
    b = cloth.bar
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    kappa = cloth.kappa
    lox = xi if xi < xj else xj
    hix = xi if xi > xj else xj
    loy = yi if yi < yj else yj
    hiy = yi if yi > yj else yj
    for o in range(cloth.n_obstacles):
        if (only >= 0 and o != only) or not meets(cloth, o, lox, hix, loy, hiy):
            continue
        oo = o + o
        shape = cloth.obstacle_shape[o]
        for c in range(corners(shape)):
            corner(shape, at[oo], at[oo + 1], half[oo], half[oo + 1], c, xi, yi, xj, yj, g)
            d = g[0]
            if d >= CONTACT_GAP or d <= 0.0:
                continue
            barrier(d, kappa, b)
            w = 1.0 - g[1]
            add_force(acc, -b[1] * w, b[2] * w * w, g[2], g[3])


def add_force(acc, f, k, ux, uy):
    """acc[0..4] += a force f along u and a block k u u^T."""
    acc[0] += f * ux
    acc[1] += f * uy
    acc[2] += k * ux * ux
    acc[3] += k * ux * uy
    acc[4] += k * uy * uy


def vertex_terms(cloth, i, acc):
    """acc[0..4] += the contact's force and block at vertex i where the cloth is now: its own
    barrier, its edges' (each edge's share at i), and its friction."""
    pos = cloth.pos
    ii = i + i
    xi = pos[ii]
    yi = pos[ii + 1]
    point_terms(cloth, i, xi, yi, -1, acc)
    other = cloth.adj_other
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        if cloth.through[cloth.adj_edge[q]] != 0:
            continue
        j = other[q]
        edge_terms(cloth, i, xi, yi, j, pos[j + j], pos[j + j + 1], -1, acc)
    friction_terms(cloth, i, xi, yi, acc)


def friction_terms(cloth, i, xi, yi, acc):
    """acc[0..4] += vertex i's friction at (xi, yi) (the module's comment)."""
    fw = cloth.fric_w[i]
    if fw <= 0.0:
        return
    ii = i + i
    b = cloth.bar
    tx = cloth.fric_t[ii]
    ty = cloth.fric_t[ii + 1]
    oo = cloth.fric_o[i] * 2
    y = tx * (xi - cloth.prev[ii] - cloth.obstacle_moved[oo]) + \
        ty * (yi - cloth.prev[ii + 1] - cloth.obstacle_moved[oo + 1])
    sign = 1.0
    if y < 0.0:
        sign = -1.0
        y = -y
    friction(y, FRICTION_SLIP * cloth.h, b)
    add_force(acc, -fw * b[1] * sign, fw * b[2], tx, ty)


def push_out(cloth, i, x, y, acc):
    """A free vertex that began the step inside an obstacle (a scene put it there, or a pin
    let go there) is pushed out of the nearest side by a spring of its own inertia's stiffness
    to CONTACT_GAP outside: its edges, through the obstacle, hold no barrier until it is out."""
    g = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    w = cloth.mass[i] * cloth.w_scale
    for o in range(cloth.n_obstacles):
        oo = o + o
        point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, g)
        if g[0] < CONTACT_GAP:
            add_force(acc, w * (CONTACT_GAP - g[0]), w, g[2], g[3])


def point_energy(cloth, i, x, y):
    """point_terms' energy with vertex i at (x, y) (BLOCKED at or inside an obstacle)."""
    g = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    s = 0.0
    if cloth.inside[i] != 0:
        w = cloth.mass[i] * cloth.w_scale
        for o in range(cloth.n_obstacles):
            oo = o + o
            point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, g)
            if g[0] < CONTACT_GAP:
                s += 0.5 * w * (CONTACT_GAP - g[0]) * (CONTACT_GAP - g[0])
        return s
    b = cloth.bar
    kappa = cloth.kappa
    for o in range(cloth.n_obstacles):
        if not meets(cloth, o, x, x, y, y):
            continue
        oo = o + o
        point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, g)
        d = g[0]
        if d >= CONTACT_GAP:
            continue
        if d <= 0.0:
            return BLOCKED
        barrier(d, kappa, b)
        s += b[0]
    return s


def edge_energy(cloth, i, xi, yi, j, xj, yj):
    """edge_terms' energy of the edge i-j with its ends at these places (BLOCKED where it would
    meet an obstacle's point feature)."""
    g = cloth.geo
    b = cloth.bar
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    kappa = cloth.kappa
    lox = xi if xi < xj else xj
    hix = xi if xi > xj else xj
    loy = yi if yi < yj else yj
    hiy = yi if yi > yj else yj
    s = 0.0
    for o in range(cloth.n_obstacles):
        if not meets(cloth, o, lox, hix, loy, hiy):
            continue
        oo = o + o
        shape = cloth.obstacle_shape[o]
        for c in range(corners(shape)):
            corner(shape, at[oo], at[oo + 1], half[oo], half[oo + 1], c, xi, yi, xj, yj, g)
            d = g[0]
            if d >= CONTACT_GAP:
                continue
            if d <= 0.0:
                return BLOCKED
            barrier(d, kappa, b)
            s += b[0]
    return s


def friction_energy(cloth, i, x, y):
    """Vertex i's friction energy with it at (x, y)."""
    fw = cloth.fric_w[i]
    if fw <= 0.0:
        return 0.0
    ii = i + i
    oo = cloth.fric_o[i] * 2
    u = cloth.fric_t[ii] * (x - cloth.prev[ii] - cloth.obstacle_moved[oo]) + \
        cloth.fric_t[ii + 1] * (y - cloth.prev[ii + 1] - cloth.obstacle_moved[oo + 1])
    friction(u if u >= 0.0 else -u, FRICTION_SLIP * cloth.h, cloth.bar)
    return fw * cloth.bar[0]


def vertex_energy(cloth, i, x, y):
    """cloth.sum[0] = the contact's terms that hold vertex i, with it at (x, y) and the rest
    where they are (BLOCKED where it or an edge of it would meet an obstacle)."""
    pos = cloth.pos
    other = cloth.adj_other
    s = point_energy(cloth, i, x, y)
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        if cloth.through[cloth.adj_edge[q]] != 0:
            continue
        j = other[q]
        s += edge_energy(cloth, i, x, y, j, pos[j + j], pos[j + j + 1])
    cloth.sum[0] = s + friction_energy(cloth, i, x, y)


def lag_friction(cloth):
    """Each free vertex's friction for the step, from the barrier's push on it where the step
    begins (IPC's lagged friction): mu lambda summed over the obstacles that push it, the
    tangent to their whole push, and the obstacle that pushes hardest (whose move its slide is
    measured against). cloth.pressed: the vertices the barrier pushes and no spring pulls (a
    crumpled pile's: obstacles.correct_where). A piece with a vertex
    near an obstacle is marked (piece_touched 2: the energy's account moves it back only along
    clear paths, energy.fall_back)."""
    pos = cloth.pos
    acc = cloth.acc
    other = cloth.adj_other
    for i in range(cloth.n_verts):
        cloth.fric_w[i] = 0.0
        cloth.pressed[i] = 0
    for z in range(zone_size(cloth)):
        i = zone_vertex(cloth, z)
        if cloth.fixed[i] != 0 or not ring_near(cloth, i, pos[i + i], pos[i + i + 1]):
            continue
        if cloth.piece_touched[cloth.piece[i]] == 0:
            cloth.piece_touched[cloth.piece[i]] = 2
        xi = pos[i + i]
        yi = pos[i + i + 1]
        fx = 0.0
        fy = 0.0
        mu = 0.0
        best = 0.0
        for o in range(cloth.n_obstacles):
            acc[0] = 0.0
            acc[1] = 0.0
            if cloth.inside[i] == 0:
                point_terms(cloth, i, xi, yi, o, acc)
            for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
                if cloth.through[cloth.adj_edge[q]] != 0:
                    continue
                j = other[q]
                edge_terms(cloth, i, xi, yi, j, pos[j + j], pos[j + j + 1], o, acc)
            f = sqrt(acc[0] * acc[0] + acc[1] * acc[1])
            fx += acc[0]
            fy += acc[1]
            mu += cloth.obstacle_friction[o] * f
            if f > best:
                best = f
                cloth.fric_o[i] = o
        f = sqrt(fx * fx + fy * fy)
        if f > 0.0 and slack(cloth, i):
            cloth.pressed[i] = 1
        if f <= 0.0 or mu <= 0.0:
            continue
        cloth.fric_w[i] = mu
        cloth.fric_t[i + i] = -fy / f
        cloth.fric_t[i + i + 1] = fx / f


def slack(cloth, i):
    """Whether no spring of vertex i is longer than at rest."""
    pos = cloth.pos
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        j = cloth.adj_other[q]
        dx = pos[j + j] - pos[i + i]
        dy = pos[j + j + 1] - pos[i + i + 1]
        if dx * dx + dy * dy > cloth.adj_rest[q] * cloth.adj_rest[q]:
            return False
    return True


def assemble(cloth, g, A):
    """The contact's terms in G's gradient g and its Hessian A (terms.assemble adds them): each
    free vertex's own barrier and friction on its block, each edge's barrier on both its ends'
    blocks and the block between them."""
    pos = cloth.pos
    geo = cloth.geo
    b = cloth.bar
    acc = cloth.acc
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for z in range(zone_size(cloth)):
        i = zone_vertex(cloth, z)
        if cloth.fixed[i] != 0:
            continue
        acc[0] = 0.0
        acc[1] = 0.0
        acc[2] = 0.0
        acc[3] = 0.0
        acc[4] = 0.0
        point_terms(cloth, i, pos[i + i], pos[i + i + 1], -1, acc)
        friction_terms(cloth, i, pos[i + i], pos[i + i + 1], acc)
        g[i + i] -= acc[0]
        g[i + i + 1] -= acc[1]
        o = (i * 9 + DIAG) * 3
        A[o] += acc[2]
        A[o + 1] += acc[3]
        A[o + 2] += acc[4]
    for e in range(cloth.n_edges):
        if cloth.through[e] != 0 or (cloth.loose == 0 and cloth.zone[cloth.edge_a[e]] == 0):
            continue
        a = cloth.edge_a[e]
        c = cloth.edge_b[e]
        xa = pos[a + a]
        ya = pos[a + a + 1]
        xc = pos[c + c]
        yc = pos[c + c + 1]
        kappa = cloth.kappa
        for o in range(cloth.n_obstacles):
            if not meets(cloth, o, xa if xa < xc else xc, xa if xa > xc else xc,
                         ya if ya < yc else yc, ya if ya > yc else yc):
                continue
            oo = o + o
            shape = cloth.obstacle_shape[o]
            for f in range(corners(shape)):
                corner(shape, at[oo], at[oo + 1], half[oo], half[oo + 1], f, xa, ya, xc, yc, geo)
                d = geo[0]
                if d >= CONTACT_GAP or d <= 0.0:
                    continue
                barrier(d, kappa, b)
                wc = geo[1]
                wa = 1.0 - wc
                ux = geo[2]
                uy = geo[3]
                g[a + a] += b[1] * wa * ux
                g[a + a + 1] += b[1] * wa * uy
                g[c + c] += b[1] * wc * ux
                g[c + c + 1] += b[1] * wc * uy
                add_block(A, a, DIAG, b[2] * wa * wa, ux, uy)
                add_block(A, c, DIAG, b[2] * wc * wc, ux, uy)
                slot = cloth.slot[e]
                add_block(A, a, slot, b[2] * wa * wc, ux, uy)
                add_block(A, c, 8 - slot, b[2] * wa * wc, ux, uy)


def add_block(A, a, slot, k, ux, uy):
    """A's block of vertex a's stencil slot `slot` += k u u^T."""
    o = (a * 9 + slot) * 3
    A[o] += k * ux * ux
    A[o + 1] += k * ux * uy
    A[o + 2] += k * uy * uy


def energy_along(cloth, d):
    """cloth.sum[1] = the contact's terms of G at pos + alpha d, alpha = cloth.alpha (BLOCKED
    where the cloth would meet an obstacle), over the zone (ccd.zone: a correction that takes a
    vertex beyond its leash is tested where it is made, ccd.move_clear)."""
    pos = cloth.pos
    alpha = cloth.alpha
    s = 0.0
    for z in range(zone_size(cloth)):
        i = zone_vertex(cloth, z)
        if cloth.fixed[i] != 0:
            continue
        x = pos[i + i] + alpha * d[i + i]
        y = pos[i + i + 1] + alpha * d[i + i + 1]
        s += point_energy(cloth, i, x, y) + friction_energy(cloth, i, x, y)
        if s >= BLOCKED:
            cloth.sum[1] = BLOCKED
            return
    for e in range(cloth.n_edges):
        if cloth.through[e] != 0 or (cloth.loose == 0 and cloth.zone[cloth.edge_a[e]] == 0):
            continue
        a = cloth.edge_a[e]
        c = cloth.edge_b[e]
        s += edge_energy(cloth, a, pos[a + a] + alpha * d[a + a], pos[a + a + 1] + alpha * d[a + a + 1],
                         c, pos[c + c] + alpha * d[c + c], pos[c + c + 1] + alpha * d[c + c + 1])
        if s >= BLOCKED:
            cloth.sum[1] = BLOCKED
            return
    cloth.sum[1] = s


def barrier_by_piece(cloth, xs, out, stride, slot):
    """The barrier's energy of each piece p with the cloth at xs (pos, or the step's start
    prev), added to out[stride p + slot]: its free vertices' and its edges' terms over the zone
    (ccd.zone: out of it, a vertex and its edges are beyond the barrier's reach). The account of
    energy.py holds the barrier as what it is, a term of the cloth's potential."""
    piece = cloth.piece
    for z in range(zone_size(cloth)):
        i = zone_vertex(cloth, z)
        if cloth.fixed[i] != 0:
            continue
        out[stride * piece[i] + slot] += point_energy(cloth, i, xs[i + i], xs[i + i + 1])
    for e in range(cloth.n_edges):
        a = cloth.edge_a[e]
        if cloth.through[e] != 0 or (cloth.loose == 0 and cloth.zone[a] == 0):
            continue
        c = cloth.edge_b[e]
        out[stride * piece[a] + slot] += edge_energy(cloth, a, xs[a + a], xs[a + a + 1],
                                                     c, xs[c + c], xs[c + c + 1])
