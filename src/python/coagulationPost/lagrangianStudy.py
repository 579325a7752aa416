# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Figures of the Kolodko-Sabelfeld-Wagner §5 studies from lagrangianStudy's CSV files.

    python3 -m coagulationPost.lagrangianStudy uniform DIR R'
                            Figs 1-2: <In>/S and In-bar/S against r' (whole range and a
                            zoom), t' = 1.25 and 55
    python3 -m coagulationPost.lagrangianStudy linear DIR R'
                            Figs 3-6: <Sp(r', t', l)> against l at r' = 0.1 R' and R';
                            Figs 7-8: <Ms(r', t')> against r'

Stochastic: dashed, with the 95 % interval over the velocity realisations (dotted / band);
<Sp_l> = <In_l>/<In>, <Ms> = <mass>/<In> (the functionals of the expectation (4.5));
deterministic (mean velocity, (5.3)): solid. Writes fig*.png into DIR, prints a summary.
The intervals are lagrangianStudy's own (the *_hw columns).
"""
import csv
import glob
import os
import re
import sys

import numpy as np


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def read(path):
    """A CSV file of numbers as {column: array}."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def times_of(names, prefix):
    """The times t of the file names PREFIX<t>[_r...].csv, as strings, sorted by value."""
    ts = []
    for name in names:
        m = re.match(prefix + r"([0-9.e+-]+?)(_r.*)?\.csv$", name)
        if m:
            ts.append(m.group(1))
    return sorted(set(ts), key=float)


def times(d, prefix):
    """times_of the files PREFIX*.csv in folder d."""
    return times_of([os.path.basename(p) for p in glob.glob(os.path.join(d, prefix + "*.csv"))],
                    prefix)


def half_radius(r, In, far):
    """The first r at which In reaches half of far (the clusters' half radius)."""
    return r[np.argmax(In >= 0.5 * far)]


def interval_sizes(l, mean, hw, det):
    """Sizes whose whole interval [mean - hw, mean + hw] lies below det, and sizes whose
    interval holds det."""
    below = [int(s) for s, m, h, dd in zip(l, mean, hw, det) if m + h < dd]
    within = [int(s) for s, m, h, dd in zip(l, mean, hw, det) if abs(m - dd) <= h]
    return below, within


def uniform(d, R):
    plt = _pyplot()
    for n, t in enumerate(times(d, "functionals_t"), start=1):
        f = read(os.path.join(d, f"functionals_t{t}.csv"))
        k = int(np.argmin(abs(f["r"] - R)))
        half = half_radius(f["r"], f["In"], f["In_det"][-1])
        ok = f["ratio_realisations"] > 0
        print(f"t' = {t}: In(R')/S = {f['In'][k]:.4g} +- {f['In_hw'][k]:.2g}, deterministic "
              f"{f['In_det'][k]:.4g} (ratio {f['In_det'][k] / f['In'][k]:.3g}); half the clusters "
              f"within r' = {half:g}; max |<Ms> - Ms-bar| = "
              f"{np.max(abs(f['Ms'] - f['Ms_det'])[ok]):.2g} over the {ok.sum()} radii with clusters")
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
        for ax, zoom in zip(axes, (False, True)):
            sel = f["r"] <= 2 * R if zoom else f["r"] > 0
            r = f["r"][sel]
            ax.plot(r, f["In_det"][sel], "k-", label="deterministic $\\overline{In}/S$")
            ax.plot(r, f["In"][sel], "k--", label="stochastic $\\langle In\\rangle/S$")
            ax.fill_between(r, (f["In"] - f["In_hw"])[sel], (f["In"] + f["In_hw"])[sel],
                            color="0.8", label="95 % interval")
            ax.set_xlabel("$r'$")
            ax.set_ylabel("$In/S$")
            ax.set_title(f"t' = {t}" + (" (zoom $r' \\leq 2R'$)" if zoom else ""))
            ax.legend(fontsize=8)
        fig.suptitle(f"Fig. {n}: uniform initial condition, clusters in $\\Omega_{{r'}}$, t' = {t}")
        fig.tight_layout()
        fig.savefig(os.path.join(d, f"fig{n}_In_t{t}.png"), dpi=110)
        plt.close(fig)


def linear(d, R):
    plt = _pyplot()
    ts = times(d, "functionals_t")
    fig_no = 3
    for rr in (0.1 * R, R):
        for t in ts:
            p = os.path.join(d, f"spectrum_t{t}_r{rr:g}.csv")
            if not os.path.exists(p):
                continue
            s = read(p)
            below, within = interval_sizes(s["l"], s["Sp"], s["Sp_hw"], s["Sp_det"])
            print(f"t' = {t}, r' = {rr:g}: <Sp_l> + interval below Sp-bar for l = {below}; "
                  f"Sp-bar inside the interval for l = {within}; Sp_5/Sp-bar = "
                  f"{s['Sp'][4] / s['Sp_det'][4]:.3f} +- {s['Sp_hw'][4] / s['Sp_det'][4]:.3f}, "
                  f"Sp_10/Sp-bar = {s['Sp'][9] / s['Sp_det'][9]:.3f} +- "
                  f"{s['Sp_hw'][9] / s['Sp_det'][9]:.3f}")
            fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
            ok = s["Sp_det"] > 0
            ax.semilogy(s["l"][ok], s["Sp_det"][ok], "k-o", ms=3, label="deterministic $\\overline{Sp}$")
            ax.semilogy(s["l"][ok], s["Sp"][ok], "k--s", ms=3, label="stochastic $\\langle Sp\\rangle$")
            lo = np.where(s["Sp"] - s["Sp_hw"] > 0, s["Sp"] - s["Sp_hw"], np.nan)
            ax.semilogy(s["l"][ok], lo[ok], "k:", lw=0.8, label="95 % interval")
            ax.semilogy(s["l"][ok], (s["Sp"] + s["Sp_hw"])[ok], "k:", lw=0.8)
            ax.set_xlabel("size $l$")
            ax.set_ylabel("$Sp(r', t', l)$")
            ax.set_title(f"Fig. {fig_no}: linear IC, r' = {rr:g}, t' = {t}")
            ax.legend(fontsize=8)
            ratio, hw = s["Sp"][ok] / s["Sp_det"][ok], s["Sp_hw"][ok] / s["Sp_det"][ok]
            ax2.axhline(1.0, color="k", lw=1, label="deterministic")
            ax2.plot(s["l"][ok], ratio, "k--s", ms=3, label="stochastic / deterministic")
            ax2.fill_between(s["l"][ok], ratio - hw, ratio + hw, color="0.8", label="95 % interval")
            ax2.set_xlabel("size $l$")
            ax2.set_ylabel("$\\langle Sp\\rangle / \\overline{Sp}$")
            ax2.set_title("the same, relative to the deterministic case")
            ax2.legend(fontsize=8)
            fig.tight_layout()
            fig.savefig(os.path.join(d, f"fig{fig_no}_Sp_t{t}_r{rr:g}.png"), dpi=110)
            plt.close(fig)
            fig_no += 1
    for t in ts:
        f = read(os.path.join(d, f"functionals_t{t}.csv"))
        for r, m, h, dd, n in zip(f["r"], f["Ms"], f["Ms_hw"], f["Ms_det"], f["ratio_realisations"]):
            print(f"t' = {t}, r' = {r:g}: <Ms> - 1 = {m - 1:.5f} +- {h:.1e}, Ms-bar - 1 = {dd - 1:.5f}"
                  f" ({n:g} realisations with clusters)")
        fig, ax = plt.subplots(figsize=(6, 4.2))
        ax.plot(f["r"], f["Ms_det"], "k-o", ms=3, label="deterministic $\\overline{Ms}$")
        ax.plot(f["r"], f["Ms"], "k--s", ms=3, label="stochastic $\\langle Ms\\rangle$")
        ax.plot(f["r"], f["Ms"] - f["Ms_hw"], "k:", lw=0.8, label="95 % interval")
        ax.plot(f["r"], f["Ms"] + f["Ms_hw"], "k:", lw=0.8)
        ax.set_xlabel("$r'$")
        ax.set_ylabel("$Ms(r', t')$")
        ax.set_title(f"Fig. {fig_no}: linear IC, mean cluster size, t' = {t}")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(d, f"fig{fig_no}_Ms_t{t}.png"), dpi=110)
        plt.close(fig)
        fig_no += 1


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 3 or argv[0] not in ("uniform", "linear"):
        print(__doc__, file=sys.stderr)
        return 1
    (uniform if argv[0] == "uniform" else linear)(argv[1], float(argv[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
