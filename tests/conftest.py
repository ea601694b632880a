"""Every run of the suite draws the same hypothesis examples (derandomize): a property test
explores widely, but a CI run on a clean clone must not pass or fail by the draw. Examples
that once failed are kept in the tests as @example."""
from hypothesis import settings

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
