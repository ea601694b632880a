"""python -m cloth run SCENE.json [--frames N] [--trace]: print what `cloth.api.run` returns.
python -m cloth keys: every scene key, its range, unit and default, as a Markdown table (from
cloth/keys.py KEYS, where each key is declared once).

CPython only (never transpiled). Bad input exits with status 2 and one line naming the key
(JSON that does not parse: its line and column). A run longer than PROGRESS_AFTER shows its
progress on standard error (a bar on a terminal, a line every PROGRESS_EVERY_LOG seconds
otherwise); Ctrl+C ends it with a one-line note and status 130.
"""

import argparse
import json
import os
import shutil
import sys
import tempfile
import time

from cloth.api import load, start, frames_of, simulate, result_of
from cloth.host import to_json
from cloth.values import SceneError
from cloth.keys import MAX_SCENE_BYTES, KEYS
from cloth.keys import SOLVERS
from cloth.scene import too_large

PROGRESS_AFTER = 1.0        # s: a run that ends sooner shows no progress
PROGRESS_EVERY_TTY = 0.2    # s between redraws of the bar on a terminal
PROGRESS_EVERY_LOG = 5.0    # s between lines where standard error is a file or a pipe
BAR = 30


class Parser(argparse.ArgumentParser):
    def error(self, message):
        # argparse's usage block is several lines; the contract is one line.
        sys.stderr.write('error: ' + message + '\n')
        sys.exit(2)


def main(argv=None):
    parser = Parser(prog='python -m cloth', description='Run a cloth scene headless.')
    sub = parser.add_subparsers(dest='command', required=True)
    p_run = sub.add_parser('run', help='run SCENE.json for N frames and print the result JSON')
    p_run.add_argument('scene', help='path to a scene JSON file, or - for standard input')
    p_run.add_argument('--frames', type=int, default=None,
                       help='frames to simulate (>= 0); default: the scene\'s "frames" key')
    p_run.add_argument('--trace', action='store_true', help='add the positions after every frame')
    p_run.add_argument('--panel', type=int, default=None,
                       help='run panel N (1 = the first) of the scene\'s "compare" list')
    sub.add_parser('keys', help='print every scene key, its range and default (Markdown)')
    args = parser.parse_args(argv)
    if args.command == 'keys':
        sys.stdout.write(keys_table())
        return 0
    if sys.stdout is None or (args.scene == '-' and sys.stdin is None):
        # A closed stream (`>&-`, `<&-`): Python makes it None.
        say('error: ' + ('output: standard output is closed' if sys.stdout is None else
                         'scene: standard input is closed'))
        return 2
    try:
        # Never more than the limit (and a byte to tell) is read.
        if args.scene == '-':
            data = sys.stdin.buffer.read(MAX_SCENE_BYTES + 1)
        else:
            with open(args.scene, 'rb') as f:
                data = f.read(MAX_SCENE_BYTES + 1)
    except OSError as err:
        sys.stderr.write('error: scene: cannot read ' + args.scene + ': ' +
                         (err.strerror or str(err)) + '\n')
        return 2
    if len(data) > MAX_SCENE_BYTES:
        sys.stderr.write('error: ' + too_large() + '\n')
        return 2
    # Bytes, decoded here: the same bytes from a file or from standard input give the same
    # answer whatever the locale, and text that is not UTF-8 is bad input like any other.
    try:
        text = data.decode('utf-8-sig')  # a leading byte-order mark is not content
    except UnicodeDecodeError as err:
        sys.stderr.write('error: scene: not UTF-8 text (invalid byte at offset ' +
                         str(err.start) + ')\n')
        return 2
    # --panel N counts from 1, as the page labels its panels; the core from 0.
    panel = -1 if args.panel is None else (args.panel - 1 if args.panel >= 1 else 10 ** 9)
    progress = None
    try:
        cloth = load(text, panel)
        frames = frames_of(cloth, args.frames)
        start(cloth, frames, args.trace)
        progress = Progress(frames, sys.stderr)
        if args.trace:
            stream_trace(cloth, frames, sys.stdout, progress)
        else:
            simulate(cloth, frames, None, progress)
            progress.end()
            sys.stdout.write(to_json(result_of(cloth, frames)) + '\n')
        sys.stdout.flush()
    except SceneError as err:
        sys.stderr.write('error: ' + str(err) + where_json_fails(text, str(err)) + '\n')
        return 2
    except KeyboardInterrupt:
        # Ctrl+C: the run ends here, with one line saying where, and no result.
        if progress is not None:
            progress.end()
        say('interrupted' + (' at frame %d of %d' % (progress.frame, progress.frames) if progress is not None else '') +
            ': no result written')
        return 130
    except BrokenPipeError:
        # The reader went away (`| head`): not an error of ours, and no traceback.
        quiet_stdout()
        return 1
    except OSError as err:
        # The output could not be written (a full disk, /dev/full): one line, no traceback.
        quiet_stdout()
        say('error: output: cannot write the result: ' + (err.strerror or str(err)))
        return 1
    return 0


def keys_table():
    """KEYS as a Markdown table: key, what it takes, unit, default (per solver where the
    solvers differ), settable live in the page."""
    def shown(v):
        return 'none' if v is None or v == -1 else json.dumps(v)
    lines = ['| key | takes | unit | default | live |', '|---|---|---|---|---|']
    for k in KEYS:
        takes = k.words or {'pins': 'a list of vertex indices', 'choice': ' or '.join(SOLVERS),
                            'actions': 'a list of actions (grab, move, release, pin, unpin, set, '
                                       'cut, obstacle)',
                            'bool': 'true or false', 'string': 'a label',
                            'compare': 'a list of 2 to 4 objects of panel keys',
                            'obstacles': 'a list of {"circle": [x, y, r]} or {"box": [x0, y0, x1, y1]}, '
                                         'each with an optional "friction" from 0 to 1'}.get(k.kind, k.kind)
        if k.by_solver is not None:
            default = ', '.join('%s %s' % (SOLVERS[i], k.by_solver[i]) for i in range(len(SOLVERS)))
        else:
            default = shown(k.fallback)
        lines.append('| `%s` | %s | %s | %s | %s |' % (k.key, takes, k.unit, default,
                                                      'yes' if k.live else ''))
    return '\n'.join(lines) + '\n'


def where_json_fails(text, message):
    """For text that is not JSON, where it fails (Python's parser, the CLI's alone: the core's
    message is the page's too): ' at line L, column C: what'."""
    if message != 'scene: not valid JSON':
        return ''
    def constant(name):
        raise ValueError(name + ' is not JSON')
    try:
        json.loads(text, parse_constant=constant)
    except json.JSONDecodeError as err:
        return ' at line %d, column %d: %s' % (err.lineno, err.colno, err.msg)
    except ValueError as err:
        return ' (%s)' % err
    except RecursionError:
        return ''
    return ''


class Progress:
    """A run's progress on `stream` (standard error), once it has taken PROGRESS_AFTER: a bar
    redrawn in place on a terminal, a line now and then otherwise."""

    def __init__(self, frames, stream):
        self.frames = frames
        self.frame = 0
        self.stream = stream
        self.t0 = time.monotonic()
        self.shown = float('-inf')
        try:
            self.tty = stream is not None and stream.isatty()
        except (AttributeError, ValueError):
            self.tty = False
        self.drawn = False

    def __call__(self, f):
        self.frame = f
        now = time.monotonic()
        if (self.stream is None or now - self.t0 < PROGRESS_AFTER or
                now - self.shown < (PROGRESS_EVERY_TTY if self.tty else PROGRESS_EVERY_LOG)):
            return
        self.shown = now
        share = f / self.frames if self.frames > 0 else 1.0
        left = (now - self.t0) * (self.frames - f) / f
        if self.tty:
            full = int(BAR * share)
            self.stream.write('\r[%s%s] %3d%%  frame %d of %d, %s left ' % (
                '#' * full, '.' * (BAR - full), int(100 * share), f, self.frames, duration(left)))
            self.drawn = True
        else:
            self.stream.write('frame %d of %d (%d%%), %s left\n' % (f, self.frames, int(100 * share), duration(left)))
        self.stream.flush()

    def end(self):
        if self.drawn:
            self.stream.write('\r' + ' ' * (BAR + 50) + '\r')
            self.stream.flush()
            self.drawn = False


def duration(seconds):
    if seconds < 90:
        return '%d s' % round(seconds)
    if seconds < 5400:
        return '%d min' % round(seconds / 60)
    return '%.1f h' % (seconds / 3600)


def quiet_stdout():
    """Python would report the failed flush again at exit: stdout goes to devnull first."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except OSError:
        pass


def say(line):
    if sys.stderr is not None:
        sys.stderr.write(line + '\n')


class TraceFile:
    """What `simulate` appends a frame's positions to: the frame goes to a temporary file as
    JSON text at once, so that memory holds one frame, never the whole trace."""

    def __init__(self, f):
        self.f = f
        self.count = 0

    def append(self, positions):
        if self.count:
            self.f.write(',')
        self.f.write(to_json(positions))
        self.count += 1


def stream_trace(cloth, frames, out, progress):
    """The text `run(text, frames, True)` returns, character for character (the trace is
    its last key), written to `out` with the trace streamed through a temporary file."""
    with tempfile.TemporaryFile('w+', encoding='utf-8') as spool:
        simulate(cloth, frames, TraceFile(spool), progress)
        progress.end()
        head = to_json(result_of(cloth, frames))
        out.write(head[:-1] + ',"trace":[')
        spool.seek(0)
        shutil.copyfileobj(spool, out, 1 << 20)
        out.write(']}\n')


if __name__ == '__main__':
    sys.exit(main())
