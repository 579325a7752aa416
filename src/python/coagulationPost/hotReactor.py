# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The hot reactor's plots (tutorials/hotReactor): coagulationFoam's time-averaged size distributions at the axis
probes (sizeDistribution 'psdAxis', postProcessing/psdAxis/<last write>/) against the
plug-flow solution of plugFlowReference (results/plugFlow.csv, plugFlowSizes.csv).

  python3 -m coagulationPost.hotReactor --case . --out results [--no-plots]
                                       [--growth-case growth]
  python3 -m coagulationPost.hotReactor --case growth --surface-rate A Ea

With --growth-case, the same function of a second run of the case with growth (the tutorial's
growth/, surface growth at the local temperature) goes beside it: OUT/psdGrowth.png (the size
distributions at three probes with and without growth) and OUT/axialGrowth.csv (d10 and M0 of
both runs at every probe). --surface-rate writes the field kSurface = A exp(-Ea/(R T)) of the
case's start time from its T (an Arrhenius surface growth rate [kg/(m2 s)], Ea in J/mol) and
exits.

Writes OUT/axial.csv (each probe: x, the residence time and T of the plug flow, coagulationFoam's
M0 and count mean diameter d10 with their 95 % intervals, the plug flow's), OUT/psd.png
(dN/dlog10 d [m^-3] against d [nm] at the probes: coagulationFoam with its 95 % intervals,
the plug flow binned in the same mass bins) and OUT/meanDiameter.png (d10 along the axis, with
the axis's temperature). Prints one line a probe. Diameters of spheres of the particles'
density: d = (6 m massUnit/(pi rho))^(1/3), masses in the case's massUnit, both from the
sample file's attributes (the case's 'particles' entry).
"""

import argparse
import csv
import math
import os
import re
import sys

import numpy as np

from . import maps
from . import psd as psdlib


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def bin_sizes(masses, numbers, upper):
    """The numbers of particles of the given masses in the bins of upper edges `upper`: bin
    b > 0 holds [upper[b-1], upper[b]), bin 0 everything below upper[0]; masses at or above
    the last edge are dropped."""
    out = np.zeros(len(upper))
    idx = np.searchsorted(upper, np.asarray(masses, float), side="right")
    ok = idx < len(upper)
    np.add.at(out, idx[ok], np.asarray(numbers, float)[ok])
    return out


GAS_CONSTANT = 8.314462618


def internal_field(text):
    """The internal field of a volScalarField file's text: a list (nonuniform) or a float."""
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", text)
    if m:
        return np.array(m.group(2).split(), dtype=float)
    m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
    if m is None:
        raise psdlib.InputError("no internalField in the field file")
    return float(m.group(1))


def surface_rate_field(case, time, A, Ea, name="kSurface"):
    """Write <case>/<time>/<name>: k_s = A exp(-Ea/(R T)) [kg/(m2 s)] of each cell from the
    case's T at that time; zeroGradient on every patch but the empty ones. Returns k_s."""
    with open(os.path.join(case, time, "T")) as f:
        T = internal_field(f.read())
    k = A * np.exp(-Ea / (GAS_CONSTANT * np.asarray(T, float)))
    values = ("nonuniform List<scalar> %d\n(\n%s\n)" % (k.size, "\n".join("%.17g" % v for v in k))
              if k.ndim else "uniform %.17g" % k)
    patches = "\n".join("    %s { type %s; }" % (p, "empty" if t == "empty" else "zeroGradient")
                         for p, t, _, _ in maps.patches(case))
    with open(os.path.join(case, time, name), "w") as f:
        f.write("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class volScalarField;\n"
                "    object %s;\n}\n\ndimensions [1 -2 -1 0 0 0 0];\n\ninternalField %s;\n\n"
                "boundaryField\n{\n%s\n}\n" % (name, values, patches))
    return k


def foam_psd(case, name):
    """A run's averaged size distribution at the probes: x of the probes, the bins' lower
    and upper masses, the mean and 95 % interval per probe and bin, the derived rows by
    (probe, quantity), and the sample file's attributes."""
    samples = psdlib.read(case, name)
    rows, derived = psdlib.read_csv(case, name)
    xs = np.asarray(samples["centres"])[:, 0]  # the probes on the axis
    nb = int(samples["nBins"])  # the rows of bins -1 and nb: under- and overflow
    lower, upper = np.zeros(nb), np.zeros(nb)
    mean, ci = np.zeros((len(xs), nb)), np.zeros((len(xs), nb))
    for r in rows:
        i, b = int(r["region"]), int(r["bin"])
        if 0 <= b < nb:
            lower[b], upper[b] = r["lower"], r["upper"]
            mean[i, b], ci[i, b] = r["mean"], r["ci95"]
    der = {(int(r["region"]), r["quantity"]): r for r in derived}
    return xs, lower, upper, mean, ci, der, samples["attrs"]


def main(argv=None):
    try:
        return plots(argv)
    except (psdlib.InputError, OSError) as e:
        print("coagulationPost.hotReactor: %s\n%s" % (e, __doc__), file=sys.stderr)
        return 2


def plots(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=".")
    ap.add_argument("--out", default="results")
    ap.add_argument("--name", default="psdAxis")
    ap.add_argument("--no-plots", action="store_true")
    ap.add_argument("--growth-case", default=None)
    ap.add_argument("--surface-rate", nargs=2, type=float, metavar=("A", "Ea"), default=None)
    a = ap.parse_args(argv)
    if a.surface_rate is not None:
        k = surface_rate_field(a.case, "0", *a.surface_rate)
        print("kSurface = %g exp(-%g/(R T)): %.4g to %.4g kg/(m2 s)"
              % (a.surface_rate[0], a.surface_rate[1], np.min(k), np.max(k)))
        return 0
    os.makedirs(a.out, exist_ok=True)

    xs, lower, upper, mean, ci, der, attrs = foam_psd(a.case, a.name)
    nreg, nb = mean.shape
    rho = float(attrs["density"])
    unit = float(attrs["massUnit"])
    if not rho > 0:
        raise psdlib.InputError("the size distribution '%s' of %s has no particle density: "
                                "give the case a 'particles' entry" % (a.name, a.case))

    def diam_nm(m):
        return 1e9 * (6.0 * np.asarray(m, float) * unit / (math.pi * rho)) ** (1.0 / 3.0)

    # the plug flow: along the axis, and its sizes at the probes
    plug = read_rows(os.path.join(a.out, "plugFlow.csv"))
    px = np.array([float(r["x"]) for r in plug])
    pT = np.array([float(r["T"]) for r in plug])
    pt = np.array([float(r["t"]) for r in plug])
    pd10 = np.array([float(r["d10_nm"]) for r in plug])
    pM0 = np.array([float(r["M0"]) for r in plug])
    sizes = read_rows(os.path.join(a.out, "plugFlowSizes.csv"))
    sx = np.array([float(r["x"]) for r in sizes])
    sm = np.array([float(r["mass"]) for r in sizes])
    sn = np.array([float(r["n"]) for r in sizes])

    # dN/dlog10 d of a bin: its number density over the width of log10 d (d ~ m^(1/3))
    dlog = np.log10(upper / lower) / 3.0
    centre_nm = diam_nm(np.sqrt(lower * upper))
    plug_binned = np.zeros((nreg, nb))
    for i, x in enumerate(xs):
        sel = np.isclose(sx, x, atol=1e-9)
        plug_binned[i] = bin_sizes(sm[sel], sn[sel], upper)

    out_rows = []
    for i, x in enumerate(xs):
        d10 = der[(i, "d10")]
        m0 = der[(i, "M0")]
        row = {
            "x": x,
            "t_plug": float(np.interp(x, px, pt)),
            "T_axis": float(np.interp(x, px, pT)),
            "M0_foam": m0["mean"], "M0_foam_ci95": m0["ci95"],
            "M0_plug": float(np.interp(x, px, pM0)),
            "d10_nm_foam": 1e9 * d10["mean"], "d10_nm_foam_ci95": 1e9 * d10["ci95"],
            "d10_nm_plug": float(np.interp(x, px, pd10)),
        }
        out_rows.append(row)
        print("x = %.3f m (t = %.4f s, T = %.0f K): d10 coagulationFoam %.3f +- %.3f nm, plug flow "
              "%.3f nm; M0 %.3e +- %.1e, plug flow %.3e m^-3"
              % (x, row["t_plug"], row["T_axis"], row["d10_nm_foam"], row["d10_nm_foam_ci95"],
                 row["d10_nm_plug"], row["M0_foam"], row["M0_foam_ci95"], row["M0_plug"]))
    with open(os.path.join(a.out, "axial.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out_rows[0]))
        w.writeheader()
        w.writerows(out_rows)
    growth = None
    if a.growth_case is not None:
        growth = foam_psd(a.growth_case, a.name)
        if len(growth[0]) != nreg or not np.allclose(growth[1], lower):
            raise psdlib.InputError("the growth case's '%s' has other probes or bins" % a.name)
        gder = growth[5]
        grows = []
        for i, x in enumerate(xs):
            grows.append({
                "x": x,
                "d10_nm": 1e9 * der[(i, "d10")]["mean"],
                "d10_nm_ci95": 1e9 * der[(i, "d10")]["ci95"],
                "d10_nm_growth": 1e9 * gder[(i, "d10")]["mean"],
                "d10_nm_growth_ci95": 1e9 * gder[(i, "d10")]["ci95"],
                "M0": der[(i, "M0")]["mean"], "M0_growth": gder[(i, "M0")]["mean"],
            })
            print("x = %.3f m: d10 without growth %.3f +- %.3f nm, with growth %.3f +- %.3f nm"
                  % (x, grows[-1]["d10_nm"], grows[-1]["d10_nm_ci95"],
                     grows[-1]["d10_nm_growth"], grows[-1]["d10_nm_growth_ci95"]))
        with open(os.path.join(a.out, "axialGrowth.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(grows[0]))
            w.writeheader()
            w.writerows(grows)
    if a.no_plots:
        return 0

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.5, 5))
    colours = plt.cm.viridis(np.linspace(0, 0.9, nreg))
    # bins that hold no integer mass (the smallest) are left out: they are empty in both
    holds = np.ceil(lower) < upper
    for i, x in enumerate(xs):
        y = mean[i] / dlog
        e = ci[i] / dlog
        ax.errorbar(centre_nm[holds], y[holds], yerr=e[holds], fmt="o", ms=3, color=colours[i], capsize=0,
                    label="x = %.2f m, t = %.0f ms" % (x, 1e3 * out_rows[i]["t_plug"]))
        ax.plot(centre_nm[holds], (plug_binned[i] / dlog)[holds], "-", color=colours[i], lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    top = max(np.max(mean / dlog), np.max(plug_binned / dlog))
    ax.set_ylim(top * 1e-3, top * 2)
    used = np.any(mean > 0, axis=0) | np.any(plug_binned > 0, axis=0)
    ax.set_xlim(0.9 * centre_nm[used].min(), 1.2 * centre_nm[used].max())
    ax.set_xlabel("d [nm]")
    ax.set_ylabel(r"dN/dlog$_{10}$d [m$^{-3}$]")
    ax.set_title("Size distribution on the axis: coagulationFoam (points, 95 % CI)\n"
                 "and the plug flow at the same residence time (lines)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "psd.png"), dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot(px, pd10, "k-", label="plug flow (axis T history), d10")
    ax.errorbar(xs, [r["d10_nm_foam"] for r in out_rows],
                yerr=[r["d10_nm_foam_ci95"] for r in out_rows], fmt="o", color="C0",
                label="coagulationFoam on the axis, d10 (95 % CI)")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("count mean diameter d10 [nm]")
    ax2 = ax.twinx()
    ax2.plot(px, pT, "C3--", lw=1)
    ax2.set_ylabel("axis temperature [K]", color="C3")
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Mean diameter along the reactor (T: dashed)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "meanDiameter.png"), dpi=120)
    plt.close(fig)

    if growth is not None:
        gmean, gci = growth[3], growth[4]
        fig, ax = plt.subplots(figsize=(7.5, 5))
        for c, i in enumerate(sorted({0, nreg // 2, nreg - 1})):
            col = "C%d" % c
            # the growing particles' masses are not integers: every bin may hold some; the
            # empty bins (zero on the log axis) are left out of the lines
            for m, e, style, what, sel in ((mean[i], ci[i], "--", "without growth", holds),
                                           (gmean[i], gci[i], "-", "with growth", nb * [True])):
                y, dy = m / dlog, e / dlog
                y = np.where(y > 0, y, np.nan)
                ax.plot(centre_nm[sel], y[sel], style, color=col,
                        label="x = %.2f m, %s" % (xs[i], what))
                ax.fill_between(centre_nm[sel], np.maximum(y - dy, 0)[sel], (y + dy)[sel],
                                color=col, alpha=0.15, lw=0)
        top = max(np.max(mean / dlog), np.max(gmean / dlog))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(top * 1e-3, top * 2)
        used = np.any(mean > 0, axis=0) | np.any(gmean > 0, axis=0)
        ax.set_xlim(0.9 * centre_nm[used].min(), 1.2 * centre_nm[used].max())
        ax.set_xlabel("d [nm]")
        ax.set_ylabel(r"dN/dlog$_{10}$d [m$^{-3}$]")
        ax.set_title("Size distribution on the axis with surface growth (solid) and without\n"
                     "(dashed), 95 % intervals shaded")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "psdGrowth.png"), dpi=120)
        plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
