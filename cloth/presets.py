"""The presets: scenes as functions of the grid, the same for the page, the tests and the
benchmark.

Each preset is a cloth of a fixed size in metres, so a finer grid is the same cloth resolved
more finely (spacing = size / (the larger of cols - 1 and rows - 1)). Every one hangs from a
rod or from clamps of finite width (CLAMP of its edge held), never from single vertices: a point
load strains a 2D continuum as 1 / r, so the strain at a point pin grows with the grid whatever
the solver (cloth/fabrics.py), while a clamp's field converges. A person can still pin any
vertex. All start on their rest grid, in the default fabric (cloth/fabrics.py) and still air's
damping of 1/s (a released cloth comes to rest within seconds, as fabric does in air).
"""

import math

from cloth.fabrics import fabric, DEFAULT_FABRIC
from cloth.keys import MODEL, spec
from cloth.hands import CLAMP, HAND_RADIUS  # a hand on a clamp's end carries the whole clamp
from cloth.ccd import CONTACT_GAP

# Two corners: the right clamp is carried in to CORNER_SPAN of the width over CARRY_FRAMES
# (a smooth start and stop), so the cloth hangs slack, its top edge sagging. Carried, not put
# there at once: a clamp moved 0.3 m in one frame stretches the cloth by as much.
CORNER_SPAN = 0.8
CARRY_FRAMES = 60
# Towel on a peg: the peg, a bar this share of the towel's width and PEG_HEIGHT tall, whose
# underside holds the middle of the towel's top edge. (A towel hung from a point of its edge,
# in the plane, folds to a strip under that point: nothing out of the plane holds its sides
# apart, and a tension-only cloth crumples sideways at no cost.)
PEG = 0.6
PEG_HEIGHT = 0.04

#          name        label               cols rows size (m)
PRESETS = [['curtain', 'Curtain', 40, 30, 2.0],
           ['corners', 'Two corners', 30, 30, 1.6],
           ['towel', 'Towel on a peg', 30, 30, 1.0],
           ['chain', 'Chain', 40, 1, 1.6],
           ['large', 'Large cloth', 100, 100, 2.0],
           ['tearable', 'Tearable', 60, 40, 2.0],
           ['flag', 'Flag in the wind', 45, 30, 1.8]]
# Tearable is a sheet of this fabric, with its strength: a hand tears it (at about 17 N on
# every grid: python -m bench --tear), where no hand tears a woven fabric or a knit.
TEARABLE_FABRIC = 'tissue'


def preset(name):
    for i in range(len(PRESETS)):
        if PRESETS[i][0] == name:
            return PRESETS[i]
    return None


def spacing_of(name, cols, rows):
    cells = max(cols - 1, rows - 1, 1)
    return preset(name)[4] / cells


def top_row_within(cols, spacing, x0, x1):
    """The top-row vertices whose x is in [x0, x1] (a clamp); on a grid coarser than the clamp,
    the one nearest its middle."""
    out = []
    for c in range(cols):
        x = c * spacing
        if x >= x0 - 1e-9 * spacing and x <= x1 + 1e-9 * spacing:
            out.append(c)
    if len(out) == 0:
        c = int(math.floor(0.5 * (x0 + x1) / spacing + 0.5))
        out.append(min(max(c, 0), cols - 1))
    return out


def clamps(name, cols, rows, spacing):
    w = (cols - 1) * spacing
    if name == 'corners':
        left = top_row_within(cols, spacing, 0.0, CLAMP)
        right = top_row_within(cols, spacing, w - CLAMP, w)
        for i in range(len(right)):
            if right[i] not in left:
                left.append(right[i])
        return left
    if name == 'towel':
        return top_row_within(cols, spacing, 0.5 * w * (1.0 - PEG), 0.5 * w * (1.0 + PEG))
    if name == 'chain':
        # A strip one spacing wide has no point-load singularity: its clamp holds its end, a
        # hand's grip of it. (Held by 6 cm laid along it, the strip bends round the clamp's
        # end, and a 0.5 m pull let go gained 0.146 J at 120 columns: python -m bench
        # --releases.)
        return top_row_within(cols, spacing, 0.0, HAND_RADIUS)
    if name == 'flag':
        return [r * cols for r in range(rows)]
    return [c for c in range(cols)]       # a rod along the top


def preset_scene(name, cols, rows):
    """The scene of preset `name` on a cols x rows grid, as a JSON object."""
    p = preset(name)
    if p is None:
        return None
    h = spacing_of(name, cols, rows)
    f = fabric(DEFAULT_FABRIC)
    scene = {'model': MODEL, 'name': p[1], 'cols': cols, 'rows': rows, 'spacing': h,
             'pins': clamps(name, cols, rows, h), 'dt': spec('dt').fallback, 'damping': 1.0,
             'stretch': f[2], 'shear': f[3], 'density': f[4]}
    w = (cols - 1) * h
    if name == 'corners' and cols > 1:
        # The script carries the right clamp (kinematic: it is where the script says).
        k = cols - 1
        actions = []
        for t in range(1, CARRY_FRAMES + 1):
            s = smooth(t / CARRY_FRAMES)
            actions.append({'frame': t, 'op': 'carry', 'vertex': k,
                            'to': [w - (1.0 - CORNER_SPAN) * w * s, 0.0]})
        scene['actions'] = actions
    if name == 'towel':
        # A towel one vertex wide (cols 1) hangs from a peg PEG of a spacing wide.
        x0 = 0.5 * w * (1.0 - PEG) if w > 0.0 else -0.5 * PEG * h
        x1 = 0.5 * w * (1.0 + PEG) if w > 0.0 else 0.5 * PEG * h
        # The peg's underside a contact's reach above the clamped row, which it holds
        # (obstacles.fasten): the edges from the clamp touch it without a barrier's push.
        scene['obstacles'] = [{'box': [x0, CONTACT_GAP, x1, CONTACT_GAP + PEG_HEIGHT], 'friction': 0.5}]
    if name == 'tearable':
        t = fabric(TEARABLE_FABRIC)
        scene['stretch'] = t[2]
        scene['shear'] = t[3]
        scene['density'] = t[4]
        scene['strength'] = t[5]
    if name == 'flag':
        scene['wind'] = [10.0, 0.0]
        scene['drag'] = 0.4
        scene['gust'] = [0.5, 1.7]
    return scene


def smooth(t):
    """0 to 1 with zero velocity at both ends: 3 t^2 - 2 t^3 (a polynomial: the same bits in
    both runtimes, where a cosine might differ in the last place)."""
    return t * t * (3.0 - 2.0 * t)


def preset_view(name, cols, rows):
    """[x0, x1, y0, y1] the page frames the preset in, or [] for the page's own fit (the grid,
    room below it for the sag, and whatever the wind and obstacles need)."""
    h = spacing_of(name, cols, rows)
    w = (cols - 1) * h
    ht = (rows - 1) * h
    if name == 'chain':
        r = w + ht
        return [-1.1 * r, 1.1 * r, -1.2 * r, 0.15 * r]
    if name == 'towel':
        big = max(w, ht)
        return [-0.1 * big, w + 0.1 * big, -ht - 0.35 * big, 0.15 * big]
    if name == 'flag':
        return [-0.15 * w, 1.15 * w, -ht - 0.6 * w, 0.1 * w]
    if name == 'corners':
        big = max(w, ht)
        return [-0.08 * big, w + 0.08 * big, -ht - 0.68 * big, 0.08 * big]
    return []
