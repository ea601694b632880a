"""The page's modules depend one way (README, "Where to change what"; docs/page.md): folders by
layer (build.LAYERS: sim, draw, input, ui), each module importing only from its own layer or a
lower one, app.js (the loop and the wiring) above them all; input turns pointers into gestures
without knowing the app; no module reads another's window global."""

import os
import re

import build


def source(module):
    with open(os.path.join(build.WEBGL, *(module + '.js').split('/')), encoding='utf-8') as f:
        return f.read()


def code_of(module):
    """The module's code without its comments (a comment may name anything)."""
    return '\n'.join(line.split('//')[0] for line in source(module).split('\n'))


def imports_of(module):
    return build.parse_module(source(module), module)[0]


def rank(module):
    return (build.LAYERS + ['app']).index(build.layer_of(module))


def test_every_page_file_is_a_module_in_a_layer_and_linked_from_app_or_the_worker():
    linked = [m for m, _ in build.modules(build.WEBGL, build.PAGE_ENTRY)]
    worker = [m for m, _ in build.modules(build.WEBGL, build.WORKER_ENTRY)]
    assert sorted(set(linked) | set(worker)) == build.page_files()
    assert {build.layer_of(m) for m in worker} == {'sim'}      # the Worker has no page to draw
    assert [m for m in linked if '/' not in m] == [build.PAGE_ENTRY]
    assert {build.layer_of(m) for m in linked} == set(build.LAYERS) | {'app'}


def test_no_import_from_a_lower_layer_to_a_higher_one():
    up = [(m, d) for m in build.page_files() for d in imports_of(m) if rank(d) > rank(m)]
    assert up == []


def test_the_layering_check_sees_an_import_upward():
    # The check above on a module that imports from a layer above its own.
    fake = "import { clothUI } from '../ui/ui.js';\nexport const x = 1;\n"
    deps = build.parse_module(fake, 'sim/fake')[0]
    assert deps == ['ui/ui'] and rank(deps[0]) > rank('sim/fake')


def test_each_module_uses_what_it_imports_and_reads_no_window_global():
    for m in build.page_files():
        code = code_of(m)
        globals_read = set(re.findall(r'window\.(cloth\w+)', code)) - {'clothApp'}
        assert globals_read == set(), (m, globals_read)
        body = '\n'.join(line for line in code.split('\n') if not line.startswith('import '))
        prologue = build.parse_module(source(m), m)[1]       # 'var local = module.name;'
        for local in (line.split()[1] for line in prologue):
            assert re.search(r'\b%s\b' % re.escape(local), body), (m, 'imports but never uses', local)


def test_input_and_gestures_know_no_other_module():
    for m in ('input/input', 'input/gestures'):
        assert imports_of(m) == [], m
    users = {m for m in build.page_files() if {'input/input', 'input/gestures'} & set(imports_of(m))}
    assert users == {'app', 'ui/seam'}     # the seam only publishes them to the tests


def test_only_the_simulation_side_holds_a_cloth_or_the_session():
    """The drawing, the input and the UI read the panels' snapshots (clothCore.snapshot) and call
    sim/panels.js: no module outside sim/ names a cloth or the session in code (the test seam
    excepted: the tests read a live cloth through it)."""
    found = []
    for m in build.page_files():
        if build.layer_of(m) == 'sim' or m == 'ui/seam':
            continue
        code = [re.sub(r"'[^']*'", "''", line) for line in code_of(m).split('\n')]
        found += [(m, line) for line in code if re.search(r'\bcloth\b|\bsess\b|core\.session|\.session\(', line)]
    assert found == []


def test_the_cloth_check_sees_a_module_that_reads_a_cloth():
    # The pattern above on the lines the old readouts and app had.
    lines = ['const c = state.cloth;', 'session.grab(sess, k, x, y);', 'panels.snap(0).rms_strain']
    hits = [line for line in lines if re.search(r'\bcloth\b|\bsess\b|core\.session|\.session\(', line)]
    assert hits == lines[:2]


def test_the_renderer_never_reads_a_cloth():
    """It draws a snapshot (clothCore.snapshot); comments and messages may name the cloth,
    code may not."""
    code = [re.sub(r"'[^']*'", "''", line) for line in code_of('draw/renderer').split('\n')]
    assert not [line for line in code if re.search(r'\bcloth\b', line)]
