"""Obstacles: rigid circles and boxes the cloth's free vertices and edges stay out of.

Last in a step, before its velocities (cloth/step.py): the solvers find where the fabric goes,
and this takes every free vertex out of every obstacle, swept in each obstacle's frame from
where the vertex began the step (`prev`), so that neither a fast cloth nor a fast obstacle
tunnels; the step's velocity then carries the push. An obstacle a person or the script moves
goes there over the frame's steps, evenly, like a hand.
"""

from cloth.values import SceneError
from cloth.keys import OBSTACLE_FAR
from cloth.contact import collide, shield_edges


def advance(cloth):
    """Before a step's solve: each obstacle moves its share of the way (cloth.share of the
    frame): `was` where the step begins, `at` where it ends."""
    m = cloth.n_obstacles
    share = cloth.share
    at = cloth.obstacle_at
    was = cloth.obstacle_was
    to = cloth.obstacle_to
    start = cloth.obstacle_from
    for i in range(m + m):
        was[i] = at[i]
        at[i] = to[i] if share == 1.0 else start[i] + (to[i] - start[i]) * share


def push_out(cloth):
    """After a step's solve: every free vertex out of every obstacle, swept from where it began
    the step (collide), and no edge through a circle (shield_edges); where the edges' push put
    a vertex back into another obstacle, or this one at a corner, the vertices once more from
    where they are."""
    m = cloth.n_obstacles
    at = cloth.obstacle_at
    was = cloth.obstacle_was
    collide(cloth.pos, cloth.prev, cloth.inv_mass, cloth.cols, cloth.rows, m, cloth.obstacle_shape,
            cloth.obstacle_half, was, at, cloth.obstacle_friction, cloth.obstacle_bounds,
            cloth.obstacle_row_box)
    if shield_edges(cloth.pos, cloth.prev, cloth.inv_mass, cloth.edge_a, cloth.edge_b,
                    cloth.n_edges, cloth.cols, cloth.rows, m, cloth.obstacle_shape,
                    cloth.obstacle_half, was, at, cloth.obstacle_row_box,
                    cloth.obstacle_row_mask) == 0:
        return
    for i in range(m + m):
        was[i] = at[i]
    collide(cloth.pos, cloth.pos, cloth.inv_mass, cloth.cols, cloth.rows, m, cloth.obstacle_shape,
            cloth.obstacle_half, at, at, cloth.obstacle_friction, cloth.obstacle_bounds,
            cloth.obstacle_row_box)


def obstacles_still(cloth):
    """Whether no obstacle moves in this step (after advance: where it was is where it is)."""
    at = cloth.obstacle_at
    was = cloth.obstacle_was
    for i in range(cloth.n_obstacles * 2):
        if at[i] != was[i]:
            return False
    return True


def obstacles_arrived(cloth):
    """At a frame's end every obstacle is where it was sent: the next frame starts there."""
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
    first step pushes them out, which tangles the cloth; the page says so)."""
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
