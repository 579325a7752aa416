# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The PNG figures of coagulationReport and coagulationTables (matplotlib, Agg).

report_figures: moments.png, relativeError.png, normalisedStdDev.png of one report.
table_figures:  Patterson & Wagner's figures 3-6 (constant kernel) and 7-10
                (additive kernel) from rows of coagulationPost.tables.
"""

import os

import numpy as np

from . import analytic
from .report import EQ_LABELS, MOMENT_NAMES, title_of
from .tables import sort_rows

MARKERS = {"SWA": "o", "DSA1": "s", "DSA2": "^"}
CMAPS = {"SWA": "Blues", "DSA1": "Reds", "DSA2": "Greens"}


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _save(plt, fig, title, path, top):
    fig.suptitle(title)
    fig.tight_layout(rect=(0, 0, 1, top))
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _moment_grid(plt, nm):
    """A 2 x 2 figure, one panel per moment k = 0..3: (fig, [(k, ax) for k < nm]);
    the panels of k >= nm are hidden."""
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5), squeeze=False)
    shown = []
    for k in range(4):
        ax = axes[k // 2][k % 2]
        if k >= nm:
            ax.set_visible(False)
        else:
            shown.append((k, ax))
    return fig, shown


def _moment_panel(ax, k, ylabel, title_suffix="", which="major"):
    ax.set_xlabel("x (cell centre)")
    ax.set_ylabel(ylabel)
    ax.set_title("k = %d (%s)%s" % (k, MOMENT_NAMES[k], title_suffix))
    ax.grid(True, which=which, alpha=0.3)
    ax.legend(fontsize=8, loc="best")


def _ci_kind(meta):
    """What the report's interval allows for (report module doc)."""
    r = meta.get("realisations", 1)
    return "%d realisations, t" % r if r > 1 else "correlated samples, n_eff"


def report_figures(res, out, x_inlet=0.0, t_end=None, check_rel_tol=None):
    """The report's figures; check_rel_tol draws the --check tolerance lines."""
    plt = _pyplot()
    meta = res["meta"]
    kind = meta["analytic"]
    x = res["x"]
    nm = min(res["mean"].shape[1], 4)
    title = title_of(meta, meta["runs"][0]["tRelax"], t_end)
    paths = []
    fine = None
    if kind is not None:
        lo, hi = res["edges"]
        xa = np.linspace(max(x_inlet, float(np.min(lo))), float(np.max(hi)), 400)
        fine = (xa, analytic.profile(kind, xa - x_inlet, meta["inceptionRate"],
                                     meta["K0"], meta["u"]))

    # moments
    fig, panels = _moment_grid(plt, nm)
    for k, ax in panels:
        ax.errorbar(x, res["mean"][:, k], yerr=res["ci"][:, k], fmt="o", ms=3, capsize=2,
                    color="C0", label="sample mean ± 95 %% CI (%s)" % _ci_kind(meta))
        if fine is not None:
            ax.plot(fine[0], fine[1][k], "k-", lw=1, label="analytic (%s)" % EQ_LABELS[kind][k])
        _moment_panel(ax, k, r"$m_{%d}(x)$" % k)
    paths.append(_save(plt, fig, "Mass moments: " + title, os.path.join(out, "moments.png"), 0.96))

    # relative error to the analytic cell average
    if kind is not None:
        fig, panels = _moment_grid(plt, nm)
        for k, ax in panels:
            a = res["analytic"][:, k]
            with np.errstate(invalid="ignore", divide="ignore"):
                if "ciIid" in res:
                    ax.errorbar(x, 100 * res["rel"][:, k], yerr=100 * res["ciIid"][:, k] / np.abs(a),
                                fmt="none", capsize=4, color="0.6", lw=2,
                                label="95 % CI if samples were independent")
                ax.errorbar(x, 100 * res["rel"][:, k], yerr=100 * res["ci"][:, k] / np.abs(a),
                            fmt="o", ms=3, capsize=2, color="C0",
                            label="(mean − analytic)/analytic ± 95 %% CI (%s)" % _ci_kind(meta))
            ax.axhline(0.0, color="k", lw=1)
            if check_rel_tol is not None:
                for s in (-1, 1):
                    ax.axhline(100 * s * check_rel_tol, color="C3", ls="--", lw=1,
                               label="check tolerance" if s > 0 else None)
            _moment_panel(ax, k, r"relative error of $M_{n,%d}$ [%%]" % k,
                          ", analytic cell average")
        paths.append(_save(plt, fig, "Relative error: " + title,
                           os.path.join(out, "relativeError.png"), 0.96))

    # normalised standard deviation
    fig, panels = _moment_grid(plt, nm)
    refname = "analytic m_k" if kind is not None else "sample mean"
    for k, ax in panels:
        y = res["nsd"][:, k]
        ax.plot(x, y, "o", ms=3, color="C0", label="simulation")
        if k == 1 and meta["inceptionRate"] and meta["V1"]:
            xe = x[x > x_inlet]
            if xe.size:
                xl = np.linspace(float(xe.min()), float(xe.max()), 300)
                ax.plot(xl, analytic.normalised_sd_m1(xl - x_inlet, meta["inceptionRate"],
                                                      meta["V1"], meta["u"]), "k-", lw=1,
                        label=r"eq. (47): $\sqrt{u/(I V_1 x)}$")
        yf = y[np.isfinite(y)]
        if k == 1 and yf.size and meta["inceptionRate"] and meta["V1"]:
            yf = np.concatenate([yf, ax.get_lines()[-1].get_ydata()])
        if yf.size and np.all(yf > 0) and yf.max() > 10 * yf.min():
            ax.set_yscale("log")   # only when the values span more than a decade
        _moment_panel(ax, k, r"$\sqrt{n\,\mathrm{var}(M_{n,%d})}\,/\,m_{%d}(x)$" % (k, k),
                      which="both")
    paths.append(_save(plt, fig, "Normalised standard deviation (m_k = %s): %s" % (refname, title),
                       os.path.join(out, "normalisedStdDev.png"), 0.96))
    return paths


def table_figures(rows, out):
    """figure3..6.png from constant-kernel rows, figure7..10.png from additive ones."""
    plt = _pyplot()
    written = []
    groups = {}
    for r in rows:
        groups.setdefault(r["kernel"], []).append(r)

    def series(ax, rs, y_of, logy=False):
        # one colour family per method, darker for larger n
        for r in rs:
            ns = sorted({q["n"] for q in rs if q["method"] == r["method"]})
            cmap = plt.get_cmap(CMAPS.get(r["method"], "Greys"))
            c = cmap(0.45 + 0.5 * ns.index(r["n"]) / max(1, len(ns) - 1))
            ax.plot(r["x"], y_of(r), MARKERS.get(r["method"], "x"), color=c, ms=4, mfc="none"
                    if r["method"] == "DSA1" else c, ls="none",
                    label="%s n=%d (R=%d)" % (r["method"], r["n"], r["R"]))
        if logy:
            ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_xlabel("x")

    def eq47_lines(ax, rs):
        done = set()
        for r in rs:
            fam = "SWA" if r["method"] == "SWA" else "DSA"
            if fam in done or not r["I"] or not r["V1"]:
                continue
            done.add(fam)
            xl = np.linspace(float(r["x"].min()), float(r["x"].max()), 300)
            ax.plot(xl, analytic.normalised_sd_m1(xl, r["I"], r["V1"], r["u"]),
                    "k-" if fam == "SWA" else "k--", lw=1,
                    label="eq. (47), %s V1 = %g" % (fam, r["V1"]))

    def save(fig, name, title):
        written.append(_save(plt, fig, title, os.path.join(out, name), 0.95))

    const = sort_rows(groups.get("constant", []))
    for k in range(4):
        if not const:
            break
        fig, ax = plt.subplots(figsize=(8, 5.5))
        series(ax, const, lambda r: r["nsd"][:, k], logy=True)
        if k == 1:
            eq47_lines(ax, const)
        ax.set_ylabel(r"$\sqrt{n\,\mathrm{var}(M_{n,%d}(x))}/m_%d(x)$" % (k, k))
        ax.legend(fontsize=7, ncol=2)
        save(fig, "figure%d.png" % (3 + k), "Figure %d: normalised standard deviation of M_{n,%d},"
             " constant-kernel duct" % (3 + k, k))

    add = sort_rows(groups.get("additive", []))
    if add:
        fig, ax = plt.subplots(figsize=(8, 5.5))
        series(ax, add, lambda r: r["mean"][:, 0])
        if add[0]["analyticKind"]:
            r = add[0]
            xl = np.linspace(0.0, float(r["edges"][1].max()), 300)
            ax.plot(xl, analytic.profile(r["analyticKind"], xl, r["I"], r["K0"], r["u"])[0],
                    "k-", lw=1, label="moment ODE")
        ax.set_ylabel(r"mean of $M_{n,0}(x)$")
        ax.legend(fontsize=7, ncol=2)
        save(fig, "figure7.png", "Figure 7: mean particle concentration, additive-kernel duct")

        fig, ax = plt.subplots(figsize=(8, 5.5))
        x0 = 0.5 * float(add[0]["edges"][1].max())
        sub = [dict(r) for r in add]
        for r in sub:
            keep = r["x"] >= x0
            r["x"], r["mean"] = r["x"][keep], r["mean"][keep]
        series(ax, sub, lambda r: r["mean"][:, 1] / 1e3)
        xl = np.linspace(x0, float(add[0]["edges"][1].max()), 100)
        ax.plot(xl, analytic.mass_moment(xl, add[0]["I"], add[0]["u"]) / 1e3, "k-", lw=1,
                label="eq. (50)")
        ax.set_ylabel(r"mean of $M_{n,1}(x)/10^3$")
        ax.legend(fontsize=7, ncol=2)
        save(fig, "figure8.png", "Figure 8: zoomed M_{n,1}(x)/1e3, additive-kernel duct")

        fig, ax = plt.subplots(figsize=(8, 5.5))
        series(ax, add, lambda r: r["nsd"][:, 1], logy=True)
        eq47_lines(ax, add)
        ax.set_ylabel(r"$\sqrt{n\,\mathrm{var}(M_{n,1}(x))}/m_1(x)$")
        ax.legend(fontsize=7, ncol=2)
        save(fig, "figure9.png", "Figure 9: normalised standard deviation of M_{n,1}, additive duct")

        fig, ax = plt.subplots(figsize=(8, 5.5))
        series(ax, add, lambda r: np.sqrt(r["n"] * r["var"][:, 0]) / 1e3, logy=True)
        ax.set_ylabel(r"$\sqrt{n\,\mathrm{var}(M_{n,0}(x))}/10^3$")
        ax.legend(fontsize=7, ncol=2)
        save(fig, "figure10.png", "Figure 10: normalised standard deviation of M_{n,0}, additive duct")
    return written
