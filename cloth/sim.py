"""The cloth: state as flat arrays, and `step()`, which reads like the algorithm.

State (struct of arrays, one per quantity; n vertices, m edges):
    pos, prev    2n doubles, x and y interleaved; velocity is (pos - prev) / h, never stored
    inv_mass     n doubles; 0 for a pinned vertex (and for one a hand moves where it is), the
                 vertex's mass (density * spacing^2, or 1 kg) inverted otherwise
    pinned, held n ints (0/1)
    target       2n doubles: where the hand holding a vertex is (see HAND_FORCE)
    hold_from    2n doubles: where that hand took hold (a `move` `by` is relative to it)
    edge_a, edge_b, rest   m edges: structural grid edges, then the shear diagonals if the
                 scene declares them
The core knows nothing of the DOM or GL: the page reads `pos`, `diff` and `stress`.
"""

import math

from cloth.host import f64, i32
from cloth.scene import SceneError, OBSTACLE_FAR, SEED_SOLVER
from cloth.solve import blow, integrate, sweep_jakobsen, sweep_xpbd, project_cells, \
    solve_lines, clear, max_motion2, copy_into, mark_crossed, \
    mark_overstretched, drive_hands, limit_speed, follow_velocity, collide, shield_edges, N_CONSTS, K_SPACING, K_TOLERANCE, K_ALPHA, \
    K_STRETCH, K_KEEP, K_AX, K_AY, K_MAX_STEP, K_TEAR2, K_HAND_STEP, K_HAND_SHARE, K_HAND_PUSH, \
    K_WIND_X, K_WIND_Y, K_AIR
from cloth.measure import deformation, nearest_vertex
from cloth.tethers import find_anchors, list_fixed, over_reach, label_pieces

# While a hand pulls the cloth beyond its reach, the tethers stretch with it, up to this
# factor (tethers.over_reach). Past it they hold the rest of the cloth near the pins: a vertex
# teleported 100 m would otherwise drag the whole cloth after it at hundreds of m/s.
MAX_STRETCH = 3.0

# Sleep: a cloth is at rest, and is not stepped again until an operation (grab, move,
# release, pin, unpin) changes it, once for SLEEP_TIME seconds of frames no free vertex moved
# more than SLEEP_MOTION of the cloth's extent in a frame and none ended more than SLEEP_DRIFT
# of it from where it was at the window's start. Relative to the extent because that is what
# the page fits to the screen: both are a fraction of a pixel there. Not zero, because a
# settled cloth can keep a tiny limit cycle of the solver (measured: 40 um per frame in a
# slack hang); two tests, because a small swing whose period fits the window returns to its
# start, and a slow creep has no fast frame.
SLEEP_MOTION = 1e-4
SLEEP_DRIFT = 1e-3
SLEEP_TIME = 1.0

# Each step removes this fraction of every cell's departure from a parallelogram
# (solve.project_cells); and the line solves are left out when a step's fall under gravity
# exceeds LINE_STEP of the spacing (see Cloth.use_lines).
CELL_STRENGTH = 0.25
LINE_STEP = 0.01
LINE_NEWTON = 2
# After the columns and rows, the top rows' column links and the top rows are solved once more:
# rows // LINE_TOP_PER rows of them, at least one (see lines).
LINE_TOP_PER = 15

# Tearing (scene key `tear`): checked once a frame, after its steps, and at most
# TEAR_PER_FRAME edges break in a frame, the most strained first. Once a frame because the
# check is a pass over the edges (per step it would cost a fifth of a frame); a few at a time
# because an edge that breaks hands its load to its neighbours, which the next frame's solve
# spreads: a tear runs from where it starts, as cloth tears, instead of a whole row past the
# limit snapping in one frame.
TEAR_PER_FRAME = 4

# A hand of finite strength. A held vertex that is not pinned (with "xpbd") is not put where
# the pointer is: each step it moves toward it, at most HAND_SPEED, as part of the cloth (the
# constraints that follow may pull it back), with a mass that makes the most it can pull
# HAND_FORCE times the cloth's weight (at 9.81 m/s^2: a step of HAND_SPEED h against a pull F
# is undone when F h^2 / mass = HAND_SPEED h). So the held vertex stops where the cloth can
# reach instead of stretching an inextensible cloth beyond it (which stored stretch that a
# release turned into a fling: 14.6 m/s after a 0.2 m pull of the Curtain preset), and a
# compliant cloth stretches as far as that force takes it. A held pin is moved where the hand
# is (a pin is fixed in space: dragging it moves the fixture), and so is every held vertex of
# the seed's method.
HAND_SPEED = 10.0
HAND_FORCE = 2.0
HAND_PUSH = 0.1
HAND_RADIUS = 0.02
HAND_MASS = 4.0
HAND_ACCEL = 100.0

# Letting go: for a while after a vertex is let go (released, unpinned), the cloth's motion
# relative to its mean motion is slowed, all of it by one factor, wherever some vertex would
# otherwise move faster than it did before (smoothed over the frames a hand held the cloth)
# plus what gravity has added since, plus LET_GO_SLACK; until a frame needs no slowing. The
# stretch a hand leaves in the cloth (a compliant one's, or what an inextensible one's solver
# could not take out) then returns without being turned into a fling, while the cloth's own
# motion (a throw: its momentum) stays.
LET_GO_SLACK = 0.5
# The window opens only where there is stretch to return: a hand of finite strength let go
# after it held its vertex through a frame (it may have pulled beyond where it could take it,
# or pushed the cloth into folds that its cells, which leave a gripped vertex alone, then
# snap open: measured 4.4 m/s after a 0.2 m push up), or a pin unpinned while an edge is
# strained beyond LET_GO_STRAIN (a pin dragged beyond reach). Anything else let go (a tap: a
# press and release with no frame between) leaves the motion as physics makes it: the
# window's bound, the speed before plus g t, would slow a swinging chain's tip, which its
# tension speeds up faster than gravity (measured: a tap on a swinging chain moved it 0.34 m),
# and a settling two-corner hang whose corners keep a residual strain (0.45 at 120x120).
LET_GO_STRAIN = 0.05


def count_edges(cols, rows, shear):
    """The edges a grid has before any breaks: its horizontal and vertical links, and one
    diagonal a cell with `shear` (the page's cost estimate counts them the same way)."""
    m = (cols - 1) * rows + cols * (rows - 1)
    if shear:
        m += (cols - 1) * (rows - 1)
    return m


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
        # The rows whose line solves are repeated (see lines): fewer than the rows.
        self.line_top = min(rows - 1, max(1, rows // LINE_TOP_PER))

        # A step's constants as doubles in a typed array, for the kernels (solve.K_*).
        self.consts = f64(N_CONSTS)
        # Zero-sized until configure() sizes what the scene's settings use.
        self.line_nx = f64(0)
        self.line_ny = f64(0)
        self.line_cc = f64(0)
        self.line_cd = f64(0)
        self.last_pos = f64(0)
        self.still_from = f64(0)
        configure(self, scene)

        self.pos = f64(2 * n)
        self.prev = f64(2 * n)
        self.inv_mass = f64(n)
        self.pinned = i32(n)
        self.held = i32(n)
        # The hands (HAND_FORCE): where each is, and where it is taking each vertex it holds.
        self.target = f64(2 * n)
        self.hold_from = f64(2 * n)
        self.aim = f64(2 * n)
        self.aim_step = f64(2 * n)
        self.hands = i32(n)
        self.n_hands = 0
        # A hand's grip (regrip): the held vertex whose hand holds each vertex (-1: none), its
        # offset from it, and how many each hand grips; work arrays to find a grip.
        self.grip = i32(n)
        self.offset = f64(2 * n)
        self.grip_count = i32(n)
        self.grip_list = i32(n)
        self.grip_dist = f64(n)
        for k in range(n):
            self.grip[k] = -1
            self.grip_dist[k] = -1.0
        for r in range(rows):
            for c in range(cols):
                k = r * cols + c
                self.pos[k + k] = c * h
                self.pos[k + k + 1] = -r * h
        for i in range(len(scene.pins)):
            self.pinned[scene.pins[i]] = 1
        for k in range(n):
            self.inv_mass[k] = 0.0 if self.pinned[k] == 1 else self.free_w
            rest_at(self, k)

        self.build_edges(scene.shear)
        self.lam = f64(self.n_edges)   # per edge in the sweep's order (order_sweep)
        # Tearing and cutting remove edges (break_marked): until the first goes the grid is
        # intact and the kernels skip every check of it. Then: which grid links (right of k,
        # below k) and which cells remain, and the connected pieces.
        self.intact = True
        self.broken = 0
        self.right_ok = i32(0)
        self.down_ok = i32(0)
        self.cell_ok = i32(0)
        self.piece = i32(0)
        self.stack = i32(0)
        # Where kernels put a double they measure (a returned double would be a heap number in
        # JS: an allocation per call in the hot path).
        self.out = f64(1)
        self.tear_q = f64(TEAR_PER_FRAME)
        self.tear_e = i32(TEAR_PER_FRAME)
        # Set when a vertex is let go: the steps from the next one on are limited
        # (LET_GO_SLACK) until a frame needs no limit.
        self.let_go_pending = False
        self.let_go = False
        self.let_go_frames = 0
        self.let_go_limited = 0
        self.let_go_t = 0.0
        self.air_t = 0.0           # s of air felt: the gusts' clock
        self.velocity = f64(2 * n)
        self.frame_start = f64(2 * n)
        self.hands_last_frame = False
        # The last step's first sweep found every edge within tolerance (see step).
        self.converged = False
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
        # The fixed vertices (listed when the anchors are), how many are held, and the factor
        # the tethers are scaled by while a hand pulls beyond reach (tethers.over_reach).
        self.fixed = i32(n)
        self.n_fixed = 0
        self.n_held = 0
        self.stretch = 1.0
        # Constraint projections done so far (edges + tethers): the benchmark's cost measure.
        self.projections = 0
        # Vertex-steps whose speed hit max_speed: non-zero means unstable settings.
        self.clamped = 0
        # Sleep (scene key `sleep`): frames in a row that were still, and whether at rest.
        self.still_frames = 0
        self.asleep = False
        # Obstacles (scene key `obstacles`): each one's shape, half width and height, friction,
        # and centre: where it is (`at`), where it was when the step began (`was`), and where
        # an `obstacle` action sends it by the end of the next frame (`to`).
        obstacles = scene.obstacles
        m = len(obstacles)
        self.n_obstacles = m
        self.obstacle_shape = i32(m)
        self.obstacle_half = f64(2 * m)
        self.obstacle_friction = f64(m)
        self.obstacle_at = f64(2 * m)
        self.obstacle_was = f64(2 * m)
        self.obstacle_to = f64(2 * m)
        self.obstacle_bounds = f64(4 * m)     # each one's swept box in a step (solve.collide)
        # Each row's box and the obstacles that can meet its edges (solve.shield_edges).
        self.obstacle_row_box = f64(4 * self.rows if m > 0 else 0)
        self.obstacle_row_mask = i32(self.rows if m > 0 else 0)
        for j in range(m):
            o = obstacles[j]
            self.obstacle_shape[j] = o[0]
            self.obstacle_half[j + j] = o[3]
            self.obstacle_half[j + j + 1] = o[4]
            self.obstacle_friction[j] = o[5]
            for c in [self.obstacle_at, self.obstacle_was, self.obstacle_to]:
                c[j + j] = o[1]
                c[j + j + 1] = o[2]

    def build_edges(self, shear):
        """Horizontal and vertical grid neighbours (rest = spacing), vertex by vertex; then,
        if the scene declares shear, one diagonal per cell (rest = spacing * sqrt 2)."""
        cols = self.cols
        rows = self.rows
        h = self.spacing
        m = count_edges(cols, rows, shear)
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
        self.adj_start = i32(n + 1)
        self.adj_fill = i32(n)
        self.adj_vertex = i32(2 * m)
        self.adj_rest = f64(2 * m)
        adjacency(self)
        self.sweep_a = i32(m)
        self.sweep_b = i32(m)
        self.sweep_rest = f64(m)
        # order_sweep's work arrays, made once: edges only go, so these sizes always suffice.
        self.sweep_ready = i32(self.n_verts)
        self.sweep_wave = i32(m if m > 0 else 1)
        self.sweep_start = i32(m + 2)
        # The sweep's slot of the grid link from k to its lower / right neighbour: the line
        # solves of a compliant cloth share the sweep's multipliers (solve.solve_lines).
        self.down_slot = i32(n)
        self.right_slot = i32(n)
        order_sweep(self)

    def set_edge(self, e, a, b, rest):
        self.edge_a[e] = a
        self.edge_b[e] = b
        self.rest[e] = rest
        return e + 1

    # Conveniences for callers outside the hot path (tests, the page's input handlers). Each
    # Transcrypt method call allocates, so per-frame callers use the module functions below.
    def frame(self):
        frame(self)

    def measure(self):
        measure(self)

    def grab(self, k, x, y):
        grab(self, k, x, y)

    def move(self, k, x, y):
        move(self, k, x, y)

    def move_by(self, k, dx, dy):
        move_by(self, k, dx, dy)

    def release(self, k):
        release(self, k)

    def pin(self, k):
        pin(self, k)

    def unpin(self, k):
        unpin(self, k)

    def toggle_pin(self, k):
        toggle_pin(self, k)

    def nearest(self, x, y, radius):
        return nearest(self, x, y, radius)


def adjacency(cloth):
    """degree[] and the CSR adjacency (adj_start, adj_vertex, adj_rest) of the edges there are
    now, in the arrays made for the whole grid (edges only ever go)."""
    n = cloth.n_verts
    m = cloth.n_edges
    degree = cloth.degree
    start = cloth.adj_start
    fill = cloth.adj_fill
    for k in range(n):
        degree[k] = 0
        fill[k] = 0
    for e in range(m):
        degree[cloth.edge_a[e]] += 1
        degree[cloth.edge_b[e]] += 1
    start[0] = 0
    for k in range(n):
        start[k + 1] = start[k] + degree[k]
    for e in range(m):
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        cloth.adj_vertex[start[a] + fill[a]] = b
        cloth.adj_rest[start[a] + fill[a]] = cloth.rest[e]
        fill[a] += 1
        cloth.adj_vertex[start[b] + fill[b]] = a
        cloth.adj_rest[start[b] + fill[b]] = cloth.rest[e]
        fill[b] += 1


def order_sweep(cloth):
    """sweep_a, sweep_b, sweep_rest: the edges in the order sweep_xpbd visits them, in waves.
    Edge e goes in wave 1 + the wave of the last edge before it (in edge order) that shares an
    end with it, or wave 0; the sweep visits wave by wave, each wave in edge order. Two edges
    that share an end keep their order, and edges that share none commute exactly (each reads
    and writes only its own two ends and its own lambda), so a sweep in this order gives every
    vertex the same updates in the same order as one in edge order: the result is the same to
    the bit. The point is speed: in edge order each edge reads an end its predecessor has just
    written, so every edge waits for the last one's three divisions; within a wave none waits.
    On the grid the waves are diagonals, row r about 2 r behind row 0 (measured on the settled
    60x60 corners in node: the sweeps 0.84 -> 0.73 ms a frame). `lam` is indexed in this
    order. Called when the edges are made and when some break (edges only go: the arrays keep
    their size)."""
    n = cloth.n_verts
    m = cloth.n_edges
    edge_a = cloth.edge_a
    edge_b = cloth.edge_b
    ready = cloth.sweep_ready      # the first wave an edge at vertex k may go in
    wave = cloth.sweep_wave
    for k in range(n):
        ready[k] = 0
    waves = 0
    for e in range(m):
        a = edge_a[e]
        b = edge_b[e]
        w = ready[a]
        if ready[b] > w:
            w = ready[b]
        wave[e] = w
        ready[a] = w + 1
        ready[b] = w + 1
        if w + 1 > waves:
            waves = w + 1
    start = cloth.sweep_start   # waves <= m
    for w in range(waves + 1):
        start[w] = 0
    for e in range(m):
        start[wave[e] + 1] += 1
    for w in range(waves):
        start[w + 1] += start[w]
    for e in range(m):
        j = start[wave[e]]
        start[wave[e]] += 1
        cloth.sweep_a[j] = edge_a[e]
        cloth.sweep_b[j] = edge_b[e]
        cloth.sweep_rest[j] = cloth.rest[e]
        a = edge_a[e]
        if edge_b[e] == a + cloth.cols:
            cloth.down_slot[a] = j
        elif edge_b[e] == a + 1:
            cloth.right_slot[a] = j


# Gusts: the wind times 1 + amplitude * GUST_PEAK * p (1 - p) (1 - 2p), p the phase in the
# period: a smooth wave from -1 to 1 (its peak at p = 0.21 is 1/GUST_PEAK before scaling),
# polynomial so that both runtimes compute it to the same bit (Math.sin and libm's sin may
# differ in the last place).
GUST_PEAK = 6.0 * math.sqrt(3.0)


# ---- the step -----------------------------------------------------------------------------
#
# Operations are module functions taking the cloth, not methods: a Transcrypt method call
# binds a fresh closure and two arrays on every call, and the hot path must not allocate.


def frame(cloth):
    """Advance one frame: `substeps` steps of dt / substeps each, then tear and settle. Its
    stages, in order; each says what it guarantees."""
    if cloth.asleep:
        return
    update_reach(cloth)
    count_let_go(cloth)
    start_hands(cloth)
    feel_air(cloth)
    for s in range(cloth.substeps):
        # A hand's motion over the frame is spread evenly over its steps.
        cloth.consts[K_HAND_SHARE] = 1.0 / (cloth.substeps - s)
        step(cloth)
    finish_hands(cloth)
    tear_overstretched(cloth)
    if cloth.use_sleep:
        settle(cloth)


def step(cloth):
    """One step of size h: the algorithm. Jakobsen's (predict by Verlet, relax the edges), with
    the stages that make it hold at every size and under a hand."""
    begin_let_go(cloth)
    move_hands(cloth)
    predict(cloth)
    if cloth.iterations > 0:
        keep_cells(cloth)
        relax_edges(cloth)
    limit_let_go(cloth)
    push_out(cloth)


def update_reach(cloth):
    """Tethers (`tethers`): each vertex's anchor among the fixed vertices and its distance
    along the cloth, found again only when a pin changed; and how far a held pin drags the
    cloth beyond its reach this frame (consts[K_STRETCH], at most MAX_STRETCH), so that the
    tethers stretch with it instead of tearing the cloth from the hand."""
    if not cloth.use_tethers:
        return
    if cloth.anchors_stale:
        find_anchors(cloth.n_verts, cloth.adj_start, cloth.adj_vertex, cloth.adj_rest,
                     cloth.pinned, cloth.anchor, cloth.tether)
        cloth.n_fixed = list_fixed(cloth.inv_mass, cloth.n_verts, cloth.fixed)
        cloth.anchors_stale = False
    cloth.stretch = 1.0
    if cloth.n_held > cloth.n_hands:
        over_reach(cloth.pos, cloth.held, cloth.pinned, cloth.use_xpbd, cloth.fixed,
                   cloth.n_fixed, cloth.cols, cloth.consts, cloth.intact, cloth.piece,
                   cloth.out)
        cloth.stretch = min(MAX_STRETCH, cloth.out[0])
    cloth.consts[K_STRETCH] = cloth.stretch


def count_let_go(cloth):
    """The let-go window (LET_GO_SLACK) stays open exactly as long as its frames need its
    limit: it closes after a frame whose steps never slowed the cloth."""
    if cloth.let_go and cloth.let_go_frames > 0 and cloth.let_go_limited == 0:
        cloth.let_go = False
    cloth.let_go_limited = 0
    if cloth.let_go:
        cloth.let_go_frames += 1
    else:
        cloth.let_go_frames = 0


def start_hands(cloth):
    """While hands hold the cloth, its velocity is measured over whole frames (finish_hands):
    the velocity a let-go starts from is the hand's throw, not one step's jitter of a hand at
    its strength's end."""
    if cloth.n_hands > 0 and not cloth.hands_last_frame:
        clear(cloth.velocity, cloth.n_verts + cloth.n_verts)
    cloth.hands_last_frame = cloth.n_hands > 0
    if cloth.hands_last_frame:
        copy_into(cloth.frame_start, cloth.pos, cloth.n_verts + cloth.n_verts)


def finish_hands(cloth):
    """See start_hands: the frame's velocity, smoothed over the frames the hands held."""
    if cloth.hands_last_frame:
        follow_velocity(cloth.pos, cloth.frame_start, cloth.n_verts, 1.0 / cloth.dt,
                        cloth.velocity)


def tear_overstretched(cloth):
    """Edges strained beyond `tear` break, at most TEAR_PER_FRAME a frame, the most strained
    first. A cloth whose last step converged has every edge within the tolerance, below any
    tear limit at least as large, and costs nothing to check."""
    if cloth.tear > 0.0 and not (cloth.converged and cloth.tolerance <= cloth.tear):
        if mark_overstretched(cloth.pos, cloth.edge_a, cloth.edge_b, cloth.rest, cloth.n_edges,
                              cloth.consts, TEAR_PER_FRAME, cloth.tear_q, cloth.tear_e) > 0:
            break_marked(cloth)


def settle(cloth):
    """Count still frames; after a window of them, sleep if nothing drifted (see SLEEP_TIME).
    Never in gusts: the air changes, however little the cloth moves."""
    if cloth.use_air and cloth.gust_amplitude > 0.0:
        cloth.still_frames = 0
        return
    n = cloth.n_verts
    max_motion2(cloth.pos, cloth.last_pos, cloth.inv_mass, n, cloth.out)
    moved2 = cloth.out[0]
    copy_into(cloth.last_pos, cloth.pos, n + n)
    if moved2 > cloth.still_motion2:
        cloth.still_frames = 0
        return
    if cloth.still_frames == 0:
        copy_into(cloth.still_from, cloth.pos, n + n)
    cloth.still_frames += 1
    if cloth.still_frames > cloth.sleep_frames:
        max_motion2(cloth.pos, cloth.still_from, cloth.inv_mass, n, cloth.out)
        if cloth.out[0] <= cloth.drift2:
            cloth.asleep = True
        else:
            cloth.still_frames = 0


def begin_let_go(cloth):
    """A vertex let go since the last step opens the let-go window (XPBD only): see
    start_let_go."""
    if cloth.let_go_pending:
        cloth.let_go_pending = False
        if cloth.use_xpbd:
            start_let_go(cloth)


def start_let_go(cloth):
    """The let-go window (LET_GO_SLACK) starts from each vertex's velocity before it: smoothed
    over the frames a hand held the cloth (a throw; a hand at its strength's end steps forward
    and is pulled back, which averages out), else the last step's."""
    if not cloth.hands_last_frame:
        clear(cloth.velocity, cloth.n_verts + cloth.n_verts)
        follow_velocity(cloth.pos, cloth.prev, cloth.n_verts, 2.0 / cloth.h, cloth.velocity)
    cloth.let_go = True
    cloth.let_go_t = 0.0


def move_hands(cloth):
    """Each hand of finite strength (solve.drive_hands) pushes the vertices in its grip toward
    where the pointer holds them, at most HAND_SPEED and with at most HAND_FORCE. The
    constraints that follow may pull them back: the hand stops at the cloth's reach instead of
    stretching it (a stretch that a release turned into a fling: 14.6 m/s after a 0.2 m pull
    of the Curtain preset). Held pins are not moved here: `move` puts them where the hand is."""
    if cloth.n_hands > 0:
        drive_hands(cloth.pos, cloth.prev, cloth.hands, cloth.n_hands, cloth.grip, cloth.offset,
                    cloth.target, cloth.aim, cloth.aim_step, cloth.consts)


def feel_air(cloth):
    """The wind (`wind`, `drag`, `gust`) pushes each edge across itself by the air's velocity
    relative to it (solve.blow): a hanging cloth leans and billows, and a cloth moving with
    the air feels nothing. Once a frame, the frame's impulse, which the steps' velocity then
    carries: the air changes over seconds, not steps, and once a step cost 18% of a dragged
    120x120 frame (`python -m bench --world`); the steady lean is the same (the impulse a
    frame is). Only in a scene whose air moves: still air costs nothing."""
    if not cloth.use_air:
        return
    cloth.air_t += cloth.dt
    f = cloth.h
    if cloth.gust_amplitude > 0.0:
        q = cloth.air_t / cloth.gust_period
        p = q - math.floor(q)
        f = cloth.h * (1.0 + cloth.gust_amplitude * GUST_PEAK * p * (1.0 - p) * (1.0 - 2.0 * p))
    cloth.consts[K_WIND_X] = cloth.scene.wind_x * f
    cloth.consts[K_WIND_Y] = cloth.scene.wind_y * f
    blow(cloth.pos, cloth.prev, cloth.inv_mass, cloth.edge_a, cloth.edge_b, cloth.n_edges,
         cloth.consts)


def predict(cloth):
    """Verlet: every free vertex moves by its velocity, gravity and damping; with tethers, each
    then right away within its rest distance along the cloth of its anchor, which takes out
    the stretch between the pins and what hangs from them in one pass (so the sweeps that
    follow measure, and fix, only what is left). XPBD's multipliers start the step at zero."""
    tethered = cloth.use_tethers and cloth.iterations > 0
    cloth.clamped += integrate(cloth.pos, cloth.prev, cloth.inv_mass, cloth.n_verts,
                               cloth.consts, cloth.anchor, cloth.tether, tethered, cloth.held,
                               cloth.n_hands > 0)
    if cloth.use_xpbd:
        clear(cloth.lam, cloth.n_edges)
    if tethered:
        cloth.projections += cloth.n_verts


def keep_cells(cloth):
    """Every grid cell is moved CELL_STRENGTH of the way back toward a parallelogram, so no
    cell folds over. Only while the cloth moves: one that converged last step is near its rest
    shape, and a cloth at rest spends its step on one sweep (curtain 120x120: 25% fewer
    projections)."""
    if cloth.use_cells and not cloth.converged:
        project_cells(cloth.pos, cloth.inv_mass, cloth.cols, cloth.rows, CELL_STRENGTH,
                      cloth.intact, cloth.cell_ok, cloth.n_hands > 0, cloth.grip)
        cloth.projections += (cloth.cols - 1) * (cloth.rows - 1)


def relax_edges(cloth):
    """Up to `iterations` sweeps over the edges (Jakobsen's projections, or XPBD's with the
    material's compliance), stopping as soon as a sweep finds every edge within `tolerance`
    (`converged`: the cloth's state is then known to be that good). A first sweep that found
    more is followed by the line solves (`lines`), which take a loaded row's or column's
    stretch out whatever its length; a cloth at rest never gets there. Not while a hand pulls
    the cloth beyond its reach: no shape has every line at its rest length then, and solving
    some lines exactly piles the stretch into the others (measured: max strain 4.5 for a
    0.3 m over-pull of a 1 m curtain, 0.38 without)."""
    m = cloth.n_edges
    track = cloth.tolerance > 0.0
    for it in range(cloth.iterations):
        if cloth.use_xpbd:
            sweep_xpbd(cloth.pos, cloth.prev, cloth.inv_mass, cloth.sweep_a, cloth.sweep_b,
                       cloth.sweep_rest, cloth.lam, m, cloth.consts, track, cloth.out)
        else:
            sweep_jakobsen(cloth.pos, cloth.inv_mass, cloth.edge_a, cloth.edge_b, cloth.rest, m,
                           track, cloth.out)
        worst = cloth.out[0]
        cloth.projections += m
        # The sweep measured the error it found before correcting.
        if track and worst <= cloth.tolerance:
            cloth.converged = it == 0
            return
        cloth.converged = False
        if it == 0 and cloth.use_lines and cloth.stretch == 1.0:
            lines(cloth)


def limit_let_go(cloth):
    """Inside the let-go window, the cloth's motion relative to its mean is slowed, all of it
    by one factor, wherever a vertex would move faster than before the let-go plus what
    gravity has added since (LET_GO_SLACK): the stretch a hand left returns without a fling,
    and a throw keeps its momentum."""
    if cloth.let_go:
        cloth.let_go_t += cloth.h
        limit_speed(cloth.pos, cloth.prev, cloth.inv_mass, cloth.n_verts, cloth.velocity,
                    cloth.h, cloth.g_abs * cloth.let_go_t + LET_GO_SLACK, cloth.out)
        if cloth.out[0] < 1.0:
            cloth.let_go_limited += 1


def push_out(cloth):
    """No free vertex ends the step inside an obstacle, nor passed through one during it
    (solve.collide: swept, in each obstacle's frame, so a fast cloth or a fast obstacle never
    tunnels). Last in the step, so that nothing after it moves a vertex back in. An obstacle
    an action moved goes there over the frame's steps, evenly (like a hand). A vertex a pin
    or a hand fixes in space stays where it is fixed, even inside. Nothing in a scene without
    obstacles."""
    m = cloth.n_obstacles
    if m == 0:
        return
    share = cloth.consts[K_HAND_SHARE]
    at = cloth.obstacle_at
    was = cloth.obstacle_was
    to = cloth.obstacle_to
    for i in range(m + m):
        was[i] = at[i]
        at[i] = to[i] if share == 1.0 else at[i] + (to[i] - at[i]) * share
    collide(cloth.pos, cloth.prev, cloth.inv_mass, cloth.cols, cloth.rows, m, cloth.obstacle_shape,
            cloth.obstacle_half, was, at, cloth.obstacle_friction, cloth.obstacle_bounds,
            cloth.obstacle_row_box)
    if shield_edges(cloth.pos, cloth.prev, cloth.inv_mass, cloth.edge_a, cloth.edge_b, cloth.n_edges,
                    cloth.cols, cloth.rows, m, cloth.obstacle_shape, cloth.obstacle_half, was, at,
                    cloth.obstacle_row_box, cloth.obstacle_row_mask) == 0:
        return
    # The edges' push may have put a vertex into another obstacle, or back into this one at a
    # corner: the vertices once more, from where they now are (a still test).
    copy_into(cloth.obstacle_was, at, m + m)
    collide(cloth.pos, cloth.pos, cloth.inv_mass, cloth.cols, cloth.rows, m, cloth.obstacle_shape,
            cloth.obstacle_half, at, at, cloth.obstacle_friction, cloth.obstacle_bounds,
            cloth.obstacle_row_box)


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
    cloth.converged = False
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


def lines(cloth):
    """Every column, then every row, solved as a chain (solve.solve_lines). Rows last: the
    top row of a cloth hung from its corners carries the whole cloth (measured at 60x60: 0.9%
    of the width from the exact hang this way, 1.0% with the rows first). Then the top
    `line_top` rows once more (their links in the columns, then the rows): the row solves pull
    the loaded top rows back up from where the column solves left them, which leaves the
    columns' top links long; a second pass over those few links and rows takes out most of
    what the first left (slack two-corner hang, 120x120: 1.24% -> 0.84% of the width, RMS
    strain 1.04e-2 -> 8.2e-3, 7% more line work; a second full pass 0.74% for 50% more)."""
    cols = cloth.cols
    rows = cloth.rows
    top = cloth.line_top
    if rows > 1:
        solve_lines(cloth.pos, cloth.inv_mass, 0, cols, rows, cols, 1, LINE_NEWTON, cloth.line_nx,
                    cloth.line_ny, cloth.line_cc, cloth.line_cd, cloth.intact, cloth.down_ok,
                    cloth.consts, cloth.lam, cloth.down_slot)
        cloth.projections += cols * (rows - 1)
    if cols > 1:
        solve_lines(cloth.pos, cloth.inv_mass, 0, 1, cols, rows, cols, LINE_NEWTON, cloth.line_nx,
                    cloth.line_ny, cloth.line_cc, cloth.line_cd, cloth.intact, cloth.right_ok,
                    cloth.consts, cloth.lam, cloth.right_slot)
        cloth.projections += rows * (cols - 1)
    if top > 0 and cols > 1:
        solve_lines(cloth.pos, cloth.inv_mass, 0, cols, top + 1, cols, 1, LINE_NEWTON,
                    cloth.line_nx, cloth.line_ny, cloth.line_cc, cloth.line_cd, cloth.intact,
                    cloth.down_ok, cloth.consts, cloth.lam, cloth.down_slot)
        cloth.projections += cols * top
        solve_lines(cloth.pos, cloth.inv_mass, 0, 1, cols, top, cols, LINE_NEWTON, cloth.line_nx,
                    cloth.line_ny, cloth.line_cc, cloth.line_cd, cloth.intact, cloth.right_ok,
                    cloth.consts, cloth.lam, cloth.right_slot)
        cloth.projections += top * (cols - 1)


def configure(cloth, scene):
    """The constants of a step, from the scene's settings: substep size, a h^2, damping
    factor, which solver and which of its parts. Called at construction, and by `retune`
    when a person changes a setting of the running cloth."""
    cloth.scene = scene
    n = cloth.n_verts
    cloth.dt = scene.dt
    cloth.substeps = scene.substeps
    cloth.iterations = scene.iterations
    cloth.h = scene.dt / scene.substeps
    h2 = cloth.h * cloth.h
    cloth.ax = scene.gravity_x * h2
    cloth.ay = scene.gravity_y * h2
    cloth.keep = 1.0 / (1.0 + scene.damping * cloth.h)
    cloth.max_step = scene.max_speed * cloth.h
    cloth.use_xpbd = scene.solver != SEED_SOLVER
    cloth.alpha = scene.compliance / h2
    cloth.tolerance = scene.tolerance
    # Tethers bound how far an inextensible cloth can reach from its pins; a compliant one
    # reaches farther by its stretch, which rigid tethers would erase (measured: 2.5e-7 at the
    # top of a hanging curtain whose exact strain is 8.3e-3). Its line solves carry the
    # hanging stretch instead, exactly (solve.solve_lines).
    cloth.use_tethers = scene.tethers and scene.compliance == 0.0
    cloth.use_cells = scene.cells and cloth.cols > 1 and cloth.rows > 1
    # Line solves assume a step that moves a vertex little against its links: their
    # linearisation of a taut, loaded, inextensible line overshoots when gravity moves it more
    # than LINE_STEP of the spacing in one step (measured: a taut cloth under 100 g, or with
    # steps of 1/32 s, never came to rest with them; the benchmark's scenes move 0.25-0.5% per
    # step). A compliant line is a better conditioned system (alpha~ on its diagonal).
    fall = math.sqrt(cloth.ax * cloth.ax + cloth.ay * cloth.ay)
    cloth.use_lines = scene.lines and (scene.compliance > 0.0 or fall <= LINE_STEP * cloth.spacing)
    cloth.g_abs = math.sqrt(scene.gravity_x * scene.gravity_x + scene.gravity_y * scene.gravity_y)
    # Masses: a free vertex's, and a hand's (HAND_FORCE), at this step size.
    cloth.free_w = 1.0 / scene.mass
    hand_force = HAND_FORCE * scene.mass * n * 9.81
    hand_mass = max(hand_force * h2 / (HAND_PUSH * cloth.spacing), HAND_MASS * scene.mass)
    hand_force = max(hand_force, hand_mass * HAND_ACCEL)
    cloth.hand_w = 1.0 / hand_mass
    cloth.hand_push = hand_force * h2 / hand_mass
    # Work arrays of the line solves (one line at a time), and the sleep test's two copies of
    # the positions (a frame ago, at the window's start): allocated when first needed.
    longest = max(cloth.cols, cloth.rows)
    if cloth.use_lines and len(cloth.line_nx) < longest:
        cloth.line_nx = f64(longest)
        cloth.line_ny = f64(longest)
        cloth.line_cc = f64(longest)
        cloth.line_cd = f64(longest)
    cloth.tear = scene.tear
    k = cloth.consts
    k[K_SPACING] = cloth.spacing
    k[K_TOLERANCE] = cloth.tolerance
    k[K_ALPHA] = cloth.alpha
    k[K_STRETCH] = 1.0
    k[K_KEEP] = cloth.keep
    k[K_AX] = cloth.ax
    k[K_AY] = cloth.ay
    k[K_MAX_STEP] = cloth.max_step
    k[K_TEAR2] = (1.0 + scene.tear) * (1.0 + scene.tear)
    k[K_HAND_STEP] = HAND_SPEED * cloth.h
    k[K_HAND_PUSH] = cloth.hand_push
    # The air, where it moves (feel_air).
    cloth.use_air = scene.drag > 0.0 and (scene.wind_x != 0.0 or scene.wind_y != 0.0)
    cloth.gust_amplitude = scene.gust_amplitude
    cloth.gust_period = scene.gust_period
    # A frame's impulse (feel_air). Over keep: the push is taken from `prev`, and integrate damps
    # (pos - prev) by keep; the air's push is a force, not a velocity to damp (measured: damping
    # 5 leaned a column 1% less).
    k[K_AIR] = 0.5 * scene.drag * cloth.spacing * scene.dt / cloth.keep
    cloth.use_sleep = scene.sleep
    extent = max(longest - 1, 1) * cloth.spacing
    cloth.still_motion2 = SLEEP_MOTION * SLEEP_MOTION * extent * extent
    cloth.drift2 = SLEEP_DRIFT * SLEEP_DRIFT * extent * extent
    cloth.sleep_frames = int(math.ceil(SLEEP_TIME / scene.dt))
    if scene.sleep and len(cloth.last_pos) < 2 * n:
        cloth.last_pos = f64(2 * n)
        cloth.still_from = f64(2 * n)


def retune(cloth, scene):
    """Apply new settings (a scene on the same grid, parse_scene-checked) to the running
    cloth: positions, velocities, pins and held vertices stay as they are."""
    if scene.cols != cloth.cols or scene.rows != cloth.rows or \
            scene.spacing != cloth.spacing or scene.shear != cloth.scene.shear:
        raise SceneError('scene: cols, rows, spacing and shear make the grid; '
                         'a change of them needs a new cloth')
    h_old = cloth.h
    configure(cloth, scene)
    # Verlet keeps the velocity as pos - prev over one step of size h: a new step size
    # rescales it, or a change of substeps would change the cloth's speed.
    if cloth.h != h_old:
        f = cloth.h / h_old
        pos = cloth.pos
        prev = cloth.prev
        for i in range(2 * cloth.n_verts):
            prev[i] = pos[i] - (pos[i] - prev[i]) * f
    # A new density or step size changes the masses; a new solver, which held vertices are
    # hands.
    for k in range(cloth.n_verts):
        if cloth.held[k] == 1:
            regrip(cloth, k)
    for k in range(cloth.n_verts):
        set_mass(cloth, k)
        if cloth.held[k] == 1 and cloth.inv_mass[k] == 0.0:
            # now moved where the hand is: the hand is where the vertex is
            cloth.target[k + k] = cloth.pos[k + k]
            cloth.target[k + k + 1] = cloth.pos[k + k + 1]
    cloth.anchors_stale = True
    cloth.converged = False
    cloth.asleep = False
    cloth.still_frames = 0


# ---- tearing and cutting -------------------------------------------------------------------


def cut(cloth, x0, y0, x1, y1):
    """Break every edge whose segment crosses the blade from (x0, y0) to (x1, y1), where the
    cloth is now."""
    for v in [x0, y0, x1, y1]:
        if not (v > -1e9 and v < 1e9):
            raise SceneError('cut: from and to must be finite and within 1e9 of the origin')
    if mark_crossed(cloth.pos, cloth.edge_a, cloth.edge_b, cloth.rest, cloth.n_edges,
                    x0, y0, x1, y1) > 0:
        break_marked(cloth)


def break_marked(cloth):
    """Remove the edges marked broken (rest < 0), keeping the others in their order, so that a
    broken edge costs nothing afterwards; then what follows from the new topology: the grid
    links and cells that remain (for the line solves and the cells), the adjacency and the
    pieces, the anchors of the tethers (a piece cut from every fixed vertex has none, and no
    tether holds it), and a wake-up. A piece that has just lost its last fixed vertex falls
    from here: its vertices keep their velocity, with `prev` moved by a h^2 / 2 as rest_at
    does, which makes its fall exact (from rest: g t^2 / 2)."""
    n = cloth.n_verts
    cols = cloth.cols
    if cloth.intact:
        cloth.intact = False
        cloth.right_ok = i32(n)
        cloth.down_ok = i32(n)
        cells = (cols - 1) * (cloth.rows - 1)
        cloth.cell_ok = i32(cells if cells > 0 else 0)
        cloth.piece = i32(n)
        cloth.stack = i32(n)
        cloth.scratch = i32(n)
        cloth.falling = i32(n)
        cloth.was_falling = i32(n)
    # Which vertices were falling before (over the edges that were there, with the fixed set
    # as it is now: a person may have pinned or let go of a piece since the last break).
    pieces(cloth)
    for k in range(n):
        cloth.was_falling[k] = cloth.falling[k]
    m = cloth.n_edges
    kept = 0
    for e in range(m):
        if cloth.rest[e] < 0.0:
            continue
        cloth.edge_a[kept] = cloth.edge_a[e]
        cloth.edge_b[kept] = cloth.edge_b[e]
        cloth.rest[kept] = cloth.rest[e]
        kept += 1
    cloth.broken += m - kept
    cloth.n_edges = kept
    adjacency(cloth)
    order_sweep(cloth)
    mark_links(cloth)
    pieces(cloth)
    falling = cloth.falling
    was = cloth.was_falling
    for k in range(n):
        if falling[k] == 1 and was[k] == 0:
            cloth.prev[k + k] += 0.5 * cloth.ax
            cloth.prev[k + k + 1] += 0.5 * cloth.ay
    cloth.anchors_stale = True
    cloth.converged = False
    cloth.asleep = False
    cloth.still_frames = 0


def mark_links(cloth):
    """right_ok[k] / down_ok[k]: the grid link from k to its right / lower neighbour remains;
    cell_ok: all four sides of a cell remain."""
    n = cloth.n_verts
    cols = cloth.cols
    rows = cloth.rows
    for k in range(n):
        cloth.right_ok[k] = 0
        cloth.down_ok[k] = 0
    for e in range(cloth.n_edges):
        a = cloth.edge_a[e]
        b = cloth.edge_b[e]
        if b == a + cols:
            cloth.down_ok[a] = 1
        elif b == a + 1:
            cloth.right_ok[a] = 1
    for r in range(rows - 1):
        for c in range(cols - 1):
            a = r * cols + c
            ok = 0
            if cloth.right_ok[a] == 1 and cloth.down_ok[a] == 1 and \
                    cloth.right_ok[a + cols] == 1 and cloth.down_ok[a + 1] == 1:
                ok = 1
            cloth.cell_ok[r * (cols - 1) + c] = ok


def pieces(cloth):
    """Label the connected pieces, and mark the vertices of pieces with no fixed vertex."""
    n = cloth.n_verts
    count = label_pieces(n, cloth.adj_start, cloth.adj_vertex, cloth.piece, cloth.stack)
    held_by = cloth.scratch   # whether each piece has a fixed vertex
    for p in range(count):
        held_by[p] = 0
    for k in range(n):
        if cloth.inv_mass[k] == 0.0:
            held_by[cloth.piece[k]] = 1
    for k in range(n):
        cloth.falling[k] = 1 - held_by[cloth.piece[k]]


# ---- holding, pinning ---------------------------------------------------------------------


def check_vertex(cloth, k):
    if not (k >= 0 and k < cloth.n_verts and math.floor(k) == k):
        raise SceneError('vertex: must be an index from 0 to cols * rows - 1')


def rest_at(cloth, k):
    """Zero velocity for vertex k, with the previous position set so that a free fall
    from here is exact: x* = x + a h^2 / 2 gives x(t) = x + a t^2 / 2 at every step."""
    i = k + k
    if cloth.inv_mass[k] == 0.0:
        cloth.prev[i] = cloth.pos[i]
        cloth.prev[i + 1] = cloth.pos[i + 1]
    else:
        cloth.prev[i] = cloth.pos[i] + 0.5 * cloth.ax
        cloth.prev[i + 1] = cloth.pos[i + 1] + 0.5 * cloth.ay


def refresh(cloth, k):
    """inv_mass follows pinned and held, the hands' grips follow the held vertices, the tether
    anchors the fixed set. A vertex that becomes fixed or free starts from rest; one that a
    hand of finite strength takes or lets go keeps its speed (a tap on a moving cloth changes
    nothing)."""
    cloth.asleep = False
    cloth.still_frames = 0
    was_fixed = cloth.inv_mass[k] == 0.0
    regrip(cloth, k)
    set_mass(cloth, k)
    if was_fixed != (cloth.inv_mass[k] == 0.0):
        cloth.anchors_stale = True
    if was_fixed or cloth.inv_mass[k] == 0.0:
        rest_at(cloth, k)


def set_mass(cloth, k):
    """inv_mass[k]: 0 for a pin and for a vertex moved where the hand is; for a vertex in a
    hand of finite strength's grip, that hand's mass shared among its grip (HAND_FORCE); the
    vertex's own otherwise."""
    if cloth.pinned[k] == 1 or (cloth.held[k] == 1 and not cloth.use_xpbd):
        cloth.inv_mass[k] = 0.0
    elif cloth.grip[k] >= 0:
        cloth.inv_mass[k] = cloth.hand_w * cloth.grip_count[cloth.grip[k]]
    else:
        cloth.inv_mass[k] = cloth.free_w


def regrip(cloth, k):
    """Held vertex k's grip after a change of state: a hand of finite strength (with "xpbd", k
    not pinned) grips k and the free vertices within HAND_RADIUS of it along the cloth (a
    pinch holds a patch of cloth, not a point: a point load strains a grid's edges as
    1 / spacing, a patch's do not depend on it), each held at its offset from k; otherwise
    nothing. Then the masses of whatever the change moved in or out of a grip, and the list of
    the hands' vertices."""
    if cloth.grip[k] == k:
        for m in range(cloth.n_verts):
            if cloth.grip[m] == k:
                cloth.grip[m] = -1
                set_mass(cloth, m)
    elif cloth.grip[k] >= 0:
        # k was gripped by another hand: it leaves that grip (grabbed, or pinned).
        other = cloth.grip[k]
        cloth.grip[k] = -1
        cloth.grip_count[other] -= 1
        for m in range(cloth.n_verts):
            if cloth.grip[m] == other:
                set_mass(cloth, m)
    if cloth.held[k] == 1 and cloth.pinned[k] == 0 and cloth.use_xpbd:
        count = gather_grip(cloth, k)
        cloth.grip_count[k] = count
        for j in range(count):
            m = cloth.grip_list[j]
            set_mass(cloth, m)
    count = 0
    for m in range(cloth.n_verts):
        if cloth.grip[m] >= 0:
            cloth.hands[count] = m
            count += 1
    cloth.n_hands = count


def gather_grip(cloth, k):
    """Grip k and the free, unheld vertices within HAND_RADIUS of it along the edges (shortest
    paths, so a grip never reaches across a cut); returns how many, listed in grip_list."""
    dist = cloth.grip_dist
    found = cloth.grip_list
    dist[k] = 0.0
    found[0] = k
    count = 1
    i = 0
    while i < count:
        v = found[i]
        i += 1
        for q in range(cloth.adj_start[v], cloth.adj_start[v + 1]):
            u = cloth.adj_vertex[q]
            d = dist[v] + cloth.adj_rest[q]
            if d <= HAND_RADIUS and (dist[u] < 0.0 or d < dist[u]):
                if dist[u] < 0.0:
                    found[count] = u
                    count += 1
                dist[u] = d
    kept = 0
    for j in range(count):
        m = found[j]
        dist[m] = -1.0
        if m == k or (cloth.pinned[m] == 0 and cloth.held[m] == 0 and cloth.grip[m] < 0):
            found[kept] = m
            kept += 1
            cloth.grip[m] = k
            i = m + m
            cloth.offset[i] = cloth.pos[i] - cloth.pos[k + k]
            cloth.offset[i + 1] = cloth.pos[i + 1] - cloth.pos[k + k + 1]
            cloth.aim[i] = cloth.pos[i]
            cloth.aim[i + 1] = cloth.pos[i + 1]
    return kept


def let_go(cloth, k, strained):
    """Vertex k has just been let go (released or unpinned): if it is free now and there is
    stretch to return (`strained`), the let-go window (LET_GO_SLACK) starts with the next
    step."""
    if cloth.pinned[k] == 0 and cloth.held[k] == 0 and strained:
        cloth.let_go_pending = True


def grab(cloth, k, x, y):
    """Hold vertex k, with the hand at (x, y): with "xpbd" a free vertex is drawn toward it by a
    hand of finite strength (HAND_FORCE); a pin, or any vertex of the seed's method, is put
    there."""
    check_vertex(cloth, k)
    if cloth.held[k] == 0:
        cloth.n_held += 1
    cloth.held[k] = 1
    refresh(cloth, k)
    place(cloth, k, x, y)
    cloth.hold_from[k + k] = x
    cloth.hold_from[k + k + 1] = y


def move(cloth, k, x, y):
    """Move the hand holding vertex k to (x, y)."""
    check_vertex(cloth, k)
    if cloth.held[k] == 0:
        raise SceneError('vertex: move needs a held vertex (grab it first)')
    if x == cloth.target[k + k] and y == cloth.target[k + k + 1]:
        return  # a hand held still changes nothing, and must not keep the cloth awake
    place(cloth, k, x, y)
    cloth.asleep = False
    cloth.still_frames = 0


def move_by(cloth, k, dx, dy):
    """Move the hand holding vertex k to (dx, dy) from where it took hold: compare mode's
    panels each hold their own vertex where it is, and one drag moves every hand by the same
    displacement."""
    check_vertex(cloth, k)         # before reading hold_from; move checks that k is held
    move(cloth, k, cloth.hold_from[k + k] + dx, cloth.hold_from[k + k + 1] + dy)


def release(cloth, k):
    """Let go: a pinned vertex stays pinned where it was left; a free one leaves a hand of
    finite strength with the hand's velocity (from rest if the hand held still), a kinematic
    hold from rest."""
    check_vertex(cloth, k)
    pulled = cloth.held[k] == 1 and cloth.grip[k] == k and cloth.hands_last_frame
    if cloth.held[k] == 1:
        cloth.n_held -= 1
    cloth.held[k] = 0
    refresh(cloth, k)
    if pulled and cloth.pinned[k] == 0:
        # It leaves the hand with the hand's velocity (a hand held still: from rest, its fall
        # exact as rest_at makes it), not with what the last push left in pos - prev.
        i = k + k
        cloth.prev[i] = cloth.pos[i] - cloth.aim_step[i] + 0.5 * cloth.ax
        cloth.prev[i + 1] = cloth.pos[i + 1] - cloth.aim_step[i + 1] + 0.5 * cloth.ay
    let_go(cloth, k, pulled)


def most_strain(cloth):
    """The largest |strain| of any edge (edges broken are removed, break_marked)."""
    pos = cloth.pos
    worst = 0.0
    for e in range(cloth.n_edges):
        a = cloth.edge_a[e] + cloth.edge_a[e]
        b = cloth.edge_b[e] + cloth.edge_b[e]
        dx = pos[b] - pos[a]
        dy = pos[b + 1] - pos[a + 1]
        strain = abs(math.sqrt(dx * dx + dy * dy) / cloth.rest[e] - 1.0)
        if strain > worst:
            worst = strain
    return worst


def pin(cloth, k):
    check_vertex(cloth, k)
    cloth.pinned[k] = 1
    refresh(cloth, k)


def unpin(cloth, k):
    check_vertex(cloth, k)
    cloth.pinned[k] = 0
    refresh(cloth, k)
    # A pin dragged beyond reach and let go; a pin in place holds no stretch of its own (the
    # strain a settled cloth keeps at a pin, 0.45 at a 120x120 two-corner hang's, is no reason).
    let_go(cloth, k, cloth.held[k] == 0 and most_strain(cloth) > LET_GO_STRAIN)


def toggle_pin(cloth, k):
    check_vertex(cloth, k)
    if cloth.pinned[k] == 1:
        unpin(cloth, k)
    else:
        pin(cloth, k)


def place(cloth, k, x, y):
    """The hand holding k goes to (x, y); a vertex moved where the hand is goes with it."""
    if not (x > -1e9 and x < 1e9 and y > -1e9 and y < 1e9):
        raise SceneError('to: must be finite and within 1e9 of the origin')
    cloth.target[k + k] = x
    cloth.target[k + k + 1] = y
    if cloth.inv_mass[k] == 0.0:
        cloth.pos[k + k] = x
        cloth.pos[k + k + 1] = y
        rest_at(cloth, k)


# ---- queries -------------------------------------------------------------------------------


def measure(cloth):
    """Fill `diff` (per edge) and `stress` (per vertex) and the summary numbers."""
    deformation(cloth.pos, cloth.edge_a, cloth.edge_b, cloth.rest, cloth.n_edges, cloth.degree,
                cloth.n_verts, cloth.diff, cloth.stress, cloth.stats)
    cloth.max_diff = cloth.stats[0]
    cloth.rms_diff = cloth.stats[1]
    cloth.max_stress = cloth.stats[2]
    cloth.max_strain = cloth.stats[3]
    cloth.rms_strain = cloth.stats[4]


def nearest(cloth, x, y, radius):
    return nearest_vertex(cloth.pos, cloth.n_verts, x, y, radius)
