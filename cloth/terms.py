"""The step's energy, term by term: each term once, with its energy, its force and its 2x2 block.

A step (cloth/integrate.py) moves the free vertices to the minimum of
    G(x) = sum_i w_i / 2 |x_i - pred_i|^2          inertia (w_i = m_i (1 + c h') / h'^2)
         + sum_e k_e / 2 (L_e - L0_e)_+^2           the fabric's springs, tension only
         + sum_hands H(x)                           the hands' capped pulls
         + the air's drag                           cloth/air.py (where the air moves)
         + the contact's barrier and friction      cloth/contact.py (where there are obstacles)
and the solvers (cloth/vbd.py, cloth/coarse.py, cloth/xpbd.py) are minimisers over it. Every
term is convex: (L - L0)_+^2 / 2 is half the squared distance of the edge vector to the disc
of radius L0, and a hand's pull is a pseudo-Huber function. So the step has one answer.

Each term here gives, for the vertex at the start of its vector d (a spring's d = far end -
near end, a hand's d = its aim - the vertex):
    t[0], t[1]  the force on that vertex, -dG/dx
    t[2..4]     its 2x2 block (xx, xy, yy), the Hessian or a majoriser of it (below)
written into a scratch array the caller adds from: doubles passed back through an array, not
returned, as JS would box them (an allocation a call in the hot path).

The blocks are majorisers where the true Hessian is not positive definite or is too small to
step with: a slack spring's block is its axial stiffness `slack` n n^T (its true curvature is
0: where a spring is about to pull, a Newton step without it overshoots into it; cotton two
corners never came to rest, and blew up at 60x60, with it left out), and a hand's block, far
from its aim, is the pull's own curvature (soft) or, near it, its largest (k I). A larger block
only shortens a step; the minimum, where every force is 0, is the same.
"""

from math import sqrt

from cloth.multigrid import DIAG
from cloth import contact
from cloth import air


def inertia_weight(cloth, i):
    """w_i: vertex i's inertia weight in G, m (1 + c h') / h'^2, more for a gripped vertex
    (its hand's damper: hands.hold)."""
    w = cloth.mass[i] * cloth.w_scale
    if cloth.grip[i] >= 0:
        w *= cloth.grip_w
    return w


def spring(k, r0, dx, dy, slack, t):
    """A spring of stiffness k and rest length r0 whose far end is (dx, dy) from its near end:
    t[0..1] its force on the near end, k (L - r0)_+ n, and t[2..4] its block, the Hessian
    k (n n^T + (1 - r0 / L) (I - n n^T)) when taut and `slack` n n^T when not (k, or 0 where a
    caller wants no majoriser). A spring of no length has no direction: all zero."""
    L2 = dx * dx + dy * dy
    if L2 < 1e-30:
        t[0] = 0.0
        t[1] = 0.0
        t[2] = 0.0
        t[3] = 0.0
        t[4] = 0.0
        return
    L = sqrt(L2)
    nx = dx / L
    ny = dy / L
    if L > r0:
        s = k * (L - r0)
        t[0] = s * nx
        t[1] = s * ny
        t1 = k - k * r0 / L
        t2 = k * r0 / L
        t[2] = t1 + t2 * nx * nx
        t[3] = t2 * nx * ny
        t[4] = t1 + t2 * ny * ny
    else:
        t[0] = 0.0
        t[1] = 0.0
        t[2] = slack * nx * nx
        t[3] = slack * nx * ny
        t[4] = slack * ny * ny


def spring_energy(k, r0, dx, dy):
    """k / 2 (L - r0)_+^2 for the edge vector (dx, dy)."""
    x = sqrt(dx * dx + dy * dy) - r0
    if x > 0.0:
        return 0.5 * k * x * x
    return 0.0


def hand(kh, f, dx, dy, soft, t):
    """A hand's pull on a vertex (dx, dy) from its aim: k d / s, s = sqrt(1 + (d / r)^2),
    r = f / k (cloth/hands.py): a spring's pull near the aim that levels off at f far from it.
    The block: where the vertex is farther than r and `soft`, the pull's own curvature, k / s^3
    along the pull and k / s across it (t[5] = 1); otherwise k I, the most the curvature
    reaches anywhere (t[5] = 0). The soft curvature lets a far hand drag its vertex as hard as
    its force can (with k along the pull a hand moved its vertex 1 mm a sweep and could not
    catch a swinging cloth); near the aim, where it climbs to k, only k cannot overshoot."""
    reach = f / kh
    d2 = dx * dx + dy * dy
    sh = sqrt(1.0 + d2 / (reach * reach))
    s = kh / sh
    t[0] = s * dx
    t[1] = s * dy
    if d2 > reach * reach and soft:
        d = sqrt(d2)
        nx = dx / d
        ny = dy / d
        along = s / (sh * sh)
        t[2] = s + (along - s) * nx * nx
        t[3] = (along - s) * nx * ny
        t[4] = s + (along - s) * ny * ny
        t[5] = 1.0
    else:
        t[2] = kh
        t[3] = 0.0
        t[4] = kh
        t[5] = 0.0


def hand_energy(f, r, d2):
    """A hand's pull's energy at a squared distance d2 from its aim: f r (sqrt(1 + d2 / r^2) - 1),
    whose gradient is the pull above (r = f / k)."""
    return f * r * (sqrt(1.0 + d2 / (r * r)) - 1.0)


def vertex(cloth, i, soft, acc):
    """acc[0..4]: the force on vertex i and its 2x2 block, summed over the terms that hold i
    where the cloth is now: its inertia, its springs (each with its axial stiffness when slack),
    its hand, if one grips it (`soft`: see hand), and the air, if it moves (cloth/air.py); the
    contact's are added where an obstacle is near (cloth/contact.py). acc[5] = 1 when the
    hand's block is the soft one."""
    pos = cloth.pos
    ii = i + i
    xi = pos[ii]
    yi = pos[ii + 1]
    w = inertia_weight(cloth, i)
    t = cloth.term
    fx = w * (cloth.pred[ii] - xi)
    fy = w * (cloth.pred[ii + 1] - yi)
    hxx = w
    hxy = 0.0
    hyy = w
    other = cloth.adj_other
    arest = cloth.adj_rest
    ak = cloth.adj_k
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        j = other[q] + other[q]
        k = ak[q]
        spring(k, arest[q], pos[j] - xi, pos[j + 1] - yi, k, t)
        fx += t[0]
        fy += t[1]
        hxx += t[2]
        hxy += t[3]
        hyy += t[4]
    acc[5] = 0.0
    if cloth.grip[i] >= 0:
        hand(cloth.grip_k[i], cloth.grip_f[i], cloth.aim[ii] - xi, cloth.aim[ii + 1] - yi, soft, t)
        fx += t[0]
        fy += t[1]
        hxx += t[2]
        hxy += t[3]
        hyy += t[4]
        acc[5] = t[5]
    acc[0] = fx
    acc[1] = fy
    acc[2] = hxx
    acc[3] = hxy
    acc[4] = hyy
    if cloth.windy:
        air.vertex_terms(cloth, i, xi, yi, acc)


def assemble(cloth, g, A):
    """The whole of G at the cloth now, for the coarse-grid correction (cloth/coarse.py): its
    gradient g (2 per vertex; 0 at a fixed vertex) and its Hessian A, a 9-point stencil of 2x2
    blocks (cloth/multigrid.py's storage), every block as the sweeps take it but one: a slack
    spring from a gripped vertex to one no hand grips puts no axial stiffness in A. The hand
    holds its vertex near its aim, and that stiffness tied the neighbour to it in the coarse
    problem, which then could not move the cloth behind a hand that moves with it (a swinging
    chain held at its end on its own path: each step 3-14 mm from the exact one, against 0.1-3
    mm untouched). Inside a patch the hand grips it stays: without it the patch went soft in
    the coarse problem and, at 200x200, the held vertex trailed a hand going round at 8 px a
    frame by 7 px. The correction's line search is on G itself, so a softer model cannot raise
    G."""
    pos = cloth.pos
    pred = cloth.pred
    fixed = cloth.fixed
    grip = cloth.grip
    n = cloth.n_verts
    t = cloth.term
    for q in range(27 * n):
        A[q] = 0.0
    for i in range(n):
        w = inertia_weight(cloth, i)
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
    for e in range(cloth.n_edges):
        a = ea[e]
        b = eb[e]
        k = stiff[e]
        spring(k, rest[e], pos[b + b] - pos[a + a], pos[b + b + 1] - pos[a + a + 1],
               0.0 if (grip[a] >= 0) != (grip[b] >= 0) else k, t)
        g[a + a] -= t[0]
        g[a + a + 1] -= t[1]
        g[b + b] += t[0]
        g[b + b + 1] += t[1]
        couple(A, a, b, slot[e], t[2], t[3], t[4], -1.0)
    for h in range(cloth.n_gripped):
        i = cloth.gripped[h]
        ii = i + i
        # The pull's own curvature far from the aim, as the sweeps take it: with k along the
        # pull the coarse problem held a far hand's patch as by a stiff spring, moving it
        # HAND_FORCE / HAND_STIFFNESS a correction at most, and a 120x120 Two corners swung
        # round by a hand trailed it by 17 cm for good.
        hand(cloth.grip_k[i], cloth.grip_f[i], cloth.aim[ii] - pos[ii], cloth.aim[ii + 1] - pos[ii + 1],
             True, t)
        g[ii] -= t[0]
        g[ii + 1] -= t[1]
        o = (i * 9 + DIAG) * 3
        A[o] += t[2]
        A[o + 1] += t[3]
        A[o + 2] += t[4]
    if cloth.windy:
        air.assemble(cloth, g, A, couple)
    if cloth.n_obstacles > 0:
        contact.assemble(cloth, g, A)
    for i in range(n):
        if fixed[i] != 0:
            g[i + i] = 0.0
            g[i + i + 1] = 0.0


def couple(A, a, b, slot, kxx, kxy, kyy, sign):
    """Add a term of two vertices a and b whose Hessian is [[K, sign K], [sign K, K]] to A:
    K on both diagonal blocks, sign K on the block between them (b is in a's stencil slot
    `slot`, a in b's 8 - slot). A spring's sign is -1."""
    o = (a * 9 + DIAG) * 3
    A[o] += kxx
    A[o + 1] += kxy
    A[o + 2] += kyy
    o = (b * 9 + DIAG) * 3
    A[o] += kxx
    A[o + 1] += kxy
    A[o + 2] += kyy
    o = (a * 9 + slot) * 3
    A[o] += sign * kxx
    A[o + 1] += sign * kxy
    A[o + 2] += sign * kyy
    o = (b * 9 + 8 - slot) * 3
    A[o] += sign * kxx
    A[o + 1] += sign * kxy
    A[o + 2] += sign * kyy


def energy_along(cloth, d):
    """cloth.out[1] = G(pos + alpha d), up to a constant, alpha = cloth.alpha (doubles pass
    through the cloth: as arguments or a return value JS would box them, an allocation a
    call)."""
    alpha = cloth.alpha
    pos = cloth.pos
    pred = cloth.pred
    fixed = cloth.fixed
    s = 0.0
    for i in range(cloth.n_verts):
        if fixed[i] != 0:
            continue
        ex = pos[i + i] + alpha * d[i + i] - pred[i + i]
        ey = pos[i + i + 1] + alpha * d[i + i + 1] - pred[i + i + 1]
        s += 0.5 * inertia_weight(cloth, i) * (ex * ex + ey * ey)
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    for e in range(cloth.n_edges):
        a = ea[e] + ea[e]
        b = eb[e] + eb[e]
        s += spring_energy(stiff[e], rest[e], pos[b] + alpha * d[b] - pos[a] - alpha * d[a],
                           pos[b + 1] + alpha * d[b + 1] - pos[a + 1] - alpha * d[a + 1])
    for h in range(cloth.n_gripped):
        i = cloth.gripped[h]
        ii = i + i
        dx = pos[ii] + alpha * d[ii] - cloth.aim[ii]
        dy = pos[ii + 1] + alpha * d[ii + 1] - cloth.aim[ii + 1]
        s += hand_energy(cloth.grip_f[i], cloth.grip_f[i] / cloth.grip_k[i], dx * dx + dy * dy)
    if cloth.windy:
        s += air.energy_along(cloth, d)
    if cloth.n_obstacles > 0:
        contact.energy_along(cloth, d)
        s += cloth.sum[1]
    cloth.out[1] = s


def vertex_energy(cloth, i, x, y):
    """cloth.sum[2] = the terms of G that hold vertex i, with i at (x, y) and the rest of the
    cloth where it is: its inertia, springs and hand, and the contact's (BLOCKED where an edge
    of it would meet an obstacle)."""
    pos = cloth.pos
    ii = i + i
    ex = x - cloth.pred[ii]
    ey = y - cloth.pred[ii + 1]
    s = 0.5 * inertia_weight(cloth, i) * (ex * ex + ey * ey)
    other = cloth.adj_other
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        j = other[q] + other[q]
        s += spring_energy(cloth.adj_k[q], cloth.adj_rest[q], pos[j] - x, pos[j + 1] - y)
    if cloth.grip[i] >= 0:
        dx = x - cloth.aim[ii]
        dy = y - cloth.aim[ii + 1]
        s += hand_energy(cloth.grip_f[i], cloth.grip_f[i] / cloth.grip_k[i], dx * dx + dy * dy)
    if cloth.windy:
        s += air.vertex_energy(cloth, i, x, y)
    if cloth.n_obstacles > 0:
        contact.vertex_energy(cloth, i, x, y)
        s += cloth.sum[0]
    cloth.sum[2] = s
