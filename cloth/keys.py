"""Every scene key, declared once: the parser checks it by this, its messages word its range,
the page's fields, captions and compare editor take their label, unit and range from it.
The settings know nothing of the physics: the solvers' code registers against the names here
(cloth/solvers.py), not the other way round."""

from cloth.fabrics import fabric, DEFAULT_FABRIC, TEAR_LENGTH

# The solvers a scene may name, with their label and their own budget: substeps, iterations
# (sweeps a step) and coarse-grid corrections a step (only the default has any). Each one's
# code is a line of cloth/solvers.py's REGISTRY, in this order.
SOLVER_TABLE = [
    # The seed's own setting: 20 relaxations a frame.
    ['jakobsen', 'Jakobsen (the seed\'s method)', [1, 20, 0]],
    # Five sweeps and one correction a step (the speed-against-error front: docs/benchmark.md).
    ['vbd', 'Vertex descent + multigrid', [1, 5, 1]],
    # XPBD's own way: many small steps of one sweep each.
    ['xpbd', 'XPBD (small steps)', [16, 1, 0]],
]
SOLVERS = [s[0] for s in SOLVER_TABLE]
SOLVER_LABELS = [s[1] for s in SOLVER_TABLE]
SOLVER_BUDGETS = [s[2] for s in SOLVER_TABLE]
DEFAULT_SOLVER = 'vbd'
SEED_SOLVER = 'jakobsen'

# Limits. A grid larger than MAX_VERTICES would need hundreds of MB of state (and would not
# run in real time anyway); the other bounds keep every parameter physically meaningful.
MAX_VERTICES = 1000000
MAX_SUBSTEPS = 1000
MAX_ITERATIONS = 10000
MAX_CORRECTIONS = 100
MAX_FRAMES = 10000000
MAX_ACTIONS = 100000
MIN_DT = 1e-6
# A scene nests 4 deep (scene, actions, an action, its `to`); deeper is not a scene.
MAX_DEPTH = 32
MAX_TEAR = 1e6
MAX_STRENGTH = 1e7
MAX_PANELS = 4
# Obstacles: at most this many (each is a test per vertex per step), within OBSTACLE_FAR of
# the origin and at most OBSTACLE_SIZE across (metres). Shapes by index: OBSTACLE_SHAPES[i].
MAX_OBSTACLES = 16
OBSTACLE_FAR = 1e6
OBSTACLE_SIZE = 1e4
OBSTACLE_SHAPES = ['circle', 'box']
OPS = ['grab', 'move', 'release', 'pin', 'unpin', 'set', 'cut', 'obstacle', 'carry']
# Every scene that comes in (a link, a file opened or dropped, the Scene JSON box, the CLI) is
# refused past this many bytes of UTF-8 JSON, counted while it is read or inflated, before
# anything is parsed: the largest recording the page makes (MAX_ACTIONS actions) is about
# 6 MB, while a 270 kB link once inflated to a 200 MB name.
MAX_SCENE_BYTES = 16 * 1024 * 1024

# The model a scene is run under. 1: the grid of structural edges of the seed with the
# tethers, cells and line solves that held it (every scene made before the key existed);
# 2: the membrane (cloth/fabrics.py). Every scene runs under MODEL; an older one says so
# (scene.legacy_note), and a recording carries the model it was made under.
MODEL = 2
# The keys of model 1 that model 2 has no use for: accepted (a scene made then still opens)
# and left out of the physics. `compliance` (m/N) becomes the stretch stiffness 1 / compliance
# where the scene has no `stretch`; a boolean `shear` said whether cells had one diagonal,
# which every cell now has two of.
LEGACY_KEYS = ['tethers', 'cells', 'lines', 'tolerance', 'max_speed', 'compliance']

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
    ['strength', 'the fabric tears where its tension (N/m), averaged over ' + str(TEAR_LENGTH) +
     ' m across its yarns, passes this; empty: it does not tear', 0, []],
]


class Key:
    """One scene key. `words` words its range in messages; `label`, `unit`, `field_lo`,
    `field_hi` and `step` are the page's field (what a person types, within the core's own
    range); `live`: a `set` may change it on a running cloth; `panel`: a compare panel may have
    its own (2: shown at once in the editor, 1: under "more"). The default is `fallback`, or
    `by_solver[i]` for SOLVERS[i] where it differs per solver. Attributes avoid the names
    Transcrypt renames (name, default, type, ...)."""

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


def budget(which):
    """Each solver's own default of substeps (0), iterations (1) or corrections (2)."""
    return [SOLVER_BUDGETS[i][which] for i in range(len(SOLVERS))]


_FABRIC = fabric(DEFAULT_FABRIC)

# Every key a scene may have. The order is the one messages list them in.
#   key  kind  lo  hi  lo_open  words  label  unit  live  panel  default  per solver
#   page field lo, hi, step
KEYS = [
    Key('cols', 'int', 1, MAX_VERTICES, False, 'an integer from 1 to 1000000', 'Columns', '',
        False, 0, None, None, 1, 200, 1),
    Key('rows', 'int', 1, MAX_VERTICES, False, 'an integer from 1 to 1000000', 'Rows', '',
        False, 0, None, None, 1, 200, 1),
    Key('spacing', 'number', 1e-4, 1e4, False, 'from 0.0001 to 10000 metres', 'Spacing', 'm',
        False, 0, None, None, 1e-4, 1e4, 0.01),
    Key('pins', 'pins', 0, 0, False, '', 'Pins', '', False, 0, None, None, 0, 0, 0),
    Key('gravity', 'point', -1e5, 1e5, False, 'at most 1e5 m/s^2 per axis', 'Gravity',
        'm/s\u00b2', True, 0, [0.0, -9.81], None, -100, 100, 0.1),
    # Not down to 0: a step's h^2 must stay a normal double; a microsecond is far below any
    # frame.
    Key('dt', 'number', MIN_DT, 1.0, False, 'from 0.000001 to 1 seconds', 'Frame time', 's',
        True, 0, 1.0 / 60.0, None, MIN_DT, 1.0, 0.001),
    Key('substeps', 'int', 1, MAX_SUBSTEPS, False, 'an integer from 1 to 1000', 'Substeps', '',
        True, 2, None, budget(0), 1, 64, 1),
    Key('iterations', 'int', 0, MAX_ITERATIONS, False, 'an integer from 0 to 10000',
        'Iterations', '', True, 2, None, budget(1), 0, 200, 1),
    # The default solver's coarse-grid corrections a step (cloth/vbd.py); the others have none.
    Key('corrections', 'int', 0, MAX_CORRECTIONS, False, 'an integer from 0 to 100',
        'Corrections', '', True, 1, None, budget(2), 0, 10, 1),
    Key('damping', 'number', 0.0, 1000.0, False, 'from 0 to 1000 per second', 'Damping', '1/s',
        True, 2, 0.0, None, 0, 100, 0.1),
    Key('solver', 'choice', 0, 0, False, '', 'Solver', '', True, 2, DEFAULT_SOLVER, None, 0, 0, 0),
    Key('actions', 'actions', 0, 0, False, '', 'Actions', '', False, 0, None, None, 0, 0, 0),
    # The fabric (cloth/fabrics.py): its three numbers, the default fabric's unless given.
    Key('stretch', 'number', 1.0, 1e6, False, 'from 1 to 1000000 N/m (the stretch stiffness)',
        'Stretch', 'N/m', True, 1, _FABRIC[2], None, 10, 1e5, 10),
    Key('shear', 'number', 0.0, 1e6, False, 'from 0 to 1000000 N/m (the shear stiffness)',
        'Shear', 'N/m', True, 1, _FABRIC[3], None, 0, 1e5, 1),
    Key('density', 'number', 0.0, 1e4, True, 'in (0, 10000] kg/m^2 (the cloth\'s mass per area)',
        'Density', 'kg/m\u00b2', True, 1, _FABRIC[4], None, 0.001, 100, 0.01),
    Key('sleep', 'bool', 0, 0, False, '', 'Sleep', '', True, 1, True, None, 0, 0, 0),
    Key('name', 'string', 0, 0, False, '', 'Name', '', False, 0, None, None, 0, 0, 0),
    Key('frames', 'int', 0, MAX_FRAMES, False,
        'an integer from 0 to 10000000 (the frames the scene was recorded for)', 'Frames', '',
        False, 0, -1, None, 0, 0, 0),
    Key('compare', 'compare', 0, 0, False, '', 'Compare', '', False, 0, None, None, 0, 0, 0),
    # The fabric's strength: the tension (N/m) at which its yarns break (cloth/tear.py); null
    # or omitted: it does not tear (0 in a Scene). The page's field takes empty, `off` or 0
    # for none.
    Key('strength', 'number', 0.0, MAX_STRENGTH, True,
        'a tension greater than 0 N/m (the fabric tears where its tension, averaged over ' +
        str(TEAR_LENGTH) + ' m across its yarns, passes it), or null for a cloth that does not '
        'tear', 'Strength', 'N/m', True, 1, 0.0, None, 1, 1e6, 1),
    # A scene made before `strength` gave the strain its springs broke at: read as the strength
    # of the stretch stiffness times it (ALIASES).
    Key('tear', 'number', 0.0, MAX_TEAR, True,
        'a strain greater than 0 (the strength of the stretch stiffness times it, where the scene '
        'gives no strength), or null for no tearing', 'Tear', 'strain', True, 0, 0.0, None,
        0.01, 100, 0.01),
    # The air: its velocity (m/s) and how hard it pushes on the cloth across an edge (drag:
    # N s/m^3, per area and m/s of air across it, so the same on every grid). Gusts scale the
    # wind by 1 + amplitude * a smooth periodic wave of the period.
    Key('wind', 'point', -1e3, 1e3, False, 'at most 1000 m/s per axis', 'Wind', 'm/s', True, 0,
        [0.0, 0.0], None, -50, 50, 0.5),
    Key('drag', 'number', 0.0, 1e3, False, 'from 0 to 1000 N s/m^3 (the air\'s push across an '
        'edge, per square metre of cloth and m/s of air)', 'Drag', 'N\u00b7s/m\u00b3', True, 1, 0.1,
        None, 0, 100, 0.01),
    Key('gust', 'gust', 0.0, 10.0, False, 'an amplitude from 0 to 10 (and a period from 0.01 to 3600 s)',
        'Gusts', '', True, 0, [0.0, 1.0], None, 0, 10, 0.1),
    # Rigid shapes the cloth's free vertices stay out of: {"circle": [x, y, r]} or
    # {"box": [x0, y0, x1, y1]}, each with an optional friction (0 to 1).
    Key('obstacles', 'obstacles', 0, 0, False, '', 'Obstacles', '', False, 0, None, None,
        0, 0, 0),
    Key('model', 'int', 1, MODEL, False, 'an integer from 1 to ' + str(MODEL) +
        ' (the model the scene was made under)', 'Model', '', False, 0, 1, None, 0, 0, 0),
]


def spec(key):
    """The Key declared for `key` (None for a key the schema does not have)."""
    for i in range(len(KEYS)):
        if KEYS[i].key == key:
            return KEYS[i]
    return None


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
# (cols, rows, spacing, pins) and what is not physics (actions, frames, name, model).
SETTABLE = keys_where('live')
# What the settings of a `set` are merged into: the scene's own keys but these.
NOT_SETTINGS = ['actions', 'pins', 'frames', 'name', 'compare', 'obstacles']
# `compare`: 2 to MAX_PANELS panels that run the scene side by side under the same hands, each
# with some of these keys of its own.
COMPARE_KEYS = keys_where('panel')
# Keys an older scene may still give in place of another (their Key says how each is read):
# accepted wherever that one is.
ALIASES = [['tear', 'strength']]


def solver_index(name):
    for i in range(len(SOLVERS)):
        if SOLVERS[i] == name:
            return i
    return -1
