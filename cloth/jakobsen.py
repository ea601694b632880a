"""The seed's method, as the seed wrote it: position Verlet and Jakobsen's relaxation of the
structural edges ("Advanced Character Physics", 2001).

    x' = x + (x - x*) + a dt^2          then, `iterations` times over every structural edge:
    diff = (|x2 - x1| - d) / |x2 - x1|,  x1 += (x2 - x1) diff / 2,  x2 -= (x2 - x1) diff / 2

(a fixed end takes none of the move, and its free partner all of it). The edges are rigid
whatever the fabric: a scene's stretch, shear and density change nothing here, and neither do
the diagonals; the page says so (scene.unused_settings). A hand puts the vertices it grips
where it holds them, as the seed's mouse does. Damping scales x - x* by 1 / (1 + damping dt).

State: the cloth keeps (pos, vel) for every solver; Verlet's x* is x - v h + a h^2 / 2 (for
constant acceleration a: so a fall from rest is exact), and after the step
v = (x' - x) / h + a h / 2.
"""

import math

from cloth.obstacles import project
from cloth import air

# Its own Verlet, not cloth/integrate.py's steps.
ORDER = 0
# Its rigid edges have no forces to balance (cloth.imbalance stays 0).
RESIDUAL = False
# Its relaxation knows no contact's barrier: it takes the contact as a constraint
# (obstacles.project), and the cloth moves by obstacles.accept after it.
BARRIER = False


def prepare(cloth):
    return


def predict(cloth):
    pos = cloth.pos
    prev = cloth.prev
    vel = cloth.vel
    fixed = cloth.fixed
    grip = cloth.grip
    aim = cloth.aim
    h = cloth.h
    keep = 1.0 / (1.0 + cloth.scene.damping * h)
    ax = cloth.gravity_x * h * h
    ay = cloth.gravity_y * h * h
    for k in range(cloth.n_verts):
        i = k + k
        x = pos[i]
        y = pos[i + 1]
        prev[i] = x
        prev[i + 1] = y
        if fixed[k] != 0:
            continue
        if grip[k] >= 0:
            pos[i] = aim[i]
            pos[i + 1] = aim[i + 1]
            continue
        pos[i] = x + keep * (vel[i] * h - 0.5 * ax) + ax
        pos[i + 1] = y + keep * (vel[i + 1] * h - 0.5 * ay) + ay


def solve(cloth):
    pos = cloth.pos
    fixed = cloth.fixed
    grip = cloth.grip
    ea = cloth.edge_a
    eb = cloth.edge_b
    rest = cloth.rest
    m = cloth.n_struct
    sqrt = math.sqrt
    for it in range(cloth.iterations):
        for e in range(m):
            a = ea[e]
            b = eb[e]
            wa = 0.0 if fixed[a] != 0 or grip[a] >= 0 else 1.0
            wb = 0.0 if fixed[b] != 0 or grip[b] >= 0 else 1.0
            w = wa + wb
            if w == 0.0:
                continue
            ia = a + a
            ib = b + b
            dx = pos[ib] - pos[ia]
            dy = pos[ib + 1] - pos[ia + 1]
            d2 = dx * dx + dy * dy
            if d2 < 1e-30:
                continue
            length = sqrt(d2)
            s = (length - rest[e]) / length / w
            sa = s * wa
            sb = s * wb
            pos[ia] += dx * sa
            pos[ia + 1] += dy * sa
            pos[ib] -= dx * sb
            pos[ib + 1] -= dy * sb
        if cloth.windy:
            air.project(cloth)
        if cloth.n_obstacles > 0:
            project(cloth)
        cloth.sweeps += 1


def finish(cloth):
    pos = cloth.pos
    prev = cloth.prev
    vel = cloth.vel
    fixed = cloth.fixed
    inv = 1.0 / cloth.h
    hx = 0.5 * cloth.gravity_x * cloth.h
    hy = 0.5 * cloth.gravity_y * cloth.h
    grip = cloth.grip
    for k in range(cloth.n_verts):
        i = k + k
        if fixed[k] != 0:
            vel[i] = 0.0
            vel[i + 1] = 0.0
        elif grip[k] >= 0:
            # moved where the hand is: the hand's velocity
            vel[i] = (pos[i] - prev[i]) * inv
            vel[i + 1] = (pos[i + 1] - prev[i + 1]) * inv
        else:
            vel[i] = (pos[i] - prev[i]) * inv + hx
            vel[i + 1] = (pos[i + 1] - prev[i + 1]) * inv + hy
