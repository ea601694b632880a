"""The scene's keys are declared once (cloth/keys.py KEYS, issue #23): the parser, its
messages, `set`, compare panels and each solver's defaults all follow the declaration. The
page's side (its fields, the compare editor, the recorder): tests/browser/test_schema_page.py.
Scenes of model 1 (made before the membrane) and what became of their keys: at the end.
"""

import json

import pytest

from cloth.api import load, run, set_settings, notes
from cloth.fabrics import fabric, DEFAULT_FABRIC
from cloth.keys import KEYS, SCENE_KEYS, SETTABLE, COMPARE_KEYS, MODEL, LEGACY_KEYS, spec, \
    solver_index
from cloth.scene import parse_scene, legacy_note
from cloth.topology import along_border
from cloth.keys import SOLVERS, SOLVER_BUDGETS, DEFAULT_SOLVER, SEED_SOLVER, ALIASES
from cloth.values import SceneError

BASE = {'model': MODEL, 'cols': 4, 'rows': 3, 'spacing': 0.1, 'pins': [0, 3]}
# What each solver's own budget holds, by key (cloth/solvers.py: [substeps, iterations,
# corrections]).
BUDGET_KEYS = ['substeps', 'iterations', 'corrections']
NUMBERS = [k for k in KEYS if k.kind in ('int', 'number') and k.key not in ('cols', 'rows', 'spacing')]


def scene_with(key, value):
    s = dict(BASE)
    s[key] = value
    return json.dumps(s)


def test_the_key_lists_are_the_declarations():
    assert SCENE_KEYS == [k.key for k in KEYS]
    assert len(set(SCENE_KEYS)) == len(SCENE_KEYS)
    assert SETTABLE == [k.key for k in KEYS if k.live]
    assert COMPARE_KEYS == [k.key for k in KEYS if k.panel]
    # What makes the grid is never set live, nor held per panel; nor is the model.
    for key in ('cols', 'rows', 'spacing', 'pins', 'model'):
        assert key not in SETTABLE
    for key in ('cols', 'rows', 'spacing', 'pins', 'gravity', 'actions', 'compare', 'model'):
        assert key not in COMPARE_KEYS
    # The fabric is live and a panel's own: its shear a number like its stretch.
    for key in ('stretch', 'shear', 'density'):
        assert key in SETTABLE and key in COMPARE_KEYS and spec(key).kind == 'number'
    # Model 1's keys that the membrane has no use for are no keys of the schema.
    assert not set(LEGACY_KEYS) & set(SCENE_KEYS)
    assert all(spec(key) is None for key in LEGACY_KEYS)


@pytest.mark.parametrize('k', NUMBERS, ids=lambda k: k.key)
def test_every_numeric_key_is_held_to_its_declared_range_and_worded_by_it(k):
    # Both ends are taken (but an open one), and just past them is refused with the words.
    if not k.lo_open:
        parse_scene(scene_with(k.key, k.lo))
    parse_scene(scene_with(k.key, k.hi))
    below = k.lo - max(1.0, abs(k.lo)) if k.kind == 'int' else k.lo - abs(k.lo) * 1e-6 - 1e-9
    above = k.hi + max(1.0, abs(k.hi)) if k.kind == 'int' else k.hi * (1 + 1e-6) + 1e-9
    for bad in ([below, above] if not k.lo_open else [k.lo, above]):
        with pytest.raises(SceneError, match='^' + k.key + ': must be ' + k.words.replace('(', r'\(')
                           .replace(')', r'\)').replace('^', r'\^').replace('[', r'\[').replace(']', r'\]')):
            parse_scene(scene_with(k.key, bad))


@pytest.mark.parametrize('k', [k for k in KEYS if k.kind == 'bool'], ids=lambda k: k.key)
def test_every_switch_takes_true_or_false_only(k):
    parse_scene(scene_with(k.key, True))
    parse_scene(scene_with(k.key, False))
    with pytest.raises(SceneError, match='^' + k.key + ': must be true or false'):
        parse_scene(scene_with(k.key, 1))


def test_a_page_field_never_offers_what_the_core_refuses():
    for k in KEYS:
        if k.field_hi > k.field_lo:
            assert k.lo <= k.field_lo < k.field_hi <= k.hi, k.key
            assert k.step > 0, k.key
            if k.lo_open:
                assert k.field_lo > k.lo, k.key


@pytest.mark.parametrize('solver', SOLVERS)
def test_each_solvers_defaults_are_its_declared_ones(solver):
    s = parse_scene(scene_with('solver', solver))
    i = solver_index(solver)
    assert sorted(k.key for k in KEYS if k.by_solver is not None) == sorted(BUDGET_KEYS)
    for which, key in enumerate(BUDGET_KEYS):
        assert getattr(s, key) == spec(key).by_solver[i] == SOLVER_BUDGETS[i][which], key
    cloth = load(scene_with('solver', solver))
    assert [cloth.substeps, cloth.iterations, cloth.corrections] == SOLVER_BUDGETS[i]
    # The keys that do not depend on the solver take their one default.
    assert [s.gravity_x, s.gravity_y] == spec('gravity').fallback
    assert [s.wind_x, s.wind_y] == spec('wind').fallback
    assert [s.gust_amplitude, s.gust_period] == spec('gust').fallback
    for key in ('dt', 'damping', 'stretch', 'shear', 'density', 'strength', 'drag', 'sleep', 'frames'):
        assert getattr(s, key) == spec(key).fallback, key


def test_the_default_fabric_is_the_fabric_keys_defaults():
    name, label, stretch, shear, density, strength, what = fabric(DEFAULT_FABRIC)
    assert [spec('stretch').fallback, spec('shear').fallback, spec('density').fallback] == \
        [stretch, shear, density]
    s = parse_scene(json.dumps(BASE))
    assert (s.solver, s.model) == (DEFAULT_SOLVER, MODEL)


def test_a_key_whose_zero_means_none_takes_null_for_none():
    nones = [k.key for k in KEYS if k.kind == 'number' and k.lo_open and k.fallback == 0.0]
    assert nones == ['strength', 'tear']
    for key in nones:
        assert run(scene_with(key, None), 30) == run(json.dumps(BASE), 30)
    # A density is no longer "0: 1 kg per vertex": it has a default of its own, and null is
    # not a density.
    for key in ('damping', 'density'):
        with pytest.raises(SceneError, match='^' + key + ': must be a number'):
            parse_scene(scene_with(key, None))


def test_live_keys_are_the_ones_a_set_takes():
    cloth = load(json.dumps(BASE))
    for k in KEYS:
        value = {'int': k.field_lo, 'number': k.field_lo, 'bool': True, 'choice': SOLVERS[0],
                 'point': [0, -1], 'gust': [0.5, 1]}.get(k.kind, 1)
        if k.kind in ('int', 'number') and k.field_hi <= k.field_lo:
            value = k.hi
        text = json.dumps({k.key: value})
        if k.live:
            set_settings(cloth, text)
        else:
            with pytest.raises(SceneError, match='cannot be set on a running cloth'):
                set_settings(cloth, text)


def test_a_panel_may_have_exactly_its_declared_keys():
    for k in KEYS:
        value = {'int': k.field_lo, 'number': k.field_hi, 'bool': True, 'choice': SOLVERS[0]}.get(k.kind, 1)
        compare = [{}, {k.key: value}]
        text = json.dumps(dict(BASE, compare=compare))
        if k.panel or k.key in [a[0] for a in ALIASES]:
            parse_scene(text)         # an alias is taken wherever the key it stands for is
        else:
            with pytest.raises(SceneError, match='not a key a panel can have'):
                parse_scene(text)


def test_the_scene_sections_fields_are_number_keys_with_fields():
    """The page's Scene section is made from SCENE_FIELDS: each a key with a field range, a
    number or an int (a point's field is its y), and the grid's keys are the ones not live."""
    from cloth.keys import SCENE_FIELDS
    k = {key.key: key for key in KEYS}
    assert len({f[0] for f in SCENE_FIELDS}) == len(SCENE_FIELDS)
    from cloth.scene import Scene
    blank = Scene()
    for key, hint, axis, parts in SCENE_FIELDS:
        assert k[key].field_hi > k[key].field_lo and k[key].kind in ('int', 'number', 'point', 'gust'), key
        assert isinstance(hint, str) and axis in ((0, 1) if parts else (0,))
        # a key of two numbers: the Scene attributes that hold them, starting at its default
        assert len(parts) in (0, 2) and (len(parts) == 2) == (k[key].kind in ('point', 'gust')), key
        assert [getattr(blank, a) for a in parts] == (k[key].fallback if parts else []), key
    assert [f[0] for f in SCENE_FIELDS if not k[f[0]].live] == ['cols', 'rows']


# ---- the model: scenes made before the membrane ---------------------------------------------

OLD = {'cols': 4, 'rows': 3, 'spacing': 0.1, 'pins': [0, 3]}      # no `model`: model 1


def test_a_scene_without_a_model_is_of_model_1_and_one_with_it_of_its_own():
    assert parse_scene(json.dumps(OLD)).model == 1 == spec('model').fallback
    assert parse_scene(json.dumps(dict(OLD, model=1))).model == 1
    assert parse_scene(json.dumps(BASE)).model == MODEL
    assert legacy_note(parse_scene(json.dumps(BASE))) == ''


@pytest.mark.parametrize('model', [0, MODEL + 1, -1, 1.5, '2', True, None, [2]])
def test_a_model_out_of_range_is_an_error_naming_it(model):
    with pytest.raises(SceneError, match='^model: must be '):
        parse_scene(scene_with('model', model))


def test_a_model_1_scene_with_legacy_keys_opens_and_the_note_says_what_became_of_them():
    keys = dict(OLD, tethers=True, cells=True, lines=False, tolerance=1e-4, max_speed=50,
                shear=True, compliance=0.01, solver='xpbd', iterations=1, substeps=8)
    text = json.dumps(keys)
    cloth = load(text)
    s = cloth.scene
    note = notes(cloth)[1]
    assert note == legacy_note(s) and note.startswith('made before the membrane model (model 1)')
    for key in ('tethers', 'cells', 'lines', 'tolerance', 'max_speed', 'shear', 'compliance'):
        assert key + ' left out' in note or key + ' became' in note, key
    # compliance (m/N) became the stretch stiffness 1 / compliance; the boolean shear left the
    # default fabric's shear; the old default solver runs as the default with its own budget.
    assert 'compliance became a stretch stiffness' in note
    assert s.stretch == pytest.approx(100.0) and s.shear == spec('shear').fallback
    assert 'solver xpbd runs as ' + DEFAULT_SOLVER in note
    assert s.solver == DEFAULT_SOLVER
    assert [s.substeps, s.iterations, s.corrections] == SOLVER_BUDGETS[solver_index(DEFAULT_SOLVER)]
    assert 'substeps left out' in note and 'iterations left out' in note
    # A model-1 scene had no density (each vertex weighed 1 kg): it takes the default fabric's.
    assert 'density the default fabric' in note and s.density == spec('density').fallback
    # It runs, as a membrane, the same as the scene that says so in model 2's keys.
    now = dict(BASE, stretch=100.0)
    assert run(text, 20) == run(json.dumps(now), 20)


def test_a_model_1_scene_of_the_seeds_solver_keeps_its_steps():
    s = parse_scene(json.dumps(dict(OLD, solver=SEED_SOLVER, iterations=7, substeps=2)))
    assert (s.solver, s.iterations, s.substeps) == (SEED_SOLVER, 7, 2)
    assert 'left out' not in legacy_note(s)


def test_a_model_1_stretch_wins_over_its_compliance():
    s = parse_scene(json.dumps(dict(OLD, compliance=0.01, stretch=800)))
    assert s.stretch == 800
    assert 'compliance left out' in legacy_note(s)


@pytest.mark.parametrize('key', LEGACY_KEYS)
def test_a_model_2_scene_with_a_legacy_key_is_an_unknown_key_error_naming_it(key):
    value = {'tethers': True, 'cells': True, 'lines': True}.get(key, 0.001)
    with pytest.raises(SceneError, match='^' + key + ': unknown key'):
        parse_scene(scene_with(key, value))
    parse_scene(json.dumps(dict(OLD, **{key: value})))          # model 1 has it
    # nor may a set or a panel of a model-2 scene have it
    cloth = load(json.dumps(BASE))
    with pytest.raises(SceneError, match='^scene.' + key + ': cannot be set on a running cloth'):
        set_settings(cloth, json.dumps({key: value}))
    with pytest.raises(SceneError, match=r'^compare\[1\]\.' + key + ': not a key a panel can have'):
        parse_scene(json.dumps(dict(BASE, compare=[{}, {key: value}])))


def test_a_set_on_a_model_1_cloth_may_have_its_legacy_keys():
    cloth = load(json.dumps(OLD))
    set_settings(cloth, json.dumps({'tethers': False, 'tolerance': 0, 'damping': 2}))
    assert cloth.scene.damping == 2 and cloth.scene.model == 1


def test_shear_is_a_number_in_model_2():
    s = parse_scene(scene_with('shear', 120))
    assert s.shear == 120
    cloth = load(scene_with('shear', 120))
    assert all(cloth.stiff[e] == 120 for e in range(cloth.n_struct, cloth.n_edges))
    assert cloth.n_edges > cloth.n_struct
    for bad in (True, False, '50', [50]):
        with pytest.raises(SceneError, match='^shear: must be a number'):
            parse_scene(scene_with('shear', bad))
    # and set live, it restiffens the diagonals
    set_settings(cloth, json.dumps({'shear': 7.5}))
    assert all(cloth.stiff[e] == 7.5 for e in range(cloth.n_struct, cloth.n_edges))
    inside = [e for e in range(cloth.n_struct) if not along_border(cloth, cloth.edge_a[e], cloth.edge_b[e])]
    assert inside and all(cloth.stiff[e] == spec('stretch').fallback for e in inside)
    # In model 1 shear was a switch (whether cells had a diagonal): true or false, left out.
    with pytest.raises(SceneError, match='^shear: must be true or false'):
        parse_scene(json.dumps(dict(OLD, shear=50)))


def test_the_keys_table_lists_every_declared_key_once():
    """`python -m cloth keys` (docs/scenes.md points to it) is derived from KEYS: every key, once,
    with its words."""
    import subprocess
    import sys
    from cloth.keys import KEYS as DECLARED
    out = subprocess.run([sys.executable, '-m', 'cloth', 'keys'], capture_output=True, text=True,
                         check=True).stdout
    names = [line.split('`')[1] for line in out.splitlines()[2:]]
    assert names == [k.key for k in DECLARED]
    from cloth.fabrics import fabric, DEFAULT_FABRIC
    assert '| `stretch` | from 1 to 1000000 N/m (the stretch stiffness) | N/m | %s | yes |' % (
        fabric(DEFAULT_FABRIC)[2]) in out


def test_the_docs_fabric_table_is_the_cores():
    """docs/physics.md's table of fabrics lists cloth/fabrics.py's FABRICS, number for number."""
    from pathlib import Path
    from cloth.fabrics import FABRICS
    text = (Path(__file__).resolve().parent.parent / 'docs' / 'physics.md').read_text()
    for f in FABRICS:
        assert '| %s | %g | %g | %g | %g | %s |' % (f[0], f[2], f[3], f[4], f[5], f[6]) in text, f[0]


def test_the_readme_stands_alone_and_lists_the_presets_fabrics_and_limits_the_core_has():
    """The README names every preset and every fabric with its numbers and states the limits as
    cloth/keys.py has them; it points at nothing outside the repository (a clone has no
    ../shared: the task is in docs/task.md)."""
    from pathlib import Path
    from cloth.fabrics import FABRICS
    from cloth.presets import PRESETS
    from cloth import keys
    root = Path(__file__).resolve().parent.parent
    text = ' '.join((root / 'README.md').read_text().split())
    assert '../' not in text and (root / 'docs' / 'task.md').exists()
    for p in PRESETS:
        assert p[1] in text, p[1]
    for f in FABRICS:
        assert '%s %g, %g, %g, %g' % (f[1], f[2], f[3], f[4], f[5]) in text, f[1]
    for limit, words in ((keys.MAX_VERTICES, 'vertices'), (keys.MAX_ACTIONS, 'actions'),
                         (keys.MAX_FRAMES, 'frames'), (keys.MAX_PANELS, 'compare panels'),
                         (keys.MAX_OBSTACLES, 'obstacles')):
        assert '{:,} {}'.format(limit, words) in text, words
    assert '%d MiB of scene JSON' % (keys.MAX_SCENE_BYTES // (1024 * 1024)) in text
    assert 'nested %d deep' % keys.MAX_DEPTH in text


def test_the_load_notes_read_true_when_an_optional_key_is_missing_zero_or_at_its_limits():
    """Every note built from a scene's optional keys (the model, the solver and the fabric's
    numbers) says what the scene holds: a scene without `model` is not said to have one, a
    scene of the current model gets no legacy note, and no note shows a fallback's -1, NaN or
    None."""
    base = {'cols': 3, 'rows': 3, 'spacing': 0.1}
    said = legacy_note(load(json.dumps(base)).scene)
    assert 'without a "model" key' in said and '"model": %d' % MODEL in said, said
    said = legacy_note(load(json.dumps(dict(base, model=1))).scene)
    assert said.startswith('made before the membrane model (model 1):') and 'without' not in said, said
    def lowest(k):
        return spec(k).lo * 1.001 + 1e-6 if spec(k).lo_open else spec(k).lo

    fabric_keys = ('stretch', 'shear', 'density')
    for keys in ({}, {k: lowest(k) for k in fabric_keys}, {k: spec(k).hi for k in fabric_keys},
                 {'tear': None}, {'tear': lowest('tear')}, {'frames': 0}, {'wind': [0, 0], 'gust': [0, 1]}):
        cloth = load(json.dumps(dict(base, model=MODEL, **keys)))
        for note in notes(cloth):
            assert not any(w in note for w in ('-1', 'nan', 'NaN', 'None', 'undefined')), (keys, note)
        assert legacy_note(cloth.scene) == '', keys
