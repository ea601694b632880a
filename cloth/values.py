"""Reading a scene's values: each checked, and each error a SceneError whose one-line message
starts with the key it is about, so that the CLI, the page and `clothCore.run` say the same.
Messages never print a parsed number back: CPython and JS would spell it differently."""

import math

from cloth.host import kind_of, is_finite, as_index, code_units


class SceneError(Exception):
    """A scene, or a request about one, that the core refuses; the message names the key."""
    pass


def fail(message):
    raise SceneError(message)


HEX = '0123456789abcdef'
SHOWN_UNITS = 40


def shown(text):
    """A key from the input, fit for a one-line message that both runtimes write alike: at
    most SHOWN_UNITS characters, anything but printable ASCII as a \\uXXXX escape of its
    UTF-16 code unit (a newline would break the line, a lone surrogate prints differently)."""
    units = code_units(text)
    out = []
    for i in range(min(len(units), SHOWN_UNITS)):
        u = units[i]
        if u >= 32 and u < 127 and u != 92:
            out.append(chr(u))
        else:
            out.append('\\u' + HEX[(u >> 12) & 15] + HEX[(u >> 8) & 15] + HEX[(u >> 4) & 15] + HEX[u & 15])
    if len(units) > SHOWN_UNITS:
        out.append('...')
    return ''.join(out)


def number(value, key, lo, hi, lo_open, what):
    """A finite JSON number in [lo, hi] (or (lo, hi] when lo_open); `what` words the range."""
    if kind_of(value) != 'number':
        fail(key + ': must be a number')
    if not is_finite(value):
        fail(key + ': must be finite')
    if value < lo or value > hi or (lo_open and value == lo):
        fail(key + ': must be ' + what)
    return value


def integer(value, key, lo, hi, what):
    if kind_of(value) != 'number':
        fail(key + ': must be an integer')
    if not is_finite(value) or math.floor(value) != value:
        fail(key + ': must be an integer')
    if value < lo or value > hi:
        fail(key + ': must be ' + what)
    return as_index(value)


def boolean(value, key):
    if kind_of(value) != 'bool':
        fail(key + ': must be true or false')
    return value


def point(value, key):
    if kind_of(value) != 'list' or len(value) != 2:
        fail(key + ': must be a list of two numbers [x, y]')
    x = number(value[0], key, -1e9, 1e9, False, 'within 1e9 of the origin')
    y = number(value[1], key, -1e9, 1e9, False, 'within 1e9 of the origin')
    return [x, y]




def known(names, key):
    for i in range(len(names)):
        if names[i] == key:
            return True
    return False
