"""python -m bench: the benchmark's command line.

    python -m bench              the speed-against-error front (bench/front.py): front.md,
                                 .json, -field.svg, -shape.svg
    python -m bench --sizes 30,60 the front at those sizes only: front-30-60.md, ...
    python -m bench --quick      the same at 30x30 for a few configurations (a smoke test:
                                 its files are git-ignored)
    python -m bench --fabrics    every fabric on the three presets: the field against the exact
                                 statics and across grids, and the time to rest at 10 to 200
                                 (bench/fabrics.py): fabrics.md, .json
    python -m bench --releases   every preset pulled and let go, and tapped: speeds, energy
                                 (bench/releases.py): releases.md, .json
    python -m bench --figures    the docs' other figures (bench/figures.py): figures.md, .json
    python -m bench --worker     input against the simulation's thread: the session in a Worker
                                 and on the page's thread (bench/worker.py): worker.md, .json
    python -m bench --contact    obstacles against hands, carries, drags and falls: edges
                                 through, rest (bench/contact.py): contact.md, .json
    python -m bench --tear       the first break's pull across grids, and what breaks release
                                 (bench/tear.py): tear.md, .json
    python -m bench --air        the Flag's shape across grids, a curtain at rest in a steady
                                 wind (bench/air.py): air.md, .json

Everything runs in the shipped page, dist/index.html, in headless Chromium.
"""

import argparse
import datetime
import json
import os
import platform
import sys

from bench.page import ROOT, Progress, BenchError, open_page
from bench.report import svg_front, json_safe

QUICK_SUFFIX = '-quick'


def main(argv=None):
    ap = argparse.ArgumentParser(prog='python -m bench',
                                 description='Speed against error of the shipped core '
                                             '(dist/index.html) in headless Chromium.')
    ap.add_argument('--quick', action='store_true', help='the small sizes only (a smoke test)')
    ap.add_argument('--fabrics', action='store_true', help='every fabric on the three presets')
    ap.add_argument('--releases', action='store_true', help='every preset pulled, let go, tapped')
    ap.add_argument('--figures', action='store_true', help='the docs\' other figures')
    ap.add_argument('--worker', action='store_true', help='input with the session in a Worker and without')
    ap.add_argument('--contact', action='store_true', help='obstacles against hands, drags and falls')
    ap.add_argument('--tear', action='store_true', help='the first break across grids, and the energy breaks release')
    ap.add_argument('--air', action='store_true', help='the Flag across grids, a curtain in a steady wind')
    ap.add_argument('--sizes', default=None,
                    help='the front\'s grid sizes, comma-separated (default: 30,60,120,200)')
    ap.add_argument('--out', default=os.path.join(ROOT, 'bench', 'results'),
                    help='folder for the results (default: bench/results)')
    args = ap.parse_args(argv)
    progress = Progress()
    from playwright.sync_api import sync_playwright
    try:
        with sync_playwright() as p:
            browser, page = open_page(p, progress)
            meta = {'date': datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC'),
                    'machine': 'Chromium %s, %d CPUs, %s %s, Python %s' % (
                        browser.version, os.cpu_count() or 0, platform.system(), platform.machine(),
                        platform.python_version())}
            try:
                name, md, result, extra = dispatch(args, page, progress, meta)
            finally:
                browser.close()
    except BenchError as err:
        sys.stderr.write('error: %s\n' % err)
        return 1
    os.makedirs(args.out, exist_ok=True)
    name += QUICK_SUFFIX if args.quick else ''
    meta['seconds_total'] = round(progress.elapsed())
    with open(os.path.join(args.out, name + '.md'), 'w', encoding='utf-8') as f:
        f.write(md)
    with open(os.path.join(args.out, name + '.json'), 'w', encoding='utf-8') as f:
        json.dump(json_safe({'meta': meta, 'rows': result}), f, indent=1, allow_nan=False)
    for suffix, text in extra:
        with open(os.path.join(args.out, name + suffix), 'w', encoding='utf-8') as f:
            f.write(text)
    sys.stdout.write(md)
    return 0


def dispatch(args, page, progress, meta):
    if args.fabrics:
        from bench import fabrics
        meta.update(fabrics.plan(args.quick))
        rows = fabrics.run(page, meta, progress)
        return 'fabrics', fabrics.markdown(rows, meta), rows, []
    if args.releases:
        from bench import releases
        rows = releases.run(page, args.quick, progress)
        return 'releases', releases.markdown(rows, meta), rows, []
    if args.worker:
        from bench import worker
        rows = worker.run(page, args.quick, progress)
        return 'worker', worker.markdown(rows, meta), rows, []
    if args.contact:
        from bench import contact
        rows = contact.run(page, args.quick, progress)
        return 'contact', contact.markdown(rows, meta), rows, []
    if args.tear:
        from bench import tear
        rows = tear.run(page, args.quick, progress)
        return 'tear', tear.markdown(rows, meta), rows, []
    if args.air:
        from bench import air
        rows = air.run(page, args.quick, progress)
        return 'air', air.markdown(rows, meta), rows, []
    if args.figures:
        from bench import figures
        rows = figures.run(page, args.quick, progress)
        return 'figures', figures.markdown(rows, meta), rows, []
    from bench import front
    meta['seconds'] = front.QUICK_SECONDS if args.quick else front.RUN_SECONDS
    meta['warm'], meta['block'], meta['rounds'] = ((front.QUICK_WARM, front.QUICK_BLOCK, front.QUICK_ROUNDS)
                                                   if args.quick else (front.WARM, front.BLOCK, front.ROUNDS))
    sizes = [int(v) for v in args.sizes.split(',')] if args.sizes else None
    rows = front.run(page, args.quick, progress, sizes)
    extra = [('-field.svg', svg_front(rows, 'field', 'Strain-field error against ms per frame', front.DEFAULT)),
             ('-shape.svg', svg_front(rows, 'shape', 'Shape error (widths) against ms per frame', front.DEFAULT))]
    name = 'front' if sizes is None else 'front-' + '-'.join(str(n) for n in sizes)
    return name, front.markdown(rows, meta), rows, extra


if __name__ == '__main__':
    sys.exit(main())
