"""The coarse-grid correction of a step (cloth/vbd.py): the gradient of the step's energy G and
its Hessian at the current positions, restricted to the coarser grids by Galerkin products
(cloth/multigrid.py), solved there, interpolated back as one direction, and a line search along
it on G itself (G is convex along any line, so a quadratic fit and a halving fallback find its
minimum). Sweeps remove an error within a few vertices' reach; this removes the smooth rest."""

import math

from cloth.multigrid import galerkin, restrict, prolong, pcg, factor_dense
from cloth.terms import assemble, energy_along
from cloth.ccd import move_clear
from cloth.hands import catch_up_limit

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


def correct(cloth):
    """One coarse-grid correction (see the module's comment)."""
    levels = cloth.levels
    fine = levels[0]
    coarse = levels[1]
    assemble(cloth, cloth.grad, fine.A)
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
    # No farther than a hand's patch may go in the step (hands.keep_up).
    top = MOST_ALPHA
    if cloth.n_gripped > 0:
        top = catch_up_limit(cloth, d, top)
        if not (top > 0.0):
            return
    cloth.alpha = 0.0
    energy_along(cloth, d)
    g0 = cloth.out[1]
    cloth.alpha = top
    energy_along(cloth, d)
    g1 = cloth.out[1]
    curv = (g1 - g0 - slope * top) / (top * top)
    alpha = top
    if curv > 0.0:
        alpha = -slope / (2.0 * curv)
        if alpha > top:
            alpha = top
    ga = g1
    if alpha != top:
        cloth.alpha = alpha
        energy_along(cloth, d)
        ga = cloth.out[1]
    tries = 0
    while ga > g0 + ARMIJO * alpha * slope and tries < 8:
        alpha *= 0.5
        cloth.alpha = alpha
        energy_along(cloth, d)
        ga = cloth.out[1]
        tries += 1
    if not (ga < g0):
        return
    pos = cloth.pos
    if cloth.n_obstacles == 0:
        for t in range(2 * cloth.n_verts):
            pos[t] += alpha * d[t]
        return
    # Near an obstacle each vertex goes only as far as its edges sweep none (contact.py).
    for k in range(cloth.n_verts):
        if cloth.fixed[k] == 0:
            move_clear(cloth, k, pos[k + k] + alpha * d[k + k], pos[k + k + 1] + alpha * d[k + k + 1])
