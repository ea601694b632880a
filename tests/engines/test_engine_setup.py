"""Issue #16 point 3: a machine without an engine skips that engine's tests with the reason;
with CI=true a missing engine fails the run. Tried here by pointing the engines' paths
(engine_drivers: CLOTH_FIREFOX, CLOTH_MINIBROWSER) at nothing, in a pytest of its own."""
import os
import subprocess
import sys

from browser_helpers import ROOT


def run_without_engines(ci):
    env = dict(os.environ, CLOTH_FIREFOX='/nonexistent/firefox-esr',
               CLOTH_MINIBROWSER='/nonexistent/MiniBrowser')
    env.pop('CI', None)
    if ci:
        env['CI'] = 'true'
    return subprocess.run([sys.executable, '-m', 'pytest', '-q', '-rs', '-p', 'no:cacheprovider',
                           'tests/engines/test_engines.py', '-k', 'opens_from_file'],
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
