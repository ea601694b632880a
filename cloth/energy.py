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
those, when no wind or moving obstacle does work, a step that raised the energy of a piece no
hand holds is solved once more, and a piece whose energy still rose gives the gain back from its motion: its
vertices' velocities scaled by sqrt((KE - gain) / KE) (a piece nothing holds: their velocities
relative to its centre of mass, so that its momentum, which the exact step keeps, stays). The
positions the solve found stay. BDF2 steps (the cloth near balance) are left alone: their
energy is not monotone even when solved exactly (a swing's energy ripples within the period).
"""

import math

from cloth.integrate import next_order
from cloth.obstacles import obstacles_still
from cloth.ccd import move_clear
from cloth.contact import barrier_by_piece
from cloth.terms import spring_energy


def by_piece(cloth):
    """cloth.piece_energy[3 p], [3 p + 1], [3 p + 2]: piece p's kinetic, elastic (its springs'
    and the contact's barrier) and gravitational energy now, in joules."""
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
    if cloth.n_obstacles > 0:
        barrier_by_piece(cloth, pos, out, 3, 1)


def motion(cloth):
    """cloth.piece_motion[3 p], [3 p + 1..2]: each piece nothing holds's mass and momentum now
    (0 for the others, and for every piece where there are obstacles: one may push it, and the
    step keeps no piece's momentum there, vbd.solve)."""
    out = cloth.piece_motion
    for t in range(3 * cloth.n_pieces):
        out[t] = 0.0
    if cloth.n_obstacles > 0:
        return
    vel = cloth.vel
    for k in range(cloth.n_verts):
        if cloth.falling[k] != 0:
            p3 = 3 * cloth.piece[k]
            m = cloth.mass[k]
            out[p3] += m
            out[p3 + 1] += m * vel[k + k]
            out[p3 + 2] += m * vel[k + k + 1]


def own_energy(cloth, p):
    """The energy of piece p that the step's account holds it to (by_piece and motion measured
    it): its whole energy, or for a piece nothing holds, its energy about its centre of mass,
    kinetic (relative to the centre) and elastic: the centre's own motion is the exact step's
    (vbd.keep_momentum)."""
    e = cloth.piece_energy
    p3 = 3 * p
    m = cloth.piece_motion[p3]
    if m > 0.0:
        px = cloth.piece_motion[p3 + 1]
        py = cloth.piece_motion[p3 + 2]
        return e[p3] - 0.5 * (px * px + py * py) / m + e[p3 + 1]
    return e[p3] + e[p3 + 1] + e[p3 + 2]


def take_stock(cloth):
    """Before a step (its stage before the integrator's predict): each piece's energy, if the
    step is one whose gain no_gain takes back (the module's comment)."""
    cloth.stock = 0
    if next_order(cloth) != 1:
        return
    if cloth.n_obstacles > 0 and not obstacles_still(cloth):
        return
    by_piece(cloth)
    motion(cloth)
    before = cloth.energy_before
    touched = cloth.piece_touched
    for p in range(cloth.n_pieces):
        before[p] = own_energy(cloth, p)
        touched[p] = 0
    # A piece a hand holds is driven (the hand does work): it is left alone, the others not (a
    # piece torn free while a hand held another gained 5.5 J within five steps, its unfinished
    # solves stretching it further each step).
    for h in range(cloth.n_gripped):
        touched[cloth.piece[cloth.gripped[h]]] = 1
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
    """Whether the step raised the energy of a piece no hand holds (take_stock marks those 1 in
    piece_touched), with each piece's energy now in piece_energy and its motion in
    piece_motion. A piece near an obstacle is held to it too: a still obstacle does no work,
    and its barrier is a term of the potential (by_piece), though outside an obstacle is not a
    convex set and the module's argument does not bound that step (a towel's clamp and peg
    yanked down 1 m in a frame, the peg then still, raised the towel's energy from 106 J to
    328 J in two steps, 1.5 to 17 kJ at 60x60, and flung its corners at 245 m/s). A piece nothing holds is held to more: the
    exact step's still air takes c h sum m |v - v_centre|^2 of its energy about its centre
    (the module's argument, about the centre), so it comes to rest relative to itself as a
    cloth does in air (its solve left unfinished by a spin, a piece of seven vertices torn off
    tissue kept 5 m/s about its centre for good, each step's gain given back to the bit)."""
    by_piece(cloth)
    motion(cloth)
    touched = cloth.piece_touched
    for p in range(cloth.n_pieces):
        if touched[p] != 1 and own_energy(cloth, p) > allowed(cloth, p):
            return True
    return False


def allowed(cloth, p):
    """The most energy piece p may have after the step (gained)."""
    m = cloth.piece_motion[3 * p]
    if m <= 0.0:
        return cloth.energy_before[p]
    px = cloth.piece_motion[3 * p + 1]
    py = cloth.piece_motion[3 * p + 2]
    inner = 2.0 * cloth.piece_energy[3 * p] - (px * px + py * py) / m
    return cloth.energy_before[p] - cloth.damping * cloth.h_bdf * inner


def give_back(cloth):
    """Each piece that gained (gained() measured it) gives the gain back from its kinetic
    energy: all of it, or a piece nothing holds from its motion about its centre of mass,
    whose momentum the exact step keeps (vbd.py keep_momentum), so its velocity P / M stays."""
    e = cloth.piece_energy
    scale = cloth.energy_before
    motion_ = cloth.piece_motion
    touched = cloth.piece_touched
    n = cloth.n_verts
    vel = cloth.vel
    piece = cloth.piece
    fixed = cloth.fixed
    falling = cloth.falling
    short = cloth.piece_sum
    any_short = False
    for p in range(cloth.n_pieces):
        p3 = 3 * p
        before = scale[p]
        gain = own_energy(cloth, p) - allowed(cloth, p)
        kinetic = e[p3]
        if motion_[p3] > 0.0:
            px = motion_[p3 + 1]
            py = motion_[p3 + 2]
            kinetic -= 0.5 * (px * px + py * py) / motion_[p3]
            motion_[p3 + 1] = px / motion_[p3]
            motion_[p3 + 2] = py / motion_[p3]
        scale[p] = 1.0
        short[6 * p] = 0.0
        if gain > 0.0 and touched[p] != 1:
            if kinetic > gain:
                scale[p] = math.sqrt((kinetic - gain) / kinetic)
            else:
                # Its motion cannot pay the gain: the rest comes from the positions
                # (fall_back), from what it has once its motion is all spent.
                scale[p] = 0.0
                short[6 * p] = 1.0
                short[6 * p + 1] = before
                short[6 * p + 2] = own_energy(cloth, p) - max(kinetic, 0.0)
                any_short = True
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
            vx = motion_[3 * p + 1]
            vy = motion_[3 * p + 2]
        vel[k + k] = vx + s * (vel[k + k] - vx)
        vel[k + k + 1] = vy + s * (vel[k + k + 1] - vy)
    if any_short:
        fall_back(cloth)


def fall_back(cloth):
    """The pieces give_back marked in piece_sum (6 p: 1; 6 p + 1: the energy the piece may keep;
    6 p + 2: what its positions hold, its motion about its centre spent) whose motion could not
    pay what the step raised: each such piece takes, of the solve's move, the part its energy
    allows (its motion spent, it may keep what it had: allowed() with no motion about the
    centre). Its own energy at the step's start positions moved with its centre (prev + s, s the
    centre's move: the energy about the centre does not see it; 0 where motion() measures
    none), E0, is at most what it had, and that at the solve's, E1, more than it may keep, E*;
    the springs' and gravity's energy is convex and the move affine, so along
    x(a) = prev + s + a (x - prev - s) it is at most (1 - a) E0 + a E1, and
    a = (E* - E0) / (E1 - E0) keeps it within E*. Where there are obstacles the barrier is not
    convex, nor the straight way clear: each vertex goes from where the step began toward its
    x(a) only as far as its edges sweep no obstacle (ccd.move_clear), and a piece that still
    has more than E* stays where the step began. Seen on tissue torn by random gestures: an
    11-vertex piece freed between two steps and a 368-vertex one kept 0.9 mJ and 38 mJ each
    step gave, their solve stretching them more than their motion held."""
    short = cloth.piece_sum
    pos = cloth.pos
    prev = cloth.prev
    fixed = cloth.fixed
    piece = cloth.piece
    mass = cloth.mass
    motion_ = cloth.piece_motion
    n = cloth.n_verts
    # The centres' moves (6 p + 3: mass, 6 p + 4..5: the move), then E0 in 6 p + 3.
    for p in range(cloth.n_pieces):
        p6 = 6 * p
        short[p6 + 3] = 0.0
        short[p6 + 4] = 0.0
        short[p6 + 5] = 0.0
    for k in range(n):
        p = piece[k]
        p6 = 6 * p
        if fixed[k] != 0 or motion_[3 * p] <= 0.0 or short[p6] == 0.0:
            continue
        m = mass[k]
        short[p6 + 3] += m
        short[p6 + 4] += m * (pos[k + k] - prev[k + k])
        short[p6 + 5] += m * (pos[k + k + 1] - prev[k + k + 1])
    for p in range(cloth.n_pieces):
        p6 = 6 * p
        if short[p6 + 3] > 0.0:
            short[p6 + 4] /= short[p6 + 3]
            short[p6 + 5] /= short[p6 + 3]
        short[p6 + 3] = 0.0
    gx = cloth.gravity_x
    gy = cloth.gravity_y
    for k in range(n):
        p = piece[k]
        p6 = 6 * p
        if fixed[k] != 0 or motion_[3 * p] > 0.0 or short[p6] == 0.0:
            continue
        short[p6 + 3] -= mass[k] * (gx * prev[k + k] + gy * prev[k + k + 1])
    edge_a = cloth.edge_a
    edge_b = cloth.edge_b
    rest = cloth.rest
    stiff = cloth.stiff
    for e in range(cloth.n_edges):
        a = edge_a[e]
        p6 = 6 * piece[a]
        if short[p6] == 0.0:
            continue
        b = edge_b[e]
        short[p6 + 3] += spring_energy(stiff[e], rest[e], prev[b + b] - prev[a + a],
                                       prev[b + b + 1] - prev[a + a + 1])
    contact = cloth.n_obstacles > 0
    if contact:
        barrier_by_piece(cloth, prev, short, 6, 3)
    for p in range(cloth.n_pieces):
        p6 = 6 * p
        if short[p6] == 0.0:
            continue
        e0 = short[p6 + 3]
        e1 = short[p6 + 2]
        a = 0.0
        if e1 > e0:
            a = min(max((short[p6 + 1] - e0) / (e1 - e0), 0.0), 1.0)
        short[p6 + 2] = a
    # x(a) in cloth.guess where there are obstacles, the piece put back where the step began.
    target = cloth.guess if contact else pos
    for k in range(n):
        p6 = 6 * piece[k]
        if fixed[k] != 0 or short[p6] == 0.0:
            continue
        a = short[p6 + 2]
        sx = short[p6 + 4]
        sy = short[p6 + 5]
        i = k + k
        target[i] = prev[i] + sx + a * (pos[i] - prev[i] - sx)
        target[i + 1] = prev[i + 1] + sy + a * (pos[i + 1] - prev[i + 1] - sy)
        if contact:
            pos[i] = prev[i]
            pos[i + 1] = prev[i + 1]
    if not contact:
        return
    for k in range(n):
        if fixed[k] != 0 or short[6 * piece[k]] == 0.0:
            continue
        move_clear(cloth, k, target[k + k], target[k + k + 1])
    by_piece(cloth)
    for k in range(n):
        p = piece[k]
        if fixed[k] != 0 or short[6 * p] == 0.0 or \
                own_energy(cloth, p) <= short[6 * p + 1]:
            continue
        pos[k + k] = prev[k + k]
        pos[k + k + 1] = prev[k + k + 1]
