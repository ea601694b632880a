"""The cloth's state: flat arrays, one per quantity (n vertices, m edges).

Hot (read and written every step):
    pos, vel      2n doubles, x and y interleaved: where each vertex is and how fast it moves
    prev, vel_prev  2n: the same one step ago (BDF2's history, cloth/integrate.py; Verlet's x*)
    pred, base    2n: a step's inertial target and BDF2's 4/3 x - 1/3 x-
    fixed         n ints: 1 for a vertex nothing moves (pinned and not in a hand)
    mass          n doubles: density times the area the vertex stands for
    edges         edge_a, edge_b, rest, stiff, slot (cloth/topology.py) and the adjacency
    grip, aim, grip_k, grip_f  the hands' springs (cloth/hands.py)
Bookkeeping: pins, holds and where each hand is; obstacles; the measures the page reads.

The core knows nothing of the DOM or GL: the page reads `pos`, the edges and the measures.
"""

from cloth.host import f64, i32


class Cloth:
    def __init__(self, scene):
        cols = scene.cols
        rows = scene.rows
        n = cols * rows
        self.scene = scene
        self.cols = cols
        self.rows = rows
        self.spacing = scene.spacing
        self.n_verts = n
        # the step (step.configure): substep size, gravity, the solver and its budget
        self.dt = scene.dt
        self.h = scene.dt
        self.h_bdf = scene.dt
        self.keep = 1.0
        self.w_scale = 1.0
        self.order = 2            # BDF2, or 1 (backward Euler): integrate.predict
        self.max_order = 2        # the solver's (its ORDER)
        self.damping = 0.0
        self.gravity_x = 0.0
        self.gravity_y = 0.0
        self.substeps = 1
        self.iterations = 0
        self.corrections = 0
        self.solver = 0
        self.stages = []          # a step's stages, chosen by step.configure
        self.frame_stages = []    # a frame's, before its steps
        self.after_stages = []    # and after them
        self.again_stages = []    # a step's from its solve to its finish (energy.no_gain)
        # motion
        self.pos = f64(2 * n)
        self.vel = f64(2 * n)
        self.prev = f64(2 * n)
        self.vel_prev = f64(2 * n)
        self.pred = f64(2 * n)
        self.base = f64(2 * n)
        self.falling = i32(n)     # 1 where nothing holds the vertex's piece (hands.refix)
        self.flying = i32(n)      # 1 where it falls freely in this step: falling, and no
                                  # obstacle near its piece (obstacles.advance)
        self.uncorrected = i32(n)  # 1 where a vertex takes no coarse correction: fixed or falling
        self.piece = i32(n)       # its connected piece (topology.label_pieces)
        self.stack = i32(n)
        self.piece_held = i32(n)
        self.was_falling = i32(n)     # `falling` before a cut (step.broke)
        self.n_pieces = 0
        self.piece_sum = f64(6 * n)   # per piece: inertia weight, offset, air (vbd.keep_momentum)
        self.piece_energy = f64(3 * n)  # per piece: kinetic, elastic, gravitational (energy.py)
        self.energy_before = f64(n)   # per piece: its energy before a step (energy.take_stock)
        self.stock = 0                # 1 when it was taken for this step
        self.piece_motion = f64(3 * n)  # per piece nothing holds: mass, then its velocity
        self.piece_touched = i32(n)   # per piece: 1 if it is near an obstacle (energy.no_gain)
        self.mass = f64(n)
        self.inv_mass = f64(n)    # 1 / mass, 0 where fixed (obstacles and air read it)
        self.fixed = i32(n)
        self.pinned = i32(n)
        self.held = i32(n)
        self.n_held = 0
        # the hands (cloth/hands.py): each held vertex's hand, where it is now (`target`),
        # where it was at the frame's start and where it took hold; per vertex the hand that
        # grips it (-1: none), its offset from the hand, and its spring's stiffness and cap
        self.target = f64(2 * n)
        self.hand_from = f64(2 * n)
        self.hold_from = f64(2 * n)
        self.hand_acted = i32(n)  # 1 once a frame has run with the hand on k (hands.release)
        self.grip = i32(n)
        self.offset = f64(2 * n)
        self.aim = f64(2 * n)
        self.grip_k = f64(n)
        self.grip_f = f64(n)
        self.grip_w = 1.0         # a gripped vertex's inertia weight factor (hands.hold)
        self.gripped = i32(n)     # the vertices some hand grips
        self.n_gripped = 0
        self.scripted = i32(n)    # 1: a pin a script carries this frame (hands.carry)
        self.n_scripted = 0
        self.script_from = f64(2 * n)
        self.script_to = f64(2 * n)
        self.grip_dist = f64(n)   # work arrays of a grip's walk
        self.grip_list = i32(n)
        for k in range(n):
            self.grip[k] = -1
            self.grip_dist[k] = -1.0
        # the edges (topology.build)
        self.n_edges = 0
        self.n_struct = 0
        self.broken = 0
        # the solvers' work (their prepare)
        self.levels = []
        self.lam = f64(0)
        self.hand_lam = f64(0)
        self.mg_stale = True
        self.mg_age = 0
        self.mg_changed = 0       # 1 while they differ from `uncorrected` and the grips now
        self.mg_uncorrected = i32(n)  # `uncorrected` and the grips the coarse operators were
        self.mg_grip = i32(n)     # made for (hands.refix: a change of them makes them stale)
        self.near = i32(0)        # the vertices near a hand, and their marks (vbd.near_hands)
        self.near_mark = i32(0)
        self.term = f64(8)        # one term's force and block (cloth/terms.py)
        self.acc = f64(8)         # a vertex's, summed over its terms
        # measures: per structural edge the value the colours show, per vertex the seed's
        # stress Q, and summaries
        self.load2 = 0.0          # sum over free vertices of (m g)^2: the imbalance's scale
        self.imbalance = 0.0      # the last step's RMS force imbalance over the weight's
        self.out = f64(4)
        # counters: the benchmark's cost measure
        self.steps = 0
        self.sweeps = 0
        self.corrected = 0
        self.rebuilds = 0
        # sleep (cloth/sleep.py)
        self.asleep = False
        self.still_frames = 0
        self.last_pos = f64(0)
        self.still_from = f64(0)
        # the air (cloth/air.py): whether it moves, its clock, its term's arrays
        self.windy = False
        self.air_t = 0.0
        self.air_k = f64(0)
        self.air_w = f64(0)
        # obstacles (cloth/obstacles.py): each one's shape, half width and height, friction,
        # and centre: where it is (`at`), where it was when the step began (`was`), where the
        # frame began (`from`), and where an `obstacle` action sends it by the end of the
        # frame (`to`)
        obstacles = scene.obstacles
        m = len(obstacles)
        self.n_obstacles = m
        self.obstacle_shape = i32(m)
        self.obstacle_half = f64(2 * m)
        self.obstacle_friction = f64(m)
        self.obstacle_at = f64(2 * m)
        self.obstacle_was = f64(2 * m)
        self.obstacle_to = f64(2 * m)
        self.obstacle_from = f64(2 * m)
        self.obstacle_aim = f64(2 * m)     # where it is sent in this step (obstacles.advance)
        self.obstacle_moved = f64(2 * m)   # how far it went in this step (obstacles.carry)
        self.obstacle_bounds = f64(4 * m)  # its box, grown by the contact's reach
        # the contact's arrays (contact.prepare, for a scene with obstacles)
        self.guess = f64(0)
        self.strength = 0.0       # N/m: the fabric's, where it tears (0: never; cloth/tear.py)
        self.tear_t = f64(0)
        self.ring = f64(0)
        self.g_ref = 9.81         # the weight's scale per kg: |g|, at least 1 g (hands.refix)
        self.kappa = 0.0          # the contact's barrier's stiffness (step.configure)
        self.barrier = True       # whether the solver has it (else obstacles.project)
        self.touching = 0         # 1 while the cloth may touch an obstacle (obstacles.advance)
        self.loose = 1            # 1 while every move is tested (ccd.zone)
        self.n_zone = 0
        self.leash_now = 0.0
        for j in range(m):
            o = obstacles[j]
            self.obstacle_shape[j] = o[0]
            self.obstacle_half[j + j] = o[3]
            self.obstacle_half[j + j + 1] = o[4]
            self.obstacle_friction[j] = o[5]
            for c in [self.obstacle_at, self.obstacle_was, self.obstacle_to, self.obstacle_from,
                      self.obstacle_aim]:
                c[j + j] = o[1]
                c[j + j + 1] = o[2]
        # the rest grid: row 0 at y = 0, x to the right, y up
        h = scene.spacing
        for r in range(rows):
            for c in range(cols):
                k = r * cols + c
                self.pos[k + k] = c * h
                self.pos[k + k + 1] = -r * h
        for i in range(len(scene.pins)):
            self.pinned[scene.pins[i]] = 1
            self.fixed[scene.pins[i]] = 1
