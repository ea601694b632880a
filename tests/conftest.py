"""Every run of the suite draws the same hypothesis examples (derandomize): a property test
explores widely, but a CI run on a clean clone must not pass or fail by the draw. Examples
that once failed are kept in the tests as @example."""
import hashlib
import json
import os

import pytest
from hypothesis import settings

from cloth.api import run
from cloth.scene import SceneError

settings.register_profile('suite', derandomize=True)
settings.load_profile('suite')


# Per browser engine (tests/browser/engines): its version, start-up and its tests' time, from the
# reports (the process that prints the summary runs no test under pytest-xdist).
ENGINES_SEEN = {}


def pytest_runtest_logreport(report):
    for key, value in report.user_properties:
        if key == 'engine':
            name, version, start = value
            seen = ENGINES_SEEN.setdefault(name, {'seconds': 0.0, 'tests': set(), 'version': version, 'start': 0.0})
            seen['seconds'] += report.duration
            seen['tests'].add(report.nodeid)
            seen['start'] = max(seen['start'], start)


def pytest_terminal_summary(terminalreporter):
    for name, seen in sorted(ENGINES_SEEN.items()):
        terminalreporter.write_line('engine %s %s: %d tests in %.1f s (start-up %.1f s)' % (
            name, seen['version'], len(seen['tests']), seen['seconds'], seen['start']))


@pytest.fixture(scope='session')
def cli_run(tmp_path_factory):
    """cli_run(text, frames=None, with_trace=False, panel=-1): cloth.api.run's text, or its
    SceneError raised again with the same message. CPython's answer is the same every time it is
    asked, and the parity tests of the three engines and the recordings' tests ask for the same
    runs (the catalogue takes CPython minutes): each is computed once a suite run and kept in a
    file that the processes of pytest-xdist share (a run asked by two at once is computed twice,
    the same text)."""
    store = tmp_path_factory.getbasetemp()
    if os.environ.get('PYTEST_XDIST_WORKER'):
        store = store.parent          # the workers' directories share their parent
    store = store / 'cli-runs'
    store.mkdir(exist_ok=True)

    def answer(text, frames, with_trace, panel):
        key = hashlib.sha256(json.dumps([text, frames, with_trace, panel]).encode()).hexdigest()
        path = store / (key + '.json')
        if path.exists():
            return json.loads(path.read_text())
        try:
            out = {'ok': run(text, frames, with_trace, panel)}
        except SceneError as e:
            out = {'error': str(e)}
        part = store / ('%s.%d.part' % (key, os.getpid()))
        part.write_text(json.dumps(out))
        os.replace(part, path)        # whole or absent: another process never reads a part
        return out

    def cached(text, frames=None, with_trace=False, panel=-1):
        out = answer(text, frames, with_trace, panel)
        if 'error' in out:
            raise SceneError(out['error'])
        return out['ok']
    return cached
