"""The air (issue #24.2): `wind`, `drag` and `gust`. Against the exact lean of a column in a
steady wind (cloth/reference.py wind_column), a curtain whose steady deflection grows with the
wind, a free cloth that the air carries up to its speed and never past it, still air that
changes nothing, gusts that replay exactly and keep the cloth awake, and bad keys refused.
The page's side: tests/browser/test_parity.py (wind scenes bit for bit)."""
import json
import math

import pytest

from cloth.api import load, run
from cloth.reference import wind_column, wind_lean
from cloth.scene import SceneError
from cloth.sim import frame


def positions(scene, frames):
    return json.loads(run(json.dumps(scene), frames))['positions']


def column(rows, wind, **keys):
    s = {'cols': 1, 'rows': rows, 'spacing': 1.0 / (rows - 1), 'pins': [0], 'density': 0.2,
         'wind': [wind, 0], 'drag': 0.1, 'damping': 1}
    s.update(keys)
    return s


@pytest.mark.parametrize('rows,wind', [(10, 20.0), (20, 10.0), (40, 2.0)])
def test_a_column_in_a_steady_wind_leans_as_the_exact_equilibrium(rows, wind):
    ref = wind_column(rows, 1.0 / (rows - 1), 0.2, 0.1, wind)
    got = positions(column(rows, wind), 600)
    # the default solver: within 0.25% of the column's length (its tethers, one-sided limits
    # projected toward the pin, bias a bent column by about a millimetre)
    assert max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(got, ref)) < 2.5e-3
    # Without them, to 7e-4 of it: the air is a frame's impulse (sim.feel_air), and what is
    # left is that splitting's, which halves with the frame time.
    errors = []
    for dt in (1.0 / 60.0, 1.0 / 120.0):
        got = positions(column(rows, wind, tethers=False, sleep=False, dt=dt), round(30.0 / dt))
        errors.append(max(math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in zip(got, ref)))
    assert errors[0] < 7e-4 and errors[1] < 0.55 * errors[0], errors


def test_the_exact_column_tends_to_the_continuums_lean():
    lean = wind_lean(0.1, 10.0, 0.2)
    errors = []
    for rows in (10, 40, 160):
        ref = wind_column(rows, 1.0 / (rows - 1), 0.2, 0.1, 10.0)
        errors.append(abs(math.atan2(ref[-1][0], -ref[-1][1]) - lean))
    assert errors[0] > errors[1] > errors[2] and errors[2] < 0.02 * lean


def curtain(wind, **keys):
    s = {'cols': 6, 'rows': 5, 'spacing': 0.15, 'pins': list(range(6)), 'density': 0.2,
         'compliance': 0.002, 'wind': [wind, 0], 'drag': 0.1, 'damping': 1}
    s.update(keys)
    return s


HEM = range(24, 30)


def test_a_curtains_steady_deflection_grows_with_the_wind_and_holds():
    hem = []
    for wind in (0.0, 2.0, 5.0, 10.0):
        cloth = load(json.dumps(curtain(wind)))
        for _ in range(700):
            frame(cloth)
        x = sum(cloth.pos[2 * k] for k in HEM) / 6 - 0.375
        assert cloth.asleep, wind                       # steady: it came to rest in the wind
        hem.append(x)
    assert abs(hem[0]) < 1e-12 and hem[1] > 0.005 and hem[2] > 2 * hem[1] and hem[3] > hem[2] + 0.03, hem
    # a wind from the other side deflects it the other way by as much
    cloth = load(json.dumps(curtain(-5.0)))
    for _ in range(700):
        frame(cloth)
    assert abs(sum(cloth.pos[2 * k] for k in HEM) / 6 - 0.375 + hem[2]) < 1e-9


@pytest.mark.parametrize('drag', [0.05, 1.0, 1000.0])
def test_the_air_carries_a_free_cloth_up_to_its_speed_and_never_past_it(drag):
    scene = {'cols': 6, 'rows': 6, 'spacing': 0.1, 'pins': [], 'gravity': [0, 0], 'density': 0.2,
             'wind': [3.0, -4.0], 'drag': drag, 'damping': 0, 'sleep': False}
    cloth = load(json.dumps(scene))
    n = cloth.n_verts
    fastest = 0.0
    for _ in range(600):
        frame(cloth)
        vx = sum(cloth.pos[2 * k] - cloth.prev[2 * k] for k in range(n)) / n / cloth.h
        vy = sum(cloth.pos[2 * k + 1] - cloth.prev[2 * k + 1] for k in range(n)) / n / cloth.h
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
        assert not cloth.use_air


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
    steady = load(json.dumps(curtain(4.0)))
    for _ in range(700):
        frame(steady)
    assert steady.asleep                               # a steady wind lets it rest


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
    s = curtain(0.0, actions=[{'frame': 10, 'op': 'set', 'scene': {'wind': [6, 0]}},
                              {'frame': 60, 'op': 'set', 'scene': {'gust': [1.0, 0.4], 'drag': 0.3}}])
    out = positions(s, 100)
    still = positions(curtain(0.0), 100)
    assert out != still and out[27][0] > still[27][0] + 0.02
