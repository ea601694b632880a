"""The numbers and reports of the speed table: formatting, the markdown, the SVG plots."""

import math

from bench.numbers import finite, fmt, fmt_ratio, setting
from bench.speed import SEED, SCENES, WIDTH, DAMPING

# ---- reports ---------------------------------------------------------------------------------

def world_line(wc):
    """The world's cost in one sentence (issue #24: four obstacles and wind at most 15% more)."""
    return ('Wind and obstacles (issue #24: four obstacles and wind at most %d%% more at %dx%d): '
            'the default on the dragged curtain %dx%d, each run timed by itself in rotated order '
            '(median of %d rounds): %s; target %s.' % (
                round(100 * (wc['target'] - 1)), wc['size'], wc['size'], wc['size'], wc['size'], wc['reps'],
                '; '.join('%s %s ms/frame (%s)' % (r['scene'], fmt(r['ms_per_frame']), fmt_ratio(r['vs_without']))
                          for r in wc['rows']), 'met' if wc['met'] else 'NOT met'))


def markdown(result):
    meta = result['meta']
    sol = result['speed_of_light']
    lines = []
    lines.append('# Cloth benchmark%s' % (' (quick)' if meta['quick'] else ''))
    lines.append('')
    lines.append('`%s` on %s, Chromium %s, %d CPUs; %s. Total %.0f s.' % (
        meta['command'], meta['date'], meta['chromium'], meta['cpus'], meta['platform'],
        meta['seconds']))
    lines.append('Scenes %g m wide, N x N, damping %g/s, dt 1/60 s; %d warm-up frames, then '
                 '%d timed repetition(s) of one batch per configuration, round-robin; ms/frame '
                 'is the median, strain and error are RMS over the samples taken after each '
                 'batch (max strain: the largest). Ratios are to `%s` (the seed) on the same '
                 'scene in this run.' % (WIDTH, DAMPING, meta['warmup_frames'], meta['reps'],
                                          SEED))
    lines.append('')
    lines.append('## Headline')
    lines.append('')
    lines.append('Speed of light (seed method, curtain %dx%d, 20 iterations): core %s ms/frame, '
                 'hand-written JS %s ms/frame, ratio **%.3f** (target <= 1.05)%s; positions '
                 'bit-identical: %s.' % (
                     sol['size'], sol['size'], fmt(sol['core_ms_per_frame']),
                     fmt(sol['kernel_ms_per_frame']), sol['ratio'],
                     ' PASS' if sol['ratio'] <= 1.05 else ' FAIL',
                     'yes' if sol['bit_identical'] else
                     'NO (max |diff| %s)' % fmt(sol['max_abs_diff'])))
    lines.append('')
    lines.append('Targets of issues #6 and #11 (the `default` row, against `%s` on the same '
                 'scene; shape = RMS distance from the exact reference, in widths W):' % SEED)
    lines.append('')
    for t in result['targets']:
        lines.append('- ' + t['line'])
    lines.append('')
    lines.append('| scene | N | seed ms/frame | seed RMS strain | seed shape RMS | default | '
                 'time x seed | RMS strain | shape RMS (max) | error / seed |')
    lines.append('|---|---|---|---|---|---|---|---|---|---|')
    for g in result['groups']:
        rows = [r for r in result['rows'] if r['scene'] == g['scene'] and r['size'] == g['size']]
        seed = next(r for r in rows if r['config'] == SEED)
        d = next(r for r in rows if r['config'] == 'default')
        lines.append('| %s | %d | %s | %s | %s | %s | %s | %s | %s (%s) | %s |' % (
            g['scene'], g['size'], fmt(seed['ms_per_frame']), fmt(seed['rms_strain']),
            fmt(seed['rms_error']), setting(d['setting']), fmt_ratio(d['time_vs_seed']),
            fmt(d['rms_strain']), fmt(d['rms_error']), fmt(d['max_error']),
            fmt_ratio(d['error_vs_seed'])))
    lines.append('')
    tc = result.get('tear_check')
    if tc:
        lines.append('Tearing\'s check (issue #15: at most 5%% of a frame of the default): the check '
                     'of one frame timed by itself against the default\'s frames with `tear` set, '
                     'alternately on the same state (median of %d rounds): %s. A frame that '
                     'converged skips the check (a curtain at rest). The `default tear=10` rows '
                     'of the tables below run the same work plus the check; their difference from '
                     '`default` is within the noise between two runs of the same work.' % (
                         tc[0]['reps'], '; '.join(
                             '%s %dx%d %.2f%% (%s of %s ms)' % (
                                 t['scene'], t['size'], t['size'], 100.0 * t['fraction'],
                                 fmt(t['check_ms']), fmt(t['frame_ms'])) for t in tc)))
        lines.append('')
    wc = result.get('world_cost')
    if wc:
        lines.append(world_line(wc))
        lines.append('')
    cm = result.get('compare_mode')
    if cm:
        lines.append('Compare mode (the page runs N panels under the same hands; the default on the '
                     'curtain %dx%d, stepped by webgl/runner.js as the page steps them): %s.' % (
                         cm['size'], cm['size'], '; '.join(
                             '%d panel%s %s ms/frame (%s one)' % (
                                 r['panels'], '' if r['panels'] == 1 else 's', fmt(r['ms_per_frame']),
                                 fmt_ratio(r['vs_one'])) for r in cm['rows'])))
        lines.append('')
    lines.append('Plots: `bench.svg` (RMS position error against ms/frame) and `bench-strain.svg` '
                 '(RMS strain against ms/frame), log-log, one line per method family.')
    for g in result['groups']:
        rows = [r for r in result['rows'] if r['scene'] == g['scene'] and r['size'] == g['size']]
        lines.append('')
        lines.append('## %s %dx%d' % (g['scene'], g['size'], g['size']))
        lines.append('')
        ref = g.get('reference', '')
        extra = ''
        if 'reference_rms_strain' in g:
            extra += ' (its RMS strain %s)' % fmt(g['reference_rms_strain'])
        if g.get('reference_vs_half_substeps') is not None:
            extra += ('; the same with half the substeps is %s m RMS away, so errors below '
                      'about that are not resolved' % fmt(g['reference_vs_half_substeps']))
        lines.append('Error against: %s%s. %d frames per timed batch.' % (ref, extra,
                                                                            g['batch_frames']))
        lines.append('')
        lines.append('| config | setting | ms/frame | time x seed | projections/frame | '
                     'RMS strain | max strain | shape RMS (m) | shape max (m) |')
        lines.append('|---|---|---|---|---|---|---|---|---|')
        for r in rows:
            flag = ''
            if (r['rms_error'] is not None and finite(r['rms_strain']) and
                    r['rms_strain'] <= 1e-2 and r['rms_error'] > 0.05 * WIDTH):
                flag = ' (low strain, wrong shape)'
            lines.append('| %s | %s | %s | %s | %s | %s | %s | %s%s | %s |' % (
                r['config'], setting(r['setting']), fmt(r['ms_per_frame']),
                fmt_ratio(r['time_vs_seed']), '%.0f' % r['projections_per_frame'],
                fmt(r['rms_strain']), fmt(r['max_strain']), fmt(r['rms_error']), flag,
                fmt(r['max_error'])))
    lines.append('')
    return '\n'.join(lines)


FAMILY_COLORS = [
    ('jakobsen: 1 step x n sweeps', '#d62728'),
    ('jakobsen: S substeps x 1 sweep', '#ff7f0e'),
    ('xpbd: S substeps (default otherwise)', '#1f77b4'),
    ('default', '#2ca02c'),
    ('default variants', '#9467bd'),
]


PLOT_FLOOR = 1e-8   # values below this (e.g. 1e-15: exact to rounding) are drawn at it


def svg_plot(result, metric, title):
    """A hand-written SVG: one log-log panel per (scene, size), one polyline per family."""
    groups = result['groups']
    scenes = [s for s in SCENES if any(g['scene'] == s for g in groups)]
    sizes = sorted(set(g['size'] for g in groups))
    pw, ph = 300, 220               # panel size
    ml, mr, mt, mb = 62, 14, 26, 40  # panel margins
    legend_h = 22 * len(FAMILY_COLORS) + 10
    width = len(sizes) * (pw + ml + mr) + 10
    height = 40 + len(scenes) * (ph + mt + mb) + legend_h
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'viewBox="0 0 %d %d" font-family="sans-serif" font-size="11">' % (
               width, height, width, height),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="10" y="22" font-size="15" font-weight="bold">%s</text>' % esc(title)]

    def decades(lo, hi):
        a = math.floor(math.log10(lo))
        b = math.ceil(math.log10(hi))
        if b == a:
            b = a + 1
        return a, b

    for si, kind in enumerate(scenes):
        for zi, n in enumerate(sizes):
            rows = [r for r in result['rows'] if r['scene'] == kind and r['size'] == n]
            pts = [(r['ms_per_frame'], max(r[metric], PLOT_FLOOR)) for r in rows
                   if finite(r['ms_per_frame']) and finite(r[metric]) and
                   r['ms_per_frame'] > 0 and r[metric] > 0]
            x0 = 10 + zi * (pw + ml + mr) + ml
            y0 = 40 + si * (ph + mt + mb) + mt
            out.append('<text x="%d" y="%d" font-weight="bold">%s %dx%d</text>' % (
                x0, y0 - 8, kind, n, n))
            out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" '
                       'stroke="#888"/>' % (x0, y0, pw, ph))
            if not pts:
                out.append('<text x="%d" y="%d">no data</text>' % (x0 + 10, y0 + 20))
                continue
            xa, xb = decades(min(p[0] for p in pts), max(p[0] for p in pts))
            ya, yb = decades(min(p[1] for p in pts), max(p[1] for p in pts))

            def px(x, xa=xa, xb=xb, x0=x0):
                return x0 + (math.log10(x) - xa) / (xb - xa) * pw

            def py(y, ya=ya, yb=yb, y0=y0):
                return y0 + ph - (math.log10(y) - ya) / (yb - ya) * ph

            for e in range(xa, xb + 1):
                x = px(10.0 ** e)
                out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#eee"/>' % (
                    x, y0, x, y0 + ph))
                out.append('<text x="%.1f" y="%d" text-anchor="middle">1e%d</text>' % (
                    x, y0 + ph + 14, e))
            every = max(1, int(math.ceil((yb - ya) / 6.0)))
            for e in range(ya, yb + 1):
                y = py(10.0 ** e)
                out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>' % (
                    x0, y, x0 + pw, y))
                if (e - ya) % every == 0:
                    out.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (
                        x0 - 4, y + 4, e))
            out.append('<text x="%d" y="%d" text-anchor="middle">ms/frame</text>' % (
                x0 + pw // 2, y0 + ph + 30))
            out.append('<text x="%d" y="%d" text-anchor="middle" transform="rotate(-90 %d %d)">'
                       '%s</text>' % (x0 - 44, y0 + ph // 2, x0 - 44, y0 + ph // 2,
                                      esc(metric.replace('_', ' '))))
            for family, color in FAMILY_COLORS:
                fam = [(r['ms_per_frame'], max(r[metric], PLOT_FLOOR), r['config'])
                       for r in rows
                       if r['family'] == family and finite(r[metric]) and r[metric] > 0 and
                       finite(r['ms_per_frame']) and r['ms_per_frame'] > 0]
                if not fam:
                    continue
                if len(fam) > 1 and family != 'default variants':
                    out.append('<polyline fill="none" stroke="%s" stroke-width="1.5" '
                               'points="%s"/>' % (color, ' '.join(
                                   '%.1f,%.1f' % (px(x), py(y)) for x, y, _ in fam)))
                for x, y, cid in fam:
                    r_ = 5 if family == 'default' else 3
                    out.append('<circle cx="%.1f" cy="%.1f" r="%d" fill="%s"><title>%s: %s '
                               'ms/frame, %s</title></circle>' % (
                                   px(x), py(y), r_, color, esc(cid), fmt(x), fmt(y)))
                    if family in ('default', 'default variants'):
                        out.append('<text x="%.1f" y="%.1f" font-size="9" fill="%s">%s</text>'
                                   % (px(x) + 5, py(y) - 4, color,
                                      esc(cid.replace('default ', '') if cid != 'default'
                                          else 'default')))
    ly = 40 + len(scenes) * (ph + mt + mb) + 6
    for i, (family, color) in enumerate(FAMILY_COLORS):
        y = ly + 22 * i
        out.append('<line x1="20" y1="%d" x2="50" y2="%d" stroke="%s" stroke-width="2"/>' % (
            y, y, color))
        out.append('<circle cx="35" cy="%d" r="3" fill="%s"/>' % (y, color))
        out.append('<text x="58" y="%d">%s</text>' % (y + 4, esc(family)))
    out.append('</svg>')
    return '\n'.join(out) + '\n'


def esc(s):
    return str(s).replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')


def json_safe(x):
    if isinstance(x, float) and not math.isfinite(x):
        return None
    if isinstance(x, dict):
        return {k: json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [json_safe(v) for v in x]
    return x
