"""The scene's keys are declared once (cloth/scene.py KEYS, issue #23): the parser, its
messages, `set`, compare panels and each solver's defaults all follow the declaration. The
page's side (its fields, the compare editor, the recorder): tests/browser/test_schema_page.py.
"""

import json

import pytest

from cloth.api import load, run, set_settings
from cloth.scene import KEYS, SCENE_KEYS, SETTABLE, COMPARE_KEYS, SOLVERS, SceneError, \
    parse_scene, solver_defaults, spec

BASE = {'cols': 4, 'rows': 3, 'spacing': 0.1, 'pins': [0, 3]}
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
    # What makes the grid is never set live, nor held per panel.
    for key in ('cols', 'rows', 'spacing', 'pins', 'shear'):
        assert key not in SETTABLE
    for key in ('cols', 'rows', 'spacing', 'pins', 'gravity', 'actions', 'compare'):
        assert key not in COMPARE_KEYS


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
    d = solver_defaults(solver)
    assert sorted(d) == sorted(k.key for k in KEYS if k.by_solver is not None)
    for key, value in d.items():
        assert getattr(s, key) == value, key
    # The keys that do not depend on the solver take their one default.
    assert [s.gravity_x, s.gravity_y] == spec('gravity').fallback
    for key in ('dt', 'damping', 'max_speed', 'shear', 'compliance', 'tear', 'density', 'frames'):
        assert getattr(s, key) == spec(key).fallback, key


def test_a_key_whose_zero_means_none_takes_null_for_none():
    for key in ('tear', 'density'):
        assert run(scene_with(key, None), 30) == run(json.dumps(BASE), 30)
    with pytest.raises(SceneError, match='^damping: must be a number'):
        parse_scene(scene_with('damping', None))


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
        if k.panel:
            parse_scene(text)
        else:
            with pytest.raises(SceneError, match='not a key a panel can have'):
                parse_scene(text)


def test_the_scene_sections_fields_are_number_keys_with_fields():
    """The page's Scene section is made from SCENE_FIELDS: each a key with a field range, a
    number or an int (a point's field is its y), and the grid's keys are the ones not live."""
    from cloth.scene import SCENE_FIELDS
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
