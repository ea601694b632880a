"""The coarse-grid correction of a step (cloth/vbd.py): the gradient of the step's energy G and
its Hessian at the current positions, restricted to the coarser grids by Galerkin products
(cloth/multigrid.py), solved there, interpolated back as one direction, and a line search along
it on G itself (G is convex along any line, so a quadratic fit and a halving fallback find its
minimum). Sweeps remove an error within a few vertices' reach; this removes the smooth rest."""

import math

from cloth.multigrid import DIAG, galerkin, restrict, prolong, pcg, factor_dense
from cloth.hands import pull_energy

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
        galerkin(fine, coarse, cloth.uncorrected)
        for l in range(2, len(levels)):
            galerkin(levels[l - 1], levels[l], None)
        factor_dense(levels[len(levels) - 1])
        for t in range(2 * cloth.n_verts):
            cloth.mg_anchor[t] = cloth.pos[t]
        for t in range(cloth.n_verts):
            cloth.mg_uncorrected[t] = cloth.uncorrected[t]
            cloth.mg_grip[t] = cloth.grip[t]
        cloth.mg_stale = False
        cloth.mg_changed = 0
        cloth.mg_age = 0
        cloth.rebuilds += 1
    cloth.mg_age += 1
    b = cloth.coarse_b
    restrict(fine, coarse, cloth.uncorrected, cloth.grad, b)
    for t in range(2 * coarse.n):
        b[t] = -b[t]
    pcg(levels, 1, COARSE_STEPS, b, cloth.coarse_e)
    d = cloth.dirn
    prolong(fine, coarse, cloth.uncorrected, cloth.coarse_e, d)
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
