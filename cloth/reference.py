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


def rest_grid(cols, rows, spacing):
    return [(c * spacing, -r * spacing) for r in range(rows) for c in range(cols)]
