"""python -m cloth run SCENE.json --frames N [--trace]: print what `cloth.api.run` returns.

CPython only (never transpiled). Bad input exits with status 2 and one line naming the key.
"""

import argparse
import sys

from cloth.api import run
from cloth.scene import SceneError


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
    p_run.add_argument('--frames', type=int, required=True, help='frames to simulate (>= 0)')
    p_run.add_argument('--trace', action='store_true', help='add the positions after every frame')
    args = parser.parse_args(argv)
    try:
        if args.scene == '-':
            text = sys.stdin.read()
        else:
            with open(args.scene, encoding='utf-8') as f:
                text = f.read()
    except (OSError, UnicodeDecodeError) as err:
        sys.stderr.write('error: scene: cannot read ' + args.scene + ': ' +
                         (err.strerror or str(err)) + '\n')
        return 2
    try:
        out = run(text, args.frames, args.trace)
    except SceneError as err:
        sys.stderr.write('error: ' + str(err) + '\n')
        return 2
    sys.stdout.write(out + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
