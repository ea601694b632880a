"""A scene is data: one JSON object drives the CLI, the tests, the benchmark and the page.

`parse_scene` validates every key and returns a `Scene` with defaults filled in. Every error is
a `SceneError` whose one-line message starts with the key it is about, so that the CLI, the
page and `clothCore.run` all say the same thing. Messages never print a parsed number back:
CPython and JS would spell it differently.
"""

import math

from cloth.host import too_deep, parse_json, kind_of, is_finite, key_list, has_key, as_index, \
    copy_object, code_units

# Limits. A grid larger than MAX_VERTICES would need hundreds of MB of state (and would not
# run in real time anyway); the other bounds keep every parameter physically meaningful.
MAX_VERTICES = 1000000
MAX_SUBSTEPS = 1000
MAX_ITERATIONS = 10000
MAX_FRAMES = 10000000
MAX_ACTIONS = 100000
MIN_DT = 1e-6
# A scene nests 4 deep (scene, actions, an action, its `to`); deeper is not a scene.
MAX_DEPTH = 32

SOLVERS = ['jakobsen', 'xpbd']
DEFAULT_SOLVER = 'xpbd'
# What the page's Solver menu and compare panels call SOLVERS[i].
SOLVER_LABELS = ['Jakobsen (the seed\'s method)', 'XPBD + tethers, cells, lines']
SEED_SOLVER = 'jakobsen'     # the seed's method, as it specifies it
OPS = ['grab', 'move', 'release', 'pin', 'unpin', 'set', 'cut', 'obstacle']
MAX_TEAR = 1e6
MAX_PANELS = 4
# Obstacles: at most this many (each is a test per vertex per step), within OBSTACLE_FAR of
# the origin and at most OBSTACLE_SIZE across (metres). Shapes by index: OBSTACLE_SHAPES[i].
MAX_OBSTACLES = 16
OBSTACLE_FAR = 1e6
OBSTACLE_SIZE = 1e4
OBSTACLE_SHAPES = ['circle', 'box']

# The page's Scene section: its number fields, in order, each with the hint it shows beside
# its range and, for a key of two numbers, the one the field is (0 or 1) and the Scene
# attributes that hold the two ([] for a key of one number). A key that is not `live` makes
# the grid: a change of it loads a new one.
SCENE_FIELDS = [
    ['cols', '', 0, []],
    ['rows', '', 0, []],
    ['iterations', '', 0, []],
    ['substeps', '', 0, []],
    ['gravity', 'its y component: down is negative', 1, ['gravity_x', 'gravity_y']],
    ['damping', 'still air: the velocity lost per second', 0, []],
    ['wind', 'its x component: the air\'s velocity, which pushes the cloth across its edges '
     '(with the scene\'s drag)', 0, ['wind_x', 'wind_y']],
    ['gust', 'how far gusts swing the wind: 0.5 is \u00b150% at their peaks (the scene\'s gust '
     'period, 1 s unless it says)', 0, ['gust_amplitude', 'gust_period']],
    ['tear', 'an edge breaks once its strain (length \u2212 rest) / rest passes this; empty: no tearing',
     0, []],
]


class Key:
    """One scene key, declared once: the parser checks it by this, its messages word its
    range with `words`, the page's fields and the compare editor take their label, unit and
    range from it (`field_lo`, `field_hi`: what a person types in the page, within the core's
    own; `step`: an arrow key's step), `live` says a `set` may change it on a running cloth, and
    `panel` that a compare panel may have its own (2: shown at once in the editor, 1: under
    "more"). The default is `fallback`, or `by_solver[i]` for SOLVERS[i] where it differs per
    solver. Attributes avoid the names Transcrypt renames (name, default, type, ...)."""

    def __init__(self, key, kind, lo, hi, lo_open, words, label, unit, live, panel, fallback,
                 by_solver, field_lo, field_hi, step):
        self.key = key
        self.kind = kind           # 'int', 'number', 'bool', 'choice', or a key's own kind
        self.lo = lo
        self.hi = hi
        self.lo_open = lo_open
        self.words = words
        self.label = label
        self.unit = unit
        self.live = live
        self.panel = panel
        self.fallback = fallback
        self.by_solver = by_solver
        self.field_lo = field_lo
        self.field_hi = field_hi
        self.step = step


# Every key a scene may have. The order is the one messages list them in.
#   key  kind  lo  hi  lo_open  words  label  unit  live  panel  default  per solver
#   (jakobsen, xpbd)  page field lo, hi, step
KEYS = [
    Key('cols', 'int', 1, MAX_VERTICES, False, 'an integer from 1 to 1000000', 'Columns', '',
        False, 0, None, None, 1, 200, 1),
    Key('rows', 'int', 1, MAX_VERTICES, False, 'an integer from 1 to 1000000', 'Rows', '',
        False, 0, None, None, 1, 200, 1),
    Key('spacing', 'number', 1e-4, 1e4, False, 'from 0.0001 to 10000 metres', 'Spacing', 'm',
        False, 0, None, None, 1e-4, 1e4, 0.01),
    Key('pins', 'pins', 0, 0, False, '', 'Pins', '', False, 0, None, None, 0, 0, 0),
    # The page's Gravity field is its y component.
    Key('gravity', 'point', -1e5, 1e5, False, 'at most 1e5 m/s^2 per axis', 'Gravity',
        'm/s\u00b2', True, 0, [0.0, -9.81], None, -100, 100, 0.1),
    # Not down to 0: a step's h^2 must stay a normal double (dt 1e-300 made it 0, and
    # compliance / h^2 a division by zero); a microsecond is far below any frame.
    Key('dt', 'number', MIN_DT, 1.0, False, 'from 0.000001 to 1 seconds', 'Frame time', 's',
        True, 0, 1.0 / 60.0, None, MIN_DT, 1.0, 0.001),
    Key('substeps', 'int', 1, MAX_SUBSTEPS, False, 'an integer from 1 to 1000', 'Substeps', '',
        True, 2, None, [1, 8], 1, 16, 1),
    Key('iterations', 'int', 0, MAX_ITERATIONS, False, 'an integer from 0 to 10000',
        'Iterations', '', True, 2, None, [20, 1], 0, 200, 1),
    Key('damping', 'number', 0.0, 1000.0, False, 'from 0 to 1000 per second', 'Damping', '1/s',
        True, 2, 0.0, None, 0, 100, 0.1),
    Key('solver', 'choice', 0, 0, False, '', 'Solver', '', True, 2, None, None, 0, 0, 0),
    Key('actions', 'actions', 0, 0, False, '', 'Actions', '', False, 0, None, None, 0, 0, 0),
    Key('tethers', 'bool', 0, 0, False, '', 'Tethers', '', True, 1, None, [False, True],
        0, 0, 0),
    Key('shear', 'bool', 0, 0, False, '', 'Shear', '', False, 1, False, None, 0, 0, 0),
    Key('compliance', 'number', 0.0, 1e3, False, 'from 0 to 1000 m/N', 'Compliance', 'm/N',
        True, 1, 0.0, None, 0, 1000, 1e-4),
    Key('tolerance', 'number', 0.0, 1.0, False, 'from 0 to 1 (a relative strain)', 'Tolerance',
        '', True, 1, None, [0.0, 1e-4], 0, 1, 1e-4),
    Key('max_speed', 'number', 0.0, 1e6, True, 'in (0, 1000000] m/s', 'Max speed', 'm/s',
        True, 1, 1000.0, None, 1e-3, 1e6, 1),
    Key('sleep', 'bool', 0, 0, False, '', 'Sleep', '', True, 1, None, [False, True], 0, 0, 0),
    Key('cells', 'bool', 0, 0, False, '', 'Cells', '', True, 1, None, [False, True], 0, 0, 0),
    Key('lines', 'bool', 0, 0, False, '', 'Lines', '', True, 1, None, [False, True], 0, 0, 0),
    Key('name', 'string', 0, 0, False, '', 'Name', '', False, 0, None, None, 0, 0, 0),
    Key('frames', 'int', 0, MAX_FRAMES, False,
        'an integer from 0 to 10000000 (the frames the scene was recorded for)', 'Frames', '',
        False, 0, -1, None, 0, 0, 0),
    Key('compare', 'compare', 0, 0, False, '', 'Compare', '', False, 0, None, None, 0, 0, 0),
    # The strain past which an edge breaks; null or omitted: no tearing (0 in a Scene). The
    # page's field takes empty, `off` or 0 for none.
    Key('tear', 'number', 0.0, MAX_TEAR, True,
        'a strain greater than 0 (an edge breaks once (length - rest) / rest exceeds it), or '
        'null for no tearing', 'Tear', 'strain', True, 1, 0.0, None, 0.01, 100, 0.01),
    # kg/m^2: a vertex stands for a cell of spacing^2 of cloth. Without it every vertex weighs
    # 1 kg, as before the key existed (the scenes and recordings made then mean what they
    # meant).
    Key('density', 'number', 0.0, 1e4, True, 'in (0, 10000] kg/m^2 (the cloth\'s mass per area)',
        'Density', 'kg/m\u00b2', True, 1, 0.0, None, 0.001, 100, 0.01),
    # The air: its velocity (m/s) and how hard it pushes on the cloth across an edge (drag:
    # N s/m^3, the force on a metre of edge standing for a strip one spacing wide, per m/s of
    # air across it: per area, like the mass, so the same on every grid). Gusts scale the
    # wind by 1 + amplitude * a smooth periodic wave of the period (polynomial, so the same to
    # the bit in both runtimes). In still air none of it runs.
    Key('wind', 'point', -1e3, 1e3, False, 'at most 1000 m/s per axis', 'Wind', 'm/s', True, 0,
        [0.0, 0.0], None, -50, 50, 0.5),
    Key('drag', 'number', 0.0, 1e3, False, 'from 0 to 1000 N s/m^3 (the air\'s push across an '
        'edge, per square metre of cloth and m/s of air)', 'Drag', 'N\u00b7s/m\u00b3', True, 1, 0.1,
        None, 0, 100, 0.01),
    Key('gust', 'gust', 0.0, 10.0, False, 'an amplitude from 0 to 10 (and a period from 0.01 to 3600 s)',
        'Gusts', '', True, 0, [0.0, 1.0], None, 0, 10, 0.1),
    # Rigid shapes the cloth's free vertices stay out of: {"circle": [x, y, r]} or
    # {"box": [x0, y0, x1, y1]}, each with an optional friction (0 to 1). A person or the
    # script moves one with the `obstacle` action; a `set` leaves them where they are.
    Key('obstacles', 'obstacles', 0, 0, False, '', 'Obstacles', '', False, 0, None, None,
        0, 0, 0),
]


def spec(key):
    """The Key declared for `key`."""
    for i in range(len(KEYS)):
        if KEYS[i].key == key:
            return KEYS[i]
    raise SceneError(key + ': not a scene key')


def keys_where(what):
    """The names of the keys that are `live` ('live') or a panel's own ('panel')."""
    out = []
    for i in range(len(KEYS)):
        k = KEYS[i]
        if (what == 'live' and k.live) or (what == 'panel' and k.panel > 0):
            out.append(k.key)
    return out


SCENE_KEYS = [k.key for k in KEYS]
ACTION_KEYS = ['frame', 'op', 'vertex', 'to', 'by', 'scene', 'from', 'index']
# The keys a `set` action may change on the running cloth: everything but what makes the grid
# (cols, rows, spacing, shear, pins) and what is not physics (actions, frames, name).
SETTABLE = keys_where('live')
# What the settings of a `set` are merged into: the scene's own keys but these, which a set
# can neither change nor needs (actions would be parsed again at every set).
NOT_SETTINGS = ['actions', 'pins', 'frames', 'name', 'compare', 'obstacles']
# `compare`: the page's compare mode, 2 to MAX_PANELS panels that run the scene side by side
# under the same hands, each with some of these keys of its own. The physics ignores it but
# for the panel a run asks for (parse_scene's `panel`).
COMPARE_KEYS = keys_where('panel')
# Every scene that comes in (a link, a file opened or dropped, the Scene JSON box, the CLI) is
# refused past this many bytes of UTF-8 JSON, counted while it is read or inflated, before
# anything is parsed: the largest recording the page makes (MAX_ACTIONS actions) is about
# 6 MB, while a 270 kB link once inflated to a 200 MB name (a tab of 900 MB that then crashed).
MAX_SCENE_BYTES = 16 * 1024 * 1024
# The page's Material control: named fabrics, each [name, label, density in kg/m^2, stretch
# stiffness in N/m (the scene's compliance is its inverse; 0: inextensible)]. Jersey is the
# presets' own: hanging 1.5 m under its own weight it stretches 0.6% at the pins (strain =
# density g height / stiffness), visible in the colours. The inextensible choice keeps
# jersey's weight, so that switching changes only the stretch. Stiffnesses are those of light
# fabrics at small strain (a woven's is set by its yarns, a knit's by its loops).
MATERIALS = [['inextensible', 'Inextensible', 0.2, 0.0],
             ['cotton', 'Cotton (woven)', 0.15, 5000.0],
             ['jersey', 'Jersey (knit)', 0.2, 500.0],
             ['spandex', 'Spandex (stretch knit)', 0.2, 100.0]]
DEFAULT_MATERIAL = 'jersey'


class SceneError(Exception):
    """A scene, or a request about one, that the core refuses; the message names the key."""
    pass


def fail(message):
    raise SceneError(message)


HEX = '0123456789abcdef'
SHOWN_UNITS = 40


def shown(text):
    """A key from the input, fit for a one-line message that both runtimes write alike: at
    most SHOWN_UNITS characters, anything but printable ASCII as a \\uXXXX escape of its
    UTF-16 code unit (a newline would break the line, a lone surrogate prints differently)."""
    units = code_units(text)
    out = []
    for i in range(min(len(units), SHOWN_UNITS)):
        u = units[i]
        if u >= 32 and u < 127 and u != 92:
            out.append(chr(u))
        else:
            out.append('\\u' + HEX[(u >> 12) & 15] + HEX[(u >> 8) & 15] + HEX[(u >> 4) & 15] + HEX[u & 15])
    if len(units) > SHOWN_UNITS:
        out.append('...')
    return ''.join(out)


def solver_defaults(solver):
    """Each solver's defaults for the keys a scene may omit (the Keys' `by_solver`).
    "jakobsen" is the seed's method exactly: one step of `iterations` Gauss-Seidel sweeps, no
    extras. "xpbd" is the best configuration the benchmark found (see README): small steps
    plus long-range tethers, cells and line solves."""
    which = 0
    for i in range(len(SOLVERS)):
        if SOLVERS[i] == solver:
            which = i
    out = {}
    for i in range(len(KEYS)):
        if KEYS[i].by_solver is not None:
            out[KEYS[i].key] = KEYS[i].by_solver[which]
    return out


class Scene:
    """A validated scene: every key present, numbers checked, indices in range."""

    def __init__(self):
        self.cols = 1
        self.rows = 1
        self.spacing = 1.0
        self.pins = []
        gravity = spec('gravity').fallback
        self.gravity_x = gravity[0]
        self.gravity_y = gravity[1]
        wind = spec('wind').fallback
        self.wind_x = wind[0]      # m/s, the air's velocity
        self.wind_y = wind[1]
        self.drag = spec('drag').fallback
        gust = spec('gust').fallback
        self.gust_amplitude = gust[0]     # the wind's relative swing
        self.gust_period = gust[1]        # s
        # Each obstacle as [shape (OBSTACLE_SHAPES' index), centre x, centre y, half width,
        # half height (a circle: its radius twice), friction].
        self.obstacles = []
        self.dt = spec('dt').fallback
        self.damping = spec('damping').fallback
        self.max_speed = spec('max_speed').fallback
        self.solver = DEFAULT_SOLVER
        by_solver = solver_defaults(DEFAULT_SOLVER)
        self.substeps = by_solver['substeps']
        self.iterations = by_solver['iterations']
        self.tethers = by_solver['tethers']
        self.tolerance = by_solver['tolerance']
        self.sleep = by_solver['sleep']
        self.cells = by_solver['cells']
        self.lines = by_solver['lines']
        self.shear = spec('shear').fallback
        self.compliance = spec('compliance').fallback
        self.tear = spec('tear').fallback        # the strain past which an edge breaks; 0: none
        self.mass = 1.0        # kg a vertex: density * spacing^2, or 1 kg without a density
        self.density = spec('density').fallback  # kg/m^2 as given; 0: none (1 kg a vertex)
        self.actions = []      # list of Action, sorted by frame (stable)
        self.frames = spec('frames').fallback    # the frames a recording ran for; -1: not given
        # The scene's JSON object without NOT_SETTINGS: what a `set` action merges its keys
        # into, so that a set means "this scene with these keys written into it" (solver
        # defaults included: a scene that omits `tethers` and is set to "jakobsen" gets
        # the seed's default, as if it had been written so).
        self.settings = None


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


def number(value, key, lo, hi, lo_open, what):
    """A finite JSON number in [lo, hi] (or (lo, hi] when lo_open); `what` words the range."""
    if kind_of(value) != 'number':
        fail(key + ': must be a number')
    if not is_finite(value):
        fail(key + ': must be finite')
    if value < lo or value > hi or (lo_open and value == lo):
        fail(key + ': must be ' + what)
    return value


def integer(value, key, lo, hi, what):
    if kind_of(value) != 'number':
        fail(key + ': must be an integer')
    if not is_finite(value) or math.floor(value) != value:
        fail(key + ': must be an integer')
    if value < lo or value > hi:
        fail(key + ': must be ' + what)
    return as_index(value)


def boolean(value, key):
    if kind_of(value) != 'bool':
        fail(key + ': must be true or false')
    return value


def off(k):
    """Whether the Key's 0 means "none" (tearing, a density): it then takes null for none too,
    and the page's field takes empty or `off`."""
    return k.kind == 'number' and k.lo_open and k.fallback == 0.0


def read(obj, key, otherwise):
    """obj[key] checked against its Key (an 'int', 'number' or 'bool'), or `otherwise` when
    the scene omits it (or gives null for a key whose 0 means none)."""
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


def point(value, key):
    if kind_of(value) != 'list' or len(value) != 2:
        fail(key + ': must be a list of two numbers [x, y]')
    x = number(value[0], key, -1e9, 1e9, False, 'within 1e9 of the origin')
    y = number(value[1], key, -1e9, 1e9, False, 'within 1e9 of the origin')
    return [x, y]


def too_large():
    """The message for a scene past MAX_SCENE_BYTES, the same wherever it came in."""
    return ('scene: too large: more than ' + str(MAX_SCENE_BYTES) + ' bytes (' +
            str(MAX_SCENE_BYTES // (1024 * 1024)) + ' MiB), the limit for any scene')


def unused_settings(scene):
    """What of a scene's settings its solver does not use, in words ('' for none): the seed's
    solver holds every edge at its rest length whatever the material, and with every vertex
    of the same mass under gravity alone, a density changes nothing either."""
    if scene.solver == SEED_SOLVER and (scene.compliance > 0.0 or scene.density > 0.0):
        return ('the seed\'s solver (Jakobsen) holds every edge at its rest length: a material '
                'has no effect under it (the default solver honours it)')
    return ''


def parse_scene(text, panel=-1):
    """JSON text -> Scene, or SceneError naming the offending key. With `panel` >= 0, the
    scene of that panel of its `compare` list: the scene with the panel's keys written in."""
    if len(text) > MAX_SCENE_BYTES:
        fail(too_large())
    if too_deep(text, MAX_DEPTH):
        fail('scene: nested more than ' + str(MAX_DEPTH) + ' levels deep')
    parsed = parse_json(text)
    if parsed is None:
        fail('scene: not valid JSON')
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
    # The panel's settings, the scene's grid, pins and script.
    own.actions = scene.actions
    own.frames = scene.frames
    return own


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
            if not known(COMPARE_KEYS, names[j]):
                fail(where + '.' + shown(names[j]) + ': not a key a panel can have (' +
                     ', '.join(COMPARE_KEYS) + ')')
        try:
            scene_from_object(copy_object(obj, ['compare', 'actions'], entry))
        except SceneError as err:
            fail(where + '.' + str(err))


def scene_from_object(obj):
    if kind_of(obj) != 'object':
        fail('scene: must be a JSON object')
    for key in key_list(obj):
        if not known(SCENE_KEYS, key):
            fail(shown(key) + ': unknown key (known: ' + ', '.join(SCENE_KEYS) + ')')
    s = Scene()
    if not has_key(obj, 'cols'):
        fail('cols: missing (an integer >= 1)')
    if not has_key(obj, 'rows'):
        fail('rows: missing (an integer >= 1)')
    if not has_key(obj, 'spacing'):
        fail('spacing: missing (the rest length in metres, > 0)')
    s.cols = read(obj, 'cols', 0)
    s.rows = read(obj, 'rows', 0)
    if s.cols * s.rows > MAX_VERTICES:
        fail('cols: cols * rows must be at most 1000000 vertices (the grid is too large)')
    s.spacing = read(obj, 'spacing', 0.0)
    n = s.cols * s.rows

    if has_key(obj, 'solver'):
        if kind_of(obj['solver']) != 'string' or not known(SOLVERS, obj['solver']):
            fail('solver: must be one of ' + ', '.join(SOLVERS))
        s.solver = obj['solver']
    defaults = solver_defaults(s.solver)

    if has_key(obj, 'pins'):
        pins = obj['pins']
        if kind_of(pins) != 'list':
            fail('pins: must be a list of vertex indices')
        for i in range(len(pins)):
            s.pins.append(integer(pins[i], 'pins', 0, n - 1,
                                  'vertex indices from 0 to cols * rows - 1'))
    if has_key(obj, 'gravity'):
        g = obj['gravity']
        if kind_of(g) != 'list' or len(g) != 2:
            fail('gravity: must be a list of two numbers [gx, gy] in m/s^2')
        k = spec('gravity')
        s.gravity_x = number(g[0], 'gravity', k.lo, k.hi, False, k.words)
        s.gravity_y = number(g[1], 'gravity', k.lo, k.hi, False, k.words)
    # In the order the keys were checked before the schema, so that a scene with several bad
    # keys is told of the same one first.
    s.dt = read(obj, 'dt', s.dt)
    s.substeps = read(obj, 'substeps', defaults['substeps'])
    s.iterations = read(obj, 'iterations', defaults['iterations'])
    s.damping = read(obj, 'damping', s.damping)
    s.max_speed = read(obj, 'max_speed', s.max_speed)
    s.tethers = read(obj, 'tethers', defaults['tethers'])
    s.shear = read(obj, 'shear', s.shear)
    s.sleep = read(obj, 'sleep', defaults['sleep'])
    s.cells = read(obj, 'cells', defaults['cells'])
    s.lines = read(obj, 'lines', defaults['lines'])
    s.compliance = read(obj, 'compliance', s.compliance)
    s.tolerance = read(obj, 'tolerance', defaults['tolerance'])
    s.density = read(obj, 'density', s.density)
    if s.density > 0.0:
        s.mass = s.density * s.spacing * s.spacing
        if s.mass < 1e-12:
            fail('density: density * spacing^2 (a vertex\'s mass) must be at least 1e-12 kg')
    if has_key(obj, 'name'):
        if kind_of(obj['name']) != 'string':
            fail('name: must be a string')
    s.tear = read(obj, 'tear', s.tear)
    s.frames = read(obj, 'frames', s.frames)
    if has_key(obj, 'wind'):
        w = obj['wind']
        if kind_of(w) != 'list' or len(w) != 2:
            fail('wind: must be a list of two numbers [wx, wy] in m/s')
        k = spec('wind')
        s.wind_x = number(w[0], 'wind', k.lo, k.hi, False, k.words)
        s.wind_y = number(w[1], 'wind', k.lo, k.hi, False, k.words)
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
    if has_key(obj, 'actions'):
        s.actions = parse_actions(obj['actions'], n, s.settings, len(s.obstacles))
    return s


def settings_scene(settings, keys, where):
    """The Scene that `settings` (a scene's JSON object without NOT_SETTINGS) with `keys`
    written into it makes: what a `set` action or a live change in the page turns the running
    cloth's settings into. Errors name the key with `where` before it."""
    if kind_of(keys) != 'object':
        fail(where + ': must be an object of scene keys (' + ', '.join(SETTABLE) + ')')
    names = key_list(keys)
    for i in range(len(names)):
        if not known(SETTABLE, names[i]):
            fail(where + '.' + shown(names[i]) + ': cannot be set on a running cloth (settable: ' +
                 ', '.join(SETTABLE) + ')')
    try:
        return scene_from_object(copy_object(settings, [], keys))
    except SceneError as err:
        fail(where + '.' + str(err))


def known(names, key):
    for i in range(len(names)):
        if names[i] == key:
            return True
    return False


def parse_obstacles(items):
    """The `obstacles` list -> [[shape, cx, cy, half width, half height, friction], ...]."""
    if kind_of(items) != 'list':
        fail('obstacles: must be a list of {"circle": [x, y, r]} or {"box": [x0, y0, x1, y1]} '
             'objects')
    if len(items) > MAX_OBSTACLES:
        fail('obstacles: at most ' + str(MAX_OBSTACLES) + ' obstacles')
    out = []
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
        far = 'within ' + str(int(OBSTACLE_FAR)) + ' m of the origin'
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


def parse_actions(actions, n, settings, obstacles):
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
            settings_scene(settings, a['scene'], where + '.scene')
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
            if op != 'grab' and op != 'move':
                fail(where + '.to: only grab and move take a target')
            to = point(a['to'], where + '.to')
        elif op == 'move':
            fail(where + '.to: missing (move needs a target "to": [x, y], or "by": [dx, dy] from where the hand took hold)')
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
