"""python -m bench [--quick] [--out DIR]: speed against error, in a real browser.

CPython only, outside the transpiled package cloth/. It opens the shipped page,
dist/index.html, in headless Chromium through Playwright and drives `window.clothCore` from
inside `page.evaluate` calls: every frame that is timed runs the same JS the page ships.

Method (issue #5):
- Scenes, 1 m wide, N x N vertices, spacing 1 / (N - 1), sizes 30, 60, 120:
  curtain (top row pinned; its exact equilibrium is the rest grid), corners (the two top
  corners pinned, the right one moved in to x = 0.8 at frame 0: grab, pin, release; measured
  after 15 s of settling against its exact hang, cloth/reference.py) and dynamic (a curtain whose
  bottom-middle vertex is grabbed and dragged along a figure-eight; error against the same
  script run with an accurate configuration).
- Every configuration of a scene runs in the same page. After some untimed warm-up frames, each
  repetition times one batch of frames per configuration with performance.now(), the
  configurations taken round-robin (a rotated order each repetition) so that machine drift
  falls on all of them alike; ms/frame is the median over repetitions. Strain and position
  error are sampled after every batch (outside the timing): RMS over the samples, max of max.
- The headline figures are ratios to the seed's method (jakobsen, 20 iterations) measured
  in the same run, because these machines are shared and noisy.
- The speed-of-light yardstick: a hand-written JS kernel of exactly the seed's method
  (Verlet + 20 Gauss-Seidel sweeps of Jakobsen's projection, inv_mass weights, the core's own
  edge order, typed arrays) timed against the core in the same page, interleaved; it also
  checks that both give bit-identical positions.

Output: progress on stderr; the markdown table on stdout and in OUT/bench.md (bench-quick.md
with --quick), the numbers in OUT/bench.json (bench-quick.json), log-log plots in
OUT/bench.svg (RMS position error against ms/frame) and OUT/bench-strain.svg (RMS strain).
"""

import json
import math
import statistics

from cloth.reference import slack_hang
from bench.page import open_page, BenchError
from bench.numbers import finite, rms, max_or_nan, ratio, setting, fmt, fmt_ratio

WIDTH = 1.0
SCENES = ['curtain', 'corners', 'dynamic']
# Every bench scene is lightly damped (1/s) so that the static scenes settle; the same value
# for every configuration and for the references.
DAMPING = 1.0
# Full and quick modes: untimed warm-up frames, timed repetitions, frames per timed batch at
# 30 x 30 (scaled by 1/N^2 above that), speed-of-light rounds.
MODES = {
    'full': {'sizes': [30, 60, 120], 'warmup': 240, 'reps': 7, 'batch30': 100,
             'sol_reps': 21},
    'quick': {'sizes': [30], 'warmup': 100, 'reps': 1, 'batch30': 50,
              'sol_reps': 5},
}
CORNER_X = 0.8               # the right corner is moved in to 80% of the width
CORNERS_SETTLE = 900         # untimed frames before the corners are measured (15 s)
PATH_PERIOD = 240            # frames per figure-eight of the dragged vertex (4 s)
PATH_AMPLITUDE = 0.25        # metres
# The figure-eight is centred PATH_LIFT above the vertex's rest position, reached by a smooth
# ramp over the first quarter period: the path never asks the cloth to stretch (a vertex
# dragged below its rest position would have to).
PATH_LIFT = 0.35
# The dragged curtain has no closed form: its reference is the same script run by XPBD with
# many small steps, tethers and no early exit. Up to REF_CHECK_MAX_N a second reference with
# half the substeps runs alongside: the RMS distance between the two says how far the
# reference itself is from converged. (The curtain and the corners have exact references.)
REF_ACCURATE = {'solver': 'xpbd', 'substeps': 40, 'iterations': 4, 'tethers': True,
                'tolerance': 0.0}
REF_CHECK_MAX_N = 60
SEED = 'jakobsen i20'        # the row every ratio is taken against
SOL_SIZE = 60

# Targets (issues #6 and #11): (scene, size, max RMS strain, max max-strain or None, max time x
# seed, max RMS shape error in widths or None).
TARGETS = [('curtain', 60, 1e-3, 1e-2, 1.5, None),
           ('curtain', 120, 1e-2, None, 1.0, None),
           ('corners', 30, 1e-2, None, 1.5, 0.01),
           ('corners', 60, 1e-2, None, 1.5, 0.01),
           ('corners', 120, 1e-2, None, 1.5, 0.01)]


# ---- configurations --------------------------------------------------------------------------

def configs():
    """(id, family, scene overrides). 'default' omits `solver`: it is whatever the core ships
    (sleep off, as in every row: see base_scene), and the xpbd rows change one thing of it, so
    each feature has a row."""
    out = []
    for n in [1, 2, 5, 10, 20, 50, 100]:
        out.append(('jakobsen i%d' % n, 'jakobsen: 1 step x n sweeps',
                    {'solver': 'jakobsen', 'substeps': 1, 'iterations': n}))
    for s in [1, 2, 5, 10, 20, 50, 100]:
        out.append(('jakobsen s%dx1' % s, 'jakobsen: S substeps x 1 sweep',
                    {'solver': 'jakobsen', 'substeps': s, 'iterations': 1}))
    for s in [1, 2, 4, 8, 16, 32]:
        out.append(('xpbd s%d' % s, 'xpbd: S substeps (default otherwise)',
                    {'solver': 'xpbd', 'substeps': s}))
    out.append(('default', 'default', {}))
    out.append(('default -tethers', 'default variants', {'tethers': False}))
    out.append(('default tolerance=0', 'default variants', {'tolerance': 0.0}))
    out.append(('default +shear', 'default variants', {'shear': True}))
    out.append(('default -cells', 'default variants', {'cells': False}))
    out.append(('default -lines', 'default variants', {'lines': False}))
    out.append(('default -cells -lines', 'default variants', {'cells': False, 'lines': False}))
    out.append(('default compliance=1e-7', 'default variants', {'compliance': 1e-7}))
    out.append(('default +sleep', 'default variants', {'sleep': True}))
    # Tearing's check, at a limit no scene here reaches (so the same work otherwise): what the
    # check costs on its own, against the `default` row (issue #15: at most 5% of a frame).
    out.append(('default tear=10', 'default variants', {'tear': 10.0}))
    return out


def base_scene(kind, n):
    h = WIDTH / (n - 1)
    # Sleep off: the benchmark times the solvers, and a cloth asleep costs nothing at all. The
    # 'default +sleep' row is the default as shipped.
    scene = {'cols': n, 'rows': n, 'spacing': h, 'damping': DAMPING, 'sleep': False}
    if kind == 'corners':
        scene['pins'] = [0, n - 1]
    else:
        scene['pins'] = list(range(n))
    return scene


def scene_actions(kind, n, frames):
    """The scripted actions, as the scene JSON spells them (webgl/runner.js applies them the
    way cloth.api.simulate does: those of frame 0 first, those of frame f after frame f)."""
    if kind == 'corners':
        return [{'frame': 0, 'op': 'grab', 'vertex': n - 1, 'to': [CORNER_X, 0.0]},
                {'frame': 0, 'op': 'pin', 'vertex': n - 1},
                {'frame': 0, 'op': 'release', 'vertex': n - 1}]
    if kind == 'dynamic':
        h = WIDTH / (n - 1)
        col = n // 2
        k = (n - 1) * n + col
        x0 = col * h
        y0 = -(n - 1) * h
        acts = [{'frame': 0, 'op': 'grab', 'vertex': k, 'to': [x0, y0]}]
        ramp = PATH_PERIOD // 4
        for f in range(1, frames + 1):
            t = 2.0 * math.pi * f / PATH_PERIOD
            lift = PATH_LIFT * 0.5 * (1.0 - math.cos(math.pi * min(f, ramp) / ramp))
            acts.append({'frame': f, 'op': 'move', 'vertex': k,
                         'to': [x0 + PATH_AMPLITUDE * math.sin(t),
                                y0 + lift + 0.5 * PATH_AMPLITUDE * math.sin(2.0 * t)]})
        return acts
    return []


def batch_frames(n, batch30):
    """Frames per timed batch: about the same work per batch at every size, so that the
    cheapest configuration's batch is still many timer ticks (performance.now() has 100 us
    resolution on file://)."""
    return max(10, int(math.ceil(batch30 * 900.0 / (n * n))))


def chunked(total, step):
    done = 0
    while done < total:
        k = min(step, total - done)
        yield done, k
        done += k


def run_group(page, kind, n, mode, progress):
    """All configurations of one scene at one size; returns (rows, group info)."""
    key = '%s-%d' % (kind, n)
    reps = mode['reps']
    warmup = mode['warmup']
    if kind == 'corners':
        # Shape is measured on the settled hang (damping 1/s: 15 s is e^-15 of a swing).
        warmup = max(warmup, CORNERS_SETTLE)
    batch = batch_frames(n, mode['batch30'])
    total = warmup + reps * batch
    cfgs = configs()
    actions = scene_actions(kind, n, total)
    scenes = []
    for cid, family, over in cfgs:
        s = base_scene(kind, n)
        s.update(over)
        if actions:
            s['actions'] = actions
        scenes.append(json.dumps(s))
    described = page.evaluate('([k, s]) => __bench.setup(k, s)', [key, scenes])
    info = {'scene': kind, 'size': n, 'batch_frames': batch, 'warmup_frames': warmup,
            'reps': reps, 'actions': len(actions)}

    # The answer to compare against.
    sample_frames = [warmup + (r + 1) * batch for r in range(reps)]
    if kind == 'curtain':
        page.evaluate('(k) => __bench.exactRest(k)', key)
        info['reference'] = 'exact: the rest grid'
    elif kind == 'corners':
        exact = slack_hang(n, n, WIDTH / (n - 1), CORNER_X)
        page.evaluate('([k, f]) => __bench.exactRef(k, f)', [key, [v for p in exact for v in p]])
        info['reference'] = ('exact: the two-corner hang of the seed\'s model (cloth/reference.py: '
                             'straight columns under the top row\'s discrete catenary)')
    else:
        ref = base_scene(kind, n)
        ref.update(REF_ACCURATE)
        ref_frames = total
        if actions:
            ref['actions'] = actions
        check = None
        if n <= REF_CHECK_MAX_N:
            check = json.dumps(dict(ref, substeps=ref['substeps'] // 2))
        desc = page.evaluate('([k, t, c]) => __bench.refSetup(k, t, c)',
                             [key, json.dumps(ref), check])
        step = max(1, int(400000.0 / (n * n)))
        for done, k in chunked(ref_frames, step):
            progress('%s %dx%d: reference (%s) frame %d/%d' % (
                kind, n, n, setting(desc), done, ref_frames))
            page.evaluate('([k, f, s]) => __bench.refAdvance(k, f, s)',
                          [key, k, sample_frames])
        info['reference_config'] = dict(ref, actions=len(actions))
        if check:
            info['reference_vs_half_substeps'] = rms(
                page.evaluate('(k) => __bench.refCheck(k)', key))
        st = page.evaluate('(k) => __bench.refStrain(k)', key)
        info['reference'] = '%s, the same script' % setting(desc)
        info['reference_rms_strain'] = st['rms_strain']
        info['reference_max_strain'] = st['max_strain']

    step = max(1, int(200000.0 / (n * n)))
    for done, k in chunked(warmup, step):
        progress('%s %dx%d: warm-up frame %d/%d (%d configurations)' % (
            kind, n, n, done, warmup, len(cfgs)))
        page.evaluate('([k, f]) => __bench.warm(k, f)', [key, k])

    samples = [[] for _ in cfgs]
    m = len(cfgs)
    for r in range(reps):
        progress('%s %dx%d: timed round %d/%d (%d frames per configuration)' % (
            kind, n, n, r + 1, reps, batch))
        start = (r * 7) % m
        order = [(start + j) % m for j in range(m)]
        for res in page.evaluate('([k, o, f]) => __bench.round(k, o, f)', [key, order, batch]):
            samples[res['i']].append(res)
    page.evaluate('(k) => __bench.drop(k)', key)

    rows = []
    for (cid, family, over), desc, smp in zip(cfgs, described, samples):
        ms = [s['ms'] / batch for s in smp]
        errs = [s['err'] for s in smp]
        rows.append({
            'scene': kind, 'size': n, 'config': cid, 'family': family, 'overrides': over,
            'setting': desc,
            'ms_per_frame': statistics.median(ms),
            'ms_per_frame_samples': ms,
            'projections_per_frame': sum(s['proj'] for s in smp) / float(batch * len(smp)),
            'rms_strain': rms([s['rms_strain'] for s in smp]),
            'max_strain': max_or_nan([s['max_strain'] for s in smp]),
            'rms_error': rms(errs) if all(e is not None for e in errs) else None,
            'max_error': (max_or_nan([s['max_err'] for s in smp])
                          if all(e is not None for e in errs) else None),
        })
    seed = next(r for r in rows if r['config'] == SEED)
    for r in rows:
        r['time_vs_seed'] = ratio(r['ms_per_frame'], seed['ms_per_frame'])
        r['strain_vs_seed'] = ratio(r['rms_strain'], seed['rms_strain'])
        r['error_vs_seed'] = (ratio(r['rms_error'], seed['rms_error'])
                              if r['rms_error'] is not None else None)
    return rows, info


def compare_cost(page, n, reps, progress):
    """Compare mode's cost: 1 to 4 panels of the default on the n x n curtain, stepped one
    after the other by webgl/runner.js as the page's loop steps them; ms per frame of them all
    against one panel, in rotated order each repetition. About N times one is expected; the
    table shows what it is (no assertion on time)."""
    s = base_scene('curtain', n)
    page.evaluate('([t, m]) => __bench.panelsSetup(t, m)', [json.dumps(s), 4])
    frames = max(5, int(math.ceil(20.0 * (60.0 / n) ** 2)))
    page.evaluate('([c, f]) => __bench.panelsRound(c, f)', [4, 240])        # warm, all alike
    samples = {c: [] for c in range(1, 5)}
    for r in range(reps):
        progress('compare mode %dx%d: round %d/%d' % (n, n, r + 1, reps))
        for j in range(4):
            c = 1 + (r + j) % 4
            samples[c].append(page.evaluate('([c, f]) => __bench.panelsRound(c, f)', [c, frames]) / frames)
    one = statistics.median(samples[1])
    rows = [{'panels': c, 'ms_per_frame': statistics.median(samples[c]),
             'vs_one': ratio(statistics.median(samples[c]), one)} for c in range(1, 5)]
    return {'scene': 'curtain', 'size': n, 'frames_per_batch': frames, 'reps': reps, 'rows': rows}


WORLD_SIZE = 120
WORLD_TARGET = 1.15          # issue #24: four obstacles and wind cost at most 15% more


def world_scenes(n, frames):
    """The dragged curtain (its hand on a figure-eight: nothing settles), as is, in wind, and
    in wind among four obstacles (two pegs below it, two boxes beside it, which the swinging
    cloth runs into): [(label, scene)]."""
    s = base_scene('dynamic', n)
    s['actions'] = scene_actions('dynamic', n, frames)
    w = WIDTH
    air = {'wind': [3.0, 0.0], 'drag': 0.1}
    world = dict(air, obstacles=[{'circle': [0.2 * w, -1.15 * w, 0.1 * w], 'friction': 0.3},
                                 {'circle': [0.8 * w, -1.15 * w, 0.1 * w]},
                                 {'box': [-0.35 * w, -0.9 * w, -0.08 * w, -0.5 * w], 'friction': 0.5},
                                 {'box': [1.08 * w, -0.9 * w, 1.35 * w, -0.5 * w]}])
    return [('without', s), ('wind', dict(s, **air)), ('wind + 4 obstacles', dict(s, **world))]


def world_cost(page, n, reps, progress):
    """Wind and obstacles against the same dragged cloth without them (issue #24: four
    obstacles and wind at most 15% more at 120x120): each run timed by itself over the same
    frames, in rotated order each repetition; the medians' ratios to the run without."""
    frames = max(5, int(math.ceil(20.0 * (60.0 / n) ** 2)))
    warm = 120
    scenes = world_scenes(n, warm + (reps + 1) * frames)
    page.evaluate('(t) => __bench.worldSetup(t)', [json.dumps(s) for _, s in scenes])
    for i in range(len(scenes)):
        page.evaluate('([i, f]) => __bench.worldRound(i, f)', [i, warm])
    samples = [[] for _ in scenes]
    for r in range(reps):
        progress('wind and obstacles %dx%d: round %d/%d' % (n, n, r + 1, reps))
        for j in range(len(scenes)):
            i = (r + j) % len(scenes)
            samples[i].append(page.evaluate('([i, f]) => __bench.worldRound(i, f)', [i, frames]) / frames)
    base = statistics.median(samples[0])
    rows = [{'scene': label, 'ms_per_frame': statistics.median(samples[i]),
             'vs_without': ratio(statistics.median(samples[i]), base)} for i, (label, _) in enumerate(scenes)]
    return {'size': n, 'frames_per_batch': frames, 'reps': reps, 'rows': rows, 'target': WORLD_TARGET,
            'met': rows[-1]['vs_without'] <= WORLD_TARGET}


def tear_cost(page, kind, n, mode, progress):
    """Tearing's check on its own (issue #15: at most 5% of a frame of the default): the check
    of one frame (at a limit nothing reaches) timed by itself, against frames of the default
    with that limit, on the same state, alternately; the median of the rounds' ratios. On a
    scene whose frames do not converge (a settled slack hang keeps a small limit cycle, a
    dragged cloth moves), so every frame makes the check; a converged frame skips it."""
    total = max(mode['warmup'], CORNERS_SETTLE if kind == 'corners' else 0)
    batch = batch_frames(n, mode['batch30'])
    s = base_scene(kind, n)
    s['tear'] = 10.0
    actions = scene_actions(kind, n, total + mode['reps'] * batch * 2)
    if actions:
        s['actions'] = actions
    page.evaluate('(t) => __bench.tearSetup(t)', json.dumps(s))
    page.evaluate('(f) => __bench.tearRound(f)', total)
    frames, checks, ratios = [], [], []
    converged = 0
    for r in range(mode['reps']):
        progress('tearing\'s check %s %dx%d: round %d/%d' % (kind, n, n, r + 1, mode['reps']))
        t = page.evaluate('(f) => __bench.tearRound(f)', batch)
        frames.append(t['frame_ms'] / batch)
        checks.append(t['check_ms'] / batch)
        ratios.append(t['check_ms'] / t['frame_ms'] if t['frame_ms'] > 0 else float('nan'))
        converged += 1 if t['converged'] else 0
    return {'scene': kind, 'size': n, 'frames_per_batch': batch, 'reps': mode['reps'],
            'frame_ms': statistics.median(frames), 'check_ms': statistics.median(checks),
            'fraction': statistics.median(ratios), 'converged_rounds': converged}


def speed_of_light(page, n, reps, progress):
    """The core against a hand-written JS kernel of the seed's method, interleaved."""
    s = base_scene('curtain', n)
    s.update({'solver': 'jakobsen', 'substeps': 1, 'iterations': 20})
    page.evaluate('(t) => __bench.solSetup(t)', json.dumps(s))
    frames = max(5, int(math.ceil(50.0 * (60.0 / n) ** 2)))
    page.evaluate('(f) => { __bench.solRound(f, false); __bench.solRound(f, true); }', frames)
    core, kernel, ratios = [], [], []
    for r in range(reps):
        if r % 5 == 0:
            progress('speed of light %dx%d: round %d/%d' % (n, n, r + 1, reps))
        t = page.evaluate('([f, k]) => __bench.solRound(f, k)', [frames, r % 2 == 1])
        core.append(t['core'] / frames)
        kernel.append(t['kernel'] / frames)
        ratios.append(t['core'] / t['kernel'])
    same = page.evaluate('() => __bench.solCompare()')
    return {'scene': 'curtain', 'size': n, 'iterations': 20, 'frames_per_batch': frames,
            'reps': reps, 'core_ms_per_frame': statistics.median(core),
            'kernel_ms_per_frame': statistics.median(kernel),
            'ratio': statistics.median(ratios), 'ratio_samples': ratios,
            'bit_identical': same['identical'], 'max_abs_diff': same['max_abs_diff']}


def check_targets(rows, quick):
    out = []
    for kind, n, rms_max, max_max, time_max, shape_max in TARGETS:
        row = next((r for r in rows if r['scene'] == kind and r['size'] == n and
                    r['config'] == 'default'), None)
        t = {'scene': kind, 'size': n, 'rms_strain_max': rms_max, 'max_strain_max': max_max,
             'time_vs_seed_max': time_max}
        if row is None:
            t.update({'measured': False, 'pass': None})
            t['line'] = ('%s %dx%d: not measured%s' % (kind, n, n, ' (--quick)' if quick else ''))
            out.append(t)
            continue
        ok_rms = finite(row['rms_strain']) and row['rms_strain'] <= rms_max
        ok_max = max_max is None or (finite(row['max_strain']) and row['max_strain'] <= max_max)
        ok_time = row['time_vs_seed'] is not None and row['time_vs_seed'] <= time_max
        ok_shape = shape_max is None or (row['rms_error'] is not None and
                                         row['rms_error'] <= shape_max * WIDTH)
        passed = ok_rms and ok_max and ok_time and ok_shape
        parts = ['RMS strain %s (<= %g) %s' % (fmt(row['rms_strain']), rms_max,
                                               'ok' if ok_rms else 'FAIL')]
        if max_max is not None:
            parts.append('max strain %s (<= %g) %s' % (fmt(row['max_strain']), max_max,
                                                       'ok' if ok_max else 'FAIL'))
        parts.append('time %s seed (<= %gx) %s' % (fmt_ratio(row['time_vs_seed']), time_max,
                                                   'ok' if ok_time else 'FAIL'))
        if shape_max is not None:
            parts.append('shape RMS %s W (<= %g) %s' % (fmt(row['rms_error'] / WIDTH), shape_max,
                                                       'ok' if ok_shape else 'FAIL'))
        others = [r['config'] for r in rows if r['scene'] == kind and r['size'] == n and
                  r['config'] != 'default' and finite(r['rms_strain']) and
                  (shape_max is None or (r['rms_error'] is not None and
                                         r['rms_error'] <= shape_max * WIDTH)) and
                  r['rms_strain'] <= rms_max and
                  (max_max is None or (finite(r['max_strain']) and r['max_strain'] <= max_max))
                  and r['time_vs_seed'] is not None and r['time_vs_seed'] <= time_max]
        t.update({'measured': True, 'pass': passed, 'rms_strain': row['rms_strain'],
                  'max_strain': row['max_strain'], 'time_vs_seed': row['time_vs_seed'],
                  'also_met_by': others})
        t['line'] = '%s: %s %dx%d, default: %s' % ('PASS' if passed else 'FAIL', kind, n, n,
                                                   '; '.join(parts))
        if others:
            t['line'] += ' (also met by: %s)' % ', '.join(others)
        out.append(t)
    return out


def bench(quick, progress):
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        raise BenchError('Playwright is missing: pip install -e ".[test]" (it installs playwright)')
    mode = MODES['quick' if quick else 'full']
    sizes = mode['sizes']
    rows, groups = [], []
    with sync_playwright() as p:
        browser, page = open_page(p, progress)
        try:
            chromium = browser.version
            for n in sizes:
                for kind in SCENES:
                    r, info = run_group(page, kind, n, mode, progress)
                    rows.extend(r)
                    groups.append(info)
                    seed = next(x for x in r if x['config'] == SEED)
                    d = next(x for x in r if x['config'] == 'default')
                    progress('%s %dx%d: seed %s ms/frame RMS strain %s; default %s seed time, '
                             'RMS strain %s' % (kind, n, n, fmt(seed['ms_per_frame']),
                                                fmt(seed['rms_strain']),
                                                fmt_ratio(d['time_vs_seed']),
                                                fmt(d['rms_strain'])))
            sol_n = SOL_SIZE if SOL_SIZE in sizes else max(s for s in sizes if s <= SOL_SIZE)
            sol = speed_of_light(page, sol_n, mode['sol_reps'], progress)
            progress('speed of light: core / hand-written JS = %.3f (bit-identical: %s)' % (
                sol['ratio'], sol['bit_identical']))
            panels = compare_cost(page, sol_n, mode['sol_reps'], progress)
            progress('compare mode: %s' % ', '.join('%d panels %s' % (r['panels'], fmt_ratio(r['vs_one']))
                                                    for r in panels['rows']))
            world = world_cost(page, WORLD_SIZE if not quick else max(sizes), mode['sol_reps'], progress)
            progress('wind and obstacles: %s' % ', '.join('%s %s' % (r['scene'], fmt_ratio(r['vs_without']))
                                                           for r in world['rows']))
            tear = []
            for n in sizes:
                for kind in ('corners', 'dynamic'):
                    t = tear_cost(page, kind, n, mode, progress)
                    tear.append(t)
                    progress('tearing\'s check %s %dx%d: %.2f%% of a frame' % (
                        kind, n, n, 100.0 * t['fraction']))
        finally:
            browser.close()
    return rows, groups, sol, panels, tear, world, chromium
