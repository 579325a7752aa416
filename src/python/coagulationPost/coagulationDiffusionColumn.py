# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The coagulationFoam column (Sabelfeld-Kolodko, Figs 3-5 setting).

    python3 -m coagulationPost.coagulationDiffusionColumn setup CASE N_PER_CELL [NX]
    python3 -m coagulationPost.coagulationDiffusionColumn compare CASE REF.csv [NX TIMES SIZES HALF]

  setup CASE N_PER_CELL [NX]
                            the 2-D case: [-4R, 4R]^2 (R = 1), NX x NX cells (80), rebound walls,
                            no flow, constant kernel K = 1, n0 = 1 monomers uniform in the
                            square [-R, R]^2 (initialPopulation over the cellZone 'square'),
                            constant-D dispersion with D = 8.88e-2 R^2/T_c (T_c = 1/(K11 n0)),
                            so t is the paper's t'
  compare CASE REF.csv [NX TIMES SIZES HALF]
                            n_l(t', 0) for l = 1..SIZES (10) at t' in TIMES (1,5,10) from the
                            particles in the central cells (centres |x|, |y| < HALF = 0.3: 6 x 6
                            at NX = 80), each with its standard error
                            (sqrt(sum w^2)/V), beside n^E and n^L of the Eulerian reference
                            (applications/studies/eulerianReference's CSV); n^E and n^L are taken at
                            x = 0 and scaled by the diffusion factor's average over the central
                            square (N^D averaged / N^D at 0, the exact Gaussian integral; the
                            last column, f);
                            exit 1 unless every |z| against n^E is below 4 and n^L is off by
                            more than 5 standard errors somewhere at the last time (t' = 10)

The CSV (stdout) is what coagulationPost.coagulationDiffusionFigures figs3to8 reads as its
third column.  Particles: coagulationPost.cloud (the case is written with writeFormat ascii).
"""
import sys

import numpy as np
from scipy.special import erf

from . import cloud

NX, W = 80, 4.0
D = 0.0888
_trapz = getattr(np, "trapezoid", None) or np.trapz


def setup(case, n_per_cell, nx=NX):
    open(case + "/system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (-4 -4 0) (4 -4 0) (4 4 0) (-4 4 0) (-4 -4 0.1) (4 -4 0.1) (4 4 0.1) (-4 4 0.1) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d 1) simpleGrading (1 1 1) );
boundary ( walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
           frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); } );
""" % (nx, nx))
    open(case + "/system/topoSetDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions ( { name square; type cellZoneSet; action new; source boxToCell; sourceInfo { box (-1 -1 -1) (1 1 1); } } );
""")
    open(case + "/0/U", "w").write("""FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 0);
boundaryField { walls { type noSlip; } frontAndBack { type empty; } }
""")
    open(case + "/constant/coagulationProperties", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object coagulationProperties; }
algorithm SWA;
splitting Strang;
kernel { type constant; K0 1; }
inception { rate 0; mass 1; }
statisticalWeight { n %d; V1 1; }
seed 7;
sampling { tRelax 1e6; sampleInterval 0.02; }
initialPopulation { numberDensity 1; mass 1; cellZone square; }
dispersion { type constant; D 0.0888; }
""" % n_per_cell)


def diffusion_factor(t, half=0.3, D=D):
    """Average of N^D over [-half, half]^2 divided by N^D at 0: N^D(x, y) = one(x) one(y),
    one(x) = (erf((1 - x)/s) + erf((1 + x)/s))/2, s = 2 sqrt(D t) (the unit square's
    monomers spread by diffusion alone); trapezoidal rule on 201 points."""
    s = 2 * np.sqrt(D * t)
    x = np.linspace(-half, half, 201)
    one = 0.5 * (erf((1 - x) / s) + erf((1 + x) / s))
    return (_trapz(one, x) / (2 * half)) ** 2 / one[100] ** 2


def central_cells(nx, half, w=W, depth=0.1):
    """The cells of the nx x nx mesh of [-w, w]^2 (blockMesh order: x fastest) whose centres
    have |x|, |y| < half: (mask [nx*nx], their volume, the half-width of the square they
    cover)."""
    H = 2 * w / nx
    i = (np.arange(nx) + 0.5) * H - w
    ix, iy = np.meshgrid(i, i)                  # blockMesh: x fastest
    centre = ((np.abs(ix) < half) & (np.abs(iy) < half)).ravel()
    vol = centre.sum() * H * H * depth
    return centre, vol, np.sqrt(centre.sum()) * H / 2


def size_density(inside, mass, weight, l, vol):
    """Number density of size l (mass rounded to the nearest integer) among the particles
    marked inside, and its standard error: (sum w, sqrt(sum w^2)) / vol."""
    sel = inside & (np.rint(mass) == l)
    return weight[sel].sum() / vol, np.sqrt((weight[sel] ** 2).sum()) / vol


def z_score(n, ref, se):
    """(n - ref)/se, NaN where se is 0."""
    return (n - ref) / se if se > 0 else np.nan


def compare(case, ref, nx=NX, times=("1", "5", "10"), sizes=10, half=0.3):
    r = np.genfromtxt(ref, delimiter=",", names=True)
    centre, vol, half = central_cells(nx, half)  # half: the region the cells cover
    print("t',l,n_coagulationFoam,se,nE,nL,z_E,z_L,f")
    worst = {}
    for t in times:
        cells = cloud.cell_of(case, t)
        m, w = cloud.field(case, t, "mass"), cloud.field(case, t, "weight")
        inside = centre[cells]
        f = diffusion_factor(float(t), half)
        for l in range(1, sizes + 1):
            n, se = size_density(inside, m, w, l, vol)
            row = (r["t"] == float(t)) & (r["l"] == l)
            nE, nL = float(r["nE"][row][0]) * f, float(r["nL"][row][0]) * f
            zE, zL = z_score(n, nE, se), z_score(n, nL, se)
            print("%s,%d,%.6g,%.3g,%.6g,%.6g,%+.2f,%+.2f,%.6g" % (t, l, n, se, nE, nL, zE, zL, f))
            worst.setdefault(t, []).append((zE, zL))
    ok = True
    for t, zs in worst.items():
        zs = np.array(zs)
        print("# t' = %s: |z| against n^E at most %.2f (mean %+.2f), against n^L at most %.2f (mean %+.2f)"
              % (t, np.nanmax(np.abs(zs[:, 0])), np.nanmean(zs[:, 0]), np.nanmax(np.abs(zs[:, 1])), np.nanmean(zs[:, 1])))
        ok &= np.nanmax(np.abs(zs[:, 0])) < 4.0
    # the effective source: at the last time the Lagrangian model must be off by many standard errors
    ok &= np.nanmax(np.abs(np.array(worst[times[-1]])[:, 1])) > 5.0
    return ok


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) in (3, 4) and argv[0] == "setup":
        setup(argv[1], int(argv[2]), *(int(a) for a in argv[3:4]))
        return 0
    if len(argv) in (3, 7) and argv[0] == "compare":
        kw = {}
        if len(argv) == 7:
            kw = dict(nx=int(argv[3]), times=tuple(argv[4].split(",")), sizes=int(argv[5]),
                      half=float(argv[6]))
        return 0 if compare(argv[1], argv[2], **kw) else 1
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
