"""Paths, launch flags and small helpers shared by the browser tests."""
import json
import os
import struct
import zlib
import pathlib
import time

from cloth.presets import PRESETS, preset_scene

# CLOTH_ROOT lets the suite test another checkout's dist/ (default: this repository).
ROOT = pathlib.Path(os.environ.get('CLOTH_ROOT') or pathlib.Path(__file__).absolute().parents[2])
DIST = ROOT / 'dist' / 'index.html'
SYSTEM_CHROMIUM = '/usr/bin/chromium'
ARGS = ['--no-sandbox', '--enable-unsafe-swiftshader', '--disable-background-networking',
        '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
        '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE localhost , EXCLUDE 127.0.0.1']
VIEWPORT = {'width': 1000, 'height': 700}
BACKGROUND_MAX = 30  # every channel of the page's background colour is below this


def page_url(query=''):
    """dist/index.html with `query` ('?a=b', '#fragment' or both) and worker=0: the session on the
    page's own thread, where the test seam's advance() and state() are synchronous (in a Web
    Worker, the page's default, advance() returns a Promise: tests/browser/test_worker_page.py)."""
    fragment = ''
    if '#' in query:
        query, fragment = query.split('#', 1)
        fragment = '#' + fragment
    query = query[1:] if query.startswith('?') else query
    return DIST.as_uri() + '?worker=0' + ('&' + query if query else '') + fragment


def free_vertex(state, cols, rows):
    """The middle vertex of the bottom row (free in every preset with rows > 1)."""
    k = (rows - 1) * cols + cols // 2
    assert not state['pinned'][k]
    return k


def near(a, b, tol):
    return abs(a[0] - b[0]) <= tol and abs(a[1] - b[1]) <= tol


def wait_until(pg, expr, timeout=20.0):
    """Poll a page expression until it is true (the page's CSP forbids the eval that
    Playwright's wait_for_function uses for a string that is not a function)."""
    end = time.time() + timeout
    while time.time() < end:
        if pg.js(expr):
            return
        time.sleep(0.03)
    raise AssertionError('timed out waiting for ' + expr)


def bytes_under(node, name, inside=False):
    """What the page's own code under function `name` allocated, in a sampling heap profile:
    the profile also holds the engine's idle-time external bookkeeping and Playwright's
    serialisation of the result, which grow with the run's length, not with the frames."""
    inside = inside or node['callFrame']['functionName'] == name
    return (node['selfSize'] if inside else 0) + sum(bytes_under(c, name, inside) for c in node['children'])


# A sampling heap profile that keeps the samples of objects collected since (garbage), not only
# of those still alive when it stops.
GARBAGE_TOO = {'samplingInterval': 256, 'includeObjectsCollectedByMajorGC': True,
               'includeObjectsCollectedByMinorGC': True}


def steady_bytes_per_frame(cdp, advance, frames, name, limit, windows=4):
    """Bytes a frame that the page's code under function `name` allocates, garbage included
    (the profile keeps the samples of objects collected since: without that, a list made every
    frame went unseen), over successive windows of `frames` frames (`advance(n)` runs them)
    until one is within `limit`. A per-frame allocation shows in every window; V8 finishing its
    optimisation shows in one (measured 2026-12-04: a late deoptimisation of `solve_lines` or
    `project_cells` on a branch first taken then, "insufficient type feedback", about 10 kB
    once between frames 3000 and 6000). Returns every window's figure."""
    cdp.send('HeapProfiler.enable')
    per_frame = []
    for _ in range(windows):
        cdp.send('HeapProfiler.startSampling', GARBAGE_TOO)
        advance(frames)
        profile = cdp.send('HeapProfiler.stopSampling')['profile']
        per_frame.append(bytes_under(profile['head'], name) / frames)
        if per_frame[-1] < limit:
            break
    return per_frame


# Run n frames of the first panel's cloth one by one in the page and watch it: each frame's
# fastest vertex (its move over the frame, per second) and the highest y any vertex reached.
# In the page, so that a test of a 1200-vertex cloth does not fetch its state every frame.
WATCH = '''(n) => { const c = clothApp.cloth(), pos = c.pos, fps = 1 / c.dt;
    const out = {fastest: [], top: -Infinity};
    const before = Float64Array.from(pos);
    for (let f = 0; f < n; f++) {
      clothApp.advance(1, true);
      let most = 0;
      for (let i = 0; i < c.n_verts; i++) {
        most = Math.max(most, Math.hypot(pos[2 * i] - before[2 * i], pos[2 * i + 1] - before[2 * i + 1]) * fps);
        out.top = Math.max(out.top, pos[2 * i + 1]);
      }
      out.fastest.push(most);
      before.set(pos);
    }
    return out; }'''


def default_preset_at(cols, rows):
    """The scene of the page's default preset (the first of cloth/presets.py PRESETS) on a grid of
    cols x rows, as text: a test whose recording the CLI replays frame by frame runs it smaller
    (CPython steps the full 40x30 at about 0.1 s a frame)."""
    return json.dumps(preset_scene(PRESETS[0][0], cols, rows))


def load_paused(pg, text):
    """Load a scene and pause in one task: no animation frame runs between them (from two
    calls, a loaded machine ran frames in the gap, and a test's frame numbers drifted)."""
    pg.js('(t) => { clothApp.loadScene(t); clothApp.setPaused(true); }', text)


def png_rgb(data):
    """(width, height, rows of RGB(A) bytes) of an 8-bit, non-interlaced PNG: enough for a
    screenshot, with no imaging library."""
    assert data[:8] == b'\x89PNG\r\n\x1a\n'
    pos, idat = 8, b''
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            width, height, depth, colour, _, _, interlace = struct.unpack('>IIBBBBB', body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    rows, prev = [], bytearray(stride)
    for r in range(height):
        f, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, bpp, rows


SETTLED = '''() => { const c = document.getElementById('view'), r = c.getBoundingClientRect();
    const key = [innerWidth, innerHeight, r.width, r.height, c.width, c.height].join();
    if (window.__settle !== key) { window.__settle = key; window.__since = performance.now(); return false; }
    return performance.now() - window.__since > 300 && c.width === Math.round(r.width * devicePixelRatio)
        && c.height === Math.round(r.height * devicePixelRatio); }'''


def wait_settled(pg):
    """The window at its size: a fresh engine window may still be resized after the page
    loaded (WebKit under Xvfb), and a press or a picture computed before that lands where the
    view no longer is. Settled: the same sizes for 300 ms, the drawing buffer following."""
    pg.wait_for_function(SETTLED)
