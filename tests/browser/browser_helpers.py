"""Paths, launch flags and small helpers shared by the browser tests."""
import os
import pathlib

# CLOTH_ROOT lets the suite test another checkout's dist/ (default: this repository).
ROOT = pathlib.Path(os.environ.get('CLOTH_ROOT') or pathlib.Path(__file__).absolute().parents[2])
DIST = ROOT / 'dist' / 'index.html'
SYSTEM_CHROMIUM = '/usr/bin/chromium'
ARGS = ['--no-sandbox', '--enable-unsafe-swiftshader', '--disable-background-networking',
        '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
        '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE localhost , EXCLUDE 127.0.0.1']
VIEWPORT = {'width': 1000, 'height': 700}


def free_vertex(state, cols, rows):
    """The middle vertex of the bottom row (free in every preset with rows > 1)."""
    k = (rows - 1) * cols + cols // 2
    assert not state['pinned'][k]
    return k


def near(a, b, tol):
    return abs(a[0] - b[0]) <= tol and abs(a[1] - b[1]) <= tol
