"""Obstacles: rigid circles and boxes, moved only by a person or a script, never by the cloth.

Their contact with the cloth is a term of the step's energy (cloth/contact.py); here is what
they do to a step around it:
    advance   where each obstacle is sent in this step (its share of the frame's move)
    begin     the solve's start (a stage after predict): the cloth where the step began, the
              obstacles moved, pushing what is in their way (carry), then each vertex as far
              toward the solver's first guess as its edges sweep no obstacle (a solver without
              the barrier: from its guess, held to the start by accept)
    project   for the solvers without the barrier (XPBD, the seed's): the contact as a
              constraint of their sweeps
    accept    after such a solve: each vertex from where the solve began to where it ended, as
              far as its edges sweep no obstacle
A pin within contact.FASTEN of an obstacle is fastened to it (fasten) and moves with it: a
towel's clamp on its peg.

A dragged obstacle pushes the cloth ahead of it: at the step's start, what its way meets (an
edge or a vertex of the cloth) goes with it from then on, and the step's solve finds where the
fabric goes from there. Where the cloth cannot go (a pin in the way, not fastened to it, or
cloth pinched against another obstacle) the obstacle stops short, at the largest half,
quarter, ... of its move that keeps every edge out, and goes on toward where it was sent in
the steps after, as far as it can.
"""

from cloth.values import SceneError
from cloth.keys import OBSTACLE_FAR
from cloth.geometry import distance, hit_time, point, corner, corners, CIRCLE
from cloth.contact import FASTEN, lag_friction
from cloth.ccd import CONTACT_GAP, bounds, mark_through, move_clear, meets, near_pieces, zone

# An obstacle's move in a step that its push cannot make clear is halved up to this many times
# (to 1/64 of itself), then not made in that step.
CARRY_TRIES = 6
# Rounds of the push: an edge that the cloth carried so far leaves inside an obstacle has its
# ends carried all the way, and so on out to this many rings of edges.
CARRY_ROUNDS = 8


def advance(cloth):
    """Before a step: each obstacle's aim for the step, its share (cloth.share) of the way
    from where the frame began to where it is sent; `was` where it is. And which vertices fall
    freely in the step (cloth.flying, integrate.predict): those of a piece nothing holds
    (cloth.falling) that no obstacle may come near in the step (ccd.near_pieces): a piece
    lying on an obstacle is held by it (correct_where). cloth.touching: whether any of the cloth may touch one (the step is then
    backward Euler's: integrate.next_order)."""
    share = cloth.share
    at = cloth.obstacle_at
    m = cloth.n_obstacles
    for i in range(m + m):
        cloth.obstacle_was[i] = at[i]
        to = cloth.obstacle_to[i]
        start = cloth.obstacle_from[i]
        cloth.obstacle_aim[i] = to if share == 1.0 else start + (to - start) * share
    b = cloth.obstacle_bounds
    half = cloth.obstacle_half
    aim = cloth.obstacle_aim
    for j in range(m):
        jj = j + j
        b[4 * j] = (at[jj] if at[jj] < aim[jj] else aim[jj]) - half[jj] - CONTACT_GAP
        b[4 * j + 1] = (at[jj] if at[jj] > aim[jj] else aim[jj]) + half[jj] + CONTACT_GAP
        b[4 * j + 2] = (at[jj + 1] if at[jj + 1] < aim[jj + 1] else aim[jj + 1]) - half[jj + 1] - CONTACT_GAP
        b[4 * j + 3] = (at[jj + 1] if at[jj + 1] > aim[jj + 1] else aim[jj + 1]) + half[jj + 1] + CONTACT_GAP
    zone(cloth)
    near = cloth.near_piece
    cloth.touching = 1 if near_pieces(cloth, near) else 0
    for k in range(cloth.n_verts):
        cloth.flying[k] = cloth.falling[k] if near[cloth.piece[k]] == 0 else 0


def begin(cloth):
    """The solve's start (the module's comment). On entry pos holds the solver's first guess
    and prev where each vertex began the step (predict), every edge then out of every
    obstacle where it was."""
    n = cloth.n_verts
    pos = cloth.pos
    prev = cloth.prev
    guess = cloth.guess
    fixed = cloth.fixed
    for t in range(n + n):
        guess[t] = pos[t]
    for k in range(n):
        if fixed[k] == 0:
            pos[k + k] = prev[k + k]
            pos[k + k + 1] = prev[k + k + 1]
    bounds(cloth)
    if obstacles_still(cloth):
        for t in range(2 * cloth.n_obstacles):
            cloth.obstacle_moved[t] = 0.0
    else:
        mark_through(cloth)
        carry(cloth)
        bounds(cloth)
    mark_through(cloth)
    lag_friction(cloth)
    correct_where(cloth)
    start = cloth.start_pos
    for t in range(n + n):
        start[t] = pos[t]
    if not cloth.barrier:
        # A solver that takes the contact as a constraint starts where it would (an obstacle's
        # push added) and is held to it afterwards (accept).
        for t in range(n + n):
            pos[t] = guess[t] + start[t] - prev[t]
        return
    for k in range(n):
        if fixed[k] == 0:
            move_clear(cloth, k, guess[k + k], guess[k + k + 1])
    if cloth.loose != 0:
        zone(cloth)       # the guess went beyond a leash: tie them where the solve starts


def correct_where(cloth):
    """Which vertices take the coarse correction in the step (cloth.uncorrected; the coarse
    operators are made again when that changes): not a fixed one, nor one of a piece falling
    freely, nor one the barrier pushes and no spring pulls (contact.slack). A piece an
    obstacle holds carries load for the coarse grids to spread along its taut fabric (a strip
    hung over a peg: its balance 100 weights off after 10 s without them; a chain sliding on a
    frictionless circle, 9 cm from where it comes to rest), but a vertex resting slack on an
    obstacle is held where it is: with it in the coarse problem, its stiff barrier took the
    corrections a crumpled pile on a box made and handed them to a vertex above it, which
    they lifted 1-2 mm a step, and the pile never rested."""
    for k in range(cloth.n_verts):
        u = 1 if cloth.fixed[k] != 0 or cloth.flying[k] != 0 or cloth.pressed[k] != 0 else 0
        if u != cloth.uncorrected[k]:
            cloth.uncorrected[k] = u
            if u != cloth.mg_uncorrected[k]:
                cloth.mg_changed = 1


def carry(cloth):
    """Each obstacle from where it was toward its aim for the step, pushing what it meets
    (push); as far as it can make clear (the module's comment). obstacle_moved: how far each
    went, which friction measures a slide against."""
    at = cloth.obstacle_at
    was = cloth.obstacle_was
    aim = cloth.obstacle_aim
    moved = cloth.obstacle_moved
    pos = cloth.pos
    keep = cloth.carry_from
    for j in range(cloth.n_obstacles):
        jj = j + j
        dx = aim[jj] - was[jj]
        dy = aim[jj + 1] - was[jj + 1]
        moved[jj] = 0.0
        moved[jj + 1] = 0.0
        if dx == 0.0 and dy == 0.0:
            continue
        for t in range(2 * cloth.n_verts):
            keep[t] = pos[t]
        f = 1.0
        done = False
        for attempt in range(CARRY_TRIES + 1):
            at[jj] = aim[jj] if f == 1.0 else was[jj] + f * dx
            at[jj + 1] = aim[jj + 1] if f == 1.0 else was[jj + 1] + f * dy
            bounds(cloth)
            if push(cloth, j, at[jj] - was[jj], at[jj + 1] - was[jj + 1]):
                done = True
                break
            for t in range(2 * cloth.n_verts):
                pos[t] = keep[t]
            f *= 0.5
        if not done:
            at[jj] = was[jj]
            at[jj + 1] = was[jj + 1]
            bounds(cloth)
        for k in range(cloth.n_verts):
            if cloth.zone[k] == 0 and (pos[k + k] != keep[k + k] or pos[k + k + 1] != keep[k + k + 1]):
                cloth.loose = 1       # (cannot be: what the way meets is in the zone)
        moved[jj] = at[jj] - was[jj]
        moved[jj + 1] = at[jj + 1] - was[jj + 1]


def push(cloth, j, dx, dy):
    """Obstacle j moved by (dx, dy) from `was` (already at its end, `at`): every edge of the
    cloth (and vertex with no edge) it meets on the way within CONTACT_GAP has its free ends go
    with it from the moment it meets them, and its fastened pins go all the way; then, round by
    round, an edge left meeting an obstacle has its free ends go all the way. Returns whether
    every edge ends out of every obstacle (else the cloth is as it was: carry restores it)."""
    n = cloth.n_verts
    pos = cloth.pos
    keep = cloth.carry_from
    share = cloth.carried
    fixed = cloth.fixed
    jj = j + j
    shape = cloth.obstacle_shape[j]
    cx = cloth.obstacle_was[jj]
    cy = cloth.obstacle_was[jj + 1]
    hx = cloth.obstacle_half[jj]
    hy = cloth.obstacle_half[jj + 1]
    lox = (cx if dx >= 0.0 else cx + dx) - hx - CONTACT_GAP
    hix = (cx + dx if dx >= 0.0 else cx) + hx + CONTACT_GAP
    loy = (cy if dy >= 0.0 else cy + dy) - hy - CONTACT_GAP
    hiy = (cy + dy if dy >= 0.0 else cy) + hy + CONTACT_GAP
    for k in range(n):
        share[k] = 1.0 if fixed[k] != 0 and cloth.fastened[k] == j + 1 else 0.0
    for e in range(cloth.n_edges):
        if cloth.through[e] != 0:
            continue
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        met(cloth, a, b, shape, cx, cy, hx, hy, dx, dy, lox, hix, loy, hiy)
    for k in range(n):
        if fixed[k] == 0 and cloth.adj_start[k] == cloth.adj_start[k + 1]:
            met(cloth, k, k, shape, cx, cy, hx, hy, dx, dy, lox, hix, loy, hiy)
    for k in range(n):
        if share[k] > 0.0:
            pos[k + k] = keep[k + k] + share[k] * dx
            pos[k + k + 1] = keep[k + k + 1] + share[k] * dy
    geo = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for r in range(CARRY_ROUNDS):
        changed = False
        stuck = False
        for e in range(cloth.n_edges):
            if cloth.through[e] != 0:
                continue
            a = cloth.edge_a[e]
            b = cloth.edge_b[e]
            xa = pos[a + a]
            ya = pos[a + a + 1]
            xb = pos[b + b]
            yb = pos[b + b + 1]
            inside = False
            for o in range(cloth.n_obstacles):
                if not meets(cloth, o, xa if xa < xb else xb, xa if xa > xb else xb,
                             ya if ya < yb else yb, ya if ya > yb else yb):
                    continue
                oo = o + o
                distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1],
                         xa, ya, xb, yb, geo)
                if geo[0] <= 0.0:
                    inside = True
                    break
            if not inside:
                continue
            went = False
            for end in range(2):
                v = a if end == 0 else b
                if fixed[v] == 0 and share[v] < 1.0:
                    share[v] = 1.0
                    pos[v + v] = keep[v + v] + dx
                    pos[v + v + 1] = keep[v + v + 1] + dy
                    went = True
            if went:
                changed = True
            else:
                stuck = True
        if not changed:
            return not stuck
    return False


def met(cloth, a, b, shape, cx, cy, hx, hy, dx, dy, lox, hix, loy, hiy):
    """push's first part for the segment a-b (a = b: a vertex alone): if the obstacle's way
    meets it, at s of the move, its free ends go with the obstacle for the rest (1 - s)."""
    keep = cloth.carry_from
    xa = keep[a + a]
    ya = keep[a + a + 1]
    xb = keep[b + b]
    yb = keep[b + b + 1]
    if (xa > hix and xb > hix) or (xa < lox and xb < lox) or (ya > hiy and yb > hiy) or \
            (ya < loy and yb < loy):
        return
    s = hit_time(shape, cx, cy, hx, hy, dx, dy, xa, ya, xb, yb, CONTACT_GAP)
    if s > 1.0:
        return
    share = cloth.carried
    if cloth.fixed[a] == 0 and share[a] < 1.0 - s:
        share[a] = 1.0 - s
    if cloth.fixed[b] == 0 and share[b] < 1.0 - s:
        share[b] = 1.0 - s


def project(cloth):
    """The contact as a constraint of a solve without the barrier (XPBD's and the seed's sweeps
    call it after each sweep), on the barrier's own pairs (cloth/contact.py): a free vertex
    nearer an obstacle than half CONTACT_GAP (or inside it) moves out to that distance, and an
    edge nearer an obstacle's point feature (a circle's centre less its radius, a box's corner)
    moves out to it along the distance's gradient, its free ends by their inverse masses and
    their share of its closest point (a point-on-segment constraint of no compliance); what
    each pushed vertex slid along the surface in the step, relative to the obstacle, is held
    back by up to friction times its push (position-based friction)."""
    pos = cloth.pos
    geo = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    inv = cloth.inv_mass
    target = 0.5 * CONTACT_GAP
    for k in range(cloth.n_verts):
        if inv[k] == 0.0:
            continue
        for o in range(cloth.n_obstacles):
            x = pos[k + k]
            y = pos[k + k + 1]
            if not meets(cloth, o, x, x, y, y):
                continue
            oo = o + o
            point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, geo)
            if geo[0] < target:
                shove(cloth, k, target - geo[0], geo[2], geo[3], o)
    for e in range(cloth.n_edges):
        if cloth.through[e] != 0:
            continue
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        wa = inv[a]
        wb = inv[b]
        if wa == 0.0 and wb == 0.0:
            continue
        for o in range(cloth.n_obstacles):
            oo = o + o
            shape = cloth.obstacle_shape[o]
            for c in range(corners(shape)):
                xa = pos[a + a]
                ya = pos[a + a + 1]
                xb = pos[b + b]
                yb = pos[b + b + 1]
                if not meets(cloth, o, xa if xa < xb else xb, xa if xa > xb else xb,
                             ya if ya < yb else yb, ya if ya > yb else yb):
                    break
                corner(shape, at[oo], at[oo + 1], half[oo], half[oo + 1], c, xa, ya, xb, yb, geo)
                d = geo[0]
                if d >= target:
                    continue
                s = geo[1]
                den = wa * (1.0 - s) * (1.0 - s) + wb * s * s
                if den == 0.0:
                    continue
                lam = (target - d) / den
                ux = geo[2]
                uy = geo[3]
                shove(cloth, a, wa * (1.0 - s) * lam, ux, uy, o)
                shove(cloth, b, wb * s * lam, ux, uy, o)


def shove(cloth, v, p, ux, uy, o):
    """project's move of vertex v by p along u, out of obstacle o, and its friction."""
    if p <= 0.0:
        return
    pos = cloth.pos
    vv = v + v
    oo = o + o
    pos[vv] += p * ux
    pos[vv + 1] += p * uy
    slide = -uy * (pos[vv] - cloth.prev[vv] - cloth.obstacle_moved[oo]) + \
        ux * (pos[vv + 1] - cloth.prev[vv + 1] - cloth.obstacle_moved[oo + 1])
    hold = cloth.obstacle_friction[o] * p
    if slide > hold:
        slide = hold
    elif slide < -hold:
        slide = -hold
    pos[vv] += uy * slide
    pos[vv + 1] -= ux * slide


def accept(cloth):
    """After a solve without the barrier: each free vertex from where the solve began
    (start_pos) to where it ended, as far as its edges sweep no obstacle; two passes in index
    order, so that a vertex held back by a neighbour not yet moved tries again."""
    n = cloth.n_verts
    pos = cloth.pos
    guess = cloth.guess
    start = cloth.start_pos
    fixed = cloth.fixed
    for k in range(n):
        if fixed[k] == 0:
            guess[k + k] = pos[k + k]
            guess[k + k + 1] = pos[k + k + 1]
            pos[k + k] = start[k + k]
            pos[k + k + 1] = start[k + k + 1]
    for p in range(2):
        for k in range(n):
            if fixed[k] == 0:
                move_clear(cloth, k, guess[k + k], guess[k + k + 1])


def fasten(cloth):
    """cloth.fastened: each fixed vertex's obstacle + 1 if it lies within FASTEN of one (the
    first), else 0 (hands.refix calls it whenever pins or holds change)."""
    if cloth.n_obstacles == 0:
        return
    geo = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for k in range(cloth.n_verts):
        cloth.fastened[k] = 0
        if cloth.fixed[k] == 0:
            continue
        x = cloth.pos[k + k]
        y = cloth.pos[k + k + 1]
        for o in range(cloth.n_obstacles):
            oo = o + o
            point(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1], x, y, geo)
            if geo[0] <= FASTEN:
                cloth.fastened[k] = o + 1
                break


def obstacles_still(cloth):
    """Whether no obstacle is sent anywhere in this step (after advance)."""
    at = cloth.obstacle_at
    aim = cloth.obstacle_aim
    for i in range(cloth.n_obstacles * 2):
        if at[i] != aim[i]:
            return False
    return True


def obstacles_arrived(cloth):
    """At a frame's end each obstacle's frame starts where it is (where it was sent, unless the
    cloth held it back: it goes on there in the next frames)."""
    for i in range(cloth.n_obstacles * 2):
        cloth.obstacle_from[i] = cloth.obstacle_at[i]


def move_obstacle(cloth, j, x, y):
    """Send obstacle j's centre to (x, y): it goes there over the next frame, pushing the
    cloth before it."""
    if j < 0 or j >= cloth.n_obstacles:
        raise SceneError('index: no obstacle ' + str(j) + ' (the scene has ' +
                         str(cloth.n_obstacles) + ')')
    if not (x >= -OBSTACLE_FAR and x <= OBSTACLE_FAR and y >= -OBSTACLE_FAR and y <= OBSTACLE_FAR):
        raise SceneError('to: must be finite and within ' + str(int(OBSTACLE_FAR)) + ' m of the origin')
    if x == cloth.obstacle_to[j + j] and y == cloth.obstacle_to[j + j + 1]:
        return
    cloth.obstacle_to[j + j] = x
    cloth.obstacle_to[j + j + 1] = y
    cloth.asleep = False
    cloth.still_frames = 0


def inside_obstacles(cloth):
    """How many free vertices are inside an obstacle now (a scene that starts them there: the
    steps push them out; the page says so)."""
    count = 0
    for k in range(cloth.n_verts):
        if cloth.inv_mass[k] == 0.0:
            continue
        x = cloth.pos[k + k]
        y = cloth.pos[k + k + 1]
        for j in range(cloth.n_obstacles):
            dx = x - cloth.obstacle_at[j + j]
            dy = y - cloth.obstacle_at[j + j + 1]
            hx = cloth.obstacle_half[j + j]
            hy = cloth.obstacle_half[j + j + 1]
            if cloth.obstacle_shape[j] == 0:
                if dx * dx + dy * dy < hx * hx:
                    count += 1
                    break
            elif dx > -hx and dx < hx and dy > -hy and dy < hy:
                count += 1
                break
    return count


def edges_through(cloth):
    """How many edges of the cloth meet an obstacle (inside it, or touching it): 0 for a scene
    that started clear, at every frame (ccd.py); the tests' and the benchmark's check."""
    count = 0
    if cloth.n_obstacles == 0:
        return count
    geo = cloth.geo
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    pos = cloth.pos
    for e in range(cloth.n_edges):
        a = cloth.edge_a[e] + cloth.edge_a[e]
        b = cloth.edge_b[e] + cloth.edge_b[e]
        for o in range(cloth.n_obstacles):
            oo = o + o
            distance(cloth.obstacle_shape[o], at[oo], at[oo + 1], half[oo], half[oo + 1],
                     pos[a], pos[a + 1], pos[b], pos[b + 1], geo)
            if geo[0] <= 0.0:
                count += 1
                break
    return count


def obstacle_under(cloth, x, y):
    """The index of the obstacle whose shape, where it is going (`to`), holds (x, y); the last
    one drawn (the highest index) first; -1 for none."""
    for j in range(cloth.n_obstacles - 1, -1, -1):
        dx = x - cloth.obstacle_to[j + j]
        dy = y - cloth.obstacle_to[j + j + 1]
        hx = cloth.obstacle_half[j + j]
        hy = cloth.obstacle_half[j + j + 1]
        if cloth.obstacle_shape[j] == 0:
            if dx * dx + dy * dy <= hx * hx:
                return j
        elif dx >= -hx and dx <= hx and dy >= -hy and dy <= hy:
            return j
    return -1
