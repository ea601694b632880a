"""The benchmark's pictures: hand-written SVG, log-log panels of error against ms per frame."""

import math

FAMILY_COLORS = [
    ('jakobsen', '#d62728'),
    ('xpbd', '#1f77b4'),
    ('vbd, no correction', '#9467bd'),
    ('vbd + coarse grid', '#2ca02c'),
]
PLOT_FLOOR = 1e-8   # values below this are drawn at it


def finite(x):
    return isinstance(x, (int, float)) and math.isfinite(x)


def esc(s):
    return str(s).replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')


def svg_front(rows, metric, title, default):
    """One panel per (scene, size): every configuration's (ms/frame, rows[metric]) on log-log
    axes, a polyline per family through its budgets, the default ringed."""
    scenes = []
    sizes = []
    for r in rows:
        if r['scene'] not in scenes:
            scenes.append(r['scene'])
        if r['n'] not in sizes:
            sizes.append(r['n'])
    sizes.sort()
    pw, ph = 300, 220
    ml, mr, mt, mb = 62, 14, 26, 40
    legend_h = 22 * len(FAMILY_COLORS) + 10
    width = len(sizes) * (pw + ml + mr) + 10
    height = 40 + len(scenes) * (ph + mt + mb) + legend_h
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'viewBox="0 0 %d %d" font-family="sans-serif" font-size="11">' % (width, height, width, height),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="10" y="22" font-size="15" font-weight="bold">%s</text>' % esc(title)]

    def decades(lo, hi):
        a = math.floor(math.log10(lo))
        b = math.ceil(math.log10(hi))
        return a, (b if b > a else a + 1)

    for si, scene in enumerate(scenes):
        for zi, n in enumerate(sizes):
            panel = [r for r in rows if r['scene'] == scene and r['n'] == n]
            pts = [(r['ms'], max(r[metric], PLOT_FLOOR)) for r in panel
                   if finite(r['ms']) and finite(r[metric]) and r['ms'] > 0]
            x0 = 10 + zi * (pw + ml + mr) + ml
            y0 = 40 + si * (ph + mt + mb) + mt
            out.append('<text x="%d" y="%d" font-weight="bold">%s %dx%d</text>' % (x0, y0 - 8, esc(scene), n, n))
            out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#888"/>' % (x0, y0, pw, ph))
            if not pts:
                continue
            xa, xb = decades(min(p[0] for p in pts), max(p[0] for p in pts))
            ya, yb = decades(min(p[1] for p in pts), max(p[1] for p in pts))

            def px(x, xa=xa, xb=xb, x0=x0):
                return x0 + (math.log10(x) - xa) / (xb - xa) * pw

            def py(y, ya=ya, yb=yb, y0=y0):
                return y0 + ph - (math.log10(y) - ya) / (yb - ya) * ph

            for e in range(xa, xb + 1):
                x = px(10.0 ** e)
                out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#eee"/>' % (x, y0, x, y0 + ph))
                out.append('<text x="%.1f" y="%d" text-anchor="middle">1e%d</text>' % (x, y0 + ph + 14, e))
            every = max(1, int(math.ceil((yb - ya) / 6.0)))
            for e in range(ya, yb + 1):
                y = py(10.0 ** e)
                out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#eee"/>' % (x0, y, x0 + pw, y))
                if (e - ya) % every == 0:
                    out.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (x0 - 4, y + 4, e))
            out.append('<text x="%d" y="%d" text-anchor="middle">ms/frame</text>' % (x0 + pw // 2, y0 + ph + 30))
            out.append('<text x="%d" y="%d" text-anchor="middle" transform="rotate(-90 %d %d)">%s error</text>' % (
                x0 - 44, y0 + ph // 2, x0 - 44, y0 + ph // 2, esc(metric)))
            for family, color in FAMILY_COLORS:
                fam = [r for r in panel if r['family'] == family and finite(r[metric]) and finite(r['ms'])]
                fam.sort(key=lambda r: r['ms'])
                if len(fam) > 1:
                    out.append('<polyline fill="none" stroke="%s" stroke-width="1.5" points="%s"/>' % (
                        color, ' '.join('%.1f,%.1f' % (px(r['ms']), py(max(r[metric], PLOT_FLOOR))) for r in fam)))
                for r in fam:
                    x, y = px(r['ms']), py(max(r[metric], PLOT_FLOOR))
                    out.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s"><title>%s: %.3g ms, %.2g</title></circle>' % (
                        x, y, color, esc(r['config']), r['ms'], r[metric]))
                    if r['config'] == default:
                        out.append('<circle cx="%.1f" cy="%.1f" r="7" fill="none" stroke="black" stroke-width="1.5"/>' % (x, y))
    ly = height - legend_h + 10
    for i, (family, color) in enumerate(FAMILY_COLORS):
        out.append('<line x1="20" y1="%d" x2="50" y2="%d" stroke="%s" stroke-width="2"/>' % (ly + 22 * i, ly + 22 * i, color))
        out.append('<text x="58" y="%d">%s</text>' % (ly + 22 * i + 4, esc(family)))
    out.append('<circle cx="300" cy="%d" r="7" fill="none" stroke="black" stroke-width="1.5"/>' % ly)
    out.append('<text x="314" y="%d">the default</text>' % (ly + 4))
    out.append('</svg>')
    return '\n'.join(out) + '\n'


def json_safe(x):
    """Infinities and NaN as strings, so the JSON is strict."""
    if isinstance(x, float) and not math.isfinite(x):
        return str(x)
    if isinstance(x, dict):
        return {k: json_safe(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [json_safe(v) for v in x]
    return x
