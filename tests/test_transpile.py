"""The core must transpile with Transcrypt 3.9.5 without a single error or warning."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
# CPython only, never part of the page: the CLI and the exact references (numpy, scipy).
CPYTHON_ONLY = ['__init__', '__main__', 'reference']


def test_core_transpiles_cleanly(tmp_path):
    out = tmp_path / 'js'
    done = subprocess.run([sys.executable, '-m', 'transcrypt', '-n', '-b', '-od', str(out),
                           'cloth/api.py'], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)
    log = done.stdout + done.stderr
    assert done.returncode == 0, log
    assert 'Error' not in log and 'Warning' not in log, log
    # Every module of the core is in the page (the entry as api.js), but the CPython-only ones.
    assert (out / 'api.js').exists()
    core = sorted(p.stem for p in (ROOT / 'cloth').glob('*.py')
                  if p.stem not in CPYTHON_ONLY + ['api'])
    assert {'scene', 'keys', 'step', 'vbd', 'jakobsen', 'xpbd', 'hands', 'measure'} <= set(core)
    for module in core:
        assert (out / ('cloth.' + module + '.js')).exists(), module
    assert not (out / 'cloth.reference.js').exists()
    # The CPython-only branches (lists, json) must not leak into the JS.
    host = (out / 'cloth.host.js').read_text()
    assert 'Float64Array' in host and 'loads' not in host


def loop_variables_reassigned(tree):
    """(line, name) of every assignment, in a `for` loop's body, to that loop's variable.
    CPython takes the next value from the range regardless; Transcrypt's `for (var t = 0; t <
    n; t++)` counts on from the value assigned, so the loop runs differently or never ends (a
    sweep's `t = (d - reach) / along` reset its vertex counter and froze the page)."""
    import ast
    out = []
    for loop in ast.walk(tree):
        if not isinstance(loop, ast.For) or not isinstance(loop.target, ast.Name):
            continue
        name = loop.target.id
        for stmt in loop.body:
            for node in ast.walk(stmt):
                targets = []
                if isinstance(node, ast.Assign):
                    targets = node.targets
                elif isinstance(node, (ast.AugAssign, ast.AnnAssign)):
                    targets = [node.target]
                elif isinstance(node, ast.For) and node is not loop:
                    targets = [node.target]
                for t in targets:
                    for n in ast.walk(t):
                        if isinstance(n, ast.Name) and n.id == name and isinstance(n.ctx, ast.Store):
                            out.append((node.lineno, name))
    return out


def test_no_loop_variable_is_assigned_in_its_loop():
    import ast
    found = []
    for path in sorted((ROOT / 'cloth').glob('*.py')):
        if path.stem in CPYTHON_ONLY:
            continue
        for line, name in loop_variables_reassigned(ast.parse(path.read_text())):
            found.append('%s:%d %s' % (path.name, line, name))
    assert found == []
    # The check can fail: the defect it was written for.
    bad = ast.parse('for t in range(n):\n    if a:\n        t = 0.5\n')
    assert loop_variables_reassigned(bad) == [(3, 't')]
