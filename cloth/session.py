"""A session: what the page runs, in the core, so that CPython runs and tests it as the page does.

A session holds a scene's panels (one cloth, or one per panel of its `compare` list) and
steps them under the same hands:
- a person's gestures and setting changes are applied to every panel and then recorded, in
  one function each (grab, move, release, toggle_pin, cut, obstacle, change);
- the recording is a scene that replays bit for bit (the scene as loaded, its own actions,
  and every gesture and change as an action at the frame where it took effect);
- a replayed recording runs up to its `frames`, and a person acting during it takes over: the
  script's later actions are cut and the holds it made let go.

The page keeps what is about pointers and pixels (input.js, gestures.js) and the timing of its
loop; it hands the session gestures in world metres.

Frames: the state at frame f is the state after f frames and the actions of frame f. A
gesture between frame f and f + 1 is recorded at frame f, after the script's actions of that
frame, which is where `run` applies an action of frame f that comes after them in the list.
"""

from cloth.host import f64, i32, parse_json, has_key, copy_object, to_json
from cloth.scene import parse_scene
from cloth.keys import MAX_ACTIONS, OPS
from cloth.values import fail
from cloth.hands import grab, move, move_by, release, pin, unpin
from cloth.step import new_cloth, cut, frame
from cloth.obstacles import move_obstacle
from cloth.script import apply_due, drop_actions_after, apply_settings



def code_of(op):
    for i in range(len(OPS)):
        if OPS[i] == op:
            return i
    fail('op: ' + op + ' is not an op')


# The recording's ops: an action is kept as its code, its index in scene.OPS, or past them the
# two forms compare mode records.
GRAB = code_of('grab')            # grab at (x, y)
MOVE = code_of('move')            # move to (x, y)
RELEASE = code_of('release')
PIN = code_of('pin')
UNPIN = code_of('unpin')
SET = code_of('set')              # the settings are sets[vertex]
CUT = code_of('cut')              # a blade from (from_x, from_y) to (x, y)
OBSTACLE = code_of('obstacle')    # obstacle `vertex` (its index) sent to (x, y)
CARRY = code_of('carry')          # a script's clamp sent to (x, y) (a person's hand never carries)
GRAB_HERE = len(OPS)              # compare mode: every panel holds its own vertex where it is
MOVE_BY = len(OPS) + 1            # compare mode: every hand moves by (x, y) from where it took hold
FIRST_CAPACITY = 1024


class Recording:
    """Everything that happened to the panels since the scene was loaded, as actions. Moves of
    one vertex within a frame are coalesced into one move to where the last went: only the
    final position matters, and whether the cloth was woken, so a run of moves that comes back
    to its start keeps one move away from it (a move to where a vertex is does nothing in the
    core and would lose the wake). Stored in arrays grown by doubling (never per frame), up to
    MAX_ACTIONS actions with the script's, the scene format's own limit; past it the recording
    ends where it is complete (the frame before the first gesture it could not keep)."""

    def __init__(self, obj, script, n):
        self.base = copy_object(obj, ['actions', 'frames'], None)
        self.script = script          # the scene's own actions (scene.Action), sorted
        self.script_count = len(script)
        self.count = 0
        self.cap = 0
        self.frame_of = i32(0)
        self.op_of = i32(0)
        self.vertex_of = i32(0)
        self.x_of = f64(0)
        self.y_of = f64(0)
        self.from_x = f64(0)
        self.from_y = f64(0)
        self.sets = []
        self.dropped_at = -1
        # Per vertex, for coalescing: the frame of its current run of moves, the index of the
        # run's last move (-1: none) and where that run started from.
        self.run_frame = i32(n)
        self.run_last = i32(n)
        self.run_from_x = f64(n)
        self.run_from_y = f64(n)
        for k in range(n):
            self.run_last[k] = -1
            self.run_frame[k] = -1


def grown_i32(old, count, size):
    out = i32(size)
    for i in range(count):
        out[i] = old[i]
    return out


def grown_f64(old, count, size):
    out = f64(size)
    for i in range(count):
        out[i] = old[i]
    return out


def room(rec, f):
    """Room for one more action at frame f? Past the limit the recording stops for good."""
    if rec.dropped_at >= 0:
        return False
    if rec.script_count + rec.count >= MAX_ACTIONS:
        rec.dropped_at = f
        return False
    if rec.count == rec.cap:
        size = min(max(rec.cap * 2, FIRST_CAPACITY), MAX_ACTIONS)
        rec.frame_of = grown_i32(rec.frame_of, rec.count, size)
        rec.op_of = grown_i32(rec.op_of, rec.count, size)
        rec.vertex_of = grown_i32(rec.vertex_of, rec.count, size)
        rec.x_of = grown_f64(rec.x_of, rec.count, size)
        rec.y_of = grown_f64(rec.y_of, rec.count, size)
        rec.from_x = grown_f64(rec.from_x, rec.count, size)
        rec.from_y = grown_f64(rec.from_y, rec.count, size)
        rec.cap = size
    return True


def push(rec, f, op, k, x, y):
    i = rec.count
    rec.frame_of[i] = f
    rec.op_of[i] = op
    rec.vertex_of[i] = k
    rec.x_of[i] = x
    rec.y_of[i] = y
    rec.count = i + 1
    return i


def record(rec, f, op, k, x, y):
    """Any action but a move: kept as it is, and it ends k's run of moves."""
    if not room(rec, f):
        return -1
    i = push(rec, f, op, k, x, y)
    if k >= 0:
        rec.run_last[k] = -1
    return i


def record_move(rec, f, op, k, x, y, x0, y0):
    """A move (MOVE: to (x, y); MOVE_BY: by (x, y)) of k from (x0, y0) at frame f, coalesced
    with k's run of moves in that frame."""
    if x == x0 and y == y0:
        return                                  # the core did nothing either
    last = rec.run_last[k] if rec.run_frame[k] == f else -1
    if last >= 0 and not (x == rec.run_from_x[k] and y == rec.run_from_y[k]):
        rec.x_of[last] = x                      # still a move away from its start
        rec.y_of[last] = y
        return
    if not room(rec, f):
        return
    rec.run_frame[k] = f
    rec.run_from_x[k] = rec.x_of[last] if last >= 0 else x0
    rec.run_from_y[k] = rec.y_of[last] if last >= 0 else y0
    rec.run_last[k] = push(rec, f, op, k, x, y)


def recorded(rec, i):
    """The recording's action i as a scene object."""
    f = rec.frame_of[i]
    op = rec.op_of[i]
    k = rec.vertex_of[i]
    if op == SET:
        return {'frame': f, 'op': 'set', 'scene': rec.sets[k]}
    if op == CUT:
        return {'frame': f, 'op': 'cut', 'from': [rec.from_x[i], rec.from_y[i]],
                'to': [rec.x_of[i], rec.y_of[i]]}
    if op == OBSTACLE:
        return {'frame': f, 'op': 'obstacle', 'index': k, 'to': [rec.x_of[i], rec.y_of[i]]}
    if op == GRAB_HERE:
        return {'frame': f, 'op': 'grab', 'vertex': k}
    if op == MOVE_BY:
        return {'frame': f, 'op': 'move', 'vertex': k, 'by': [rec.x_of[i], rec.y_of[i]]}
    if op == GRAB:
        return {'frame': f, 'op': 'grab', 'vertex': k, 'to': [rec.x_of[i], rec.y_of[i]]}
    if op == MOVE or op == CARRY:
        return {'frame': f, 'op': OPS[op], 'vertex': k, 'to': [rec.x_of[i], rec.y_of[i]]}
    return {'frame': f, 'op': OPS[op], 'vertex': k}


def scripted(a):
    """A parsed scene.Action as the scene object it came from."""
    if a.op == 'set':
        return {'frame': a.frame, 'op': 'set', 'scene': a.keys}
    if a.op == 'cut':
        return {'frame': a.frame, 'op': 'cut', 'from': [a.from_x, a.from_y], 'to': [a.to_x, a.to_y]}
    if a.op == 'obstacle':
        return {'frame': a.frame, 'op': 'obstacle', 'index': a.vertex, 'to': [a.to_x, a.to_y]}
    if a.by:
        return {'frame': a.frame, 'op': a.op, 'vertex': a.vertex, 'by': [a.to_x, a.to_y]}
    if a.has_to:
        return {'frame': a.frame, 'op': a.op, 'vertex': a.vertex, 'to': [a.to_x, a.to_y]}
    return {'frame': a.frame, 'op': a.op, 'vertex': a.vertex}


def complete(rec, frames):
    """The frame up to which the recording is complete, given the frames run."""
    if rec.dropped_at < 0:
        return frames
    return max(rec.dropped_at - 1, 0)


def recording_scene(rec, frames):
    """The recording as a scene object, `frames` frames long. Within a frame the script's
    actions come first: they were applied when the frame ended, before any gesture."""
    actions = []
    i = 0
    j = 0
    while i < rec.script_count or j < rec.count:
        if j >= rec.count or (i < rec.script_count and rec.script[i].frame <= rec.frame_of[j]):
            actions.append(scripted(rec.script[i]))
            i += 1
        else:
            actions.append(recorded(rec, j))
            j += 1
    over = {'frames': frames}
    if len(actions) > 0:
        over = {'actions': actions, 'frames': frames}
    return copy_object(rec.base, [], over)


class Session:
    """A scene's panels under one pair of hands, their scripts, the recording, the replay."""

    def __init__(self, text):
        scene = parse_scene(text)
        obj = parse_json(text)[1]
        count = len(obj['compare']) if has_key(obj, 'compare') else 0
        self.panels = []
        if count == 0:
            self.panels.append(new_cloth(scene))
            self.base = self.panels[0]
        else:
            for i in range(count):
                self.panels.append(new_cloth(parse_scene(text, i)))
            # What the scene's own settings make, never stepped: the settings panel shows it.
            self.base = new_cloth(scene)
        self.n_panels = len(self.panels)
        n = scene.cols * scene.rows
        self.n_verts = n
        self.frame = 0
        # Each panel's next scripted action (every panel has the same script), and the base's.
        self.script_next = i32(self.n_panels)
        self.base_next = 0
        # A recording replays to its `frames` and stops there; -1: nothing to stop at.
        self.replay_end = scene.frames
        self.replay_ended = False
        # 1 where a person's hand holds the vertex (a scripted grab takes it over).
        self.person = i32(n)
        # Compare mode: where each hand took hold (world metres, in the panel pressed) and how
        # far it has moved since; every panel's hand moves by that from its own vertex.
        self.hand_x = f64(n)
        self.hand_y = f64(n)
        self.hand_dx = f64(n)
        self.hand_dy = f64(n)
        self.recording = Recording(obj, scene.actions, n)
        for i in range(self.n_panels):
            self.script_next[i] = apply_due(self.panels[i], 0, 0)
        if self.base is not self.panels[0]:
            self.base_next = apply_due(self.base, 0, 0)
        # Set when a person's act made a replay that had ended run again (the page unpauses).
        self.resumed = False
        after_script(self, 0, self.script_next[0])


def open_session(text):
    """Scene JSON text -> a Session at frame 0 (SceneError if the scene is bad)."""
    return Session(text)


def after_script(s, start, end):
    """The script's actions [start, end) were applied: a scripted grab takes its vertex from
    a person's hand (the script moves it now, and the pointer's release must not let go of
    the script's hold)."""
    actions = s.panels[0].scene.actions
    for i in range(start, end):
        a = actions[i]
        if a.op == 'grab':
            s.person[a.vertex] = 0


def step_panel(s, i, f):
    """One frame of panel i, which then stands at frame f, and the script's actions of f."""
    cloth = s.panels[i]
    frame(cloth)
    if s.script_next[i] < len(cloth.scene.actions):
        s.script_next[i] = apply_due(cloth, s.script_next[i], f)


def frames_ran(s, frames, start):
    """Every panel ran `frames` more frames (step_panel); `start`: panel 0's next scripted
    action before them. The base follows the script."""
    s.frame += frames
    if s.base is not s.panels[0]:
        s.base_next = apply_due(s.base, s.base_next, s.frame)
    after_script(s, start, s.script_next[0])


def frames_left(s, wanted):
    """How many of `wanted` frames may run: a replay stops at its end."""
    # (No min or max: Transcrypt's spread their arguments into a new array, and this runs
    # every frame.)
    if s.replay_end >= 0 and s.replay_end - s.frame < wanted:
        left = s.replay_end - s.frame
        return left if left > 0 else 0
    return wanted


def at_replay_end(s):
    """True once, when a replay has reached its last frame (the page then pauses)."""
    if s.replay_end >= 0 and s.frame >= s.replay_end:
        s.replay_end = -1
        s.replay_ended = True
        return True
    return False


def take_over(s):
    """A person acts. A replay still playing is cut at this frame (the script's later actions
    are gone from every panel and from the recording), and the holds the script made that no
    person's hand has are let go, recorded. A replay that had ended runs again (`resumed`)."""
    if s.replay_end >= 0:
        s.replay_end = -1
        for i in range(s.n_panels):
            drop_actions_after(s.panels[i], s.frame)
        if s.base is not s.panels[0]:
            drop_actions_after(s.base, s.frame)
        rec = s.recording
        keep = 0
        while keep < rec.script_count and rec.script[keep].frame <= s.frame:
            keep += 1
        rec.script_count = keep
        held = s.panels[0].held
        for k in range(s.n_verts):
            if held[k] != 0 and s.person[k] == 0:
                for i in range(s.n_panels):
                    release(s.panels[i], k)
                record(rec, s.frame, RELEASE, k, 0.0, 0.0)
    if s.replay_ended:
        s.replay_ended = False
        s.resumed = True


def gesture_grab(s, k, x, y):
    """A person's hand takes hold of k at (x, y), world metres in the panel pressed. One
    panel: it holds k there. Compare mode: each panel's hand holds its own k where it is (the
    cloths differ: one panel's point would move the others' vertex at once, and a tap would
    fling them), recorded as a grab without `to`."""
    take_over(s)
    if s.n_panels > 1:
        for i in range(s.n_panels):
            p = s.panels[i]
            grab(p, k, p.pos[k + k], p.pos[k + k + 1])
        s.hand_x[k] = x
        s.hand_y[k] = y
        s.hand_dx[k] = 0.0
        s.hand_dy[k] = 0.0
        record(s.recording, s.frame, GRAB_HERE, k, 0.0, 0.0)
    else:
        grab(s.panels[0], k, x, y)
        record(s.recording, s.frame, GRAB, k, x, y)
    s.person[k] = 1
    return True


def gesture_move(s, k, x, y):
    """The hand on k goes to (x, y) (compare mode: every hand moves by the pointer's
    displacement from where it took hold). A hand held still changes nothing. Each gesture
    returns True when it changed the panels."""
    if s.person[k] == 0:
        return False                              # no person's hand holds k
    if s.n_panels > 1:
        dx = x - s.hand_x[k]
        dy = y - s.hand_y[k]
        dx0 = s.hand_dx[k]
        dy0 = s.hand_dy[k]
        if dx == dx0 and dy == dy0:
            return False
        take_over(s)
        for i in range(s.n_panels):
            move_by(s.panels[i], k, dx, dy)
        s.hand_dx[k] = dx
        s.hand_dy[k] = dy
        record_move(s.recording, s.frame, MOVE_BY, k, dx, dy, dx0, dy0)
        return True
    # Where the hand is (a hand of finite strength's vertex may be short of it).
    target = s.panels[0].target
    x0 = target[k + k]
    y0 = target[k + k + 1]
    if x == x0 and y == y0:
        return False
    take_over(s)
    move(s.panels[0], k, x, y)
    record_move(s.recording, s.frame, MOVE, k, x, y, x0, y0)
    return True


def gesture_release(s, k):
    """The hand on k lets go (a hold the script took from it stays the script's)."""
    if k < 0 or k >= s.n_verts or s.person[k] == 0:
        return False
    s.person[k] = 0
    if s.panels[0].held[k] == 0:
        return False
    take_over(s)
    for i in range(s.n_panels):
        release(s.panels[i], k)
    record(s.recording, s.frame, RELEASE, k, 0.0, 0.0)
    return True


def gesture_toggle_pin(s, k):
    """Pin k where it is, or free it (as panel 0 has it)."""
    take_over(s)
    pinned = s.panels[0].pinned[k] != 0
    for i in range(s.n_panels):
        if pinned:
            unpin(s.panels[i], k)
        else:
            pin(s.panels[i], k)
    record(s.recording, s.frame, UNPIN if pinned else PIN, k, 0.0, 0.0)
    return True


def gesture_cut(s, x0, y0, x1, y1):
    """A blade from (x0, y0) to (x1, y1): what it crosses breaks, in every panel (every cut is
    kept: several in a frame are their union)."""
    if x0 == x1 and y0 == y1:
        return False
    take_over(s)
    for i in range(s.n_panels):
        cut(s.panels[i], x0, y0, x1, y1)
    i = record(s.recording, s.frame, CUT, -1, x1, y1)
    if i >= 0:
        s.recording.from_x[i] = x0
        s.recording.from_y[i] = y0
    return True


def gesture_obstacle(s, j, x, y):
    """A person drags obstacle j: its centre goes to (x, y), world metres, in every panel.
    Moves of one obstacle with nothing between them in a frame are recorded as one, to where
    the last went."""
    p = s.panels[0]
    if j < 0 or j >= p.n_obstacles:
        return False
    if x == p.obstacle_to[j + j] and y == p.obstacle_to[j + j + 1]:
        return False
    take_over(s)
    for i in range(s.n_panels):
        move_obstacle(s.panels[i], j, x, y)
    rec = s.recording
    last = rec.count - 1
    if last >= 0 and rec.op_of[last] == OBSTACLE and rec.vertex_of[last] == j and \
            rec.frame_of[last] == s.frame and rec.dropped_at < 0:
        rec.x_of[last] = x
        rec.y_of[last] = y
    else:
        # Recorded with no vertex (it ends no vertex's run of moves), then given its index.
        i = record(rec, s.frame, OBSTACLE, -1, x, y)
        if i >= 0:
            rec.vertex_of[i] = j
    return True


def change(s, keys_json_text):
    """New settings on the running panels (an object of scene keys, as a `set` action has):
    checked on the base first, so that bad keys change nothing (SceneError); then every panel,
    keys a panel has of its own included, as the recording's `set` replays them."""
    parsed = parse_json(keys_json_text)
    if parsed is None:
        fail('scene: not valid JSON')
    keys = parsed[1]
    apply_settings(s.base, keys, 'scene')
    take_over(s)
    for i in range(s.n_panels):
        if s.panels[i] is not s.base:
            apply_settings(s.panels[i], keys, 'scene')
    rec = s.recording
    if room(rec, s.frame):
        rec.sets.append(keys)
        push(rec, s.frame, SET, len(rec.sets) - 1, 0.0, 0.0)
    return True


def recording_text(s):
    """The recording so far as scene JSON text: it replays, in the CLI and in the page, to
    exactly where the panels are."""
    return to_json(recording_scene(s.recording, complete(s.recording, s.frame)))


def recording_complete(s):
    """The frame up to which the recording is complete."""
    return complete(s.recording, s.frame)


def recording_count(s):
    """How many actions the recording holds, the script's included."""
    return s.recording.script_count + s.recording.count


def recording_full(s):
    """Whether the recording stopped at the scene format's limit (MAX_ACTIONS)."""
    return s.recording.dropped_at >= 0


def advance(s, frames):
    """Run every panel `frames` frames (up to a replay's end) with their scripts; returns the
    frames run. The page runs its panels in timed batches through step_panel instead."""
    frames = frames_left(s, frames)
    start = s.script_next[0]
    for i in range(s.n_panels):
        for f in range(s.frame + 1, s.frame + frames + 1):
            step_panel(s, i, f)
    frames_ran(s, frames, start)
    return frames
