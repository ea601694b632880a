"""Sleep (scene key `sleep`): a cloth at rest is not stepped again until something changes it
(a gesture, a setting, an obstacle moved: hands.wake).

At rest means: for SLEEP_TIME seconds of frames no free vertex moved more than SLEEP_MOTION of
the cloth's extent in a frame, none ended more than SLEEP_DRIFT of it from where it was at the
window's start, and the solver's own imbalance (the RMS force left unbalanced, over the
vertices' weight) stayed under SLEEP_IMBALANCE. Relative to the extent because that is what the
page fits to the screen: both are a fraction of a pixel there. The drift test catches a slow
creep that has no fast frame, and the imbalance one a cloth that has stopped short of its
equilibrium (a solver that has not converged can crawl slower than any motion bound)."""

import math

from cloth.host import f64

SLEEP_MOTION = 1e-4
SLEEP_DRIFT = 1e-3
SLEEP_TIME = 1.0
SLEEP_IMBALANCE = 0.01


def configure(cloth, scene):
    n = cloth.n_verts
    extent = max(max(cloth.cols, cloth.rows) - 1, 1) * cloth.spacing
    cloth.still_motion2 = SLEEP_MOTION * SLEEP_MOTION * extent * extent
    cloth.drift2 = SLEEP_DRIFT * SLEEP_DRIFT * extent * extent
    cloth.sleep_frames = int(math.ceil(SLEEP_TIME / scene.dt))
    if len(cloth.last_pos) < 2 * n:
        cloth.last_pos = f64(2 * n)
        cloth.still_from = f64(2 * n)
        for i in range(2 * n):
            cloth.last_pos[i] = cloth.pos[i]


def settle(cloth):
    """Count still frames; after a window of them, sleep if nothing drifted. Never in gusts:
    the air changes, however little the cloth moves."""
    if cloth.scene.gust_amplitude > 0.0 and cloth.scene.drag > 0.0:
        cloth.still_frames = 0
        return
    n = cloth.n_verts
    most_moved2(cloth.pos, cloth.last_pos, cloth.fixed, n, cloth.out)
    moved2 = cloth.out[0]
    copy_into(cloth.last_pos, cloth.pos, n + n)
    if moved2 > cloth.still_motion2 or cloth.imbalance > SLEEP_IMBALANCE:
        cloth.still_frames = 0
        return
    if cloth.still_frames == 0:
        copy_into(cloth.still_from, cloth.pos, n + n)
    cloth.still_frames += 1
    if cloth.still_frames > cloth.sleep_frames:
        most_moved2(cloth.pos, cloth.still_from, cloth.fixed, n, cloth.out)
        if cloth.out[0] <= cloth.drift2:
            cloth.asleep = True
        else:
            cloth.still_frames = 0


def most_moved2(pos, before, fixed, n, out):
    """out[0] = the largest squared distance a free vertex is from where `before` has it (a
    double comes back through an array: returned, JS would box it, an allocation a frame)."""
    worst = 0.0
    for k in range(n):
        if fixed[k] != 0:
            continue
        dx = pos[k + k] - before[k + k]
        dy = pos[k + k + 1] - before[k + k + 1]
        d2 = dx * dx + dy * dy
        if d2 > worst:
            worst = d2
    out[0] = worst


def copy_into(dst, src, m):
    for i in range(m):
        dst[i] = src[i]
