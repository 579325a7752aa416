# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The square cylinder's plots (tutorials/squareCylinder): the particles' size distributions
at the wake probes (sizeDistribution 'wakePsd') over successive windows of time, and the
probes' time series of the transverse velocity (probes 'wake'), the number density and the
count mean diameter.

  python3 -m coagulationPost.squareCylinder --case . --out results [--windows 4] [--no-plots]

Writes OUT/wake.csv (each probe and window: the window, M0 and d10 with their 95 % intervals
for correlated samples, the count median diameter and the geometric standard deviation of the
window's mean distribution), OUT/wakePsd.png (dN/dlog10 d [m^-3] against d [nm] at each probe,
one curve a window, its 95 % band, the count median diameter and sigma_g in the legend) and
OUT/wakeProbes.png (u_y, M0 and d10 at the probes against time). Prints one line a probe and
window. Diameters of spheres of the particles' density, d = (6 m massUnit/(pi rho))^(1/3),
both from the sample file's attributes (the case's 'particles' entry).
"""

import argparse
import csv
import math
import os
import re
import sys

import numpy as np

from . import psd as psdlib
from . import statistics


def read_probes(case, name="wake", field="U"):
    """The probes function object's vector series: times [N], values [N][probes][3], the
    run's starts concatenated (a restart's values replace the later ones)."""
    folder = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(folder):
        raise psdlib.InputError("no probes '%s' in %s" % (name, case))
    starts = sorted((d for d in os.listdir(folder) if os.path.exists(os.path.join(folder, d, field))),
                    key=float)
    t_all, v_all = [], []
    for d in starts:
        rows = []
        with open(os.path.join(folder, d, field)) as f:
            for line in f:
                if line.startswith("#"):
                    continue
                nums = [float(v) for v in re.findall(r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?", line)]
                if nums:
                    rows.append(nums)
        if not rows:
            continue
        a = np.array(rows)
        t, v = a[:, 0], a[:, 1:].reshape(len(a), -1, 3)
        if t_all:
            keep = np.concatenate(t_all) < t[0]
            t_all, v_all = [np.concatenate(t_all)[keep]], [np.concatenate(v_all)[keep]]
        t_all.append(t)
        v_all.append(v)
    if not t_all:
        raise psdlib.InputError("no samples of %s in %s" % (field, folder))
    return np.concatenate(t_all), np.concatenate(v_all)


def median_and_gsd(d, n):
    """Count median diameter and geometric standard deviation of a binned number
    distribution (bin centres d > 0, numbers n >= 0); nan for an empty one."""
    n = np.clip(np.asarray(n, float), 0.0, None)
    total = n.sum()
    if not total > 0:
        return float("nan"), float("nan")
    c = np.cumsum(n) / total
    k = int(np.searchsorted(c, 0.5))
    lnd = np.log(d)
    if k == 0:
        med = d[0]
    else:   # linear in ln d between the bin centres around the median
        f = (0.5 - c[k - 1]) / (c[k] - c[k - 1]) if c[k] > c[k - 1] else 0.0
        med = math.exp(lnd[k - 1] + f * (lnd[k] - lnd[k - 1]))
    mean_ln = (n * lnd).sum() / total
    gsd = math.exp(math.sqrt(max((n * (lnd - mean_ln) ** 2).sum() / total, 0.0)))
    return med, gsd


def main(argv=None):
    try:
        return plots(argv)
    except (psdlib.InputError, OSError) as e:
        print("coagulationPost.squareCylinder: %s\n%s" % (e, __doc__), file=sys.stderr)
        return 2


def plots(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default=".")
    ap.add_argument("--out", default="results")
    ap.add_argument("--name", default="wakePsd")
    ap.add_argument("--probes", default="wake")
    ap.add_argument("--windows", type=int, default=4)
    ap.add_argument("--no-plots", action="store_true")
    a = ap.parse_args(argv)
    os.makedirs(a.out, exist_ok=True)

    s = psdlib.read(a.case, a.name)
    rho = float(s["attrs"]["density"])
    unit = float(s["attrs"]["massUnit"])
    if not rho > 0:
        raise psdlib.InputError("the size distribution '%s' of %s has no particle density: "
                                "give the case a 'particles' entry" % (a.name, a.case))
    time, data, cols = s["time"], s["data"], s["columns"]
    if time.size < 4 * a.windows:
        raise psdlib.InputError("%d samples of '%s' are too few for %d windows"
                                % (time.size, a.name, a.windows))
    nb = s["nBins"]
    edges = s["edges"]
    lower, upper = edges[:-1], edges[1:]

    def diam_nm(m):
        return 1e9 * (6.0 * np.asarray(m, float) * unit / (math.pi * rho)) ** (1.0 / 3.0)

    centre_nm = diam_nm(np.sqrt(lower * upper))
    dlog = np.log10(upper / lower) / 3.0         # the bins' widths in log10 d
    # the bins' columns hold number densities [m^-3]: dN/dlog10 d = n / dlog
    dndlog = data[:, :, :nb] / dlog
    m0 = data[:, :, cols.index("M0")]
    d10 = 1e9 * data[:, :, cols.index("d10")]
    probes = np.asarray(s["centres"])
    nreg = probes.shape[0]
    bounds = np.linspace(time[0], time[-1], a.windows + 1)
    windows = [(time >= lo) & (time <= hi if k == a.windows - 1 else time < hi)
               for k, (lo, hi) in enumerate(zip(bounds[:-1], bounds[1:]))]

    rows, curves = [], {}
    for i in range(nreg):
        for k, w in enumerate(windows):
            mean, _, ci, _ = statistics.correlated_interval(dndlog[w, i, :])
            mm0, _, cm0, _ = statistics.correlated_interval(m0[w, i])
            ok = np.isfinite(d10[w, i])
            md10, _, cd10, _ = statistics.correlated_interval(d10[w, i][ok])
            med, gsd = median_and_gsd(centre_nm, mean * dlog)
            curves[(i, k)] = (mean, ci, med, gsd)
            rows.append({"probe": i, "x": probes[i, 0], "y": probes[i, 1],
                         "tStart": bounds[k], "tEnd": bounds[k + 1], "samples": int(w.sum()),
                         "M0": float(mm0), "M0_ci95": float(cm0),
                         "d10_nm": float(md10), "d10_nm_ci95": float(cd10),
                         "cmd_nm": med, "sigma_g": gsd})
            print("probe %d (x = %.3f m), t = %.3f..%.3f s: M0 %.3e +- %.1e m^-3, d10 %.2f +- %.2f nm, "
                  "CMD %.2f nm, sigma_g %.3f" % (i, probes[i, 0], bounds[k], bounds[k + 1], mm0, cm0,
                                                 md10, cd10, med, gsd))
    with open(os.path.join(a.out, "wake.csv"), "w", newline="") as f:
        wr = csv.DictWriter(f, fieldnames=list(rows[0]))
        wr.writeheader()
        wr.writerows(rows)
    if a.no_plots:
        return 0

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, nreg, figsize=(4.2 * nreg, 4.2), sharey=True, squeeze=False)
    colours = plt.cm.viridis(np.linspace(0, 0.85, a.windows))
    for i, ax in enumerate(axes[0]):
        for k in range(a.windows):
            mean, ci, med, gsd = curves[(i, k)]
            pos = mean > 0
            ax.fill_between(centre_nm[pos], np.clip(mean - ci, mean * 1e-3, None)[pos],
                            (mean + ci)[pos], color=colours[k], alpha=0.2, lw=0)
            ax.plot(centre_nm[pos], mean[pos], color=colours[k], lw=1.5,
                    label="t %.2f-%.2f s: CMD %.1f nm, $\\sigma_g$ %.2f"
                    % (bounds[k], bounds[k + 1], med, gsd))
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("d [nm]")
        ax.set_title("probe %d: x = %.0f mm behind the axis" % (i, 1e3 * probes[i, 0]))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="lower left")
    axes[0][0].set_ylabel("dN/dlog$_{10}$d [m$^{-3}$]")
    fig.suptitle("Size distributions in the wake (mean over each window, 95 % bands)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "wakePsd.png"), dpi=120)
    plt.close(fig)

    fig, axes = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True)
    try:
        tu, u = read_probes(a.case, a.probes)
        sel = tu >= time[0]
        for i in range(min(nreg, u.shape[1])):
            axes[0].plot(tu[sel], u[sel, i, 1], lw=0.8, label="probe %d" % i)
        axes[0].set_ylabel("$u_y$ [m/s]")
        axes[0].legend(fontsize=8, ncol=nreg)
    except psdlib.InputError as e:
        axes[0].text(0.5, 0.5, str(e), transform=axes[0].transAxes, ha="center")
    for i in range(nreg):
        axes[1].plot(time, m0[:, i], lw=0.8)
        axes[2].plot(time, d10[:, i], lw=0.8)
    axes[1].set_ylabel("M0 [m$^{-3}$]")
    axes[1].set_yscale("log")
    axes[2].set_ylabel("d$_{10}$ [nm]")
    axes[2].set_xlabel("t [s]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.suptitle("Wake probes: the vortex street carries the particles past them")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "wakeProbes.png"), dpi=120)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
