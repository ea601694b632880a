"""A scene is data: one JSON object drives the CLI, the tests, the benchmark and the page.

`parse_scene` validates every key (cloth/keys.py declares them) and returns a `Scene` with
defaults filled in. Every error is a SceneError naming its key (cloth/values.py).

Scenes of model 1 (made before the membrane, without a `model` key) still open: their keys that
the membrane has no use for are accepted and left out, `compliance` becomes a stretch
stiffness, the old default solver ("xpbd" with its tethers, cells and line solves) becomes the
default, and `legacy_note` says so in words.
"""

import math

from cloth.host import too_deep, parse_json, kind_of, has_key, key_list, copy_object
from cloth.keys import MAX_VERTICES, MAX_SCENE_BYTES, MAX_DEPTH, MAX_PANELS, MAX_OBSTACLES, \
    OBSTACLE_FAR, OBSTACLE_SIZE, SCENE_KEYS, SETTABLE, NOT_SETTINGS, COMPARE_KEYS, MODEL, \
    LEGACY_KEYS, ALIASES, spec, solver_index
from cloth.keys import SOLVERS, SOLVER_BUDGETS, DEFAULT_SOLVER, SEED_SOLVER
from cloth.values import SceneError, fail, shown, number, integer, boolean, known
from cloth.actions import parse_actions


class Scene:
    """A validated scene: every key present, numbers checked, indices in range."""

    def __init__(self):
        self.model = MODEL
        self.cols = 1
        self.rows = 1
        self.spacing = 1.0
        self.pins = []
        gravity = spec('gravity').fallback
        self.gravity_x = gravity[0]
        self.gravity_y = gravity[1]
        self.dt = spec('dt').fallback
        self.damping = spec('damping').fallback
        self.solver = DEFAULT_SOLVER
        budget = SOLVER_BUDGETS[solver_index(DEFAULT_SOLVER)]
        self.substeps = budget[0]
        self.iterations = budget[1]
        self.corrections = budget[2]
        self.stretch = spec('stretch').fallback     # N/m
        self.shear = spec('shear').fallback         # N/m
        self.density = spec('density').fallback     # kg/m^2
        self.sleep = spec('sleep').fallback
        self.strength = spec('strength').fallback   # N/m: where the fabric tears; 0: never
        wind = spec('wind').fallback
        self.wind_x = wind[0]
        self.wind_y = wind[1]
        self.drag = spec('drag').fallback
        gust = spec('gust').fallback
        self.gust_amplitude = gust[0]
        self.gust_period = gust[1]
        # Each obstacle as [shape (OBSTACLE_SHAPES' index), centre x, centre y, half width,
        # half height (a circle: its radius twice), friction].
        self.obstacles = []
        self.actions = []          # list of actions.Action, sorted by frame (stable)
        self.frames = spec('frames').fallback       # the frames a recording ran for; -1: none
        # The scene's JSON object without NOT_SETTINGS: what a `set` merges its keys into.
        self.settings = None
        # Model 1's keys as read, for legacy_note: [key, what became of it] pairs.
        self.legacy = []
        self.model_given = False   # the scene said its model (a scene without one is model 1's)


def off(k):
    """Whether the Key's 0 means "none" (tearing): it then takes null for none too, and the
    page's field takes empty or `off`."""
    return k.kind == 'number' and k.lo_open and k.fallback == 0.0


def read(obj, key, otherwise):
    """obj[key] checked against its Key (an 'int', 'number' or 'bool'), or `otherwise` when the
    scene omits it (or gives null for a key whose 0 means none)."""
    if not has_key(obj, key):
        return otherwise
    k = spec(key)
    if obj[key] is None and off(k):
        return otherwise
    if k.kind == 'int':
        return integer(obj[key], key, k.lo, k.hi, k.words)
    if k.kind == 'number':
        return number(obj[key], key, k.lo, k.hi, k.lo_open, k.words)
    return boolean(obj[key], key)


def pair(obj, key, words):
    """A key of two numbers, each within its Key's range."""
    v = obj[key]
    if kind_of(v) != 'list' or len(v) != 2:
        fail(key + ': must be a list of two numbers ' + words)
    k = spec(key)
    return [number(v[0], key, k.lo, k.hi, False, k.words),
            number(v[1], key, k.lo, k.hi, False, k.words)]


def too_large():
    """The message for a scene past MAX_SCENE_BYTES, the same wherever it came in."""
    return ('scene: too large: more than ' + str(MAX_SCENE_BYTES) + ' bytes (' +
            str(MAX_SCENE_BYTES // (1024 * 1024)) + ' MiB), the limit for any scene')


def unused_settings(scene):
    """What of a scene's settings its solver does not use, in words ('' for none)."""
    if scene.solver == SEED_SOLVER:
        return ('the seed\'s solver (Jakobsen) holds every edge at its rest length: the fabric\'s '
                'stretch, shear and density change nothing under it (the default solver honours them)')
    return ''


def legacy_note(scene):
    """'' for a scene of the current model; else what running it under the membrane did."""
    if scene.model == MODEL:
        return ''
    parts = []
    for i in range(len(scene.legacy)):
        parts.append(scene.legacy[i][0] + ' ' + scene.legacy[i][1])
    text = 'made before the membrane model (model ' + str(scene.model) + ')'
    if not scene.model_given:
        text += ', as a scene without a "model" key is read (a new scene says "model": ' + str(MODEL) + ')'
    text += ': it runs as a membrane of its fabric'
    if len(parts) > 0:
        text += '; ' + '; '.join(parts)
    return text


def blank(text):
    """Whether the text is nothing but JSON's whitespace (stops at the first other character)."""
    for c in text:
        if c != ' ' and c != '\t' and c != '\n' and c != '\r':
            return False
    return True


def parse_scene(text, panel=-1):
    """JSON text -> Scene, or SceneError naming the offending key. With `panel` >= 0, the
    scene of that panel of its `compare` list: the scene with the panel's keys written in."""
    if len(text) > MAX_SCENE_BYTES:
        fail(too_large())
    if too_deep(text, MAX_DEPTH):
        fail('scene: nested more than ' + str(MAX_DEPTH) + ' levels deep')
    parsed = parse_json(text)
    if parsed is None:
        fail('scene: empty (a scene is a JSON object: docs/scenes.md)' if blank(text) else 'scene: not valid JSON')
    obj = parsed[1]
    scene = scene_from_object(obj)
    if panel < 0:
        return scene
    count = 0
    if has_key(obj, 'compare'):
        count = len(obj['compare'])
    if count == 0:
        fail('panel: the scene has no "compare" panels')
    if not (panel < count and math.floor(panel) == panel):
        fail('panel: must be from 1 to ' + str(count) + ' (the scene compares ' + str(count) +
             ' panels)')
    own = scene_from_object(copy_object(obj, ['compare', 'actions'], obj['compare'][panel]))
    own.actions = scene.actions
    own.frames = scene.frames
    return own


def alias(key):
    """Whether `key` is one an older scene may give in place of another (keys.ALIASES)."""
    for i in range(len(ALIASES)):
        if ALIASES[i][0] == key:
            return True
    return False


def parse_compare(compare, obj):
    """Check `compare`: 2 to MAX_PANELS objects of COMPARE_KEYS, each a valid scene when written
    into this one."""
    if kind_of(compare) != 'list' or len(compare) < 2 or len(compare) > MAX_PANELS:
        fail('compare: must be a list of 2 to ' + str(MAX_PANELS) + ' objects of scene keys, one per panel')
    for i in range(len(compare)):
        where = 'compare[' + str(i) + ']'
        entry = compare[i]
        if kind_of(entry) != 'object':
            fail(where + ': must be an object of scene keys (' + ', '.join(COMPARE_KEYS) + ')')
        names = key_list(entry)
        for j in range(len(names)):
            if not known(COMPARE_KEYS, names[j]) and not alias(names[j]):
                fail(where + '.' + shown(names[j]) + ': not a key a panel can have (' +
                     ', '.join(COMPARE_KEYS) + ')')
        try:
            scene_from_object(copy_object(obj, ['compare', 'actions'], entry))
        except SceneError as err:
            fail(where + '.' + str(err))


def scene_from_object(obj):
    if kind_of(obj) != 'object':
        fail('scene: must be a JSON object')
    s = Scene()
    s.model = 1
    if has_key(obj, 'model'):
        s.model = read(obj, 'model', MODEL)
        s.model_given = True
    old = s.model < MODEL
    for key in key_list(obj):
        if not known(SCENE_KEYS, key) and not (old and known(LEGACY_KEYS, key)):
            fail(shown(key) + ': unknown key (known: ' + ', '.join(SCENE_KEYS) + ')')
    for key in ['cols', 'rows', 'spacing']:
        if not has_key(obj, key):
            fail(key + (': missing (the rest length in metres, > 0)' if key == 'spacing' else
                        ': missing (an integer >= 1)'))
    s.cols = read(obj, 'cols', 0)
    s.rows = read(obj, 'rows', 0)
    if s.cols * s.rows > MAX_VERTICES:
        fail('cols: cols * rows must be at most 1000000 vertices (the grid is too large)')
    s.spacing = read(obj, 'spacing', 0.0)
    n = s.cols * s.rows

    if has_key(obj, 'solver'):
        name = obj['solver']
        if old and name == 'xpbd':
            s.legacy.append(['solver xpbd', 'runs as ' + DEFAULT_SOLVER + ' with its own steps'])
            name = DEFAULT_SOLVER
        elif kind_of(name) != 'string' or not known(SOLVERS, name):
            fail('solver: must be one of ' + ', '.join(SOLVERS))
        s.solver = name
    budget = SOLVER_BUDGETS[solver_index(s.solver)]
    # A model-1 scene's steps were its old solver's: the seed's still mean what they meant.
    own_budget = not old or s.solver == SEED_SOLVER

    if has_key(obj, 'pins'):
        pins = obj['pins']
        if kind_of(pins) != 'list':
            fail('pins: must be a list of vertex indices')
        for i in range(len(pins)):
            s.pins.append(integer(pins[i], 'pins', 0, n - 1,
                                  'vertex indices from 0 to cols * rows - 1'))
    if has_key(obj, 'gravity'):
        g = pair(obj, 'gravity', '[gx, gy] in m/s^2')
        s.gravity_x = g[0]
        s.gravity_y = g[1]
    s.dt = read(obj, 'dt', s.dt)
    s.substeps = read(obj, 'substeps', budget[0])
    s.iterations = read(obj, 'iterations', budget[1])
    s.corrections = read(obj, 'corrections', budget[2])
    if not own_budget:
        for key in ['substeps', 'iterations']:
            if has_key(obj, key):
                s.legacy.append([key, 'left out (the old solver\'s)'])
        s.substeps = budget[0]
        s.iterations = budget[1]
    s.damping = read(obj, 'damping', s.damping)
    s.sleep = read(obj, 'sleep', s.sleep)
    if old:
        read_legacy(obj, s)
    else:
        s.shear = read(obj, 'shear', s.shear)
    s.stretch = read(obj, 'stretch', s.stretch)
    s.density = read(obj, 'density', s.density)
    if s.density * s.spacing * s.spacing < 1e-12:
        fail('density: density * spacing^2 (a vertex\'s mass) must be at least 1e-12 kg')
    if has_key(obj, 'name') and kind_of(obj['name']) != 'string':
        fail('name: must be a string')
    s.strength = read(obj, 'strength', s.strength)
    tear = read(obj, 'tear', 0.0)
    if tear > 0.0 and not (has_key(obj, 'strength') and obj['strength'] is not None):
        s.strength = s.stretch * tear
    s.frames = read(obj, 'frames', s.frames)
    if has_key(obj, 'wind'):
        w = pair(obj, 'wind', '[wx, wy] in m/s')
        s.wind_x = w[0]
        s.wind_y = w[1]
    s.drag = read(obj, 'drag', s.drag)
    if has_key(obj, 'gust'):
        g = obj['gust']
        if kind_of(g) != 'list' or len(g) != 2:
            fail('gust: must be a list [amplitude, period]: the wind swings by amplitude (0 to 10) '
                 'of itself every period seconds (0.01 to 3600)')
        s.gust_amplitude = number(g[0], 'gust', 0.0, 10.0, False, 'an amplitude from 0 to 10')
        s.gust_period = number(g[1], 'gust', 0.01, 3600.0, False, 'a period from 0.01 to 3600 s')
    if has_key(obj, 'obstacles'):
        s.obstacles = parse_obstacles(obj['obstacles'])
    if has_key(obj, 'compare'):
        parse_compare(obj['compare'], obj)
    s.settings = copy_object(obj, NOT_SETTINGS, None)

    def check_set(keys, where):
        settings_scene(s.settings, keys, where)

    if has_key(obj, 'actions'):
        s.actions = parse_actions(obj['actions'], n, len(s.obstacles), check_set)
    return s


def read_legacy(obj, s):
    """A model-1 scene's keys that the membrane has no use for: checked as they were, noted."""
    for key in ['tethers', 'cells', 'lines', 'shear']:
        if has_key(obj, key):
            boolean(obj[key], key)
            s.legacy.append([key, 'left out (every cell has both diagonals)' if key == 'shear'
                             else 'left out (the membrane needs none)'])
    if has_key(obj, 'tolerance'):
        number(obj['tolerance'], 'tolerance', 0.0, 1.0, False, 'from 0 to 1 (a relative strain)')
        s.legacy.append(['tolerance', 'left out'])
    if has_key(obj, 'max_speed'):
        number(obj['max_speed'], 'max_speed', 0.0, 1e6, True, 'in (0, 1000000] m/s')
        s.legacy.append(['max_speed', 'left out (no speed limit)'])
    if has_key(obj, 'compliance'):
        c = number(obj['compliance'], 'compliance', 0.0, 1e3, False, 'from 0 to 1000 m/N')
        if c > 0.0 and not has_key(obj, 'stretch'):
            s.stretch = 1.0 / c
            if s.stretch < 1.0:
                s.stretch = 1.0
            s.legacy.append(['compliance', 'became a stretch stiffness of 1 / compliance'])
        else:
            s.legacy.append(['compliance', 'left out (the fabric\'s stretch instead)'])
    if not has_key(obj, 'density'):
        s.legacy.append(['density', 'the default fabric\'s (each vertex weighed 1 kg)'])


def settings_scene(settings, keys, where):
    """The Scene that `settings` (a scene's JSON object without NOT_SETTINGS) with `keys`
    written into it makes: what a `set` action or a live change in the page turns the running
    cloth's settings into. Errors name the key with `where` before it."""
    if kind_of(keys) != 'object':
        fail(where + ': must be an object of scene keys (' + ', '.join(SETTABLE) + ')')
    names = key_list(keys)
    old = not has_key(settings, 'model') or settings['model'] != MODEL
    for i in range(len(names)):
        if not known(SETTABLE, names[i]) and not (old and known(LEGACY_KEYS, names[i])):
            fail(where + '.' + shown(names[i]) + ': cannot be set on a running cloth (settable: ' +
                 ', '.join(SETTABLE) + ')')
    try:
        return scene_from_object(copy_object(settings, [], keys))
    except SceneError as err:
        fail(where + '.' + str(err))


def parse_obstacles(items):
    """The `obstacles` list -> [[shape, cx, cy, half width, half height, friction], ...]."""
    if kind_of(items) != 'list':
        fail('obstacles: must be a list of {"circle": [x, y, r]} or {"box": [x0, y0, x1, y1]} '
             'objects')
    if len(items) > MAX_OBSTACLES:
        fail('obstacles: at most ' + str(MAX_OBSTACLES) + ' obstacles')
    out = []
    far = 'within ' + str(int(OBSTACLE_FAR)) + ' m of the origin'
    for i in range(len(items)):
        o = items[i]
        where = 'obstacles[' + str(i) + ']'
        if kind_of(o) != 'object':
            fail(where + ': must be an object: {"circle": [x, y, r]} or {"box": [x0, y0, x1, y1]}, '
                 'and an optional "friction"')
        for key in key_list(o):
            if not known(['circle', 'box', 'friction'], key):
                fail(where + '.' + shown(key) + ': unknown key (known: circle, box, friction)')
        if has_key(o, 'circle') == has_key(o, 'box'):
            fail(where + ': needs one shape: "circle": [x, y, r] or "box": [x0, y0, x1, y1]')
        friction = 0.0
        if has_key(o, 'friction'):
            friction = number(o['friction'], where + '.friction', 0.0, 1.0, False, 'from 0 to 1')
        if has_key(o, 'circle'):
            c = o['circle']
            if kind_of(c) != 'list' or len(c) != 3:
                fail(where + '.circle: must be a list of three numbers [x, y, r] in metres')
            x = number(c[0], where + '.circle', -OBSTACLE_FAR, OBSTACLE_FAR, False, far)
            y = number(c[1], where + '.circle', -OBSTACLE_FAR, OBSTACLE_FAR, False, far)
            r = number(c[2], where + '.circle', 0.0, 0.5 * OBSTACLE_SIZE, True,
                       'a radius in (0, ' + str(int(0.5 * OBSTACLE_SIZE)) + '] m')
            out.append([0, x, y, r, r, friction])
        else:
            b = o['box']
            if kind_of(b) != 'list' or len(b) != 4:
                fail(where + '.box: must be a list of four numbers [x0, y0, x1, y1] in metres')
            v = []
            for j in range(4):
                v.append(number(b[j], where + '.box', -OBSTACLE_FAR, OBSTACLE_FAR, False, far))
            if not (v[2] > v[0] and v[3] > v[1]):
                fail(where + '.box: must have x1 > x0 and y1 > y0 (its corners, lower left first)')
            if v[2] - v[0] > OBSTACLE_SIZE or v[3] - v[1] > OBSTACLE_SIZE:
                fail(where + '.box: at most ' + str(int(OBSTACLE_SIZE)) + ' m a side')
            out.append([1, 0.5 * (v[0] + v[2]), 0.5 * (v[1] + v[3]), 0.5 * (v[2] - v[0]),
                        0.5 * (v[3] - v[1]), friction])
    return out
