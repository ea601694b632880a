"""Disturbances for a settled cloth to recover from, shared by the CPython tests
(tests/test_shape.py) and the browser tests (tests/browser/test_shape_page.py).

Shape, not only strain: strain says the edges have their rest length, not that the cloth hangs
where the physics puts it. How a settled cloth hangs against the exact statics is
tests/test_shape.py's first test (cloth/reference.py); here, a disturbed cloth must come back
to the hang of the same cloth left alone.
"""
import json
import math

from cloth.keys import MODEL


def shape_error(positions, reference, width):
    """(RMS, max) distance between matching vertices, in units of `width`."""
    d2 = [(p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 for p, q in zip(positions, reference)]
    return math.sqrt(sum(d2) / len(d2)) / width, math.sqrt(max(d2)) / width


# Disturbances of a 10 x 8 cloth, 1 m wide, hung from its top corners (damping 1/s, as the
# presets): a vertex is grabbed after the cloth has hung for HANG frames (as a fixture, see
# gesture_actions), carried by (dx, dy) over `frames` frames in a straight line (1 frame:
# thrown), and let go. Afterwards the cloth
# must come back to its undisturbed hang.
COLS, ROWS = 10, 8
HANG = 120
SETTLE = 600
BOTTOM_LEFT = (ROWS - 1) * COLS
BOTTOM_MIDDLE = (ROWS - 1) * COLS + 4
BOTTOM_RIGHT = ROWS * COLS - 1
DISTURBANCES = {
    # name: (vertex, dx, dy, frames)
    'flick-up-1.4m': (BOTTOM_MIDDLE, 0.3, 1.35, 1),
    'flick-sideways-1.4m': (BOTTOM_LEFT, 1.4, 0.2, 1),
    'throw-over-the-pins': (BOTTOM_MIDDLE, 0.2, 1.6, 20),
    'corner-over-the-cloth': (BOTTOM_RIGHT, -1.2, 1.2, 5),
    'pull-far-down': (BOTTOM_MIDDLE, 0.0, -1.5, 30),
}


def hang_scene(**keys):
    scene = dict(model=MODEL, cols=COLS, rows=ROWS, spacing=1.0 / (COLS - 1), pins=[0, COLS - 1],
                 damping=1.0, sleep=False)
    scene.update(keys)
    return scene


def gesture_actions(vertex, path, start=HANG, fixture=False):
    """grab at frame `start`, then one move per point of `path` ([(x, y)] relative to where the
    vertex hangs, which the caller gives as the first point's base), then release. With
    `fixture` the vertex is pinned before the grab and unpinned after the release: a dragged
    pin goes exactly where the hand puts it, however fast (a free vertex's hand has a finite
    strength, cloth/hands.py HAND_FORCE), the most violent gesture a person can make."""
    end = start + 1 + len(path)
    actions = [{'frame': start, 'op': 'pin', 'vertex': vertex}] if fixture else []
    actions.append({'frame': start, 'op': 'grab', 'vertex': vertex})
    for i, (x, y) in enumerate(path):
        actions.append({'frame': start + 1 + i, 'op': 'move', 'vertex': vertex, 'to': [x, y]})
    actions.append({'frame': end, 'op': 'release', 'vertex': vertex})
    if fixture:
        actions.append({'frame': end, 'op': 'unpin', 'vertex': vertex})
    return actions


def straight_path(x0, y0, dx, dy, frames):
    return [(x0 + dx * f / frames, y0 + dy * f / frames) for f in range(1, frames + 1)]


def zigzag_path(x0, y0, amplitude, period, cycles):
    out = []
    for f in range(1, period * cycles + 1):
        phase = (f % period) / period
        tri = 4 * phase - 1 if phase < 0.5 else 3 - 4 * phase
        out.append((x0 + amplitude * tri, y0 + 0.3 * amplitude * math.sin(6 * math.pi * f / period)))
    return out


def recovery(positions, undisturbed, pins):
    """(RMS error in widths, max error, how many vertices are above the highest pin by more
    than ABOVE of the width)."""
    width = (COLS - 1) / (COLS - 1)
    rms, worst = shape_error(positions, undisturbed, width)
    top = max(positions[p][1] for p in pins)
    above = sum(1 for p in positions if p[1] > top + ABOVE * width)
    return rms, worst, above


# These scenes hang their top row taut (the pins a rest width apart): after a disturbance the
# top row may rest bowed up a little (a tension-only row between pins a rest length apart
# carries no force when bowed: it settles where the last motion left it, millimetres on the
# 1 m cloth); a row folded back over the pins stands about 10% of the width above them.
ABOVE = 0.01


def to_text(scene):
    return json.dumps(scene)
