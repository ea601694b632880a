"""XPBD on the membrane (Macklin, Mueller, Chentanez, "XPBD", 2016): the same step energy as
the default solver (cloth/integrate.py), minimised by Gauss-Seidel sweeps over the edges, each
a compliant constraint C = L - L0 with compliance 1 / k:
    d_lambda = (-C - lambda / k) / (1 / w_a + 1 / w_b + 1 / k),  lambda <= 0 (tension only),
    x_a -= n d_lambda / w_a,  x_b += n d_lambda / w_b
(w: a vertex's inertia weight, m (1 + c h') / h'^2). Kept for comparison on the benchmark's
front: with one sweep a substep, its stiff fabric is biased by a residual that falls as 1/S^2
and grows as N^2 (it becomes accurate only once a substep resolves the fabric's stretch wave).
A hand is one more constraint, its pull capped at its force."""

import math

from cloth.host import f64
from cloth.obstacles import project
from cloth.hands import keep_up
from cloth import air

# Its steps are position Verlet's, as XPBD's are (cloth/integrate.py, order 0): with one sweep
# a substep its solve is never finished, and BDF2, which damps what a step leaves unfinished
# less, let a stiff chain from rest reach hundreds of m/s.
ORDER = 0
# Whether its solve measures cloth.imbalance (the legend's "how far from balance"): XPBD's
# constraint sweeps do not compute the forces.
RESIDUAL = False
# Its sweeps know no contact's barrier: they take the contact as a constraint
# (obstacles.project), and the cloth moves by obstacles.accept after them.
BARRIER = False


def prepare(cloth):
    if len(cloth.lam) < cloth.n_edges or len(cloth.lam) == 0:
        cloth.lam = f64(cloth.n_edges if cloth.n_edges > 0 else 1)
        cloth.hand_lam = f64(cloth.n_verts)


def solve(cloth):
    pos = cloth.pos
    fixed = cloth.fixed
    mass = cloth.mass
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    lam = cloth.lam
    grip = cloth.grip
    m = cloth.n_edges
    ws = cloth.w_scale
    sqrt = math.sqrt
    # XPBD starts from the inertial target, where the constraints alone then pull it back
    # (an obstacle's push added: obstacles.begin).
    contact = cloth.n_obstacles > 0
    pred = cloth.pred
    for i in range(2 * cloth.n_verts):
        pos[i] = pred[i] + (cloth.start_pos[i] - cloth.prev[i] if contact else 0.0)
    for e in range(m):
        lam[e] = 0.0
    for h in range(cloth.n_gripped):
        cloth.hand_lam[cloth.gripped[h]] = 0.0
    for it in range(cloth.iterations):
        for e in range(m):
            a = ea[e]
            b = eb[e]
            wa = 0.0 if fixed[a] != 0 else 1.0 / (mass[a] * ws * (cloth.grip_w if grip[a] >= 0 else 1.0))
            wb = 0.0 if fixed[b] != 0 else 1.0 / (mass[b] * ws * (cloth.grip_w if grip[b] >= 0 else 1.0))
            if wa + wb == 0.0:
                continue
            ia = a + a
            ib = b + b
            dx = pos[ib] - pos[ia]
            dy = pos[ib + 1] - pos[ia + 1]
            d2 = dx * dx + dy * dy
            if d2 < 1e-30:
                continue
            if stiff[e] <= 0.0:
                continue              # no stiffness: no force (a scene's shear 0)
            length = sqrt(d2)
            alpha = 1.0 / stiff[e]
            c = length - rest[e]
            dl = (-c - alpha * lam[e]) / (wa + wb + alpha)
            if lam[e] + dl > 0.0:
                dl = -lam[e]
            lam[e] += dl
            s = dl / length
            pos[ia] -= dx * s * wa
            pos[ia + 1] -= dy * s * wa
            pos[ib] += dx * s * wb
            pos[ib + 1] += dy * s * wb
        for h in range(cloth.n_gripped):
            i = cloth.gripped[h]
            ii = i + i
            dx = pos[ii] - cloth.aim[ii]
            dy = pos[ii + 1] - cloth.aim[ii + 1]
            d = sqrt(dx * dx + dy * dy)
            if d < 1e-15:
                continue
            w = 1.0 / (mass[i] * ws * cloth.grip_w)
            alpha = 1.0 / cloth.grip_k[i]
            lo = -cloth.grip_f[i]
            dl = (-d - alpha * cloth.hand_lam[i]) / (w + alpha)
            if cloth.hand_lam[i] + dl < lo:
                dl = lo - cloth.hand_lam[i]
            cloth.hand_lam[i] += dl
            s = dl / d * w
            keep_up(cloth, i, pos[ii] + dx * s, pos[ii + 1] + dy * s, cloth.term)
            pos[ii] = cloth.term[0]
            pos[ii + 1] = cloth.term[1]
        if cloth.windy:
            air.project(cloth)
        if contact:
            project(cloth)
        cloth.sweeps += 1
