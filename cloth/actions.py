"""A scene's script: its `actions`, checked, in frame order.

Each is {"frame": f, "op": ...}: grab, move, release, pin, unpin (a vertex, and a `to` or
`by`), set (scene keys changed on the running cloth at frame f), cut (a blade `from` -> `to`),
obstacle (obstacle `index` sent `to` a point over the next frame) and carry (a pinned vertex
and its clamp carried rigidly `to` a point over the next frame: a script's clamp, kinematic,
where grab and move are a person's hand, of finite force)."""

from cloth.host import kind_of, key_list, has_key
from cloth.keys import MAX_ACTIONS, MAX_FRAMES, OPS, ACTION_KEYS, OBSTACLE_FAR
from cloth.values import fail, shown, integer, point, known


class Action:
    def __init__(self, frame, op, vertex, has_to, to_x, to_y, keys):
        self.frame = frame
        self.op = op
        self.vertex = vertex
        self.has_to = has_to
        self.to_x = to_x
        self.to_y = to_y
        self.keys = keys       # `set`: the scene keys it sets (a JSON object); else None
        self.from_x = 0.0      # `cut`: the blade runs from (from_x, from_y) to (to_x, to_y)
        self.from_y = 0.0
        self.by = False        # `move`: (to_x, to_y) is a displacement from where the hand took hold


def parse_actions(actions, n, obstacles, check_set):
    """`check_set(keys, where)` checks a set's keys (scene.settings_scene)."""
    if kind_of(actions) != 'list':
        fail('actions: must be a list of {"frame", "op", "vertex", "to"} objects')
    if len(actions) > MAX_ACTIONS:
        fail('actions: at most 100000 actions')
    parsed = []
    for i in range(len(actions)):
        a = actions[i]
        where = 'actions[' + str(i) + ']'
        if kind_of(a) != 'object':
            fail(where + ': must be an object with frame, op, vertex and optional to')
        for key in key_list(a):
            if not known(ACTION_KEYS, key):
                fail(where + '.' + shown(key) + ': unknown key (known: ' + ', '.join(ACTION_KEYS) + ')')
        for key in ['frame', 'op']:
            if not has_key(a, key):
                fail(where + '.' + key + ': missing')
        frame = integer(a['frame'], where + '.frame', 0, MAX_FRAMES,
                        'an integer from 0 to 10000000')
        op = a['op']
        if kind_of(op) != 'string' or not known(OPS, op):
            fail(where + '.op: must be one of ' + ', '.join(OPS))
        if op == 'set':
            # {"frame": f, "op": "set", "scene": {key: value, ...}}: settings changed on the
            # running cloth at frame f (the page records a person's live changes so).
            for key in ['vertex', 'to', 'by']:
                if has_key(a, key):
                    fail(where + '.' + key + ': a set takes no ' + key)
            if not has_key(a, 'scene'):
                fail(where + '.scene: missing (set needs the scene keys it sets)')
            check_set(a['scene'], where + '.scene')
            parsed.append(Action(frame, op, -1, False, 0.0, 0.0, a['scene']))
            continue
        if has_key(a, 'scene'):
            fail(where + '.scene: only set takes scene keys')
        if op == 'cut':
            # {"frame": f, "op": "cut", "from": [x0, y0], "to": [x1, y1]}: every edge whose
            # segment crosses the blade's, where the cloth is at that moment, breaks.
            if has_key(a, 'vertex'):
                fail(where + '.vertex: a cut takes no vertex (it cuts what its blade crosses)')
            if has_key(a, 'by'):
                fail(where + '.by: only move takes "by" (a displacement from where the hand took hold)')
            for key in ['from', 'to']:
                if not has_key(a, key):
                    fail(where + '.' + key + ': missing (cut needs "from" and "to", [x, y] each)')
            p0 = point(a['from'], where + '.from')
            p1 = point(a['to'], where + '.to')
            cut = Action(frame, op, -1, True, p1[0], p1[1], None)
            cut.from_x = p0[0]
            cut.from_y = p0[1]
            parsed.append(cut)
            continue
        if has_key(a, 'from'):
            fail(where + '.from: only cut takes "from"')
        if op == 'obstacle':
            # {"frame": f, "op": "obstacle", "index": i, "to": [x, y]}: obstacle i's centre
            # goes to (x, y) over the next frame, pushing the cloth before it.
            for key in ['vertex', 'by']:
                if has_key(a, key):
                    fail(where + '.' + key + ': an obstacle move takes no ' + key)
            for key in ['index', 'to']:
                if not has_key(a, key):
                    fail(where + '.' + key + ': missing (obstacle needs "index" and "to": [x, y])')
            if obstacles == 0:
                fail(where + '.index: the scene has no obstacles')
            index = integer(a['index'], where + '.index', 0, obstacles - 1,
                            'an obstacle index from 0 to ' + str(obstacles - 1))
            to = point(a['to'], where + '.to')
            if to[0] < -OBSTACLE_FAR or to[0] > OBSTACLE_FAR or to[1] < -OBSTACLE_FAR or \
                    to[1] > OBSTACLE_FAR:
                fail(where + '.to: must be within ' + str(int(OBSTACLE_FAR)) + ' m of the origin')
            parsed.append(Action(frame, op, index, True, to[0], to[1], None))
            continue
        if has_key(a, 'index'):
            fail(where + '.index: only obstacle takes "index"')
        if not has_key(a, 'vertex'):
            fail(where + '.vertex: missing')
        vertex = integer(a['vertex'], where + '.vertex', 0, n - 1,
                         'a vertex index from 0 to cols * rows - 1')
        has_to = has_key(a, 'to')
        has_by = has_key(a, 'by')
        to = [0.0, 0.0]
        if has_by:
            # {"op": "move", "by": [dx, dy]}: the hand goes (dx, dy) from where it took hold
            # (compare mode's panels each hold their own vertex where it is).
            if op != 'move':
                fail(where + '.by: only move takes "by" (a displacement from where the hand took hold)')
            if has_to:
                fail(where + '.by: a move takes "to" or "by", not both')
            to = point(a['by'], where + '.by')
        elif has_to:
            if op != 'grab' and op != 'move' and op != 'carry':
                fail(where + '.to: only grab, move and carry take a target')
            to = point(a['to'], where + '.to')
        elif op == 'move':
            fail(where + '.to: missing (move needs a target "to": [x, y], or "by": [dx, dy] from where the hand took hold)')
        elif op == 'carry':
            fail(where + '.to: missing (carry needs a target "to": [x, y] for the pin)')
        action = Action(frame, op, vertex, has_to, to[0], to[1], None)
        action.by = has_by
        parsed.append(action)
    return check_holds(stable_sort_by_frame(parsed))


def stable_sort_by_frame(actions):
    """Bottom-up merge sort by frame: stable (actions of one frame keep the order they were
    written in), n log n in any order, and the same steps in both runtimes. A list already in
    frame order, the usual case, is returned after one pass."""
    n = len(actions)
    ordered = True
    for i in range(1, n):
        if actions[i - 1].frame > actions[i].frame:
            ordered = False
            break
    if ordered:
        return actions
    src = [a for a in actions]
    dst = [a for a in actions]
    width = 1
    while width < n:
        lo = 0
        while lo < n:
            mid = min(lo + width, n)
            hi = min(lo + width + width, n)
            i = lo
            j = mid
            k = lo
            while k < hi:
                # `<=` takes from the left run on ties: that is what keeps the sort stable.
                if i < mid and (j >= hi or src[i].frame <= src[j].frame):
                    dst[k] = src[i]
                    i += 1
                else:
                    dst[k] = src[j]
                    j += 1
                k += 1
            lo = hi
        tmp = src
        src = dst
        dst = tmp
        width += width
    return src


def check_holds(actions):
    """`move` and `release` need a vertex that an earlier `grab` holds: say so up front."""
    held = {}
    for i in range(len(actions)):
        a = actions[i]
        key = str(a.vertex)
        if a.op == 'grab':
            held[key] = True
        elif a.op == 'move' or a.op == 'release':
            if not has_key(held, key) or not held[key]:
                fail('actions: ' + a.op + ' of vertex ' + key + ' at frame ' + str(a.frame) +
                     ' which is not held (grab it first)')
            if a.op == 'release':
                held[key] = False
    return actions
