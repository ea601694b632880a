"""Exact references for the tests and the benchmark (CPython only; never transpiled).

The exact statics of a scene: `python -m cloth.reference SCENE.json` prints where its cloth
comes to rest (the fixed vertices where the scene's script leaves them) and its strain field.
It is Newton's method on the same energy the solvers minimise (cloth/vbd.py), without the
inertia: E(x) = sum_e k_e / 2 (L_e - L0_e)_+^2 - sum_i m_i g . x_i over the free vertices,
with a sparse direct solve a step, a Levenberg-Marquardt term mu M (large while the cloth is far
from rest, shrinking as the steps succeed), and an Armijo line search on E. E is convex, and
every edge that pulls at the minimum has one length there (a convex sum that is constant along a
segment has every term affine on it, and a pulling spring's energy is strictly convex in its
length), so the strain field is unique even where a slack region leaves the positions free.
numpy and scipy are fine here: the core never imports this module.

Also the closed forms the tests hold the physics to: a pendulum's period, a chain's discrete
equilibrium, a column leaning in a steady wind.
"""
import json
import math
import sys

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from cloth.api import load
from cloth.scene import parse_scene
from cloth.presets import preset_scene
from cloth.hands import CLAMP


# ---- the exact statics of the membrane --------------------------------------------------------


def net_of(cloth):
    """The cloth's springs and masses as numpy arrays: (a, b, rest, stiff, mass, fixed)."""
    m = cloth.n_edges
    a = np.array(cloth.edge_a[:m], dtype=np.int64)
    b = np.array(cloth.edge_b[:m], dtype=np.int64)
    rest = np.array(cloth.rest[:m], dtype=float)
    stiff = np.array(cloth.stiff[:m], dtype=float)
    mass = np.array(cloth.mass, dtype=float)
    fixed = np.array(cloth.fixed, dtype=bool)
    return a, b, rest, stiff, mass, fixed


def _energy(x, a, b, rest, k, mass, g):
    d = x[b] - x[a]
    L = np.sqrt((d * d).sum(1))
    s = np.maximum(L - rest, 0.0)
    E = 0.5 * (k * s * s).sum() - (mass[:, None] * g[None, :] * x).sum()
    f = (k * s / np.where(L > 0, L, 1.0))[:, None] * d
    grad = np.zeros_like(x)
    np.add.at(grad, a, -f)
    np.add.at(grad, b, f)
    grad -= mass[:, None] * g[None, :]
    return E, grad, d, L


def _hessian(n, a, b, rest, k, d, L):
    safe = np.where(L > 0, L, 1.0)
    nx = d[:, 0] / safe
    ny = d[:, 1] / safe
    taut = L > rest
    t = np.where(taut, 1.0 - rest / safe, 0.0)
    ka = np.where(taut, k, 0.0)
    kt = k * t
    kxx = ka * nx * nx + kt * (1 - nx * nx)
    kxy = ka * nx * ny - kt * nx * ny
    kyy = ka * ny * ny + kt * (1 - ny * ny)
    rows, cols, vals = [], [], []
    for (p, q, sign) in ((a, a, 1), (b, b, 1), (a, b, -1), (b, a, -1)):
        for (i, j, v) in ((0, 0, kxx), (0, 1, kxy), (1, 0, kxy), (1, 1, kyy)):
            rows.append(2 * p + i)
            cols.append(2 * q + j)
            vals.append(sign * v)
    return sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(2 * n, 2 * n)).tocsc()


def statics(cloth, start=None, tol=1e-9, max_iter=2000):
    """The cloth's equilibrium from `start` (n x 2; its positions if None), its fixed vertices
    where they are. Returns (positions n x 2, {'iterations', 'residual'}), the residual the
    largest unbalanced force over the largest vertex weight."""
    a, b, rest, k, mass, fixed = net_of(cloth)
    x = np.array(cloth.pos, dtype=float).reshape(-1, 2) if start is None else \
        np.array(start, dtype=float).copy()
    pos = np.array(cloth.pos, dtype=float).reshape(-1, 2)
    x[fixed] = pos[fixed]
    n = len(x)
    g = np.array([cloth.gravity_x, cloth.gravity_y])
    idx = np.nonzero(np.repeat(~fixed, 2))[0]
    load_ = mass.max() * max(np.linalg.norm(g), 1e-300)
    mvec = np.repeat(mass, 2)[idx]
    mu = 1e3 * k.max() / mass.max()
    E, grad, d, L = _energy(x, a, b, rest, k, mass, g)
    it = 0
    for it in range(max_iter):
        gf = grad.reshape(-1)[idx]
        worst = np.abs(gf).max() / load_ if len(gf) else 0.0
        if worst < tol:
            break
        H = _hessian(n, a, b, rest, k, d, L)[idx][:, idx]
        step = spla.spsolve((H + sp.diags(mu * mvec)).tocsc(), -gf)
        alpha = 1.0
        ok = False
        for _ in range(40):
            xt = x.copy()
            xt.reshape(-1)[idx] += alpha * step
            Et, gt, dt, Lt = _energy(xt, a, b, rest, k, mass, g)
            # Near the answer E changes below its rounding: take a step that shrinks the force.
            if Et <= E + 1e-4 * alpha * gf.dot(step) or (
                    abs(Et - E) <= 1e-13 * abs(E) and
                    np.abs(gt.reshape(-1)[idx]).max() < np.abs(gf).max()):
                ok = True
                break
            alpha *= 0.5
        if ok:
            x, E, grad, d, L = xt, Et, gt, dt, Lt
            if alpha == 1.0:
                mu = max(mu * 0.3, 1e-12)
        else:
            mu *= 10.0
    gf = grad.reshape(-1)[idx]
    return x, {'iterations': it, 'residual': float(np.abs(gf).max() / load_) if len(gf) else 0.0}


def tension_strain(cloth, x):
    """The tension strain max(0, L / L0 - 1) of each structural edge at positions x (n x 2)."""
    m = cloth.n_struct
    a = np.array(cloth.edge_a[:m])
    b = np.array(cloth.edge_b[:m])
    rest = np.array(cloth.rest[:m])
    d = x[b] - x[a]
    return np.maximum(np.sqrt((d * d).sum(1)) / rest - 1.0, 0.0)


def away_from_fixed(cloth, x, distance):
    """Which structural edges have their midpoint farther than `distance` from every fixed
    vertex (the field near a clamp's end has a corner singularity, like any 2D continuum)."""
    m = cloth.n_struct
    a = np.array(cloth.edge_a[:m])
    b = np.array(cloth.edge_b[:m])
    mid = 0.5 * (x[a] + x[b])
    fixed = x[np.array(cloth.fixed, dtype=bool)]
    if len(fixed) == 0:
        return np.ones(m, dtype=bool)
    best = np.full(m, np.inf)
    for p in fixed:
        best = np.minimum(best, np.sqrt(((mid - p) ** 2).sum(1)))
    return best > distance


def field_error(strain, exact, mask):
    """RMS over the masked edges of (strain - exact), relative to the exact field's RMS."""
    ref = math.sqrt(float((exact[mask] ** 2).mean()))
    return math.sqrt(float(((strain - exact)[mask] ** 2).mean())) / ref if ref > 0 else 0.0


def at_rest_of(text):
    """The scene's cloth with its script's holds, pins and carries applied where they leave
    the fixed vertices, without stepping: the fixed set and where it ends, and a first guess
    for the free vertices (the rest grid stretched or squeezed to span the fixed ones)."""
    cloth = load(text)
    scene = cloth.scene
    pos = np.array(cloth.pos, dtype=float).reshape(-1, 2)
    pinned = np.array(cloth.pinned, dtype=bool)
    hands = {}
    for act in scene.actions:
        k = act.vertex
        if act.op == 'grab':
            hands[k] = [pos[k].copy(), np.array([act.to_x, act.to_y]) if act.has_to else pos[k].copy()]
        elif act.op == 'move' and k in hands:
            hands[k][1] = np.array([act.to_x, act.to_y]) if not act.by else \
                hands[k][0] + np.array([act.to_x, act.to_y])
        elif act.op == 'release' and k in hands:
            grip = np.sqrt(((pos - pos[k]) ** 2).sum(1)) <= CLAMP * (1 + 1e-9)
            moved = grip & pinned if pinned[k] else np.zeros(len(pos), dtype=bool)
            pos[moved] += hands[k][1] - hands[k][0]
            del hands[k]
        elif act.op == 'pin':
            pinned[k] = True
        elif act.op == 'unpin':
            pinned[k] = False
    rest = np.array(cloth.pos, dtype=float).reshape(-1, 2)
    if pinned.sum() >= 2:
        w0 = np.ptp(rest[pinned][:, 0])
        w1 = np.ptp(pos[pinned][:, 0])
        if w0 > 0:
            x0 = rest[pinned][:, 0].min()
            guess = rest.copy()
            guess[:, 0] = pos[pinned][:, 0].min() + (rest[:, 0] - x0) * (w1 / w0)
            guess[pinned] = pos[pinned]
            pos = guess
    for i in range(cloth.n_verts):
        cloth.pinned[i] = 1 if pinned[i] else 0
        cloth.fixed[i] = 1 if pinned[i] else 0
        cloth.pos[i + i] = float(pos[i, 0])
        cloth.pos[i + i + 1] = float(pos[i, 1])
    return cloth


def exact_rest(text):
    """(cloth, positions, info): the scene's exact statics from at_rest_of's guess."""
    cloth = at_rest_of(text)
    x, info = statics(cloth)
    return cloth, x, info


def preset_rest(name, n, stretch=None, shear=None, density=None):
    """The exact statics of preset `name` on an n x n grid (a fabric's numbers may be given)."""
    obj = preset_scene(name, n, n)
    for key, v in (('stretch', stretch), ('shear', shear), ('density', density)):
        if v is not None:
            obj[key] = v
    return exact_rest(json.dumps(obj))


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        sys.stderr.write('usage: python -m cloth.reference SCENE.json\n')
        return 2
    with open(argv[0], encoding='utf-8') as f:
        text = f.read()
    parse_scene(text)
    cloth, x, info = exact_rest(text)
    strain = tension_strain(cloth, x)
    sys.stdout.write(json.dumps({'positions': x.tolist(), 'strain': strain.tolist(),
                                 'iterations': info['iterations'], 'residual': info['residual'],
                                 'max_strain': float(strain.max()) if len(strain) else 0.0,
                                 'rms_strain': float(math.sqrt((strain ** 2).mean())) if len(strain) else 0.0}) + '\n')
    return 0


# ---- closed forms ----------------------------------------------------------------------------


def elliptic_k(m):
    """Complete elliptic integral of the first kind K(m), m = k^2, by the AGM."""
    a, b = 1.0, math.sqrt(1.0 - m)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def pendulum_period(length, amplitude, g=9.81):
    """Exact period of a point pendulum released from rest `amplitude` radians from the
    vertical: T = 4 sqrt(L / g) K(sin^2(amplitude / 2))."""
    return 4 * math.sqrt(length / g) * elliptic_k(math.sin(amplitude / 2) ** 2)


def wind_column(rows, spacing, density, drag, wind, gravity=9.81):
    """Exact equilibrium of one column of `rows` vertices (rigid links of `spacing`, vertex 0
    fixed at the origin, each vertex density * spacing^2 kg but the last, half that) in a
    horizontal wind `wind` m/s with drag `drag` (cloth/air.py: a link at angle theta from the
    vertical is pushed along its normal by drag * spacing^2 * wind * cos theta, half on each
    end): [(x, y)] of the vertices. Each link points along the total load below it; found by
    fixed-point iteration on the angles."""
    n = rows - 1
    masses = [density * spacing * spacing] * (n + 1)
    masses[n] *= 0.5
    theta = [wind_lean(drag, wind, density, gravity)] * n
    for _ in range(10000):
        fx = [0.0] * (n + 1)
        fy = [-masses[v] * gravity for v in range(n + 1)]
        for j in range(n):
            f = drag * spacing * spacing * wind * math.cos(theta[j])
            for v in (j, j + 1):
                fx[v] += 0.5 * f * math.cos(theta[j])
                fy[v] += 0.5 * f * math.sin(theta[j])
        new = []
        px = py = 0.0
        for j in range(n - 1, -1, -1):
            px += fx[j + 1]
            py += fy[j + 1]
            new.append(math.atan2(px, -py))
        new.reverse()
        moved = max(abs(a - b) for a, b in zip(new, theta)) if n else 0.0
        theta = new
        if moved < 1e-15:
            break
    out = [(0.0, 0.0)]
    for j in range(n):
        x, y = out[-1]
        out.append((x + spacing * math.sin(theta[j]), y - spacing * math.cos(theta[j])))
    return out


def wind_lean(drag, wind, density, gravity=9.81):
    """The angle from the vertical of a long column in a horizontal wind: the normal push
    drag * wind * cos theta per area balances the weight's part across it, density g sin theta:
    tan theta = drag wind / (density g)."""
    return math.atan(drag * wind / (density * gravity))


if __name__ == '__main__':
    sys.exit(main())
