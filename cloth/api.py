"""The core's entry points, the same in CPython and in the page (`window.clothCore`).

`run(scene_json_text, frames)` is the whole headless pipeline: the CLI prints exactly what it
returns, and the parity tests compare its CPython and browser results number for number.
"""

from cloth.host import to_json, kind_of, is_finite
from cloth.scene import parse_scene, SceneError, fail, MAX_FRAMES
from cloth.sim import Cloth, frame, measure, grab, move, release, pin, unpin, retune

# A trace holds frames x vertices points. The CLI streams it (cloth/__main__.py: memory
# stays that of one frame); in memory, as `run` holds it, it would be gigabytes.
MAX_TRACE_POINTS = 20000000


def load(scene_json_text):
    """Scene JSON text -> a Cloth ready to step (SceneError if the scene is bad)."""
    return Cloth(parse_scene(scene_json_text))


def check(scene_json_text):
    """Scene JSON text -> a checked Scene, nothing built (SceneError if the scene is bad)."""
    return parse_scene(scene_json_text)


def build(scene):
    """A checked Scene (parse_scene) -> a Cloth: the page checks its own limits between."""
    return Cloth(scene)


def set_scene(cloth, scene_json_text):
    """New settings for the running cloth (gravity, dt, substeps, iterations, solver,
    damping, ...): a whole scene on the same grid, checked as `load` checks one. Positions,
    velocities, pins and held vertices stay (sim.retune); a bad scene changes nothing."""
    retune(cloth, parse_scene(scene_json_text))


def check_frames(frames):
    if kind_of(frames) != 'number' or not is_finite(frames) or frames != frames // 1:
        fail('frames: must be a non-negative integer')
    if frames < 0 or frames > MAX_FRAMES:
        fail('frames: must be a non-negative integer of at most 10000000')


def apply_action(cloth, action):
    op = action.op
    k = action.vertex
    if op == 'grab':
        if action.has_to:
            grab(cloth, k, action.to_x, action.to_y)
        else:
            grab(cloth, k, cloth.pos[k + k], cloth.pos[k + k + 1])
    elif op == 'move':
        move(cloth, k, action.to_x, action.to_y)
    elif op == 'release':
        release(cloth, k)
    elif op == 'pin':
        pin(cloth, k)
    elif op == 'unpin':
        unpin(cloth, k)


def positions_of(cloth):
    pos = cloth.pos
    return [[pos[k + k], pos[k + k + 1]] for k in range(cloth.n_verts)]


def apply_due(cloth, next_action, f):
    """Apply the scene's actions from index `next_action` on whose frame is <= f (they come
    sorted by frame); return the index of the first one not yet due. The CLI and the page step
    scripted scenes through this one function."""
    actions = cloth.scene.actions
    while next_action < len(actions) and actions[next_action].frame <= f:
        apply_action(cloth, actions[next_action])
        next_action += 1
    return next_action


def simulate(cloth, frames, trace):
    """Step `frames` frames, applying each action before the frame after its `frame`."""
    next_action = 0
    for f in range(frames):
        next_action = apply_due(cloth, next_action, f)
        frame(cloth)
        if trace is not None:
            trace.append(positions_of(cloth))


def run(scene_json_text, frames, with_trace=False):
    """Run a scene for `frames` frames; return the result as JSON text (see README)."""
    cloth = start(scene_json_text, frames, with_trace)
    trace = [] if with_trace else None
    simulate(cloth, frames, trace)
    result = result_of(cloth, frames)
    if with_trace:
        result['trace'] = trace
    return to_json(result)


def start(scene_json_text, frames, with_trace):
    """The checks of a run, before any work: the scene, the frames, the trace's size."""
    cloth = load(scene_json_text)
    check_frames(frames)
    if with_trace and frames * cloth.n_verts > MAX_TRACE_POINTS:
        fail('frames: a trace of frames x vertices must be at most 20000000 points')
    return cloth


def result_of(cloth, frames):
    measure(cloth)
    m = cloth.n_edges
    return {
        'frames': frames,
        'edges': [[cloth.edge_a[e], cloth.edge_b[e]] for e in range(m)],
        'positions': positions_of(cloth),
        'edge_diff': [cloth.diff[e] for e in range(m)],
        'node_stress': [cloth.stress[k] for k in range(cloth.n_verts)],
    }
