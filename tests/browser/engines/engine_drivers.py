"""Firefox ESR (marionette-driver) and WebKitGTK (WebKitWebDriver + selenium) behind one small
API, plus the Xvfb they need (neither creates a WebGL context headless).

Only what the tests use: open a URL, evaluate JS in the page's global scope (the result comes
back as JSON text, so doubles arrive exact), W3C pointer actions, the window size, a PNG
screenshot. The recipe and its traps are in ../shared/notes/browser-testing.md.
"""
import gc
import glob
import json
import os
import pathlib
import select
import shutil
import subprocess
import sys
import threading
import time


def _find(env, *candidates):
    """$env if set (a path, or 'none' to pretend the engine is missing), else the first
    candidate that exists: a command on PATH or a glob."""
    if os.environ.get(env):
        return os.environ[env]
    for c in candidates:
        found = shutil.which(c) if '/' not in c else next(iter(sorted(glob.glob(c))), None)
        if found:
            return found
    return candidates[0]


FIREFOX = _find('CLOTH_FIREFOX', 'firefox-esr', 'firefox')
# Debian's webkit2gtk-driver: the driver on PATH, MiniBrowser in the multiarch library folder.
MINIBROWSER = _find('CLOTH_MINIBROWSER', '/usr/lib/*/webkit2gtk-4.1/MiniBrowser', '/usr/lib/*/webkit2gtk-4.0/MiniBrowser')
WEBKIT_DRIVER = _find('CLOTH_WEBKIT_DRIVER', 'WebKitWebDriver')
START_WAIT = 90    # s: a WebKit session that has not answered by then never will
XVFB = _find('CLOTH_XVFB', 'Xvfb')
SCREEN = '1280x1024x24'

# Evaluates an expression in the page's own realm: a function is called with the argument and
# awaited, anything else is awaited; the value comes back as JSON text. Not in the WebDriver
# script itself: Firefox runs that with builtins of its own (there the page's arrays are not
# `instanceof Array` and its errors not `instanceof Error`), so the expression goes into a
# <script> element (the page's CSP allows inline scripts) and hands its result to a callback.
CALL = '''
const key = arguments[0], source = arguments[1];
return new Promise((resolve) => {
  const back = window[key] = (text) => { delete window[key]; resolve(text); };
  const s = document.createElement('script');
  s.textContent = source;
  document.documentElement.appendChild(s);
  s.remove();
  if (!back.ran) back(null);           // it did not parse
});'''
SOURCE = '''window[%s].ran = true;
(async () => {
  const __arg = %s;
  const __f = (%s);
  return typeof __f === 'function' ? await __f(__arg) : await __f;
})().then((v) => ['ok', JSON.stringify(v === undefined ? null : v)],
          (e) => ['error', e instanceof Error ? e.name + ': ' + e.message : String(e)])
  .then((r) => window[%s](r));'''


class PageError(Exception):
    """An expression threw (or its Promise rejected) in the page."""


class Xvfb:
    """One X server on a free display number (Xvfb picks it: -displayfd)."""

    def __init__(self):
        read, write = os.pipe()
        self.proc = subprocess.Popen([XVFB, '-displayfd', str(write), '-screen', '0', SCREEN,
                                      '-nolisten', 'tcp'], pass_fds=(write,),
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write)
        number, end = b'', time.time() + 30
        while not number.endswith(b'\n'):
            ready = select.select([read], [], [], max(0.0, end - time.time()))[0]
            chunk = os.read(read, 16) if ready else b''
            if not chunk:
                self.stop()
                raise RuntimeError('Xvfb did not start')
            number += chunk
        os.close(read)
        self.display = ':' + number.decode().strip()

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()


def missing(name):
    """Why engine `name` cannot run here ('' when it can)."""
    need = {'firefox': [FIREFOX, XVFB], 'webkit': [MINIBROWSER, WEBKIT_DRIVER, XVFB]}[name]
    gone = [p for p in need if not (os.path.isfile(p) and os.access(p, os.X_OK))]
    module = {'firefox': 'marionette_driver', 'webkit': 'selenium'}[name]
    try:
        __import__(module)
    except ImportError:
        gone.append('the Python package ' + module.replace('_', '-'))
    if not gone:
        return ''
    return '%s is not installed (%s): apt-get install -y %s xvfb; pip install -e ".[test]"' % (
        name, ', '.join(gone), {'firefox': 'firefox-esr', 'webkit': 'webkit2gtk-driver'}[name])


class Engine:
    name = ''
    version = ''
    current = None      # the Page loaded now
    size = None         # the viewport set last
    harvested = ()      # errors of the documents replaced since the last take_errors()

    def harvest(self):
        """Keep the errors of the document about to be replaced."""
        if self.current is not None:
            try:
                found = self.current.errors() + ['request: ' + u for u in self.current.requests()]
            except Exception as e:         # a document that is gone cannot be asked
                found = ['could not read the errors: %s' % e]
            if not self.current.expect_errors:
                self.harvested = list(self.harvested) + found
            self.current = None

    def take_errors(self):
        self.harvest()
        out, self.harvested = list(self.harvested), ()
        return out

    calls = 0
    stuck = ''

    def pressed(self, button):
        """A mouse button goes down (WebKit keeps track: see WebKit.pressed)."""

    def device_scale(self, factor):
        """Make devicePixelRatio `factor` (1 or 2) for the pages opened from now on."""
        raise NotImplementedError

    def restart(self):
        pass

    def js(self, expr, arg=None):
        self.calls += 1
        key = '__engineCall%d' % self.calls
        result = self._execute(CALL, [key, SOURCE % (json.dumps(key), json.dumps(arg), expr, json.dumps(key))])
        if result is None:
            raise PageError('%s: the expression did not run (a syntax error?): %s' % (self.name, expr))
        kind, value = result
        if kind != 'ok':
            raise PageError('%s: %s\n  in: %s' % (self.name, value, expr))
        return json.loads(value)

    def window_size(self, width, height):
        """Set the viewport (innerWidth x innerHeight) to width x height CSS pixels."""
        for _ in range(3):
            inner = self.js('[window.innerWidth, window.innerHeight, window.outerWidth, window.outerHeight]')
            if inner[:2] == [width, height]:
                return
            self._window_rect(width + inner[2] - inner[0], height + inner[3] - inner[1])
            time.sleep(0.1)
        raise AssertionError('the %s viewport stays %r, not %dx%d' % (self.name, inner[:2], width, height))


class Firefox(Engine):
    name = 'firefox'

    def __init__(self, display, downloads):
        self.display, self.downloads = display, downloads
        self.start()

    def start(self):
        from marionette_driver.marionette import Marionette
        display, downloads = self.display, self.downloads
        self.log = pathlib.Path(downloads).parent / 'gecko.log'
        prefs = {
            'devtools.console.stdout.content': True,     # the page's console.* and errors in the log
            'devtools.console.stdout.chrome': False,     # not the browser's own
            'messaging-system.rsexperimentloader.enabled': False, 'app.normandy.enabled': False,
            'datareporting.policy.dataSubmissionEnabled': False, 'toolkit.telemetry.enabled': False,
            'extensions.update.enabled': False, 'browser.newtabpage.enabled': False,
            'browser.download.folderList': 2, 'browser.download.dir': str(downloads),
            'browser.download.useDownloadDir': True, 'browser.download.always_ask_before_handling_new_types': False,
            'browser.download.alwaysOpenPanel': False,
            'network.proxy.type': 0, 'browser.safebrowsing.malware.enabled': False,
            'browser.safebrowsing.phishing.enabled': False, 'app.update.enabled': False,
        }
        old = os.environ.get('DISPLAY')
        os.environ['DISPLAY'] = display                  # mozrunner copies os.environ
        try:
            self.m = Marionette(bin=FIREFOX, headless=False, port=0, gecko_log=str(self.log),
                                prefs=prefs, startup_timeout=120)
            # Not strict: WebDriver may send a path to the page's hidden file input, as a
            # person's file picker would fill it.
            self.m.start_session({'strictFileInteractability': False})
        finally:
            if old is None:
                os.environ.pop('DISPLAY', None)
            else:
                os.environ['DISPLAY'] = old
        self.m.timeout.script = 600
        self.m.timeout.page_load = 120
        self.version = self.m.session_capabilities.get('browserVersion', '')

    def open(self, url):
        self.m.navigate(url)

    def _execute(self, body, args):
        # sandbox=None: the page's window (the default sandbox cannot see the page's globals).
        return self.m.execute_script(body, script_args=args, sandbox=None, new_sandbox=False)

    def actions(self, sources):
        self.m.actions.perform(sources)

    def release(self):
        self.m.actions.release()

    def _window_rect(self, width, height):
        # Not WebDriver's Set Window Rect: without a window manager it waits 5 s for a
        # window-state event that never comes. The chrome window's own resizeTo is immediate.
        with self.m.using_context('chrome'):
            self.m.execute_script('window.resizeTo(arguments[0], arguments[1])', script_args=[width, height])

    def screenshot(self):
        return self.m.screenshot(format='binary', full=False)

    def send_file(self, selector, path):
        self.m.find_element('css selector', selector).send_keys(path)

    def prompt(self):
        """The text of an open window.prompt/alert, dismissed; None when there is none."""
        from marionette_driver.errors import NoAlertPresentException
        from marionette_driver.marionette import Alert
        try:
            alert = Alert(self.m)
            text = alert.text
            alert.dismiss()
            return text
        except NoAlertPresentException:
            return None

    def device_scale(self, factor):
        if factor == 1:
            self.m.clear_pref('layout.css.devPixelsPerPx')
        else:
            self.m.set_pref('layout.css.devPixelsPerPx', str(float(factor)))
        self.size = None

    def log_text(self):
        try:
            return self.log.read_text(encoding='utf-8', errors='replace')
        except OSError:
            return ''

    def quit(self):
        m, self.m = self.m, None
        try:
            m.quit(in_app=False)
        finally:
            m.cleanup()
            # Drop the profile now: its __del__ at interpreter exit prints an ImportError.
            del m
            gc.collect()

    def restart(self):
        """A new Firefox after the last one died (ESR once exited with SIGSEGV loading the page,
        and every later test of the run failed on its dead session). Its log is kept beside."""
        try:
            self.quit()
        except Exception:
            pass
        if self.log.exists():
            self.log.replace(self.log.with_suffix('.died.log'))
        self.start()
        self.current, self.size = None, None


class WebKit(Engine):
    name = 'webkit'
    scale = 1

    def __init__(self, display, downloads):
        self.display, self.downloads = display, downloads
        self.start()

    def start(self):
        from selenium import webdriver
        from selenium.webdriver.webkitgtk.options import Options
        from selenium.webdriver.webkitgtk.service import Service
        options = Options()
        options.binary_location = MINIBROWSER
        options.add_argument('--automation')             # without it the session never starts
        # Downloads go to the XDG download folder, else $HOME: a test's own folder here.
        config = pathlib.Path(self.downloads).parent / 'xdg-config'
        config.mkdir(exist_ok=True)
        (config / 'user-dirs.dirs').write_text('XDG_DOWNLOAD_DIR="%s"\n' % self.downloads)
        env = dict(os.environ, DISPLAY=self.display, XDG_CONFIG_HOME=str(config), GDK_SCALE=str(self.scale))
        self.log = pathlib.Path(self.downloads).parent / 'webkit.log'
        # WebKitWebDriver sometimes never answers a new session: its MiniBrowser never
        # connects, and the request waits forever (seen once in a loaded run, in a restart
        # for devicePixelRatio 2; the driver's log was empty). A session answers in seconds
        # even under load, so a start that has not answered in START_WAIT is that hang: the
        # driver is killed and started afresh, once, saying so on stderr. Any other error,
        # or a second hang, fails the start.
        for attempt in (1, 2):
            service = Service(executable_path=WEBKIT_DRIVER, log_output=str(self.log), env=env)
            done = {}

            def connect():
                try:
                    done['driver'] = webdriver.WebKitGTK(options=options, service=service)
                except Exception as err:       # handed to the caller below
                    done['error'] = err
            thread = threading.Thread(target=connect, daemon=True)
            thread.start()
            thread.join(START_WAIT)
            if not thread.is_alive():
                if 'error' in done:
                    raise done['error']
                self.d = done['driver']
                break
            if service.process is not None:
                service.process.kill()
            thread.join(30)
            if attempt == 2:
                raise RuntimeError('WebKitWebDriver answered no new session within %d s, twice'
                                   % START_WAIT)
            sys.stderr.write('\nWebKitWebDriver answered no new session within %d s: started '
                             'afresh\n' % START_WAIT)
        self.d.set_script_timeout(600)
        self.d.set_page_load_timeout(120)
        self.version = self.d.capabilities.get('browserVersion', '')

    def open(self, url):
        self.d.get(url)

    def _execute(self, body, args):
        return self.d.execute_script(body, *args)

    def actions(self, sources):
        self.d.execute('actions', {'actions': sources})

    def release(self):
        self.d.execute('clearActionState')

    def _window_rect(self, width, height):
        self.d.set_window_rect(width=width, height=height)

    def screenshot(self):
        return self.d.get_screenshot_as_png()

    def send_file(self, selector, path):
        self.d.find_element('css selector', selector).send_keys(path)

    def prompt(self):
        from selenium.common.exceptions import NoAlertPresentException
        try:
            alert = self.d.switch_to.alert
            text = alert.text
            alert.dismiss()
            return text
        except NoAlertPresentException:
            return None

    def log_text(self):
        return ''          # WebKitWebDriver has no log endpoint: errors are caught in the page

    def quit(self):
        self.d.quit()

    def restart(self):
        """A new session (and MiniBrowser): the only way to let go of a stuck button."""
        self.harvest()
        self.quit()
        self.start()
        self.current, self.size, self.stuck = None, None, ''

    def device_scale(self, factor):
        """GTK's scale is read once, at start: a new MiniBrowser."""
        self.scale = factor
        self.restart()

    # WebKit's automation releases every mouse button as the left one: SimulatedInputDispatcher
    # simulates pointerUp with the state after the release (no button: MouseButton::None), which
    # WebAutomationSessionGtk turns into GDK_BUTTON_PRIMARY, so the right (or middle) button
    # stays in its pressed-button mask for the rest of the session. The page then sees
    # `buttons: 2` on every later event, and a later press is a chorded pointermove, not a
    # pointerdown. A right-click is therefore the last press of a WebKit session.
    def pressed(self, button):
        if self.stuck:
            raise AssertionError('webkit: a press after a right-click in the same session never reaches '
                                 'the page as a pointerdown (%s); restart the engine first' % self.stuck)
        if button != 0:
            self.stuck = 'button %d is stuck' % button


ENGINES = {'firefox': Firefox, 'webkit': WebKit}
