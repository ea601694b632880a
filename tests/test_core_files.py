"""Issue #40: one file per concept in the core, none over MOST_LINES lines. A file past it holds
more than one concept: cloth/vbd.py, at 629 lines, held the sweeps and the coarse-grid
correction, which is now cloth/coarse.py."""
from pathlib import Path

CORE = Path(__file__).resolve().parent.parent / 'cloth'
MOST_LINES = 600


def test_no_core_file_is_over_600_lines():
    sizes = {p.name: len(p.read_text().splitlines()) for p in sorted(CORE.glob('*.py'))}
    assert len(sizes) > 20
    assert {name: n for name, n in sizes.items() if n > MOST_LINES} == {}
