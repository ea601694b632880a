"""The solvers, registered: a solver is a module with NAME, LABEL, BUDGET (its own substeps,
iterations and corrections), ORDER (the highest order of cloth/integrate.py's steps it takes;
0: it has its own integrator), RESIDUAL (whether its solve measures cloth.imbalance),
prepare(cloth) (its work arrays) and a step's three stages, predict(cloth), solve(cloth) and
finish(cloth). Adding one is its module and one line here.

The membrane's solvers share the BDF2 integrator (cloth/integrate.py) and differ in how they
minimise a step's energy; the seed's method has its own Verlet."""

from cloth import integrate
from cloth import jakobsen
from cloth import vbd
from cloth import xpbd

#           module    predict             solve           finish
REGISTRY = [[jakobsen, jakobsen.predict, jakobsen.solve, jakobsen.finish],
            [vbd, integrate.predict, vbd.solve, integrate.finish],
            [xpbd, integrate.predict, xpbd.solve, integrate.finish]]

SOLVERS = [r[0].NAME for r in REGISTRY]
SOLVER_LABELS = [r[0].LABEL for r in REGISTRY]
SOLVER_BUDGETS = [r[0].BUDGET for r in REGISTRY]
# The solvers whose solve measures cloth.imbalance (the legend says how far from balance).
MEASURED = [r[0].NAME for r in REGISTRY if r[0].RESIDUAL]
DEFAULT_SOLVER = vbd.NAME
SEED_SOLVER = jakobsen.NAME
