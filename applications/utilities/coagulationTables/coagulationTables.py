#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationTables: the tables and variance figures of Patterson & Wagner's
weighted-particle paper from ensembles of coagulationFoam runs.

Each --rows argument is one ensemble folder (what coagulationEnsemble -out
writes): its realisation_* sub-folders are independent runs of one method
(algorithm attribute) at one statistical weight n, each with its HDF5 samples
in postProcessing/coagulationSamples.  A row's samples are taken from each
run's tRelax to the run's end (or --t-end), so DSA rows averaged over
[0.2, 4.0] and SWA rows over [0.2, 0.4] just need runs of those lengths.
"DIR1+DIR2" pools the realisations of several such folders (the same method
and n, grown over several studies, all seeds distinct) into one row.

For the table cell (the cell holding --table-x, by default 0.099, the cell
[0.098, 0.1] of the additive duct) and each row it reports, as in the paper:
  mean     sample mean of M_{n,k} over all samples of all realisations
  sd       sample standard deviation of those samples
  ci95     1.96 sd / sqrt(samples): the paper's half-width, which treats
           successive samples as independent
and, because successive samples are correlated, also
  ci95_R   the half-width from the R independent realisation means
           (Student t, R-1 degrees of freedom; empty when R < 2).

Outputs in --out:
  table1.csv / table1.md     M_{n,1} rows (Table 1, units 1e3 in the .md)
  table2.csv / table2.md     M_{n,2} rows (Table 2, units 1e7 in the .md)
  tableM0M3.csv              the same statistics for M_{n,0} and M_{n,3}
  rows.csv                   every row: method, kernel, n, V1, realisations, time
                             window, wall and core seconds of the ensemble
  figure3..6.png             constant-kernel rows: sqrt(n var(M_{n,k}))/m_k(x),
                             k = 0..3, eq. (47) lines in figure 4
  figure7..10.png            additive-kernel rows: mean M_{n,0}(x); M_{n,1}(x)/1e3
                             near the outlet with eq. (50); sqrt(n var(M_{n,1}))/m_1
                             with eq. (47); sqrt(n var(M_{n,0}))/1e3
  checks.txt                 the --check results

--check applies the paper's acceptance statements to the rows present
(each check is skipped, and says so, when its rows are missing):
  SWA M1 mean within --swa-m1-tol of --swa-m1-ref (9.877e3)
  SWA M2 mean within --swa-m2-tol of --swa-m2-ref (9.1e7)
  SWA sd of M1 and M2 falling like n^(-1/2): fitted exponent within
      --sd-exponent-tol of -0.5 (needs two SWA rows)
  SWA normalised sd of M1 within --nsd-tol of eq. (47) in every cell past
      --nsd-skip-cells
  DSA1 M1 mean above 9.90e3 by more than --z-dsa1 standard errors (default --z)
  DSA2 M2 mean rising with n: largest-n row above the smallest-n row by more
      than --z combined standard errors, and closer to the SWA value
A mean check passes when |mean - ref| <= tol*ref + z_ci*SE, with SE from the
realisation means (R >= 3) or else from the samples; the sd checks likewise
widen their tolerance by z_ci standard errors of the sd (from the spread of
the realisations' own sds when R >= 3, else sd/sqrt(2 samples)). z_ci = 0
(the default) is the paper's fixed tolerance; reduced studies with few
samples widen it by their own statistical error (e.g. --z-ci 3).

Exit status: 0 ok, 1 a check failed, 2 bad input.
"""

import argparse
import csv
import glob
import json
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "coagulationReport"))
import coagulationReport as cr  # noqa: E402
import analyticDuct  # noqa: E402

# Published values (Patterson & Wagner, Tables 1 and 2), shown beside ours for
# comparison only; nothing is checked against them except through the options.
PAPER = {
    1: {  # mean, sd, ci95 in units of 1e3
        "DSA1": {2048: (10.570, 11.09, 0.062), 4096: (10.514, 9.99, 0.079),
                 8192: (10.347, 7.64, 0.086), 16384: (10.097, 5.09, 0.081),
                 32768: (10.112, 4.64, 0.104), 65536: (10.319, 3.66, 0.116),
                 131072: (10.147, 2.56, 0.114), 262144: (10.132, 1.99, 0.126)},
        "DSA2": {2048: (9.894, 9.923, 0.0220), 4096: (9.854, 3.271, 0.0260),
                 8192: (9.874, 2.645, 0.0297), 16384: (9.898, 2.064, 0.0293),
                 32768: (9.880, 1.534, 0.0345), 65536: (9.890, 1.143, 0.0363),
                 131072: (9.871, 0.811, 0.0365), 262144: (9.894, 0.586, 0.0372)},
        "SWA": {2048: (9.878, 0.249, 0.0060), 4096: (9.887, 0.178, 0.0061),
                8192: (9.886, 0.126, 0.0061), 16384: (9.880, 0.085, 0.0059),
                32768: (9.877, 0.064, 0.0062), 65536: (9.878, 0.046, 0.0063),
                131072: (9.876, 0.030, 0.0059), 262144: (9.877, 0.020, 0.0055)},
    },
    2: {  # units of 1e7
        "DSA1": {2048: (10.55, 50.83, 0.286), 4096: (16.95, 123.15, 0.978),
                 8192: (20.63, 100.39, 1.128), 16384: (19.92, 61.58, 0.978),
                 32768: (31.45, 105.39, 2.368), 65536: (40.68, 134.16, 4.263),
                 131072: (40.79, 82.59, 3.712), 262144: (48.09, 99.28, 6.310)},
        "DSA2": {2048: (2.953, 3.45, 0.019), 4096: (4.176, 4.69, 0.037),
                 8192: (5.549, 5.97, 0.067), 16384: (6.836, 6.70, 0.095),
                 32768: (7.660, 6.39, 0.144), 65536: (8.376, 5.80, 0.184),
                 131072: (8.661, 4.60, 0.207), 262144: (8.981, 3.26, 0.207)},
        "SWA": {2048: (9.354, 2.09, 0.051), 4096: (9.273, 1.42, 0.049),
                8192: (9.192, 1.02, 0.050), 16384: (9.110, 0.72, 0.049),
                32768: (9.049, 0.50, 0.049), 65536: (9.105, 0.48, 0.047),
                131072: (9.145, 0.26, 0.050), 262144: (9.110, 0.18, 0.049)},
    },
}
TABLE_UNIT = {1: 1e3, 2: 1e7}
METHOD_ORDER = {"DSA1": 0, "DSA2": 1, "SWA": 2}
MARKERS = {"SWA": "o", "DSA1": "s", "DSA2": "^"}
CMAPS = {"SWA": "Blues", "DSA1": "Reds", "DSA2": "Greens"}


class TablesError(Exception):
    """Bad input: reported on stderr, exit status 2."""


# --------------------------------------------------------------------------- rows

def student_t975(dof):
    """97.5 % quantile of Student's t (two-sided 95 %); scipy is a bootstrap dependency."""
    from scipy.stats import t
    return float(t.ppf(0.975, dof))


def realisation_dirs(row_dir):
    dirs = sorted(d for d in glob.glob(os.path.join(row_dir, "realisation_*")) if os.path.isdir(d))
    if not dirs and os.path.isdir(os.path.join(row_dir, cr.SAMPLE_DIR)):
        dirs = [row_dir]  # a single run given directly
    if not dirs:
        raise TablesError("%s holds no realisation_* folder and no %s" % (row_dir, cr.SAMPLE_DIR))
    return dirs


def load_row(row_dir, t_end):
    """Per-realisation statistics of one ensemble, pooled. "DIR1+DIR2+..." pools the
    realisations of several ensembles of the same method and n (a row grown over several
    studies); their seeds must all differ, and their wall and core seconds add up."""
    parts = row_dir.split("+")
    dirs = [d for part in parts for d in realisation_dirs(part)]
    per = []
    for d in dirs:
        ns = argparse.Namespace(realisations=None, case=d, t_relax=None, t_end=t_end, u=None,
                                x_inlet=0.0, analytic="auto")
        try:
            per.append(cr.compute(ns))
        except cr.ReportError as e:
            raise TablesError("%s: %s" % (d, e))
    meta = per[0]["meta"]
    for p, d in zip(per[1:], dirs[1:]):
        for key in ("algorithm", "kernel", "n", "V1", "K0", "inceptionRate"):
            if not cr._same(p["meta"][key], meta[key]):
                raise TablesError("%s: attribute %s = %r differs from %r in %s"
                                  % (d, key, p["meta"][key], meta[key], dirs[0]))
        if p["x"].shape != per[0]["x"].shape or not np.allclose(p["x"], per[0]["x"]):
            raise TablesError("%s: cells differ from those of %s" % (d, dirs[0]))
    seeds = [s for p in per for r in p["meta"]["runs"] for s in r["seeds"]]
    if len(set(map(str, seeds))) != len(seeds):
        raise TablesError("%s: realisations share seeds %s; they are not independent"
                          % (row_dir, seeds))

    # pool (Chan et al.): per realisation count c, mean m, variance v
    c = np.array([p["count"] for p in per])            # [R][cells][k]
    m = np.array([p["mean"] for p in per])
    v = np.nan_to_num(np.array([p["var"] for p in per]))
    n_tot = c.sum(axis=0)
    mean = (c * m).sum(axis=0) / n_tot
    ss = ((c - 1).clip(min=0) * v + c * (m - mean[None]) ** 2).sum(axis=0)
    var = ss / np.maximum(n_tot - 1, 1)
    sd = np.sqrt(var)
    R = len(per)
    # standard error of the pooled sd: from the spread of the realisations' own sds when
    # there are enough of them (this sees the samples' correlation), else the independent-
    # sample value sd/sqrt(2 count)
    with np.errstate(invalid="ignore", divide="ignore"):
        if R >= 3:
            sd_se = np.sqrt(v).std(axis=0, ddof=1) / math.sqrt(R)
        else:
            sd_se = sd / np.sqrt(2.0 * np.maximum(n_tot, 1))
    if R >= 2:
        se_R = m.std(axis=0, ddof=1) / math.sqrt(R)
        ci_R = student_t975(R - 1) * se_R
    else:
        se_R = ci_R = np.full_like(mean, np.nan)
    res0 = per[0]
    windows = [(r["tRelax"], r["timeRange"][1] if t_end is None else min(t_end, r["timeRange"][1]))
               for p in per for r in p["meta"]["runs"]]
    timing = {}
    for part in parts:
        tj = os.path.join(part, "ensemble.json")
        if os.path.isfile(tj):
            with open(tj) as f:
                t = json.load(f)
            if not timing:
                timing = t
            else:
                for key in ("wallSeconds", "cpuSeconds"):
                    if key in timing and key in t:
                        timing[key] = timing[key] + t[key]
                    else:
                        timing.pop(key, None)
        elif len(parts) > 1:
            timing = {}
            break
    with np.errstate(invalid="ignore", divide="ignore"):
        nsd = np.sqrt(meta["n"] * var) / np.where(np.isfinite(res0["analytic"]), res0["analytic"], mean)
    return {
        "dir": row_dir, "method": meta["algorithm"], "kernel": meta["kernel"], "n": int(meta["n"]),
        "V1": meta["V1"], "I": meta["inceptionRate"], "K0": meta["K0"], "u": meta["u"],
        "analyticKind": meta["analytic"], "R": R, "x": res0["x"], "edges": res0["edges"],
        "analytic": res0["analytic"], "count": n_tot, "mean": mean, "sd": sd, "var": var,
        "ci": cr.Z95 * sd / np.sqrt(n_tot), "seR": se_R, "ciR": ci_R, "sdSE": sd_se,
        "realisationMeans": m, "nsd": nsd, "window": (min(w[0] for w in windows),
                                                       max(w[1] for w in windows)),
        "timing": timing,
    }


def table_cell(row, x):
    lo, hi = row["edges"]
    if lo is None:
        return int(np.argmin(np.abs(row["x"] - x)))
    inside = np.nonzero((lo <= x) & (x <= hi))[0]
    if inside.size == 0:
        raise TablesError("no cell of %s holds x = %g (cells span [%g, %g])"
                          % (row["dir"], x, float(lo.min()), float(hi.max())))
    return int(inside[-1])


def cell_label(row, i):
    lo, hi = row["edges"]
    if lo is None:
        return "cell centre x = %s" % fmt(float(row["x"][i]), 4)
    return "cell [%s, %s]" % (fmt(float(lo[i]), 4), fmt(float(hi[i]), 4))


def se_of(row, i, k):
    """Standard error of the row mean: from realisation means when R >= 3."""
    if row["R"] >= 3 and np.isfinite(row["seR"][i, k]):
        return float(row["seR"][i, k]), "realisations"
    return float(row["sd"][i, k] / math.sqrt(row["count"][i, k])), "samples"


# --------------------------------------------------------------------------- output

def fmt(v, digits=6):
    return "" if v is None or not np.isfinite(v) else "%.*g" % (digits, v)


def sort_rows(rows):
    return sorted(rows, key=lambda r: (METHOD_ORDER.get(r["method"], 9), r["method"], r["n"]))


def write_tables(rows, table_rows, x, out):
    """Tables 1, 2 and M0/M3 from table_rows; rows.csv lists every row."""
    written = []
    all_rows, rows = rows, table_rows
    header = ["method", "n", "realisations", "samples", "tStart", "tEnd", "mean", "sd", "ci95",
              "ci95_realisations", "paper_mean", "paper_sd", "paper_ci95"]
    for k, name in ((1, "table1"), (2, "table2")):
        unit = TABLE_UNIT[k]
        lines = []
        with open(os.path.join(out, name + ".csv"), "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            for r in rows:
                i = table_cell(r, x)
                paper = PAPER[k].get(r["method"], {}).get(r["n"])
                pv = [p * unit for p in paper] if paper else [None] * 3
                w.writerow([r["method"], r["n"], r["R"], int(r["count"][i, k]),
                            fmt(r["window"][0]), fmt(r["window"][1]),
                            fmt(r["mean"][i, k], 8), fmt(r["sd"][i, k]), fmt(r["ci"][i, k]),
                            fmt(r["ciR"][i, k])] + [fmt(p) for p in pv])
                lines.append((r, i, paper))
        written.append(os.path.join(out, name + ".csv"))
        e = int(round(math.log10(unit)))
        md = ["# Table %d: confidence intervals for the mean of M_{n,%d}, %s"
              % (k, k, cell_label(lines[0][0], lines[0][1]) if lines else "no row"),
              "",
              "Units: 1e%d. `ci95` = 1.96 sd/sqrt(samples), the paper's half-width; `ci95 (R)` from "
              "the R independent realisation means (Student t). Paper columns: Patterson & Wagner, "
              "Table %d." % (e, k),
              "",
              "| method | n | R | samples | t window | sample mean | sample sd | ci95 | ci95 (R) "
              "| paper mean | paper sd | paper ci95 |",
              "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|"]
        for r, i, paper in lines:
            p = paper if paper else ("", "", "")
            md.append("| %s | %d | %d | %d | [%s, %s] | %.4f | %.4g | %.3g | %s | %s | %s | %s |"
                      % (r["method"], r["n"], r["R"], int(r["count"][i, k]), fmt(r["window"][0], 3),
                         fmt(r["window"][1], 3), r["mean"][i, k] / unit, r["sd"][i, k] / unit,
                         r["ci"][i, k] / unit,
                         "%.3g" % (r["ciR"][i, k] / unit) if np.isfinite(r["ciR"][i, k]) else "",
                         *(("%g" % v) if v != "" else "" for v in p)))
        with open(os.path.join(out, name + ".md"), "w") as f:
            f.write("\n".join(md) + "\n")
        written.append(os.path.join(out, name + ".md"))

    p = os.path.join(out, "tableM0M3.csv")
    with open(p, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "n", "realisations", "samples", "M0_mean", "M0_sd", "M0_ci95",
                    "M0_ci95_realisations", "M3_mean", "M3_sd", "M3_ci95", "M3_ci95_realisations"])
        for r in rows:
            i = table_cell(r, x)
            row = [r["method"], r["n"], r["R"], int(r["count"][i, 0])]
            for k in (0, 3):
                row += [fmt(r["mean"][i, k], 8), fmt(r["sd"][i, k]), fmt(r["ci"][i, k]),
                        fmt(r["ciR"][i, k])]
            w.writerow(row)
    written.append(p)

    p = os.path.join(out, "rows.csv")
    with open(p, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["method", "kernel", "n", "V1", "realisations", "tStart", "tEnd",
                    "wallSeconds", "cpuSeconds", "jobs", "ranksPerRealisation",
                    "threadsPerRank", "folder"])
        for r in all_rows:
            t = r["timing"]
            w.writerow([r["method"], r["kernel"], r["n"], fmt(r["V1"]), r["R"], fmt(r["window"][0]),
                        fmt(r["window"][1]), fmt(t.get("wallSeconds")), fmt(t.get("cpuSeconds")),
                        t.get("jobs", ""), t.get("ranksPerRealisation", ""),
                        t.get("threadsPerRank", 1), r["dir"]])
    written.append(p)
    return written


def eq47(row, x):
    """sqrt(n var(M_{n,1}))/m_1 from inception alone: sqrt(u/(I V1 x)) (eq. 47)."""
    return np.sqrt(row["u"] / (row["I"] * row["V1"] * x))


def write_figures(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

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
            ax.plot(xl, eq47(r, xl), "k-" if fam == "SWA" else "k--", lw=1,
                    label="eq. (47), %s V1 = %g" % (fam, r["V1"]))

    def save(fig, name, title):
        fig.suptitle(title)
        fig.tight_layout(rect=(0, 0, 1, 0.95))
        p = os.path.join(out, name)
        fig.savefig(p, dpi=110)
        plt.close(fig)
        written.append(p)

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
            ax.plot(xl, analyticDuct.profile(r["analyticKind"], xl, r["I"], r["K0"], r["u"])[0],
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
        ax.plot(xl, add[0]["I"] * xl / add[0]["u"] / 1e3, "k-", lw=1, label="eq. (50)")
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


# --------------------------------------------------------------------------- checks

class Checks:
    def __init__(self):
        self.lines = []
        self.failed = 0
        self.run = 0

    def result(self, ok, text):
        self.run += 1
        self.failed += 0 if ok else 1
        self.lines.append(("check passed: " if ok else "CHECK FAILED: ") + text)

    def skip(self, text):
        self.lines.append("check skipped: " + text)


def mean_check(chk, row, i, k, ref, tol, z_ci, label):
    m = float(row["mean"][i, k])
    se, src = se_of(row, i, k)
    allowed = tol * abs(ref) + z_ci * se
    dev = m - ref
    chk.result(abs(dev) <= allowed,
               "%s %s n=%d M%d mean %.6g vs %.6g: %+.3f%% (allowed %.3f%% = tol %.3g%% + %g SE, "
               "SE %.3g from %s, R=%d)"
               % (label, row["method"], row["n"], k, m, ref, 100 * dev / ref,
                  100 * allowed / abs(ref), 100 * tol, z_ci, se, src, row["R"]))


def fit_exponent(ns, ys):
    a = np.polyfit(np.log(np.asarray(ns, float)), np.log(np.asarray(ys, float)), 1)
    return float(a[0])


def run_checks(rows, args):
    chk = Checks()
    add = [r for r in rows if r["kernel"] == "additive"]
    by = {m: sorted([r for r in add if r["method"] == m], key=lambda r: r["n"])
          for m in ("SWA", "DSA1", "DSA2")}
    swa, dsa1, dsa2 = by["SWA"], by["DSA1"], by["DSA2"]
    x = args.table_x

    if not swa:
        chk.skip("no additive-kernel SWA row")
    for r in swa:
        i = table_cell(r, x)
        mean_check(chk, r, i, 1, args.swa_m1_ref, args.swa_m1_tol, args.z_ci, "Table 1")
        mean_check(chk, r, i, 2, args.swa_m2_ref, args.swa_m2_tol, args.z_ci, "Table 2")
    if len(swa) >= 2:
        ns = [r["n"] for r in swa]
        for k in (1, 2):
            sds = [r["sd"][table_cell(r, x), k] for r in swa]
            rel_se = [r["sdSE"][table_cell(r, x), k] / r["sd"][table_cell(r, x), k] for r in swa]
            e = fit_exponent(ns, sds)
            # standard error of the fitted exponent from the sds' relative errors
            lx = np.log(np.asarray(ns, float))
            e_se = math.sqrt(sum((w * q) ** 2 for w, q in
                                 zip((lx - lx.mean()) / ((lx - lx.mean()) ** 2).sum(), rel_se)))
            allowed = args.sd_exponent_tol + args.z_ci * e_se
            chk.result(abs(e + 0.5) <= allowed,
                       "SWA sd of M%d ~ n^%.3f over n = %s (expected -0.5, allowed ± %.3g = %g + %g"
                       " SE, SE %.3g); sd = %s" % (k, e, ns, allowed, args.sd_exponent_tol, args.z_ci,
                                                  e_se, ", ".join("%.4g" % s for s in sds)))
    elif swa:
        chk.skip("sd ~ n^-1/2 needs two SWA rows")
    for r in swa:
        cells = np.arange(args.nsd_skip_cells, len(r["x"]))
        if cells.size == 0:
            raise TablesError("--nsd-skip-cells %d leaves no cell of %d" % (args.nsd_skip_cells,
                                                                            len(r["x"])))
        ref = eq47(r, r["x"][cells])
        rel = r["nsd"][cells, 1] / ref - 1
        allowed = args.nsd_tol + args.z_ci * r["sdSE"][cells, 1] / r["sd"][cells, 1]
        worst = int(np.argmax(np.abs(rel) / allowed))
        chk.result(bool(np.all(np.abs(rel) <= allowed)),
                   "SWA n=%d normalised sd of M1 vs eq. (47) in cells %d..%d: worst %+.1f%% at x=%.4g"
                   " (allowed %.1f%% = %g%% + %g SE of the sd), mean over cells %+.1f%%"
                   % (r["n"], cells[0], cells[-1], 100 * rel[worst], r["x"][cells[worst]],
                      100 * allowed[worst], 100 * args.nsd_tol, args.z_ci, 100 * float(np.mean(rel))))

    if not dsa1:
        chk.skip("no additive-kernel DSA1 row")
    for r in dsa1:
        i = table_cell(r, x)
        se, src = se_of(r, i, 1)
        z = (r["mean"][i, 1] - args.m1_exact) / se
        chk.result(z > args.z_dsa1, "DSA1 n=%d M1 mean %.6g above %.6g by %.2f SE (SE %.3g from %s,"
                   " R=%d; need > %g)" % (r["n"], r["mean"][i, 1], args.m1_exact, z, se, src, r["R"],
                                          args.z_dsa1))

    if len(dsa2) >= 2:
        lo, hi = dsa2[0], dsa2[-1]
        il, ih = table_cell(lo, x), table_cell(hi, x)
        sl, _ = se_of(lo, il, 2)
        sh, _ = se_of(hi, ih, 2)
        z = (hi["mean"][ih, 2] - lo["mean"][il, 2]) / math.hypot(sl, sh)
        chk.result(z > args.z, "DSA2 M2 mean rises from %.4g (n=%d) to %.4g (n=%d): %.2f combined SE"
                   " (need > %g)" % (lo["mean"][il, 2], lo["n"], hi["mean"][ih, 2], hi["n"], z, args.z))
        target = swa[-1]["mean"][table_cell(swa[-1], x), 2] if swa else args.swa_m2_ref
        chk.result(abs(hi["mean"][ih, 2] - target) < abs(lo["mean"][il, 2] - target),
                   "DSA2 M2 at n=%d is closer than at n=%d to the SWA value %.4g"
                   % (hi["n"], lo["n"], target))
    else:
        chk.skip("the DSA2 trend needs two DSA2 rows")
    return chk


# --------------------------------------------------------------------------- main

def parse_args(argv):
    p = argparse.ArgumentParser(prog="coagulationTables.py",
                                description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="See the module documentation (head of this file).")
    p.add_argument("--rows", nargs="+", required=True, metavar="DIR",
                   help="ensemble folders (coagulationEnsemble -out), one per method and n; "
                        "DIR1+DIR2 pools the realisations of several folders into one row")
    p.add_argument("--out", default="results", help="output folder (default: results)")
    p.add_argument("--table-x", type=float, default=0.099,
                   help="x inside the table cell (default 0.099: the cell [0.098, 0.1])")
    p.add_argument("--t-end", type=float, default=None, help="last sample time (default: all)")
    p.add_argument("--no-plots", action="store_true")
    g = p.add_argument_group("checks (exit 1 on failure)")
    g.add_argument("--check", action="store_true")
    g.add_argument("--swa-m1-ref", type=float, default=9.877e3)
    g.add_argument("--swa-m1-tol", type=float, default=0.002)
    g.add_argument("--swa-m2-ref", type=float, default=9.1e7)
    g.add_argument("--swa-m2-tol", type=float, default=0.03)
    g.add_argument("--m1-exact", type=float, default=9.90e3, help="eq. (50) at the cell centre")
    g.add_argument("--z-ci", type=float, default=0.0,
                   help="widen the SWA tolerances by this many standard errors (default 0)")
    g.add_argument("--z", type=float, default=3.0,
                   help="significance (standard errors) of the DSA2 trend check (default 3)")
    g.add_argument("--z-dsa1", type=float, default=None,
                   help="significance of the DSA1 bias check (default: --z)")
    g.add_argument("--sd-exponent-tol", type=float, default=0.1)
    g.add_argument("--nsd-tol", type=float, default=0.10)
    g.add_argument("--nsd-skip-cells", type=int, default=3)
    args = p.parse_args(argv)
    if args.nsd_skip_cells < 0:
        p.error("--nsd-skip-cells must be >= 0")
    if args.z_dsa1 is None:
        args.z_dsa1 = args.z
    for name in ("swa_m1_tol", "swa_m2_tol", "z_ci", "sd_exponent_tol", "nsd_tol"):
        if getattr(args, name) < 0:
            p.error("--%s must be >= 0" % name.replace("_", "-"))
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        rows = sort_rows([load_row(d, args.t_end) for d in args.rows])
        seen = {}
        for r in rows:
            key = (r["kernel"], r["method"], r["n"])
            if key in seen:
                raise TablesError("rows %s and %s are both %s n=%d (%s kernel)"
                                  % (seen[key], r["dir"], r["method"], r["n"], r["kernel"]))
            seen[key] = r["dir"]
        os.makedirs(args.out, exist_ok=True)
        add = [r for r in rows if r["kernel"] == "additive"]
        written = write_tables(rows, add if add else rows, args.table_x, args.out)
        if not args.no_plots:
            written += write_figures(rows, args.out)
    except TablesError as e:
        print("coagulationTables: error: %s" % e, file=sys.stderr)
        return 2
    for k in (1, 2):
        with open(os.path.join(args.out, "table%d.md" % k)) as f:
            print(f.read())
    ok = True
    if args.check:
        try:
            chk = run_checks(rows, args)
        except TablesError as e:
            print("coagulationTables: error: %s" % e, file=sys.stderr)
            return 2
        with open(os.path.join(args.out, "checks.txt"), "w") as f:
            f.write("\n".join(chk.lines) + "\n")
        print("\n".join(chk.lines))
        print("checks: %d run, %d failed" % (chk.run, chk.failed))
        if chk.run == 0:
            print("checks: none applies to these rows (the checks are for additive-kernel "
                  "SWA, DSA1 and DSA2 rows): --check fails")
        ok = chk.failed == 0 and chk.run > 0
        written.append(os.path.join(args.out, "checks.txt"))
    print("outputs:\n  " + "\n  ".join(written))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
