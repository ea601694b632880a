"""Issue #16 point 3: a machine without an engine skips that engine's tests with the reason;
with CI=true a missing engine fails the run. Tried here by pointing the engines' paths
(engine_drivers: CLOTH_FIREFOX, CLOTH_MINIBROWSER) at nothing, in a pytest of its own."""
import os
import subprocess
import sys
import time

import pytest

from browser_helpers import ROOT


def run_without_engines(ci):
    env = dict(os.environ, CLOTH_FIREFOX='/nonexistent/firefox-esr',
               CLOTH_MINIBROWSER='/nonexistent/MiniBrowser')
    env.pop('CI', None)
    if ci:
        env['CI'] = 'true'
    return subprocess.run([sys.executable, '-m', 'pytest', '-q', '-rs', '-n', '0', '-p', 'no:cacheprovider',
                           'tests/browser/engines/test_engines.py', '-k', 'opens_from_file'],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=300)


def test_a_missing_engine_is_skipped_with_the_reason():
    done = run_without_engines(ci=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert '2 skipped' in done.stdout, done.stdout
    assert 'firefox is not installed (/nonexistent/firefox-esr)' in done.stdout, done.stdout
    assert 'webkit is not installed (/nonexistent/MiniBrowser)' in done.stdout, done.stdout


def test_with_ci_true_a_missing_engine_fails_the_run():
    done = run_without_engines(ci=True)
    assert done.returncode == 1, done.stdout + done.stderr
    assert '2 errors' in done.stdout, done.stdout
    assert 'CI=true and firefox is not installed' in done.stdout, done.stdout
    assert 'CI=true and webkit is not installed' in done.stdout, done.stdout


def test_a_webkit_driver_that_never_answers_is_started_afresh_then_fails_clearly(tmp_path, monkeypatch,
                                                                                capsys):
    # A stand-in for WebKitWebDriver that listens on its port, takes every connection and
    # answers none: the hang seen once in a loaded CI run. The start must not wait forever.
    import engine_drivers
    fake = tmp_path / 'fake-webkit-driver'
    fake.write_text('#!%s\n' % sys.executable +
                    'import socket, sys, time\n'
                    'port = int(sys.argv[sys.argv.index("-p") + 1] if "-p" in sys.argv else\n'
                    '           [a for a in sys.argv if a.startswith("--port=")][0][7:])\n'
                    's = socket.socket(); s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)\n'
                    's.bind(("127.0.0.1", port)); s.listen(16)\n'
                    'held = []\n'
                    'while True:\n'
                    '    held.append(s.accept()[0])\n')
    fake.chmod(0o755)
    monkeypatch.setattr(engine_drivers, 'WEBKIT_DRIVER', str(fake))
    monkeypatch.setattr(engine_drivers, 'START_WAIT', 2)
    monkeypatch.setattr(engine_drivers, 'MINIBROWSER', '/bin/true')   # never launched
    downloads = tmp_path / 'downloads'
    downloads.mkdir()
    started = time.monotonic()
    with pytest.raises(RuntimeError, match='answered no new session within 2 s, twice'):
        engine_drivers.WebKit(':0', str(downloads))
    assert time.monotonic() - started < 60
    assert 'answered no new session within 2 s: started afresh' in capsys.readouterr().err
