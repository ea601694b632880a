"""Pulling beyond reach and letting go: the stretch is shared out while held, the cloth returns
to shape without being flung, and a flick still throws it (cloth/sim.py RELIEVE_SLACK,
cloth/solve.py relieve, cloth/tethers.py over_reach)."""
import math

import pytest

import cloth.sim as sim
from cloth.sim import frame, grab, move, release, pin, unpin
from helpers import load, scene

N = 12
H = 1.0 / (N - 1)


def hanging(**extra):
    keys = dict(cols=N, rows=N, spacing=H, pins=list(range(0, N, 3)) + [N - 1], damping=0.5)
    keys.update(extra)
    cloth = load(scene(**keys))
    for _ in range(120):
        frame(cloth)
    return cloth


def speeds(cloth):
    return [math.hypot(cloth.pos[2 * k] - cloth.prev[2 * k],
                       cloth.pos[2 * k + 1] - cloth.prev[2 * k + 1]) / cloth.h
            for k in range(cloth.n_verts)]


def overpull_and_let_go(cloth, dx, dy):
    """Grab the bottom-middle vertex, pull it (dx, dy) beyond where it hangs over a second,
    hold it there a second, let go; return the largest speed over the next 10 frames."""
    k = (N - 1) * N + N // 2
    x0, y0 = cloth.pos[2 * k], cloth.pos[2 * k + 1]
    grab(cloth, k, x0, y0)
    for f in range(120):
        t = min(1.0, f / 60.0)
        move(cloth, k, x0 + dx * t, y0 + dy * t)
        frame(cloth)
    release(cloth, k)
    fastest = 0.0
    for _ in range(10):
        frame(cloth)
        fastest = max(fastest, max(speeds(cloth)))
    return fastest


@pytest.mark.parametrize('dx, dy', [(0.0, -0.3), (1.0, -1.5)])
def test_a_cloth_pulled_beyond_its_reach_is_not_flung_when_let_go(dx, dy):
    fastest = overpull_and_let_go(hanging(), dx, dy)
    seed = overpull_and_let_go(hanging(solver='jakobsen'), dx, dy)
    # It springs back about as fast as the seed's cloth does (which stretches instead).
    assert fastest < max(5.0, 1.5 * seed), (fastest, seed)


def test_without_relieve_the_same_release_flings_it(monkeypatch):
    # The test above can fail: with the relieving passes off, the same release is violent.
    monkeypatch.setattr(sim, 'RELIEVE_PASSES', 0)
    assert overpull_and_let_go(hanging(), 0.0, -0.3) > 20.0


def flick(speed, **extra):
    """A free cloth in zero gravity, its middle vertex dragged sideways at `speed` m/s for a
    third of a second and let go; returns the centre of mass's speed over the next 0.5 s."""
    cloth = load(scene(cols=N, rows=N, spacing=H, gravity=[0.0, 0.0], **extra))
    k = (N // 2) * N + N // 2
    x0, y0 = cloth.pos[2 * k], cloth.pos[2 * k + 1]
    grab(cloth, k, x0, y0)
    for f in range(1, 21):
        move(cloth, k, x0 + speed * f / 60.0, y0)
        frame(cloth)
    release(cloth, k)
    cx0 = sum(cloth.pos[0::2]) / cloth.n_verts
    for _ in range(30):
        frame(cloth)
    cx1 = sum(cloth.pos[0::2]) / cloth.n_verts
    return (cx1 - cx0) / 0.5


@pytest.mark.parametrize('speed', [1.0, 3.0, 10.0])
def test_a_flick_still_throws_the_cloth(speed, monkeypatch):
    # A free grid of structural edges is a mechanism: it follows a hand partly by shearing, so
    # it may fly slower than the hand or, whipped, faster (measured 0.46 to 1.54 times its
    # speed). What letting go must not do is take momentum out of the throw.
    thrown = flick(speed)
    assert 0.3 * speed < thrown < 2.0 * speed, (speed, thrown)
    monkeypatch.setattr(sim, 'RELIEVE_PASSES', 0)
    assert flick(speed) == pytest.approx(thrown, rel=0.02)


def test_relieve_runs_only_when_a_vertex_is_let_go_and_never_for_compliant_edges(
        monkeypatch):
    calls = []
    monkeypatch.setattr(sim, 'relieve', lambda *args: calls.append(args[-1]) or 0)
    monkeypatch.setattr(sim, 'relieve_cells', lambda *args: 0)
    cloth = hanging()
    k = N * N - 1
    assert calls == []                    # 120 frames, nothing changed: never
    pin(cloth, k)                         # fixing a vertex reveals no stretch (and relieving
    grab(cloth, k - 1, 0.9, -1.3)         # there would steal a hand's yank from the cloth)
    frame(cloth)
    assert calls == []
    release(cloth, k - 1)                 # letting go does: once, at the next step
    frame(cloth)
    frame(cloth)
    assert len(calls) == 1                # (the stub reports nothing left to relieve)
    unpin(cloth, k)
    frame(cloth)
    assert len(calls) == 2
    soft = hanging(compliance=1e-3, tethers=False)
    calls.clear()
    pin(soft, k)
    unpin(soft, k)
    frame(soft)
    assert calls == []                    # a compliant cloth's stretch is its material's


def strain_while_pulled(cloth, dx, dy):
    """Pull the bottom-middle vertex (dx, dy) beyond where it hangs and hold it: the largest
    strain over the hold."""
    k = (N - 1) * N + N // 2
    x0, y0 = cloth.pos[2 * k], cloth.pos[2 * k + 1]
    grab(cloth, k, x0, y0)
    worst = 0.0
    for f in range(120):
        t = min(1.0, f / 60.0)
        move(cloth, k, x0 + dx * t, y0 + dy * t)
        frame(cloth)
        cloth.measure()
        worst = max(worst, cloth.max_strain)
    return worst


@pytest.mark.parametrize('dx, dy', [(0.0, -0.3), (1.0, -1.5)])
def test_a_hand_pulling_beyond_reach_stretches_the_cloth_evenly(dx, dy, monkeypatch):
    # The tethers stretch with the hand (tethers.over_reach), so the edges share the stretch
    # out as the seed's cloth does, instead of gathering it where the vertices tied to the
    # hand meet those tied to the pins.
    tethered = strain_while_pulled(hanging(), dx, dy)
    seed = strain_while_pulled(hanging(solver='jakobsen'), dx, dy)
    assert tethered <= 1.2 * seed, (tethered, seed)
    monkeypatch.setattr(sim, 'over_reach', lambda *args: 1.0)
    unscaled = strain_while_pulled(hanging(), dx, dy)
    # Measured: 1.56 against 0.38 for the 0.3 m pull, 6.9 against 3.7 for the 1.5 m one (with
    # the stretch unscaled the line solves run too, and share out a little of it).
    assert unscaled > 1.5 * tethered, (unscaled, tethered)
