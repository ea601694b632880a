"""Every run of the suite draws the same hypothesis examples (derandomize): a property test
explores widely, but a CI run on a clean clone must not pass or fail by the draw. Examples
that once failed are kept in the tests as @example."""
import fcntl
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
    file that the processes of pytest-xdist share. A run another process is computing is waited
    for, not computed again (a lock on the run's own file, which the system lets go if that
    process dies); cli_run.ahead(runs) computes those of [(text, frames)] that no other process
    has taken, so that two asking for the same list share it instead of waiting in turn."""
    store = tmp_path_factory.getbasetemp()
    if os.environ.get('PYTEST_XDIST_WORKER'):
        store = store.parent          # the workers' directories share their parent
    store = store / 'cli-runs'
    store.mkdir(exist_ok=True)

    def answer(text, frames, with_trace, panel, wait=True):
        key = hashlib.sha256(json.dumps([text, frames, with_trace, panel]).encode()).hexdigest()
        path = store / (key + '.json')
        if path.exists():
            return json.loads(path.read_text())
        with open(store / (key + '.lock'), 'w') as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | (0 if wait else fcntl.LOCK_NB))
            except BlockingIOError:
                return None           # another process is computing it
            if path.exists():         # computed while this one waited
                return json.loads(path.read_text())
            try:
                out = {'ok': run(text, frames, with_trace, panel)}
            except SceneError as e:
                out = {'error': str(e)}
            part = store / ('%s.%d.part' % (key, os.getpid()))
            part.write_text(json.dumps(out))
            os.replace(part, path)    # whole or absent: another process never reads a part
            return out

    def cached(text, frames=None, with_trace=False, panel=-1):
        out = answer(text, frames, with_trace, panel)
        if 'error' in out:
            raise SceneError(out['error'])
        return out['ok']

    def ahead(runs):
        # From the end: a process asking for the same list in order meets this one midway.
        for text, frames in reversed(runs):
            answer(text, frames, False, -1, wait=False)
    cached.ahead = ahead
    return cached
