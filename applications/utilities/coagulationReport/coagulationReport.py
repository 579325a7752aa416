#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationReport: time-averaged moment statistics of coagulationFoam runs.

Reads the HDF5 moment samples written by the solver,

    <case>/postProcessing/coagulationSamples/*.h5   (also in sub-folders)

each holding /cellCentres [nCells][3], /time [nSamples],
/moments [nSamples][nCells][nMoments] (M_{n,k} of Patterson & Wagner eq. 37)
and the root attributes n, V1, K0, inceptionRate, seed, splitDeltaT,
sampleInterval, tRelax, algorithm, kernel.

Files of one run hold disjoint cell sets (processors) and/or different time
ranges (restarts).  Cells are merged by centre; where several files hold the
same cell at the same time, the sample of the file whose first time is latest
wins (a restart overrides what the run it restarted from wrote after the
restart time).  Cells are sorted by x.

For every cell and moment k, over the samples with t_relax <= t <= t_end
(pooled over all realisations given with --realisations; successive samples
are treated as independent, as in the paper), it reports the sample mean,
sample standard deviation, count, 95 % confidence half-width of the mean
1.96 sd / sqrt(count), and the normalised standard deviation
sqrt(n var(M_k)) / m_k (m_k the cell-averaged analytic reference where there
is one, otherwise the sample mean).

Outputs in --out (resolved against --case when relative):
  moments.csv        x, Mk_mean, Mk_ci95 for k = 0..3
  moments_full.csv   x, y, z, and per k: mean, sd, count, ci95, analytic cell
                     average, analytic value at the centre, relative error,
                     normalised standard deviation
  moments.png        m_k(x): means with 95 % CI bars and the analytic curve
  relativeError.png  (mean - analytic cell average) / analytic, with CI bars
  normalisedStdDev.png  sqrt(n var)/m_k against x, eq. (47) line for k = 1
  summary.json       run attributes, time window, files, realisations

Exit status: 0 success, 1 a --check / --check-value failed, 2 bad input
(no sample files, missing dataset, inconsistent files, bad options).

Examples:
  coagulationReport.py --case tutorials/constantDuct --check \\
      --check-rel-tol 0.03 --check-skip-cells 3 --check-moments 0,1,2,3
  coagulationReport.py --case tutorials/additiveDuct \\
      --check-cell-index -1 --check-moment 1 --check-value 9.90e3 \\
      --check-value-rel-tol 0.003
  coagulationReport.py --out pooled --realisations run_seed1 run_seed2 run_seed3
"""

import argparse
import glob
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
import analyticDuct  # noqa: E402

SAMPLE_DIR = os.path.join("postProcessing", "coagulationSamples")
DATASETS = ("cellCentres", "time", "moments")
# attributes that must agree between all files that are pooled
MUST_AGREE = ("n", "V1", "K0", "inceptionRate", "algorithm", "kernel")
Z95 = 1.96

EXIT_OK, EXIT_CHECK_FAILED, EXIT_INPUT = 0, 1, 2


class ReportError(Exception):
    """Bad input: reported on stderr, exit status 2."""


def warn(msg):
    print("coagulationReport: warning: " + msg, file=sys.stderr)


# --------------------------------------------------------------------------- input

def _attr_value(v):
    """h5py attribute -> python scalar/str."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray):
        if v.dtype.kind in "SO" or v.dtype.kind == "U":
            v = v.ravel()
            return _attr_value(v[0]) if v.size else ""
        if v.size == 1:
            return v.ravel()[0].item()
        return v.tolist()
    if isinstance(v, np.generic):
        return v.item()
    return v


def find_sample_files(case):
    d = os.path.join(case, SAMPLE_DIR)
    files = sorted(set(glob.glob(os.path.join(d, "*.h5"))
                       + glob.glob(os.path.join(d, "**", "*.h5"), recursive=True)))
    if not files:
        raise ReportError("no HDF5 sample file found: %s/*.h5 does not exist or is empty"
                          % d)
    return files


def read_sample_file(path):
    import h5py
    try:
        f = h5py.File(path, "r")
    except (OSError, IOError) as e:
        raise ReportError("cannot open %s as HDF5: %s" % (path, e))
    with f:
        missing = [d for d in DATASETS if d not in f]
        if missing:
            raise ReportError("%s lacks dataset%s %s" % (
                path, "s" if len(missing) > 1 else "", ", ".join("/" + m for m in missing)))
        attrs = {k: _attr_value(v) for k, v in f.attrs.items()}
        centres = np.asarray(f["cellCentres"][()], dtype=float)
        times = np.asarray(f["time"][()], dtype=float).ravel()
        moments = np.asarray(f["moments"][()], dtype=float)
    if centres.ndim == 1:
        centres = centres.reshape(-1, 1)
    if centres.ndim != 2:
        raise ReportError("%s: /cellCentres has shape %s, expected [nCells][3]"
                          % (path, centres.shape))
    if centres.shape[1] < 3:
        centres = np.hstack([centres, np.zeros((centres.shape[0], 3 - centres.shape[1]))])
    nc = centres.shape[0]
    if moments.ndim == 2 and nc == 1:
        moments = moments[:, None, :]
    if moments.ndim != 3 or moments.shape[0] != times.size or moments.shape[1] != nc:
        raise ReportError("%s: /moments has shape %s, expected [nSamples=%d][nCells=%d][nMoments]"
                          % (path, moments.shape, times.size, nc))
    return {"path": path, "attrs": attrs, "centres": centres[:, :3], "times": times,
            "moments": moments}


def _same(a, b):
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b))
    return str(a) == str(b)


def check_consistent(files, ref_attrs, ref_path):
    for fd in files:
        for key in MUST_AGREE:
            if key in ref_attrs and key in fd["attrs"] and not _same(ref_attrs[key], fd["attrs"][key]):
                raise ReportError("attribute '%s' differs: %r in %s but %r in %s"
                                  % (key, ref_attrs[key], ref_path, fd["attrs"][key], fd["path"]))


class Accumulator:
    """Per-cell, per-moment count / mean / sum of squared deviations, merged
    across realisations with the pairwise (Chan et al.) update."""

    def __init__(self, nmom, cell_quantum):
        self.nmom = nmom
        self.cq = cell_quantum
        self.index = {}
        self.centres = []
        self.count = np.zeros((0, nmom))
        self.mean = np.zeros((0, nmom))
        self.m2 = np.zeros((0, nmom))

    def keys(self, centres):
        q = np.round(centres / self.cq).astype(np.int64)
        return [tuple(r) for r in q]

    def cell_ids(self, centres):
        ids = np.empty(len(centres), dtype=np.int64)
        new = 0
        for i, k in enumerate(self.keys(centres)):
            j = self.index.get(k)
            if j is None:
                j = len(self.centres)
                self.index[k] = j
                self.centres.append(centres[i])
                new += 1
            ids[i] = j
        if new:
            z = np.zeros((new, self.nmom))
            self.count = np.vstack([self.count, z])
            self.mean = np.vstack([self.mean, z])
            self.m2 = np.vstack([self.m2, z])
        return ids

    def add(self, ids, data):
        """data: [nSamples][len(ids)][nmom], NaN = no sample."""
        valid = ~np.isnan(data)
        nb = valid.sum(axis=0).astype(float)
        with np.errstate(invalid="ignore", divide="ignore"):
            mb = np.where(nb > 0, np.nansum(data, axis=0) / np.maximum(nb, 1), 0.0)
            m2b = np.nansum((data - mb[None]) ** 2, axis=0)
        na, ma, m2a = self.count[ids], self.mean[ids], self.m2[ids]
        n = na + nb
        safe = np.maximum(n, 1)
        delta = mb - ma
        self.mean[ids] = np.where(n > 0, ma + delta * nb / safe, 0.0)
        self.m2[ids] = m2a + m2b + delta ** 2 * na * nb / safe
        self.count[ids] = n


def load_realisation(case, acc_holder, t_relax_opt, t_end, ref):
    """Read, merge and accumulate one run (one case directory).

    acc_holder: dict with 'acc' (Accumulator or None); ref: dict of reference
    attributes (filled by the first file seen)."""
    paths = find_sample_files(case)
    files = [read_sample_file(p) for p in paths]
    for fd in files:
        if fd["times"].size == 0:
            warn("%s holds no sample; ignored" % fd["path"])
    files = [fd for fd in files if fd["times"].size > 0]
    if not files:
        raise ReportError("no sample in the HDF5 files of %s" % case)
    if not ref:
        ref.update(files[0]["attrs"])
        ref["_path"] = files[0]["path"]
    check_consistent(files, ref, ref["_path"])

    nmom = min(fd["moments"].shape[2] for fd in files)
    if any(fd["moments"].shape[2] != nmom for fd in files):
        warn("files of %s differ in nMoments; using the first %d" % (case, nmom))

    if acc_holder.get("acc") is None:
        allc = np.vstack([fd["centres"] for fd in files])
        scale = max(float(np.ptp(allc, axis=0).max()) if allc.size else 0.0,
                    float(np.abs(allc).max()) if allc.size else 0.0, 1e-30)
        acc_holder["acc"] = Accumulator(nmom, 1e-9 * scale)
    acc = acc_holder["acc"]
    if nmom < acc.nmom:
        raise ReportError("%s has %d moments, earlier runs %d" % (case, nmom, acc.nmom))

    # time window
    attrs = files[0]["attrs"]
    t_relax = t_relax_opt
    if t_relax is None:
        t_relax = float(attrs.get("tRelax", 0.0) or 0.0)
        for fd in files:
            tr = fd["attrs"].get("tRelax")
            if tr is not None and not _same(float(tr), t_relax):
                warn("tRelax differs between files (%g in %s); using %g"
                     % (tr, fd["path"], t_relax))
                break
    dt_s = float(attrs.get("sampleInterval", 0.0) or 0.0)
    tmax = max(float(np.abs(fd["times"]).max()) for fd in files)
    tq = dt_s * 1e-6 if dt_s > 0 else 1e-12 * max(1.0, tmax)
    eps = 0.5 * tq
    lo = t_relax - eps
    hi = (t_end + eps) if t_end is not None else np.inf

    # union of cells and of in-window times of this run
    ids_per_file = [acc.cell_ids(fd["centres"]) for fd in files]
    run_cells = np.unique(np.concatenate(ids_per_file))
    col_of = {int(c): i for i, c in enumerate(run_cells)}
    tkeys_per_file, inwin_per_file = [], []
    for fd in files:
        w = (fd["times"] >= lo) & (fd["times"] <= hi)
        inwin_per_file.append(w)
        tkeys_per_file.append(np.round(fd["times"][w] / tq).astype(np.int64))
    all_keys = np.unique(np.concatenate(tkeys_per_file))
    data = np.full((all_keys.size, run_cells.size, acc.nmom), np.nan)
    # restarts: files with a later first time overwrite earlier ones
    order = sorted(range(len(files)), key=lambda i: (float(files[i]["times"][0]), files[i]["path"]))
    for i in order:
        fd = files[i]
        if tkeys_per_file[i].size == 0:
            continue
        rows = np.searchsorted(all_keys, tkeys_per_file[i])
        cols = np.array([col_of[int(c)] for c in ids_per_file[i]], dtype=np.int64)
        data[np.ix_(rows, cols)] = fd["moments"][inwin_per_file[i]][:, :, :acc.nmom]
    acc.add(run_cells, data)

    nvalid = (~np.isnan(data[:, :, 0])).sum(axis=0) if data.size else np.zeros(0)
    seeds = sorted({fd["attrs"].get("seed") for fd in files if fd["attrs"].get("seed") is not None},
                   key=str)
    t_all = np.concatenate([fd["times"] for fd in files])
    return {
        "case": case,
        "files": [fd["path"] for fd in files],
        "seeds": seeds,
        "tRelax": t_relax,
        "tEnd": t_end,
        "timeRange": [float(t_all.min()), float(t_all.max())],
        "nCells": int(run_cells.size),
        "samplesPerCell": [int(nvalid.min()) if nvalid.size else 0,
                           int(nvalid.max()) if nvalid.size else 0],
    }


# --------------------------------------------------------------------------- statistics

def compute(args):
    cases = args.realisations if args.realisations else [args.case]
    holder, ref, runs = {}, {}, []
    for c in cases:
        runs.append(load_realisation(c, holder, args.t_relax, args.t_end, ref))
    acc = holder["acc"]
    centres = np.array(acc.centres)
    order = np.lexsort((centres[:, 2], centres[:, 1], centres[:, 0]))
    centres = centres[order]
    count = acc.count[order]
    mean = np.where(count > 0, acc.mean[order], np.nan)
    with np.errstate(invalid="ignore", divide="ignore"):
        var = np.where(count > 1, acc.m2[order] / np.maximum(count - 1, 1), np.nan)
        sd = np.sqrt(var)
        ci = Z95 * sd / np.sqrt(count)
    empty = int((count[:, 0] == 0).sum())
    if empty == len(count):
        raise ReportError("no sample with %s <= t <= %s in any cell"
                          % (runs[0]["tRelax"], "inf" if args.t_end is None else args.t_end))
    if empty:
        warn("%d cell(s) have no sample in the time window" % empty)

    # duplicate seeds across realisations are not independent
    if len(runs) > 1:
        seen = {}
        for r in runs:
            for s in r["seeds"]:
                if s in seen:
                    warn("seed %r appears in both %s and %s: realisations not independent"
                         % (s, seen[s], r["case"]))
                seen.setdefault(s, r["case"])

    def num(key, default=None):
        v = ref.get(key, default)
        try:
            return float(v)
        except (TypeError, ValueError):
            return default

    meta = {
        "algorithm": str(ref.get("algorithm", "?")),
        "kernel": str(ref.get("kernel", "?")),
        "n": num("n"),
        "V1": num("V1"),
        "K0": num("K0"),
        "inceptionRate": num("inceptionRate"),
        "splitDeltaT": num("splitDeltaT"),
        "sampleInterval": num("sampleInterval"),
        "u": args.u if args.u is not None else num("u", 1.0),
        "xInlet": args.x_inlet,
        "realisations": len(runs),
        "runs": runs,
    }

    # analytic reference
    kind = args.analytic
    if kind == "auto":
        kind = analyticDuct.kind_for_kernel(meta["kernel"])
        if kind is None:
            print("no analytic reference for kernel '%s'" % meta["kernel"])
    elif kind == "none":
        kind = None
    elif analyticDuct.kind_for_kernel(meta["kernel"]) not in (None, kind):
        warn("--analytic %s but the runs used the '%s' kernel" % (kind, meta["kernel"]))
    if kind is not None:
        for key in ("inceptionRate", "K0"):
            if meta[key] is None:
                raise ReportError("analytic reference %s needs the attribute '%s'" % (kind, key))
    meta["analytic"] = kind

    x = centres[:, 0]
    nm = count.shape[1]
    ana_avg = np.full((len(x), nm), np.nan)
    ana_ctr = np.full((len(x), nm), np.nan)
    lo = hi = None
    if kind is not None:
        I, K0, u = meta["inceptionRate"], meta["K0"], meta["u"]
        lo, hi = analyticDuct.cell_edges(x, args.x_inlet)
        k = min(nm, analyticDuct.N_MOMENTS)
        ana_avg[:, :k] = analyticDuct.cell_average(kind, lo, hi, I, K0, u, args.x_inlet).T[:, :k]
        ana_ctr[:, :k] = analyticDuct.profile(kind, x - args.x_inlet, I, K0, u).T[:, :k]
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = (mean - ana_avg) / ana_avg
        norm_ref = np.where(np.isfinite(ana_avg), ana_avg, mean)
        nsd = np.sqrt(meta["n"] * var) / norm_ref if meta["n"] else np.full_like(var, np.nan)

    return {
        "meta": meta, "centres": centres, "x": x, "count": count, "mean": mean,
        "sd": sd, "ci": ci, "var": var, "analytic": ana_avg, "analyticCentre": ana_ctr,
        "rel": rel, "nsd": nsd, "edges": (lo, hi),
    }


# --------------------------------------------------------------------------- output

def fmt(v):
    return "nan" if not np.isfinite(v) else "%.12g" % v


def write_csv(res, out):
    nm = res["mean"].shape[1]
    p1 = os.path.join(out, "moments.csv")
    with open(p1, "w") as f:
        f.write("x," + ",".join("M%d_mean,M%d_ci95" % (k, k) for k in range(nm)) + "\n")
        for i, x in enumerate(res["x"]):
            f.write(fmt(x) + "," + ",".join(
                fmt(res["mean"][i, k]) + "," + fmt(res["ci"][i, k]) for k in range(nm)) + "\n")
    p2 = os.path.join(out, "moments_full.csv")
    cols = ("mean", "sd", "count", "ci95", "analytic", "analyticCentre", "relErr", "normStdDev")
    keys = ("mean", "sd", "count", "ci", "analytic", "analyticCentre", "rel", "nsd")
    with open(p2, "w") as f:
        f.write("x,y,z," + ",".join("M%d_%s" % (k, c) for k in range(nm) for c in cols) + "\n")
        for i, c in enumerate(res["centres"]):
            row = [fmt(v) for v in c]
            for k in range(nm):
                for key in keys:
                    v = res[key][i, k]
                    row.append("%d" % v if key == "count" else fmt(v))
            f.write(",".join(row) + "\n")
    return [p1, p2]


def write_summary(res, out, args):
    meta = dict(res["meta"])
    meta["tRelax"] = meta["runs"][0]["tRelax"]
    meta["tEnd"] = args.t_end
    meta["samplesPerCell"] = [int(res["count"][:, 0].min()), int(res["count"][:, 0].max())]
    meta["nCells"] = int(len(res["x"]))
    p = os.path.join(out, "summary.json")
    with open(p, "w") as f:
        json.dump(meta, f, indent=2, default=str)
        f.write("\n")
    return p


MOMENT_NAMES = ("number density", "mass", "second moment", "third moment")
EQ_LABELS = {"constantDuct": ("eq. 39", "eq. 41", "eq. 43", "eq. 45"),
             "additiveDuct": ("moment ODE", "eq. 50", "moment ODE", "moment ODE")}


def title_of(meta, t_relax, t_end):
    n = meta["n"]
    ns = ("%d" % n) if n is not None and float(n).is_integer() else str(n)
    t = "%s, n = %s, %s kernel" % (meta["algorithm"], ns, meta["kernel"])
    r = meta["realisations"]
    t += ", %d realisation%s" % (r, "" if r == 1 else "s")
    t += ", t in [%g, %s]" % (t_relax, "end" if t_end is None else "%g" % t_end)
    return t


def write_plots(res, out, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    meta = res["meta"]
    kind = meta["analytic"]
    x = res["x"]
    nm = min(res["mean"].shape[1], 4)
    title = title_of(meta, meta["runs"][0]["tRelax"], args.t_end)
    paths = []
    fine = None
    if kind is not None:
        lo, hi = res["edges"]
        xa = np.linspace(max(args.x_inlet, float(np.min(lo))), float(np.max(hi)), 400)
        fine = (xa, analyticDuct.profile(kind, xa - args.x_inlet, meta["inceptionRate"],
                                         meta["K0"], meta["u"]))
    xlabel = "x (cell centre)"

    # moments
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5), squeeze=False)
    for k in range(4):
        ax = axes[k // 2][k % 2]
        if k >= nm:
            ax.set_visible(False)
            continue
        ax.errorbar(x, res["mean"][:, k], yerr=res["ci"][:, k], fmt="o", ms=3, capsize=2,
                    color="C0", label="sample mean ± 95 % CI")
        if fine is not None:
            ax.plot(fine[0], fine[1][k], "k-", lw=1, label="analytic (%s)" % EQ_LABELS[kind][k])
        ax.set_xlabel(xlabel)
        ax.set_ylabel(r"$m_{%d}(x)$" % k)
        ax.set_title("k = %d (%s)" % (k, MOMENT_NAMES[k]))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    fig.suptitle("Mass moments: " + title)
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    p = os.path.join(out, "moments.png")
    fig.savefig(p, dpi=110)
    plt.close(fig)
    paths.append(p)

    # relative error to the analytic cell average
    if kind is not None:
        fig, axes = plt.subplots(2, 2, figsize=(12, 8.5), squeeze=False)
        for k in range(4):
            ax = axes[k // 2][k % 2]
            if k >= nm:
                ax.set_visible(False)
                continue
            a = res["analytic"][:, k]
            with np.errstate(invalid="ignore", divide="ignore"):
                ax.errorbar(x, 100 * res["rel"][:, k], yerr=100 * res["ci"][:, k] / np.abs(a),
                            fmt="o", ms=3, capsize=2, color="C0",
                            label="(mean − analytic)/analytic ± 95 % CI")
            ax.axhline(0.0, color="k", lw=1)
            if args.check:
                for s in (-1, 1):
                    ax.axhline(100 * s * args.check_rel_tol, color="C3", ls="--", lw=1,
                               label="check tolerance" if s > 0 else None)
            ax.set_xlabel(xlabel)
            ax.set_ylabel(r"relative error of $M_{n,%d}$ [%%]" % k)
            ax.set_title("k = %d (%s), analytic cell average" % (k, MOMENT_NAMES[k]))
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=8, loc="best")
        fig.suptitle("Relative error: " + title)
        fig.tight_layout(rect=(0, 0, 1, 0.96))
        p = os.path.join(out, "relativeError.png")
        fig.savefig(p, dpi=110)
        plt.close(fig)
        paths.append(p)

    # normalised standard deviation
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5), squeeze=False)
    refname = "analytic m_k" if kind is not None else "sample mean"
    for k in range(4):
        ax = axes[k // 2][k % 2]
        if k >= nm:
            ax.set_visible(False)
            continue
        y = res["nsd"][:, k]
        ax.plot(x, y, "o", ms=3, color="C0", label="simulation")
        if k == 1 and meta["inceptionRate"] and meta["V1"]:
            I, V1, u = meta["inceptionRate"], meta["V1"], meta["u"]
            xe = x[x > args.x_inlet]
            if xe.size:
                xl = np.linspace(float(xe.min()), float(xe.max()), 300)
                ax.plot(xl, np.sqrt(u / (I * V1 * (xl - args.x_inlet))), "k-", lw=1,
                        label=r"eq. (47): $\sqrt{u/(I V_1 x)}$")
        yf = y[np.isfinite(y)]
        if k == 1 and yf.size and meta["inceptionRate"] and meta["V1"]:
            yf = np.concatenate([yf, ax.get_lines()[-1].get_ydata()])
        if yf.size and np.all(yf > 0) and yf.max() > 10 * yf.min():
            ax.set_yscale("log")   # only when the values span more than a decade
        ax.set_xlabel(xlabel)
        ax.set_ylabel(r"$\sqrt{n\,\mathrm{var}(M_{n,%d})}\,/\,m_{%d}(x)$" % (k, k))
        ax.set_title("k = %d (%s)" % (k, MOMENT_NAMES[k]))
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="best")
    fig.suptitle("Normalised standard deviation (m_k = %s): %s" % (refname, title))
    fig.tight_layout(rect=(0, 0, 1, 0.96))
    p = os.path.join(out, "normalisedStdDev.png")
    fig.savefig(p, dpi=110)
    plt.close(fig)
    paths.append(p)
    return paths


def print_table(res, args):
    meta = res["meta"]
    nm = res["mean"].shape[1]
    print(title_of(meta, meta["runs"][0]["tRelax"], args.t_end))
    print("analytic reference: %s%s" % (meta["analytic"] or "none",
                                        " (relative error to the cell average)"
                                        if meta["analytic"] else ""))
    head = "%4s %11s %6s" % ("cell", "x", "count")
    for k in range(nm):
        head += "  %-30s" % ("M%d mean ± ci95 (rel.err)" % k)
    print(head)
    for i, x in enumerate(res["x"]):
        line = "%4d %11.5g %6d" % (i, x, res["count"][i, 0])
        for k in range(nm):
            r = res["rel"][i, k]
            rs = "(%+.2f%%)" % (100 * r) if np.isfinite(r) else ""
            line += "  %-30s" % ("%.4e ± %.1e %s" % (res["mean"][i, k], res["ci"][i, k], rs))
        print(line)


# --------------------------------------------------------------------------- checks

def run_checks(res, args):
    ok = True
    nm = res["mean"].shape[1]
    ncell = len(res["x"])
    if args.check:
        if res["meta"]["analytic"] is None:
            raise ReportError("--check needs an analytic reference (kernel '%s', --analytic %s)"
                              % (res["meta"]["kernel"], args.analytic))
        moments = args.check_moments if args.check_moments is not None else \
            list(range(min(nm, analyticDuct.N_MOMENTS)))
        for k in moments:
            if k < 0 or k >= min(nm, analyticDuct.N_MOMENTS):
                raise ReportError("--check-moments: no moment %d" % k)
        nfail = ntested = 0
        for i in range(args.check_skip_cells, ncell):
            for k in moments:
                ntested += 1
                m, a, r, c = res["mean"][i, k], res["analytic"][i, k], res["rel"][i, k], res["ci"][i, k]
                if not (np.isfinite(r) and abs(r) <= args.check_rel_tol):
                    nfail += 1
                    print("CHECK FAILED cell %d x=%.6g M%d: mean %.6e analytic %.6e rel.err %+.3f%% "
                          "(tol %.3g%%) ci95 %.3e" % (i, res["x"][i], k, m, a, 100 * r,
                                                     100 * args.check_rel_tol, c))
        if nfail:
            ok = False
            print("check: %d of %d cell moments outside the relative tolerance %g"
                  % (nfail, ntested, args.check_rel_tol))
        else:
            print("check passed: %d cell moments (cells %d..%d, moments %s) within relative "
                  "tolerance %g of the analytic cell averages"
                  % (ntested, args.check_skip_cells, ncell - 1,
                     ",".join(map(str, moments)), args.check_rel_tol))

    for ci_, k, v, tol in args.value_checks:
        if not (-ncell <= ci_ < ncell):
            raise ReportError("--check-cell-index %d: only %d cells" % (ci_, ncell))
        if not (0 <= k < nm):
            raise ReportError("--check-moment %d: the files hold moments 0..%d" % (k, nm - 1))
        i = ci_ % ncell
        m, c = res["mean"][i, k], res["ci"][i, k]
        r = (m - v) / abs(v) if v != 0 else (m - v)
        good = bool(np.isfinite(r) and abs(r) <= tol)
        print("%s cell %d x=%.6g M%d: mean %.6e ± %.3e expected %.6e rel.err %+.3f%% (tol %.3g%%)"
              % ("check passed:" if good else "CHECK FAILED", i, res["x"][i], k, m, c, v,
                 100 * r, 100 * tol))
        ok = ok and good
    return ok


# --------------------------------------------------------------------------- main

def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="coagulationReport.py",
        description="Time-averaged moment statistics, analytic comparison and plots for "
                    "coagulationFoam sample files (<case>/postProcessing/coagulationSamples/*.h5).",
        epilog="Exit status: 0 ok, 1 a check failed, 2 bad input or options.")
    p.add_argument("--case", default=".", help="case directory (default: .)")
    p.add_argument("--realisations", nargs="+", metavar="DIR",
                   help="several case directories (independent seeds) whose samples are pooled; "
                        "replaces --case as the data source")
    p.add_argument("--t-relax", type=float, default=None,
                   help="first sample time used (default: the files' tRelax attribute)")
    p.add_argument("--t-end", type=float, default=None, help="last sample time used (default: all)")
    p.add_argument("--u", type=float, default=None,
                   help="advection speed of the analytic duct (default: attribute u, else 1.0)")
    p.add_argument("--x-inlet", type=float, default=0.0,
                   help="x of the duct inlet, where the analytic moments vanish (default 0)")
    p.add_argument("--out", default="results",
                   help="output folder; a relative path is taken inside --case (default: results)")
    p.add_argument("--analytic", default="auto",
                   choices=("auto",) + analyticDuct.KINDS + ("none",),
                   help="analytic reference (auto: from the kernel attribute)")
    p.add_argument("--no-plots", action="store_true", help="skip the PNG files")
    g = p.add_argument_group("checks (exit 1 on failure)")
    g.add_argument("--check", action="store_true",
                   help="compare every cell mean with the analytic cell average")
    g.add_argument("--check-rel-tol", type=float, default=0.03,
                   help="--check: largest allowed |mean - analytic|/analytic (default 0.03)")
    g.add_argument("--check-skip-cells", type=int, default=0,
                   help="--check: ignore this many cells at the inlet (default 0)")
    g.add_argument("--check-moments", type=lambda s: [int(t) for t in s.split(",") if t.strip()],
                   default=None, help="--check: comma-separated moment orders (default: all)")
    g.add_argument("--check-cell-index", type=int, action="append", metavar="I",
                   help="cell index (sorted by x; negative counts from the outlet) of a "
                        "--check-value; once for all values or once per value")
    g.add_argument("--check-moment", type=int, action="append", metavar="K",
                   help="moment order of a --check-value; once for all or once per value")
    g.add_argument("--check-value", type=float, action="append", metavar="V",
                   help="expected cell mean; repeatable")
    g.add_argument("--check-value-rel-tol", type=float, action="append", metavar="TOL",
                   help="relative tolerance of a --check-value; once for all or once per value "
                        "(default 0.01)")
    args = p.parse_args(argv)
    if args.check_skip_cells < 0:
        p.error("--check-skip-cells must be >= 0")
    if args.check_rel_tol <= 0:
        p.error("--check-rel-tol must be > 0")

    # single-value checks: --check-cell-index / --check-moment / --check-value-rel-tol
    # given once apply to every --check-value, otherwise once per value, in order
    args.value_checks = []
    if args.check_value:
        nv = len(args.check_value)

        def spread(lst, name, default=None):
            if not lst:
                if default is None:
                    p.error("--check-value needs %s" % name)
                return [default] * nv
            if len(lst) == 1:
                return lst * nv
            if len(lst) != nv:
                p.error("%s given %d times for %d --check-value (give it once or once per value)"
                        % (name, len(lst), nv))
            return lst

        args.value_checks = list(zip(spread(args.check_cell_index, "--check-cell-index"),
                                     spread(args.check_moment, "--check-moment"),
                                     args.check_value,
                                     spread(args.check_value_rel_tol, "--check-value-rel-tol", 0.01)))
    else:
        for name in ("check_cell_index", "check_moment", "check_value_rel_tol"):
            if getattr(args, name):
                p.error("--%s without --check-value" % name.replace("_", "-"))
    return args


def main(argv=None):
    try:  # behave like a normal filter under `| head`
        import signal
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    except (ImportError, AttributeError, ValueError):
        pass
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        res = compute(args)
        out = args.out if os.path.isabs(args.out) else os.path.join(args.case, args.out)
        os.makedirs(out, exist_ok=True)
        print_table(res, args)
        written = write_csv(res, out)
        written.append(write_summary(res, out, args))
        if not args.no_plots:
            written += write_plots(res, out, args)
        ok = run_checks(res, args)
    except ReportError as e:
        print("coagulationReport: error: %s" % e, file=sys.stderr)
        return EXIT_INPUT
    print("samples: %d realisation(s), %d cells, %d..%d samples per cell"
          % (res["meta"]["realisations"], len(res["x"]), res["count"][:, 0].min(),
             res["count"][:, 0].max()))
    print("outputs:")
    for w in written:
        print("  " + w)
    return EXIT_OK if ok else EXIT_CHECK_FAILED


if __name__ == "__main__":
    sys.exit(main())
