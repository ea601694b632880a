"""docs/tests.md's CPython-only command, `python -m pytest tests --ignore=tests/browser`, starts no
browser: every test that drives a browser (Chromium through Playwright, Firefox and WebKit
through their drivers, the benchmark's page) lives under tests/browser/. Checked on the
sources, so a new test that starts one outside it fails here before it slows that command."""
import ast
import pathlib

TESTS = pathlib.Path(__file__).absolute().parent
BROWSER = TESTS / 'browser'
# Modules that start or drive a browser, and commands that do.
BROWSER_MODULES = ('playwright', 'selenium', 'browser_helpers', 'engine_drivers', 'engine_page',
                   'bench.page', 'bench.__main__')
BROWSER_WORDS = ('chromium', 'firefox', 'webkit', 'minibrowser', "'bench'", '"bench"')


def outside_browser():
    return sorted(p for p in TESTS.rglob('*.py') if BROWSER not in p.parents)


def imported(tree):
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                yield alias.name
        elif isinstance(node, ast.ImportFrom) and node.module:
            yield node.module
            for alias in node.names:
                yield node.module + '.' + alias.name


def test_no_test_outside_tests_browser_imports_a_browser_driver():
    found = []
    for path in outside_browser():
        for name in imported(ast.parse(path.read_text(encoding='utf-8'))):
            if any(name == m or name.startswith(m + '.') for m in BROWSER_MODULES):
                found.append('%s imports %s' % (path.relative_to(TESTS), name))
    assert not found, found


def test_no_test_outside_tests_browser_names_a_browser_or_the_benchmark():
    found = []
    for path in outside_browser():
        for node in ast.walk(ast.parse(path.read_text(encoding='utf-8'))):
            if isinstance(node, ast.Call):
                text = ast.unparse(node).lower()
                if ('subprocess' in text or 'popen' in text or 'launch' in text) and \
                        any(w in text for w in BROWSER_WORDS):
                    found.append('%s: %s' % (path.relative_to(TESTS), ast.unparse(node)[:80]))
    assert not found, found


def test_the_browser_tests_are_where_the_readme_says():
    assert (BROWSER / 'engines' / 'test_engines.py').exists()
    assert (BROWSER / 'test_bench.py').exists()
    assert not (TESTS / 'engines').exists()
