"""Contact with the obstacles: the kernels (cloth/obstacles.py runs them as stages).

keep_out is a constraint inside the solve (cloth/vbd.py's sweeps); collide and shield_edges
run after it, swept over the step, so that nothing tunnels whatever the solver did.
"""

import math

# Below this squared length an edge has no direction to push along.
TINY2 = 1e-30
# A vertex this close to an obstacle's surface (m) rests on it: keep_out puts it on the
# surface to rounding, so a millimetre's thousandth is far above rounding and far below a step.
TOUCH = 1e-6


def keep_out(cloth, i):
    """Vertex i, if inside an obstacle where it now is, onto its surface the nearest way: the
    contact as a constraint of the solve (vbd.sweep calls it after each vertex's step, so the
    fabric comes to rest against an obstacle instead of being pushed out after every step)."""
    ii = i + i
    x = cloth.pos[ii]
    y = cloth.pos[ii + 1]
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for j in range(cloth.n_obstacles):
        jj = j + j
        dx = x - at[jj]
        dy = y - at[jj + 1]
        hx = half[jj]
        hy = half[jj + 1]
        if cloth.obstacle_shape[j] == 0:
            d2 = dx * dx + dy * dy
            if d2 < hx * hx and d2 > 0.0:
                s = hx / math.sqrt(d2)
                x = at[jj] + dx * s
                y = at[jj + 1] + dy * s
        elif dx > -hx and dx < hx and dy > -hy and dy < hy:
            gx = hx - abs(dx)
            gy = hy - abs(dy)
            if gx < gy:
                x = at[jj] + (hx if dx >= 0.0 else -hx)
            else:
                y = at[jj + 1] + (hy if dy >= 0.0 else -hy)
    cloth.pos[ii] = x
    cloth.pos[ii + 1] = y


def unopposed(cloth, i, fx, fy):
    """The squared force (fx, fy) on vertex i that the obstacles it rests on do not oppose: the
    part pushing into an obstacle's surface is met by the contact's reaction, and up to
    friction times that push, the part along the surface by its friction. What the solve's
    imbalance counts at a vertex in contact (a cloth lying still on a box is balanced)."""
    ii = i + i
    x = cloth.pos[ii]
    y = cloth.pos[ii + 1]
    at = cloth.obstacle_at
    half = cloth.obstacle_half
    for j in range(cloth.n_obstacles):
        jj = j + j
        dx = x - at[jj]
        dy = y - at[jj + 1]
        hx = half[jj]
        hy = half[jj + 1]
        nx = 0.0
        ny = 0.0
        if cloth.obstacle_shape[j] == 0:
            d2 = dx * dx + dy * dy
            if d2 > 0.0 and d2 < (hx + TOUCH) * (hx + TOUCH):
                d = math.sqrt(d2)
                nx = dx / d
                ny = dy / d
        elif dx > -hx - TOUCH and dx < hx + TOUCH and dy > -hy - TOUCH and dy < hy + TOUCH:
            if hx - abs(dx) < hy - abs(dy):
                nx = 1.0 if dx >= 0.0 else -1.0
            else:
                ny = 1.0 if dy >= 0.0 else -1.0
        push = fx * nx + fy * ny
        if push < 0.0:
            fx -= push * nx
            fy -= push * ny
            along = math.sqrt(fx * fx + fy * fy)
            grip = -push * cloth.obstacle_friction[j]
            if along <= grip:
                return 0.0
            fx *= 1.0 - grip / along
            fy *= 1.0 - grip / along
    return fx * fx + fy * fy


def collide(pos, prev, inv_mass, cols, rows, count, shape, half, was, now, friction, bounds, row_box):
    """Every free vertex out of every obstacle (sim.OBSTACLES), swept: in the obstacle's own
    frame the vertex went from prev - was to pos - now over the step (the step's start, `prev`
    after predict, and its end; `was` and `now`: each obstacle's centre then, 2 per obstacle).
    A vertex whose path enters the shape is put where it entered, then slides on along the
    surface by what was left of its step's tangential part times (1 - friction): so a fast
    cloth or a fast obstacle (a box moved 1 m in one frame) never tunnels, and a moving one
    carries what it pushes. A vertex that starts the step inside (a scene that put it there)
    goes out the nearest way. Shapes: 0 a circle (half[2j]: its radius), 1 an axis-aligned
    box (half width, half height).

    By rows of the grid: a row's paths' box is found in one pass over it, and only an obstacle
    whose swept box (bounds: 4 per obstacle, filled here) meets it looks at the row's vertices
    one by one (a vertex-by-obstacle test for every vertex cost 17% of a 120x120 frame with
    four obstacles far away, measured by `python -m bench --world`). Each vertex still meets
    the obstacles in their order, each where the one before put it. row_box (4 per row) keeps
    each row's box, grown by the swept box of every obstacle that met it (where it may have
    put a vertex), for shield_edges."""
    sqrt = math.sqrt
    for j in range(count):
        jj = j + j
        b = j * 4
        bounds[b] = min(was[jj], now[jj]) - half[jj]
        bounds[b + 1] = max(was[jj], now[jj]) + half[jj]
        bounds[b + 2] = min(was[jj + 1], now[jj + 1]) - half[jj + 1]
        bounds[b + 3] = max(was[jj + 1], now[jj + 1]) + half[jj + 1]
    for row in range(rows):
        first = row * cols
        last = first + cols
        moved = True
        row_lo_x = 0.0
        row_hi_x = 0.0
        row_lo_y = 0.0
        row_hi_y = 0.0
        for j in range(count):
            if moved:
                # The row's box (again after an obstacle moved some of it).
                row_lo_x = 1e300
                row_hi_x = -1e300
                row_lo_y = 1e300
                row_hi_y = -1e300
                for k in range(first, last):
                    # Fixed vertices too: their edges are shield_edges' as well.
                    i = k + k
                    px = pos[i]
                    qx = prev[i]
                    py = pos[i + 1]
                    qy = prev[i + 1]
                    if px < row_lo_x:
                        row_lo_x = px
                    if qx < row_lo_x:
                        row_lo_x = qx
                    if px > row_hi_x:
                        row_hi_x = px
                    if qx > row_hi_x:
                        row_hi_x = qx
                    if py < row_lo_y:
                        row_lo_y = py
                    if qy < row_lo_y:
                        row_lo_y = qy
                    if py > row_hi_y:
                        row_hi_y = py
                    if qy > row_hi_y:
                        row_hi_y = qy
                if j == 0:
                    rb = row * 4
                    row_box[rb] = row_lo_x
                    row_box[rb + 1] = row_hi_x
                    row_box[rb + 2] = row_lo_y
                    row_box[rb + 3] = row_hi_y
                moved = False
            b = j * 4
            if row_hi_x < bounds[b] or row_lo_x > bounds[b + 1] or row_hi_y < bounds[b + 2] or \
                    row_lo_y > bounds[b + 3]:
                continue
            rb = row * 4
            row_box[rb] = min(row_box[rb], bounds[b])
            row_box[rb + 1] = max(row_box[rb + 1], bounds[b + 1])
            row_box[rb + 2] = min(row_box[rb + 2], bounds[b + 2])
            row_box[rb + 3] = max(row_box[rb + 3], bounds[b + 3])
            for k in range(first, last):
                if inv_mass[k] == 0.0:
                    continue
                i = k + k
                px = pos[i]
                py = pos[i + 1]
                qx = prev[i]
                qy = prev[i + 1]
                if (px < bounds[b] and qx < bounds[b]) or (px > bounds[b + 1] and qx > bounds[b + 1]) or \
                        (py < bounds[b + 2] and qy < bounds[b + 2]) or (py > bounds[b + 3] and qy > bounds[b + 3]):
                    continue
                jj = j + j
                ox0 = was[jj]
                oy0 = was[jj + 1]
                ox1 = now[jj]
                oy1 = now[jj + 1]
                hx = half[jj]
                hy = half[jj + 1]
                slide = 1.0 - friction[j]
                # Relative to the obstacle: from (ax, ay) to (bx, by).
                ax = qx - ox0
                ay = qy - oy0
                bx = px - ox1
                by = py - oy1
                dx = bx - ax
                dy = by - ay
                if shape[j] == 0:
                    r = hx
                    r2 = r * r
                    b2 = bx * bx + by * by
                    a2 = ax * ax + ay * ay
                    if a2 < r2:
                        # Started inside: out radially, if it is still in.
                        if b2 < r2:
                            if b2 > 0.0:
                                s = r / sqrt(b2)
                                bx = bx * s
                                by = by * s
                            else:
                                bx = 0.0
                                by = r
                            px = ox1 + bx
                            py = oy1 + by
                            pos[i] = px
                            pos[i + 1] = py
                            moved = True
                        continue
                    # Entered? |a + t d| = r for t in [0, 1], moving inward.
                    dd = dx * dx + dy * dy
                    ad = ax * dx + ay * dy
                    if ad >= 0.0 or dd == 0.0:
                        continue
                    disc = ad * ad - dd * (a2 - r2)
                    if disc < 0.0:
                        continue
                    t = (-ad - sqrt(disc)) / dd
                    if t > 1.0:
                        continue
                    if t < 0.0:
                        t = 0.0
                    ex = ax + t * dx
                    ey = ay + t * dy
                    # The entry point, exactly on the circle, and the surface's normal there.
                    el = sqrt(ex * ex + ey * ey)
                    nx = ex / el
                    ny = ey / el
                    ex = nx * r
                    ey = ny * r
                    # What was left of the step, less its part into the surface, slowed by friction.
                    u = 1.0 - t
                    rx = dx * u
                    ry = dy * u
                    rn = rx * nx + ry * ny
                    if rn < 0.0:
                        rx = rx - rn * nx
                        ry = ry - rn * ny
                    bx = ex + rx * slide
                    by = ey + ry * slide
                    b2 = bx * bx + by * by
                    if b2 < r2:
                        s = r / sqrt(b2)
                        bx = bx * s
                        by = by * s
                    px = ox1 + bx
                    py = oy1 + by
                    pos[i] = px
                    pos[i + 1] = py
                    moved = True
                    continue
                # A box: inside is |x| < hx and |y| < hy.
                if ax > -hx and ax < hx and ay > -hy and ay < hy:
                    if bx > -hx and bx < hx and by > -hy and by < hy:
                        # Started inside and still in: out through the nearest side.
                        gx = hx - abs(bx)
                        gy = hy - abs(by)
                        if gx < gy:
                            bx = hx if bx >= 0.0 else -hx
                        else:
                            by = hy if by >= 0.0 else -hy
                        px = ox1 + bx
                        py = oy1 + by
                        pos[i] = px
                        pos[i + 1] = py
                        moved = True
                    continue
                # Entered? The slabs' entry and exit times along a + t d.
                t_in = -1.0
                t_out = 2.0
                side = 0
                if dx != 0.0:
                    t1 = (-hx - ax) / dx
                    t2 = (hx - ax) / dx
                    if t1 > t2:
                        tmp = t1
                        t1 = t2
                        t2 = tmp
                    if t1 > t_in:
                        t_in = t1
                        side = 1
                    if t2 < t_out:
                        t_out = t2
                elif ax <= -hx or ax >= hx:
                    continue
                if dy != 0.0:
                    t1 = (-hy - ay) / dy
                    t2 = (hy - ay) / dy
                    if t1 > t2:
                        tmp = t1
                        t1 = t2
                        t2 = tmp
                    if t1 > t_in:
                        t_in = t1
                        side = 2
                    if t2 < t_out:
                        t_out = t2
                elif ay <= -hy or ay >= hy:
                    continue
                if t_in >= t_out or t_in > 1.0 or t_out <= 0.0 or side == 0:
                    continue
                if t_in < 0.0:
                    t_in = 0.0
                u = 1.0 - t_in
                if side == 1:
                    # Through a vertical side: on it, sliding along y.
                    bx = -hx if dx > 0.0 else hx
                    by = ay + t_in * dy + dy * u * slide
                else:
                    by = -hy if dy > 0.0 else hy
                    bx = ax + t_in * dx + dx * u * slide
                px = ox1 + bx
                py = oy1 + by
                pos[i] = px
                pos[i + 1] = py
                moved = True


def shield_edges(pos, prev, inv_mass, edge_a, edge_b, n_edges, cols, rows, count, shape, half,
                 was, at, row_box, row_mask):
    """No edge passes through a circle either (collide keeps the vertices out; a peg narrower
    than the spacing, or a stretched cloth, would otherwise slip between two of them: a towel
    on the seed's method fell through its peg). An edge whose segment enters a circle, its ends
    outside, is moved out along the normal at its nearest point, its ends by their inverse
    masses and their share of that point (a point-on-segment constraint), so that it touches.
    Rows first: each row's box (row_box, as collide left it) with the next's marks the circles
    that can meet its edges (row_mask: a bit per obstacle), and an edge in rows none meets
    costs one lookup. Returns how many edges it moved."""
    sqrt = math.sqrt
    hits = 0
    for row in range(rows):
        b = row * 4
        lo_x = row_box[b]
        hi_x = row_box[b + 1]
        lo_y = row_box[b + 2]
        hi_y = row_box[b + 3]
        if row + 1 < rows:
            lo_x = min(lo_x, row_box[b + 4])
            hi_x = max(hi_x, row_box[b + 5])
            lo_y = min(lo_y, row_box[b + 6])
            hi_y = max(hi_y, row_box[b + 7])
        mask = 0
        for j in range(count):
            if shape[j] != 0:
                continue
            jj = j + j
            if hi_x < at[jj] - half[jj] or lo_x > at[jj] + half[jj] or \
                    hi_y < at[jj + 1] - half[jj + 1] or lo_y > at[jj + 1] + half[jj + 1]:
                continue
            mask = mask | (1 << j)
        row_mask[row] = mask
        if mask != 0:
            hits += 1
    moved = 0
    if hits == 0:
        return moved
    for e in range(n_edges):
        a = edge_a[e]
        bb = edge_b[e]
        row = (a if a < bb else bb) // cols
        mask = row_mask[row]
        if mask == 0:
            continue
        wa = inv_mass[a]
        wb = inv_mass[bb]
        if wa == 0.0 and wb == 0.0:
            continue
        i = a + a
        ii = bb + bb
        for j in range(count):
            if (mask & (1 << j)) == 0:
                continue
            jj = j + j
            cx = at[jj]
            cy = at[jj + 1]
            hx = half[jj]
            hy = half[jj + 1]
            ax = pos[i]
            ay = pos[i + 1]
            dx = pos[ii] - ax
            dy = pos[ii + 1] - ay
            dd = dx * dx + dy * dy
            if dd < TINY2:
                continue
            nx = 0.0
            ny = 0.0
            depth = 0.0
            t = 0.0
            if shape[j] == 0:
                t = ((cx - ax) * dx + (cy - ay) * dy) / dd
                if t <= 0.0 or t >= 1.0:
                    continue
                # A chord of the circle is where a cloth lying on it has its edges: an edge
                # may cut in as deep as a chord of its length, never past half the radius (to
                # slip through it must pass the centre).
                re = sqrt(max(hx * hx - 0.25 * dd, 0.0))
                if re < 0.5 * hx:
                    re = 0.5 * hx
                # Which side of the edge the centre is on now, and was on when the step began
                # (swept: an edge that passed the centre within the step goes back to its side,
                # not on through).
                v = sqrt(dd)
                px = -dy / v
                py = dx / v
                side = (cx - ax) * px + (cy - ay) * py
                qx = prev[i]
                qy = prev[i + 1]
                ex = prev[ii] - qx
                ey = prev[ii + 1] - qy
                before = (was[jj] - qx) * (-ey) + (was[jj + 1] - qy) * ex
                ee = ex * ex + ey * ey
                tb = ((was[jj] - qx) * ex + (was[jj + 1] - qy) * ey) / ee if ee > TINY2 else 0.5
                if before == 0.0 or tb <= 0.0 or tb >= 1.0:
                    before = side
                if before >= 0.0:
                    depth = re - side
                    nx = -px
                    ny = -py
                else:
                    depth = re + side
                    nx = px
                    ny = py
                if depth <= 0.0:
                    continue
            else:
                # Boxes: their vertices' test only. An edge's push at a box's corners kept a
                # cloth lying over them from settling (0.2 m/s after 8 s, 10x10 on a box), and
                # a box's corner slips between two vertices only when the cloth is stretched
                # past the box's own size.
                continue
            s = 1.0 - t
            den = s * s * wa + t * t * wb
            if den == 0.0:
                continue
            lam = depth / den
            ka = wa * s * lam
            kb = wb * t * lam
            pos[i] += ka * nx
            pos[i + 1] += ka * ny
            pos[ii] += kb * nx
            pos[ii + 1] += kb * ny
            moved += 1
    return moved
