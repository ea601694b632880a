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
