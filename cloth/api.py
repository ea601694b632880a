"""The core's entry points, the same in CPython and in the page (`window.clothCore`).

`run(scene_json_text, frames)` is the whole headless pipeline: the CLI prints exactly what it
returns, and the parity tests compare its CPython and browser results number for number.
"""

from cloth.host import to_json, kind_of, is_finite, parse_json
from cloth.scene import (parse_scene, fail, MAX_FRAMES, MATERIALS,
                         DEFAULT_MATERIAL, MAX_SCENE_BYTES, too_large, KEYS, SOLVERS, SOLVER_LABELS, SEED_SOLVER,
                         DEFAULT_SOLVER, OPS, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES,
                         unused_settings, SCENE_FIELDS)
from cloth.sim import HAND_FORCE, obstacle_under, inside_obstacles, Cloth, count_edges, frame, measure, grab, move, move_by, release, pin, unpin, cut, \
    nearest
from cloth.script import apply_settings, apply_due as due
from cloth.session import open_session, step_panel, frames_ran, frames_left, at_replay_end, \
    gesture_grab, gesture_move, gesture_release, gesture_toggle_pin, gesture_cut, gesture_obstacle, change, \
    recording_text, recording_complete, recording_count, recording_full
from cloth.solve import mark_overstretched

# A trace holds frames x vertices points. The CLI streams it (cloth/__main__.py: memory
# stays that of one frame); in memory, as `run` holds it, it would be gigabytes.
MAX_TRACE_POINTS = 20000000


def load(scene_json_text, panel=-1):
    """Scene JSON text -> a Cloth ready to step (SceneError if the scene is bad); with
    `panel` >= 0, the cloth of that panel of the scene's `compare` list."""
    return Cloth(parse_scene(scene_json_text, panel))


def check(scene_json_text, panel=-1):
    """Scene JSON text -> a checked Scene, nothing built (SceneError if the scene is bad)."""
    return parse_scene(scene_json_text, panel)


def materials():
    """The named fabrics of the page's Material control (scene.MATERIALS: name, label,
    density kg/m^2, stiffness N/m) and the presets' own, declared once for both runtimes."""
    return [MATERIALS, DEFAULT_MATERIAL]


def schema():
    """The scene's keys as scene.KEYS declares them (each a Key: kind, range and its words,
    label, unit, live, panel, defaults, the page's field range), and the limits and names the
    page's other parts check against: [keys, solvers, default solver, action ops, most actions,
    most panels, most vertices, the Scene section's fields, the solvers' labels, the seed's solver,
    a hand's most force in the cloth's weights]. The page derives its fields, the compare editor and the
    recorder from these, so that a key is declared once."""
    return [KEYS, SOLVERS, DEFAULT_SOLVER, OPS, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES, SCENE_FIELDS,
            SOLVER_LABELS, SEED_SOLVER, HAND_FORCE]


def unused(cloth):
    """What of the cloth's settings its solver does not use, in words ('' for none)."""
    return unused_settings(cloth.scene)


def edges_of(cols, rows, shear):
    """How many edges such a grid has (sim.count_edges): the page's cost estimate."""
    return count_edges(cols, rows, shear)


def session_functions():
    """[[name, function]] of a session's entry points (cloth/session.py), each taking the
    session first: the page's panels, gestures, settings, recording and replay."""
    return [['open', open_session], ['stepPanel', step_panel], ['framesRan', frames_ran],
            ['framesLeft', frames_left], ['atReplayEnd', at_replay_end], ['grab', gesture_grab],
            ['move', gesture_move], ['release', gesture_release],
            ['togglePin', gesture_toggle_pin], ['cut', gesture_cut], ['obstacle', gesture_obstacle],
            ['change', change],
            ['recordingText', recording_text], ['recordingComplete', recording_complete],
            ['recordingCount', recording_count], ['recordingFull', recording_full]]


def operations():
    """[[name, function]] of the operations the page calls on a running cloth, every frame or
    every pointer event: cloth/sim.py's module functions, each taking the cloth first. The page
    calls them as they are, because a Transcrypt bound method (cloth.frame()) copies its
    arguments into fresh arrays on every call, which the hot loop must not do."""
    return [['frame', frame], ['measure', measure], ['grab', grab], ['move', move],
            ['move_by', move_by], ['release', release], ['pin', pin], ['unpin', unpin],
            ['nearest', nearest], ['cut', cut], ['obstacle_under', obstacle_under],
            ['inside_obstacles', inside_obstacles]]


def tear_check(cloth, most):
    """The tear check a frame makes (solve.mark_overstretched over every edge, up to `most`
    marked), on its own: the benchmark times it against whole frames. Returns how many edges
    it marked."""
    return mark_overstretched(cloth.pos, cloth.edge_a, cloth.edge_b, cloth.rest, cloth.n_edges,
                              cloth.consts, most, cloth.tear_q, cloth.tear_e)


def scene_limit():
    """[the most bytes a scene may have (scene.MAX_SCENE_BYTES), the message past it]: every
    way a scene comes in checks it while reading, before parsing."""
    return [MAX_SCENE_BYTES, too_large()]


def set_settings(cloth, keys_json_text):
    """New settings for the running cloth, as the JSON text of an object of scene keys (those
    of scene.SETTABLE: gravity, substeps, iterations, solver, damping, ...): what a `set`
    action does (the page's session applies it to every panel: session.change). Positions,
    velocities, pins and held vertices stay (sim.retune); bad keys change nothing."""
    parsed = parse_json(keys_json_text)
    if parsed is None:
        fail('scene: not valid JSON')
    apply_settings(cloth, parsed[1], 'scene')


def check_frames(frames):
    if kind_of(frames) != 'number' or not is_finite(frames) or frames != frames // 1:
        fail('frames: must be a non-negative integer')
    if frames < 0 or frames > MAX_FRAMES:
        fail('frames: must be a non-negative integer of at most ' + str(MAX_FRAMES))


def positions_of(cloth):
    pos = cloth.pos
    return [[pos[k + k], pos[k + k + 1]] for k in range(cloth.n_verts)]


def apply_due(cloth, next_action, f):
    """The scene's actions from index `next_action` on that are due at frame f, applied;
    returns the index of the first one not yet due (script.apply_due: the CLI's loop and the
    benchmark's runs step through it)."""
    return due(cloth, next_action, f)


def simulate(cloth, frames, trace):
    """Step `frames` frames. The state at frame f is the state after f frames and the actions
    of frame f: those of frame 0 come before the first frame, and those of the last frame
    after it (a recording made in the page ends with what a person did at its last frame)."""
    next_action = apply_due(cloth, 0, 0)
    for f in range(1, frames + 1):
        frame(cloth)
        next_action = apply_due(cloth, next_action, f)
        if trace is not None:
            trace.append(positions_of(cloth))


def run(scene_json_text, frames=None, with_trace=False, panel=-1):
    """Run a scene for `frames` frames (None: the scene's own `frames`), or its panel `panel`
    of a compare list; return the result as JSON text (see README)."""
    cloth = load(scene_json_text, panel)
    frames = frames_of(cloth, frames)
    start(cloth, frames, with_trace)
    trace = [] if with_trace else None
    simulate(cloth, frames, trace)
    result = result_of(cloth, frames)
    if with_trace:
        result['trace'] = trace
    return to_json(result)


def frames_of(cloth, frames):
    """The frames to run: those asked for, else the scene's `frames` key."""
    if frames is None:
        if cloth.scene.frames < 0:
            fail('frames: missing: give the frames to run (--frames N), or a "frames" key in the scene')
        return cloth.scene.frames
    return frames


def start(cloth, frames, with_trace):
    """The checks of a run, before any work: the frames, the trace's size."""
    check_frames(frames)
    if with_trace and frames * cloth.n_verts > MAX_TRACE_POINTS:
        fail('frames: a trace of frames x vertices must be at most ' + str(MAX_TRACE_POINTS) + ' points')


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
