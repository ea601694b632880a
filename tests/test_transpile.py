"""The core must transpile with Transcrypt 3.9.5 without a single error or warning."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_core_transpiles_cleanly(tmp_path):
    out = tmp_path / 'js'
    done = subprocess.run([sys.executable, '-m', 'transcrypt', '-n', '-b', '-od', str(out),
                           'cloth/api.py'], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)
    log = done.stdout + done.stderr
    assert done.returncode == 0, log
    assert 'Error' not in log and 'Warning' not in log, log
    for module in ['api', 'cloth.sim', 'cloth.solve', 'cloth.scene', 'cloth.host',
                   'cloth.measure', 'cloth.tethers']:
        assert (out / (module + '.js')).exists(), module
    # The CPython-only branches (lists, json) must not leak into the JS.
    host = (out / 'cloth.host.js').read_text()
    assert 'Float64Array' in host and 'loads' not in host
