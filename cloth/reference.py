"""Exact equilibria of the seed's model, for the tests and the benchmark (CPython only; never
transpiled).

- A curtain (the whole top row pinned) hangs as the rest grid.
- A grid of structural edges hung from its two top corners `span` apart: every cell is a
  rhombus, so vertex (r, c) = U_c + V_r (U_c the sum of the first c edges of the top row, V_r
  of a column), and the potential energy rows * sum(U_c.y) + cols * sum(V_r.y) is least with
  straight columns (V_r = (0, -r h)) under the top row's discrete catenary, a chain of `cols`
  nodes that each carry one column: link k at angle theta_k, tan(theta_k) = c ((cols-2)/2 - k),
  with c from a 1-D root find on the span. Every row is the top row moved down by r h.
"""
import math


def discrete_chain(n_links, link, span):
    """Exact equilibrium of n equal rigid links with equal weights at the inner joints, hung
    between two points `span` apart at equal height: [(x, y)] of the n + 1 joints from (0, 0),
    link k (1..n) at angle theta_k below the horizontal, tan(theta_k) = c ((n+1)/2 - k)."""
    def width(c):
        return sum(link * math.cos(math.atan(c * ((n_links + 1) / 2 - k)))
                   for k in range(1, n_links + 1))
    lo, hi = 0.0, 1.0
    while width(hi) > span:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        if width(mid) > span:
            lo = mid
        else:
            hi = mid
    c = (lo + hi) / 2
    pts = [(0.0, 0.0)]
    for k in range(1, n_links + 1):
        t = math.atan(c * ((n_links + 1) / 2 - k))
        x, y = pts[-1]
        pts.append((x + link * math.cos(t), y - link * math.sin(t)))
    return pts


def slack_hang(cols, rows, spacing, span):
    """[(x, y)] of the exact two-corner hang, the corners at (0, 0) and (span, 0): the top row
    is the discrete chain of cols - 1 links (each inner node carries one column, the same
    weight for all), and every row is the top row moved down by r h."""
    top = discrete_chain(cols - 1, spacing, span)
    return [(top[col][0], top[col][1] - row * spacing) for row in range(rows) for col in range(cols)]


def elliptic_k(m):
    """Complete elliptic integral of the first kind K(m), m = k^2, by the AGM."""
    a, b = 1.0, math.sqrt(1.0 - m)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def pendulum_period(length, amplitude, g=9.81):
    """Exact period of a point pendulum released from rest `amplitude` radians from the
    vertical: T = 4 sqrt(L / g) K(sin^2(amplitude / 2))."""
    return 4 * math.sqrt(length / g) * elliptic_k(math.sin(amplitude / 2) ** 2)


def rest_grid(cols, rows, spacing):
    return [(c * spacing, -r * spacing) for r in range(rows) for c in range(cols)]


# ---- a material of finite stiffness ---------------------------------------------------------
#
# A compliant edge (compliance a, m/N) carrying a tension T is T a longer than its rest length:
# its strain is T a / h. In a grid of structural edges a vertex of mass m stands for a cell of
# cloth (m = density h^2), so the strain of a column link that carries k vertices is
# k m g a / h = density g a (k h): the same at every resolution for the same length of cloth.


def hanging_column_strains(rows, spacing, mass, compliance, g=9.81):
    """Strains of the rows - 1 links of a column hung from its top vertex, top first: the link
    below row r carries the rows - 1 - r vertices under it."""
    return [(rows - 1 - r) * mass * g * compliance / spacing for r in range(rows - 1)]


def elastic_chain(n_links, link, span, node_weight, compliance):
    """A chain of n equal links (rest length `link`, compliance a) whose n - 1 inner joints each
    carry `node_weight` (N), hung between (0, 0) and (span, 0). Returns (points, tensions):
    the n + 1 joints and the n links' tensions. Statics: the horizontal tension H is the same in
    every link and the vertical one drops by node_weight at each joint, V_k = node_weight
    ((n - 1) / 2 - k) for link k (from 0); link k is (H, -V_k) / T_k long link + a T_k, so H
    solves sum (link + a T_k) H / T_k = span (bisection: the sum grows with H). With a = 0 this
    is `discrete_chain`."""
    def links(H):
        out = []
        for k in range(n_links):
            V = node_weight * ((n_links - 1) / 2 - k)
            T = math.sqrt(H * H + V * V)
            out.append((H, V, T, link + compliance * T))
        return out

    def width(H):
        return sum(L * Hh / T for Hh, V, T, L in links(H))

    if n_links * link <= span:
        raise ValueError('elastic_chain: a chain that reaches the span is taut (no sag to solve)')
    lo, hi = 0.0, node_weight * n_links + 1.0
    while width(hi) < span:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        if width(mid) < span:
            lo = mid
        else:
            hi = mid
    pts = [(0.0, 0.0)]
    tensions = []
    for Hh, V, T, L in links((lo + hi) / 2):
        x, y = pts[-1]
        pts.append((x + L * Hh / T, y - L * V / T))
        tensions.append(T)
    return pts, tensions


# A compliant grid hung from two corners has no such closed form: its rows cannot all be copies
# of the top row (a lower row whose links had the top row's stretched length would carry the
# same tension, and its vertices would not balance), so the load spreads over rows in a way
# only a 2-D solve gives. The benchmark holds that scene against the same run at 8x the
# substeps and at other grid sizes instead.


def wind_column(rows, spacing, density, drag, wind, gravity=9.81):
    """Exact equilibrium of one column of `rows` vertices (rigid links of `spacing`, vertex 0
    pinned at the origin, each vertex density * spacing^2 kg) in a horizontal wind `wind` m/s
    with drag `drag` (sim.feel_air: a link at angle theta from the vertical is pushed along
    its normal (cos theta, sin theta) by drag * spacing^2 * wind * cos theta, half on each
    end): [(x, y)] of the vertices. Each link points along the total load below it; found by
    fixed-point iteration on the angles. The continuum's lean: tan theta = drag wind /
    (density g) (wind_lean)."""
    n = rows - 1
    mass = density * spacing * spacing
    theta = [wind_lean(drag, wind, density, gravity)] * n
    for _ in range(10000):
        # loads on vertices 1..n
        fx = [0.0] * (n + 1)
        fy = [-mass * gravity] * (n + 1)
        for j in range(n):             # link j joins vertex j and j + 1
            f = drag * spacing * spacing * wind * math.cos(theta[j])
            for v in (j, j + 1):
                fx[v] += 0.5 * f * math.cos(theta[j])
                fy[v] += 0.5 * f * math.sin(theta[j])
        new = []
        px = py = 0.0
        for j in range(n - 1, -1, -1):
            px += fx[j + 1]
            py += fy[j + 1]
            new.append(math.atan2(px, -py))
        new.reverse()
        moved = max(abs(a - b) for a, b in zip(new, theta)) if n else 0.0
        theta = new
        if moved < 1e-15:
            break
    out = [(0.0, 0.0)]
    for j in range(n):
        x, y = out[-1]
        out.append((x + spacing * math.sin(theta[j]), y - spacing * math.cos(theta[j])))
    return out


def wind_lean(drag, wind, density, gravity=9.81):
    """The angle from the vertical of a long column in a horizontal wind (the continuum of
    wind_column): the normal push drag * wind * cos theta per area, tilted with the column,
    balances the weight's part across it, density g sin theta: tan theta = drag wind /
    (density g)."""
    return math.atan(drag * wind / (density * gravity))
