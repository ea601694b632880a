"""python -m bench: the benchmark's command line (see bench/speed.py for the method)."""

import argparse
import json
import os
import platform
import sys
import time

from bench.page import ROOT, Progress, BenchError, open_page
from bench.speed import MODES, DAMPING, WIDTH, SEED, WORLD_SIZE, bench, check_targets, world_cost
from bench.report import markdown, svg_plot, json_safe, world_line, PLOT_FLOOR
from bench.gestures import gestures

# The files a run writes: bench<suffix><ending>. A quick run's files are a smoke test, not
# results: .gitignore keeps them out of commits (tests/test_bench.py checks that it does).
OUTPUTS = ['.md', '.json', '.svg', '-strain.svg']
QUICK_SUFFIX = '-quick'


def world_only(progress):
    """`--world`: the world's cost table alone, as markdown."""
    from playwright.sync_api import sync_playwright
    with sync_playwright() as p:
        browser, page = open_page(p, progress)
        try:
            wc = world_cost(page, WORLD_SIZE, MODES['full']['sol_reps'], progress)
        finally:
            browser.close()
    return '# Wind and obstacles\n\n`python -m bench --world`\n\n' + world_line(wc) + '\n'


def main(argv=None):
    ap = argparse.ArgumentParser(prog='python -m bench',
                                 description='Speed against error of the shipped core '
                                             '(dist/index.html) in headless Chromium.')
    ap.add_argument('--quick', action='store_true',
                    help='30x30 only, one repetition (under a minute)')
    ap.add_argument('--out', default=os.path.join(ROOT, 'bench', 'results'),
                    help='folder for bench.md / .json / .svg (default: bench/results)')
    ap.add_argument('--gestures', action='store_true',
                    help='only the gestures: pulling beyond reach, letting go, flicking '
                         '(OUT/gestures.md)')
    ap.add_argument('--physics', action='store_true',
                    help='only the release table and the strain fields at rest, on the page\'s '
                         'presets (OUT/physics.md, .json, .svg; with --quick: 10x10 and 30x30)')
    ap.add_argument('--world', action='store_true',
                    help='only the cost of wind and obstacles against the same cloth without '
                         'them (the default, 120x120; OUT/world.md)')
    ap.add_argument('--figures', action='store_true',
                    help='only the README\'s other figures: sleep, the pendulum, the seed\'s '
                         'stretch, one sweep per step, the carried corner, tethers, drawing '
                         '(OUT/figures.md, .json; with --quick: the small sizes)')
    args = ap.parse_args(argv)
    progress = Progress()
    if args.world:
        try:
            md = world_only(progress)
        except BenchError as err:
            sys.stderr.write('error: %s\n' % err)
            return 1
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, 'world.md'), 'w', encoding='utf-8') as f:
            f.write(md)
        sys.stdout.write(md)
        return 0
    if args.physics or args.figures:
        from bench import physics as bench_physics, figures as bench_figures
        module, name = (bench_physics, 'physics') if args.physics else (bench_figures, 'figures')
        try:
            md, result = module.run(args.quick, progress)
        except BenchError as err:
            sys.stderr.write('error: %s\n' % err)
            return 1
        os.makedirs(args.out, exist_ok=True)
        name += QUICK_SUFFIX if args.quick else ''
        with open(os.path.join(args.out, name + '.md'), 'w', encoding='utf-8') as f:
            f.write(md)
        with open(os.path.join(args.out, name + '.json'), 'w', encoding='utf-8') as f:
            json.dump(json_safe(result), f, indent=1, allow_nan=False)
            f.write('\n')
        if args.physics:
            with open(os.path.join(args.out, name + '.svg'), 'w', encoding='utf-8') as f:
                f.write(bench_physics.svg_release(result))
        sys.stdout.write(md)
        return 0
    if args.gestures:
        try:
            md = gestures(progress)
        except BenchError as err:
            sys.stderr.write('error: %s\n' % err)
            return 1
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, 'gestures.md'), 'w', encoding='utf-8') as f:
            f.write(md)
        sys.stdout.write(md)
        return 0
    try:
        rows, groups, sol, panels, tear, world, chromium = bench(args.quick, progress)
    except BenchError as err:
        sys.stderr.write('error: %s\n' % err)
        return 1
    mode = 'quick' if args.quick else 'full'
    meta = {'command': 'python -m bench' + (' --quick' if args.quick else ''),
            'quick': args.quick, 'date': time.strftime('%Y-%m-%d %H:%M:%S %Z'),
            'chromium': chromium, 'cpus': os.cpu_count() or 0,
            'platform': '%s %s, Python %s' % (platform.system(), platform.machine(),
                                              platform.python_version()),
            'reps': MODES[mode]['reps'], 'warmup_frames': MODES[mode]['warmup'],
            'damping': DAMPING, 'width': WIDTH, 'seed_row': SEED,
            'seconds': progress.elapsed()}
    result = {'meta': meta, 'speed_of_light': sol, 'compare_mode': panels, 'tear_check': tear,
              'world_cost': world,
              'groups': groups, 'rows': rows}
    result['targets'] = check_targets(rows, args.quick)
    md = markdown(result)
    suffix = QUICK_SUFFIX if args.quick else ''
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, 'bench%s.md' % suffix), 'w', encoding='utf-8') as f:
        f.write(md)
    with open(os.path.join(args.out, 'bench%s.json' % suffix), 'w', encoding='utf-8') as f:
        json.dump(json_safe(result), f, indent=1, allow_nan=False)
        f.write('\n')
    with open(os.path.join(args.out, 'bench%s.svg' % suffix), 'w', encoding='utf-8') as f:
        f.write(svg_plot(result, 'rms_error', 'RMS position error (m) against ms/frame%s; '
                         'values below %g drawn at %g' % (' (quick)' if args.quick else '',
                                                           PLOT_FLOOR, PLOT_FLOOR)))
    with open(os.path.join(args.out, 'bench%s-strain.svg' % suffix), 'w', encoding='utf-8') as f:
        f.write(svg_plot(result, 'rms_strain', 'RMS strain against ms/frame%s; values below '
                         '%g drawn at %g' % (' (quick)' if args.quick else '', PLOT_FLOOR,
                                             PLOT_FLOOR)))
    sys.stdout.write(md)
    progress('wrote %s' % ', '.join(os.path.join(args.out, 'bench%s%s' % (suffix, e))
                                    for e in OUTPUTS))
    return 0


if __name__ == '__main__':
    sys.exit(main())
