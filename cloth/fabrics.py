"""The fabrics a scene may be made of: each one's stretch stiffness, shear stiffness, density and
strength.

A fabric is a membrane (cloth/topology.py): structural edges of stiffness `stretch` (N/m) and
both diagonals of every cell of stiffness `shear` (N/m), each pulling only when longer than at
rest, and a mass of `density` (kg/m^2) spread over the vertices by the area each stands for.
The three numbers are the fabric's and not the grid's: a spring of stiffness k between two
vertices one spacing h apart stands for a strip of cloth h wide, whose tension per width
k * strain is then independent of h; a square lattice with both diagonals of stiffness kd has
the in-plane shear modulus G = kd. So the same fabric is the same cloth at every grid size.

The numbers are orders of magnitude from measured fabrics at small strain: the Kawabata
KES-FB1 tensile and shear tests (1 gf/(cm deg) of shear is 56 N/m per radian) as tabulated for
woven and knitted apparel fabrics, and the in-plane stiffnesses fitted by Clyde, Teran and
Tamstorf ("Modeling and data-driven parameter estimation for woven fabrics", SCA 2017) and by
Wang, O'Brien and Ramamoorthi ("Data-driven elastic models for cloth", SIGGRAPH 2011). Woven
fabrics: stretch 1e3-1e4 N/m, shear 20-170 N/m (a shear/stretch ratio of 0.005-0.05); knits,
whose loops straighten before their yarn stretches: stretch 1e2-1e3 N/m, shear/stretch
0.03-0.2; apparel weights 0.1-0.4 kg/m^2.
"""

# [name, label, stretch N/m, shear N/m, density kg/m^2, strength N/m, what it is]
# Strength: the tension at which a line of yarns breaks (cloth/tear.py), from strip tests
# (ISO 13934-1, ASTM D5035: the force per 50 mm of width at break; x 20 is N/m). Retailers'
# minimums for woven apparel are 2.4-4.4 kN/m by weight (18 daN a 50 mm strip for a 120-200
# g/m^2 shirting), denim's grab minimums reach 12-31 kN/m, a 190T polyester taffeta's yarns
# carry about 7-11 kN/m; knits are tested by bursting, not strips (their numbers here are
# orders of magnitude). No hand tears these: 20 N spread over 2 cm is at most 1 kN/m. The
# tissue tears in a hand: a 2-ply facial tissue (32-50 g/m^2) breaks at 48-80 N/m across its
# machine direction and 110-180 N/m along it, at 13-18% strain (US patent 11280050 B2's
# tables), a secant stiffness of about 1 kN/m; paper is near isotropic in shear
# (G = E / 2(1 + nu), nu ~ 0.3).
FABRICS = [
    ['cotton', 'Cotton (woven shirting)', 5000.0, 150.0, 0.15, 4000.0,
     'a plain-woven cotton shirting: stiff along its yarns, a little give on the bias'],
    ['denim', 'Denim (heavy twill)', 10000.0, 170.0, 0.4, 15000.0,
     'a 12 oz cotton twill: the stiffest, heaviest and strongest here'],
    ['polyester', 'Polyester (light woven)', 2000.0, 20.0, 0.1, 5000.0,
     'a light plain-woven polyester lining: stiff in stretch, soft in shear'],
    ['jersey', 'Jersey (cotton knit)', 500.0, 50.0, 0.2, 2000.0,
     'a single-knit cotton jersey, as in a T-shirt'],
    ['spandex', 'Spandex (stretch knit)', 150.0, 30.0, 0.2, 1500.0,
     'a cotton-elastane knit: stretches under its own weight'],
    ['tissue', 'Tissue (2-ply paper)', 1000.0, 380.0, 0.035, 60.0,
     'a 2-ply facial tissue: light, stiff for its weight, and torn by a hand'],
]
# Every fabric's edges are hemmed: folded over twice and sewn, HEM_LAYERS more layers of the
# fabric over HEM_WIDTH along the border (a 1 cm double-fold hem). The hem is a line of finite
# stiffness (HEM_LAYERS * HEM_WIDTH * stretch, N) and mass. Without it a free edge that the
# load curves (the top edge of Two corners, sagging between its clamps) is a cable of no
# width in the membrane limit: the exact statics' top-row strain grew 35% a doubling of the
# grid (cotton, 30 -> 60) and the field across grids differed 38-40%; hemmed, the top row's
# mean strain is the same at 30 and 60 and the woven fields differ 18-22% (2 cm clamps).
HEM_LAYERS = 2.0
HEM_WIDTH = 0.01
# A fabric's strength (FABRICS, N/m) is the tension at which a line of its yarns breaks,
# averaged over this length across them (m; cloth/tear.py): the coarsest grid a preset is
# drawn at resolves it (Tearable, 2 m wide, at 10 columns: 0.22 m cells), so a tear starts at
# the same pull on every grid (python -m bench --tear).
TEAR_LENGTH = 0.2
# The presets' fabric: its stretch under its own weight shows in the colours (a 1.5 m drop
# strains jersey's top edge by density g height / stretch, 0.6%).
DEFAULT_FABRIC = 'jersey'


def fabric(name):
    """The FABRICS row of `name` (None when there is none)."""
    for i in range(len(FABRICS)):
        if FABRICS[i][0] == name:
            return FABRICS[i]
    return None


def fabric_of(stretch, shear, density):
    """The name of the fabric with exactly these numbers, or '' for none."""
    for i in range(len(FABRICS)):
        f = FABRICS[i]
        if f[2] == stretch and f[3] == shear and f[4] == density:
            return f[0]
    return ''
