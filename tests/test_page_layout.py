"""The page's files depend one way (README, "Layout"): each uses only the globals of files
linked before it, and input turns pointers into gestures without knowing the app."""

import os
import re

import build
from build import WEBGL


def globals_of(name):
    with open(os.path.join(WEBGL, name), encoding='utf-8') as f:
        text = f.read()
    defined = set(re.findall(r'window\.(cloth\w+)\s*=', text))
    used = set(re.findall(r'window\.(cloth\w+)', text)) - defined
    return defined, used


def test_each_file_uses_only_what_comes_before_it():
    before = set()
    for name in build.SCRIPTS:
        defined, used = globals_of(name)
        assert used <= before, (name, sorted(used - before))
        before |= defined


def test_every_page_file_is_linked():
    on_disk = {f for f in os.listdir(WEBGL) if f.endswith('.js')}
    assert on_disk == set(build.SCRIPTS)


def test_input_and_gestures_know_no_other_file():
    for name in ('input.js', 'gestures.js'):
        assert globals_of(name)[1] == set(), name
    users = {name for name in build.SCRIPTS
             if {'clothInput', 'clothGestures'} & globals_of(name)[1]}
    assert users == {'app.js'}


def test_the_renderer_never_reads_a_cloth():
    """It draws a snapshot (clothCore.snapshot); comments and messages may name the cloth,
    code may not."""
    with open(os.path.join(WEBGL, 'renderer.js'), encoding='utf-8') as f:
        code = [re.sub(r"'[^']*'", "''", line.split('//')[0]) for line in f]
    assert not [line for line in code if re.search(r'\bcloth\b', line)]
