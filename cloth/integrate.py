"""Time integration for the implicit solvers: BDF2, the second-order backward differentiation
formula, as an energy to minimise.

BDF2 for x' = v, M v' = f(x) - c M v with a constant step h:
    x+ = 4/3 x - 1/3 x- + (2/3 h) v+,    v+ = 4/3 v - 1/3 v- + (2/3 h) (f(x+) / M - c v+)
Eliminating v+, the new positions minimise the incremental potential
    G(x) = sum_i w_i / 2 |x_i - pred_i|^2 + E(x),   w_i = m_i (1 + c h') / h'^2,  h' = 2h/3,
    pred = base + h' keep (4/3 v - 1/3 v-) + keep h'^2 g,  base = 4/3 x - 1/3 x-,
    keep = 1 / (1 + c h')
with E the fabric's elastic energy (and a hand's), and then v+ = (x+ - base) / h'. G is convex
(every term is: cloth/vbd.py), so each step has one answer, which the solvers approach.

Why BDF2 and not backward Euler: both are L-stable (a fabric's stretch waves, far faster than a
frame, are damped instead of blowing up), but backward Euler takes 1 - exp(-2 pi omega h) of a
swing's energy per period: 28% for a 1 m pendulum at 60 Hz, 30% of its height a swing
(measured). BDF2 is second order: 0.4% a swing, at the same cost a step. It needs the last
two positions and velocities, kept in `prev` and `vel_prev`.

Exactness: BDF2 is exact for motion under constant acceleration (a polynomial of degree two)
when its history is; `rest_at` writes a vertex's history as that of a fall from rest, and
`restart` that of the current velocity under gravity alone. So a free vertex falls exactly
(to rounding), and the first step after a change of step size needs no special case.
"""


# A step that follows one whose solve left its forces this far from balance (cloth.imbalance:
# the RMS unbalanced force over the RMS weight of a vertex) is taken by backward Euler instead
# of BDF2. BDF2 passes on what an unfinished solve leaves more than backward Euler, which
# damps it: a stiff towel's flaps swinging from its clamp went unstable under BDF2 whatever
# the solver's budget (denim 20x20, polyester 30x30: 2-10 m/s after 10 s), and came to rest
# under backward Euler or under this choice, at the same cost; a pendulum, solved exactly,
# keeps BDF2's period and energy.
UNBALANCED = 0.1


def configure(cloth, scene):
    """The step's constants of the integrator (cloth.h is the substep size)."""
    cloth.damping = scene.damping
    order(cloth, cloth.max_order)


def order(cloth, k):
    """Steps of BDF2 (k = 2), backward Euler (k = 1) or position Verlet (k = 0: XPBD's own,
    Macklin et al. 2016: the target x + v h + g h^2 / 2 with damping explicit, and after the
    step v = (x+ - x) / h + g h / 2, which makes a free fall exact) from now on."""
    hp = cloth.h * 2.0 / 3.0 if k == 2 else cloth.h
    cloth.order = k
    cloth.h_bdf = hp
    cloth.keep = 1.0 / (1.0 + cloth.damping * hp)
    cloth.w_scale = (1.0 + cloth.damping * hp) / (hp * hp) if k > 0 else 1.0 / (hp * hp)


def rest_at(cloth, k):
    """Vertex k at rest now, with the history of a fall from rest (or of standing still, for a
    fixed vertex): x- = x + g h^2 / 2, v- = -g h."""
    i = k + k
    cloth.vel[i] = 0.0
    cloth.vel[i + 1] = 0.0
    if cloth.fixed[k] != 0:
        cloth.prev[i] = cloth.pos[i]
        cloth.prev[i + 1] = cloth.pos[i + 1]
        cloth.vel_prev[i] = 0.0
        cloth.vel_prev[i + 1] = 0.0
        return
    h = cloth.h
    cloth.prev[i] = cloth.pos[i] + 0.5 * cloth.gravity_x * h * h
    cloth.prev[i + 1] = cloth.pos[i + 1] + 0.5 * cloth.gravity_y * h * h
    cloth.vel_prev[i] = -cloth.gravity_x * h
    cloth.vel_prev[i + 1] = -cloth.gravity_y * h


def restart(cloth):
    """A history for every vertex from its velocity now, as if gravity alone had acted over the
    last step: after a change of the step size, which makes the stored one meaningless."""
    for k in range(cloth.n_verts):
        restart_at(cloth, k)


def restart_at(cloth, k):
    """Vertex k's history from its velocity now, as if gravity alone had acted over the last
    step (a fixed vertex: standing still). Also for a vertex whose piece a cut has just set
    free: its history held the springs' pull, which a BDF2 step would go on extrapolating (a
    piece cut off while it hung fell g h / 2 slower than free fall)."""
    h = cloth.h
    pos = cloth.pos
    vel = cloth.vel
    i = k + k
    if cloth.fixed[k] != 0:
        cloth.prev[i] = pos[i]
        cloth.prev[i + 1] = pos[i + 1]
        vel[i] = 0.0
        vel[i + 1] = 0.0
        cloth.vel_prev[i] = 0.0
        cloth.vel_prev[i + 1] = 0.0
        return
    gx = cloth.gravity_x
    gy = cloth.gravity_y
    cloth.prev[i] = pos[i] - vel[i] * h + 0.5 * gx * h * h
    cloth.prev[i + 1] = pos[i + 1] - vel[i + 1] * h + 0.5 * gy * h * h
    cloth.vel_prev[i] = vel[i] - gx * h
    cloth.vel_prev[i + 1] = vel[i + 1] - gy * h


def next_order(cloth):
    """The order of the next step: the solver's, but backward Euler (1) in place of BDF2 after
    a solve left the cloth off balance (UNBALANCED), and while any of it may touch an obstacle
    (cloth.touching: obstacles.advance). A stiff contact stops what meets it within a step,
    and BDF2's velocity after such a stop is half the speed it came with, backwards (x+ = x:
    v+ = (x+ - 4/3 x + 1/3 x-) / (2h/3) = -(x - x-) / 2h): a strip dropped flat on a box
    bounced a fifth of its fall back up. Backward Euler's is 0: cloth meets an obstacle
    inelastically, as it does."""
    if cloth.max_order == 2 and (cloth.imbalance > UNBALANCED or cloth.touching != 0):
        return 1
    return cloth.max_order


def predict(cloth):
    """The step's inertial target `pred` and `base`, its history moved on (prev = x, vel_prev =
    v), and the solvers' first guess in `pos`: where its velocity alone carries each vertex
    over the step (x + h v: BDF2's own extrapolation, from two steps of history, passes on
    twice the noise of an unfinished solve, and a stiff towel hung from a clamp went unstable
    with it), and for a vertex of a piece nothing holds (no pin, no hand: hands.refix) its
    target, where it falls to. A held cloth's guess leaves gravity's h'^2 g out: in it, it would have to be
    undone every step by the springs holding the cloth up, and what the sweeps leave of it
    keeps a stiff cloth from ever coming to rest (measured: cotton two corners 30x30 still at
    0.2 m/s after 20 s with it, at rest in 7 s without; guessing per vertex, from which springs
    pulled it or from its last change of velocity as VBD's adaptive start does, flips between
    the two guesses from step to step and never settles). A falling piece's guess has it: its
    springs at rest pull on nothing there, and the fall is exact (without it, sweeps slowed by
    its springs pulled a free 6x4 cloth down unevenly: 1.5 cm sideways in a second)."""
    k2 = next_order(cloth)
    if k2 != cloth.order:
        order(cloth, k2)
    pos = cloth.pos
    prev = cloth.prev
    vel = cloth.vel
    vold = cloth.vel_prev
    pred = cloth.pred
    base = cloth.base
    fixed = cloth.fixed
    hp = cloth.h_bdf
    h = cloth.h
    keep = cloth.keep
    gx = cloth.gravity_x * hp * hp
    gy = cloth.gravity_y * hp * hp
    ax = gx * (keep if k2 > 0 else 0.5)
    ay = gy * (keep if k2 > 0 else 0.5)
    flying = cloth.flying
    for k in range(cloth.n_verts):
        i = k + k
        x = pos[i]
        y = pos[i + 1]
        if fixed[k] != 0:
            pred[i] = x
            pred[i + 1] = y
            base[i] = x
            base[i + 1] = y
            prev[i] = x
            prev[i + 1] = y
            continue
        vx = vel[i]
        vy = vel[i + 1]
        if k2 == 2:
            bx = (4.0 * x - prev[i]) / 3.0
            by = (4.0 * y - prev[i + 1]) / 3.0
            px = bx + hp * keep * (4.0 * vx - vold[i]) / 3.0
            py = by + hp * keep * (4.0 * vy - vold[i + 1]) / 3.0
        elif k2 == 0:
            bx = x
            by = y
            px = x + keep * (hp * vx - 0.5 * gx) + 0.5 * gx
            py = y + keep * (hp * vy - 0.5 * gy) + 0.5 * gy
        else:
            bx = x
            by = y
            px = x + hp * keep * vx
            py = y + hp * keep * vy
        if flying[k] != 0 and k2 == 1:
            # Backward Euler puts all of gravity's h^2 g into a step's target: the velocity
            # keep (v + g h) is a fall's, the position h^2 g / 2 below it, every step. A piece
            # nothing holds takes half of it into its target and half into its base, so that
            # v+ = (x+ - base) / h is the same and x+ is the fall's (each step backward Euler
            # takes while the part that hangs is unbalanced left a cut piece 1.4 mm low).
            bx -= 0.5 * ax
            by -= 0.5 * ay
            px -= 0.5 * ax
            py -= 0.5 * ay
        base[i] = bx
        base[i + 1] = by
        pred[i] = px + ax
        pred[i + 1] = py + ay
        if flying[k] != 0:
            pos[i] = px + ax
            pos[i + 1] = py + ay
        else:
            pos[i] = x + h * keep * vx
            pos[i + 1] = y + h * keep * vy
        prev[i] = x
        prev[i + 1] = y
        vold[i] = vx
        vold[i + 1] = vy


def finish(cloth):
    """The new velocities, v+ = (x+ - base) / h' (Verlet's with g h / 2 more; a fixed vertex
    has none)."""
    pos = cloth.pos
    base = cloth.base
    vel = cloth.vel
    fixed = cloth.fixed
    inv = 1.0 / cloth.h_bdf
    hx = 0.5 * cloth.gravity_x * cloth.h_bdf if cloth.order == 0 else 0.0
    hy = 0.5 * cloth.gravity_y * cloth.h_bdf if cloth.order == 0 else 0.0
    for k in range(cloth.n_verts):
        i = k + k
        if fixed[k] != 0:
            vel[i] = 0.0
            vel[i + 1] = 0.0
            continue
        vel[i] = (pos[i] - base[i]) * inv + hx
        vel[i + 1] = (pos[i + 1] - base[i + 1]) * inv + hy
