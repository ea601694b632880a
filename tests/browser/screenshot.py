"""Regenerate docs/screenshot.png from dist/index.html (not a test).

    python tests/browser/screenshot.py [--mode strain|stress] [--out docs/screenshot.png]
    python tests/browser/screenshot.py --compare --out docs/compare.png

Loads the "two corners" preset, lets it settle, pulls a bottom vertex down and to the
side with the mouse and photographs the page while the vertex is held. With --compare, the
seed's method and the default side by side under the same hand.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser_helpers import ARGS, DIST, ROOT, SYSTEM_CHROMIUM, page_url  # noqa: E402
sys.path.insert(0, str(ROOT))
from cloth.keys import SOLVERS  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--mode', default='strain', choices=['strain', 'stress'])
    ap.add_argument('--solver', default='jakobsen', choices=SOLVERS)
    ap.add_argument('--out', default=str(ROOT / 'docs' / 'screenshot.png'))
    ap.add_argument('--compare', action='store_true', help='seed vs default, side by side')
    args = ap.parse_args()
    from playwright.sync_api import sync_playwright
    with sync_playwright() as p:
        kwargs = {'args': ARGS}
        if os.path.exists(SYSTEM_CHROMIUM):
            kwargs['executable_path'] = SYSTEM_CHROMIUM
        browser = p.chromium.launch(**kwargs)
        page = browser.new_page(viewport={'width': 1200, 'height': 720})
        page.goto(page_url('?preset=corners'))
        page.wait_for_function('window.clothApp && clothApp.info().frames > 0')
        page.evaluate("(m) => clothApp.setColorMode(m)", args.mode)
        if args.solver != 'jakobsen':
            page.evaluate("(s) => clothApp.setSolver(s)", args.solver)
        if args.compare:
            page.click('#btn-compare-pair')
        page.evaluate('clothApp.setPaused(true)')
        page.evaluate('clothApp.advance(240)')
        st = page.evaluate('clothApp.state()')
        cols = page.evaluate('clothApp.info().params.cols')
        k = len(st['positions']) - cols + cols // 3      # bottom row, a third of the way
        x, y = st['screen'][k]
        page.mouse.move(x, y)
        page.mouse.down()
        dx, dy = (90, -120) if args.compare else (-110, 35)
        page.mouse.move(x + dx, y + dy, steps=8)
        page.evaluate('clothApp.setPaused(false)')
        page.wait_for_timeout(3000 if args.compare else 1500)   # readouts, legend, charts fill in
        os.makedirs(os.path.dirname(args.out), exist_ok=True)
        page.screenshot(path=args.out)
        page.mouse.up()
        browser.close()
    print('wrote ' + args.out)


if __name__ == '__main__':
    main()
