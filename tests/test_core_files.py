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


def test_the_solvers_code_is_registered_under_the_settings_names_and_the_settings_import_no_physics():
    """Issue #60.7: cloth/keys.py declares the solvers' names, labels and budgets; the registry
    of their code follows it, in its order, and keys.py imports nothing of the physics."""
    from cloth.keys import SOLVERS, SOLVER_TABLE
    from cloth.solvers import REGISTRY
    assert [r[0] for r in REGISTRY] == SOLVERS == [s[0] for s in SOLVER_TABLE]
    imports = [line for line in (CORE / 'keys.py').read_text().splitlines()
               if line.startswith(('import ', 'from '))]
    assert [line.split(' import')[0] for line in imports] == ['from cloth.fabrics']
