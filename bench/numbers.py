"""Numbers as the benchmark's tables show them."""

import math

def finite(x):
    return x is not None and isinstance(x, (int, float)) and math.isfinite(x)


def rms(values):
    if not values or not all(finite(v) for v in values):
        return float('nan')
    return math.sqrt(sum(v * v for v in values) / len(values))


def max_or_nan(values):
    if not values or not all(finite(v) for v in values):
        return float('nan')
    return max(values)


def ratio(a, b):
    if not finite(a) or not finite(b) or b == 0:
        return None
    return a / b


def setting(d):
    """'S8 x 2, tethers, tol 1e-4' from what the page reports for a loaded cloth."""
    parts = ['%s S%d x %d' % (d['solver'], d['substeps'], d['iterations'])]
    if d['tethers']:
        parts.append('tethers')
    if d.get('cells'):
        parts.append('cells')
    if d.get('lines'):
        parts.append('lines')
    if d['shear']:
        parts.append('shear')
    if d['tolerance']:
        parts.append('tol %g' % d['tolerance'])
    if d['compliance']:
        parts.append('compliance %g' % d['compliance'])
    if d.get('sleep'):
        parts.append('sleep')
    if d.get('tear'):
        parts.append('tear %g' % d['tear'])
    return ', '.join(parts)


def fmt(x, digits=3):
    if x is None:
        return '-'
    if not finite(x):
        return 'NaN'
    if x == 0:
        return '0'
    if 1e-3 <= abs(x) < 1e4:
        return '%.*g' % (digits, x)
    return '%.*e' % (digits - 1, x)


def fmt_ratio(x):
    return '-' if x is None else '%.2fx' % x
