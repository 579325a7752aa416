# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The laminar channels of tests/cases/poiseuille.sh.

  setup CASE FLOW           blockMeshDict, 0/U of FLOW (poiseuille | couette)
  check CASE FLOW SCHEME    cell averages of M0..M3 against the exact answer, SCHEME cell or
                            cellPoint; exit 1 when they are off

A 2-D channel, length L = 0.1, height H = 0.02, 20 x 10 cells, walls top and bottom, a
frozen flow u(y) along x, constant kernel with monomer inception everywhere, nothing
entering, no dispersion. Without dispersion a particle keeps its y, so each streamline is
the homogeneous constant-kernel system at residence time x/u(y): the duct's closed forms
(eqs 39-45) with x -> x/u (analytic.cell_average with speed u).
  poiseuille  u = 1.5 (1 - (2y/H - 1)^2), the cell scheme: every particle of a row moves with
              its cell's value u(y_c), so the exact cell average is the duct profile at speed
              u(y_c), averaged over x in the cell.
  couette     u = 0.5 + y/H (walls moving at 0.5 and 1.5), the cellPoint scheme: the
              velocity interpolated to the particle's place is exact for a linear field
              (volPointInterpolation and the tets' linear interpolant reproduce it), so the
              cell average is also averaged over y in the cell (8 Gauss points).
  (cellPoint on the parabola is not exact: its point values, averages of the neighbouring
  cells, sit 1.5 (h/H)^2 = 1.5 % low at 10 rows, which shows as a bias of about 1.6
  standard errors in M1; a test against x/u(y) there would measure the interpolation, not
  the tracking.)
Intervals: the run's own (correlated time samples, report.compute, windows at least the
largest residence time). Checked over the cells from the fourth column on, M0..M3: at most
15 % outside the nominal 95 % intervals (single-run intervals cover 90-95 % on the ducts),
none beyond 5 of their standard errors.
"""

import sys

import numpy as np

from coagulationPost import analytic, report

L, H, NX, NY = 0.1, 0.02, 20, 10
DZ = H / NY
I, K0 = 3e8, 1e-5


FLOWS = {
    "poiseuille": lambda y: 1.5 * (1.0 - (2.0 * y / H - 1.0) ** 2),
    "couette": lambda y: 0.5 + y / H,
}


def setup(case, flow):
    u_of = FLOWS[flow]
    open(case + "/system/blockMeshDict", "w").write("""FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (%(L)g 0 0) (%(L)g %(H)g 0) (0 %(H)g 0)
           (0 0 %(D)g) (%(L)g 0 %(D)g) (%(L)g %(H)g %(D)g) (0 %(H)g %(D)g) );
blocks ( hex (0 1 2 3 4 5 6 7) (%(NX)d %(NY)d 1) simpleGrading (1 1 1) );
boundary
(
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall;  faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
""" % dict(L=L, H=H, D=DZ, NX=NX, NY=NY))
    yc = (np.arange(NY) + 0.5) * H / NY
    cells = np.tile(u_of(yc)[:, None], (1, NX)).ravel()   # x fastest
    # the walls patch: the bottom's faces, then the top's, each along x
    wall_u = np.concatenate([np.full(NX, u_of(0.0)), np.full(NX, u_of(H))])
    vec = lambda us: " ".join("(%.17g 0 0)" % v for v in us)
    open(case + "/0/U", "w").write("""FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField nonuniform List<vector> %d (%s);
boundaryField
{
    inlet  { type fixedValue; value nonuniform List<vector> %d (%s); }
    outlet { type zeroGradient; }
    walls  { type fixedValue; value nonuniform List<vector> %d (%s); }
    frontAndBack { type empty; }
}
""" % (len(cells), vec(cells), NY, vec(u_of(yc)), len(wall_u), vec(wall_u)))


def check(case, flow, scheme):
    u_of = FLOWS[flow]
    res = report.compute([case], analytic_kind="none",
                         correlation_time=L / min(u_of(0.5 * H / NY), u_of(H - 0.5 * H / NY)))
    c = res["centres"]
    hx, hy = L / NX, H / NY
    keep = c[:, 0] > 3 * hx
    exact = np.full(res["mean"].shape, np.nan)
    g, w = np.polynomial.legendre.leggauss(8)
    for i in np.nonzero(keep)[0]:
        lo, hi = c[i, 0] - 0.5 * hx, c[i, 0] + 0.5 * hx
        if scheme == "cell":
            exact[i] = analytic.cell_average("constantDuct", [lo], [hi], I, K0, u_of(c[i, 1]))[:, 0]
        else:
            ys = c[i, 1] + 0.5 * hy * g
            vals = [analytic.cell_average("constantDuct", [lo], [hi], I, K0, u_of(y))[:, 0] for y in ys]
            exact[i] = 0.5 * np.einsum("n,nk->k", w, np.array(vals))
    mean, ci = res["mean"][keep, :4], res["ci"][keep, :4]
    z = (mean - exact[keep]) / (ci / 1.96)
    outside = np.mean(np.abs(z) > 1.96)
    zmax = np.nanmax(np.abs(z))
    rel = np.abs(mean / exact[keep] - 1)
    print("%s, %s velocity: %d cells x 4 moments, %.1f %% outside the 95 %% intervals, largest |z| %.2f,"
          " mean z per moment %s, median |rel. error| %.2g %%"
          % (flow, scheme, keep.sum(), 100 * outside, zmax, np.round(np.mean(z, axis=0), 2),
             100 * np.median(rel)))
    return outside <= 0.15 and zmax < 5.0


if __name__ == "__main__":
    if sys.argv[1] == "setup":
        setup(sys.argv[2], sys.argv[3])
    else:
        sys.exit(0 if check(sys.argv[2], sys.argv[3], sys.argv[4]) else 1)
