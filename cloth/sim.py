"""The cloth: state as flat arrays, and `step()`, which reads like the algorithm.

State (struct of arrays, one per quantity; n vertices, m edges):
    pos, prev    2n doubles, x and y interleaved; velocity is (pos - prev) / h, never stored
    inv_mass     n doubles; 0 for a pinned or held vertex (unit mass otherwise)
    pinned, held n ints (0/1); a vertex is fixed while either is set
    edge_a, edge_b, rest   m edges: structural grid edges, then the shear diagonals if the
                 scene declares them
The core knows nothing of the DOM or GL: the page reads `pos`, `diff` and `stress`.
"""

import math

from cloth.host import f64, i32
from cloth.scene import SceneError
from cloth.solve import integrate, sweep_jakobsen, sweep_xpbd, project_tethers, clear
from cloth.measure import deformation, nearest_vertex
from cloth.tethers import find_anchors


class Cloth:
    def __init__(self, scene):
        self.scene = scene
        cols = scene.cols
        rows = scene.rows
        h = scene.spacing
        n = cols * rows
        self.cols = cols
        self.rows = rows
        self.spacing = h
        self.n_verts = n

        # The constants of a step, computed once: substep size, a h^2, damping factor.
        self.dt = scene.dt
        self.substeps = scene.substeps
        self.iterations = scene.iterations
        self.h = scene.dt / scene.substeps
        h2 = self.h * self.h
        self.ax = scene.gravity_x * h2
        self.ay = scene.gravity_y * h2
        self.keep = 1.0 / (1.0 + scene.damping * self.h)
        self.use_xpbd = scene.solver == 'xpbd'
        self.alpha = scene.compliance / h2
        self.tolerance = scene.tolerance
        self.use_tethers = scene.tethers

        self.pos = f64(2 * n)
        self.prev = f64(2 * n)
        self.inv_mass = f64(n)
        self.pinned = i32(n)
        self.held = i32(n)
        for r in range(rows):
            for c in range(cols):
                k = r * cols + c
                self.pos[k + k] = c * h
                self.pos[k + k + 1] = -r * h
        for i in range(len(scene.pins)):
            self.pinned[scene.pins[i]] = 1
        for k in range(n):
            self.inv_mass[k] = 0.0 if self.pinned[k] == 1 else 1.0
            self.rest_at(k)

        self.build_edges(scene.shear)
        self.lam = f64(self.n_edges)
        self.diff = f64(self.n_edges)
        self.stress = f64(n)
        self.stats = f64(5)
        self.max_diff = 0.0
        self.rms_diff = 0.0
        self.max_stress = 0.0
        self.max_strain = 0.0
        self.rms_strain = 0.0
        self.anchor = i32(n)
        self.tether = f64(n)
        self.anchors_stale = True
        self.frames_done = 0
        # Constraint projections done so far (edges + tethers): the benchmark's cost measure.
        self.projections = 0

    def build_edges(self, shear):
        """Horizontal and vertical grid neighbours (rest = spacing), vertex by vertex; then,
        if the scene declares shear, one diagonal per cell (rest = spacing * sqrt 2)."""
        cols = self.cols
        rows = self.rows
        h = self.spacing
        m = (cols - 1) * rows + cols * (rows - 1)
        if shear:
            m += (cols - 1) * (rows - 1)
        self.n_edges = m
        self.edge_a = i32(m)
        self.edge_b = i32(m)
        self.rest = f64(m)
        e = 0
        for r in range(rows):
            for c in range(cols):
                k = r * cols + c
                if c + 1 < cols:
                    e = self.set_edge(e, k, k + 1, h)
                if r + 1 < rows:
                    e = self.set_edge(e, k, k + cols, h)
        if shear:
            diagonal = h * math.sqrt(2.0)
            for r in range(rows - 1):
                for c in range(cols - 1):
                    k = r * cols + c
                    e = self.set_edge(e, k, k + cols + 1, diagonal)

        # Vertex -> edges adjacency (CSR): degree for the stress mean, neighbours for tethers.
        n = self.n_verts
        self.degree = i32(n)
        for e in range(m):
            self.degree[self.edge_a[e]] += 1
            self.degree[self.edge_b[e]] += 1
        self.adj_start = i32(n + 1)
        for k in range(n):
            self.adj_start[k + 1] = self.adj_start[k] + self.degree[k]
        fill = i32(n)
        self.adj_vertex = i32(2 * m)
        self.adj_rest = f64(2 * m)
        for e in range(m):
            a = self.edge_a[e]
            b = self.edge_b[e]
            self.adj_vertex[self.adj_start[a] + fill[a]] = b
            self.adj_rest[self.adj_start[a] + fill[a]] = self.rest[e]
            fill[a] += 1
            self.adj_vertex[self.adj_start[b] + fill[b]] = a
            self.adj_rest[self.adj_start[b] + fill[b]] = self.rest[e]
            fill[b] += 1

    def set_edge(self, e, a, b, rest):
        self.edge_a[e] = a
        self.edge_b[e] = b
        self.rest[e] = rest
        return e + 1

    # ---- the step ------------------------------------------------------------------------

    def frame(self):
        """Advance one frame: `substeps` steps of dt / substeps each."""
        if self.use_tethers and self.anchors_stale:
            find_anchors(self.n_verts, self.adj_start, self.adj_vertex, self.adj_rest,
                         self.inv_mass, self.anchor, self.tether)
            self.anchors_stale = False
        for s in range(self.substeps):
            self.step()
        self.frames_done += 1

    def step(self):
        """One step of size h: predict by Verlet, then relax the constraints."""
        n = self.n_verts
        m = self.n_edges
        pos = self.pos
        inv_mass = self.inv_mass
        integrate(pos, self.prev, inv_mass, n, self.keep, self.ax, self.ay)
        if self.use_xpbd:
            clear(self.lam, m)
        track = self.tolerance > 0.0
        for it in range(self.iterations):
            if self.use_xpbd:
                worst = sweep_xpbd(pos, self.prev, inv_mass, self.edge_a, self.edge_b, self.rest,
                                   self.lam, m, self.alpha, track)
            else:
                worst = sweep_jakobsen(pos, inv_mass, self.edge_a, self.edge_b, self.rest,
                                       m, track)
            self.projections += m
            if self.use_tethers:
                project_tethers(pos, inv_mass, self.anchor, self.tether, n)
                self.projections += n
            # The sweep measured the error it found before correcting: once that is within
            # tolerance the cloth is converged and further sweeps would be wasted.
            if track and worst <= self.tolerance:
                break

    # ---- holding, pinning ----------------------------------------------------------------

    def check_vertex(self, k):
        if not (k >= 0 and k < self.n_verts and math.floor(k) == k):
            raise SceneError('vertex: must be an index from 0 to cols * rows - 1')

    def rest_at(self, k):
        """Zero velocity for vertex k, with the previous position set so that a free fall
        from here is exact: x* = x + a h^2 / 2 gives x(t) = x + a t^2 / 2 at every step."""
        i = k + k
        if self.inv_mass[k] == 0.0:
            self.prev[i] = self.pos[i]
            self.prev[i + 1] = self.pos[i + 1]
        else:
            self.prev[i] = self.pos[i] + 0.5 * self.ax
            self.prev[i + 1] = self.pos[i + 1] + 0.5 * self.ay

    def refresh(self, k):
        """inv_mass follows pinned and held; the tether anchors follow the fixed set."""
        fixed = self.pinned[k] == 1 or self.held[k] == 1
        was_fixed = self.inv_mass[k] == 0.0
        self.inv_mass[k] = 0.0 if fixed else 1.0
        if fixed != was_fixed:
            self.anchors_stale = True
        self.rest_at(k)

    def grab(self, k, x, y):
        """Hold vertex k fixed at (x, y)."""
        self.check_vertex(k)
        self.held[k] = 1
        self.place(k, x, y)
        self.refresh(k)

    def move(self, k, x, y):
        """Move a held vertex to (x, y); it stays fixed there."""
        self.check_vertex(k)
        if self.held[k] == 0:
            raise SceneError('vertex: move needs a held vertex (grab it first)')
        self.place(k, x, y)
        self.refresh(k)

    def release(self, k):
        """Let go: a pinned vertex stays pinned where it was left, a free one falls from rest."""
        self.check_vertex(k)
        self.held[k] = 0
        self.refresh(k)

    def pin(self, k):
        self.check_vertex(k)
        self.pinned[k] = 1
        self.refresh(k)

    def unpin(self, k):
        self.check_vertex(k)
        self.pinned[k] = 0
        self.refresh(k)

    def toggle_pin(self, k):
        self.check_vertex(k)
        if self.pinned[k] == 1:
            self.unpin(k)
        else:
            self.pin(k)

    def place(self, k, x, y):
        if not (x > -1e9 and x < 1e9 and y > -1e9 and y < 1e9):
            raise SceneError('to: must be finite and within 1e9 of the origin')
        self.pos[k + k] = x
        self.pos[k + k + 1] = y

    # ---- queries --------------------------------------------------------------------------

    def measure(self):
        """Fill `diff` (per edge) and `stress` (per vertex) and the summary numbers."""
        deformation(self.pos, self.edge_a, self.edge_b, self.rest, self.n_edges, self.degree,
                    self.n_verts, self.diff, self.stress, self.stats)
        self.max_diff = self.stats[0]
        self.rms_diff = self.stats[1]
        self.max_stress = self.stats[2]
        self.max_strain = self.stats[3]
        self.rms_strain = self.stats[4]

    def nearest(self, x, y, radius):
        return nearest_vertex(self.pos, self.n_verts, x, y, radius)
