# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Cases and checks of the random-walk tests (tests/cases/dispersion.sh).

  setup CASE KIND       write blockMeshDict, 0/U (and 0/nut) and coagulationProperties of
                        KIND (puff | slab | wellMixed) into a copy of a tutorial
  check CASE KIND       compare the run with the exact answer; exit 1 when it is off

puff       2-D box [0,1]^2 (20 x 20 cells), rebound walls, constant D = 2e-3, a puff of
           40 000 particles released uniformly in [0.2,0.3] x [0.6,0.7]; each cell's count
           at t = 5 and 10 against the image-sum Gaussian (reflecting walls), binomial
           intervals: chi-square over the cells and the largest |z|.
puffBrownian  the same puff walked by the Brownian model (Stokes-Einstein with slip), of
           particles of mass 8, the gas chosen so that D(1) = 2e-3, hence D(8) = 1e-3.
slab       1-D slab [0,1] (25 cells), both walls stick, D = 1, uniform start (40 000
           particles), sqrt(2 D dt) = h/2; the fraction remaining at D t/L^2 = 0.025 ...
           0.2 against the Fourier series, binomial intervals; deposited + remaining =
           initial exactly (the balance closes, checked by the shell script).
wellMixed  1-D box [0,1] (50 cells), rebound walls, D = nut/Sct with nut = 1e-4 100^x
           (100x across the box), uniform start (25 000 particles, from numberDensityField):
           the counts per cell at
           t = 10 and 20 stay uniform (chi-square, largest |z|).
"""

import re
import sys

import numpy as np
from scipy import stats

from coagulationPost import diffusion

HEADER = """FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}
"""


def block_mesh(nx, ny, lx, ly, patches):
    """A box [0,lx] x [0,ly] x [0,lz], nx x ny x 1 cells; patches: name -> (type, faces)."""
    lz = min(lx / nx, ly / ny)
    faces = {"left": "(0 4 7 3)", "right": "(1 2 6 5)", "bottom": "(0 1 5 4)",
             "top": "(3 7 6 2)", "frontAndBack": "(0 3 2 1) (4 5 6 7)"}
    body = "\n".join("    %s { type %s; faces (%s); }" % (name, typ, " ".join(faces[f] for f in fs))
                     for name, (typ, fs) in patches.items())
    return HEADER.format(cls="dictionary", obj="blockMeshDict") + """
vertices ( (0 0 0) ({lx} 0 0) ({lx} {ly} 0) (0 {ly} 0)
           (0 0 {lz}) ({lx} 0 {lz}) ({lx} {ly} {lz}) (0 {ly} {lz}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
boundary
(
{body}
);
""".format(lx=lx, ly=ly, lz=lz, nx=nx, ny=ny, body=body)


def zero_velocity(patches):
    bf = "\n".join("    %s { type %s; }" % (name, "empty" if typ == "empty" else "noSlip")
                   for name, (typ, _) in patches.items())
    return HEADER.format(cls="volVectorField", obj="U") + """
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
%s
}
""" % bf


def properties(extra, n_per_cell, zone=None):
    """SWA, no coagulation to speak of (K0 = 1e-30), no inception; W = Vref/n (V1 = 1)."""
    return HEADER.format(cls="dictionary", obj="coagulationProperties") + """
algorithm SWA;
splitting Lie;
kernel {{ type constant; K0 1e-30; }}
inception {{ rate 0; mass 1; }}
statisticalWeight {{ n {n}; V1 1; }}
seed 3;
sampling {{ tRelax 1e6; sampleInterval SAMPLE; }}
initialPopulation {{ numberDensity 1; mass 1; {zone} }}
{extra}
""".format(n=n_per_cell, zone=("cellZone %s;" % zone) if zone else "", extra=extra)


KINDS = {
    "puff": dict(nx=20, ny=20, lx=1.0, ly=1.0, n=10000, zone="puff",
                 patches={"walls": ("wall", ["left", "right", "bottom", "top"]),
                          "frontAndBack": ("empty", ["frontAndBack"])},
                 dispersion="dispersion { type constant; D 2e-3; }",
                 deltaT=0.5, endTime=10, writeInterval=5),
    # The same puff walked by the Brownian model with particles of mass 8, its gas set so that
    # D(m = 1) = 2e-3: a sphere of mass m and density 6/pi has d = m^(1/3), a mean free path
    # of 1e-30 makes Cc = 1, mu = k T/(3 pi 2e-3); so D(8) = 1e-3 (Stokes-Einstein, D ~ 1/d)
    "puffBrownian": dict(nx=20, ny=20, lx=1.0, ly=1.0, n=10000, zone="puff",
                 patches={"walls": ("wall", ["left", "right", "bottom", "top"]),
                          "frontAndBack": ("empty", ["frontAndBack"])},
                 dispersion="dispersion { type Brownian; T 300; mu %.17g; lambda 1e-30; }\n"
                            "particles { density %.17g; }"
                            % (1.380649e-23 * 300 / (3 * np.pi * 2e-3), 6 / np.pi),
                 deltaT=0.5, endTime=10, writeInterval=5, mass=8, D=1e-3),
    "slab": dict(nx=25, ny=1, lx=1.0, ly=0.04, n=1600,
                 patches={"walls": ("wall", ["left", "right"]),
                          "sides": ("empty", ["bottom", "top", "frontAndBack"])},
                 dispersion="dispersion { type constant; D 1; }\n"
                            "patchInteraction { patches { walls stick; } }",
                 deltaT=2e-4, endTime=0.2, writeInterval=0.025),
    "wellMixed": dict(nx=50, ny=1, lx=1.0, ly=0.02, n=500,
                      patches={"walls": ("wall", ["left", "right"]),
                               "sides": ("empty", ["bottom", "top", "frontAndBack"])},
                      dispersion="dispersion { type turbulent; Sct 1; }",
                      deltaT=0.04, endTime=20, writeInterval=10),
}


def setup(case, kind):
    k = KINDS[kind]
    open(case + "/system/blockMeshDict", "w").write(
        block_mesh(k["nx"], k["ny"], k["lx"], k["ly"], k["patches"]))
    open(case + "/0/U", "w").write(zero_velocity(k["patches"]))
    text = properties(k["dispersion"], k["n"], k.get("zone"))
    text = text.replace("mass 1; ", "mass %g; " % k.get("mass", 1))
    text = text.replace("SAMPLE", repr(k["deltaT"]))
    open(case + "/constant/coagulationProperties", "w").write(text)
    if kind == "wellMixed":
        # the initial population from a field (numberDensityField): 1 everywhere
        text = open(case + "/constant/coagulationProperties").read()
        open(case + "/constant/coagulationProperties", "w").write(
            text.replace("numberDensity 1;", "numberDensityField n0;"))
        open(case + "/0/n0", "w").write(
            HEADER.format(cls="volScalarField", obj="n0")
            + "dimensions [0 -3 0 0 0 0 0];\ninternalField nonuniform List<scalar> %d (%s);\n"
              "boundaryField\n{\n    walls { type zeroGradient; }\n    sides { type empty; }\n}\n"
            % (k["nx"], " ".join(["1"] * k["nx"])))
        h = k["lx"] / k["nx"]
        x = (np.arange(k["nx"]) + 0.5) * h
        nut = 1e-4 * 100.0 ** x
        bf = "    walls { type zeroGradient; }\n    sides { type empty; }"
        open(case + "/0/nut", "w").write(
            HEADER.format(cls="volScalarField", obj="nut")
            + "dimensions [0 2 -1 0 0 0 0];\ninternalField nonuniform List<scalar> %d (%s);\n"
              "boundaryField\n{\n%s\n}\n" % (len(nut), " ".join(repr(v) for v in nut), bf))
    if kind.startswith("puff"):
        open(case + "/system/topoSetDict", "w").write(
            HEADER.format(cls="dictionary", obj="topoSetDict")
            + "actions ( { name puff; type cellZoneSet; action new; source boxToCell;"
              " sourceInfo { box (0.2 0.6 -1) (0.3 0.7 1); } } );\n")
    return k


def read_field(case, time, name):
    text = open("%s/%s/%s" % (case, time, name)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", text)
    if m:
        return np.array(m.group(2).split(), dtype=float)
    m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
    return None if m is None else float(m.group(1))


def cell_counts(case, time, k):
    """Computational particles per cell: M0 V / w, w = 1/(n ... ) of the initial population."""
    ncell = k["nx"] * k["ny"]
    m0 = read_field(case, time, "M0")
    m0 = np.full(ncell, m0) if np.isscalar(m0) else m0
    # numberDensity 1: a populated cell holds N = V physical particles as n computational
    # ones of weight V/n, so count = M0 V/(V/n) = M0 n
    return m0 * k["n"]


def verdict(name, z, chi2, dof):
    p = stats.chi2.sf(chi2, dof)
    zmax = np.max(np.abs(z))
    # 4.5 sigma for the largest of up to 400 cells: a 0.3 % false alarm rate
    ok = p > 1e-3 and zmax < 4.5
    print("%s: chi2 %.1f on %d dof (p = %.3g), largest |z| %.2f -> %s"
          % (name, chi2, dof, p, zmax, "ok" if ok else "OFF"))
    return ok


def check(case, kind):
    k = KINDS[kind]
    ok = True
    if kind.startswith("puff"):
        D, n_total = k.get("D", 2e-3), 4 * k["n"]
        h = k["lx"] / k["nx"]
        edges = np.arange(k["nx"] + 1) * h
        for t in ("5", "10"):
            s = np.sqrt(2 * D * float(t))
            px = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.2, 0.3, 1.0, s)
            py = diffusion.reflected_cell_probability(edges[:-1], edges[1:], 0.6, 0.7, 1.0, s)
            p = np.outer(py, px).ravel()  # blockMesh numbers cells x fastest
            counts = cell_counts(case, t, k)
            assert abs(counts.sum() - n_total) < 1e-6 * n_total, counts.sum()
            e = n_total * p
            z = (counts - e) / np.sqrt(e * (1 - p))
            mask = e > 5
            chi2 = np.sum(z[mask] ** 2)
            ok &= verdict("%s t = %s (%d cells)" % (kind, t, mask.sum()), z[mask], chi2, mask.sum() - 1)
    elif kind == "slab":
        n0 = k["nx"] * k["n"]
        times = ["0.025", "0.05", "0.075", "0.1", "0.125", "0.15", "0.175", "0.2"]
        for t in times:
            remaining = cell_counts(case, t, k).sum()
            f = diffusion.absorbed_remaining_fourier(float(t))
            sd = np.sqrt(n0 * f * (1 - f))
            z = (remaining - n0 * f) / sd
            good = abs(z) < 3.5
            ok &= good
            print("slab D t/L^2 = %s: remaining %.5f, Fourier series %.5f, z = %+.2f -> %s"
                  % (t, remaining / n0, f, z, "ok" if good else "OFF"))
    elif kind == "wellMixed":
        ncell = k["nx"]
        n_total = ncell * k["n"]
        for t in ("10", "20"):
            counts = cell_counts(case, t, k)
            p = 1.0 / ncell
            e = n_total * p
            z = (counts - e) / np.sqrt(e * (1 - p))
            ok &= verdict("well-mixed t = %s" % t, z, np.sum(z ** 2), ncell - 1)
            lo, hi = counts[: ncell // 5].sum() / (e * ncell // 5), counts[-ncell // 5:].sum() / (e * ncell // 5)
            print("    low-D fifth %.4f, high-D fifth %.4f of uniform" % (lo, hi))
    return ok


if __name__ == "__main__":
    cmd, case, kind = sys.argv[1:4]
    if cmd == "setup":
        k = setup(case, kind)
        print("%g %g %g" % (k["deltaT"], k["endTime"], k["writeInterval"]))
    else:
        sys.exit(0 if check(case, kind) else 1)
