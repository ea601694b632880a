"""The cloth's energy, piece by piece, and the one thing a step may not do with it: raise it
when nothing drives the cloth.

A piece's energy is its free vertices' kinetic energy m |v|^2 / 2 and gravitational -m g . x,
and its taut springs' k (L - L0)^2 / 2 (a fixed vertex's parts are constant: nothing moves it
but a hand). Pieces (topology.label_pieces) share no spring, so each keeps its own account.

No gain. A backward-Euler step solved exactly never raises the energy of a cloth nothing
drives: its positions minimise G(x) = sum m |x - x0 - h v0|^2 / 2h^2 + U(x) (integrate.py),
so m (v - v0) / h = -grad U(x) - c m v, and U convex (tension-only springs, gravity) gives
U(x0) >= U(x) + grad U(x) . (x0 - x) = U(x) + m (v - v0) . v + c h m |v|^2, hence
KE + U after <= KE + U before. An unfinished solve keeps no such promise: a curtain lifted by
its hem at 3 m/s and let go, its lower half slack and folding, gained up to 23% of the energy
it moved with within half a second (24x24; 19% on a 60x60 towel; the solve run to the end,
1000 sweeps, loses 20-46%). The steps the integrator takes by backward Euler are those after a
solve left the cloth off balance (integrate.UNBALANCED), the ones in which that happens; on
those, when no hand, wind or moving obstacle does work, a step that raised a piece's energy is
solved once more, and a piece whose energy still rose gives the gain back from its motion: its
vertices' velocities scaled by sqrt((KE - gain) / KE) (a piece nothing holds: their velocities
relative to its centre of mass, so that its momentum, which the exact step keeps, stays). The
positions the solve found stay. BDF2 steps (the cloth near balance) are left alone: their
energy is not monotone even when solved exactly (a swing's energy ripples within the period).
"""

import math

from cloth.integrate import next_order
from cloth.obstacles import obstacles_still
from cloth.terms import spring_energy


def by_piece(cloth):
    """cloth.piece_energy[3 p], [3 p + 1], [3 p + 2]: piece p's kinetic, elastic and
    gravitational energy now, in joules."""
    out = cloth.piece_energy
    piece = cloth.piece
    for t in range(3 * cloth.n_pieces):
        out[t] = 0.0
    pos = cloth.pos
    vel = cloth.vel
    mass = cloth.mass
    fixed = cloth.fixed
    gx = cloth.gravity_x
    gy = cloth.gravity_y
    for k in range(cloth.n_verts):
        if fixed[k] != 0:
            continue
        m = mass[k]
        vx = vel[k + k]
        vy = vel[k + k + 1]
        p3 = 3 * piece[k]
        out[p3] += 0.5 * m * (vx * vx + vy * vy)
        out[p3 + 2] -= m * (gx * pos[k + k] + gy * pos[k + k + 1])
    edge_a = cloth.edge_a
    edge_b = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    for e in range(cloth.n_edges):
        a = edge_a[e]
        b = edge_b[e]
        out[3 * piece[a] + 1] += spring_energy(stiff[e], rest[e], pos[b + b] - pos[a + a],
                                               pos[b + b + 1] - pos[a + a + 1])


def take_stock(cloth):
    """Before a step (its stage before the integrator's predict): each piece's energy, if the
    step is one whose gain no_gain takes back (the module's comment)."""
    cloth.stock = 0
    if cloth.n_gripped > 0 or next_order(cloth) != 1:
        return
    if cloth.n_obstacles > 0 and not obstacles_still(cloth):
        return
    by_piece(cloth)
    e = cloth.piece_energy
    before = cloth.energy_before
    touched = cloth.piece_touched
    for p in range(cloth.n_pieces):
        before[p] = e[3 * p] + e[3 * p + 1] + e[3 * p + 2]
        touched[p] = 0
    cloth.stock = 1


def no_gain(cloth):
    """After the step (its stage after the integrator's finish): a step that raised a piece's
    energy is unfinished, and is solved once more from where it stopped (the step's stages from
    the solve to the finish again: cloth.again_stages); a piece whose energy still rose gives
    the gain back from its motion (the module's comment). Once more, not never: a 200x1 chain
    whose end was lifted at 3 m/s and let go, its end outrunning the slack vertex next to it,
    gained more in the first step than it moved with, and stopped dead (91% of its energy
    lost at once, 8% solved to the end); solved once more, 12%, and three times 12%."""
    if cloth.stock == 0 or not gained(cloth):
        return
    stages = cloth.again_stages
    for i in range(len(stages)):
        stages[i](cloth)
    if gained(cloth):
        give_back(cloth)


def gained(cloth):
    """Whether the step raised the energy of a piece no obstacle is near (contact.lag_friction
    marks those in piece_touched: outside an obstacle is not a convex set, and the module's
    argument says nothing of a piece that touches one), with each piece's energy now in
    piece_energy."""
    by_piece(cloth)
    touched = cloth.piece_touched
    e = cloth.piece_energy
    before = cloth.energy_before
    for p in range(cloth.n_pieces):
        if touched[p] == 0 and e[3 * p] + e[3 * p + 1] + e[3 * p + 2] > before[p]:
            return True
    return False


def give_back(cloth):
    """Each piece that gained (gained() measured it) gives the gain back from its kinetic
    energy: all of it, or a piece nothing holds from its motion about its centre of mass,
    whose momentum the exact step keeps (vbd.py keep_momentum), so its velocity P / M stays."""
    e = cloth.piece_energy
    scale = cloth.energy_before
    motion = cloth.piece_motion
    touched = cloth.piece_touched
    n = cloth.n_verts
    vel = cloth.vel
    piece = cloth.piece
    mass = cloth.mass
    fixed = cloth.fixed
    falling = cloth.falling
    for t in range(3 * cloth.n_pieces):
        motion[t] = 0.0
    for k in range(n):
        if falling[k] != 0:
            p3 = 3 * piece[k]
            m = mass[k]
            motion[p3] += m
            motion[p3 + 1] += m * vel[k + k]
            motion[p3 + 2] += m * vel[k + k + 1]
    for p in range(cloth.n_pieces):
        p3 = 3 * p
        gain = e[p3] + e[p3 + 1] + e[p3 + 2] - scale[p]
        kinetic = e[p3]
        if motion[p3] > 0.0:
            px = motion[p3 + 1]
            py = motion[p3 + 2]
            kinetic -= 0.5 * (px * px + py * py) / motion[p3]
            motion[p3 + 1] = px / motion[p3]
            motion[p3 + 2] = py / motion[p3]
        scale[p] = 1.0
        if gain > 0.0 and kinetic > 0.0 and touched[p] == 0:
            scale[p] = math.sqrt(max(kinetic - gain, 0.0) / kinetic)
    for k in range(n):
        if fixed[k] != 0:
            continue
        p = piece[k]
        s = scale[p]
        if s == 1.0:
            continue
        vx = 0.0
        vy = 0.0
        if falling[k] != 0:
            vx = motion[3 * p + 1]
            vy = motion[3 * p + 2]
        vel[k + k] = vx + s * (vel[k + k] - vx)
        vel[k + k + 1] = vy + s * (vel[k + k + 1] - vy)
