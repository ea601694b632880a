"""Fixtures for the page in Firefox ESR and WebKitGTK (issue #16): one Xvfb for the session,
one browser per engine (every test runs once per engine, all of one engine's tests together,
so only one browser is alive at a time), and a fresh load of dist/index.html (file://) per page.

A machine without an engine skips that engine's tests with the reason; with CI=true a missing
engine fails them. Teardown fails a test on any uncaught error, unhandled rejection,
console.error or Content-Security-Policy violation in its pages (hooks in the page:
engine_page.HOOKS), on a resource that is not a file:, data: or blob: URL, and, in Firefox, on a
JavaScript error or console.error the browser logged for the page.
"""
import os
import pathlib
import sys
import time

import pytest

HERE = pathlib.Path(__file__).absolute().parent
sys.path.insert(0, str(HERE.parent))   # browser_helpers and the Chromium tests reused here

from browser_helpers import DIST, ROOT, page_url  # noqa: E402,F401 (test_parity imports them from `conftest`)
from engine_drivers import ENGINES, Xvfb, missing  # noqa: E402
from engine_page import Page  # noqa: E402

VIEWPORT = (1000, 700)          # as the Chromium tests' viewport
ON_CI = os.environ.get('CI', '').strip().lower() in ('1', 'true', 'yes')

# Firefox's log lines that are the page's errors (pref devtools.console.stdout.content).
FIREFOX_ERRORS = ('JavaScript error: file://',)


def pytest_collection_modifyitems(config, items):
    for item in items:
        if HERE in pathlib.Path(str(item.fspath)).parents:
            item.add_marker(pytest.mark.engines)
            # Under pytest-xdist (--dist loadgroup) one worker runs every engine test, so each
            # engine starts once and only one of their browsers is alive at a time.
            item.add_marker(pytest.mark.xdist_group('engines'))


@pytest.fixture(scope='session')
def xvfb():
    """xvfb() -> the display of one Xvfb, started for the first engine that needs it."""
    server = None

    def display():
        nonlocal server
        if server is None:
            server = Xvfb()
        return server.display
    yield display
    if server is not None:
        server.stop()


@pytest.fixture(scope='session', params=sorted(ENGINES))
def engine(request, xvfb, tmp_path_factory):
    """One browser of each engine for the session."""
    name = request.param
    reason = missing(name)
    if reason:
        if ON_CI:
            pytest.fail('CI=true and ' + reason, pytrace=False)
        pytest.skip(reason)
    home = tmp_path_factory.mktemp(name)
    downloads = home / 'downloads'
    downloads.mkdir()
    t0 = time.time()
    eng = ENGINES[name](xvfb(), downloads)
    eng.downloads = downloads
    eng.started_in = time.time() - t0
    yield eng
    eng.quit()


@pytest.fixture(autouse=True)
def engine_in_report(request):
    """Names the engine, its version and start-up in the test's reports, for the summary at the
    end (tests/conftest.py: under pytest-xdist only the reports reach the process that prints)."""
    eng = request.node.funcargs.get('engine')
    if eng is not None:
        request.node.user_properties.append(('engine', (eng.name, eng.version, eng.started_in)))
    yield


@pytest.fixture
def open_page(engine):
    """open_page(query='', expect_errors=False, url=None, size=VIEWPORT) -> Page: dist/index.html
    + query (or a fragment), or url, in a fresh document; the viewport `size` (CSS pixels)."""
    engine.current = None
    engine.harvested = ()
    log_start = len(engine.log_text())
    expected = []

    def _open(query='', expect_errors=False, url=None, size=VIEWPORT):
        assert DIST.exists(), 'dist/index.html is missing: run `python build.py`'
        if engine.size != size:
            engine.window_size(*size)
            engine.size = size
        pg = Page(engine, expect_errors)
        expected.append(expect_errors)
        pg.goto(url or page_url(query))
        return pg

    yield _open
    try:
        engine.release()
    except Exception:
        pass
    try:
        errors = engine.take_errors()
        assert errors == [], '%s: the page had errors or made requests: %r' % (engine.name, errors)
        logged = [line for line in engine.log_text()[log_start:].splitlines() if line.startswith(FIREFOX_ERRORS)]
        assert logged == [] or any(expected), '%s logged errors for the page: %r' % (engine.name, logged)
    finally:
        if engine.stuck:
            engine.restart()
        else:
            # A blank document: the last page's cloth would otherwise go on animating (a
            # third of a CPU in WebKit) beside every later test of the run, until the session ends.
            engine.current = None
            try:
                engine.open('about:blank')
            except Exception:
                # The browser died under the test, which fails for it; the tests after it get
                # a new one, not its dead session.
                engine.restart()
