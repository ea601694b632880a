"""Distances and sweeps between the cloth's segments and the obstacles' shapes, exactly.

A shape is a circle (radius hx about its centre) or an axis-aligned box (half sizes hx, hy
about its centre): cloth/keys.py OBSTACLE_SHAPES. A segment A-B is an edge of the cloth (a
vertex with no edge left is the segment A-A). Only + - * / and sqrt, whose results are the
same bits in both runtimes (docs: Transcrypt's notes), so a contact decided in CPython is
decided the same way in the page.

Four questions, each once:
    distance(...)   how far a segment is from a shape, the closest point's place along it and
                    the direction from the shape to it (the distance's gradient)
    point(...)      how far a point is from a shape, and the direction (one vertex's contact)
    corner(...)     a shape's point features: a circle's centre (its radius away), a box's
                    four corners; and how far a segment is from one (an edge's contact)
    clear(...)      whether a triangle stays strictly outside a shape: a vertex moving from P0
                    to P1 while its neighbour F stays sweeps the edge F-P over the triangle
                    (F, P0, P1), so the move crosses nothing iff the triangle is clear
    hit_time(...)   when a shape moving in a straight line first comes within a gap of a
                    segment that stays (an obstacle dragged into the cloth: cloth/obstacles.py)
"""

from math import sqrt

CIRCLE = 0


def distance(shape, cx, cy, hx, hy, ax, ay, bx, by, t):
    """Segment A-B against the shape: t[0] = the distance (<= 0: they meet), t[1] = s, the
    closest point's place A + s (B - A), t[2..3] = u, the unit direction from the shape to it.
    The distance's gradient is (1 - s) u at A and s u at B (the closest point moves with them;
    where two points are as close, either gives it)."""
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    if shape == CIRCLE:
        s = 0.0
        if ee > 0.0:
            s = ((cx - ax) * ex + (cy - ay) * ey) / ee
            if s < 0.0:
                s = 0.0
            elif s > 1.0:
                s = 1.0
        qx = ax + s * ex - cx
        qy = ay + s * ey - cy
        r = sqrt(qx * qx + qy * qy)
        t[1] = s
        if r > 0.0:
            t[2] = qx / r
            t[3] = qy / r
        else:
            t[2] = 0.0
            t[3] = 1.0
        t[0] = r - hx
        return
    # A box: the segment inside it somewhere, or the nearest of its ends to the box and the
    # box's corners to it (two convex shapes apart are nearest at a corner of one of them).
    if meets_box(cx, cy, hx, hy, ax, ay, ex, ey):
        point_box(cx, cy, hx, hy, ax, ay, t)
        t[0] = -1.0
        t[1] = 0.0
        return
    point_box(cx, cy, hx, hy, ax, ay, t)
    best = t[0]
    s = 0.0
    ux = t[2]
    uy = t[3]
    if ee > 0.0:
        point_box(cx, cy, hx, hy, bx, by, t)
        if t[0] < best:
            best = t[0]
            s = 1.0
            ux = t[2]
            uy = t[3]
        for c in range(4):
            kx = cx + (hx if c == 1 or c == 2 else -hx)
            ky = cy + (hy if c >= 2 else -hy)
            v = ((kx - ax) * ex + (ky - ay) * ey) / ee
            if v <= 0.0 or v >= 1.0:
                continue          # its nearest point is an end: counted above
            qx = ax + v * ex - kx
            qy = ay + v * ey - ky
            q = sqrt(qx * qx + qy * qy)
            if q < best and q > 0.0:
                best = q
                s = v
                ux = qx / q
                uy = qy / q
    t[0] = best
    t[1] = s
    t[2] = ux
    t[3] = uy


def point_box(cx, cy, hx, hy, px, py, t):
    """Point P against the box: t[0] its distance (negative inside: minus the depth to the
    nearest side), t[2..3] the unit direction from the box to it (inside: out of the nearest
    side)."""
    rx = px - cx
    ry = py - cy
    sx = 1.0 if rx >= 0.0 else -1.0
    sy = 1.0 if ry >= 0.0 else -1.0
    dx = rx * sx - hx
    dy = ry * sy - hy
    if dx > 0.0 and dy > 0.0:
        d = sqrt(dx * dx + dy * dy)
        t[0] = d
        t[2] = sx * dx / d
        t[3] = sy * dy / d
    elif dx > 0.0 or (dx <= 0.0 and dy <= 0.0 and dx >= dy):
        t[0] = dx
        t[2] = sx
        t[3] = 0.0
    else:
        t[0] = dy
        t[2] = 0.0
        t[3] = sy


def meets_box(cx, cy, hx, hy, ax, ay, ex, ey):
    """Whether the segment A + s e, s in [0, 1], passes through the box's open interior (a
    segment along a side or through a corner only touches it: distance 0, caught by
    `distance`)."""
    lo = 0.0
    hi = 1.0
    for axis in range(2):
        a = ax - cx if axis == 0 else ay - cy
        e = ex if axis == 0 else ey
        h = hx if axis == 0 else hy
        if e == 0.0:
            if a <= -h or a >= h:
                return False
            continue
        s0 = (-h - a) / e
        s1 = (h - a) / e
        if s0 > s1:
            tmp = s0
            s0 = s1
            s1 = tmp
        if s0 > lo:
            lo = s0
        if s1 < hi:
            hi = s1
        if lo >= hi:
            return False
    return lo < hi


def clear(shape, cx, cy, hx, hy, x0, y0, x1, y1, x2, y2):
    """Whether the triangle (P0, P1, P2), a degenerate one too, lies strictly outside the shape
    (at a distance above 0)."""
    if shape == CIRCLE:
        d1 = (x1 - x0) * (cy - y0) - (y1 - y0) * (cx - x0)
        d2 = (x2 - x1) * (cy - y1) - (y2 - y1) * (cx - x1)
        d3 = (x0 - x2) * (cy - y2) - (y0 - y2) * (cx - x2)
        if (d1 >= 0.0 and d2 >= 0.0 and d3 >= 0.0) or (d1 <= 0.0 and d2 <= 0.0 and d3 <= 0.0):
            return False
        r2 = hx * hx
        return seg_point2(x0, y0, x1, y1, cx, cy) > r2 and \
            seg_point2(x1, y1, x2, y2, cx, cy) > r2 and seg_point2(x2, y2, x0, y0, cx, cy) > r2
    # A box: separated strictly along one of its axes or one of the triangle's sides' normals.
    lo = x0 if x0 < x1 else x1
    lo = lo if lo < x2 else x2
    hi = x0 if x0 > x1 else x1
    hi = hi if hi > x2 else x2
    if hi < cx - hx or lo > cx + hx:
        return True
    lo = y0 if y0 < y1 else y1
    lo = lo if lo < y2 else y2
    hi = y0 if y0 > y1 else y1
    hi = hi if hi > y2 else y2
    if hi < cy - hy or lo > cy + hy:
        return True
    for side in range(3):
        px = x0 if side == 0 else (x1 if side == 1 else x2)
        py = y0 if side == 0 else (y1 if side == 1 else y2)
        qx = x1 if side == 0 else (x2 if side == 1 else x0)
        qy = y1 if side == 0 else (y2 if side == 1 else y0)
        nx = py - qy
        ny = qx - px
        if nx == 0.0 and ny == 0.0:
            continue
        a = nx * x0 + ny * y0
        b = nx * x1 + ny * y1
        c = nx * x2 + ny * y2
        lo = a if a < b else b
        lo = lo if lo < c else c
        hi = a if a > b else b
        hi = hi if hi > c else c
        mid = nx * cx + ny * cy
        reach = (nx if nx >= 0.0 else -nx) * hx + (ny if ny >= 0.0 else -ny) * hy
        if hi < mid - reach or lo > mid + reach:
            return True
    return False


def seg_point2(ax, ay, bx, by, px, py):
    """The squared distance from point P to the segment A-B."""
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    s = 0.0
    if ee > 0.0:
        s = ((px - ax) * ex + (py - ay) * ey) / ee
        if s < 0.0:
            s = 0.0
        elif s > 1.0:
            s = 1.0
    qx = ax + s * ex - px
    qy = ay + s * ey - py
    return qx * qx + qy * qy


def hit_time(shape, cx, cy, hx, hy, dx, dy, ax, ay, bx, by, gap):
    """The first s in [0, 1] at which the shape, moved by s (dx, dy), comes within `gap` of the
    segment A-B (0 if it is already; 2.0 if it never does)."""
    if shape == CIRCLE:
        rho = hx + gap
        if seg_point2(ax, ay, bx, by, cx, cy) <= rho * rho:
            return 0.0
        first = 2.0
        # The centre's path against the capsule of radius rho round the segment: its two end
        # discs and the two sides between them.
        for end in range(2):
            px = cx - (ax if end == 0 else bx)
            py = cy - (ay if end == 0 else by)
            s = ray_disc(px, py, dx, dy, rho)
            if s < first:
                first = s
        ex = bx - ax
        ey = by - ay
        ee = ex * ex + ey * ey
        if ee > 0.0:
            el = sqrt(ee)
            nx = -ey / el
            ny = ex / el
            off = (cx - ax) * nx + (cy - ay) * ny
            rate = dx * nx + dy * ny
            if rate != 0.0:
                for side in range(2):
                    target = rho if side == 0 else -rho
                    s = (target - off) / rate
                    if s >= 0.0 and s < first:
                        v = ((cx + s * dx - ax) * ex + (cy + s * dy - ay) * ey) / ee
                        if v >= 0.0 and v <= 1.0:
                            first = s
        return first if first <= 1.0 else 2.0
    # A box: when the projections of the moving box and of the segment, grown by the gap,
    # overlap on every separating axis (the box's two and the segment's normal).
    enter = 0.0
    leave = 1.0
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    for axis in range(3):
        nx = 1.0 if axis == 0 else 0.0
        ny = 1.0 if axis == 1 else 0.0
        if axis == 2:
            if ee == 0.0:
                continue
            el = sqrt(ee)
            nx = -ey / el
            ny = ex / el
        a = ax * nx + ay * ny
        b = bx * nx + by * ny
        lo = (a if a < b else b) - gap
        hi = (a if a > b else b) + gap
        mid = cx * nx + cy * ny
        reach = (nx if nx >= 0.0 else -nx) * hx + (ny if ny >= 0.0 else -ny) * hy
        rate = dx * nx + dy * ny
        # overlap while mid + s rate - reach <= hi and mid + s rate + reach >= lo
        if rate == 0.0:
            if mid - reach > hi or mid + reach < lo:
                return 2.0
            continue
        s0 = (lo - reach - mid) / rate
        s1 = (hi + reach - mid) / rate
        if s0 > s1:
            tmp = s0
            s0 = s1
            s1 = tmp
        if s0 > enter:
            enter = s0
        if s1 < leave:
            leave = s1
        if enter > leave:
            return 2.0
    return enter


def ray_disc(px, py, dx, dy, r):
    """The first s >= 0 at which P + s d is within r of the origin (2.0 if never)."""
    a = dx * dx + dy * dy
    b = px * dx + py * dy
    c = px * px + py * py - r * r
    if c <= 0.0:
        return 0.0
    if a == 0.0 or b >= 0.0:
        return 2.0
    disc = b * b - a * c
    if disc < 0.0:
        return 2.0
    return (-b - sqrt(disc)) / a


def point(shape, cx, cy, hx, hy, px, py, t):
    """Point P against the shape: t[0] its distance (negative inside), t[2..3] the unit
    direction from the shape to it (out of the nearest side, inside)."""
    if shape != CIRCLE:
        point_box(cx, cy, hx, hy, px, py, t)
        return
    qx = px - cx
    qy = py - cy
    r = sqrt(qx * qx + qy * qy)
    if r > 0.0:
        t[2] = qx / r
        t[3] = qy / r
    else:
        t[2] = 0.0
        t[3] = 1.0
    t[0] = r - hx


def corners(shape):
    """How many point features the shape has: a circle 1 (its centre), a box 4 (its corners)."""
    return 1 if shape == CIRCLE else 4


def corner(shape, cx, cy, hx, hy, c, ax, ay, bx, by, t):
    """Segment A-B against the shape's point feature c: t[0] = its distance from the segment
    less the feature's radius (a circle's radius, a corner's 0), t[1] = s, the closest point's
    place A + s (B - A), t[2..3] = u, the unit direction from the feature to it. A point's
    distance from a segment is continuously differentiable off the segment, and the sum of
    these and the vertices' own (point) keeps every edge out: an edge that enters a convex
    shape first touches it with an end (a vertex's distance is 0) or across a corner (this)."""
    kx = cx
    ky = cy
    radius = hx
    if shape != CIRCLE:
        kx = cx + (hx if c == 1 or c == 2 else -hx)
        ky = cy + (hy if c >= 2 else -hy)
        radius = 0.0
    ex = bx - ax
    ey = by - ay
    ee = ex * ex + ey * ey
    s = 0.0
    if ee > 0.0:
        s = ((kx - ax) * ex + (ky - ay) * ey) / ee
        if s < 0.0:
            s = 0.0
        elif s > 1.0:
            s = 1.0
    qx = ax + s * ex - kx
    qy = ay + s * ey - ky
    r = sqrt(qx * qx + qy * qy)
    t[1] = s
    if r > 0.0:
        t[2] = qx / r
        t[3] = qy / r
    else:
        t[2] = 0.0
        t[3] = 1.0
    t[0] = r - radius
