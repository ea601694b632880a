"""Stable under abuse (CPython): the hard cases, and fuzzing with random scenes and actions."""

import json
import math

import pytest
from hypothesis import given, settings, strategies as st

from cloth.api import load, run
from cloth.keys import MODEL
from cloth.script import apply_action
from cloth.values import SceneError
from cloth.step import frame
from cloth.measure import measure, energies

from hard_cases import HARD, BOUNDED


def hand_energy(cloth):
    """The energy stored in the hands' springs (cloth/hands.py: a Huber spring to each gripped
    vertex's aim, stiffness grip_k, its pull capped at grip_f)."""
    total = 0.0
    for h in range(cloth.n_gripped):
        v = cloth.gripped[h]
        d = math.hypot(cloth.aim[2 * v] - cloth.pos[2 * v], cloth.aim[2 * v + 1] - cloth.pos[2 * v + 1])
        k, f = cloth.grip_k[v], cloth.grip_f[v]
        total += 0.5 * k * d * d if k * d <= f else f * d - 0.5 * f * f / k
    return total


def energy(cloth, before):
    """(the cloth's energy in its solver's own model, the sum of its parts' magnitudes), J.
    The membrane (vbd, xpbd): kinetic + elastic + gravitational (measure.energies) + the
    hands' springs. The seed's method holds its edges rigid (what its unfinished sweeps leave
    of a stretch is error, not stored energy): kinetic, from the frame's motion (its Verlet
    velocity of a vertex at rest on a support is g h / 2, not 0), + gravitational. The
    magnitudes are the scale of the total's rounding (a free fall's total is 0 up to the
    rounding of two large parts)."""
    if not cloth.seed:
        parts = energies(cloth) + [hand_energy(cloth)]
        return sum(parts), sum(abs(p) for p in parts)
    kinetic = 0.0
    gravity = 0.0
    for k in range(cloth.n_verts):
        if cloth.fixed[k]:
            continue
        m = cloth.mass[k]
        vx = (cloth.pos[2 * k] - before[2 * k]) / cloth.dt
        vy = (cloth.pos[2 * k + 1] - before[2 * k + 1]) / cloth.dt
        kinetic += 0.5 * m * (vx * vx + vy * vy)
        gravity -= m * (cloth.gravity_x * cloth.pos[2 * k] + cloth.gravity_y * cloth.pos[2 * k + 1])
    return kinetic + gravity, kinetic + abs(gravity)


def no_gain(name, energy_after):
    """After its last action nothing drives the cloth (a hand held still does no work): its
    energy may only fall, up to the integrator's small fluctuation, bounded by a fraction of
    the energy it has (and the rounding of its parts)."""
    totals = [e[0] for e in energy_after]
    allowed = 0.05 * max(abs(e) for e in totals) + 1e-12 * max(e[1] for e in energy_after)
    peak = max(totals[1:]) if len(totals) > 1 else totals[0]
    assert peak <= totals[0] + allowed, (name, totals[0], peak, allowed)


def motion(cloth, before):
    """The fastest a vertex moved over the last frame, m/s."""
    return max(math.hypot(cloth.pos[2 * k] - before[2 * k], cloth.pos[2 * k + 1] - before[2 * k + 1])
               for k in range(cloth.n_verts)) / cloth.dt


def play(scene, frames, on_frame, before_frame=None):
    """cloth.api.simulate, with hooks before (after that frame's actions) and after a frame;
    on_frame(f, cloth, positions before the frame)."""
    cloth = load(json.dumps(scene)) if isinstance(scene, dict) else scene
    actions = cloth.scene.actions
    nxt = 0
    for f in range(frames):
        while nxt < len(actions) and actions[nxt].frame <= f:
            apply_action(cloth, actions[nxt])
            nxt += 1
        if before_frame:
            before_frame(f, cloth)
        before = list(cloth.pos)
        frame(cloth)
        on_frame(f, cloth, before)
    return cloth


def core_bug(reason):
    return pytest.mark.xfail(strict=True, reason='core bug: ' + reason)


# XPBD steps by position Verlet (cloth/integrate.py ORDER 0), its velocity whatever the
# unfinished solve left: with one sweep and one substep, or a stiff or very soft fabric, it
# gains energy (measured: the damped 8x8 two-corner hang -0.95 J -> +6.1 J peak; stiff
# -0.97 -> -0.61 J; soft, one substep, -0.98 -> -0.66 J).
XPBD_GAINS = core_bug('XPBD gains energy when its solve is unfinished (one sweep and one substep, '
                      'or a stiff or very soft fabric): nothing measures its imbalance')
# The default solver with one sweep a step on an undamped cloth gained energy: the 10x10 hung
# from one corner went from -0.98 J to +63 J (peak) with no coarse correction, and to -0.63 J
# with it, its steps backward Euler while its imbalance stayed past integrate.UNBALANCED. Such
# a step, solved exactly, raises no energy, and a piece whose unfinished one did gives the gain
# back from its motion (cloth/energy.py): both cases now pass as every other hard case.
XFAIL = {
    'xpbd-one-substep-one-sweep': XPBD_GAINS,
    'soft-xpbd-one-substep': XPBD_GAINS,
    'stiff-xpbd': XPBD_GAINS,
    'xpbd-undamped-one-sweep-one-substep': XPBD_GAINS,
    'xpbd-one-sweep-20x20-undamped-one-corner': core_bug(
        'XPBD with one sweep and one substep on an undamped 20x20 cloth blows up (1e84 m/s '
        'after 300 frames; the max_speed net that held it is gone)'),
}


def case(name):
    return pytest.param(name, marks=XFAIL[name]) if name in XFAIL else name


@pytest.mark.parametrize('name', [case(name) for name in sorted(HARD)])
def test_hard_case(name):
    scene, frames, last_action = HARD[name]
    energy_after = []
    speeds = []

    def check(f, cloth, before):
        assert all(math.isfinite(v) for v in cloth.pos), (name, f)
        if last_action is not None and f > last_action + 1:
            energy_after.append(energy(cloth, before))
        speeds.append(motion(cloth, before))

    cloth = play(scene, frames, check)
    measure(cloth)
    for v in [cloth.max_value, cloth.rms_strain, cloth.max_stress, cloth.max_strain]:
        assert math.isfinite(v)
    if energy_after:
        no_gain(name, energy_after)
        # A a damped one comes back to rest: no vertex moves a centimetre a second (a
        # hundred times that in a hundred times gravity: a sag scales with it).
        if scene.get('damping', 0) > 0:
            g = scene.get('gravity', [0, -9.81])
            assert speeds[-1] < 0.01 * max(1.0, math.hypot(*g) / 9.81), (name, speeds[-1])


@pytest.mark.parametrize('name', [case(name) for name in sorted(BOUNDED)])
def test_an_undamped_cloth_with_one_sweep_stays_bounded(name):
    """What the old safety net (`max_speed`) held now holds by itself: undamped, one sweep a
    step, on a larger grid, the cloth stays finite and gains no energy."""
    scene, frames = BOUNDED[name]
    energy_after = []

    def check(f, cloth, before):
        assert all(math.isfinite(v) for v in cloth.pos), (name, f)
        energy_after.append(energy(cloth, before))

    play(scene, frames, check)
    no_gain(name, energy_after)


@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_fabric_with_no_shear_stiffness_runs(solver):
    """`shear` may be 0 (cloth/keys.py: from 0 N/m): the diagonals are then springs of no
    stiffness, which pull on nothing; the cloth still runs, finite, under every solver."""
    text = json.dumps({'model': MODEL, 'cols': 4, 'rows': 4, 'spacing': 0.1, 'pins': [0, 3],
                       'shear': 0.0, 'damping': 1.0, 'solver': solver})
    out = json.loads(run(text, 30))
    assert all(math.isfinite(v) for p in out['positions'] for v in p)


# ---- fuzzing ------------------------------------------------------------------------------

ANY = st.one_of(st.none(), st.booleans(), st.integers(-5, 5), st.floats(allow_nan=True),
                st.text(max_size=3), st.lists(st.integers(-2, 40), max_size=3))


@st.composite
def wild_scene(draw):
    """Mostly valid scenes, with any key sometimes replaced by garbage."""
    cols, rows = draw(st.integers(1, 6)), draw(st.integers(1, 6))
    n = cols * rows
    s = {'model': MODEL, 'cols': cols, 'rows': rows, 'spacing': draw(st.floats(0.01, 2.0)),
         'pins': draw(st.lists(st.integers(0, n - 1), max_size=4)),
         'solver': draw(st.sampled_from(['jakobsen', 'vbd', 'xpbd'])),
         'substeps': draw(st.integers(1, 4)), 'iterations': draw(st.integers(0, 10)),
         'corrections': draw(st.integers(0, 2)),
         'damping': draw(st.floats(0, 10)), 'dt': draw(st.sampled_from([1 / 60, 0.1, 1.0])),
         'gravity': [draw(st.floats(-100, 100)), draw(st.floats(-1000, 100))],
         'stretch': draw(st.sampled_from([1.0, 10.0, 500.0, 1e4, 1e6])),
         'shear': draw(st.sampled_from([0.0, 1.0, 50.0, 1e4])),
         'density': draw(st.sampled_from([0.01, 0.2, 10.0])),
         'sleep': draw(st.booleans())}
    ops = []
    for _ in range(draw(st.integers(0, 12))):
        a = {'frame': draw(st.integers(0, 20)),
             'op': draw(st.sampled_from(['grab', 'move', 'release', 'pin', 'unpin'])),
             'vertex': draw(st.integers(0, n - 1))}
        if draw(st.booleans()):
            a['to'] = [draw(st.floats(-50, 50)), draw(st.floats(-50, 50))]
        ops.append(a)
    s['actions'] = ops
    if draw(st.integers(0, 4)) == 0:
        s[draw(st.sampled_from(sorted(s)))] = draw(ANY)
    return s


@settings(max_examples=150, deadline=None)
@given(scene=wild_scene(), frames=st.integers(0, 25))
def test_fuzz_no_nan_pins_exact_only_validation_errors(scene, frames):
    try:
        cloth = load(json.dumps(scene))
    except SceneError as err:
        assert str(err).split(':')[0], err      # a one-line message naming a key
        return
    fixed_before = {}

    def check(f, cloth, before):
        for k in range(cloth.n_verts):
            if cloth.fixed[k] and k in fixed_before:
                assert (cloth.pos[2 * k], cloth.pos[2 * k + 1]) == fixed_before[k]
        assert all(math.isfinite(v) for v in cloth.pos)
        fixed_before.clear()

    def record(f, cloth):
        # Where every fixed vertex is after the actions of a frame, before the step.
        for k in range(cloth.n_verts):
            if cloth.fixed[k]:
                fixed_before[k] = (cloth.pos[2 * k], cloth.pos[2 * k + 1])

    play(cloth, frames, check, record)
    measure(cloth)
    values = [cloth.edge_value[e] for e in range(cloth.n_struct)] + list(cloth.stress)
    assert all(math.isfinite(v) for v in values)


@settings(max_examples=200, deadline=None)
@given(text=st.one_of(st.text(max_size=40), st.binary(max_size=40).map(lambda b: b.decode('latin-1')),
                      st.recursive(ANY, lambda c: st.lists(c, max_size=3) |
                                   st.dictionaries(st.sampled_from(['cols', 'rows', 'spacing', 'pins', 'actions',
                                                                    'model', 'x']), c, max_size=4),
                                   max_leaves=8).map(json.dumps)))
def test_fuzz_garbage_text_is_a_validation_error(text):
    try:
        out = json.loads(run(text, 2))
    except SceneError as err:
        assert '\n' not in str(err) and ':' in str(err)
        return
    assert all(math.isfinite(v) for p in out['positions'] for v in p)
