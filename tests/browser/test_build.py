"""build.py's linker on the ES-module forms Transcrypt emits (no browser needed)."""
import shutil
import subprocess
import sys

import pytest

from browser_helpers import ROOT

sys.path.insert(0, str(ROOT))
import build  # noqa: E402

MODULES = {
    'a': ("// Transcrypt'ed from Python, 2026-01-01 00:00:00\n"
          "var __name__ = 'a';\n"
          "export var one = 1;\n"
          "export function two () { return 2; }\n"
          "var hidden = 3;\n"
          "export {hidden as three};\n"
          "//# sourceMappingURL=a.map\n"),
    'b.c': ("import {one, two as deux, three} from './a.js';\n"
            "import * as __module_a__ from './a.js';\n"
            "export class Sum { total () { return one + deux () + three + __module_a__.one; } }\n"),
    'api': ("import {Sum} from './b.c.js';\n"
            "export var run = function () { return new Sum ().total (); };\n"),
}


def write(tmp_path, modules):
    for name, text in modules.items():
        (tmp_path / (name + '.js')).write_text(text)


def test_link_orders_scopes_and_exports(tmp_path):
    write(tmp_path, MODULES)
    js = build.link(str(tmp_path))
    assert "Transcrypt'ed" not in js and 'sourceMappingURL' not in js
    assert 'import ' not in js and 'export ' not in js
    assert js.index('var __m_a =') < js.index('var __m_b_c =') < js.index('var __m_api =')
    assert js == build.link(str(tmp_path))  # deterministic
    node = shutil.which('node')
    if node:
        out = subprocess.run([node, '-e', js + '\nconsole.log(clothTranscrypt.api.run(),'
                              ' Object.keys(clothTranscrypt).join())'],
                             capture_output=True, text=True, check=True).stdout
        assert out.strip() == '7 api'   # nothing past the entry point is exposed


@pytest.mark.parametrize('line', ["import x from './a.js';", "export default 3;",
                                  "var do = 1;"])
def test_link_refuses_what_it_cannot_translate(tmp_path, line):
    write(tmp_path, {'a': 'export var one = 1;\n', 'api': line + '\n'})
    with pytest.raises(build.BuildError):
        build.link(str(tmp_path))


def test_link_refuses_cycles(tmp_path):
    write(tmp_path, {'api': "import {b} from './b.js';\nexport var a = 1;\n",
                     'b': "import {a} from './api.js';\nexport var b = 1;\n"})
    with pytest.raises(build.BuildError, match='cycle'):
        build.link(str(tmp_path))
