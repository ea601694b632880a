"""A frame of the cloth: its stages, chosen once when the scene is configured.

    frame:  `substeps` steps of dt / substeps, each:
                aim the hands  ->  where the obstacles go (if any)  ->  take stock of the energy
                ->  predict  ->  the grips' damping and first guess (the implicit solvers)
                ->  the air's drag for the step (if it moves)  ->  the solve's start clear of
                the obstacles, which push what they meet (if any)  ->  solve  ->  finish
                (velocities)  ->  give back what the step gained  ->  tear (if it tears)
            then: hands and obstacles arrive where they were going, the air's clock moves on,
            and sleep (if on)

The solver (cloth/solvers.py) supplies predict, solve and finish: the integrator and the
minimisation of the step's energy. Everything a stage needs is decided in `configure` (which
stages run, the step's constants), never by the stage itself, each step.

Operations are module functions taking the cloth, not methods: a Transcrypt method call binds
a fresh closure on every call, and the hot path must not allocate.
"""

from cloth.fabrics import HEM_LAYERS, HEM_WIDTH
from cloth.values import SceneError
from cloth.keys import solver_index, SEED_SOLVER
from cloth.solvers import REGISTRY
from cloth.state import Cloth
from cloth import topology
from cloth import integrate
from cloth import energy
from cloth import measure
from cloth import hands
from cloth import obstacles
from cloth import contact
from cloth.ccd import CONTACT_GAP
from cloth import air
from cloth import sleep
from cloth import tear as tearing


def new_cloth(scene):
    """A cloth for a parsed scene, at rest on its rest grid."""
    cloth = Cloth(scene)
    topology.build(cloth, scene.stretch, scene.shear)
    set_masses(cloth, scene.density)
    measure.prepare(cloth)
    configure(cloth, scene)
    for k in range(cloth.n_verts):
        integrate.rest_at(cloth, k)
    hands.regrip(cloth)
    return cloth


def set_masses(cloth, density):
    """Each vertex's mass: density times the area it stands for, a spacing square inside, half
    of it on an edge and a quarter at a corner, so the cloth weighs density times its area on
    every grid (a grid of one row or column stands for a strip one spacing wide), and on the
    border the hem's (HEM_LAYERS * HEM_WIDTH of fabric per length of border: a border vertex
    stands for one spacing of it, a corner for half a spacing on each side)."""
    h = cloth.spacing
    hem = density * HEM_LAYERS * HEM_WIDTH * h
    for r in range(cloth.rows):
        ay = h if cloth.rows == 1 or (r > 0 and r < cloth.rows - 1) else 0.5 * h
        for c in range(cloth.cols):
            ax = h if cloth.cols == 1 or (c > 0 and c < cloth.cols - 1) else 0.5 * h
            k = r * cloth.cols + c
            cloth.mass[k] = density * ax * ay + (hem if topology.on_border(cloth, k) else 0.0)


def configure(cloth, scene):
    """The step's constants and stages, from the scene's settings: at construction, and by
    `retune` when a person changes a setting of the running cloth."""
    cloth.scene = scene
    cloth.dt = scene.dt
    cloth.substeps = scene.substeps
    cloth.iterations = scene.iterations
    cloth.corrections = scene.corrections
    cloth.h = scene.dt / scene.substeps
    cloth.gravity_x = scene.gravity_x
    cloth.gravity_y = scene.gravity_y
    cloth.solver = solver_index(scene.solver)
    cloth.seed = scene.solver == SEED_SOLVER
    cloth.strength = scene.strength
    cloth.kappa = scene.stretch * CONTACT_GAP / 14.0
    solver = REGISTRY[cloth.solver]
    cloth.max_order = solver[1].ORDER
    cloth.barrier = solver[1].BARRIER
    integrate.configure(cloth, scene)
    cloth.mg_stale = True
    solver[1].prepare(cloth)
    contact.prepare(cloth)
    cloth.frame_stages = []
    windy = scene.drag > 0.0 and (scene.wind_x != 0.0 or scene.wind_y != 0.0)
    cloth.windy = windy
    if windy:
        air.prepare(cloth)
    cloth.stages = [hands.aim_hands]
    carries = False
    for i in range(len(scene.actions)):
        if scene.actions[i].op == 'carry':
            carries = True
    if carries:
        cloth.stages.append(hands.carry_pins)
    touching = cloth.n_obstacles > 0
    if touching:
        cloth.stages.append(obstacles.advance)
    # A backward-Euler step of a cloth nothing drives raises no energy (energy.py): not with
    # wind, which does work.
    no_gain = solver[2] == integrate.predict and not windy
    if no_gain:
        cloth.stages.append(energy.take_stock)
    cloth.stages.append(solver[2])
    if solver[2] == integrate.predict:
        cloth.stages.append(hands.hold)
    if windy:
        cloth.stages.append(air.begin)
    if touching:
        cloth.stages.append(obstacles.begin)
    solving = [solver[3]]
    if touching and not solver[1].BARRIER:
        # A solver without the contact's barrier moves the cloth only as far as its edges
        # sweep no obstacle.
        solving.append(obstacles.accept)
    solving.append(solver[4])
    for i in range(len(solving)):
        cloth.stages.append(solving[i])
    if no_gain:
        cloth.again_stages = solving
        cloth.stages.append(energy.no_gain)
    if scene.strength > 0.0:
        tearing.prepare(cloth)
        cloth.stages.append(tear)
    cloth.after_stages = [hands.hands_arrived]
    if carries:
        cloth.after_stages.append(hands.pins_arrived)
    if windy:
        cloth.after_stages.append(air.frame_passed)
    if cloth.n_obstacles > 0:
        cloth.after_stages.append(obstacles.obstacles_arrived)
    if scene.sleep:
        sleep.configure(cloth, scene)
        cloth.after_stages.append(sleep.settle)
    cloth.n_stages = len(cloth.stages)
    cloth.n_frame_stages = len(cloth.frame_stages)
    cloth.n_after_stages = len(cloth.after_stages)


def frame(cloth):
    """Advance one frame (see the module's comment)."""
    if cloth.asleep:
        return
    stages = cloth.frame_stages
    for i in range(cloth.n_frame_stages):
        stages[i](cloth)
    stages = cloth.stages
    count = cloth.n_stages
    substeps = cloth.substeps
    for s in range(substeps):
        cloth.share = (s + 1) / substeps
        for i in range(count):
            stages[i](cloth)
        cloth.steps += 1
    stages = cloth.after_stages
    for i in range(cloth.n_after_stages):
        stages[i](cloth)


def tear(cloth):
    """What passes the fabric's strength breaks (cloth/tear.py), each step (a tear runs as fast
    as the fabric hands its load on to the next yarns, not at a rate of edges a frame)."""
    if tearing.mark(cloth) > 0:
        broke(cloth)


def cut(cloth, x0, y0, x1, y1):
    """Break every edge whose segment crosses the blade from (x0, y0) to (x1, y1), where the
    cloth is now."""
    for v in [x0, y0, x1, y1]:
        if not (v > -1e9 and v < 1e9):
            raise SceneError('cut: from and to must be finite and within 1e9 of the origin')
    if topology.mark_crossed(cloth.pos, cloth.edge_a, cloth.edge_b, cloth.rest, cloth.n_edges,
                             x0, y0, x1, y1) > 0:
        broke(cloth)


def broke(cloth):
    """Edges were marked broken: they go, and what follows from the new topology (the grips
    never reach across a cut; the coarse operators are stale; a piece the cut set free falls
    from the velocity it has, its history restarted: integrate.restart_at)."""
    cloth.broken += topology.remove_marked(cloth)
    cloth.mg_stale = True
    for k in range(cloth.n_verts):
        cloth.was_falling[k] = cloth.falling[k]
    hands.regrip(cloth)
    for k in range(cloth.n_verts):
        if cloth.falling[k] != 0 and cloth.was_falling[k] == 0:
            integrate.restart_at(cloth, k)
    hands.wake(cloth)


def retune(cloth, scene):
    """Apply new settings (a scene on the same grid, parse_scene-checked) to the running cloth:
    positions, velocities, pins and holds stay as they are."""
    if scene.cols != cloth.cols or scene.rows != cloth.rows or scene.spacing != cloth.spacing:
        raise SceneError('scene: cols, rows and spacing make the grid; a change of them needs a '
                         'new cloth')
    old = cloth.scene
    h_old = cloth.h
    solver_old = cloth.solver
    if scene.stretch != old.stretch or scene.shear != old.shear:
        topology.restiffen(cloth, scene.stretch, scene.shear)
    if scene.density != old.density:
        set_masses(cloth, scene.density)
    configure(cloth, scene)
    if cloth.h != h_old or cloth.solver != solver_old or \
            scene.gravity_x != old.gravity_x or scene.gravity_y != old.gravity_y:
        integrate.restart(cloth)
    hands.refix(cloth)
    hands.wake(cloth)
