"""The air: wind (`wind`, `drag`, `gust`) pushes each edge across itself by the air's velocity
relative to it, so a hanging cloth leans and billows and a cloth moving with the air feels
nothing. Felt once a frame, as the frame's impulse on the velocities: the air changes over
seconds, not steps (once a step cost 18% of a dragged 120x120 frame), and the steady lean is
the same. Only in a scene whose air moves: still air costs nothing (its stage is not chosen)."""

import math

# At most this share of the air's velocity across an edge relative to its ends is given to
# each end in one frame: a vertex has up to four structural edges, and four such shares are half
# that velocity, short of overshooting the air (an explicit drag is stable only while
# drag dt / mass stays small; capped, any is).
AIR_MOST = 0.125
# Gusts: the wind times 1 + amplitude * GUST_PEAK * p (1 - p) (1 - 2p), p the phase in the
# period: a smooth wave from -1 to 1, polynomial so that both runtimes compute it to the bit.
GUST_PEAK = 6.0 * math.sqrt(3.0)


def feel_air(cloth):
    cloth.air_t += cloth.dt
    f = 1.0
    if cloth.scene.gust_amplitude > 0.0:
        q = cloth.air_t / cloth.scene.gust_period
        p = q - math.floor(q)
        f = 1.0 + cloth.scene.gust_amplitude * GUST_PEAK * p * (1.0 - p) * (1.0 - 2.0 * p)
    air = cloth.out
    air[0] = cloth.scene.wind_x * f
    air[1] = cloth.scene.wind_y * f
    air[2] = 0.5 * cloth.scene.drag * cloth.spacing * cloth.dt
    blow(cloth.pos, cloth.vel, cloth.vel_prev, cloth.inv_mass, cloth.edge_a, cloth.edge_b,
         cloth.n_struct, air)


def blow(pos, vel, vel_prev, inv_mass, edge_a, edge_b, n_edges, air):
    """Each structural edge of length L stands for a strip of cloth one spacing s wide (the
    rows' edges take the air across the rows, the columns' across the columns: per area, as
    the key says; the diagonals stand for shear, not for more cloth): the air moving at v_rel
    relative to it (its ends' mean velocity) pushes it with drag L s (v_rel . n) n along its
    normal n, half on each end, over the frame dt: each end's velocity changes by
    k w L (v_rel . n) n, k = drag s dt / 2, w its inverse mass (capped: AIR_MOST). The change
    goes into the velocity BDF2 remembers from the last step too: its next step extrapolates
    4/3 v - 1/3 v-, and an impulse in v alone would count 4/3 of itself.
    air = [wind x, wind y, k]."""
    sqrt = math.sqrt
    wx = air[0]
    wy = air[1]
    k = air[2]
    for e in range(n_edges):
        a = edge_a[e]
        b = edge_b[e]
        wa = inv_mass[a]
        wb = inv_mass[b]
        if wa == 0.0 and wb == 0.0:
            continue
        i = a + a
        j = b + b
        # n * L: the edge (b - a) turned a quarter
        nx = pos[i + 1] - pos[j + 1]
        ny = pos[j] - pos[i]
        l2 = nx * nx + ny * ny
        if l2 < 1e-30:
            continue
        length = sqrt(l2)
        rx = wx - 0.5 * (vel[i] + vel[j])
        ry = wy - 0.5 * (vel[i + 1] + vel[j + 1])
        across = (rx * nx + ry * ny) / l2
        ca = k * wa * length
        if ca > AIR_MOST:
            ca = AIR_MOST
        cb = k * wb * length
        if cb > AIR_MOST:
            cb = AIR_MOST
        vel[i] += ca * across * nx
        vel[i + 1] += ca * across * ny
        vel[j] += cb * across * nx
        vel[j + 1] += cb * across * ny
        vel_prev[i] += ca * across * nx
        vel_prev[i + 1] += ca * across * ny
        vel_prev[j] += cb * across * nx
        vel_prev[j + 1] += cb * across * ny
