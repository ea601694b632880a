"""Deformation, picking, every action op, and degenerate geometry."""

import json
import math

import pytest

from helpers import scene, curtain, load, step, xy, result, all_finite
from cloth.api import run, simulate
from cloth.fabrics import HEM_LAYERS, HEM_WIDTH
from cloth.hands import HAND_FORCE, HAND_STIFFNESS, grab, release, pin, unpin, toggle_pin
from cloth.keys import spec
from cloth.measure import measure, energies, nearest
from cloth.keys import SOLVERS, DEFAULT_SOLVER, SEED_SOLVER
from cloth.topology import count_edges

DEFAULT_STRETCH = spec('stretch').fallback      # N/m: the default fabric's
DEFAULT_DENSITY = spec('density').fallback      # kg/m^2


def place(cloth, k, x, y):
    cloth.pos[2 * k] = x
    cloth.pos[2 * k + 1] = y


def hand_placed(solver):
    """A 2x2 grid of spacing 1 put by hand into a configuration whose every edge is known;
    edges in order (0,1) (0,2) (1,3) (2,3), then the two diagonals."""
    cloth = load(scene(cols=2, rows=2, spacing=1.0, solver=solver))
    assert [(cloth.edge_a[e], cloth.edge_b[e]) for e in range(4)] == [(0, 1), (0, 2), (1, 3), (2, 3)]
    assert cloth.n_struct == 4 and cloth.n_edges == 6
    place(cloth, 0, 0.0, 0.0)
    place(cloth, 1, 2.0, 0.0)      # (0,1): length 2
    place(cloth, 2, 0.0, -0.5)     # (0,2): length 0.5, shorter than at rest
    place(cloth, 3, 2.0, -2.0)     # (1,3): length 2; (2,3): length 2.5
    measure(cloth)
    return cloth


def test_diff_and_stress_on_a_hand_computed_configuration():
    # The seed's measure, under the seed's solver: |diff| = |L - L0| / L per edge ...
    cloth = hand_placed(SEED_SOLVER)
    assert list(cloth.edge_value) == pytest.approx([0.5, 1.0, 0.5, 0.6], abs=1e-15)
    # ... and Q = the mean |diff| over each vertex's edges.
    assert list(cloth.stress) == pytest.approx([0.75, 0.5, 0.8, 0.55], abs=1e-15)
    assert cloth.max_value == pytest.approx(1.0)
    assert cloth.max_stress == pytest.approx(0.8)
    # The tension strain max(0, L / L0 - 1), whatever the solver: 1, 0 (compressed), 1, 1.5.
    assert cloth.max_strain == pytest.approx(1.5)
    rms = math.sqrt((1 + 0 + 1 + 2.25) / 4)
    assert cloth.rms_strain == pytest.approx(rms)


def test_the_membranes_value_is_the_tension_strain_on_the_same_configuration():
    # Under the default an edge shows its tension strain: a compressed edge is wrinkled, not
    # strained (0); Q is the mean of it over each vertex's edges.
    cloth = hand_placed(DEFAULT_SOLVER)
    assert list(cloth.edge_value) == pytest.approx([1.0, 0.0, 1.0, 1.5], abs=1e-15)
    assert list(cloth.stress) == pytest.approx([0.5, 1.0, 0.75, 1.25], abs=1e-15)
    assert cloth.max_value == pytest.approx(1.5)
    assert cloth.max_stress == pytest.approx(1.25)
    assert cloth.max_strain == pytest.approx(1.5)
    assert cloth.rms_strain == pytest.approx(math.sqrt((1 + 0 + 1 + 2.25) / 4))


PLACED = [[0, 0], [2, 0], [0, -0.5], [2, -2]]


def test_run_reports_the_same_deformation():
    # Pinned, then grabbed: the seed's hand puts what it holds exactly where it holds it.
    actions = []
    for k, to in enumerate(PLACED):
        actions += [{'frame': 0, 'op': 'pin', 'vertex': k},
                    {'frame': 0, 'op': 'grab', 'vertex': k, 'to': to}]
    out = result(scene(cols=2, rows=2, spacing=1.0, solver=SEED_SOLVER, actions=actions), 3)
    assert out['frames'] == 3
    assert out['edges'] == [[0, 1], [0, 2], [1, 3], [2, 3]]     # the structural edges only
    assert out['positions'] == PLACED
    assert out['edge_value'] == pytest.approx([0.5, 1.0, 0.5, 0.6])
    assert out['node_stress'] == pytest.approx([0.75, 0.5, 0.8, 0.55])


def test_run_reports_the_tension_strain_of_where_the_cloth_is():
    # The default's hands pull with at most HAND_FORCE: the cloth stretched this far pulls
    # back harder, so it is not where the hands are; what run reports is the strain of the
    # positions it reports.
    actions = []
    for k, to in enumerate(PLACED):
        actions += [{'frame': 0, 'op': 'pin', 'vertex': k},
                    {'frame': 0, 'op': 'grab', 'vertex': k, 'to': to}]
    out = result(scene(cols=2, rows=2, spacing=1.0, actions=actions), 3)
    p = out['positions']
    strain = [max(0.0, math.dist(p[a], p[b]) - 1.0) for a, b in out['edges']]
    assert out['edge_value'] == pytest.approx(strain, abs=1e-12)
    stress = [(strain[0] + strain[1]) / 2, (strain[0] + strain[2]) / 2,
              (strain[1] + strain[3]) / 2, (strain[2] + strain[3]) / 2]
    assert out['node_stress'] == pytest.approx(stress, abs=1e-12)


def test_trace_holds_every_frame():
    out = json.loads(run(scene(cols=2, rows=1, spacing=1.0, pins=[0]), 4, True))
    assert len(out['trace']) == 4
    assert out['trace'][-1] == out['positions']
    assert 'trace' not in result(scene(cols=2, rows=1, spacing=1.0), 2)


def test_nearest_vertex_within_radius():
    cloth = load(scene(cols=3, rows=3, spacing=1.0))
    assert nearest(cloth, 1.1, -0.9, 0.5) == 4
    assert nearest(cloth, 2.0, -2.0, 0.01) == 8
    assert nearest(cloth, 5.0, 5.0, 1.0) == -1


@pytest.mark.parametrize('solver', SOLVERS)
def test_grab_without_target_holds_in_place(solver):
    actions = [{'frame': 3, 'op': 'grab', 'vertex': 8}]
    first = load(curtain(3, solver=solver))
    step(first, 3)
    where = xy(first, 8)
    out = result(curtain(3, solver=solver, actions=actions), 40)
    if solver == SEED_SOLVER:
        assert tuple(out['positions'][8]) == where      # the seed's: held where it is
    else:
        # A hand is a stiff spring (hands.HAND_STIFFNESS): it holds the vertex where it was
        # but for the force it carries over its stiffness. Here that force is less than 1 N
        # (the whole 1 m^2 of jersey weighs 2 N, and three pins share it with the hand).
        assert math.dist(out['positions'][8], where) < 1.0 / HAND_STIFFNESS


def test_grab_move_release_a_free_vertex_of_the_seeds_method():
    # The seed's hand puts what it holds where it holds it. A move at frame 10 sends the hand
    # there over the next frame (hands.move): the state at frame 10 holds the move, and the
    # vertex is there at frame 11.
    actions = [{'frame': 0, 'op': 'grab', 'vertex': 7, 'to': [0.3, -1.2]},
               {'frame': 10, 'op': 'move', 'vertex': 7, 'to': [0.6, -1.5]}]
    seed = SEED_SOLVER
    out = result(curtain(3, solver=seed, actions=actions), 9)
    assert out['positions'][7] == [0.3, -1.2]
    cloth = load(curtain(3, solver=seed, actions=actions))
    simulate(cloth, 10, None)
    assert xy(cloth, 7) == (0.3, -1.2) and cloth.held[7] == 1
    assert (cloth.target[14], cloth.target[15]) == (0.6, -1.5)
    out = result(curtain(3, solver=seed, actions=actions), 11)
    assert out['positions'][7] == [0.6, -1.5]
    out = result(curtain(3, solver=seed, actions=actions), 30)
    assert out['positions'][7] == [0.6, -1.5]
    released = actions + [{'frame': 30, 'op': 'release', 'vertex': 7}]
    out = result(curtain(3, solver=seed, actions=released), 31)
    assert out['positions'][7] != [0.6, -1.5]      # it moves again
    assert all_finite(sum(out['positions'], []))


def test_grab_move_release_a_free_vertex():
    # The default's hand (a spring pulling with at most HAND_FORCE) takes the vertex where it
    # is moved, within the cloth's reach (the bottom middle of a 3x3 curtain of spacing 0.5,
    # swung aside and up), to within the force it holds against over its stiffness: inside
    # the stiff part of its pull (HAND_FORCE / HAND_STIFFNESS, 5 mm), where the cloth swinging
    # on it pulls it by a few newtons, never levelled off at HAND_FORCE as beyond reach.
    stiff = HAND_FORCE / HAND_STIFFNESS
    actions = [{'frame': 0, 'op': 'grab', 'vertex': 7, 'to': [0.8, -0.9]},
               {'frame': 10, 'op': 'move', 'vertex': 7, 'to': [0.35, -0.95]}]
    # (A patch left behind catches up with its hand at HAND_CATCH_UP more than the hand's own
    # speed: the hand that took hold 0.32 m away in 4 frames, the 0.45 m jump in 6.)
    for f in range(5, 11):
        out = result(curtain(3, actions=actions), f)
        assert math.dist(out['positions'][7], [0.8, -0.9]) < stiff, f
    for f in range(17, 31, 5):
        out = result(curtain(3, actions=actions), f)
        assert math.dist(out['positions'][7], [0.35, -0.95]) < stiff, f
    # Beyond reach (1.2 m below the pin above it, whose column is 1 m long) the hand pulls
    # with HAND_FORCE and the fabric stretches as far as that takes it, no farther: less than
    # its column of two edges in series would stretch under the hand and the cloth's weight
    # alone (the other columns and the diagonals share the load). Damped, to come to rest.
    far = actions + [{'frame': 30, 'op': 'move', 'vertex': 7, 'to': [0.5, -1.2]}]
    out = result(curtain(3, damping=2.0, actions=far), 150)
    reach = math.dist(out['positions'][7], [0.5, 0.0])
    weight = DEFAULT_DENSITY * 9.81 * 1.0 * 1.0
    assert 1.0 < reach < 1.0 + 2 * (HAND_FORCE + weight) / DEFAULT_STRETCH
    assert math.dist(out['positions'][7], [0.5, -1.2]) > 0.1
    released = far + [{'frame': 150, 'op': 'release', 'vertex': 7}]
    moved = result(curtain(3, damping=2.0, actions=released), 170)['positions'][7]
    assert moved != out['positions'][7] and all_finite(moved)


@pytest.mark.parametrize('solver', SOLVERS)
def test_dragged_pin_stays_pinned_where_left(solver):
    # A hand on a pin moves it; letting go leaves it fixed where the hand left it. The seed's
    # hand takes it all the way; a membrane's hand pulls with at most HAND_FORCE, and the
    # corner dragged 0.5 m from its neighbour in a frame is left where that force got it.
    actions = [{'frame': 0, 'op': 'grab', 'vertex': 2, 'to': [0.9, 0.2]},
               {'frame': 5, 'op': 'move', 'vertex': 2, 'to': [1.4, 0.5]},
               {'frame': 6, 'op': 'release', 'vertex': 2}]
    left = result(curtain(3, solver=solver, actions=actions), 6)['positions'][2]
    assert left != [1.0, 0.0]                       # it was dragged
    out = result(curtain(3, solver=solver, actions=actions), 60)
    assert out['positions'][2] == left
    if solver == SEED_SOLVER:
        assert left == [1.4, 0.5]
    cloth = load(curtain(3, solver=solver, actions=actions))
    simulate(cloth, 6, None)
    assert cloth.pinned[2] == 1 and cloth.fixed[2] == 1 and cloth.held[2] == 0


def test_actions_in_one_frame_apply_in_list_order():
    actions = [{'frame': 2, 'op': 'grab', 'vertex': 0, 'to': [1, 1]},
               {'frame': 2, 'op': 'move', 'vertex': 0, 'to': [1, -1]},
               {'frame': 1, 'op': 'pin', 'vertex': 1}]
    out = result(scene(cols=2, rows=1, spacing=1.0, actions=actions), 60)
    assert math.dist(out['positions'][0], [1, -1]) < 0.01     # the move, not the grab, counts


def test_pin_and_unpin():
    cloth = load(scene(cols=2, rows=1, spacing=1.0, pins=[0]))
    step(cloth, 20)
    where = xy(cloth, 1)
    pin(cloth, 1)
    step(cloth, 20)
    assert xy(cloth, 1) == where
    unpin(cloth, 1)
    step(cloth, 5)
    assert xy(cloth, 1) != where
    toggle_pin(cloth, 1)
    assert cloth.pinned[1] == 1 and cloth.fixed[1] == 1 and cloth.inv_mass[1] == 0.0
    toggle_pin(cloth, 1)
    assert cloth.pinned[1] == 0 and cloth.fixed[1] == 0 and cloth.inv_mass[1] == 1.0 / cloth.mass[1]


@pytest.mark.parametrize('solver', SOLVERS)
def test_letting_go_keeps_the_motion_and_the_vertex_falls_freely(solver):
    # A hand holds a free vertex where it is: the seed's exactly, a spring under the vertex's
    # weight m g over its stiffness.
    cloth = load(scene(cols=1, rows=1, spacing=1.0, pins=[], solver=solver))
    grab(cloth, 0, 0.0, 0.0)
    step(cloth, 30)
    x, y = xy(cloth, 0)
    sag = cloth.mass[0] * 9.81 / HAND_STIFFNESS
    assert math.dist((x, y), (0.0, 0.0)) <= (0.0 if solver == SEED_SOLVER else sag * 1.5)
    # Letting go removes the springs and nothing else: where it is and how it moves stay.
    vx, vy = cloth.vel[0], cloth.vel[1]
    release(cloth, 0)
    assert xy(cloth, 0) == (x, y) and (cloth.vel[0], cloth.vel[1]) == (vx, vy)
    # From then on gravity alone: 0.5 s later it has gained g t of speed, to within one step's
    # g h (what a two-step integrator's history of a held vertex leaves: cloth/integrate.py).
    step(cloth, 30)
    h = 1.0 / 60.0
    assert cloth.vel[0] == pytest.approx(vx, abs=1e-12)
    assert cloth.vel[1] - vy == pytest.approx(-9.81 * 0.5, abs=9.81 * h)
    assert xy(cloth, 0)[1] - y == pytest.approx(vy * 0.5 - 0.5 * 9.81 * 0.25, abs=9.81 * h * 0.5)


@pytest.mark.parametrize('solver', SOLVERS)
def test_two_pinned_neighbours_dragged_onto_one_point(solver):
    actions = [{'frame': 0, 'op': 'grab', 'vertex': 0, 'to': [0.5, 0.0]},
               {'frame': 0, 'op': 'grab', 'vertex': 1, 'to': [0.5, 0.0]}]
    out = result(curtain(4, solver=solver, actions=actions), 50)
    flat = sum(out['positions'], []) + out['edge_value'] + out['node_stress']
    assert all_finite(flat)
    if solver == SEED_SOLVER:
        assert out['edge_value'][0] == 1.0     # the collapsed edge reads as fully compressed
        assert out['positions'][0] == out['positions'][1] == [0.5, 0.0]
    elif solver == DEFAULT_SOLVER:
        # Within reach: each hand holds its pin to within 1 mm (HAND_FORCE / HAND_STIFFNESS),
        # and the collapsed edge, shorter than at rest, has no tension strain.
        for k in (0, 1):
            assert math.dist(out['positions'][k], [0.5, 0.0]) < HAND_FORCE / HAND_STIFFNESS
        assert out['edge_value'][0] == 0.0


@pytest.mark.parametrize('solver', SOLVERS)
def test_every_vertex_pinned_and_all_dragged_to_the_origin(solver):
    n = 3
    actions = [{'frame': 0, 'op': 'grab', 'vertex': k, 'to': [0, 0]} for k in range(n * n)]
    out = result(curtain(n, solver=solver, actions=actions), 5)
    assert all_finite(sum(out['positions'], []) + out['edge_value'] + out['node_stress'])


def test_one_by_one_grid():
    out = result(scene(cols=1, rows=1, spacing=1.0), 10)
    assert out['edges'] == [] and out['edge_value'] == [] and out['node_stress'] == [0]


@pytest.mark.parametrize('solver', [
    SEED_SOLVER, 'xpbd',
    DEFAULT_SOLVER])
def test_zero_iterations_is_free_fall(solver):
    out = result(curtain(4, solver=solver, iterations=0), 30)
    assert all_finite(sum(out['positions'], []))
    assert out['positions'][15][1] == pytest.approx(-1.0 - 0.5 * 9.81 * 0.25, rel=1e-9)


@pytest.mark.parametrize('solver', SOLVERS)
def test_huge_drag_stays_finite(solver):
    actions = [{'frame': 1, 'op': 'grab', 'vertex': 15, 'to': [1e8, -1e8]},
               {'frame': 3, 'op': 'release', 'vertex': 15}]
    out = result(curtain(4, solver=solver, actions=actions), 60)
    assert all_finite(sum(out['positions'], []) + out['edge_value'] + out['node_stress'])


def test_shear_diagonals_are_declared_edges():
    # Both diagonals of every cell, after the structural edges: rest spacing sqrt 2, stiffness
    # the scene's shear (N/m); the structural edges' the scene's stretch (on the border, the
    # half cell's and the hem's).
    cloth = load(scene(cols=3, rows=3, spacing=1.0, stretch=700.0, shear=30.0))
    assert [cloth.n_struct, cloth.n_edges] == count_edges(3, 3) == [12, 12 + 8]
    for e in range(cloth.n_edges):
        diagonal = e >= cloth.n_struct
        assert cloth.rest[e] == pytest.approx(math.sqrt(2) if diagonal else 1.0)
        a, b = cloth.edge_a[e], cloth.edge_b[e]
        border = not diagonal and (a // 3 == b // 3 and a // 3 in (0, 2) or
                                   a % 3 == b % 3 and a % 3 in (0, 2))
        # a border edge stands for the half cell inside it, plus the hem's line stiffness
        hem = 700.0 * (0.5 + HEM_LAYERS * HEM_WIDTH / 1.0)
        assert cloth.stiff[e] == (30.0 if diagonal else hem if border else 700.0), e
    assert sum(cloth.stiff[e] == 700.0 for e in range(12)) == 4       # the four to the centre
    cells = {tuple(sorted((cloth.edge_a[e], cloth.edge_b[e]))) for e in range(12, 20)}
    assert cells == {(0, 4), (1, 3), (1, 5), (2, 4), (3, 7), (4, 6), (4, 8), (5, 7)}


@pytest.mark.parametrize('phi', [0.3, -0.3])
def test_shearing_a_cell_costs_only_its_stretched_diagonals_energy(phi):
    # A unit cell sheared by phi keeps its four sides at rest: the structural grid alone is a
    # mechanism, and with shear 0 shearing it costs nothing. With the diagonals it costs the
    # one stretched diagonal's k / 2 (L - L0)^2; the shortened one is slack (tension only).
    for shear in (0.0, 50.0):
        cloth = load(scene(cols=2, rows=2, spacing=1.0, gravity=[0, 0], shear=shear))
        place(cloth, 2, math.sin(phi), -math.cos(phi))
        place(cloth, 3, 1 + math.sin(phi), -math.cos(phi))
        long = math.sqrt(2 + 2 * abs(math.sin(phi)))
        kinetic, elastic, gravity = energies(cloth)
        assert kinetic == 0.0 and gravity == 0.0
        assert elastic == pytest.approx(0.5 * shear * (long - math.sqrt(2)) ** 2, rel=1e-12, abs=1e-300)


@pytest.mark.parametrize('x, text', [
    (1.0, '1'), (-2.0, '-2'), (0.5, '0.5'), (0.1, '0.1'), (1 / 3, '0.3333333333333333'),
    (-0.0, '0'), (1e-6, '0.000001'), (1e-7, '1e-7'), (1.5e-7, '1.5e-7'), (123.456, '123.456'),
    (1e20, '100000000000000000000'), (1e21, '1e+21'), (1.25e22, '1.25e+22'),
    (2.0 ** 53, '9007199254740992'), (5e-324, '5e-324'), (1.7976931348623157e308,
                                                        '1.7976931348623157e+308')])
def test_numbers_are_written_as_js_writes_them(x, text):
    # What JSON.stringify prints for each (checked against node for 6,000 random doubles
    # when this was written); the browser parity tests compare whole outputs as text.
    from cloth.host import js_number
    assert js_number(x) == text


def test_run_output_is_compact_json_with_js_numbers():
    text = run(scene(cols=2, rows=1, spacing=1.0, pins=[0], gravity=[0, 0]), 1)
    assert text.startswith('{"frames":1,"edges":[[0,1]],"positions":[[0,0],[1,0]]')


def test_a_fabric_under_the_seeds_solver_changes_nothing_and_the_core_says_so():
    """The page's note (cloth/scene.py unused_settings) is true: under Jakobsen's solver two
    fabrics give the same cloth, bit for bit, under gravity and a hand; under the default
    they differ and nothing is said."""
    from cloth import api
    from cloth.scene import unused_settings

    def run(solver, stretch, shear, density):
        text = scene(cols=12, rows=9, spacing=0.05, pins=[0, 11], solver=solver,
                     stretch=stretch, shear=shear, density=density,
                     actions=[{'frame': 5, 'op': 'grab', 'vertex': 100, 'to': [0.3, -0.6]},
                              {'frame': 40, 'op': 'release', 'vertex': 100}])
        return api.run(text, 80), unused_settings(api.check(text))

    seed_a, said_a = run(SEED_SOLVER, 500.0, 50.0, 0.2)
    seed_b, said_b = run(SEED_SOLVER, 10000.0, 170.0, 0.4)
    assert seed_a == seed_b and said_a == said_b
    assert all(key in said_a for key in ('stretch', 'shear', 'density'))
    vbd_a, said = run(DEFAULT_SOLVER, 500.0, 50.0, 0.2)
    vbd_b, _ = run(DEFAULT_SOLVER, 10000.0, 170.0, 0.4)
    assert vbd_a != vbd_b and said == ''
    # Every scene has a fabric (the default one when it names none): under the seed's solver
    # it changes nothing either, and the note says so.
    plain = api.check(scene(cols=3, rows=3, spacing=0.1, pins=[0], solver=SEED_SOLVER))
    assert unused_settings(plain) == said_a
