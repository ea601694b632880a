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
(cloth/multigrid.py) removes the smooth rest: the Hessian of G and its gradient at the current
positions, restricted to coarser grids by Galerkin products, solved there, interpolated back as
one direction, and a line search along it on G itself (G is convex along any line, so a
quadratic fit and a halving fallback find its minimum). Per step: iterations // 2 sweeps,
the corrections (a sweep between two), the other sweeps; while a hand holds the cloth, one
more correction and NEAR_SWEEPS sweeps over the vertices near it (below). The coarse
operators are rebuilt every REBUILD steps, or at once when a vertex has moved more than a spacing since they were
made, or the topology, the pins or the hands changed.
"""

import math

from cloth.host import f64, i32
from cloth.multigrid import DIAG, hierarchy, galerkin, restrict, prolong, pcg, factor_dense
from cloth.contact import keep_out, unopposed
from cloth.hands import pull_energy

NAME = 'vbd'
LABEL = 'Vertex descent + multigrid'
# substeps, iterations (sweeps a step) and coarse corrections a step
BUDGET = [1, 5, 1]
# Its steps are BDF2 (cloth/integrate.py), backward Euler after one left off balance.
ORDER = 2
# Its last sweep measures cloth.imbalance (sweep).
RESIDUAL = True
# The coarse operators are reused for this many steps: they are the Hessian where the cloth
# was, and a rebuild costs about six sweeps (measured at 60x60); a cloth that moved more than a
# spacing since gets new ones at once.
REBUILD = 8
# Conjugate gradient steps on the coarse problem, each preconditioned by one V-cycle.
COARSE_STEPS = 2
# The line search along a correction: at most the correction itself (a step beyond it, which a
# quadratic fit through a kink of G may ask for, once gained energy that a stiff cloth's
# swinging flaps kept: a cotton towel hung from one point went unstable at 20x20), and
# Armijo's fraction.
MOST_ALPHA = 1.0
ARMIJO = 1e-4
# A hand moved fast pulls the whole cloth a little and the cloth near it a lot, and the
# scene's budget leaves both behind on a fine grid: one correction a step carries part of the
# far field, and a sweep carries a change about one vertex onward, so the cells between the
# grip and the coarse grid's scale lag. While a hand holds, the step ends with one more
# correction and NEAR_SWEEPS sweeps over the vertices within NEAR_RADIUS (rows and columns, in
# metres: the same patch of fabric at every grid). Measured in the page round a 40 px circle
# at 20 px a frame (tests/browser/test_input.py's path; the held vertex's worst lag behind the
# pointer, curtain / Two corners / towel at 120x120, then at 200x200):
#   nothing more                          2.9 / 6.1 / 5.5 px     5.6 / 6.4 / 7.5 px
#   40 sweeps over 0.10 m                 1.7 / 1.5 / 1.5
#   40 sweeps over 0.15 m                 1.5 / 1.4 / 1.4        1.9 / 2.7 / 5.1
#   40 sweeps over 0.25 m                 1.4 / 1.8 / 1.4
#   the same 40 before the solve          6.4 / 5.7 / 3.4        (the correction undoes them)
#   a correction and 10 over 0.15 m       0.5 / 0.7 / 1.0        1.0 / 1.0 / 3.4
#   a correction and 40 over 0.15 m       0.7 / 0.9 / 0.5        1.1 / 1.1 / 1.7
#   40 sweeps and 6 corrections a step    0.2 / 0.1 / 0.1        0.3 / 0.2 / 16 (beyond reach)
# The last but one is the choice: a frame with a hand costs 1.3x one without at 60x60, 1.4x at
# 120x120 and 1.8x at 200x200 (the correction is most of it); a cloth no hand holds, and so
# every figure of the benchmark's front, is unchanged.
NEAR_RADIUS = 0.15
NEAR_SWEEPS = 40


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
        for s in range(NEAR_SWEEPS):
            relax(cloth, forward, False, cloth.near, count)
            forward = not forward
    let_fall(cloth)
    if cloth.n_obstacles == 0:
        keep_momentum(cloth)


def keep_momentum(cloth):
    """Every piece nothing holds (no pin, no hand, no obstacle: only its own springs act
    on it) is moved as a whole so that its centre of mass is where the step's inertia puts it.
    At G's minimum sum_i w_i (x_i - pred_i) is the sum of the springs' forces, which cancel in
    pairs: the exact step keeps a free piece's momentum. An unfinished solve does not (the
    sweeps' order and the coarse correction, which interpolates across a cut, move the centre:
    a free jittered 10x10 drifted 0.3 m in 4 s, a piece cut off fell 2 cm behind free fall in
    a second); the shift restores it and leaves the piece's shape, and its springs' energy,
    as the solve left them."""
    pos = cloth.pos
    pred = cloth.pred
    mass = cloth.mass
    falling = cloth.falling
    piece = cloth.piece
    acc = cloth.piece_sum
    n = cloth.n_verts
    for t in range(3 * cloth.n_pieces):
        acc[t] = 0.0
    any_free = False
    for k in range(n):
        if falling[k] == 0:
            continue
        any_free = True
        p3 = 3 * piece[k]
        m = mass[k]
        acc[p3] += m
        acc[p3 + 1] += m * (pred[k + k] - pos[k + k])
        acc[p3 + 2] += m * (pred[k + k + 1] - pos[k + k + 1])
    if not any_free:
        return
    for k in range(n):
        if falling[k] == 0:
            continue
        p3 = 3 * piece[k]
        pos[k + k] += acc[p3 + 1] / acc[p3]
        pos[k + k + 1] += acc[p3 + 2] / acc[p3]


def let_fall(cloth):
    """Every free vertex that no spring pulls, with room to spare (each of its springs shorter
    than its rest length by more than the vertex's way to its inertial target, here and
    there), goes to that target: its exact local minimum. The sweeps, whose Hessian takes every
    spring's axial stiffness, move such a vertex only w / (w + k) of the way: a curtain's hem
    lifted 0.8 m and let go fell 0.1 m in its first 0.25 s (0.24 m with this; free fall 0.31 m).
    The room to spare keeps a stiff cloth's vertices near their springs' rest lengths, which
    noise makes slack now and taut next, where they are: let go there, each falls a step,
    its spring snaps it back, and a cotton hang never settled."""
    pos = cloth.pos
    pred = cloth.pred
    start = cloth.adj_start
    other = cloth.adj_other
    arest = cloth.adj_rest
    fixed = cloth.fixed
    grip = cloth.grip
    for i in range(cloth.n_verts):
        if fixed[i] != 0 or grip[i] >= 0:
            continue
        ii = i + i
        xi = pos[ii]
        yi = pos[ii + 1]
        px = pred[ii]
        py = pred[ii + 1]
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
        if free:
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
    backward."""
    pos = cloth.pos
    pred = cloth.pred
    fixed = cloth.fixed
    mass = cloth.mass
    start = cloth.adj_start
    other = cloth.adj_other
    arest = cloth.adj_rest
    ak = cloth.adj_k
    grip = cloth.grip
    aim = cloth.aim
    grip_k = cloth.grip_k
    grip_f = cloth.grip_f
    ws = cloth.w_scale
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
        w = mass[i] * ws
        if grip[i] >= 0:
            w *= cloth.grip_w
        # A second Newton step only for a gripped vertex whose first stopped short (below).
        for again in range(2):
            xi = pos[ii]
            yi = pos[ii + 1]
            fx = w * (pred[ii] - xi)
            fy = w * (pred[ii + 1] - yi)
            hxx = w
            hxy = 0.0
            hyy = w
            for q in range(start[i], start[i + 1]):
                j = other[q] + other[q]
                dx = pos[j] - xi
                dy = pos[j + 1] - yi
                L2 = dx * dx + dy * dy
                if L2 < 1e-30:
                    continue
                L = sqrt(L2)
                k = ak[q]
                nx = dx / L
                ny = dy / L
                r0 = arest[q]
                if L > r0:
                    s = k * (L - r0)
                    fx += s * nx
                    fy += s * ny
                    t1 = k - k * r0 / L
                    t2 = k * r0 / L
                    hxx += t1 + t2 * nx * nx
                    hxy += t2 * nx * ny
                    hyy += t1 + t2 * ny * ny
                else:
                    hxx += k * nx * nx
                    hxy += k * nx * ny
                    hyy += k * ny * ny
            pulled = False
            reach = 0.0
            if grip[i] >= 0:
                # A hand: its pull k (aim - x) / s, s = sqrt(1 + (d / r)^2), r = f / k, grows as
                # a spring's near the aim and levels off at f (cloth/hands.py). Its curvature,
                # k / s^3 along the pull and k / s across it, is small when it pulls hard from
                # afar: a far hand drags its vertex as hard as its force can (with k along the
                # pull a hand moved its vertex 1 mm a sweep, and could not catch a swinging
                # cloth); a step that would carry the vertex within r of the aim, where the
                # curvature climbs to k, stops at r (below), and a second step from there takes
                # k, the most the curvature reaches anywhere (a majoriser: it cannot overshoot).
                # Without it a vertex stopped a hair beyond r took the soft curvature again and
                # the stop kept it there: while the hand moved, its vertex trailed by r, 1.4 px
                # of the towel at the page's scale.
                dx = aim[ii] - xi
                dy = aim[ii + 1] - yi
                kh = grip_k[i]
                reach = grip_f[i] / kh
                d2 = dx * dx + dy * dy
                sh = sqrt(1.0 + d2 / (reach * reach))
                s = kh / sh
                fx += s * dx
                fy += s * dy
                if d2 > reach * reach and again == 0:
                    d = sqrt(d2)
                    nx = dx / d
                    ny = dy / d
                    along = s / (sh * sh)
                    hxx += s + (along - s) * nx * nx
                    hxy += (along - s) * nx * ny
                    hyy += s + (along - s) * ny * ny
                    pulled = True
                else:
                    hxx += kh
                    hyy += kh
            if last and again == 0 and grip[i] < 0:
                f2 += unopposed(cloth, i, fx, fy) if contact else fx * fx + fy * fy
            det = hxx * hyy - hxy * hxy
            mx = (hyy * fx - hxy * fy) / det
            my = (hxx * fy - hxy * fx) / det
            stopped = False
            if pulled:
                # No farther along the pull than to within r of the aim: the pull's curvature
                # there is k, not the k / s^3 the step was taken with (a light vertex in a
                # hand's full pull would otherwise be thrown far past the hand: 20 N on a gram
                # is 2 km/s^2).
                dx = aim[ii] - xi
                dy = aim[ii + 1] - yi
                d = sqrt(dx * dx + dy * dy)
                along = (mx * dx + my * dy) / d
                if along > d - reach:
                    short = (d - reach) / along
                    mx *= short
                    my *= short
                    stopped = True
            pos[ii] = xi + mx
            pos[ii + 1] = yi + my
            if contact:
                keep_out(cloth, i)
            if not stopped:
                break
    if last:
        cloth.out[0] = f2
        cloth.imbalance = sqrt(f2 / cloth.load2) if cloth.load2 > 0.0 else 0.0


def assemble(cloth):
    """grad = dG/dx at pos, and levels[0].A its Hessian (every spring's axial stiffness in it,
    as the sweeps have it); a fixed vertex's gradient is 0."""
    pos = cloth.pos
    pred = cloth.pred
    g = cloth.grad
    A = cloth.levels[0].A
    mass = cloth.mass
    fixed = cloth.fixed
    n = cloth.n_verts
    ws = cloth.w_scale
    sqrt = math.sqrt
    for t in range(27 * n):
        A[t] = 0.0
    for i in range(n):
        w = mass[i] * ws
        if cloth.grip[i] >= 0:
            w *= cloth.grip_w
        g[i + i] = w * (pos[i + i] - pred[i + i])
        g[i + i + 1] = w * (pos[i + i + 1] - pred[i + i + 1])
        o = (i * 9 + DIAG) * 3
        A[o] = w
        A[o + 2] = w
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    slot = cloth.slot
    grip = cloth.grip
    for e in range(cloth.n_edges):
        a = ea[e]
        b = eb[e]
        dx = pos[b + b] - pos[a + a]
        dy = pos[b + b + 1] - pos[a + a + 1]
        L2 = dx * dx + dy * dy
        r0 = rest[e]
        if L2 < 1e-30:
            continue
        L = sqrt(L2)
        k = stiff[e]
        nx = dx / L
        ny = dy / L
        if L > r0:
            s = k * (L - r0)
            g[a + a] -= s * nx
            g[a + a + 1] -= s * ny
            g[b + b] += s * nx
            g[b + b + 1] += s * ny
            t1 = k - k * r0 / L
            t2 = k * r0 / L
            kxx = t1 + t2 * nx * nx
            kxy = t2 * nx * ny
            kyy = t1 + t2 * ny * ny
        else:
            # A slack spring's axial stiffness, as the sweeps take it (a majoriser: its true
            # curvature is 0), but none on a spring from a gripped vertex to one no hand grips:
            # the hand holds its vertex near its aim, and that stiffness tied the neighbour to
            # it in the coarse problem, which then could not move the cloth behind a hand that
            # moves with it (a swinging chain held at its end on its own path: each step 3-14
            # mm from the exact one, against 0.1-3 mm untouched; 0.1-5 mm without it). Inside
            # a patch the hand grips the stiffness stays: without it the patch went soft in the
            # coarse problem and, at 200x200, the held vertex trailed a hand going round at 8
            # px a frame by 7 px. The line search along the correction is on G itself, so a
            # softer model cannot raise G.
            c = 0.0 if (grip[a] >= 0) != (grip[b] >= 0) else k
            kxx = c * nx * nx
            kxy = c * nx * ny
            kyy = c * ny * ny
        s = slot[e]
        o = (a * 9 + DIAG) * 3
        A[o] += kxx
        A[o + 1] += kxy
        A[o + 2] += kyy
        o = (b * 9 + DIAG) * 3
        A[o] += kxx
        A[o + 1] += kxy
        A[o + 2] += kyy
        o = (a * 9 + s) * 3
        A[o] -= kxx
        A[o + 1] -= kxy
        A[o + 2] -= kyy
        o = (b * 9 + 8 - s) * 3
        A[o] -= kxx
        A[o + 1] -= kxy
        A[o + 2] -= kyy
    for h in range(cloth.n_gripped):
        i = cloth.gripped[h]
        ii = i + i
        dx = cloth.aim[ii] - pos[ii]
        dy = cloth.aim[ii + 1] - pos[ii + 1]
        kh = cloth.grip_k[i]
        reach = cloth.grip_f[i] / kh
        d2 = dx * dx + dy * dy
        sh = math.sqrt(1.0 + d2 / (reach * reach))
        s = kh / sh
        g[ii] -= s * dx
        g[ii + 1] -= s * dy
        o = (i * 9 + DIAG) * 3
        if d2 > reach * reach:
            # The pull's own curvature, as the sweeps take it: k / s^3 along the pull, k / s
            # across. With k along it the coarse problem held a far hand's patch as by a stiff
            # spring, moving it HAND_FORCE / HAND_STIFFNESS a correction at most, and a
            # 120x120 Two corners swung round by a hand trailed it by 17 cm for good.
            d = sqrt(d2)
            nx = dx / d
            ny = dy / d
            along = s / (sh * sh)
            A[o] += s + (along - s) * nx * nx
            A[o + 1] += (along - s) * nx * ny
            A[o + 2] += s + (along - s) * ny * ny
        else:
            A[o] += kh
            A[o + 2] += kh
    for i in range(n):
        if fixed[i] != 0:
            g[i + i] = 0.0
            g[i + i + 1] = 0.0


def energy(cloth):
    """out[1] = G(pos + alpha dirn) up to a constant, alpha = cloth.alpha (doubles pass through
    the cloth: as arguments or a return value JS would box them, an allocation a call)."""
    alpha = cloth.alpha
    pos = cloth.pos
    d = cloth.dirn
    pred = cloth.pred
    mass = cloth.mass
    fixed = cloth.fixed
    half_ws = 0.5 * cloth.w_scale
    sqrt = math.sqrt
    s = 0.0
    for i in range(cloth.n_verts):
        if fixed[i] != 0:
            continue
        ex = pos[i + i] + alpha * d[i + i] - pred[i + i]
        ey = pos[i + i + 1] + alpha * d[i + i + 1] - pred[i + i + 1]
        w = half_ws * mass[i]
        if cloth.grip[i] >= 0:
            w *= cloth.grip_w
        s += w * (ex * ex + ey * ey)
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    for e in range(cloth.n_edges):
        a = ea[e] + ea[e]
        b = eb[e] + eb[e]
        dx = pos[b] + alpha * d[b] - pos[a] - alpha * d[a]
        dy = pos[b + 1] + alpha * d[b + 1] - pos[a + 1] - alpha * d[a + 1]
        x = sqrt(dx * dx + dy * dy) - rest[e]
        if x > 0.0:
            s += 0.5 * stiff[e] * x * x
    for h in range(cloth.n_gripped):
        i = cloth.gripped[h]
        ii = i + i
        dx = pos[ii] + alpha * d[ii] - cloth.aim[ii]
        dy = pos[ii + 1] + alpha * d[ii + 1] - cloth.aim[ii + 1]
        s += pull_energy(cloth.grip_f[i], cloth.grip_f[i] / cloth.grip_k[i], dx * dx + dy * dy)
    cloth.out[1] = s


def correct(cloth):
    """One coarse-grid correction (see the module's comment)."""
    levels = cloth.levels
    fine = levels[0]
    coarse = levels[1]
    assemble(cloth)
    if cloth.mg_changed != 0:
        cloth.mg_stale = True
    if not cloth.mg_stale:
        if cloth.mg_age >= REBUILD:
            cloth.mg_stale = True
        else:
            lim = cloth.spacing * cloth.spacing
            pos = cloth.pos
            anchor = cloth.mg_anchor
            for t in range(cloth.n_verts):
                dx = pos[t + t] - anchor[t + t]
                dy = pos[t + t + 1] - anchor[t + t + 1]
                if dx * dx + dy * dy > lim:
                    cloth.mg_stale = True
                    break
    if cloth.mg_stale:
        galerkin(fine, coarse, cloth.fixed)
        for l in range(2, len(levels)):
            galerkin(levels[l - 1], levels[l], None)
        factor_dense(levels[len(levels) - 1])
        for t in range(2 * cloth.n_verts):
            cloth.mg_anchor[t] = cloth.pos[t]
        for t in range(cloth.n_verts):
            cloth.mg_fixed[t] = cloth.fixed[t]
            cloth.mg_grip[t] = cloth.grip[t]
        cloth.mg_stale = False
        cloth.mg_changed = 0
        cloth.mg_age = 0
        cloth.rebuilds += 1
    cloth.mg_age += 1
    b = cloth.coarse_b
    restrict(fine, coarse, cloth.fixed, cloth.grad, b)
    for t in range(2 * coarse.n):
        b[t] = -b[t]
    pcg(levels, 1, COARSE_STEPS, b, cloth.coarse_e)
    d = cloth.dirn
    prolong(fine, coarse, cloth.fixed, cloth.coarse_e, d)
    slope = 0.0
    g = cloth.grad
    for t in range(2 * cloth.n_verts):
        slope += g[t] * d[t]
    cloth.corrected += 1
    if not (slope < 0.0):
        return
    cloth.alpha = 0.0
    energy(cloth)
    g0 = cloth.out[1]
    cloth.alpha = 1.0
    energy(cloth)
    g1 = cloth.out[1]
    curv = g1 - g0 - slope
    alpha = 1.0
    if curv > 0.0:
        alpha = -slope / (2.0 * curv)
        if alpha > MOST_ALPHA:
            alpha = MOST_ALPHA
    ga = g1
    if alpha != 1.0:
        cloth.alpha = alpha
        energy(cloth)
        ga = cloth.out[1]
    tries = 0
    while ga > g0 + ARMIJO * alpha * slope and tries < 8:
        alpha *= 0.5
        cloth.alpha = alpha
        energy(cloth)
        ga = cloth.out[1]
        tries += 1
    if not (ga < g0):
        return
    pos = cloth.pos
    for t in range(2 * cloth.n_verts):
        pos[t] += alpha * d[t]
