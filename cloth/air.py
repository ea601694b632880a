"""The air: wind (`wind`, `drag`, `gust`) as a term of the step's energy, implicit in the cloth's
velocity relative to the air.

Each structural edge of length L stands for a strip of cloth one spacing s wide, half of it on
the border (the rows' edges take the air across the rows, the columns' across the columns: per
area, as the key says; the diagonals stand for shear, not for more cloth). With a whole spacing
on the border too, a grid's border caught s / 2 more air per length than its cloth has: on the
Flag, a pull on its free edge that the coarse grids felt most, and their upper corner drooped
20 cm less than at 200x133. The air moving at w relative to the edge's
middle, whose velocity is v, pushes it across itself by D ((w - v) . n) n, D = drag L s, half on
each end. A force linear in the velocity the step ends with, v+ = (x+ - base) / h'
(cloth/integrate.py), is the gradient of a quadratic in the positions:
    Phi_e(x) = k_e / 2 (m_e . n - c_e)^2,   m_e = (x_a + x_b) / 2,   k_e = D / h',
    c_e = (base_a + base_b) / 2 . n + h' (w - u) . n
(u: what the integrator adds to (x+ - base) / h' to make its velocity, g h / 2 for the Verlet of
XPBD and the seed's method, 0 otherwise), with the edge's normal n and its length L taken where
the step began. Its force on each end is -k_e r n / 2 (r = m_e . n - c_e), its block k_e n n^T / 4
on each end and between them: convex, so the step stays one minimum, and the air can never push
the cloth past its own speed or make a stiff cloth flutter (felt once a frame as an explicit
impulse, a curtain in a steady wind never came to rest at the page's frame time, and a free
cloth was pushed 1e-4 m/s past the air). Under XPBD and the seed's method it is a compliant
constraint of compliance 1 / k_e (project): the same term, minimised their way.

Only in a scene whose air moves: still air costs nothing (its stages are not chosen). Gusts
scale the wind by 1 + amplitude * GUST_PEAK * p (1 - p) (1 - 2p), p the phase in the period: a
smooth wave from -1 to 1, polynomial so that both runtimes compute it to the bit.
"""

import math
from math import sqrt

from cloth.host import f64
from cloth.topology import along_border

GUST_PEAK = 6.0 * math.sqrt(3.0)


def prepare(cloth):
    """The term's per-edge arrays (a scene whose air moves)."""
    m = cloth.n_struct
    if len(cloth.air_k) >= m and len(cloth.air_k) > 0:
        return
    cloth.air_k = f64(m if m > 0 else 1)      # k_e
    cloth.air_n = f64(2 * m if m > 0 else 2)  # n
    cloth.air_c = f64(m if m > 0 else 1)      # c_e
    cloth.air_lam = f64(m if m > 0 else 1)    # its multiplier under project
    # The width of cloth each edge stands for, in spacings: half on the border, as its mass
    # and stretch are (the hem is more layers of the same area, not more area).
    cloth.air_w = f64(m if m > 0 else 1)
    for e in range(m):
        cloth.air_w[e] = 0.5 if along_border(cloth, cloth.edge_a[e], cloth.edge_b[e]) else 1.0


def gust(cloth, t):
    """The wind's factor at time t."""
    if cloth.scene.gust_amplitude <= 0.0:
        return 1.0
    q = t / cloth.scene.gust_period
    p = q - math.floor(q)
    return 1.0 + cloth.scene.gust_amplitude * GUST_PEAK * p * (1.0 - p) * (1.0 - 2.0 * p)


def begin(cloth):
    """The step's air (a stage after predict): each structural edge's k_e, n and c_e, from where
    the step began (prev) and the wind at the step's end."""
    f = gust(cloth, cloth.air_t + cloth.share * cloth.dt)
    wx = cloth.scene.wind_x * f
    wy = cloth.scene.wind_y * f
    hp = cloth.h_bdf
    # The velocity the step ends with is (x+ - base) / h' + u.
    ux = 0.5 * cloth.gravity_x * hp if cloth.order == 0 else 0.0
    uy = 0.5 * cloth.gravity_y * hp if cloth.order == 0 else 0.0
    base = cloth.base if cloth.order > 0 else cloth.prev
    prev = cloth.prev
    drag = cloth.scene.drag * cloth.spacing / hp
    for e in range(cloth.n_struct):
        a = cloth.edge_a[e] + cloth.edge_a[e]
        b = cloth.edge_b[e] + cloth.edge_b[e]
        # n L: the edge (b - a) where the step began, turned a quarter
        nx = prev[a + 1] - prev[b + 1]
        ny = prev[b] - prev[a]
        length = sqrt(nx * nx + ny * ny)
        if length < 1e-15 or (cloth.fixed[cloth.edge_a[e]] != 0 and cloth.fixed[cloth.edge_b[e]] != 0):
            cloth.air_k[e] = 0.0
            continue
        nx /= length
        ny /= length
        cloth.air_k[e] = drag * cloth.air_w[e] * length
        cloth.air_n[e + e] = nx
        cloth.air_n[e + e + 1] = ny
        cloth.air_c[e] = 0.5 * ((base[a] + base[b]) * nx + (base[a + 1] + base[b + 1]) * ny) + \
            hp * ((wx - ux) * nx + (wy - uy) * ny)
        cloth.air_lam[e] = 0.0


def frame_passed(cloth):
    """The air's clock, a frame on (a stage after the frame's steps)."""
    cloth.air_t += cloth.dt


def vertex_terms(cloth, i, x, y, acc):
    """acc[0..4] += the air's force and block at vertex i, at (x, y), the rest where it is."""
    pos = cloth.pos
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        e = cloth.adj_edge[q]
        if e >= cloth.n_struct or cloth.air_k[e] == 0.0:
            continue
        j = cloth.adj_other[q]
        nx = cloth.air_n[e + e]
        ny = cloth.air_n[e + e + 1]
        k = cloth.air_k[e]
        r = 0.5 * ((x + pos[j + j]) * nx + (y + pos[j + j + 1]) * ny) - cloth.air_c[e]
        acc[0] -= 0.5 * k * r * nx
        acc[1] -= 0.5 * k * r * ny
        acc[2] += 0.25 * k * nx * nx
        acc[3] += 0.25 * k * nx * ny
        acc[4] += 0.25 * k * ny * ny


def piece_push(cloth, acc):
    """For vbd.keep_momentum: each piece nothing holds, p, gets the air's whole force on it where
    the cloth is now (acc[6p + 1..2] +=) and its stiffness to a shift of the whole piece,
    sum_e k_e n_e n_e^T (acc[6p + 3..5] +=)."""
    pos = cloth.pos
    for e in range(cloth.n_struct):
        k = cloth.air_k[e]
        a = cloth.edge_a[e]
        if k == 0.0 or cloth.falling[a] == 0:
            continue
        b = cloth.edge_b[e]
        nx = cloth.air_n[e + e]
        ny = cloth.air_n[e + e + 1]
        r = 0.5 * ((pos[a + a] + pos[b + b]) * nx + (pos[a + a + 1] + pos[b + b + 1]) * ny) - cloth.air_c[e]
        p6 = 6 * cloth.piece[a]
        acc[p6 + 1] -= k * r * nx
        acc[p6 + 2] -= k * r * ny
        acc[p6 + 3] += k * nx * nx
        acc[p6 + 4] += k * nx * ny
        acc[p6 + 5] += k * ny * ny


def vertex_energy(cloth, i, x, y):
    """The air's terms that hold vertex i, with it at (x, y)."""
    pos = cloth.pos
    s = 0.0
    for q in range(cloth.adj_start[i], cloth.adj_start[i + 1]):
        e = cloth.adj_edge[q]
        if e >= cloth.n_struct or cloth.air_k[e] == 0.0:
            continue
        j = cloth.adj_other[q]
        r = 0.5 * ((x + pos[j + j]) * cloth.air_n[e + e] + (y + pos[j + j + 1]) * cloth.air_n[e + e + 1]) - \
            cloth.air_c[e]
        s += 0.5 * cloth.air_k[e] * r * r
    return s


def assemble(cloth, g, A, couple):
    """The air's terms in G's gradient g and Hessian A (terms.assemble; `couple` adds a term
    of two vertices to A)."""
    pos = cloth.pos
    for e in range(cloth.n_struct):
        k = cloth.air_k[e]
        if k == 0.0:
            continue
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        nx = cloth.air_n[e + e]
        ny = cloth.air_n[e + e + 1]
        r = 0.5 * ((pos[a + a] + pos[b + b]) * nx + (pos[a + a + 1] + pos[b + b + 1]) * ny) - cloth.air_c[e]
        g[a + a] += 0.5 * k * r * nx
        g[a + a + 1] += 0.5 * k * r * ny
        g[b + b] += 0.5 * k * r * nx
        g[b + b + 1] += 0.5 * k * r * ny
        couple(A, a, b, cloth.slot[e], 0.25 * k * nx * nx, 0.25 * k * nx * ny, 0.25 * k * ny * ny, 1.0)


def energy_along(cloth, d):
    """The air's terms of G at pos + alpha d, alpha = cloth.alpha."""
    pos = cloth.pos
    alpha = cloth.alpha
    s = 0.0
    for e in range(cloth.n_struct):
        k = cloth.air_k[e]
        if k == 0.0:
            continue
        a = cloth.edge_a[e] + cloth.edge_a[e]
        b = cloth.edge_b[e] + cloth.edge_b[e]
        r = 0.5 * ((pos[a] + alpha * d[a] + pos[b] + alpha * d[b]) * cloth.air_n[e + e] +
                   (pos[a + 1] + alpha * d[a + 1] + pos[b + 1] + alpha * d[b + 1]) * cloth.air_n[e + e + 1]) - \
            cloth.air_c[e]
        s += 0.5 * k * r * r
    return s


def project(cloth):
    """The air as a compliant constraint of XPBD's and the seed's sweeps: C_e = r, of compliance
    1 / k_e, its gradient n / 2 at each end, each end moved by its inverse inertia weight
    (XPBD's update, Macklin et al. 2016: d_lambda = (-C - lambda / k) / (sum w |grad C|^2 + 1 / k))."""
    pos = cloth.pos
    for e in range(cloth.n_struct):
        k = cloth.air_k[e]
        if k == 0.0:
            continue
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        wa = 0.0 if cloth.fixed[a] != 0 else 1.0 / (cloth.mass[a] * cloth.w_scale)
        wb = 0.0 if cloth.fixed[b] != 0 else 1.0 / (cloth.mass[b] * cloth.w_scale)
        nx = cloth.air_n[e + e]
        ny = cloth.air_n[e + e + 1]
        r = 0.5 * ((pos[a + a] + pos[b + b]) * nx + (pos[a + a + 1] + pos[b + b + 1]) * ny) - cloth.air_c[e]
        dl = (-r - cloth.air_lam[e] / k) / (0.25 * (wa + wb) + 1.0 / k)
        cloth.air_lam[e] += dl
        pos[a + a] += 0.5 * wa * dl * nx
        pos[a + a + 1] += 0.5 * wa * dl * ny
        pos[b + b] += 0.5 * wb * dl * nx
        pos[b + b + 1] += 0.5 * wb * dl * ny
