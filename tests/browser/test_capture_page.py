"""Export what you see (issue #24.3): Picture saves a PNG of the stage at the canvas's device
pixels, the cloth and the obstacles over it; Video records the stage as it plays
(MediaRecorder on a canvas's stream, the best format the browser has) and saves it, or says
why the browser cannot. Runs in Chromium here and in Firefox and WebKit (tests/engines/)."""
import base64
import re
import struct

import pytest

from browser_helpers import png_rgb, wait_settled


def noted(pg, note):
    """The page's note once it matches `note` (Playwright gives a handle, the engines a value)."""
    v = pg.wait_for_function('(r) => new RegExp(r).test(clothApp.info().note) && clothApp.info().note', arg=note)
    return v.json_value() if hasattr(v, 'json_value') else v


def saved(pg, click, note):
    """Click, and (name, bytes) of the file the page saved, whose name its note (matching
    `note`, a regex with the name as its group) gives. Playwright catches Chromium's download;
    Firefox and WebKit save into the engine's download folder."""
    if not hasattr(pg, 'engine'):
        with pg.expect_download() as d:
            click()
        name = d.value.suggested_filename
        assert re.search(note, noted(pg, note)).group(1) == name
        return name, open(d.value.path(), 'rb').read()
    click()
    name = re.search(note, noted(pg, note)).group(1)
    path = pg.engine.downloads / name
    size = -1
    for _ in range(200):
        if path.exists() and path.stat().st_size > 0 and path.stat().st_size == size:
            break
        size = path.stat().st_size if path.exists() else -1
        pg.wait_for_timeout(50)
    return name, path.read_bytes()


def test_picture_is_the_stage_at_device_pixels(open_page):
    pg = open_page('?paused=1&preset=towel')
    pg.js('clothApp.advance(90)')
    wait_settled(pg)
    # What the stage is as the picture is taken (paused: the picture draws this same frame).
    size = pg.js('''() => { const c = document.getElementById('view'); const r = c.getBoundingClientRect();
                          return [c.width, c.height, r.left, r.top, c.width / r.width]; }''')
    st = pg.state()
    pts = [[round(x), round(y)] for i, (x, y) in enumerate(st['screen']) if i % 5 == 0]
    drawn = pg.js('(p) => clothApp.pixels(p)', pts)
    lit = [i for i, c in enumerate(drawn) if c[0] > 60]
    assert len(lit) > len(pts) // 3
    peg = pg.js('(p) => clothApp.clientOf(p[0], p[1])', pg.js('clothApp.obstacles()')[0]['at'])
    # (WebKit then shows its download bar, which shortens the window: the stage changes after.)
    name, data = saved(pg, lambda: pg.locator('#btn-picture').click(), r'Picture saved as (cloth-towel-f\d+\.png)')
    width, height, bpp, rows = png_rgb(data)
    assert [width, height] == size[:2]

    def at(p):
        x, y = round((p[0] - size[2]) * size[4]), round((p[1] - size[3]) * size[4])
        return tuple(rows[y][x * bpp:x * bpp + 3])
    same = sum(1 for i in lit if max(abs(a - b) for a, b in zip(at(pts[i]), drawn[i][:3])) <= 40)
    assert same >= 0.8 * len(lit), (same, len(lit))
    grey = at(peg)
    assert min(grey) > 60 and max(grey) - min(grey) < 60, grey      # the peg's grey fill, not the dark stage


def test_video_records_the_stage_or_says_why_not(open_page):
    pg = open_page('?preset=flag')
    support = pg.js('clothCapture.videoSupport()')
    has = pg.js('!!window.MediaRecorder && !!document.createElement("canvas").captureStream')
    if support['why']:
        # The page's reason is the browser's: it lacks the recorder, the stream or a format.
        assert not has or not any(pg.js('(t) => MediaRecorder.isTypeSupported(t)', t)
                                  for t in ['video/webm', 'video/mp4'])
        pg.locator('#btn-video').click()
        assert pg.info()['note'] == 'Video: ' + support['why'] + '; Picture saves a PNG'
        assert pg.locator('#btn-video').inner_text() == 'Video'
        return
    pg.locator('#btn-video').click()
    assert pg.locator('#btn-video').inner_text() == 'Stop video'
    assert pg.info()['note'].startswith('Recording video (')
    pg.wait_for_timeout(1200)                       # the flag flies and gusts: frames change
    engine = getattr(pg, 'name', 'chromium')
    note = r'Video saved as (cloth-flag-f\d+\.(?:webm|mp4))'
    if engine == 'webkit':
        # WebKitGTK says yes to MP4 and, without GStreamer's encoders (this machine's), gives no
        # data: the page says so and saves nothing; with them, it saves the file.
        pg.locator('#btn-video').click()
        said = noted(pg, r'^Video( saved as|: the browser recorded nothing)')
        assert pg.locator('#btn-video').inner_text() == 'Video'
        if 'recorded nothing' in said:
            assert 'nothing saved' in said and not list(pg.engine.downloads.glob('cloth-flag-*'))
            return
        name, data = saved(pg, lambda: None, note)
    else:
        name, data = saved(pg, lambda: pg.locator('#btn-video').click(), note)
    assert pg.locator('#btn-video').inner_text() == 'Video'
    assert len(data) > 2000
    if name.endswith('.webm'):
        assert data[:4] == b'\x1a\x45\xdf\xa3'      # EBML: a WebM file
    else:
        assert data[4:8] == b'ftyp'                 # an MP4 file


# The saved video (base64) in a <video> of a blank page (the app's own page allows no media):
# its duration, and whether a seek to its middle lands.
PLAY = '''(b64) => new Promise(function (done) {
  const bin = atob(b64), bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  const v = document.createElement('video'); v.muted = true; v.preload = 'auto';
  v.onerror = function () { done({error: String(v.error && v.error.message)}); };
  v.onloadedmetadata = function () {
    const d = v.duration;
    if (!isFinite(d)) { done({duration: String(d)}); return; }
    v.onseeked = function () { done({duration: d, at: v.currentTime}); };
    v.currentTime = d / 2;
  };
  v.src = URL.createObjectURL(new Blob([bytes], {type: 'video/webm'})); })'''


def webm_duration_ms(data):
    """The Duration in a WebM's Info (ms), or None: the element 0x4489 of size 8, a float64 of
    ticks of the TimecodeScale (ns; 1e6 when the file says none)."""
    at = data.find(b'\x44\x89\x88', 0, 4096)
    if at < 0:
        return None
    ticks = struct.unpack('>d', data[at + 3:at + 11])[0]
    scale = data.find(b'\x2a\xd7\xb1', 0, 4096)
    ns = 1e6
    if scale >= 0:
        n = data[scale + 3] & 0x7f                  # a one-byte size
        ns = int.from_bytes(data[scale + 4:scale + 4 + n], 'big')
    return ticks * ns / 1e6


def test_a_saved_video_has_its_duration_and_seeks_even_when_made_paused(open_page):
    """MediaRecorder's WebM carries no duration: players show no length and cannot seek. The
    page writes it into the header; a video made while paused holds the paused picture for as
    long as it was paused (not one frame)."""
    pg = open_page('?preset=curtain&paused=1')
    support = pg.js('clothCapture.videoSupport()')
    if support['why'] or 'webm' not in support['type']:
        pytest.skip('this browser records no WebM: ' + (support['why'] or support['type']))
    pg.locator('#btn-video').click()
    pg.wait_for_timeout(1500)                       # paused all along
    name, data = saved(pg, lambda: pg.locator('#btn-video').click(), r'Video saved as (cloth-curtain-f\d+\.webm)')
    note = pg.info()['note']
    assert 'no duration' not in note, note
    seconds = float(re.search(r'\((\d+\.\d) s,', note).group(1))
    assert seconds >= 1.5
    ms = webm_duration_ms(data)
    assert ms is not None and ms == pytest.approx(seconds * 1000, abs=100), (ms, seconds)
    player = pg.context.new_page()
    played = player.evaluate(PLAY, base64.b64encode(data).decode())
    player.close()
    assert isinstance(played.get('duration'), float), played
    # The paused stretch is in the video: its frames run to the end (within a frame's time
    # at the recorder's lowest rate), and a seek to the middle lands there.
    assert played['duration'] == pytest.approx(seconds, abs=0.3), played
    assert played['at'] == pytest.approx(played['duration'] / 2, abs=0.3), played
