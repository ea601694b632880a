"""The core's entry points, the same in CPython and in the page (`window.clothCore`).

`run(scene_json_text, frames)` is the whole headless pipeline: the CLI prints exactly what it
returns, and the parity tests compare its CPython and browser results number for number.
"""

from cloth.host import to_json, kind_of, is_finite, parse_json
from cloth.keys import KEYS, OPS, MAX_FRAMES, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES, \
    MAX_SCENE_BYTES, SCENE_FIELDS, MODEL
from cloth.values import fail
from cloth.keys import SOLVERS, SOLVER_LABELS, DEFAULT_SOLVER, SEED_SOLVER
from cloth.solvers import MEASURED
from cloth.fabrics import FABRICS, DEFAULT_FABRIC
from cloth.scene import parse_scene, too_large, unused_settings, legacy_note
from cloth.presets import PRESETS, preset_scene, preset_view
from cloth.topology import count_edges
from cloth.hands import HAND_FORCE, HAND_RADIUS, grab, move, move_by, release, pin, unpin
from cloth.sleep import SLEEP_IMBALANCE
from cloth.obstacles import obstacle_under, inside_obstacles, edges_through, move_obstacle
from cloth.step import new_cloth, frame, cut
from cloth.measure import measure, nearest, energies
from cloth.script import apply_settings, apply_due as due
from cloth.session import open_session, step_panel, frames_ran, frames_left, at_replay_end, \
    gesture_grab, gesture_move, gesture_release, gesture_toggle_pin, gesture_cut, \
    gesture_obstacle, change, recording_text, recording_complete, recording_count, recording_full

# A trace holds frames x vertices points. The CLI streams it (cloth/__main__.py: memory
# stays that of one frame); in memory, as `run` holds it, it would be gigabytes.
MAX_TRACE_POINTS = 20000000


def load(scene_json_text, panel=-1):
    """Scene JSON text -> a cloth ready to step (SceneError if the scene is bad); with `panel`
    >= 0, the cloth of that panel of the scene's `compare` list."""
    return new_cloth(parse_scene(scene_json_text, panel))


def check(scene_json_text, panel=-1):
    """Scene JSON text -> a checked Scene, nothing built (SceneError if the scene is bad)."""
    return parse_scene(scene_json_text, panel)


def fabrics():
    """[FABRICS (name, label, stretch N/m, shear N/m, density kg/m^2, strength N/m, what it is), the
    presets' fabric], declared once for both runtimes (cloth/fabrics.py)."""
    return [FABRICS, DEFAULT_FABRIC]


def presets():
    """[[name, label, cols, rows, size m], ...]: the Preset menu (cloth/presets.py)."""
    return PRESETS


def preset(name, cols, rows):
    """[the preset's scene object on a cols x rows grid, its view box or []]."""
    return [preset_scene(name, cols, rows), preset_view(name, cols, rows)]


def schema():
    """The scene's keys as cloth/keys.py declares them, and the limits and names the page's
    other parts check against: [keys, solvers, default solver, action ops, most actions, most
    panels, most vertices, the Scene section's fields, the solvers' labels, the seed's solver,
    a hand's force (N), a hand's grip radius (m), the model, the imbalance a cloth at rest has
    at most, the solvers that measure it]. The page derives its fields, the compare editor and
    the recorder from these, so that a key is declared once."""
    return [KEYS, SOLVERS, DEFAULT_SOLVER, OPS, MAX_ACTIONS, MAX_PANELS, MAX_VERTICES, SCENE_FIELDS,
            SOLVER_LABELS, SEED_SOLVER, HAND_FORCE, HAND_RADIUS, MODEL, SLEEP_IMBALANCE, MEASURED]


def notes(cloth):
    """[what of the cloth's settings its solver leaves unused, what running an older scene
    under the membrane did] in words ('' for none)."""
    return [unused_settings(cloth.scene), legacy_note(cloth.scene)]


def edges_of(cols, rows):
    """[structural edges, all edges] of such a grid (topology.count_edges): the page's cost
    estimate."""
    return count_edges(cols, rows)


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
    every pointer event, each taking the cloth first. The page calls them as they are, because
    a Transcrypt bound method copies its arguments into fresh arrays on every call, which the
    hot loop must not do."""
    return [['frame', frame], ['measure', measure], ['grab', grab], ['move', move],
            ['move_by', move_by], ['release', release], ['pin', pin], ['unpin', unpin],
            ['nearest', nearest], ['cut', cut], ['obstacle_under', obstacle_under],
            ['inside_obstacles', inside_obstacles], ['edges_through', edges_through],
            ['move_obstacle', move_obstacle], ['energies', energies]]


def scene_limit():
    """[the most bytes a scene may have (keys.MAX_SCENE_BYTES), the message past it]: every
    way a scene comes in checks it while reading, before parsing."""
    return [MAX_SCENE_BYTES, too_large()]


def set_settings(cloth, keys_json_text):
    """New settings for the running cloth, as the JSON text of an object of scene keys: what a
    `set` action does. Positions, velocities, pins and holds stay (step.retune); bad keys
    change nothing."""
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
    returns the index of the first one not yet due (script.apply_due)."""
    return due(cloth, next_action, f)


def simulate(cloth, frames, trace, progress=None):
    """Step `frames` frames. The state at frame f is the state after f frames and the actions
    of frame f: those of frame 0 come before the first frame, and those of the last frame
    after it (a recording made in the page ends with what a person did at its last frame).
    progress(f), if given, after each frame (the CLI's progress on a long run)."""
    next_action = apply_due(cloth, 0, 0)
    for f in range(1, frames + 1):
        frame(cloth)
        next_action = apply_due(cloth, next_action, f)
        if trace is not None:
            trace.append(positions_of(cloth))
        if progress is not None:
            progress(f)


def run(scene_json_text, frames=None, with_trace=False, panel=-1):
    """Run a scene for `frames` frames (None: the scene's own `frames`), or its panel `panel`
    of a compare list; return the result as JSON text (docs/scenes.md)."""
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
    m = cloth.n_struct
    return {
        'frames': frames,
        'edges': [[cloth.edge_a[e], cloth.edge_b[e]] for e in range(m)],
        'positions': positions_of(cloth),
        'edge_value': [cloth.edge_value[e] for e in range(m)],
        'node_stress': [cloth.stress[k] for k in range(cloth.n_verts)],
    }
