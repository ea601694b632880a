"""The solvers' code, registered under the names cloth/keys.py's SOLVER_TABLE gives them (in its
order): a solver is a module with ORDER (the highest order of cloth/integrate.py's steps it
takes; 0: it has its own integrator), RESIDUAL (whether its solve measures cloth.imbalance),
BARRIER (whether it minimises G with the contact's barrier, else it takes the contact as a
constraint: cloth/obstacles.py),
prepare(cloth) (its work arrays) and a step's three stages, predict(cloth), solve(cloth) and
finish(cloth). Adding one is its module, its row in SOLVER_TABLE and its line here.

The membrane's solvers share the BDF2 integrator (cloth/integrate.py) and minimise the same
step energy (cloth/terms.py) in their own ways; the seed's method has its own Verlet."""

from cloth import integrate
from cloth import jakobsen
from cloth import vbd
from cloth import xpbd

#           name        module    predict             solve           finish
REGISTRY = [['jakobsen', jakobsen, jakobsen.predict, jakobsen.solve, jakobsen.finish],
            ['vbd', vbd, integrate.predict, vbd.solve, integrate.finish],
            ['xpbd', xpbd, integrate.predict, xpbd.solve, integrate.finish]]

# The solvers whose solve measures cloth.imbalance (the legend says how far from balance).
MEASURED = [r[0] for r in REGISTRY if r[1].RESIDUAL]

