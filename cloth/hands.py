"""Hands and pins.

A hand holds a patch, with a finite force. It grips the vertex a person took hold of and the
vertices within HAND_RADIUS of it along the cloth, each by a spring to where the hand holds it
(the hand's position plus the vertex's offset from the held one when it took hold) that pulls
with k d / sqrt(1 + (d / r)^2): k = HAND_STIFFNESS / count near the hand, levelling off at
f = HAND_FORCE / count far from it (r = f / k; a pseudo-Huber energy, f r (sqrt(1 + (d/r)^2)
- 1): convex and smooth, so the step's energy stays convex and its Newton steps stay good,
cloth/vbd.py). These springs are part of the fabric's step, solved with it: within reach the
held vertex ends every step where the hand is (1 mm off while it pulls with a fifth of its
force), and beyond it the hand pulls with up to HAND_FORCE and the fabric stretches as far as
that force takes it, no farther. Why a patch: a
point force strains a 2D continuum as 1 / r, so a grid's edge at a point grip strains more the
finer the grid; a patch of fixed size does not (cloth/fabrics.py).

A pin is fixed in space. A hand that takes hold of a pin holds the pins and the cloth within
its radius (a clamp and the cloth at it), moving them with the same force; letting go leaves
the pins fixed where they are. Letting go removes the springs and nothing else: the cloth keeps
the motion it has, and the stretch the hand left returns as the fabric's own motion.
"""

import math

from cloth.values import SceneError
from cloth.topology import walk_grip, label_pieces
from cloth.integrate import rest_at, restart_at
from cloth.terms import inertia_weight, hand_energy, spring_energy
from cloth.obstacles import fasten

# A person's pull: enough to lift and carry every preset's cloth in the heaviest fabric the
# page offers (the Large cloth, 2 x 2 m of denim, weighs 16 N) and a little more, not so much
# that a pull beyond reach stores more stretch than a release lets go as a gentle snap.
HAND_FORCE = 20.0
# A hand's grip: the vertices within this distance of the held one along the cloth.
HAND_RADIUS = 0.02
# A clamp's width: how much of an edge a preset's clamp holds, and the pins a hand on a pin
# carries with it (a clamp moves whole). Six centimetres, two vertices of Two corners at 30x30:
# a clamp held by one vertex is a pivot at 30x30 and 60x60 and a clamp from 120x120 on, and the
# woven fabrics' fields then differed 50-110% from 120x120's; resolved at every size, 13-19% at
# 60x60 and 40-44% at 30x30, near the clamps' ends (python -m bench --fabrics).
CLAMP = 0.06
# Its springs' stiffness near the hand, all together: the pull is HAND_STIFFNESS times the
# distance up to about HAND_FORCE / HAND_STIFFNESS = 5 mm (the vertex is 1 mm off the hand
# while it pulls with a fifth of its force), and levels off at HAND_FORCE beyond.
HAND_STIFFNESS = HAND_FORCE / 0.005
# A grip is damped: each gripped vertex's motion relative to the hand loses this much of itself
# per second, as a damper in the step (implicit, like still air's damping: it only ever takes
# energy away). A pull at the hand's full force is a constant pull toward the pointer, and
# without it a free vertex held so orbits the pointer for good under the lightly damped
# solvers (measured: XPBD, a 2x1 cloth's vertex 0.4-1.25 m off after 10 s). Proportional to
# the gripped mass, it adds at most 5 s^-1 x 0.03 kg x 5 m/s = 1 N to a fast flick's pull.
HAND_DAMPING = 5.0
# A hand moves what it holds at its own speed and catches up with it at most this much faster
# (m/s). Beyond its reach the hand's pull is a constant HAND_FORCE, and held back by heavy cloth
# its patch lags the pointer (the hand's intent) by as much as the pull cannot make up; when
# the cloth behind it tears away, that pull on a patch of a few grams covers the whole lag in
# one step: a tissue's corner torn off while a hand dragged it at 23 m/s flew at 51 m/s, where
# a hand, which has a mass of its own, follows its pointer no faster than an arm moves (5 m/s:
# what the releases' bench holds a cloth let go to, and a hand's quick move; a hand that takes
# hold 0.3 m from its vertex has it in four frames).
HAND_CATCH_UP = 5.0


def check_vertex(cloth, k):
    if not (k >= 0 and k < cloth.n_verts and k == (k // 1)):
        raise SceneError('vertex: must be an index from 0 to cols * rows - 1')


def check_point(x, y):
    if not (x > -1e9 and x < 1e9 and y > -1e9 and y < 1e9):
        raise SceneError('to: must be finite and within 1e9 of the origin')


def grab(cloth, k, x, y):
    """A hand takes hold of vertex k and holds it at (x, y)."""
    check_vertex(cloth, k)
    check_point(x, y)
    if cloth.held[k] == 0:
        cloth.n_held += 1
    cloth.held[k] = 1
    cloth.target[k + k] = x
    cloth.target[k + k + 1] = y
    cloth.hand_from[k + k] = x
    cloth.hand_from[k + k + 1] = y
    cloth.hold_from[k + k] = x
    cloth.hold_from[k + k + 1] = y
    cloth.hand_acted[k] = 0
    regrip(cloth)
    wake(cloth)


def move(cloth, k, x, y):
    """The hand holding k goes to (x, y) by the end of the next frame."""
    check_vertex(cloth, k)
    if cloth.held[k] == 0:
        raise SceneError('vertex: move needs a held vertex (grab it first)')
    check_point(x, y)
    if x == cloth.target[k + k] and y == cloth.target[k + k + 1]:
        return  # a hand held still changes nothing, and must not keep the cloth awake
    cloth.target[k + k] = x
    cloth.target[k + k + 1] = y
    wake(cloth)


def move_by(cloth, k, dx, dy):
    """The hand holding k goes (dx, dy) from where it took hold (compare mode: every panel's
    hand moves by the pointer's displacement)."""
    check_vertex(cloth, k)
    move(cloth, k, cloth.hold_from[k + k] + dx, cloth.hold_from[k + k + 1] + dy)


def release(cloth, k):
    """Let go of k: its hand's springs go; a pin it held stays where it is."""
    check_vertex(cloth, k)
    if cloth.held[k] == 1:
        cloth.n_held -= 1
    cloth.held[k] = 0
    # The hand's pull is in the BDF2 history of what it gripped (the last step's velocity
    # change), which the next step would extrapolate: a chain's end held still for a frame
    # and let go swung 50% of its energy higher. That history starts again from the velocity
    # now (kept as it is); a tap, with no frame under the hand, leaves it untouched.
    if cloth.hand_acted[k] != 0:
        for h in range(cloth.n_gripped):
            v = cloth.gripped[h]
            if cloth.grip[v] == k:
                restart_at(cloth, v)
    regrip(cloth)
    wake(cloth)


def pin(cloth, k):
    check_vertex(cloth, k)
    cloth.pinned[k] = 1
    regrip(cloth)
    wake(cloth)


def unpin(cloth, k):
    check_vertex(cloth, k)
    cloth.pinned[k] = 0
    regrip(cloth)
    wake(cloth)


def toggle_pin(cloth, k):
    check_vertex(cloth, k)
    if cloth.pinned[k] == 1:
        unpin(cloth, k)
    else:
        pin(cloth, k)


def carry(cloth, k, x, y):
    """A script's clamp: vertex k (pinned, if it was not) and the pins within CLAMP of it along
    the cloth go rigidly, evenly over the next frame, so that k is at (x, y) at its end
    (carry_pins). Kinematic: what a script fixes is where the script says, at every grid,
    however the cloth pulls (carried by a hand of finite force, Two corners' right clamp ended
    1-6.7 mm low and bent, and the denim field 26% off the statics of the scene as written).
    A person's hand is a hand (grab)."""
    check_vertex(cloth, k)
    check_point(x, y)
    if cloth.pinned[k] == 0:
        pin(cloth, k)
    # From where the clamp is going (a carry this frame already sent it) or where it is.
    kk = k + k
    fx = cloth.script_to[kk] if cloth.scripted[k] != 0 else cloth.pos[kk]
    fy = cloth.script_to[kk + 1] if cloth.scripted[k] != 0 else cloth.pos[kk + 1]
    dx = x - fx
    dy = y - fy
    found = walk_grip(cloth, k, CLAMP * (1.0 + 1e-9), cloth.grip_dist, cloth.grip_list)
    for j in range(found):
        v = cloth.grip_list[j]
        if cloth.pinned[v] == 0 or cloth.fixed[v] == 0:
            continue
        vv = v + v
        if cloth.scripted[v] == 0:
            cloth.scripted[v] = 1
            cloth.script_from[vv] = cloth.pos[vv]
            cloth.script_from[vv + 1] = cloth.pos[vv + 1]
            cloth.script_to[vv] = cloth.pos[vv]
            cloth.script_to[vv + 1] = cloth.pos[vv + 1]
        cloth.script_to[vv] += dx
        cloth.script_to[vv + 1] += dy
    cloth.n_scripted = 1
    wake(cloth)


def carry_pins(cloth):
    """Before a step: each pin a script carries goes its share (cloth.share) of the way from
    where it was at the frame's start to where it is going."""
    if cloth.n_scripted == 0:
        return
    share = cloth.share
    for v in range(cloth.n_verts):
        if cloth.scripted[v] == 0 or cloth.fixed[v] == 0:
            continue
        vv = v + v
        for t in range(2):
            start = cloth.script_from[vv + t]
            end = cloth.script_to[vv + t]
            cloth.pos[vv + t] = end if share == 1.0 else start + (end - start) * share


def pins_arrived(cloth):
    """At a frame's end the carried pins are where they were going: the next frame starts
    there, and a pin no script moves any more is left alone."""
    if cloth.n_scripted == 0:
        return
    for v in range(cloth.n_verts):
        if cloth.scripted[v] != 0:
            cloth.scripted[v] = 0
    cloth.n_scripted = 0


def wake(cloth):
    cloth.asleep = False
    cloth.still_frames = 0


def near(cloth, k, v, r):
    """Whether vertex v is within r of vertex k (straight)."""
    dx = cloth.pos[v + v] - cloth.pos[k + k]
    dy = cloth.pos[v + v + 1] - cloth.pos[k + k + 1]
    return dx * dx + dy * dy <= r * r * (1.0 + 1e-9)


def regrip(cloth):
    """The grips after any change of holds, pins or edges: each held vertex, in index order,
    grips itself and what is within HAND_RADIUS of it that no earlier hand grips (a hand on a
    free vertex only free vertices; a hand on a pin pins too, and the pins of its clamp, within
    CLAMP along the cloth); then who is fixed. A vertex
    that starts or stops being fixed starts from rest."""
    n = cloth.n_verts
    grip = cloth.grip
    for k in range(n):
        grip[k] = -1
    count = 0
    for k in range(n):
        if cloth.held[k] == 0 or grip[k] >= 0:
            continue
        on_pin = cloth.pinned[k] != 0
        reach = CLAMP if on_pin and CLAMP > HAND_RADIUS else HAND_RADIUS
        found = walk_grip(cloth, k, reach * (1.0 + 1e-9), cloth.grip_dist, cloth.grip_list)
        kept = 0
        for j in range(found):
            v = cloth.grip_list[j]
            if v != k and (grip[v] >= 0 or cloth.held[v] != 0 or
                           (cloth.pinned[v] != 0 and not on_pin)):
                continue
            if v != k and cloth.pinned[v] == 0 and not near(cloth, k, v, HAND_RADIUS):
                continue                          # beyond the hand, only its clamp's pins
            cloth.grip_list[kept] = v
            kept += 1
        for j in range(kept):
            v = cloth.grip_list[j]
            grip[v] = k
            cloth.offset[v + v] = cloth.pos[v + v] - cloth.pos[k + k]
            cloth.offset[v + v + 1] = cloth.pos[v + v + 1] - cloth.pos[k + k + 1]
            cloth.grip_k[v] = HAND_STIFFNESS / kept
            cloth.grip_f[v] = HAND_FORCE / kept
            cloth.gripped[count] = v
            count += 1
    cloth.n_gripped = count
    refix(cloth)


def refix(cloth):
    """fixed = pinned and in no hand; inv_mass; which vertices fall freely (their piece has no
    fixed vertex and no hand: integrate.predict's guess); the weight the imbalance is measured
    against; whether the coarse operators are stale (the fixed vertices or the grips are not
    those they were made for: a hand that takes hold and lets go between two frames leaves
    them as they were, and changes nothing at all)."""
    g2 = cloth.gravity_x * cloth.gravity_x + cloth.gravity_y * cloth.gravity_y
    if g2 < 9.81 * 9.81:
        g2 = 9.81 * 9.81     # in weak or no gravity, the imbalance is still against 1 g
    cloth.g_ref = math.sqrt(g2)
    load2 = 0.0
    for k in range(cloth.n_verts):
        fixed = 1 if cloth.pinned[k] != 0 and cloth.grip[k] < 0 else 0
        if fixed != cloth.fixed[k]:
            cloth.fixed[k] = fixed
            rest_at(cloth, k)
        if fixed != 0:
            cloth.inv_mass[k] = 0.0
        else:
            cloth.inv_mass[k] = 1.0 / cloth.mass[k]
            if cloth.grip[k] < 0:
                load2 += cloth.mass[k] * cloth.mass[k] * g2
    cloth.load2 = load2
    count = label_pieces(cloth)
    cloth.n_pieces = count
    held = cloth.piece_held
    for p in range(count):
        held[p] = 0
    for k in range(cloth.n_verts):
        if cloth.fixed[k] != 0 or cloth.grip[k] >= 0:
            held[cloth.piece[k]] = 1
    changed = 0
    for k in range(cloth.n_verts):
        cloth.falling[k] = 1 - held[cloth.piece[k]]
        cloth.flying[k] = cloth.falling[k]
        # A piece nothing holds carries no load for the coarse grids to spread: its guess is
        # its fall and its sweeps do the rest (coarse.py).
        cloth.uncorrected[k] = 1 if cloth.fixed[k] != 0 or cloth.falling[k] != 0 else 0
        if cloth.uncorrected[k] != cloth.mg_uncorrected[k] or cloth.grip[k] != cloth.mg_grip[k]:
            changed = 1
    cloth.mg_changed = changed
    fasten(cloth)


def aim_hands(cloth):
    """Where each gripped vertex's spring pulls it this step: the hand cloth.share of the way
    from where it was at the frame's start to where it is going."""
    share = cloth.share
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        k = cloth.grip[v]
        kk = k + k
        x = cloth.hand_from[kk] + (cloth.target[kk] - cloth.hand_from[kk]) * share
        y = cloth.hand_from[kk + 1] + (cloth.target[kk + 1] - cloth.hand_from[kk + 1]) * share
        cloth.aim[v + v] = x + cloth.offset[v + v]
        cloth.aim[v + v + 1] = y + cloth.offset[v + v + 1]


def hold(cloth):
    """After predict: each gripped vertex's inertial target with the grip's damper in it,
    v+ (1 + (c + b) h') = u + h' (f / m + b v_hand), b = HAND_DAMPING (integrate.py's form with
    the damper's pull toward the hand's velocity; u = 4/3 v - 1/3 v-, or v under backward
    Euler), the factor its inertia weight takes (cloth.grip_w: the solvers multiply by it), and
    its first guess (guess_grip)."""
    if cloth.n_gripped == 0:
        return
    hp = cloth.h_bdf
    keep = cloth.keep
    held = 1.0 / (1.0 + (cloth.damping + HAND_DAMPING) * hp)
    cloth.grip_w = keep / held
    gx = keep * cloth.gravity_x * hp * hp
    gy = keep * cloth.gravity_y * hp * hp
    inv_dt = 1.0 / cloth.dt
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        if cloth.fixed[v] != 0:
            continue
        k = cloth.grip[v]
        kk = k + k
        hx = (cloth.target[kk] - cloth.hand_from[kk]) * inv_dt
        hy = (cloth.target[kk + 1] - cloth.hand_from[kk + 1]) * inv_dt
        i = v + v
        ux = (cloth.pred[i] - cloth.base[i] - gx) / (keep * hp)
        uy = (cloth.pred[i + 1] - cloth.base[i + 1] - gy) / (keep * hp)
        cloth.pred[i] = cloth.base[i] + hp * held * (ux + hp * HAND_DAMPING * hx) + gx * held / keep
        cloth.pred[i + 1] = cloth.base[i + 1] + hp * held * (uy + hp * HAND_DAMPING * hy) + gy * held / keep
    for h in range(cloth.n_gripped):
        k = cloth.gripped[h]
        if cloth.grip[k] == k:
            guess_grip(cloth, k)


def patch_energy(cloth, k, t):
    """The terms of the step's energy at hand k's gripped vertices (their inertia, their hand's
    pull, their springs), each gripped vertex v at pos + t way_v (guess_grip), the rest of the
    cloth where it is; a spring between two of them counted once."""
    pos = cloth.pos
    mx = (cloth.target[k + k] - cloth.hand_from[k + k]) * cloth.h / cloth.dt
    my = (cloth.target[k + k + 1] - cloth.hand_from[k + k + 1]) * cloth.h / cloth.dt
    total = 0.0
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        if cloth.grip[v] != k or cloth.fixed[v] != 0:
            continue
        i = v + v
        x = pos[i] + t * (cloth.prev[i] + mx - pos[i])
        y = pos[i + 1] + t * (cloth.prev[i + 1] + my - pos[i + 1])
        ex = x - cloth.pred[i]
        ey = y - cloth.pred[i + 1]
        total += 0.5 * inertia_weight(cloth, v) * (ex * ex + ey * ey)
        dx = x - cloth.aim[i]
        dy = y - cloth.aim[i + 1]
        total += hand_energy(cloth.grip_f[v], cloth.grip_f[v] / cloth.grip_k[v], dx * dx + dy * dy)
        for q in range(cloth.adj_start[v], cloth.adj_start[v + 1]):
            o = cloth.adj_other[q]
            j = o + o
            share = 1.0
            ox = pos[j]
            oy = pos[j + 1]
            if cloth.grip[o] == k and cloth.fixed[o] == 0:
                share = 0.5
                ox += t * (cloth.prev[j] + mx - ox)
                oy += t * (cloth.prev[j + 1] + my - oy)
            total += share * spring_energy(cloth.adj_k[q], cloth.adj_rest[q], ox - x, oy - y)
    return total


def guess_grip(cloth, k):
    """The solve's first guess for hand k's gripped vertices, moved as one: each on the line
    from predict's guess (where its velocity carries it) to where it was moved by the hand's
    move this step (way_v), the same share t of it for all, the t where their terms of the step
    are least (patch_energy; a parabola through t = 0, 1/2, 1, the best of the four). A hand
    that starts or turns fast leaves predict's guess centimetres from its aim, more than the
    sweeps bring back in a step: 2.9 px on the towel at 60x60 flicked at 20 px a frame."""
    e0 = patch_energy(cloth, k, 0.0)
    eh = patch_energy(cloth, k, 0.5)
    e1 = patch_energy(cloth, k, 1.0)
    best = 0.0
    low = e0
    if eh < low:
        best = 0.5
        low = eh
    if e1 < low:
        best = 1.0
        low = e1
    curv = e0 - 2.0 * eh + e1
    if curv > 0.0:
        t = 0.25 * (3.0 * e0 - 4.0 * eh + e1) / curv
        if t > 0.0 and t < 1.0 and patch_energy(cloth, k, t) < low:
            best = t
    if best == 0.0:
        return
    pos = cloth.pos
    mx = (cloth.target[k + k] - cloth.hand_from[k + k]) * cloth.h / cloth.dt
    my = (cloth.target[k + k + 1] - cloth.hand_from[k + k + 1]) * cloth.h / cloth.dt
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        if cloth.grip[v] != k or cloth.fixed[v] != 0:
            continue
        i = v + v
        pos[i] += best * (cloth.prev[i] + mx - pos[i])
        pos[i + 1] += best * (cloth.prev[i + 1] + my - pos[i + 1])


def keep_up(cloth, v, x, y, out):
    """out[0..1]: where gripped vertex v may go toward (x, y) this step (its solver's move): no
    farther from where it began the step (`prev`) than the hand moves in the step plus
    HAND_CATCH_UP times the step. A hand's patch moves no faster than the hand, catching up at
    most that much faster: a constraint of the step's minimisation (the disc of the places it
    allows is convex)."""
    k = cloth.grip[v]
    kk = k + k
    vv = v + v
    f = cloth.h / cloth.dt
    hx = (cloth.target[kk] - cloth.hand_from[kk]) * f
    hy = (cloth.target[kk + 1] - cloth.hand_from[kk + 1]) * f
    most = math.sqrt(hx * hx + hy * hy) + HAND_CATCH_UP * cloth.h
    dx = x - cloth.prev[vv]
    dy = y - cloth.prev[vv + 1]
    d2 = dx * dx + dy * dy
    if d2 > most * most:
        s = most / math.sqrt(d2)
        x = cloth.prev[vv] + dx * s
        y = cloth.prev[vv + 1] + dy * s
    out[0] = x
    out[1] = y


def catch_up_limit(cloth, d, top):
    """The largest alpha, at most `top`, for which every gripped vertex at pos + alpha d keeps to
    keep_up's disc (or, already outside it, comes no farther out): the coarse correction's
    limit, so that what a hand's patch may not do a sweep's step, a correction does not either
    (taking a torn tissue's strands the whole way to a hand 1 m off, it flung them at 77 m/s)."""
    f = cloth.h / cloth.dt
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        if cloth.fixed[v] != 0:
            continue
        k = cloth.grip[v]
        kk = k + k
        vv = v + v
        hx = (cloth.target[kk] - cloth.hand_from[kk]) * f
        hy = (cloth.target[kk + 1] - cloth.hand_from[kk + 1]) * f
        most = math.sqrt(hx * hx + hy * hy) + HAND_CATCH_UP * cloth.h
        px = cloth.pos[vv] - cloth.prev[vv]
        py = cloth.pos[vv + 1] - cloth.prev[vv + 1]
        dx = d[vv]
        dy = d[vv + 1]
        # |p + a d|^2 <= R^2: a^2 dd + 2 a pd + pp - R^2 <= 0
        dd = dx * dx + dy * dy
        if dd == 0.0:
            continue
        pd = px * dx + py * dy
        pp = px * px + py * py
        r2 = most * most if pp <= most * most else pp
        disc = pd * pd - dd * (pp - r2)
        a = (-pd + math.sqrt(disc if disc > 0.0 else 0.0)) / dd
        if a < top:
            top = a
    return top


def hands_arrived(cloth):
    """At a frame's end every hand is where it was going."""
    for h in range(cloth.n_gripped):
        k = cloth.grip[cloth.gripped[h]]
        cloth.hand_from[k + k] = cloth.target[k + k]
        cloth.hand_from[k + k + 1] = cloth.target[k + k + 1]
        cloth.hand_acted[k] = 1
