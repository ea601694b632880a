"""Every control and every readout is on screen and uncovered (issue #41 item 4) at the four
viewport sizes a person brings (two laptops, two phones), on the page as it opens, with the
help open, and in compare mode with the most panels and an error banner showing: each one, its
scroll box scrolled to it as a person would, lies inside the viewport and its scroll box; no
two overlap; no readout's text is cut short; the compare panels lie clear of the readouts."""
import pytest

from cloth.keys import MAX_PANELS

SIZES = [(1280, 800), (1366, 768), (390, 844), (360, 640)]

PROBE = r'''(helpOnly) => {
  const vw = document.documentElement.clientWidth, vh = document.documentElement.clientHeight;
  const sel = 'button, input:not([type=hidden]), select, textarea, summary, a[href], #hud > div, #legend, .panel-label, #charts, #note, #banner, #rec-status';
  const root = helpOnly ? document.getElementById('help') : document;
  const els = Array.from(root.querySelectorAll(sel)).filter(function (e) {
    if (!helpOnly && e.closest('#help')) return false;
    if (e.hidden || e.closest('[hidden]')) return false;
    const cs = getComputedStyle(e); if (cs.display === 'none' || cs.visibility === 'hidden') return false;
    const d = e.closest('details'); if (d && !d.open && e.tagName !== 'SUMMARY' && !e.closest('summary')) return false;
    const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0;
  });
  function name(e) { return e.id || (typeof e.className === 'string' && e.className) || e.tagName + ':' + (e.type || '') + ':' + ((e.closest('label') || e).textContent || '').trim().slice(0, 24); }
  function scroller(e) {
    for (let p = e.parentElement; p && p !== document.body; p = p.parentElement) {
      const o = getComputedStyle(p).overflowY; if ((o === 'auto' || o === 'scroll') && p.scrollHeight > p.clientHeight) return p;
    }
    return null;
  }
  const bad = [];
  // 1. on screen: each one, its scroll box scrolled to it (as a person scrolls: only boxes that scroll)
  els.forEach(function (e) {
    const s = scroller(e);
    let clip = {left: 0, top: 0, right: vw, bottom: vh};
    if (s) {
      const sr = s.getBoundingClientRect(), r0 = e.getBoundingClientRect();
      // whole pixels, rounded away: an engine keeps scrollTop whole
      if (r0.top < sr.top) s.scrollTop -= Math.ceil(sr.top - r0.top);
      else if (r0.bottom > sr.bottom) s.scrollTop += Math.ceil(Math.min(r0.bottom - sr.bottom, r0.top - sr.top));
      clip = {left: Math.max(0, sr.left), top: Math.max(0, sr.top), right: Math.min(vw, sr.right), bottom: Math.min(vh, sr.bottom)};
    }
    const r = e.getBoundingClientRect();
    if (r.left < clip.left - 0.5 || r.top < clip.top - 0.5 || r.right > clip.right + 0.5 || r.bottom > clip.bottom + 0.5)
      bad.push(['off screen', name(e), [r.left, r.top, r.right, r.bottom].map(Math.round), [clip.left, clip.top, clip.right, clip.bottom].map(Math.round)]);
  });
  // 2. against each other, every scroll box at its top: each box clipped to its scroll box
  document.querySelectorAll('*').forEach(function (p) { if (p.scrollTop) p.scrollTop = 0; });
  const boxes = els.map(function (e) {
    const r = e.getBoundingClientRect(), s = scroller(e), c = s ? s.getBoundingClientRect() : {left: 0, top: 0, right: vw, bottom: vh};
    return {left: Math.max(r.left, c.left), top: Math.max(r.top, c.top), right: Math.min(r.right, c.right), bottom: Math.min(r.bottom, c.bottom)};
  });
  for (let i = 0; i < els.length; i++) for (let j = i + 1; j < els.length; j++) {
    const a = els[i], b = els[j];
    if (a.contains(b) || b.contains(a)) continue;
    const la = a.closest('label'), lb = b.closest('label'); if (la && la === lb) continue;
    const ra = boxes[i], rb = boxes[j];
    const ox = Math.min(ra.right, rb.right) - Math.max(ra.left, rb.left), oy = Math.min(ra.bottom, rb.bottom) - Math.max(ra.top, rb.top);
    if (ox > 1 && oy > 1) bad.push(['overlap', name(a), name(b), Math.round(ox), Math.round(oy)]);
  }
  // 3. no readout's text cut short (an ellipsis or a clipped line)
  document.querySelectorAll('#legend *, #hud *, .panel-label, .panel-label *, #help .card *').forEach(function (e) {
    if (e.closest('[hidden]') || getComputedStyle(e).display === 'none' || !e.textContent.trim()) return;
    if (e.scrollWidth > e.clientWidth + 1 && getComputedStyle(e).overflowX !== 'visible')
      bad.push(['cut short', name(e), e.textContent.trim().slice(0, 40), e.scrollWidth, e.clientWidth]);
  });
  return {n: els.length, bad: bad};
}
'''

# The compare panels' rectangles (canvas px) against the readouts' boxes (same origin).
PANELS_CLEAR = '''() => { const v = document.getElementById('view').getBoundingClientRect(), bad = [];
  const rects = clothApp.info().rects;
  ['hud', 'legend', 'charts'].forEach(function (id) {
    const e = document.getElementById(id); if (getComputedStyle(e).display === 'none') return;
    const b = e.getBoundingClientRect();
    rects.forEach(function (r, i) {
      const ox = Math.min(r[0] + r[2], b.right - v.left) - Math.max(r[0], b.left - v.left);
      const oy = Math.min(r[1] + r[3], b.bottom - v.top) - Math.max(r[1], b.top - v.top);
      if (ox > 1 && oy > 1) bad.push([id, 'covers panel', i + 1, Math.round(ox), Math.round(oy)]);
    });
  });
  return bad; }'''


def walk(pg, size):
    """The checks on an open page of `size` (any engine: only js, locators and waits)."""
    pg.wait_for_function('() => /\\d/.test(document.getElementById("r-size").textContent)')
    seen = pg.js(PROBE, False)
    assert seen['n'] > 30 and seen['bad'] == [], (size, seen)
    # The help: its card and its Close inside the screen.
    pg.locator('#btn-help').click()
    seen = pg.js(PROBE, True)
    assert seen['n'] >= 1 and seen['bad'] == [], (size, seen)
    card = pg.js("() => document.querySelector('#help .card').getBoundingClientRect().toJSON()")
    assert card['top'] >= 0 and card['left'] >= 0 and card['bottom'] <= size[1] and card['right'] <= size[0], card
    pg.locator('#help-close').click()
    # Compare mode with the most panels, a note and an error showing.
    pg.js('(n) => clothApp.compare(Array.from({length: n}, (_, i) => ({iterations: i + 2})))', MAX_PANELS)
    pg.js('clothApp.advance(2)')
    pg.js("() => { document.getElementById('json-box').open = true;"
          " document.getElementById('scene-json').value = '{\"cols\": \"many\"}'; }")
    pg.locator('#btn-load-json').click()                    # a scene refused: the banner
    assert pg.info()['panels'] == MAX_PANELS and pg.info()['error'] != ''
    pg.wait_for_timeout(400)                                # the readouts' next refresh
    seen = pg.js(PROBE, False)
    assert seen['n'] > 30 and seen['bad'] == [], (size, seen)
    assert pg.js(PANELS_CLEAR) == [], size


@pytest.mark.parametrize('size', SIZES, ids=['%dx%d' % s for s in SIZES])
def test_every_control_and_readout_is_on_screen_and_uncovered(open_page, size):
    phone = size[0] < 500
    walk(open_page('?paused=1', viewport={'width': size[0], 'height': size[1]}, has_touch=phone, is_mobile=phone), size)
