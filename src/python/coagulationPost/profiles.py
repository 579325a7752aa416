# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Profiles of a run on a general mesh: moments along an axis, deposition per wall.

axial(case, axis, bins, t_relax)    time-averaged M0..M3 per cell (from the HDF5 samples,
                                    t >= t_relax), averaged over each slab of cells along
                                    the axis (volume weights: the cells' sample weights are
                                    equal on a uniform mesh, so the mean of the cells);
                                    returns centres of the slabs and [slabs][moments]
deposition(case)                    per patch: kind (outflow | deposited), particles,
                                    number, mass at the last time of
                                    postProcessing/coagulationBalance/patches.csv
write(case, out, axis, bins)        profiles.csv, deposition.csv, axialMoments.png,
                                    deposition.png
"""

import csv
import os

import numpy as np

from . import samples

AXES = {"x": 0, "y": 1, "z": 2}


def axial(case, axis="x", bins=50, t_relax=None):
    reader = samples.RunReader()
    ids, data, _ = reader.read(case, t_relax, None)
    centres = np.array(reader.cells.centres)[ids]
    # data: [samples][cells][moments] with NaN where a cell has no sample
    means = np.nanmean(data, axis=0)
    coord = centres[:, AXES[axis]]
    edges = np.linspace(coord.min(), coord.max(), bins + 1)
    slab = np.clip(np.searchsorted(edges, coord, side="right") - 1, 0, bins - 1)
    prof = np.full((bins, means.shape[1]), np.nan)
    for b in range(bins):
        sel = slab == b
        if np.any(sel):
            prof[b] = np.nanmean(means[sel], axis=0)
    return 0.5 * (edges[:-1] + edges[1:]), prof


def deposition(case):
    path = os.path.join(case, "postProcessing", "coagulationBalance", "patches.csv")
    rows = list(csv.DictReader(open(path)))
    if not rows:
        return {}
    last = max(float(r["time"]) for r in rows)
    out = {}
    for r in rows:
        if float(r["time"]) == last:
            out[r["patch"]] = (r["kind"], float(r["particles"]), float(r["number"]), float(r["mass"]))
    return out


def write(case, out, axis="x", bins=50, t_relax=None, plots=True):
    os.makedirs(out, exist_ok=True)
    x, prof = axial(case, axis, bins, t_relax)
    with open(os.path.join(out, "profiles.csv"), "w") as f:
        f.write("%s,%s\n" % (axis, ",".join("M%d" % k for k in range(prof.shape[1]))))
        for xi, row in zip(x, prof):
            f.write("%.9g,%s\n" % (xi, ",".join("%.9g" % v for v in row)))
    dep = deposition(case)
    with open(os.path.join(out, "deposition.csv"), "w") as f:
        f.write("patch,kind,particles,number,mass\n")
        for p, (kind, n, num, m) in sorted(dep.items()):
            f.write("%s,%s,%d,%.9g,%.9g\n" % (p, kind, n, num, m))
    if not plots:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axs = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    for k, a in enumerate(axs.ravel()[: prof.shape[1]]):
        a.plot(x, prof[:, k], "o-", ms=3)
        a.set_ylabel("M%d (cross-section mean)" % k)
        a.set_yscale("log")
        a.grid(True, alpha=0.3)
    for a in axs[-1]:
        a.set_xlabel(axis + " [m]")
    fig.suptitle("Time-averaged moments along %s (%s)" % (axis, os.path.basename(os.path.abspath(case))))
    fig.tight_layout()
    fig.savefig(os.path.join(out, "axialMoments.png"), dpi=110)
    plt.close(fig)
    if dep:
        names = sorted(dep)
        fig, axs = plt.subplots(1, 2, figsize=(9, 3.5))
        colours = ["tab:red" if dep[p][0] == "deposited" else "tab:blue" for p in names]
        axs[0].bar(names, [dep[p][2] for p in names], color=colours)
        axs[0].set_ylabel("physical particles")
        axs[1].bar(names, [dep[p][3] for p in names], color=colours)
        axs[1].set_ylabel("mass (monomers)")
        for a in axs:
            a.tick_params(axis="x", rotation=30)
            a.set_yscale("log")
        fig.suptitle("Leaving the domain per patch since the start (red: deposited, blue: outflow)")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "deposition.png"), dpi=110)
        plt.close(fig)
