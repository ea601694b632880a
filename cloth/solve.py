"""The per-step kernels: integration and the constraint projections.

Each kernel is one plain function over flat arrays, with the arrays and constants in locals
and no calls in its loop but `sqrt`: that is what lets Transcrypt's output run as fast as
hand-written JS (../shared/notes/transcrypt.md section 3). Only + - * / and sqrt touch the
floats, in a fixed order, so CPython and the browser agree bit for bit.

Layout: `pos` and `prev` interleave x and y (pos[2k], pos[2k+1]); `inv_mass[k]` is 0 for a
pinned or held vertex; edge e joins `edge_a[e]` and `edge_b[e]` with rest length `rest[e]`.
"""

import math

# A step's constants, in one Float64Array per cloth (Cloth.consts, filled by sim.configure):
# a double passed as an argument to a kernel V8 does not inline is boxed into a fresh heap
# number on every call (measured: about 50 bytes a frame through the line solves), where a
# read from a typed array inside the kernel is not.
K_SPACING = 0
K_TOLERANCE = 1
K_ALPHA = 2
K_STRETCH = 3
K_KEEP = 4
K_AX = 5
K_AY = 6
K_MAX_STEP = 7
K_TEAR2 = 8
K_HAND_STEP = 9
K_HAND_SHARE = 10
K_HAND_PUSH = 11
K_WIND_X = 12      # the air's displacement in this step (wind * gusts * h), m
K_WIND_Y = 13
K_AIR = 14         # drag * spacing * h / (2 keep) (blow)
N_CONSTS = 15

# At most this share of the air's relative motion across an edge is taken up by each end in
# one step: a vertex has up to eight edges, and a stronger push would overshoot the air (an
# explicit drag is stable only while drag * h / mass stays small; capped, any drag is).
AIR_MOST = 0.125

# Below this squared length an edge has no direction to push along (two fixed vertices
# dragged onto one point): it is skipped rather than divided by zero, which would turn the
# whole cloth into NaN within a frame.
TINY2 = 1e-30


def blow(pos, prev, inv_mass, edge_a, edge_b, n_edges, consts):
    """The air's drag across every edge: an edge of length L stands for a strip of cloth one
    spacing s wide, and the air moving at v_rel relative to it (its ends' mean velocity)
    pushes it with drag * L * s * (v_rel . n) n along its normal n, half on each end. As a
    change of each end's step (its velocity times the step h), taken from `prev`, so that
    Verlet carries it: a frame's impulse (sim.feel_air), du = drag * s * dt / 2 * w * L *
    ((u_air - u_edge) . n) n with u the motions over one step h, each end's share
    at most AIR_MOST of the relative motion across the edge. An edge moving with the air, or
    along itself, feels nothing. (consts[K_AIR] carries 1 / keep: integrate's damping then
    leaves the push whole.)"""
    sqrt = math.sqrt
    wx = consts[K_WIND_X]
    wy = consts[K_WIND_Y]
    k = consts[K_AIR]
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
        if l2 < TINY2:
            continue
        length = sqrt(l2)
        rx = wx - 0.5 * ((pos[i] - prev[i]) + (pos[j] - prev[j]))
        ry = wy - 0.5 * ((pos[i + 1] - prev[i + 1]) + (pos[j + 1] - prev[j + 1]))
        across = (rx * nx + ry * ny) / l2
        ca = k * wa * length
        if ca > AIR_MOST:
            ca = AIR_MOST
        cb = k * wb * length
        if cb > AIR_MOST:
            cb = AIR_MOST
        prev[i] -= ca * across * nx
        prev[i + 1] -= ca * across * ny
        prev[j] -= cb * across * nx
        prev[j + 1] -= cb * across * ny


def integrate(pos, prev, inv_mass, n, consts, anchor, tether, tethered, held, hands_on):
    """Position Verlet, x' = x + (x - x*) * keep + a h^2, for every free vertex, and when
    `tethered` its tether's projection right after it (below); returns how many vertices had
    their speed clamped. A hand (held[k] == 1 with a mass: drive_hands has already placed it)
    gets only its tether; `hands_on`: there is one (else held is not read).

    keep = 1 / (1 + damping h): the velocity (x - x*) / h loses damping * h of itself per step,
    in a form that stays in (0, 1] for any damping and step (exp would not be bit-exact).
    max_step = max_speed * h is a safety net, not physics: with one or two sweeps an undamped
    cloth can pump energy without bound (a 60x60 cloth on one pin reaches 1e9 m/s, then NaN).
    Speeds above max_speed are scaled down to it; below it the step is exactly the seed's.

    One pass for both because a vertex's tether reads only the vertex and its anchor, a fixed
    vertex, which neither moves: every vertex sees the same operations as with a pass of
    Verlet and then one of tethers, and positions are the same to the bit.

    Tethers, long-range attachments (Kim, Chentanez, Mueller 2012), one-sided: a free vertex
    may be no farther from its anchor (the nearest fixed vertex along the cloth) than the
    length of the shortest path between them over the edges (tethers.find_anchors). One
    projection per vertex removes the low-frequency stretch that Gauss-Seidel sweeps take
    O(N^2) passes to remove. Like sweep_xpbd, the vertex moves along the anchor-to-vertex
    direction at the start of the step (one Newton step on |d|^2 = limit^2, no sqrt), so
    that a tether that is also an edge (a pendulum) keeps its energy; far from the limit or
    after a sharp turn it is projected along d onto the exact distance instead.
    consts[K_STRETCH] (>= 1) scales every limit while a hand pulls the cloth beyond its reach
    (tethers.over_reach)."""
    sqrt = math.sqrt
    keep = consts[K_KEEP]
    ax = consts[K_AX]
    ay = consts[K_AY]
    max_step = consts[K_MAX_STEP]
    max_step2 = max_step * max_step
    stretch = consts[K_STRETCH]
    clamped = 0
    for k in range(n):
        if inv_mass[k] == 0.0:
            continue
        i = k + k
        x = pos[i]
        y = pos[i + 1]
        if hands_on and held[k] == 1:
            px = x
            py = y
            x = prev[i]
            y = prev[i + 1]
        else:
            vx = (x - prev[i]) * keep
            vy = (y - prev[i + 1]) * keep
            v2 = vx * vx + vy * vy
            if v2 > max_step2:
                s = max_step / sqrt(v2)
                vx = vx * s
                vy = vy * s
                clamped += 1
            px = x + vx + ax
            py = y + vy + ay
            pos[i] = px
            pos[i + 1] = py
            prev[i] = x
            prev[i + 1] = y
        if not tethered:
            continue
        c = anchor[k]
        if c < 0:
            continue
        # The tether (see above).
        j = c + c
        dx = px - pos[j]
        dy = py - pos[j + 1]
        d2 = dx * dx + dy * dy
        limit = tether[k] * stretch
        limit2 = limit * limit
        if d2 <= limit2:
            continue
        ox = x - prev[j]
        oy = y - prev[j + 1]
        dot = dx * ox + dy * oy
        if dot * dot > 0.81 * d2 * (ox * ox + oy * oy) and dot > 0.0 and d2 < 1.21 * limit2:
            s = 0.5 * (d2 - limit2) / dot
            pos[i] = px - ox * s
            pos[i + 1] = py - oy * s
        else:
            d = sqrt(d2)
            s = (d - limit) / d
            pos[i] = px - dx * s
            pos[i + 1] = py - dy * s
    return clamped


def sweep_jakobsen(pos, inv_mass, edge_a, edge_b, rest, m, track, out):
    """One Gauss-Seidel pass of the seed's projection; out[0] = the largest |len - rest| / rest
    seen (when `track`, else 0). Doubles come back through `out`, not as the return value: a
    returned double is a heap number in JS, an allocation per call in the hot path.

    Per edge: diff = (len - rest) / len, and each end moves along the edge by its share
    w_i / (w_a + w_b) of diff: 1/2 each for two free ends (the seed's formula exactly), the
    whole of it for a free end joined to a fixed one, nothing for two fixed ends."""
    sqrt = math.sqrt
    worst = 0.0
    for e in range(m):
        a = edge_a[e]
        b = edge_b[e]
        wa = inv_mass[a]
        wb = inv_mass[b]
        w = wa + wb
        if w == 0.0:
            continue
        ia = a + a
        ib = b + b
        dx = pos[ib] - pos[ia]
        dy = pos[ib + 1] - pos[ia + 1]
        d2 = dx * dx + dy * dy
        if d2 < TINY2:
            continue
        length = sqrt(d2)
        err = length - rest[e]
        if track:
            r = err / rest[e]
            if r > worst:
                worst = r
            elif -r > worst:
                worst = -r
        s = err / length / w
        sa = s * wa
        sb = s * wb
        pos[ia] += dx * sa
        pos[ia + 1] += dy * sa
        pos[ib] -= dx * sb
        pos[ib + 1] -= dy * sb
    out[0] = worst


def sweep_xpbd(pos, prev, inv_mass, edge_a, edge_b, rest, lam, m, consts, track, out):
    """One Gauss-Seidel pass of XPBD (Macklin, Mueller, Chentanez 2016) with the constraint
    gradient taken at the start of the step, as SHAKE does; out[0] = the largest |C| / rest.

    C = (|d|^2 - rest^2) / (2 rest) (= len - rest to first order), d = x_b - x_a now, o the
    same edge at the start of the step (`prev`). Moving the ends along o rather than d is what
    makes the projection time-reversible: a pendulum keeps its energy to 1e-6 per swing where
    the seed's projection along d loses 28% per period at 60 Hz. And it needs no sqrt.
        d_lambda = (-C - alpha~ lambda) / ((w_a + w_b) (d . o) / rest^2 + alpha~)
        x_b += w_b d_lambda o / rest,  x_a -= w_a d_lambda o / rest,  alpha~ = compliance / h^2
    The accumulated lambda makes stiffness a material property (compliance, m/N) instead of a
    function of the iteration count; compliance 0 is an inextensible edge. Where the edge has
    turned by more than 25 degrees within the step, or is more than 10% off its rest length,
    the linearisation is poor, and the edge is projected along d onto its exact length.
    The error it measures is the constraint's residual, C + alpha~ lambda (for an inextensible
    edge C itself): a compliant edge is right when its stretch matches its force, not at rest
    length."""
    sqrt = math.sqrt
    alpha = consts[K_ALPHA]
    worst = 0.0
    for e in range(m):
        a = edge_a[e]
        b = edge_b[e]
        wa = inv_mass[a]
        wb = inv_mass[b]
        w = wa + wb
        if w == 0.0:
            continue
        ia = a + a
        ib = b + b
        dx = pos[ib] - pos[ia]
        dy = pos[ib + 1] - pos[ia + 1]
        d2 = dx * dx + dy * dy
        if d2 < TINY2:
            continue
        r = rest[e]
        r2 = r * r
        ox = prev[ib] - prev[ia]
        oy = prev[ib + 1] - prev[ia + 1]
        dot = dx * ox + dy * oy
        # alpha~ lambda: the force the edge carries so far this step, as a length
        held_by = alpha * lam[e]
        if dot * dot > 0.81 * d2 * (ox * ox + oy * oy) and dot > 0.0 and \
                d2 < 1.21 * r2 and d2 > 0.81 * r2:
            # The usual case: within 10% of rest and turned < 25 degrees in the step.
            c = (d2 - r2) / (r + r)
            dl = (-c - held_by) / (w * dot / r2 + alpha)
            s = dl / r
        else:
            # Far from rest or turned sharply (a drag, a teleport): the linearisation along o
            # would under- or over-shoot, so project along d onto the exact length instead.
            length = sqrt(d2)
            c = length - r
            dl = (-c - held_by) / (w + alpha)
            s = dl / length
            ox = dx
            oy = dy
        if track:
            q = (c + held_by) / r
            if q > worst:
                worst = q
            elif -q > worst:
                worst = -q
        lam[e] += dl
        sa = s * wa
        sb = s * wb
        pos[ia] -= ox * sa
        pos[ia + 1] -= oy * sa
        pos[ib] += ox * sb
        pos[ib + 1] += oy * sb
    out[0] = worst


def project_cells(pos, inv_mass, cols, rows, strength, intact, cell_ok, hands_on, grip):
    """Pull every cell toward a parallelogram: for the cell A = (r, c), B = (r, c+1),
    C = (r+1, c+1), D = (r+1, c), the linear constraint A + C - B - D = 0, of which each pass
    removes the fraction `strength` (each corner moving by its share w_i / sum w).

    Why: a quadrilateral of four equal, inextensible sides is either a rhombus (a parallelogram)
    or folded flat onto itself (B on D, or A on C). The folded branch is where an exactly
    inextensible structural grid gets stuck after a flick: a folded cell can turn freely about
    its fold, gravity has nothing to pull it open with, and unfolding through the rhombus branch
    means first straightening the fold. Measured on a 10x8 cloth hung from two corners, after a
    bottom vertex was thrown 1.4 m, dragged zig-zag or pulled far: without this constraint every
    inextensible variant stayed 10-25% of the width from its undisturbed hang (ten folded cells
    for good); with it, within 0.1%. On the rhombus branch the constraint holds exactly, so it
    changes no equilibrium of the seed's model: its hang from two corners has every cell a
    rhombus (every row is the top row moved down). Linear, so no square root; it conserves
    linear and angular momentum (its gradient sums to zero and it is invariant under rotation).
    Not all of the defect at once: pins a person sets or drags can ask for cells no
    parallelogram grid can take (two pinned neighbours dragged onto one point), and a hard
    constraint would then fight the edges for good (measured: a cloth that never came to
    rest); a partial pull gives way to them.

    Order: the cells of row r, column c in waves t = c + 2 r, each wave's cells by row. A cell
    shares corners only with the eight around it, and those of the row-major order before it,
    (r-1, c-1..c+1) and (r, c-1), are in earlier waves (t-3..t-1), the later ones in later
    waves, while the cells of one wave share none: so each corner sees the same updates in the
    same order as row by row, and the result is the same to the bit. But consecutive cells no
    longer wait for each other: row by row each cell read the corners its predecessor had just
    written, a chain through two divisions (measured on the settled 60x60 corners in node:
    0.30 -> 0.22 ms a frame)."""
    if rows < 2 or cols < 2:
        return
    last_c = cols - 2
    last_r = rows - 2
    for t in range(last_c + last_r + last_r + 1):
        r = 0
        if t > last_c:
            r = (t - last_c + 1) >> 1
        r_end = t >> 1
        if r_end > last_r:
            r_end = last_r
        while r <= r_end:
            c = t - r - r
            a = r * cols + c
            cell = a - r
            r += 1
            if not intact and cell_ok[cell] == 0:
                continue    # a cell with a broken side is no longer a cell
            b = a + 1
            d = a + cols
            e = d + 1
            if hands_on and (grip[a] >= 0 or grip[b] >= 0 or grip[d] >= 0 or grip[e] >= 0):
                continue    # a hand bends the cloth where it holds it (sim.HAND_FORCE)
            wa = inv_mass[a]
            wb = inv_mass[b]
            we = inv_mass[e]
            wd = inv_mass[d]
            w = wa + wb + we + wd
            if w == 0.0:
                continue
            ia = a + a
            ib = b + b
            ie = e + e
            idd = d + d
            sx = (pos[ia] + pos[ie] - pos[ib] - pos[idd]) * strength / w
            sy = (pos[ia + 1] + pos[ie + 1] - pos[ib + 1] - pos[idd + 1]) * strength / w
            pos[ia] -= wa * sx
            pos[ia + 1] -= wa * sy
            pos[ie] -= we * sx
            pos[ie + 1] -= we * sy
            pos[ib] += wb * sx
            pos[ib + 1] += wb * sy
            pos[idd] += wd * sx
            pos[idd + 1] += wd * sy


def solve_lines(pos, inv_mass, first, stride, nodes, lines, line_step, newton, nx, ny, cc, cd,
                intact, link_ok, consts, lam, slot):
    """Solve every edge of a grid line at once: for each of `lines` lines (node i of line l is
    first + l * line_step + i * stride, `nodes` nodes, every link consts[K_SPACING] long), the
    linearised
    constraints len_i - rest = 0 of the line's links form a tridiagonal system in the
    multipliers,
        (w_i + w_i+1) dl_i - w_i (n_i-1 . n_i) dl_i-1 - w_i+1 (n_i . n_i+1) dl_i+1 = len_i - rest,
    solved exactly by the Thomas algorithm (diagonally dominant, so stable), after which node i
    moves by w_i (n_i dl_i - n_i-1 dl_i-1). That is one Newton step. A line none of whose links
    is off by more than `tolerance` (a fraction of rest) is left alone; one whose worst link is
    off by more than sqrt(tolerance) is solved again, up to `newton` steps in all. nx, ny, cc, cd are work arrays of `nodes` doubles.

    A compliant material (consts[K_ALPHA] = compliance / h^2 > 0) is the same solve of XPBD's
    equations for the line: alpha~ joins the diagonal and the right-hand side is the residual
    len_i - rest + alpha~ lambda_i, lambda the link's multiplier this step, shared with the
    sweeps (lam[slot[a]] for the link from node a), so that each link ends where its stretch
    matches its force. A hanging column is then exact in one solve, whatever its length
    (measured: a 30x30 curtain hung from its top row, compliance 1e-6 m/N, 1 kg a vertex:
    top strain 8.24e-3 against the exact 8.25e-3; 4.3e-2 without line solves).
    A torn cloth (not `intact`) has broken links (link_ok[a] == 0 for the link from node a):
    such a link has no direction and no error, so its multiplier is 0 and its neighbours'
    coupling to it vanishes: the line is solved as the chains between its breaks.
    Two passes per Newton step: one computes the links' directions and errors and eliminates
    forward (the super-diagonal of link i is the sub-diagonal of link i + 1, known one link
    later); the other substitutes back from the last link, moving each link's ends as it goes.

    Why: a row or column carrying a load (the top row of a cloth hung from two corners holds
    the whole cloth) is a chain, and Gauss-Seidel moves a correction one link per sweep, so a
    chain of N links needs O(N^2) sweeps; its stretch made the slack hang sag centimetres too
    low at 60x60. One line solve removes a line's stretch whatever its length. More than one
    Newton step, because the column solves that come first pull a loaded top row far from its
    length (measured at 120x120: links 20-90% long), where one step leaves much of it."""
    sqrt = math.sqrt
    rest = consts[K_SPACING]
    tolerance = consts[K_TOLERANCE]
    alpha = consts[K_ALPHA]
    compliant = alpha > 0.0
    links = nodes - 1
    tol = tolerance * rest
    # Newton converges quadratically: from a largest error e one step leaves about e^2 / rest,
    # which is within the tolerance once e is within sqrt(tolerance).
    once = sqrt(tolerance) * rest
    # A link whose squared length lies within [lo2, hi2] is within the tolerance for certain
    # (the margins of 1e-9 are far wider than the rounding of sqrt and of the bounds), so a line
    # whose links all do is left alone at the cost of a pass of multiplications, not the
    # elimination's four divisions and a square root a link; a link outside them is measured
    # as the elimination measures it. The decision is exactly the elimination's. (Settled
    # 60x60 corners: most columns' second Newton step finds them within the tolerance; the
    # line solves 1.84 -> 1.44 ms a frame in node.)
    hi = rest + tol
    hi2 = hi * hi * (1.0 - 1e-9)
    lo = rest - tol
    lo2 = -1.0
    if lo > 0.0:
        lo2 = lo * lo * (1.0 + 1e-9)
    for l in range(lines):
        start = first + l * line_step
        for it in range(newton):
            a = start
            wa = inv_mass[a]
            # (A compliant link's error is its residual, which needs its multiplier: measured
            # by the elimination below.)
            within = not compliant
            for i in range(links if within else 0):
                b = a + stride
                wb = inv_mass[b]
                if wa + wb > 0.0 and (intact or link_ok[a] == 1):
                    ia = a + a
                    ib = b + b
                    dx = pos[ib] - pos[ia]
                    dy = pos[ib + 1] - pos[ia + 1]
                    d2 = dx * dx + dy * dy
                    if d2 > hi2 or d2 < lo2:
                        length = sqrt(d2)
                        if length >= 1e-15 and (length - rest > tol or rest - length > tol):
                            within = False
                            break
                a = b
                wa = wb
            if within:
                break
            a = start
            wa = inv_mass[a]
            worst = 0.0
            # The previous link's direction, 1 / den and rhs / den, carried in locals: the
            # elimination is a chain from link to link, and a value read back from the arrays it
            # was just stored in would lengthen it by a store-to-load round trip.
            pux = 0.0
            puy = 0.0
            pcc = 0.0
            pcd = 0.0
            for i in range(links):
                b = a + stride
                wb = inv_mass[b]
                ia = a + a
                ib = b + b
                dx = pos[ib] - pos[ia]
                dy = pos[ib + 1] - pos[ia + 1]
                length = sqrt(dx * dx + dy * dy)
                ux = 0.0
                uy = 0.0
                rhs = 0.0
                if length >= 1e-15 and (intact or link_ok[a] == 1):
                    ux = dx / length
                    uy = dy / length
                    rhs = length - rest
                    if compliant:
                        rhs += alpha * lam[slot[a]]
                den = wa + wb
                if den > 0.0:
                    if rhs > worst:
                        worst = rhs
                    elif -rhs > worst:
                        worst = -rhs
                    if compliant:
                        den += alpha
                nx[i] = ux
                ny[i] = uy
                if i > 0:
                    # cc[i - 1] holds 1 / den of the previous link until its super-diagonal,
                    # this link's sub-diagonal, is known.
                    sub = -wa * (pux * ux + puy * uy)
                    pcc = sub * pcc
                    cc[i - 1] = pcc
                    den -= sub * pcc
                    rhs -= sub * pcd
                if den <= 1e-12:
                    # A link between two fixed nodes: nothing to move (dl = 0).
                    pcc = 0.0
                    pcd = 0.0
                else:
                    pcc = 1.0 / den
                    pcd = rhs / den
                cc[i] = pcc
                cd[i] = pcd
                pux = ux
                puy = uy
                a = b
                wa = wb
            if worst <= tol:
                break
            later = 0.0
            i = links - 1
            b = start + links * stride
            while i >= 0:
                a = b - stride
                dl = cd[i]
                if i < links - 1:
                    dl -= cc[i] * later
                later = dl
                if compliant:
                    lam[slot[a]] -= dl
                sa = inv_mass[a] * dl
                sb = inv_mass[b] * dl
                ia = a + a
                ib = b + b
                ux = nx[i]
                uy = ny[i]
                pos[ia] += ux * sa
                pos[ia + 1] += uy * sa
                pos[ib] -= ux * sb
                pos[ib + 1] -= uy * sb
                b = a
                i -= 1
            if worst <= once and not compliant:
                break


def mark_crossed(pos, edge_a, edge_b, rest, m, px, py, qx, qy):
    """Mark (rest = -1) every edge whose segment crosses the blade P -> Q, where the cloth is
    now; returns how many. Crossing is decided by the signs of four orientations (exact
    + - * on the same doubles in both runtimes): the edge's ends strictly on either side of the
    blade's line, and the blade's ends on either side of the edge's line, or one on it (a blade
    that stops on an edge cuts it). So an edge that only touches the blade, or lies along it,
    is not crossed, and a blade of no length crosses nothing."""
    ux = qx - px
    uy = qy - py
    count = 0
    for e in range(m):
        ia = edge_a[e] + edge_a[e]
        ib = edge_b[e] + edge_b[e]
        ax = pos[ia]
        ay = pos[ia + 1]
        bx = pos[ib]
        by = pos[ib + 1]
        d1 = ux * (ay - py) - uy * (ax - px)
        d2 = ux * (by - py) - uy * (bx - px)
        if not ((d1 > 0.0 and d2 < 0.0) or (d1 < 0.0 and d2 > 0.0)):
            continue
        vx = bx - ax
        vy = by - ay
        d3 = vx * (py - ay) - vy * (px - ax)
        d4 = vx * (qy - ay) - vy * (qx - ax)
        if (d3 > 0.0 and d4 > 0.0) or (d3 < 0.0 and d4 < 0.0):
            continue
        rest[e] = -1.0
        count += 1
    return count


def mark_overstretched(pos, edge_a, edge_b, rest, m, consts, most, best_q, best_e):
    """Mark (rest = -1) the `most` edges strained most past the limit: (len / rest)^2 >
    limit2 = consts[K_TEAR2] = (1 + tear)^2, no square root. Returns how many. best_q / best_e (`most` long)
    keep the worst ones seen, most strained first (an insertion; `most` is small)."""
    limit2 = consts[K_TEAR2]
    found = 0
    for e in range(m):
        ia = edge_a[e] + edge_a[e]
        ib = edge_b[e] + edge_b[e]
        dx = pos[ib] - pos[ia]
        dy = pos[ib + 1] - pos[ia + 1]
        r = rest[e]
        q = (dx * dx + dy * dy) / (r * r)
        if q <= limit2:
            continue
        if found < most:
            found += 1
        elif q <= best_q[found - 1]:
            continue
        i = found - 1
        while i > 0 and best_q[i - 1] < q:
            best_q[i] = best_q[i - 1]
            best_e[i] = best_e[i - 1]
            i -= 1
        best_q[i] = q
        best_e[i] = e
    for i in range(found):
        rest[best_e[i]] = -1.0
    return found


def drive_hands(pos, prev, hands, count, grip, offset, target, aim, aim_step, consts):
    """Before a step's constraints, the hands (sim.HAND_FORCE). For each vertex in a hand's grip
    (sim.regrip), its own point `aim` moves toward where the hand holds it (the hand's target +
    the vertex's offset) by consts[K_HAND_SHARE] of what is left of the way (1 / the steps left
    in the frame: a frame's motion is spread evenly over its steps), at most
    consts[K_HAND_STEP] = HAND_SPEED h. Then the vertex, a particle with inertia, is pushed so
    that it lands on the aim, x' = x + (x - x*) + push, the push at most consts[K_HAND_PUSH]:
    the most force the hand has (sim.HAND_FORCE). The constraints that follow may pull it back:
    the next step's push, which makes up for the velocity that left, pulls harder (a hand that
    holds a load rests where it is held while the load is within its strength). aim_step: how
    far each aim moved in this step (the hand's velocity times h, for a release)."""
    sqrt = math.sqrt
    share = consts[K_HAND_SHARE]
    most = consts[K_HAND_STEP]
    most2 = most * most
    push = consts[K_HAND_PUSH]
    push2 = push * push
    for j in range(count):
        k = hands[j]
        i = k + k
        ax = aim[i]
        ay = aim[i + 1]
        g = grip[k] + grip[k]
        gx = (target[g] + offset[i] - ax) * share
        gy = (target[g + 1] + offset[i + 1] - ay) * share
        g2 = gx * gx + gy * gy
        if g2 > most2:
            s = most / sqrt(g2)
            gx = gx * s
            gy = gy * s
        ax += gx
        ay += gy
        aim[i] = ax
        aim[i + 1] = ay
        aim_step[i] = gx
        aim_step[i + 1] = gy
        x = pos[i]
        y = pos[i + 1]
        vx = x - prev[i]
        vy = y - prev[i + 1]
        # The step it should take: all the way to the aim, but no faster than it could stop
        # by pushing back with half its strength (sqrt(push d), a braking distance; the other
        # half for the cloth's pull), so that a push too weak to land on the aim in one step
        # does not overshoot it (measured, 3x3 curtain: with all of it, 6 cm past the aim).
        dx = ax - x
        dy = ay - y
        d2 = dx * dx + dy * dy
        brake = push * sqrt(d2)
        if d2 > brake:
            s = sqrt(brake / d2)
            dx = dx * s
            dy = dy * s
        px = dx - vx
        py = dy - vy
        p2 = px * px + py * py
        if p2 > push2:
            s = push / sqrt(p2)
            px = px * s
            py = py * s
        prev[i] = x
        prev[i + 1] = y
        pos[i] = x + vx + px
        pos[i + 1] = y + vy + py


def follow_velocity(pos, before, n, per_time, vel):
    """vel (2n) <- the mean of vel and (pos - before) * per_time: each vertex's velocity,
    smoothed over frames (a vertex that only shakes back and forth averages out)."""
    for i in range(n + n):
        vel[i] = 0.5 * (vel[i] + (pos[i] - before[i]) * per_time)


def limit_speed(pos, prev, inv_mass, n, vel, h, extra, out):
    """If some free vertex's step, relative to the free vertices' mean step, is longer than
    (|vel_k| + extra) h, scale every free vertex's relative step by the one factor that brings
    the worst back to it; out[0] = that factor (1: none). One factor for all, so that the
    cloth's shape is a blend of two shapes the solver made (where it was and where it would
    go) and not bent by a limit that holds back one vertex and not its neighbour; relative to
    the mean step, so that the cloth's momentum (a throw) stays."""
    sqrt = math.sqrt
    mx = 0.0
    my = 0.0
    count = 0
    for k in range(n):
        if inv_mass[k] == 0.0:
            continue
        i = k + k
        mx += pos[i] - prev[i]
        my += pos[i + 1] - prev[i + 1]
        count += 1
    out[0] = 1.0
    if count == 0:
        return
    mx = mx / count
    my = my / count
    scale = 1.0
    for k in range(n):
        if inv_mass[k] == 0.0:
            continue
        i = k + k
        ux = pos[i] - prev[i] - mx
        uy = pos[i + 1] - prev[i + 1] - my
        u2 = ux * ux + uy * uy
        most = (sqrt(vel[i] * vel[i] + vel[i + 1] * vel[i + 1]) + extra) * h
        if u2 * scale * scale > most * most:
            scale = most / sqrt(u2)
    out[0] = scale
    if scale == 1.0:
        return
    for k in range(n):
        if inv_mass[k] == 0.0:
            continue
        i = k + k
        pos[i] = prev[i] + mx + (pos[i] - prev[i] - mx) * scale
        pos[i + 1] = prev[i + 1] + my + (pos[i + 1] - prev[i + 1] - my) * scale


def max_motion2(pos, prev, inv_mass, n, out):
    """out[0] = the largest squared distance between a free vertex's positions in `pos` and
    `prev`."""
    worst = 0.0
    for k in range(n):
        if inv_mass[k] == 0.0:
            continue
        i = k + k
        dx = pos[i] - prev[i]
        dy = pos[i + 1] - prev[i + 1]
        d2 = dx * dx + dy * dy
        if d2 > worst:
            worst = d2
    out[0] = worst


def copy_into(dst, src, m):
    for i in range(m):
        dst[i] = src[i]


def clear(values, m):
    for e in range(m):
        values[e] = 0.0


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
