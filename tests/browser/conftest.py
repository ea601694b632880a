"""Playwright fixtures: one Chromium per session, a fresh context per test, and
dist/index.html opened through its file:// URL with every other request refused.

Chromium: /usr/bin/chromium where it exists (Debian's package; `playwright install`
cannot download here), otherwise Playwright's own build. Launch flags from
notes/browser-testing.md: SwiftShader WebGL with no GPU, and no background traffic.
"""
import json
import os
import pathlib

import pytest

from browser_helpers import ARGS, DIST, ROOT, SYSTEM_CHROMIUM, VIEWPORT, page_url  # noqa: F401 (ROOT, DIST: used by test modules)


def pytest_collection_modifyitems(config, items):
    here = pathlib.Path(__file__).parent
    for item in items:
        if here in pathlib.Path(str(item.fspath)).parents:
            item.add_marker(pytest.mark.browser)


@pytest.fixture(scope='session')
def browser():
    sync_api = pytest.importorskip('playwright.sync_api')
    with sync_api.sync_playwright() as p:
        kwargs = {'args': ARGS}
        if os.path.exists(SYSTEM_CHROMIUM):
            kwargs['executable_path'] = SYSTEM_CHROMIUM
        b = p.chromium.launch(**kwargs)
        yield b
        b.close()


class Page:
    """A loaded page plus what it did: console errors, page errors, network attempts."""

    def __init__(self, context, page):
        self.context = context
        self.page = page
        self.errors = []
        self.requests = []

    def __getattr__(self, name):
        return getattr(self.page, name)

    def js(self, expr, arg=None):
        return self.page.evaluate(expr, arg)

    def state(self):
        # As JSON text: Playwright's own serialisation of a curtain's nested arrays takes
        # 130 ms, the text 6 ms, with the same doubles (-0 reads as 0, equal to it).
        return json.loads(self.page.evaluate('JSON.stringify(clothApp.state())'))

    def info(self):
        return self.page.evaluate('clothApp.info()')


@pytest.fixture
def open_page(browser):
    """open_page(query='', **context_options) -> Page. On teardown, fails the test on
    any console error, uncaught exception or non-file request."""
    opened = []

    def _open(query='', expect_errors=False, **ctx):
        assert DIST.exists(), 'dist/index.html is missing: run `python build.py`'
        ctx.setdefault('viewport', VIEWPORT)
        context = browser.new_context(**ctx)
        page = context.new_page()
        pg = Page(context, page)
        pg.expect_errors = expect_errors

        def route(r):
            url = r.request.url
            if url.startswith('file://'):
                r.continue_()
            else:
                pg.requests.append(url)
                r.abort()
        context.route('**/*', route)
        page.on('console', lambda m: pg.errors.append('console: ' + m.text) if m.type == 'error' else None)
        page.on('pageerror', lambda e: pg.errors.append('pageerror: ' + str(e)))
        page.goto(page_url(query))
        page.wait_for_function('window.clothApp && clothApp.info().frames >= 0')
        opened.append(pg)
        return pg

    yield _open
    for pg in opened:
        errors, requests = pg.errors, pg.requests
        pg.context.close()
        assert requests == [], 'the page made network requests: %r' % requests
        if not pg.expect_errors:
            assert errors == [], 'the page logged errors: %r' % errors
