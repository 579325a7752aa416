# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationFoam in a frozen pseudo-turbulent U against the Lagrangian reference.

    python3 -m coagulationPost.pseudoTurbulencePuff setup CASE N_PER_CELL SEED
                                  write the mesh, zone, U, dictionaries
    python3 -m coagulationPost.pseudoTurbulencePuff compare CASE REF.csv T
                                  clusters and mass in the unions of cells with centres in
                                  |x| <= r, against REF (build/tests/benchmarks/
                                  pseudoTurbulencePuff's CSV), as CSV on stdout

A cube [-12, 12]^3 of 48^3 cells (h = 0.5; PUFF_NX in the environment changes the 48); monomers of density 1 in the cells with centres in
|x| <= 4 (sphereToCell); Saffman-Turner kernel with K_11 = 1 (K0 = 1/8); no dispersion; U one
sample of the pseudo-turbulence with epsilon = 1, eta = 2 (4 cells), L = 24, 4 x 8 harmonics,
interpolated to the particles by cellPoint.  Particles: coagulationPost.cloud (the case is
written with writeFormat ascii).
"""
import os
import sys

import numpy as np

from . import cloud

HALF = 12.0


def cells_per_side():
    """PUFF_NX from the environment, else 48."""
    return int(os.environ.get("PUFF_NX", "48"))


def setup(case, n_per_cell, seed, nx=None):
    nx = cells_per_side() if nx is None else nx
    open(case + "/system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (-12 -12 -12) (12 -12 -12) (12 12 -12) (-12 12 -12) (-12 -12 12) (12 -12 12) (12 12 12) (-12 12 12) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); } );
""" % (nx, nx, nx))
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


def centre_radius2(nx, half=HALF):
    """|x|^2 of the cell centres of the nx^3 block [-half, half]^3, in blockMesh's cell
    order (x fastest, then y, then z)."""
    h = 2 * half / nx
    c = (np.arange(nx) + 0.5) * h - half
    cx, cy, cz = np.meshgrid(c, c, c, indexing="ij")
    return (cx ** 2 + cy ** 2 + cz ** 2).transpose(2, 1, 0).ravel()


def ball_sums(r2, cells, mass, weight, r):
    """Clusters (sum w), their standard error sqrt(sum w^2) and mass (sum w m) of the
    particles in the cells whose centres have |x| <= r."""
    sel = r2[cells] <= r * r
    return weight[sel].sum(), np.sqrt((weight[sel] ** 2).sum()), (weight[sel] * mass[sel]).sum()


def z_score(n, se, ref, ref_se):
    """(n - ref) over the two standard errors combined."""
    return (n - ref) / np.hypot(se, ref_se)


def compare(case, ref, time, nx=None):
    nx = cells_per_side() if nx is None else nx
    r = np.genfromtxt(ref, delimiter=",", names=True)
    r2 = centre_radius2(nx)
    cells = cloud.cell_of(case, time)
    m, w = cloud.field(case, time, "mass"), cloud.field(case, time, "weight")
    print("r,In_foam,In_foam_se,In_lagrangian,In_lagrangian_se,In_no_transport,z,mass_foam,mass_lagrangian")
    for k, rr in enumerate(np.atleast_1d(r["r"])):
        n, se, mass = ball_sums(r2, cells, m, w, rr)
        ref_n, ref_se = float(np.atleast_1d(r["In"])[k]), float(np.atleast_1d(r["In_se"])[k])
        z = z_score(n, se, ref_n, ref_se)
        print("%g,%.5g,%.3g,%.5g,%.3g,%.5g,%+.2f,%.5g,%.5g" % (rr, n, se, ref_n, ref_se,
              float(np.atleast_1d(r["In_v0"])[k]), z, mass, float(np.atleast_1d(r["mass"])[k])))
    return True


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) == 4 and argv[0] == "setup":
        setup(argv[1], int(argv[2]), int(argv[3]))
        return 0
    if len(argv) == 4 and argv[0] == "compare":
        return 0 if compare(argv[1], argv[2], argv[3]) else 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
