"""The default solver: vertex block descent on the step's energy, with a coarse-grid correction.

A step (cloth/integrate.py) is the minimum of the convex energy
    G(x) = sum_i w_i / 2 |x_i - pred_i|^2 + sum_e k_e / 2 (L_e - L0_e)_+^2 + sum_hands H(x)
over the free vertices: inertia, tension-only springs (cloth/topology.py) and hands
(cloth/hands.py). Each of its terms is convex: (L - L0)_+^2 / 2 is half the squared distance
of the edge vector to the disc of radius L0, and a hand's capped pull is a Huber function. So
the step has one answer, and any method that lowers G approaches it.

Vertex block descent (Chen, Macklin et al., "Vertex Block Descent", SIGGRAPH 2024) is the
seed's relaxation done on that energy: for each vertex in turn, one 2x2 Newton step on G with
its neighbours held, x_i += H_i^-1 f_i, with f_i = -dG/dx_i and
    H_i = w_i I + sum_e k (n n^T + (1 - L0/L)_+ (I - n n^T)) + a hand's k_h I.
Every spring's axial stiffness k n n^T is in H_i, even a slack spring's (whose force and true
curvature are 0): where a spring is about to pull, the true Hessian lacks it and the Newton
step overshoots into it (measured: cotton two corners never came to rest, and blew up at
60x60, when only springs longer than 0.8 L0 put it in); a larger H only shortens steps, and
the fixed point, where every f_i = 0, is the same.

Sweeps alternate forward and backward, starting forward every step: a fixed order leans the
answer one way, and a step that starts where the last one ended would flip the lean between
frames (measured: a 30 Hz limit cycle of 3 cm/s at a clamp's end).

Sweeps remove an error within a few vertices' reach only; the coarse-grid correction
(cloth/coarse.py) removes the smooth rest. Per step: iterations // 2 sweeps, the corrections (a
sweep between two), the other sweeps; while a hand holds the cloth, one more correction and
the sweeps over the vertices near it (NEAR_SWEEPS, below).
"""

import math

from cloth.host import f64, i32
from cloth.multigrid import hierarchy
from cloth.coarse import correct
from cloth.contact import vertex_terms
from cloth.ccd import HALVINGS, ring_near, path_clear, margin_of, move_clear
from cloth.terms import vertex, vertex_energy, inertia_weight
from cloth.hands import keep_up
from cloth import air

# Its steps are BDF2 (cloth/integrate.py), backward Euler after one left off balance.
ORDER = 2
# Its last sweep measures cloth.imbalance (sweep).
RESIDUAL = True
# Whether its sweeps minimise G with the contact's barrier in it (cloth/contact.py).
BARRIER = True
# A hand moved fast pulls the whole cloth a little and the cloth near it a lot, and the
# scene's budget leaves both behind on a fine grid: one correction a step carries part of the
# far field, and a sweep carries a change about one vertex onward, so the cells between the
# grip and the coarse grid's scale lag. While a hand holds, the step ends with one more
# correction and sweeps over the vertices within NEAR_RADIUS (rows and columns, in metres: the
# same patch of fabric at every grid): NEAR_SWEEPS, or NEAR_PER_REACH for each vertex of the
# window's reach where that is more (a sweep pair carries a change a vertex or two onward, and
# the reach grows with the grid: 30 vertices on a 200x200 towel). Measured in the page round a
# 40 px circle at 20 px a frame (tests/browser/test_input.py's path; the held vertex's worst lag
# behind the pointer, curtain / Two corners / towel at 120x120, then at 200x200):
#   nothing more                          2.9 / 6.1 / 5.5 px     5.6 / 6.4 / 7.5 px
#   40 sweeps over 0.10 m                 1.7 / 1.5 / 1.5
#   40 sweeps over 0.15 m                 1.5 / 1.4 / 1.4        1.9 / 2.7 / 5.1
#   40 sweeps over 0.25 m                 1.4 / 1.8 / 1.4
#   the same 40 before the solve          6.4 / 5.7 / 3.4        (the correction undoes them)
#   a correction and 10 over 0.15 m       0.5 / 0.7 / 1.0        1.0 / 1.0 / 3.4
#   a correction and 40 over 0.15 m       0.7 / 0.9 / 0.5        1.1 / 1.1 / 1.7
#   a correction and 2 a vertex of reach  0.6 / 0.8 / 0.5        1.1 / 1.1 / 1.3 (30 / 38 / 60)
#   a correction, 40 or 2 a vertex        0.7 / 0.9 / 0.5        1.2 / 1.1 / 1.3
#   40 sweeps and 6 corrections a step    0.2 / 0.1 / 0.1        0.3 / 0.2 / 16 (beyond reach)
# The last but one is the choice: a frame with a hand costs 1.3x one without at 60x60, 1.4x at
# 120x120 and 1.7x at 200x200 (the correction is most of it); a cloth no hand holds, and so
# every figure of the benchmark's front, is unchanged. Two a vertex alone is as good on fine
# grids but too few on coarse ones: a 5x5 free cloth carried and let go (6 sweeps) then gained
# 18% of the energy moving (tests/test_release.py), none with 9 or more.
NEAR_RADIUS = 0.15
NEAR_SWEEPS = 40
NEAR_PER_REACH = 2


def prepare(cloth):
    """The multigrid levels and the correction's work arrays (once per cloth: their sizes are
    the grid's)."""
    if len(cloth.near) == 0:
        cloth.near = i32(cloth.n_verts)
        cloth.near_mark = i32(cloth.n_verts)
    if len(cloth.levels) > 0 or cloth.n_verts < 4:
        return
    cloth.levels = hierarchy(cloth.cols, cloth.rows)
    cloth.grad = f64(2 * cloth.n_verts)
    cloth.dirn = f64(2 * cloth.n_verts)
    cloth.mg_anchor = f64(2 * cloth.n_verts)
    nc = cloth.levels[1].n if len(cloth.levels) > 1 else 0
    cloth.coarse_e = f64(2 * nc)
    cloth.coarse_b = f64(2 * nc)
    cloth.mg_stale = True


def solve(cloth):
    """Minimise G from the guess `predict` left in pos: iterations // 2 sweeps, the
    corrections (a sweep between two), the rest of the sweeps. The budget is the scene's: a
    step far from balance is not given more (its cost would jump when a person drags hard);
    the integrator takes the next one by backward Euler instead (integrate.UNBALANCED)."""
    sweeps = cloth.iterations
    if sweeps == 0:
        # No iterations, no solve: every free vertex goes where its inertia and gravity take it.
        pos = cloth.pos
        for t in range(2 * cloth.n_verts):
            pos[t] = cloth.pred[t]
        return
    first = sweeps // 2
    forward = True
    for s in range(first):
        sweep(cloth, forward, False)
        forward = not forward
    coarse = len(cloth.levels) > 1
    if coarse:
        for c in range(cloth.corrections):
            if c > 0:
                sweep(cloth, forward, False)
                forward = not forward
            correct(cloth)
    for s in range(first, sweeps):
        sweep(cloth, forward, s == sweeps - 1)
        forward = not forward
    if cloth.n_gripped > 0:
        # A hand holds: one more correction for the far field its pull moved, then the near
        # field's sweeps (NEAR_SWEEPS).
        if coarse:
            correct(cloth)
        count = near_hands(cloth)
        reach = int(math.ceil(NEAR_RADIUS / cloth.spacing))
        for s in range(max(NEAR_SWEEPS, NEAR_PER_REACH * reach)):
            relax(cloth, forward, False, cloth.near, count)
            forward = not forward
    let_fall(cloth)
    if cloth.n_obstacles == 0:
        keep_momentum(cloth)


def keep_momentum(cloth):
    """Every piece nothing holds (no pin, no hand, no obstacle: only its own springs and the air
    act on it) is moved as a whole so that its momentum changes by what the air gives it, as the
    exact step's does. At G's minimum sum_i w_i (x_i - pred_i) is the sum of the forces, and
    the springs' cancel in pairs: what is left is the air's, F(x). An unfinished solve leaves
    it otherwise (the sweeps' order and the coarse correction, which interpolates across a cut,
    move the centre: a free jittered 10x10 drifted 0.3 m in 4 s, a piece cut off fell 2 cm
    behind free fall in a second; and a vertex moved alone stretches one spring as it slacks
    another, so the sweeps carry a piece along with the air 60 times too slowly). The shift
    delta that restores it solves (sum w_i) delta + K delta = sum w_i (pred_i - x_i) + F(x),
    K = sum_e k_e n_e n_e^T the air's stiffness to a shift (cloth/air.py); it leaves the
    piece's shape, and its springs' energy, as the solve left them."""
    pos = cloth.pos
    pred = cloth.pred
    falling = cloth.falling
    piece = cloth.piece
    acc = cloth.piece_sum
    n = cloth.n_verts
    for t in range(6 * cloth.n_pieces):
        acc[t] = 0.0
    any_free = False
    for k in range(n):
        if falling[k] == 0:
            continue
        any_free = True
        p6 = 6 * piece[k]
        w = inertia_weight(cloth, k)
        acc[p6] += w
        acc[p6 + 1] += w * (pred[k + k] - pos[k + k])
        acc[p6 + 2] += w * (pred[k + k + 1] - pos[k + k + 1])
    if not any_free:
        return
    if cloth.windy:
        air.piece_push(cloth, acc)
    for p in range(cloth.n_pieces):
        p6 = 6 * p
        hxx = acc[p6] + acc[p6 + 3]
        hxy = acc[p6 + 4]
        hyy = acc[p6] + acc[p6 + 5]
        det = hxx * hyy - hxy * hxy
        if det > 0.0:
            dx = (hyy * acc[p6 + 1] - hxy * acc[p6 + 2]) / det
            dy = (hxx * acc[p6 + 2] - hxy * acc[p6 + 1]) / det
            acc[p6 + 1] = dx
            acc[p6 + 2] = dy
    for k in range(n):
        if falling[k] == 0:
            continue
        p6 = 6 * piece[k]
        pos[k + k] += acc[p6 + 1]
        pos[k + k + 1] += acc[p6 + 2]


def let_fall(cloth):
    """Every free vertex that no spring pulls, with room to spare (each of its springs shorter
    than its rest length by more than the vertex's way to its target, here and there), goes to
    its target: its exact local minimum, where its inertia (and the air, which moves) alone
    hold it: `pred`, or in a wind one Newton step on those quadratic terms from there. The
    sweeps, whose Hessian takes every spring's axial stiffness, move such a vertex only
    w / (w + k) of the way: a curtain's hem lifted 0.8 m and let go fell 0.1 m in its first
    0.25 s (0.24 m with this; free fall 0.31 m). The room to spare keeps a stiff cloth's
    vertices near their springs' rest lengths, which noise makes slack now and taut next, where
    they are: let go there, each falls a step, its spring snaps it back, and a cotton hang
    never settled. (Near an obstacle the target is not its minimum: the barrier is in G.)"""
    pos = cloth.pos
    pred = cloth.pred
    start = cloth.adj_start
    other = cloth.adj_other
    arest = cloth.adj_rest
    fixed = cloth.fixed
    grip = cloth.grip
    contact = cloth.n_obstacles > 0
    acc = cloth.acc
    for i in range(cloth.n_verts):
        if fixed[i] != 0 or grip[i] >= 0:
            continue
        ii = i + i
        xi = pos[ii]
        yi = pos[ii + 1]
        px = pred[ii]
        py = pred[ii + 1]
        if cloth.windy:
            w = inertia_weight(cloth, i)
            acc[0] = 0.0
            acc[1] = 0.0
            acc[2] = w
            acc[3] = 0.0
            acc[4] = w
            air.vertex_terms(cloth, i, px, py, acc)
            det = acc[2] * acc[4] - acc[3] * acc[3]
            px += (acc[4] * acc[0] - acc[3] * acc[1]) / det
            py += (acc[2] * acc[1] - acc[3] * acc[0]) / det
        jump = math.sqrt((px - xi) * (px - xi) + (py - yi) * (py - yi))
        free = True
        for q in range(start[i], start[i + 1]):
            j = other[q] + other[q]
            r = arest[q] - jump
            if r <= 0.0:
                free = False
                break
            r2 = r * r
            dx = pos[j] - xi
            dy = pos[j + 1] - yi
            ex = pos[j] - px
            ey = pos[j + 1] - py
            if dx * dx + dy * dy >= r2 or ex * ex + ey * ey >= r2:
                free = False
                break
        if free and not (contact and ring_near(cloth, i, px, py)):
            pos[ii] = px
            pos[ii + 1] = py


def near_hands(cloth):
    """cloth.near[:count], in index order: the vertices within NEAR_RADIUS of a held vertex
    in rows and in columns; returns count."""
    cols = cloth.cols
    rows = cloth.rows
    near = cloth.near
    mark = cloth.near_mark
    reach = int(math.ceil(NEAR_RADIUS / cloth.spacing))
    for k in range(cloth.n_verts):
        if cloth.held[k] == 0:
            continue
        r0 = k // cols
        c0 = k - r0 * cols
        for r in range(max(0, r0 - reach), min(rows, r0 + reach + 1)):
            for c in range(max(0, c0 - reach), min(cols, c0 + reach + 1)):
                mark[r * cols + c] = 1
    count = 0
    for v in range(cloth.n_verts):
        if mark[v] != 0:
            mark[v] = 0
            near[count] = v
            count += 1
    return count


def sweep(cloth, forward, last):
    """One vertex block descent sweep over every vertex. On the step's last (`last`), the
    force each vertex found before its move is summed: cloth.imbalance, the solver's own
    residual (over the vertices no hand grips: a hand's stiff spring leaves forces of its own
    scale, and what a person's hand does is not the cloth's balance)."""
    relax(cloth, forward, last, None, cloth.n_verts)
    cloth.sweeps += 1


def relax(cloth, forward, last, verts, n):
    """A sweep over verts[:n] (every vertex, in index order, if verts is None), forward or
    backward: each vertex in turn one Newton step on G with the others held,
    x_i += H_i^-1 f_i (terms.vertex gives f_i and H_i)."""
    pos = cloth.pos
    fixed = cloth.fixed
    grip = cloth.grip
    aim = cloth.aim
    acc = cloth.acc
    contact = cloth.n_obstacles > 0
    sqrt = math.sqrt
    f2 = 0.0
    for t in range(n):
        i = t if forward else n - 1 - t
        if verts is not None:
            i = verts[i]
        if fixed[i] != 0:
            continue
        ii = i + i
        # A second Newton step only for a gripped vertex whose first stopped short (below).
        for again in range(2):
            xi = pos[ii]
            yi = pos[ii + 1]
            vertex(cloth, i, again == 0, acc)
            near = contact and ring_near(cloth, i, xi, yi)
            if near:
                vertex_terms(cloth, i, acc)
            fx = acc[0]
            fy = acc[1]
            hxx = acc[2]
            hxy = acc[3]
            hyy = acc[4]
            pulled = acc[5] != 0.0
            if last and again == 0 and grip[i] < 0:
                f2 += fx * fx + fy * fy
            det = hxx * hyy - hxy * hxy
            if not (det > 0.0):
                break           # no step to take (a block that lost its positive part to rounding)
            mx = (hyy * fx - hxy * fy) / det
            my = (hxx * fy - hxy * fx) / det
            stopped = False
            if pulled:
                # A hand far from its vertex took the pull's soft curvature (terms.hand): no
                # farther along the pull than to within r of the aim, where the curvature is
                # k, not the k / s^3 the step was taken with (a light vertex in a hand's full
                # pull would otherwise be thrown far past the hand: 20 N on a gram is
                # 2 km/s^2); a second step from there takes k, which cannot overshoot. (A
                # vertex stopped a hair beyond r that took the soft curvature again stayed
                # there: while the hand moved, its vertex trailed by r, 1.4 px of the towel.)
                reach = cloth.grip_f[i] / cloth.grip_k[i]
                dx = aim[ii] - xi
                dy = aim[ii + 1] - yi
                d = sqrt(dx * dx + dy * dy)
                along = (mx * dx + my * dy) / d
                if along > d - reach:
                    short = (d - reach) / along
                    mx *= short
                    my *= short
                    stopped = True
            if grip[i] >= 0:
                keep_up(cloth, i, xi + mx, yi + my, cloth.term)
                mx = cloth.term[0] - xi
                my = cloth.term[1] - yi
            if contact:
                descend(cloth, i, xi, yi, mx, my)
            else:
                pos[ii] = xi + mx
                pos[ii + 1] = yi + my
            if not stopped:
                break
    if last:
        cloth.out[0] = f2
        cloth.imbalance = sqrt(f2 / cloth.load2) if cloth.load2 > 0.0 else 0.0


def descend(cloth, i, x0, y0, mx, my):
    """Vertex i's Newton step (mx, my) where an obstacle is near: the whole step if its edges
    sweep no obstacle and it lowers G, else the largest half, quarter, ... of it that does
    (none after contact.HALVINGS). The barrier's curvature grows without bound toward the
    obstacle, so a Newton step taken with its curvature here can overshoot into it."""
    pos = cloth.pos
    ii = i + i
    if not ring_near(cloth, i, x0 + mx, y0 + my):
        pos[ii] = x0 + mx
        pos[ii + 1] = y0 + my
        return
    vertex_energy(cloth, i, x0, y0)
    e0 = cloth.sum[2]
    margin = margin_of(cloth, i)
    f = 1.0
    for k in range(HALVINGS):
        x = x0 + f * mx
        y = y0 + f * my
        if path_clear(cloth, i, x0, y0, x, y, margin):
            vertex_energy(cloth, i, x, y)
            if cloth.sum[2] <= e0:
                pos[ii] = x
                pos[ii + 1] = y
                return
        f *= 0.5
