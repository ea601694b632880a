"""Smoke test of the benchmark: `python -m bench --quick` runs the shipped page in Chromium
and writes the speed-against-error front at 30x30. No timing thresholds (machines are noisy):
what is checked is that every configuration ran, its errors are measured against the exact
statics, and the table, the JSON and the plots say the same."""

import json
import os
import re
import subprocess
import sys

import pytest

from bench import front

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

pytestmark = pytest.mark.browser


@pytest.fixture(scope='module')
def quick(tmp_path_factory):
    pytest.importorskip('playwright.sync_api')
    out = tmp_path_factory.mktemp('bench')
    proc = subprocess.run([sys.executable, '-m', 'bench', '--quick', '--out', str(out)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return proc, out


def table_rows(markdown, section):
    """The rows of the table under `## section`, as lists of cells."""
    part = markdown.split('## ' + section + '\n', 1)[1].split('\n## ', 1)[0]
    rows = [[c.strip() for c in m.group(1).split('|')]
            for m in re.finditer(r'^\| (.+) \|$', part, re.M)]
    return [r for r in rows[1:] if not r[0].startswith('---')]


def test_quick_writes_the_front_and_its_plots(quick):
    proc, out = quick
    assert proc.stderr.strip(), 'no progress on stderr'
    md = (out / 'front-quick.md').read_text()
    assert md.startswith('# Speed against error') and proc.stdout == md
    for name in ['front-quick-field.svg', 'front-quick-shape.svg']:
        svg = (out / name).read_text()
        assert svg.startswith('<svg') and svg.rstrip().endswith('</svg>'), name


def test_every_configuration_ran_and_the_table_matches_the_json(quick):
    proc, out = quick
    md = (out / 'front-quick.md').read_text()
    rows = json.loads((out / 'front-quick.json').read_text())['rows']
    for scene in front.SCENES:
        table = table_rows(md, '%s 30x30' % scene)
        assert [r[0] for r in table] == front.QUICK_CONFIGS, (scene, table)
        for cells in table:
            r = next(r for r in rows if r['scene'] == scene and r['n'] == 30 and r['config'] == cells[0])
            # | configuration | ms/frame | x seed (range) | sweeps | corrections | field error | ...
            assert float(cells[1]) == pytest.approx(r['ms'], rel=5e-3)
            assert float(cells[2].split()[0]) == pytest.approx(r['ratio'], abs=5e-3)
            assert r['ratio_lo'] <= r['ratio'] <= r['ratio_hi']
            assert float(cells[5]) == pytest.approx(r['field'], rel=5e-2)
            assert r['ms'] > 0 and r['field'] >= 0 and r['shape'] >= 0
        # What the exact statics tell apart: the seed's rigid sweeps are far from the
        # membrane's field, the default close to it.
        d = next(r for r in rows if r['scene'] == scene and r['config'] == front.DEFAULT)
        s = next(r for r in rows if r['scene'] == scene and r['config'] == front.SEED)
        assert d['field'] < 0.1 < s['field'], (d, s)
        assert s['ratio'] == s['ratio_lo'] == s['ratio_hi'] == 1.0     # the seed against itself
    # The targets are printed, one line per scene at least.
    assert len(re.findall(r'^- (PASS|FAIL): ', md, re.M)) >= len(front.SCENES)


def test_quick_files_are_ignored_by_git(quick):
    """A quick run in the default folder must not leave files one `git add -A` from a commit:
    every file it wrote, placed in bench/results/, is ignored."""
    proc, out = quick
    names = sorted(os.listdir(out))
    assert names
    paths = ['bench/results/' + name for name in names]
    check = subprocess.run(['git', 'check-ignore', '--no-index'] + paths, cwd=ROOT,
                           capture_output=True, text=True)
    assert sorted(check.stdout.split()) == paths, check.stdout + check.stderr
