"""The air (issue #24.2): `wind`, `drag` and `gust`. Against the exact lean of a column in a
steady wind (cloth/reference.py wind_column: rigid links, which a stiff fabric stands in for),
a curtain whose steady deflection grows with the wind, a free cloth that the air carries up to
its speed and never past it, still air that changes nothing, gusts that replay exactly and
keep the cloth awake, and bad keys refused.
The page's side: tests/browser/test_parity.py (wind scenes bit for bit)."""
import json
import math

import pytest

from cloth.api import apply_due, load, run
from cloth.air import begin as air_stage
from cloth.keys import MODEL
from cloth.reference import wind_column, wind_lean
from cloth.values import SceneError
from cloth.step import frame


def positions(scene, frames):
    return json.loads(run(json.dumps(scene), frames))['positions']


def column(rows, wind, **keys):
    s = {'model': MODEL, 'cols': 1, 'rows': rows, 'spacing': 1.0 / (rows - 1), 'pins': [0],
         'density': 0.2, 'wind': [wind, 0], 'drag': 0.1, 'damping': 1}
    s.update(keys)
    return s


def worst(got, ref):
    return max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(got, ref))


@pytest.mark.parametrize('rows,wind', [(10, 20.0), (20, 10.0)])
def test_the_seeds_rigid_column_leans_as_the_exact_equilibrium(rows, wind):
    """The seed's method holds every link at its length, as the reference does. Converged
    (100 sweeps a step), what is left is the seed's weights': it relaxes its links as if every
    vertex weighed the same, the air (a compliant constraint of its sweeps: air.project) by
    the vertices' inertia, and the two agree as the frame time shrinks (measured: 2.3e-3 and
    1.1e-3 of the column's 1 m at 10 rows, 3.8e-3 and 1.3e-3 at 20; felt once a frame as an
    impulse, 7e-3 and 3.6e-3)."""
    ref = wind_column(rows, 1.0 / (rows - 1), 0.2, 0.1, wind)
    errors = []
    for dt in (1.0 / 60.0, 1.0 / 120.0):
        s = column(rows, wind, solver='jakobsen', iterations=100, sleep=False, dt=dt)
        errors.append(worst(positions(s, round(20.0 / dt)), ref))
    assert errors[0] < 5e-3 and errors[1] < 0.55 * errors[0], errors


# The air is a term of the step under every solver (cloth/air.py), so the column leans as the
# exact equilibrium of the scene's drag.
@pytest.mark.parametrize('solver,rows,wind', [
    ('vbd', 10, 2.0), ('vbd', 20, 2.0), ('vbd', 10, 5.0),
    ('xpbd', 10, 2.0), ('xpbd', 20, 2.0), ('xpbd', 10, 5.0)])
def test_a_stiff_column_in_a_steady_wind_leans_as_the_exact_equilibrium(solver, rows, wind):
    """Denim's stretch (1e4 N/m) stands in for the reference's rigid links: its weight
    stretches the column by 1e-5 of its length. Within 0.25% of the column's length (the
    fabric's stretch); the column comes to rest."""
    ref = wind_column(rows, 1.0 / (rows - 1), 0.2, 0.1, wind)
    cloth = load(json.dumps(column(rows, wind, solver=solver, stretch=1e4)))
    for _ in range(1200):
        frame(cloth)
    got = [(cloth.pos[2 * k], cloth.pos[2 * k + 1]) for k in range(rows)]
    assert worst(got, ref) < 2.5e-3, worst(got, ref)
    assert cloth.asleep


def test_the_exact_column_leans_as_the_continuum_at_every_resolution():
    """The reference's column, its last vertex half a spacing's mass as the grid's strip end
    has it (step.set_masses), carries below each link a load whose weight and wind grow in
    the same proportion: every link leans at the continuum's angle, tan theta = drag wind /
    (density g), on every grid (to rounding)."""
    lean = wind_lean(0.1, 10.0, 0.2)
    for rows in (10, 40, 160):
        ref = wind_column(rows, 1.0 / (rows - 1), 0.2, 0.1, 10.0)
        angles = [math.atan2(ref[i + 1][0] - ref[i][0], ref[i][1] - ref[i + 1][1])
                  for i in range(rows - 1)]
        assert max(abs(a - lean) for a in angles) < 1e-12, rows


def curtain(wind, **keys):
    s = {'model': MODEL, 'cols': 6, 'rows': 5, 'spacing': 0.15, 'pins': list(range(6)),
         'density': 0.2, 'wind': [wind, 0], 'drag': 0.1, 'damping': 1}
    s.update(keys)
    return s


HEM = range(24, 30)


def hem_after(scene, frames):
    cloth = load(json.dumps(scene))
    for _ in range(frames):
        frame(cloth)
    return cloth, sum(cloth.pos[2 * k] for k in HEM) / 6 - 0.375


# The air is a term of the step (cloth/air.py): at the page's frame time every solver's curtain
# comes to rest in every wind here. Felt once a frame as an explicit impulse, it fluttered at
# 0.2-2 m/s after 20 s and never rested (only at dt = 1/240). XPBD's kept moving at 1.5-3 cm/s
# after 25 s while the border's edges caught the air of a whole spacing (the width of cloth they
# stand for is half of it).
@pytest.mark.parametrize('solver', ['vbd', 'xpbd', 'jakobsen'])
def test_a_curtains_steady_deflection_grows_with_the_wind_and_holds(solver):
    """A curtain in a steady wind comes to rest deflected, the more the stronger the wind, and
    a wind from the other side deflects it the other way by as much: to a millimetre (no
    solver is mirror-symmetric to the bit, its sweeps run in the grid's order; the seed's
    method measured 3e-6 m)."""
    hem = []
    for wind in (0.0, 2.0, 5.0, 10.0):
        cloth, x = hem_after(curtain(wind, solver=solver), 900)
        assert cloth.asleep, wind                       # steady: it came to rest in the wind
        hem.append(x)
    assert abs(hem[0]) < 1e-4 and hem[1] > 0.005 and hem[2] > 2 * hem[1] and hem[3] > hem[2] + 0.03, hem
    _, x = hem_after(curtain(-5.0, solver=solver), 900)
    assert abs(x + hem[2]) < 1e-3, x + hem[2]


# The air pushes a free cloth past its own speed, a little: 5.00006 m/s (drag 1) and 5.003 m/s
# (drag 1000, in its fourth frame) for a wind of 5 m/s under the default solver. Drag 1000 is
# BDF2's: a relaxation much faster than a step is not monotone under it (its characteristic
# roots are complex once the drag's rate times h' passes 3/4), where backward Euler's is. Drag 1
# is the edges': each pushes by its ends' mean velocity along its own normal, so the air's
# whole force is not a function of the centre's velocity alone, and a crumpling cloth's
# inner motion carries it 6e-5 m/s past (the energy in the air's frame only falls).
PAST_THE_AIR = pytest.mark.xfail(strict=True, reason=(
    'core bug: the air pushes a free cloth past its own speed by 6e-5 m/s (drag 1: each edge pushes '
    'along its normal by its ends\' mean velocity) and 3e-3 m/s (drag 1000: BDF2 is not monotone '
    'for a relaxation faster than its step)'))


@pytest.mark.parametrize('drag', [0.05, pytest.param(1.0, marks=PAST_THE_AIR),
                                  pytest.param(1000.0, marks=PAST_THE_AIR)])
def test_the_air_carries_a_free_cloth_up_to_its_speed_and_never_past_it(drag):
    """The centre of mass's velocity (the momentum over the mass) rises to the air's and
    never past it."""
    scene = {'model': MODEL, 'cols': 6, 'rows': 6, 'spacing': 0.1, 'pins': [], 'gravity': [0, 0],
             'density': 0.2, 'wind': [3.0, -4.0], 'drag': drag, 'damping': 0, 'sleep': False}
    cloth = load(json.dumps(scene))
    n = cloth.n_verts
    mass = sum(cloth.mass)
    fastest = 0.0
    for _ in range(600):
        frame(cloth)
        vx = sum(cloth.mass[k] * cloth.vel[2 * k] for k in range(n)) / mass
        vy = sum(cloth.mass[k] * cloth.vel[2 * k + 1] for k in range(n)) / mass
        fastest = max(fastest, math.hypot(vx, vy))
        assert math.isfinite(vx) and math.isfinite(vy)
    assert fastest <= 5.0 + 1e-9                       # the air's own speed, never passed
    if drag >= 1.0:
        assert abs(vx - 3.0) < 1e-3 and abs(vy + 4.0) < 1e-3


def test_still_air_changes_nothing_and_costs_nothing():
    base = curtain(0.0)
    del base['wind']
    # a drag with no wind, a zero wind, gusts of no wind: the same cloth to the bit
    for keys in ({'drag': 5.0}, {'wind': [0, 0]}, {'wind': [0, 0], 'gust': [2.0, 0.3]}):
        s = dict(base, **keys)
        assert positions(s, 120) == positions(base, 120), keys
        cloth = load(json.dumps(s))
        assert air_stage not in cloth.stages            # the air's stage is not even chosen


def test_gusts_replay_exactly_and_keep_the_cloth_awake():
    s = curtain(4.0, gust=[0.8, 0.5])
    assert positions(s, 150) == positions(s, 150)
    cloth = load(json.dumps(s))
    hem = []
    for f in range(400):
        frame(cloth)
        if f >= 200:
            hem.append(cloth.pos[2 * 27])
    assert not cloth.asleep
    assert max(hem) - min(hem) > 0.01                  # it swings with the gusts
    # (a steady wind lets it rest: test_a_curtains_steady_deflection_grows_with_the_wind_and_holds)


@pytest.mark.parametrize('keys,message', [
    ({'wind': 5}, 'wind: must be a list of two numbers'),
    ({'wind': [1e9, 0]}, 'wind: must be at most 1000 m/s per axis'),
    ({'drag': -1}, 'drag: must be from 0 to 1000'),
    ({'gust': [0.5]}, 'gust: must be a list [amplitude, period]'),
    ({'gust': [0.5, 0]}, 'gust: must be a period from 0.01 to 3600 s'),
    ({'gust': [11, 1]}, 'gust: must be an amplitude from 0 to 10'),
])
def test_bad_air_keys_are_refused_with_their_words(keys, message):
    with pytest.raises(SceneError) as err:
        load(json.dumps(dict(curtain(1.0), **keys)))
    assert message in str(err.value)


def test_the_wind_set_live_is_recorded_and_replayed():
    """A wind set at frame 10 and gusts from frame 60 (recorded actions) replay to the bit and
    blow the hem downwind: its mean x over the frames after the wind is set lies well past
    the still curtain's."""
    s = curtain(0.0, actions=[{'frame': 10, 'op': 'set', 'scene': {'wind': [6, 0]}},
                              {'frame': 60, 'op': 'set', 'scene': {'gust': [1.0, 0.4], 'drag': 0.3}}])
    assert positions(s, 100) == positions(s, 100)
    blown, still = load(json.dumps(s)), load(json.dumps(curtain(0.0)))
    mean_blown = mean_still = 0.0
    due = apply_due(blown, 0, 0)
    for f in range(1, 101):
        frame(blown)
        frame(still)
        due = apply_due(blown, due, f)
        if f > 20:
            mean_blown += blown.pos[2 * 27] / 80
            mean_still += still.pos[2 * 27] / 80
    assert mean_blown > mean_still + 0.02, (mean_blown, mean_still)


@pytest.mark.parametrize('cols', [4, 8, 16, 32])
def test_the_airs_push_on_a_sheet_is_its_area_on_every_grid(cols):
    """The air pushes each edge's strip of cloth, a spacing wide inside and half of it on the
    border, as the cloth's mass and stretch are: the whole push on a still sheet is drag x wind
    x its area on every grid. (With a whole spacing on the border too, a grid's border caught
    1 / (cols - 1) more of it: 33% at 4 columns, 3% at 32; the Flag's free corner hung 0.2 m
    higher at 45x30 than at 200x133.)"""
    side, drag, wind = 1.0, 0.05, 4.0
    scene = {'model': MODEL, 'cols': cols, 'rows': cols, 'spacing': side / (cols - 1), 'pins': [],
             'gravity': [0, 0], 'density': 0.2, 'wind': [wind, 0], 'drag': drag, 'damping': 0,
             'sleep': False}
    cloth = load(json.dumps(scene))

    def momentum():
        return [sum(cloth.mass[k] * cloth.vel[2 * k + t] for k in range(cloth.n_verts)) for t in (0, 1)]
    for _ in range(12):                # BDF2's start from rest decays by a third a step
        frame(cloth)
    before = momentum()
    frame(cloth)
    after = momentum()
    px, py = after[0] - before[0], after[1] - before[1]
    # The frame's impulse over its time against drag x the wind relative to the sheet (its
    # mean velocity over the frame) x its area.
    relative = wind - 0.5 * (before[0] + after[0]) / sum(cloth.mass)
    push = px / cloth.dt
    assert abs(push / (drag * relative * side * side) - 1) < 0.005, push
    assert abs(py) < 1e-4 * abs(px)        # across: only as the sheet deforms
