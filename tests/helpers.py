"""Shared helpers for the CPython tests: scenes as data, and runs through the public API."""

import json
import math

from cloth.api import load, run


def scene(**keys):
    return json.dumps(keys)


def curtain(n, solver=None, **extra):
    keys = dict(cols=n, rows=n, spacing=1.0 / (n - 1), pins=list(range(n)))
    if solver:
        keys['solver'] = solver
    keys.update(extra)
    return scene(**keys)


def result(scene_text, frames):
    return json.loads(run(scene_text, frames))


def all_finite(values):
    return all(math.isfinite(v) for v in values)


def step(cloth, frames):
    for _ in range(frames):
        cloth.frame()
    return cloth


def xy(cloth, k):
    return cloth.pos[2 * k], cloth.pos[2 * k + 1]



__all__ = ['scene', 'curtain', 'result', 'all_finite', 'step', 'xy', 'load']
