"""Shared helpers for the CPython tests: scenes as data, and runs through the public API."""

import json
import math

from cloth.api import load, run
from cloth.keys import MODEL
from cloth.step import frame
from cloth.measure import measure, energies
from cloth.hands import grab, move, move_by, release, pin, unpin, toggle_pin
from cloth.presets import preset_scene


def scene(**keys):
    """Scene JSON text of the current model (pass model=1 for a scene made before it)."""
    keys.setdefault('model', MODEL)
    if keys['model'] is None:
        del keys['model']
    return json.dumps(keys)


def curtain(n, solver=None, **extra):
    """An n x n cloth 1 m wide hung from a rod: its whole top row pinned."""
    keys = dict(cols=n, rows=n, spacing=1.0 / (n - 1), pins=list(range(n)))
    if solver:
        keys['solver'] = solver
    keys.update(extra)
    return scene(**keys)


def preset(name, cols, rows=None, **extra):
    """Preset `name`'s scene JSON on a cols x rows grid, with `extra` keys written in."""
    obj = preset_scene(name, cols, cols if rows is None else rows)
    obj.update(extra)
    return json.dumps(obj)


def result(scene_text, frames):
    return json.loads(run(scene_text, frames))


def all_finite(values):
    return all(math.isfinite(v) for v in values)


def step(cloth, frames):
    for _ in range(frames):
        frame(cloth)
    return cloth


def xy(cloth, k):
    return cloth.pos[2 * k], cloth.pos[2 * k + 1]


def fastest(cloth):
    """The largest speed of a free vertex, m/s."""
    best = 0.0
    for k in range(cloth.n_verts):
        if cloth.fixed[k]:
            continue
        best = max(best, math.hypot(cloth.vel[2 * k], cloth.vel[2 * k + 1]))
    return best


def energy(cloth):
    """Kinetic + elastic + gravitational energy, J."""
    return sum(energies(cloth))


__all__ = ['scene', 'curtain', 'preset', 'result', 'all_finite', 'step', 'xy', 'load', 'frame',
           'measure', 'grab', 'move', 'move_by', 'release', 'pin', 'unpin', 'toggle_pin',
           'fastest', 'energy', 'energies']
