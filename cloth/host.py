"""What differs between the two runtimes, and nothing else.

Everything in the core above this module is plain Python that Transcrypt turns into the
same arithmetic in JS. Here live the few primitives whose best form differs: storage (lists in
CPython, where a list comprehension is 2.3x faster than `array.array`; typed arrays in JS,
which is what makes the transpiled kernel as fast as hand-written JS), JSON, and the type
tests that JSON values need (Transcrypt's `isinstance` does not know JS's plain objects).
"""

# __pragma__ ('skip')
import json as _json
import math as _math
import re as _re


def f64(n):
    return [0.0 for _ in range(n)]


def i32(n):
    return [0 for _ in range(n)]


def _reject_constant(name):
    raise ValueError(name)


def parse_json(text):
    """Parse JSON text the way JS's JSON.parse does: every number a double, no NaN or Infinity.

    Returns None when the text is not valid JSON (the caller words the error)."""
    if not isinstance(text, str):
        return None
    try:
        return (True, _json.loads(text, parse_int=float, parse_constant=_reject_constant))
    except (ValueError, RecursionError):
        return None


def too_deep(text, limit):
    """True when the text nests arrays and objects more than `limit` deep (outside strings),
    checked before parsing: CPython's parser gives up (RecursionError) near 1000 levels where
    JSON.parse does not, and a bound that both runtimes test the same way says the same thing
    in both. Invalid text is measured all the same, so the order of the checks agrees too."""
    if not isinstance(text, str) or text.count('[') + text.count('{') <= limit:
        return False
    bare = _re.sub(r'[^\[\]{}]', '', _STRING.sub('', text))
    depth = 0
    for c in bare:
        if c == '[' or c == '{':
            depth += 1
            if depth > limit:
                return True
        else:
            depth -= 1
    return False


# A string as JS's scanner below skips it: an escape takes the next character, and an
# unterminated string runs to the end of the text.
_STRING = _re.compile(r'"(?:[^"\\]|\\[\s\S])*(?:"|\\?\Z)')


def to_json(value):
    """JSON text exactly as JS's JSON.stringify writes it, so that the CLI and the page print
    the same characters (Python writes 1.0 and 1e-07 where JS writes 1 and 1e-7)."""
    out = []
    _write_json(value, out)
    return ''.join(out)


def _write_json(value, out):
    if value is None or isinstance(value, (bool, str)):
        out.append(_json.dumps(value))
    elif isinstance(value, (int, float)):
        out.append(js_number(value))
    elif isinstance(value, (list, tuple)):
        out.append('[')
        for i, item in enumerate(value):
            if i:
                out.append(',')
            _write_json(item, out)
        out.append(']')
    elif isinstance(value, dict):
        out.append('{')
        for i, (key, item) in enumerate(value.items()):
            if i:
                out.append(',')
            out.append(_json.dumps(str(key)))
            out.append(':')
            _write_json(item, out)
        out.append('}')
    else:
        raise TypeError('not JSON: %r' % (value,))


def js_number(x):
    """A finite number as JS's Number.prototype.toString writes it (ECMA-262 Number::toString):
    the shortest digits that round-trip (Python's repr finds the same ones), in plain notation
    for 1e-7 <= |x| < 1e21, else as d.ddde+n."""
    x = float(x)
    if not _math.isfinite(x):
        raise ValueError('JSON has no NaN or Infinity')
    if x == 0.0:
        return '0'
    sign = '-' if x < 0 else ''
    mantissa, _, exponent = repr(abs(x)).partition('e')
    whole, _, frac = mantissa.partition('.')
    digits = (whole + frac).lstrip('0')
    # value = 0.digits x 10^n, with n counted from the decimal point of `mantissa`
    n = len(whole.lstrip('0')) if whole.strip('0') else -(len(frac) - len(frac.lstrip('0')))
    n += int(exponent or 0)
    digits = digits.rstrip('0')
    k = len(digits)
    if k <= n <= 21:
        text = digits + '0' * (n - k)
    elif 0 < n <= 21:
        text = digits[:n] + '.' + digits[n:]
    elif -6 < n <= 0:
        text = '0.' + '0' * (-n) + digits
    else:
        e = n - 1
        text = digits[0] + ('.' + digits[1:] if k > 1 else '') + 'e' + ('+' if e >= 0 else '-') + \
            str(abs(e))
    return sign + text


def kind_of(value):
    """'null', 'bool', 'number', 'string', 'list' or 'object', as JSON sees the value."""
    if value is None:
        return 'null'
    if isinstance(value, bool):
        return 'bool'
    if isinstance(value, (int, float)):
        return 'number'
    if isinstance(value, str):
        return 'string'
    if isinstance(value, (list, tuple)):
        return 'list'
    if isinstance(value, dict):
        return 'object'
    return 'other'


def is_finite(x):
    return _math.isfinite(x)


def key_list(obj):
    return list(obj.keys())


def has_key(obj, key):
    return key in obj


def code_units(text):
    """The UTF-16 code units of a string, as JS sees it (a lone surrogate is one unit)."""
    data = text.encode('utf-16-le', 'surrogatepass')
    return [data[i] | (data[i + 1] << 8) for i in range(0, len(data), 2)]


def copy_object(obj, skip, over):
    """A new JSON object: obj's keys but those in `skip`, then the keys of `over` (or None)
    written over them."""
    out = {key: value for key, value in obj.items() if key not in skip}
    if over is not None:
        out.update(over)
    return out


def as_index(x):
    return int(x)
# __pragma__ ('noskip')

# __pragma__ ('ecom')
'''?
def f64(n):
    return __new__ (Float64Array (n))


def i32(n):
    return __new__ (Int32Array (n))


def parse_json(text):
    if typeof (text) != 'string':
        return None
    try:
        return [True, JSON.parse (text)]
    except:
        return None


def too_deep(text, limit):
    if typeof (text) != 'string':
        return False
    depth = 0
    inside = False
    i = 0
    n = text.length
    while i < n:
        c = text.charCodeAt (i)
        if inside:
            if c == 92:
                i += 1
            elif c == 34:
                inside = False
        elif c == 34:
            inside = True
        elif c == 91 or c == 123:
            depth += 1
            if depth > limit:
                return True
        elif c == 93 or c == 125:
            depth -= 1
        i += 1
    return False


def to_json(value):
    return JSON.stringify (value)


def kind_of(value):
    if value is None:
        return 'null'
    t = typeof (value)
    if t == 'boolean':
        return 'bool'
    if t == 'number':
        return 'number'
    if t == 'string':
        return 'string'
    if Array.isArray (value):
        return 'list'
    if t == 'object':
        return 'object'
    return 'other'


def is_finite(x):
    return Number.isFinite (x)


def key_list(obj):
    # Written as raw JS: Transcrypt would rename `keys` to `py_keys`.
    return __pragma__ ('js', '{}', 'Object.keys (obj)')


def has_key(obj, key):
    return __pragma__ ('js', '{}', 'Object.prototype.hasOwnProperty.call (obj, key)')


def code_units(text):
    units = []
    for i in range(text.length):
        units.append(text.charCodeAt(i))
    return units


def copy_object(obj, skip, over):
    # A plain JS object (a Transcrypt dict literal would carry its methods).
    out = __pragma__ ('js', '{}', '{}')
    __pragma__ ('js', '{}', """
    for (const key of Object.keys (obj)) {
        if (skip.indexOf (key) < 0) out [key] = obj [key];
    }
    if (over !== null && over !== undefined) {
        for (const key of Object.keys (over)) out [key] = over [key];
    }""")
    return out


def as_index(x):
    return x
?'''
# __pragma__ ('noecom')
