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


def slack_hang(cols, rows, spacing, span):
    """[(x, y)] of the exact two-corner hang, the corners at (0, 0) and (span, 0)."""
    links = cols - 1

    def width(c):
        return sum(spacing * math.cos(math.atan(c * ((cols - 2) / 2 - k))) for k in range(links))

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
    top = [(0.0, 0.0)]
    for k in range(links):
        t = math.atan(c * ((cols - 2) / 2 - k))
        x, y = top[-1]
        top.append((x + spacing * math.cos(t), y - spacing * math.sin(t)))
    return [(top[col][0], top[col][1] - row * spacing) for row in range(rows) for col in range(cols)]


def rest_grid(cols, rows, spacing):
    return [(c * spacing, -r * spacing) for r in range(rows) for c in range(cols)]
