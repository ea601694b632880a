"""A page in Firefox or WebKit with the small part of Playwright's Page that the Chromium tests
use (js, state, info, mouse, locator, goto, wait_for_function, set_input_files), so that the
tests of tests/browser/ that need nothing more run unchanged in the other engines.

Differences from Playwright, on purpose: WebDriver pointers take integer client coordinates,
so the mouse rounds (a grab keeps its offset from the pointer, so nothing jumps); one tab per
engine, so goto() replaces the document (a fresh load, never a fragment-only change).
"""
import time

# Installed in the page right after it loads (and, for the load test, inlined before the
# page's own scripts): uncaught errors, unhandled rejections, console.error, and CSP
# violations (every request the page would make is one: its CSP is default-src 'none').
HOOKS = r'''
(() => {
  if (window.__engineErrors) return;
  const out = window.__engineErrors = [];
  const text = (v) => { try { return v instanceof Error ? v.name + ': ' + v.message : String(v); } catch (e) { return '?'; } };
  window.addEventListener('error', (e) => out.push('error: ' + e.message + ' (' + e.filename + ':' + e.lineno + ')'));
  window.addEventListener('unhandledrejection', (e) => out.push('unhandledrejection: ' + text(e.reason)));
  document.addEventListener('securitypolicyviolation', (e) =>
      out.push('csp: ' + e.violatedDirective + ' blocked ' + e.blockedURI));
  const error = console.error;
  console.error = function () { out.push('console.error: ' + Array.from(arguments).map(text).join(' ')); return error.apply(console, arguments); };
})()
'''

ERRORS = '''() => window.__engineErrors ? window.__engineErrors.slice() : ['the page lost its error hooks']'''
REQUESTS = '''performance.getEntriesByType('resource').map((e) => e.name).filter((u) => !/^(file|data|blob):/.test(u))'''
READY = '!!(window.clothApp && window.clothCore) && clothApp.info().frames >= 0'
BUTTONS = {'left': 0, 'middle': 1, 'right': 2}


class Page:
    def __init__(self, engine, expect_errors=False):
        self.engine = engine
        self.name = engine.name
        self.expect_errors = expect_errors
        self.mouse = Mouse(engine)

    # ---- the seam ----
    def js(self, expr, arg=None):
        return self.engine.js(expr, arg)

    def state(self):
        return self.js('clothApp.state()')

    def info(self):
        return self.js('clothApp.info()')

    def at(self, k):
        """Vertex k's client position, rounded (WebDriver pointers take integers)."""
        x, y = self.state()['screen'][k]
        return round(x), round(y)

    # ---- loading ----
    def goto(self, url):
        """A fresh document at url (about:blank first: a fragment-only change would not
        reload). The errors of the document it replaces are kept for the teardown."""
        self.engine.harvest()
        self.engine.open('about:blank')
        self.engine.open(url)
        self.wait_for_function(READY)
        self.js(HOOKS)
        self.engine.current = self

    def wait_for_function(self, expr, arg=None, timeout=20.0):
        end = time.time() + timeout
        while True:
            value = self.js(expr, arg)
            if value:
                return value
            if time.time() > end:
                raise AssertionError('%s: timed out waiting for %s' % (self.name, expr))
            time.sleep(0.03)

    def wait_for_timeout(self, ms):
        time.sleep(ms / 1000)

    def errors(self):
        return self.js(ERRORS)

    def requests(self):
        return self.js(REQUESTS)

    # ---- elements ----
    def locator(self, selector):
        return Locator(self, selector)

    def set_input_files(self, selector, path):
        """WebDriver's Element Send Keys on a file input (hidden is fine for file inputs)."""
        self.engine.send_file(selector, str(path))

    def key(self, key):
        """A real key press (W3C key actions), e.g. 'e' for Export."""
        self.engine.actions([{'type': 'key', 'id': 'keyboard', 'actions': [
            {'type': 'keyDown', 'value': key}, {'type': 'keyUp', 'value': key}]}])

    def window_size(self, width, height):
        self.engine.window_size(width, height)
        self.engine.size = (width, height)


class Locator:
    def __init__(self, page, selector):
        self.page, self.selector = page, selector

    def _el(self, body):
        return self.page.js('(s) => { const el = document.querySelector(s); %s }' % body, self.selector)

    def inner_text(self):
        return self._el('return el.innerText;')

    def is_visible(self):
        return self._el('const r = el.getBoundingClientRect();'
                        ' return !el.closest("[hidden]") && getComputedStyle(el).visibility !== "hidden"'
                        ' && r.width > 0 && r.height > 0;')

    def is_hidden(self):
        return not self.is_visible()

    def centre(self):
        """The element's middle in the viewport, scrolled into view first (as a person scrolls
        the side panel to reach a control below the fold)."""
        r = self._el('el.scrollIntoView({block: "center"}); const r = el.getBoundingClientRect();'
                     ' return [r.left + r.width / 2, r.top + r.height / 2];')
        return round(r[0]), round(r[1])

    def click(self):
        """A real mouse click in the middle of the element."""
        x, y = self.centre()
        self.page.mouse.click(x, y)


class Mouse:
    """Playwright's page.mouse over W3C actions: trusted pointer events, integer coordinates.
    Each call returns after the page's next animation frame: WebDriver returns as soon as the
    events are dispatched, sooner than Playwright, and what the page measures at its frame (the
    strain a drag made) would otherwise be read before that frame."""

    def __init__(self, engine):
        self.engine = engine
        self.x = self.y = 0

    def _send(self, actions):
        self.engine.actions([{'type': 'pointer', 'id': 'mouse1', 'parameters': {'pointerType': 'mouse'},
                              'actions': actions}])
        self.engine.js('new Promise((done) => requestAnimationFrame(() => done()))')

    def _moves(self, x, y, steps):
        out = []
        x0, y0 = self.x, self.y
        for i in range(1, steps + 1):
            px, py = round(x0 + (x - x0) * i / steps), round(y0 + (y - y0) * i / steps)
            out.append({'type': 'pointerMove', 'x': px, 'y': py, 'origin': 'viewport', 'duration': 0})
        self.x, self.y = round(x), round(y)
        return out

    def move(self, x, y, steps=1):
        self._send(self._moves(x, y, steps))

    def down(self, button='left'):
        self.engine.pressed(BUTTONS[button])
        self._send([{'type': 'pointerDown', 'button': BUTTONS[button]}])

    def up(self, button='left'):
        self._send([{'type': 'pointerUp', 'button': BUTTONS[button]}])

    def click(self, x, y, button='left'):
        b = BUTTONS[button]
        self.engine.pressed(b)
        self._send(self._moves(x, y, 1) + [{'type': 'pointerDown', 'button': b},
                                           {'type': 'pointerUp', 'button': b}])
