# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Rows of Patterson & Wagner's Tables 1 and 2 from ensembles of runs
(coagulationTables): one row per method and statistical weight n, its
realisations pooled, and the tables' CSV and markdown.

Each row holds, per cell and moment:
  mean     sample mean of M_{n,k} over all samples of all realisations
  sd       sample standard deviation of those samples
  ci       1.96 sd / sqrt(samples): the paper's half-width, which treats
           successive samples as independent
  ciR      the half-width from the R independent realisation means
           (Student t, R-1 degrees of freedom; NaN when R < 2)
"""

import csv
import json
import math
import os

import numpy as np

from . import report, samples, statistics
from .samples import InputError

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


# --------------------------------------------------------------------------- rows

def _timing(parts):
    """ensemble.json of the folders pooled into a row; wall and core seconds add up,
    and a row pooled from folders of which one lacks it has none."""
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
            return {}
    return timing


def load_row(row_dir, t_end):
    """Per-realisation statistics of one ensemble, pooled. "DIR1+DIR2+..." pools the
    realisations of several ensembles of the same method and n (a row grown over several
    studies); their seeds must all differ, and their wall and core seconds add up."""
    parts = row_dir.split("+")
    dirs = [d for part in parts for d in samples.realisation_dirs(part)]
    per = []
    for d in dirs:
        try:
            per.append(report.compute([d], t_end=t_end))
        except InputError as e:
            raise InputError("%s: %s" % (d, e))
    meta = per[0]["meta"]
    for p, d in zip(per[1:], dirs[1:]):
        for key in ("algorithm", "kernel", "n", "V1", "K0", "inceptionRate"):
            if not samples.same(p["meta"][key], meta[key]):
                raise InputError("%s: attribute %s = %r differs from %r in %s"
                                 % (d, key, p["meta"][key], meta[key], dirs[0]))
        if p["x"].shape != per[0]["x"].shape or not np.allclose(p["x"], per[0]["x"]):
            raise InputError("%s: cells differ from those of %s" % (d, dirs[0]))
    seeds = [s for p in per for r in p["meta"]["runs"] for s in r["seeds"]]
    if len(set(map(str, seeds))) != len(seeds):
        raise InputError("%s: realisations share seeds %s; they are not independent"
                         % (row_dir, seeds))

    # pool: per realisation count c, mean m, variance v  [R][cells][k]
    m = np.array([p["mean"] for p in per])
    v = np.nan_to_num(np.array([p["var"] for p in per]))
    n_tot, mean, m2 = statistics.pool(statistics.group_of(p["count"], p["mean"], p["var"])
                                      for p in per)
    pooled = statistics.summary(n_tot, mean, m2)
    sd, var = pooled["sd"], pooled["var"]
    R = len(per)
    sd_se = statistics.standard_error_of_sd(np.sqrt(v), sd, n_tot)
    se_R, ci_R = statistics.standard_error_from_realisations(m)
    res0 = per[0]
    windows = [(r["tRelax"], r["timeRange"][1] if t_end is None else min(t_end, r["timeRange"][1]))
               for p in per for r in p["meta"]["runs"]]
    nsd = statistics.normalised_sd(meta["n"], var, res0["analytic"], pooled["mean"])
    return {
        "dir": row_dir, "method": meta["algorithm"], "kernel": meta["kernel"], "n": int(meta["n"]),
        "V1": meta["V1"], "I": meta["inceptionRate"], "K0": meta["K0"], "u": meta["u"],
        "analyticKind": meta["analytic"], "R": R, "x": res0["x"], "edges": res0["edges"],
        "analytic": res0["analytic"], "count": n_tot, "mean": pooled["mean"], "sd": sd,
        "var": var, "ci": pooled["ci"], "seR": se_R, "ciR": ci_R, "sdSE": sd_se,
        "realisationMeans": m, "nsd": nsd, "window": (min(w[0] for w in windows),
                                                       max(w[1] for w in windows)),
        "timing": _timing(parts),
    }


def load_rows(row_dirs, t_end):
    """load_row of each folder, sorted (method, n); two rows of one kernel, method and
    n are an error."""
    rows = sort_rows([load_row(d, t_end) for d in row_dirs])
    seen = {}
    for r in rows:
        key = (r["kernel"], r["method"], r["n"])
        if key in seen:
            raise InputError("rows %s and %s are both %s n=%d (%s kernel)"
                             % (seen[key], r["dir"], r["method"], r["n"], r["kernel"]))
        seen[key] = r["dir"]
    return rows


def sort_rows(rows):
    return sorted(rows, key=lambda r: (METHOD_ORDER.get(r["method"], 9), r["method"], r["n"]))


def table_cell(row, x):
    """Index of the cell holding x (the last one when x is on a face)."""
    lo, hi = row["edges"]
    if lo is None:
        return int(np.argmin(np.abs(row["x"] - x)))
    inside = np.nonzero((lo <= x) & (x <= hi))[0]
    if inside.size == 0:
        raise InputError("no cell of %s holds x = %g (cells span [%g, %g])"
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
