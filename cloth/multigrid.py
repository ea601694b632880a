"""Geometric multigrid for the linearised step: the coarse grids of cloth/coarse.py.

Gauss-Seidel sweeps (the seed's relaxation, or vertex descent) remove an error in a few sweeps
only where it varies from vertex to vertex; an error that varies over the whole cloth (a
sag, a stretch spread over the width) shrinks by about 1 - c / N^2 a sweep, so an N x N cloth
needs O(N^2) sweeps: measured, a two-point hang of jersey needed 10 sweeps a frame at 30x30,
40 at 60x60 and more than 40 at 120x120. Such an error is smooth, so a coarser grid sees it:
on a grid with half the spacing in each direction it varies twice as fast per vertex, and
sweeps there remove it, down to a grid of a few vertices, solved exactly.

The operators. Level 0 is the cloth's grid; its operator A0 is the Hessian of the step's energy
at the current positions (coarse.assemble), a 9-point stencil of 2x2 blocks: vertex (r, c) couples
to (r + dr, c + dc), dr, dc in {-1, 0, 1}, through the structural edges and diagonals that join
them. Level l + 1 has the nodes 0, 2, 4, ... of each dimension of level l and its last one (so
any size coarsens), and P_l interpolates bilinearly from it; A_{l+1} = P_l^T A_l P_l (Galerkin),
again a 9-point stencil. A vertex that takes no correction (fixed, or of a piece nothing holds:
cloth.uncorrected) has no row in P_0 (its correction is 0).

Storage: a level's operator is 27 doubles a node, 9 slots (dr + 1) * 3 + (dc + 1) of a
symmetric 2x2 block (xx, xy, yy); every block of a spring's Hessian is symmetric, and
P^T A P keeps them so.
"""

import math

from cloth.host import f64, i32

DIAG = 4
# A level of at most this many nodes is solved exactly (dense Cholesky: (2n)^3 / 3 flops when
# the operators are made, (2n)^2 a solve).
COARSEST = 48


def coarse_count(s):
    """The nodes a dimension of s nodes keeps: 0, 2, 4, ... and the last."""
    if s <= 2:
        return s
    return (s - 1) // 2 + 1 + ((s - 1) % 2)


class Level:
    def __init__(self, cols, rows):
        n = cols * rows
        self.cols = cols
        self.rows = rows
        self.n = n
        self.A = f64(27 * n)
        self.x = f64(2 * n)       # a V-cycle's answer on this level
        self.b = f64(2 * n)       # its right-hand side
        self.r = f64(2 * n)
        self.p = f64(2 * n)       # conjugate gradients' directions
        self.q = f64(2 * n)
        self.z = f64(2 * n)
        self.active = i32(n)      # 1 where a node interpolates to some free vertex below
        # Interpolation to this level from the next coarser: per node up to 4 parents, their
        # index, weight and coarse row and column.
        self.par = i32(4 * n)
        self.w = f64(4 * n)
        self.npar = i32(n)
        self.pr = i32(4 * n)
        self.pc = i32(4 * n)
        self.dense = f64(0)       # the coarsest level's Cholesky factor
        self.dense_n = 0


def parents_1d(f, s):
    """[coarse node, second coarse node or -1, the first's weight] of node f of a dimension of
    s nodes: a kept node is its own parent; one between two kept nodes takes half of each."""
    if s <= 2:
        return [f, -1, 1.0]
    if f == s - 1:
        return [coarse_count(s) - 1, -1, 1.0]
    if f % 2 == 0:
        return [f // 2, -1, 1.0]
    return [f // 2, f // 2 + 1, 0.5]


def hierarchy(cols, rows):
    """The levels of a cols x rows grid, finest first: coarsened while a level has more than
    COARSEST nodes (and once at least, where coarsening shrinks it), the last solved densely."""
    levels = [Level(cols, rows)]
    while True:
        top = levels[len(levels) - 1]
        if top.n <= COARSEST and len(levels) > 1:
            break
        cc = coarse_count(top.cols)
        cr = coarse_count(top.rows)
        if cc * cr >= top.n:
            break
        for r in range(top.rows):
            pr = parents_1d(r, top.rows)
            for c in range(top.cols):
                pc = parents_1d(c, top.cols)
                i = r * top.cols + c
                k = 0
                for a in range(2):
                    R = pr[0] if a == 0 else pr[1]
                    if R < 0:
                        continue
                    wr = pr[2] if a == 0 else 1.0 - pr[2]
                    for b in range(2):
                        C = pc[0] if b == 0 else pc[1]
                        if C < 0:
                            continue
                        wc = pc[2] if b == 0 else 1.0 - pc[2]
                        top.par[4 * i + k] = R * cc + C
                        top.w[4 * i + k] = wr * wc
                        top.pr[4 * i + k] = R
                        top.pc[4 * i + k] = C
                        k += 1
                top.npar[i] = k
        levels.append(Level(cc, cr))
    last = levels[len(levels) - 1]
    if len(levels) > 1:
        last.dense_n = 2 * last.n
        last.dense = f64(last.dense_n * last.dense_n)
    return levels


def galerkin(fine, coarse, fixed):
    """coarse.A = P^T fine.A P; `fixed` (1 per fine node that takes no correction) or None. A
    coarse node that interpolates to no free node gets the identity (its correction is 0)."""
    A = fine.A
    C = coarse.A
    nc = coarse.n
    for t in range(27 * nc):
        C[t] = 0.0
    for t in range(nc):
        coarse.active[t] = 0
    cols = fine.cols
    rows = fine.rows
    par = fine.par
    w = fine.w
    npar = fine.npar
    pr = fine.pr
    pc = fine.pc
    for r in range(rows):
        r0 = -1 if r > 0 else 0
        r1 = 2 if r + 1 < rows else 1
        for c in range(cols):
            i = r * cols + c
            if fixed is not None and fixed[i] != 0:
                continue
            ni = npar[i]
            for p in range(ni):
                coarse.active[par[4 * i + p]] = 1
            c0 = -1 if c > 0 else 0
            c1 = 2 if c + 1 < cols else 1
            for dr in range(r0, r1):
                for dc in range(c0, c1):
                    j = i + dr * cols + dc
                    if fixed is not None and fixed[j] != 0:
                        continue
                    base = (i * 9 + (dr + 1) * 3 + dc + 1) * 3
                    axx = A[base]
                    axy = A[base + 1]
                    ayy = A[base + 2]
                    if axx == 0.0 and axy == 0.0 and ayy == 0.0:
                        continue
                    nj = npar[j]
                    for p in range(ni):
                        I = par[4 * i + p]
                        wi = w[4 * i + p]
                        Ir = pr[4 * i + p] - 1
                        Ic = pc[4 * i + p] - 1
                        for q in range(nj):
                            wq = wi * w[4 * j + q]
                            o = (I * 9 + (pr[4 * j + q] - Ir) * 3 + pc[4 * j + q] - Ic) * 3
                            C[o] += wq * axx
                            C[o + 1] += wq * axy
                            C[o + 2] += wq * ayy
    for t in range(nc):
        if coarse.active[t] == 0:
            o = (t * 9 + DIAG) * 3
            C[o] = 1.0
            C[o + 1] = 0.0
            C[o + 2] = 1.0


def restrict(fine, coarse, fixed, v, out):
    """out = P^T v."""
    for t in range(2 * coarse.n):
        out[t] = 0.0
    par = fine.par
    w = fine.w
    npar = fine.npar
    for i in range(fine.n):
        if fixed is not None and fixed[i] != 0:
            continue
        vx = v[i + i]
        vy = v[i + i + 1]
        for p in range(npar[i]):
            I = par[4 * i + p]
            wi = w[4 * i + p]
            out[I + I] += wi * vx
            out[I + I + 1] += wi * vy


def prolong(fine, coarse, fixed, e, out):
    """out = P e (0 at a fixed node)."""
    par = fine.par
    w = fine.w
    npar = fine.npar
    for i in range(fine.n):
        sx = 0.0
        sy = 0.0
        if fixed is None or fixed[i] == 0:
            for p in range(npar[i]):
                I = par[4 * i + p]
                wi = w[4 * i + p]
                sx += wi * e[I + I]
                sy += wi * e[I + I + 1]
        out[i + i] = sx
        out[i + i + 1] = sy


def matvec(lv, x, out):
    """out = A x on level lv."""
    A = lv.A
    cols = lv.cols
    rows = lv.rows
    for r in range(rows):
        r0 = -1 if r > 0 else 0
        r1 = 2 if r + 1 < rows else 1
        for c in range(cols):
            i = r * cols + c
            c0 = -1 if c > 0 else 0
            c1 = 2 if c + 1 < cols else 1
            sx = 0.0
            sy = 0.0
            for dr in range(r0, r1):
                for dc in range(c0, c1):
                    j = i + dr * cols + dc
                    o = (i * 9 + (dr + 1) * 3 + dc + 1) * 3
                    sx += A[o] * x[j + j] + A[o + 1] * x[j + j + 1]
                    sy += A[o + 1] * x[j + j] + A[o + 2] * x[j + j + 1]
            out[i + i] = sx
            out[i + i + 1] = sy


def smooth(lv, x, b, forward):
    """One Gauss-Seidel sweep of 2x2 blocks on A x = b, forward or backward (a forward sweep
    before the coarse grid and a backward one after keep the V-cycle symmetric, as conjugate
    gradients needs of its preconditioner)."""
    A = lv.A
    cols = lv.cols
    rows = lv.rows
    n = lv.n
    for t in range(n):
        i = t if forward else n - 1 - t
        r = i // cols
        c = i - r * cols
        r0 = -1 if r > 0 else 0
        r1 = 2 if r + 1 < rows else 1
        c0 = -1 if c > 0 else 0
        c1 = 2 if c + 1 < cols else 1
        rx = b[i + i]
        ry = b[i + i + 1]
        for dr in range(r0, r1):
            for dc in range(c0, c1):
                if dr == 0 and dc == 0:
                    continue
                j = i + dr * cols + dc
                o = (i * 9 + (dr + 1) * 3 + dc + 1) * 3
                rx -= A[o] * x[j + j] + A[o + 1] * x[j + j + 1]
                ry -= A[o + 1] * x[j + j] + A[o + 2] * x[j + j + 1]
        o = (i * 9 + DIAG) * 3
        axx = A[o]
        axy = A[o + 1]
        ayy = A[o + 2]
        det = axx * ayy - axy * axy
        if det > 0.0:
            x[i + i] = (ayy * rx - axy * ry) / det
            x[i + i + 1] = (axx * ry - axy * rx) / det


def factor_dense(lv):
    """The coarsest level's operator as a dense matrix, Cholesky-factored in place (lower,
    row-major); a pivot below 1e-14 of the largest diagonal (a mode nothing resists) is
    raised to it."""
    N = lv.dense_n
    D = lv.dense
    A = lv.A
    cols = lv.cols
    rows = lv.rows
    sqrt = math.sqrt
    for t in range(N * N):
        D[t] = 0.0
    for r in range(rows):
        r0 = -1 if r > 0 else 0
        r1 = 2 if r + 1 < rows else 1
        for c in range(cols):
            i = r * cols + c
            c0 = -1 if c > 0 else 0
            c1 = 2 if c + 1 < cols else 1
            for dr in range(r0, r1):
                for dc in range(c0, c1):
                    j = i + dr * cols + dc
                    o = (i * 9 + (dr + 1) * 3 + dc + 1) * 3
                    D[(2 * i) * N + 2 * j] = A[o]
                    D[(2 * i) * N + 2 * j + 1] = A[o + 1]
                    D[(2 * i + 1) * N + 2 * j] = A[o + 1]
                    D[(2 * i + 1) * N + 2 * j + 1] = A[o + 2]
    scale = 0.0
    for i in range(N):
        if D[i * N + i] > scale:
            scale = D[i * N + i]
    tiny = 1e-14 * scale + 1e-300
    for j in range(N):
        s = D[j * N + j]
        for k in range(j):
            s -= D[j * N + k] * D[j * N + k]
        if s < tiny:
            s = tiny
        d = sqrt(s)
        D[j * N + j] = d
        for i in range(j + 1, N):
            s = D[i * N + j]
            for k in range(j):
                s -= D[i * N + k] * D[j * N + k]
            D[i * N + j] = s / d


def solve_dense(lv, x, b):
    N = lv.dense_n
    D = lv.dense
    for i in range(N):
        s = b[i]
        for k in range(i):
            s -= D[i * N + k] * x[k]
        x[i] = s / D[i * N + i]
    for t in range(N):
        i = N - 1 - t
        s = x[i]
        for k in range(i + 1, N):
            s -= D[k * N + i] * x[k]
        x[i] = s / D[i * N + i]


def vcycle(levels, l):
    """One V(1,1) cycle on levels[l]: its x from 0 for its b."""
    lv = levels[l]
    x = lv.x
    m = 2 * lv.n
    for t in range(m):
        x[t] = 0.0
    if l == len(levels) - 1:
        solve_dense(lv, x, lv.b)
        return
    coarse = levels[l + 1]
    smooth(lv, x, lv.b, True)
    matvec(lv, x, lv.r)
    r = lv.r
    b = lv.b
    for t in range(m):
        r[t] = b[t] - r[t]
    restrict(lv, coarse, None, r, coarse.b)
    vcycle(levels, l + 1)
    # x += P e (no fixed nodes below level 0), through r as scratch
    prolong(lv, coarse, None, coarse.x, r)
    for t in range(m):
        x[t] += r[t]
    smooth(lv, x, b, False)


def dot(a, b, m):
    s = 0.0
    for t in range(m):
        s += a[t] * b[t]
    return s


def pcg(levels, l, iters, b, x):
    """x ~ A^-1 b on level l: `iters` steps of conjugate gradients preconditioned by a V-cycle
    (uses the level's r, p, q, z, and its b and x for the cycle)."""
    lv = levels[l]
    m = 2 * lv.n
    r = lv.r
    p = lv.p
    q = lv.q
    z = lv.z
    for t in range(m):
        x[t] = 0.0
        z[t] = b[t]        # the residual, kept in z: the cycle overwrites r
    rz = 0.0
    for it in range(iters):
        for t in range(m):
            lv.b[t] = z[t]
        vcycle(levels, l)
        rz_new = dot(z, lv.x, m)
        if it == 0:
            for t in range(m):
                p[t] = lv.x[t]
        else:
            beta = rz_new / rz if rz != 0.0 else 0.0
            for t in range(m):
                p[t] = lv.x[t] + beta * p[t]
        rz = rz_new
        matvec(lv, p, q)
        pq = dot(p, q, m)
        if not (pq > 0.0):
            return
        alpha = rz / pq
        for t in range(m):
            x[t] += alpha * p[t]
            z[t] -= alpha * q[t]
