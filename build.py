"""Build the page: transpile the core with Transcrypt, link it into one classic
script, and inline it with the hand-written webgl/ sources into dist/index.html.

    python build.py            # write dist/index.html
    python build.py --check    # exit 1 if dist/index.html is not what the sources give

Why a linker: Transcrypt 3.9 emits only ES modules, and Chromium refuses module
scripts (and their imports) on a file:// page. So each module, the core's and the
page's own (webgl/, in folders by layer), is wrapped in a function scope, its
`import` lines become reads from the modules evaluated before it (dependency order)
and its `export`s become the function's return value. Only single-line
`import {a, b as c} from './x.js'`, `import * as m from '../y/z.js'`, `export <decl>`
and `export {a, b as c}` are accepted; anything else stops the build.

Reproducible: Transcrypt's timestamp line and sourceMappingURL lines are dropped,
files are read in a fixed order, so the same sources give a byte-identical dist/.
Transcrypt's -b wipes its output folder, so it writes into build/, never dist/.
"""
import argparse
import os
import posixpath
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.abspath(__file__))
ENTRY = os.path.join('cloth', 'api.py')
TRANSCRYPT_OUT = os.path.join(ROOT, 'build', 'transcrypt')
WEBGL = os.path.join(ROOT, 'webgl')
DIST_HTML = os.path.join(ROOT, 'dist', 'index.html')

# The hand-written page: ES modules in folders by layer, each importing only from its own
# layer or one listed before it (tests/test_page_layout.py), linked from app.js, the loop
# and the wiring, which sits above them all.
LAYERS = ['sim', 'draw', 'input', 'ui']
PAGE_ENTRY = 'app'
# The session's Web Worker: this module and what it imports, linked into a script of its own
# that the page inlines as text (<script type="text/plain" id="cloth-worker">) and starts, with
# the core's script (id="cloth-core"), as a Worker made from a Blob (webgl/sim/remote.js).
WORKER_ENTRY = 'sim/worker'
STYLES = ['style.css']
# GLSL, inlined as <script type="x-shader/x-vertex|fragment" id="shader-NAME"> for renderer.js.
SHADERS = ['colour.glsl', 'edge-quad.glsl', 'edge.vert', 'edge-fetch.vert', 'es3.vert', 'es3.frag', 'edge.frag', 'cell.vert', 'cell.frag', 'mark.vert', 'mark.frag']
TEMPLATE = 'index.html'

_IMPORT_NAMED = re.compile(r"^import\s*\{([^}]*)\}\s*from\s*'(\.\.?/[^']+)\.js';?\s*$")
_IMPORT_STAR = re.compile(r"^import\s*\*\s*as\s+([\w$]+)\s+from\s*'(\.\.?/[^']+)\.js';?\s*$")
_EXPORT_DECL = re.compile(r'^export\s+(var|let|const|function\*?|class|async\s+function)\s+([\w$]+)')
_EXPORT_LIST = re.compile(r'^export\s*\{([^}]*)\}\s*;?\s*$')
# Transcrypt passes some JS reserved words through as variable names (a Python
# local called `do` becomes `var do`), which only fails when the page loads.
_RESERVED = re.compile(r'\b(?:var|let|const)\s+(do|if|in|for|new|try|case|else|enum|this|void|with|'
                       r'break|catch|class|const|super|throw|while|yield|delete|export|import|'
                       r'return|static|switch|typeof|extends|finally|continue|debugger|function|'
                       r'instanceof|interface|package|private|protected|public|implements)\b')
_TIMESTAMP = re.compile(r"^// Transcrypt'ed from Python, ")
_SOURCEMAP = re.compile(r'^//# sourceMappingURL=')


class BuildError(Exception):
    pass


def transpile(out_dir=TRANSCRYPT_OUT):
    """Run Transcrypt on the entry module; -od must be absolute (it is taken
    relative to the source file's folder otherwise)."""
    cmd = [sys.executable, '-m', 'transcrypt', '-n', '-b', '-od', out_dir, ENTRY]
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if proc.returncode != 0 or not os.path.exists(os.path.join(out_dir, 'api.js')):
        raise BuildError('transcrypt failed:\n' + proc.stdout + proc.stderr)
    return out_dir


def _ident(module):
    return '__m_' + re.sub(r'[^\w$]', '_', module)


def _split_names(spec):
    """'a, b as c' -> [('a', 'a'), ('b', 'c')] (exported name, local name)."""
    out = []
    for part in spec.split(','):
        part = part.strip()
        if not part:
            continue
        bits = part.split()
        if len(bits) == 1:
            out.append((bits[0], bits[0]))
        elif len(bits) == 3 and bits[1] == 'as':
            out.append((bits[0], bits[2]))
        else:
            raise BuildError('cannot parse import/export list: ' + spec)
    return out


def resolve(module, spec):
    """The module an import of `spec` ('./x', '../sim/y') from `module` ('ui/z') names: its
    path under the linked folder, without '.js' ('x', 'sim/y')."""
    path = posixpath.normpath(posixpath.join(posixpath.dirname(module), spec))
    if path.startswith('..'):
        raise BuildError('%s: import %r reaches outside the linked folder' % (module, spec))
    return path


def parse_module(text, module):
    """Return (deps, prologue lines, body lines, exports [(exported, local)])."""
    deps, prologue, body, exports = [], [], [], []
    for line in text.split('\n'):
        if _TIMESTAMP.match(line) or _SOURCEMAP.match(line):
            continue
        m = _RESERVED.search(line)
        if m:
            raise BuildError('%s: the Python source uses the JS reserved word %r as a name: %s'
                             % (module, m.group(1), line.strip()[:120]))
        m = _IMPORT_NAMED.match(line)
        if m:
            dep = resolve(module, m.group(2))
            deps.append(dep)
            for exported, local in _split_names(m.group(1)):
                prologue.append('var %s = %s.%s;' % (local, _ident(dep), exported))
            continue
        m = _IMPORT_STAR.match(line)
        if m:
            dep = resolve(module, m.group(2))
            deps.append(dep)
            prologue.append('var %s = %s;' % (m.group(1), _ident(dep)))
            continue
        if line.startswith('import ') or line.startswith('import{'):
            raise BuildError('%s: unsupported import form: %s' % (module, line[:120]))
        m = _EXPORT_DECL.match(line)
        if m:
            exports.append((m.group(2), m.group(2)))
            body.append(line[len('export'):].lstrip())
            continue
        m = _EXPORT_LIST.match(line)
        if m:
            for local, exported in _split_names(m.group(1)):
                exports.append((exported, local))
            continue
        if line.startswith('export ') or line.startswith('export{'):
            raise BuildError('%s: unsupported export form: %s' % (module, line[:120]))
        body.append(line)
    while body and not body[-1].strip():
        body.pop()
    return deps, prologue, body, exports


def modules(js_dir, entry):
    """The ES modules under js_dir reachable from entry, parsed, in dependency order:
    [(module, (deps, prologue, body, exports))]."""
    parsed = {}
    order = []

    def visit(module, stack):
        if module in parsed:
            if module in stack:
                raise BuildError('import cycle: ' + ' -> '.join(stack + [module]))
            return
        path = os.path.join(js_dir, *(module + '.js').split('/'))
        if not os.path.exists(path):
            raise BuildError('missing module ' + path)
        with open(path, encoding='utf-8') as f:
            parsed[module] = parse_module(f.read(), module)
        for dep in parsed[module][0]:
            visit(dep, stack + [module])
        order.append(module)

    visit(entry, [])
    return [(m, parsed[m]) for m in order]


def wrapped(module, parsed, label):
    """One module as a function scope whose value is its exports."""
    deps, prologue, body, exports = parsed
    out = ['// ---- %s ----' % label, 'var %s = (function () {' % _ident(module), "'use strict';"]
    out.extend(prologue)
    out.extend(body)
    out.append('return {%s};' % ', '.join('%s: %s' % (e, local) for e, local in exports))
    out.append('})();')
    return out


def link(js_dir, entry='api'):
    """Link the ES modules under js_dir, reachable from entry, into one classic
    script that defines the single global `clothTranscrypt` = {api}."""
    out = ['// Generated by build.py from cloth/ via Transcrypt: do not edit.',
           'var clothTranscrypt = (function () {']
    for module, parsed in modules(js_dir, entry):
        out.extend(wrapped(module, parsed, 'module ' + module))
    # Only the entry point: the page and the benchmark go through cloth/api.py, never past it.
    out.append('return {api: %s};' % _ident(entry))
    out.append('})();')
    return '\n'.join(out) + '\n'


def page_files():
    """Every page source under webgl/, as module names ('app', 'sim/core', ...)."""
    found = []
    for folder, _, files in os.walk(WEBGL):
        for name in files:
            if name.endswith('.js'):
                rel = os.path.relpath(os.path.join(folder, name), WEBGL)
                found.append(rel[:-3].replace(os.sep, '/'))
    return sorted(found)


def layer_of(module):
    """The layer a page module belongs to: its folder (LAYERS), or 'app' at the top."""
    return module.split('/')[0] if '/' in module else 'app'


def link_worker():
    """The Worker's modules, from webgl/sim/worker.js down, as one classic script that serves
    the messages of the Worker it runs in (after the core's script)."""
    linked = modules(WEBGL, WORKER_ENTRY)
    bad = [m for m, _ in linked if layer_of(m) != 'sim']
    if bad:
        raise BuildError('the Worker reaches modules outside sim/: %s' % bad)
    out = ['(function () {']
    for module, parsed in linked:
        out.extend(wrapped(module, parsed, 'webgl/%s.js' % module))
    out.append('%s.clothWorker.serve(self);' % _ident(WORKER_ENTRY))
    out.append('})();')
    return '\n'.join(out) + '\n'


def link_page():
    """The page's modules, from webgl/app.js down, as one classic script: no global of its
    own (the test seam publishes what the tests and the benchmark reach)."""
    linked = modules(WEBGL, PAGE_ENTRY)
    names = [m for m, _ in linked] + [m for m, _ in modules(WEBGL, WORKER_ENTRY)]
    missing = sorted(set(page_files()) - set(names))
    if missing:
        raise BuildError('page files that neither app.js nor the Worker reaches: %s' % missing)
    bad = [m for m in names if layer_of(m) not in LAYERS + ['app'] or (layer_of(m) == 'app' and m != PAGE_ENTRY)]
    if bad:
        raise BuildError('page files outside the layers %s: %s' % (LAYERS, bad))
    out = ['(function () {']
    for module, parsed in linked:
        out.extend(wrapped(module, parsed, 'webgl/%s.js' % module))
    out.append('})();')
    return '\n'.join(out) + '\n'


def _read(name):
    with open(os.path.join(WEBGL, name), encoding='utf-8') as f:
        return f.read()


def _inline_safe(text, name):
    # Inside <script>, '</script' ends the element and '<!--' can change how the
    # parser reads the rest; neither may appear in the inlined code.
    text = re.sub(r'</(script)', r'<\\/\1', text, flags=re.IGNORECASE)
    if '<!--' in text:
        raise BuildError(name + ": contains '<!--', which is unsafe inside an inline <script>")
    return text


def page(core_js):
    """dist/index.html: the template with styles and scripts inlined."""
    shader_dir = os.path.join(WEBGL, 'shaders')
    present = set(os.listdir(shader_dir))
    if present != set(SHADERS):
        raise BuildError('webgl/shaders/ and build.SHADERS differ: %s' % sorted(present ^ set(SHADERS)))
    css = ''.join(_read(n) for n in STYLES)
    blocks = []
    for name in SHADERS:
        kind = 'x-shader/x-vertex' if name.endswith('.vert') else 'x-shader/x-fragment'
        blocks.append('<script type="%s" id="shader-%s">\n%s</script>' % (
            kind, name, _inline_safe(_read(os.path.join('shaders', name)), name)))
    blocks.append('<script id="cloth-core">\n' + _inline_safe(core_js, 'core') + '</script>')
    blocks.append('<script type="text/plain" id="cloth-worker">\n' + _inline_safe(link_worker(), 'worker') + '</script>')
    blocks.append('<script>\n' + _inline_safe(link_page(), 'webgl') + '</script>')
    html = _read(TEMPLATE)
    for marker in ('<!-- @style -->', '<!-- @scripts -->'):
        if html.count(marker) != 1:
            raise BuildError('template needs exactly one ' + marker)
    html = html.replace('<!-- @style -->', '<style>\n' + css + '</style>')
    html = html.replace('<!-- @scripts -->', '\n'.join(blocks))
    return html


def build(out_dir=TRANSCRYPT_OUT):
    return page(link(transpile(out_dir)))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--check', action='store_true',
                    help='exit 1 if dist/index.html differs from a fresh build; write nothing in dist/')
    ap.add_argument('--open', action='store_true',
                    help='open dist/index.html in the default browser after building')
    args = ap.parse_args(argv)
    try:
        if args.check:
            with tempfile.TemporaryDirectory(prefix='cloth-build-') as tmp:
                html = build(os.path.join(tmp, 'transcrypt'))
        else:
            html = build()
    except BuildError as e:
        print('build.py: ' + str(e), file=sys.stderr)
        return 2
    data = html.encode('utf-8')
    if args.check:
        try:
            with open(DIST_HTML, 'rb') as f:
                current = f.read()
        except OSError:
            current = None
        if current != data:
            print('build.py: dist/index.html is stale; run `python build.py`', file=sys.stderr)
            return 1
        print('dist/index.html is up to date')
        return 0
    os.makedirs(os.path.dirname(DIST_HTML), exist_ok=True)
    with open(DIST_HTML, 'wb') as f:
        f.write(data)
    print('wrote dist/index.html (%d bytes)' % len(data))
    if args.open:
        import pathlib
        import webbrowser
        url = pathlib.Path(DIST_HTML).resolve().as_uri()
        if not webbrowser.open(url):
            print('open this in a browser: ' + url)
    return 0


if __name__ == '__main__':
    sys.exit(main())
