# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Per-cell moment statistics of one case, or of realisations pooled, against the
analytic duct reference; their CSV, JSON and text table (coagulationReport).

For every cell and moment k, over the samples with t_relax <= t <= t_end (pooled
over all realisations): sample mean, sample standard deviation, count, the 95 %
confidence half-width of the mean (ci), and the normalised standard deviation
sqrt(n var(M_k)) / m_k (m_k the cell-averaged analytic reference where there is
one, otherwise the sample mean).  Cells are sorted by x.

Successive samples of a run are correlated (over up to the residence time
upstream of the cell), so ci is not the paper's 1.96 sd / sqrt(count) (kept as
ciIid):
  one run (R = 1): statistics.correlated_interval of the run's ordered time
      series: integrated autocorrelation time tau_int (Sokal's window, widened to
      the residence time upstream of the cell where that gives a larger tau_int),
      effective sample size n_eff and t_{0.975, nu} sqrt(var(mean));
  R >= 2 realisations: t_{0.975, R-1} sd(realisation means) / sqrt(R)
      (statistics.standard_error_from_realisations), which needs no model of the
      time correlation; neff is then the sum of the runs' n_eff and tauInt the
      runs' mean tau_int.
"""

import json
import os

import numpy as np

from . import analytic, samples, statistics
from .samples import InputError, warn

MOMENT_NAMES = ("number density", "mass", "second moment", "third moment")
EQ_LABELS = {"constantDuct": ("eq. 39", "eq. 41", "eq. 43", "eq. 45"),
             "additiveDuct": ("moment ODE", "eq. 50", "moment ODE", "moment ODE")}


def cell_order(centres):
    """The rows' order: cells by x, then y, then z, the keys rounded to 1e-9 of the mesh's
    extent, so that the cells of one column sort by y whatever the round-off of their x (a
    decomposed mesh's centres differ from the serial mesh's in the last bits; sorted on the raw
    centres, the rows of a serial and a decomposed run differed in order)."""
    centres = np.asarray(centres, dtype=float).reshape(-1, 3)
    span = float(np.ptp(centres, axis=0).max()) if len(centres) else 0.0
    key = np.round(centres / (1e-9 * span)) if span > 0 else centres
    return np.lexsort((key[:, 2], key[:, 1], key[:, 0]))


def _min_window(ref, x, u, x_inlet, correlation_time):
    """Smallest autocorrelation window (samples) of each cell: correlation_time
    seconds / sampleInterval; correlation_time None: the residence time upstream of
    the cell, (x - x_inlet)/u (u: the option, else the attribute u, else 1)."""
    try:
        dt = float(ref.get("sampleInterval", 0) or 0)
    except (TypeError, ValueError):
        dt = 0.0
    if dt <= 0 or correlation_time == 0:
        return 0
    if correlation_time is None:
        try:
            uu = float(u if u is not None else ref.get("u", 1.0))
        except (TypeError, ValueError):
            uu = 1.0
        t = np.maximum(x - x_inlet, 0.0) / abs(uu) if uu else np.zeros_like(x)
    else:
        t = np.full(len(x), float(correlation_time))
    return np.ceil(t / dt - 1e-9).astype(int)[:, None]


def compute(cases, t_relax=None, t_end=None, u=None, x_inlet=0.0, analytic_kind="auto",
            correlation_time=None):
    """Statistics of the runs in `cases` (case directories, pooled).

    t_relax None: the files' tRelax; t_end None: all samples; u None: attribute u,
    else 1.0; analytic_kind "auto" (from the kernel attribute), "none" or one of
    analytic.KINDS; correlation_time: the smallest window of the autocorrelation sum
    in seconds (None: the residence time upstream of each cell, 0: Sokal's alone).
    Returns a dict of per-cell arrays [cells][moments] (count,
    mean, sd, var, ci, analytic, analyticCentre, rel, nsd), x, centres, the cell
    edges and meta (run attributes, realisations, the reference used)."""
    reader, acc, runs, per_run = samples.RunReader(), None, [], []
    for c in cases:
        ids, data, info = reader.read(c, t_relax, t_end)
        if acc is None:
            acc = statistics.Accumulator(reader.nmom)
        acc.add(ids, data)
        runs.append(info)
        # the run's ordered time series: its own mean, n_eff, interval and tau_int
        xs = np.array(reader.cells.centres)[ids, 0] if len(ids) else np.zeros(0)
        window = _min_window(reader.ref, xs, u, x_inlet, correlation_time)
        r = statistics.correlated_interval_masked(data, min_window=window)
        per_run.append((ids, r + mean_mass_interval(data, r[0], window)))
    ref = reader.ref
    centres = np.array(reader.cells.centres)
    order = cell_order(centres)
    centres = centres[order]
    count = acc.count[order]
    st = statistics.summary(count, acc.mean[order], acc.m2[order])
    mean, var, sd, ci_iid = st["mean"], st["var"], st["sd"], st["ci"]
    ncells, nmom = len(reader.cells), reader.nmom
    run_arrays = []                       # per run: mean, neff, ci, tau [cells][moments]
    ratio_arrays = []                     # per run: the mean mass and its ci [cells]
    for ids, r in per_run:
        full = [np.full((ncells, nmom), np.nan) for _ in range(4)]
        for f, v in zip(full, r[:4]):
            f[ids] = v
        run_arrays.append([f[order] for f in full])
        ratio = [np.full(ncells, np.nan) for _ in range(2)]
        for f, v in zip(ratio, r[4:]):
            f[ids] = v
        ratio_arrays.append([f[order] for f in ratio])
    R = len(per_run)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean_mass = np.where(acc.mean[order][:, 0] > 0,
                             acc.mean[order][:, 1] / acc.mean[order][:, 0], np.nan)
    if R == 1:
        _, neff, ci, tau = run_arrays[0]
        mean_mass_ci = ratio_arrays[0][1]
        interval = ("one run: t_{0.975, N/(2M+1)} sqrt(var(mean)), var(mean) = 2 tau_int "
                    "gamma0/(N-2M-1), n_eff = sd^2/var(mean), tau_int the integrated "
                    "autocorrelation time summed over M lags (Sokal window c = %g)"
                    % statistics.SOKAL_C)
        interval += "; window at least %s" % (
            "the residence time (x - xInlet)/u" if correlation_time is None
            else "%g s" % correlation_time)
    else:
        _, ci = statistics.standard_error_from_realisations(np.array([a[0] for a in run_arrays]))
        _, mean_mass_ci = statistics.standard_error_from_realisations(
            np.array([a[0] for a in ratio_arrays]))
        neff = np.sum([a[1] for a in run_arrays], axis=0)
        tau = np.mean([a[3] for a in run_arrays], axis=0)
        interval = ("%d realisations: t_{0.975, R-1} sd(realisation means) / sqrt(R)" % R)
    if os.environ.get("COAGULATIONPOST_IID_INTERVAL") == "1":   # tests: the correction removed
        ci = ci_iid
    empty = int((count[:, 0] == 0).sum())
    if empty == len(count):
        raise InputError("no sample with %s <= t <= %s in any cell"
                         % (runs[0]["tRelax"], "inf" if t_end is None else t_end))
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
        "u": u if u is not None else num("u", 1.0),
        "xInlet": x_inlet,
        "realisations": len(runs),
        "density": num("density"),
        "massUnit": num("massUnit"),
        "growthTotals": samples.largest_totals(r.get("growthTotals", {}) for r in runs),
        "interval": interval,
        "runs": runs,
    }

    # analytic reference: by default (auto) the duct reference of the kernel where the runs
    # are the paper's duct case, none elsewhere, and why; a kind given is drawn whatever the
    # case, with a warning where the runs are not that case
    why = analytic.not_the_papers_duct({**ref, **meta["growthTotals"]}) or lighter_than_unit(
        acc.mean[order], centres)
    meta["analyticMismatch"] = why
    kind = analytic_kind
    if kind == "auto":
        kind = None if why else analytic.kind_for_kernel(meta["kernel"])
        if why:
            print("no analytic reference: %s" % why)
    elif kind == "none":
        kind = None
    elif analytic.kind_for_kernel(meta["kernel"]) not in (None, kind):
        warn("--analytic %s but the runs used the '%s' kernel" % (kind, meta["kernel"]))
    elif why:
        warn("--analytic %s although %s" % (kind, why))
    if kind is not None:
        for key in ("inceptionRate", "K0"):
            if meta[key] is None:
                raise InputError("analytic reference %s needs the attribute '%s'" % (kind, key))
    meta["analytic"] = kind

    x = centres[:, 0]
    nm = count.shape[1]
    ana_avg = np.full((len(x), nm), np.nan)
    ana_ctr = np.full((len(x), nm), np.nan)
    lo = hi = None
    if kind is not None:
        I, K0, uu = meta["inceptionRate"], meta["K0"], meta["u"]
        lo, hi = analytic.cell_edges(x, x_inlet)
        k = min(nm, analytic.N_MOMENTS)
        ana_avg[:, :k] = analytic.cell_average(kind, lo, hi, I, K0, uu, x_inlet).T[:, :k]
        ana_ctr[:, :k] = analytic.profile(kind, x - x_inlet, I, K0, uu).T[:, :k]
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = (mean - ana_avg) / ana_avg
    nsd = statistics.normalised_sd(meta["n"], var, ana_avg, mean)

    return {
        "meta": meta, "centres": centres, "x": x, "count": count, "mean": mean,
        "sd": sd, "ci": ci, "ciIid": ci_iid, "neff": neff, "tauInt": tau, "var": var, "analytic": ana_avg, "analyticCentre": ana_ctr,
        "rel": rel, "nsd": nsd, "edges": (lo, hi), "meanMass": mean_mass,
        "meanMassCi": mean_mass_ci,
    }


def lighter_than_unit(mean, centres, below=0.5):
    """Why the cell means [cells][moments] cannot be the paper's duct, or None: particles of
    unit mass and heavier have M1 >= M0 in every sample, so a mean mass M1/M0 below `below`
    in a cell says the masses are in another unit (kg) than the incepted particle's."""
    if mean.shape[1] < 2:
        return None
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(mean[:, 0] > 0, mean[:, 1] / mean[:, 0], np.nan)
    light = np.nonzero(ratio < below)[0]
    if not light.size:
        return None
    i = light[np.argmin(ratio[light])]
    return ("the particles are lighter than the incepted unit of mass of the references (mean "
            "mass M1/M0 %.4g in the cell at x = %.6g; masses in kg?)" % (ratio[i], centres[i, 0]))


def mean_mass_interval(data, mean, min_window):
    """The mean mass R = m1/m0 of each cell of one run, data [N][cells][moments] (NaN: no
    sample) with the run's means [cells][moments], and its 95 % half-width: that of the
    mean of z_t = (M1_t - R M0_t)/m0 (the ratio estimator's linearisation, which keeps the
    covariance of M0 and M1: R's error is mean(z) to first order), by the same interval for
    correlated samples as the moments'. NaN where m0 = 0."""
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.where(mean[:, 0] > 0, mean[:, 1] / mean[:, 0], np.nan)
        z = (data[:, :, 1] - ratio * data[:, :, 0]) / mean[:, 0]
    _, _, ci, _ = statistics.correlated_interval_masked(z[:, :, None], min_window=min_window)
    return ratio, np.where(np.isfinite(ratio), ci[:, 0], np.nan)


# --------------------------------------------------------------------------- output

def fmt(v):
    return "nan" if not np.isfinite(v) else "%.12g" % v


def write_csv(res, out):
    """moments.csv (x, Mk_mean, Mk_ci95) and moments_full.csv (every column)."""
    nm = res["mean"].shape[1]
    p1 = os.path.join(out, "moments.csv")
    with open(p1, "w") as f:
        f.write("x," + ",".join("M%d_mean,M%d_ci95" % (k, k) for k in range(nm)) + "\n")
        for i, x in enumerate(res["x"]):
            f.write(fmt(x) + "," + ",".join(
                fmt(res["mean"][i, k]) + "," + fmt(res["ci"][i, k]) for k in range(nm)) + "\n")
    p2 = os.path.join(out, "moments_full.csv")
    cols = ("mean", "sd", "count", "ci95", "analytic", "analyticCentre", "relErr", "normStdDev",
            "neff", "tauInt", "ci95_iid")
    keys = ("mean", "sd", "count", "ci", "analytic", "analyticCentre", "rel", "nsd",
            "neff", "tauInt", "ciIid")
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


def write_summary(res, out, t_end):
    meta = dict(res["meta"])
    meta["tRelax"] = meta["runs"][0]["tRelax"]
    meta["tEnd"] = t_end
    meta["samplesPerCell"] = [int(res["count"][:, 0].min()), int(res["count"][:, 0].max())]
    meta["nCells"] = int(len(res["x"]))
    meta["intervalNote"] = ("ci95 in moments*.csv and the plots' bars: " + meta["interval"]
                            + "; ci95_iid = 1.96 sd / sqrt(count), as if samples were independent")
    # per cell (sorted by x) and moment: effective sample size and tau_int (sample units)
    meta["neff"] = [[None if not np.isfinite(v) else float(v) for v in row] for row in res["neff"]]
    meta["tauInt"] = [[None if not np.isfinite(v) else float(v) for v in row]
                      for row in res["tauInt"]]
    p = os.path.join(out, "summary.json")
    with open(p, "w") as f:
        json.dump(meta, f, indent=2, default=str)
        f.write("\n")
    return p


def title_of(meta, t_relax, t_end):
    n = meta["n"]
    ns = ("%d" % n) if n is not None and float(n).is_integer() else str(n)
    t = "%s, n = %s, %s kernel" % (meta["algorithm"], ns, meta["kernel"])
    r = meta["realisations"]
    t += ", %d realisation%s" % (r, "" if r == 1 else "s")
    t += ", t in [%g, %s]" % (t_relax, "end" if t_end is None else "%g" % t_end)
    return t


def print_table(res, t_end):
    meta = res["meta"]
    nm = res["mean"].shape[1]
    print(title_of(meta, meta["runs"][0]["tRelax"], t_end))
    print("95 %% interval: %s" % meta["interval"])
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
