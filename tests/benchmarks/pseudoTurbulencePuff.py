#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationFoam in a frozen pseudo-turbulent U (issue 17) against the Lagrangian reference.

    pseudoTurbulencePuff.py setup CASE N_PER_CELL SEED   write the mesh, zone, U, dictionaries
    pseudoTurbulencePuff.py compare CASE REF.csv T       clusters and mass in the unions of cells
                                                         with centres in |x| <= r, against REF

A cube [-12, 12]^3 of 48^3 cells (h = 0.5; PUFF_NX in the environment changes the 48); monomers of density 1 in the cells with centres in
|x| <= 4 (sphereToCell); Saffman-Turner kernel with K_11 = 1 (K0 = 1/8); no dispersion; U one
sample of the pseudo-turbulence with epsilon = 1, eta = 2 (4 cells), L = 24, 4 x 8 harmonics,
interpolated to the particles by cellPoint.
"""
import os
import sys

import numpy as np

# The particle files' readers of the issue-16 column (same folder)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from coagulationDiffusionColumn import cell_of, field  # noqa: E402

NX, HALF = int(os.environ.get("PUFF_NX", "48")), 12.0
H = 2 * HALF / NX


def setup(case, n_per_cell, seed):
    open(case + "/system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (-12 -12 -12) (12 -12 -12) (12 12 -12) (-12 12 -12) (-12 -12 12) (12 -12 12) (12 12 12) (-12 12 12) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); } );
""" % (NX, NX, NX))
    open(case + "/system/topoSetDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions ( { name puff; type cellZoneSet; action new; source sphereToCell; sourceInfo { origin (0 0 0); radius 4; } } );
""")
    open(case + "/0/U", "w").write("""FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 0);
boundaryField { walls { type fixedValue; value uniform (0 0 0); } }
""")
    open(case + "/system/pseudoTurbulenceDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object pseudoTurbulenceDict; }
epsilon 1; eta 2; L 24; logIntervals 4; nPerInterval 8; seed %d;
""" % seed)
    open(case + "/constant/coagulationProperties", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object coagulationProperties; }
algorithm SWA;
splitting Strang;
kernel { type saffmanTurner; K0 0.125; }
inception { rate 0; mass 1; }
statisticalWeight { n %d; V1 1; }
seed 7;
sampling { tRelax 1e6; sampleInterval 0.02; }
initialPopulation { numberDensity 1; mass 1; cellZone puff; }
transport { type frozenFlow; interpolationSchemes { U cellPoint; } maxCo 0.3; }
""" % n_per_cell)


def compare(case, ref, time):
    r = np.genfromtxt(ref, delimiter=",", names=True)
    c = (np.arange(NX) + 0.5) * H - HALF
    cx, cy, cz = np.meshgrid(c, c, c, indexing="ij")   # blockMesh: x fastest
    r2 = (cx ** 2 + cy ** 2 + cz ** 2).transpose(2, 1, 0).ravel()
    cells = cell_of(case, time)
    m, w = field(case, time, "mass"), field(case, time, "weight")
    ok = True
    print("r,In_foam,In_foam_se,In_lagrangian,In_lagrangian_se,In_no_transport,z,mass_foam,mass_lagrangian")
    for k, rr in enumerate(np.atleast_1d(r["r"])):
        sel = r2[cells] <= rr * rr
        n, se = w[sel].sum(), np.sqrt((w[sel] ** 2).sum())
        mass = (w[sel] * m[sel]).sum()
        ref_n, ref_se = float(np.atleast_1d(r["In"])[k]), float(np.atleast_1d(r["In_se"])[k])
        z = (n - ref_n) / np.hypot(se, ref_se)
        print("%g,%.5g,%.3g,%.5g,%.3g,%.5g,%+.2f,%.5g,%.5g" % (rr, n, se, ref_n, ref_se,
              float(np.atleast_1d(r["In_v0"])[k]), z, mass, float(np.atleast_1d(r["mass"])[k])))
    return ok


if __name__ == "__main__":
    if sys.argv[1] == "setup":
        setup(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    else:
        sys.exit(0 if compare(sys.argv[2], sys.argv[3], sys.argv[4]) else 1)
