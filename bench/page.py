"""The benchmark's browser: the shipped page, dist/index.html, in headless Chromium through
Playwright, with the benchmark's JS (bench/harness.js) added; every figure is measured by the
JS the page ships."""

import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DIST = os.path.join(ROOT, 'dist', 'index.html')
SYSTEM_CHROMIUM = '/usr/bin/chromium'
ARGS = ['--no-sandbox', '--enable-unsafe-swiftshader', '--disable-background-networking',
        '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
        '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE localhost , EXCLUDE 127.0.0.1']

# The benchmark's JS: bench/harness.js, on webgl/sim/runner.js (shipped in the page: the code the
# page's compare mode measures with).
HARNESS = os.path.join(ROOT, 'bench', 'harness.js')


class Progress:
    def __init__(self):
        self.t0 = time.monotonic()

    def __call__(self, message):
        sys.stderr.write('[%6.1fs] %s\n' % (time.monotonic() - self.t0, message))
        sys.stderr.flush()

    def elapsed(self):
        return time.monotonic() - self.t0


def page_of(browser, errors):
    """A new tab on dist/index.html that may fetch nothing else; page errors go to `errors`."""
    page = browser.new_page()
    page.on('pageerror', lambda e: errors.append(str(e)))
    page.route('**/*', lambda route: route.continue_() if route.request.url.startswith('file:')
               else route.abort())
    page.goto('file://' + DIST + '?worker=0')   # the benchmark steps cloths itself (harness.js)
    return page


def open_page(p, progress):
    if not os.path.exists(DIST):
        raise BenchError('dist/index.html is missing: build it with `python build.py`')
    kwargs = {'args': ARGS}
    if os.path.exists(SYSTEM_CHROMIUM):
        kwargs['executable_path'] = SYSTEM_CHROMIUM
    browser = p.chromium.launch(**kwargs)
    errors = []
    page = page_of(browser, errors)
    if not page.evaluate("() => typeof window.clothCore === 'object' && window.clothCore !== null"
                         " && typeof window.clothCore.load === 'function'"):
        browser.close()
        raise BenchError('dist/index.html has no window.clothCore (page errors: %s); '
                         'rebuild it with `python build.py`' % ('; '.join(errors) or 'none'))
    # Stop the app so that only the benchmark computes: pause it, and end its render loop
    # (this page instance is the benchmark's own; nothing else uses it).
    page.evaluate("""() => {
      if (window.clothApp && typeof window.clothApp.setPaused === 'function')
        window.clothApp.setPaused(true);
      window.requestAnimationFrame = function () { return 0; };
    }""")
    if not page.evaluate("() => typeof window.clothRunner === 'object'"):
        browser.close()
        raise BenchError('dist/index.html has no window.clothRunner; rebuild it with `python build.py`')
    page.add_script_tag(path=HARNESS)
    progress('Chromium %s (%s), page %s' % (browser.version, kwargs.get('executable_path',
             'Playwright build'), os.path.relpath(DIST, ROOT)))
    return browser, page


class BenchError(Exception):
    pass
