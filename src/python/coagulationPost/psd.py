# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""The particle size distribution of a run: the samples the
sizeDistribution cloud function writes, their time averages with intervals for
correlated samples, the exact distribution where one exists, checks and plots.

Files of a function NAME (constant/coagulationProperties, cloudFunctions):
  postProcessing/NAME/<startTime>/sizeDistribution.h5   every sample (one file per
      run start): /time, /cellCentres [regions][3], /moments [samples][regions][cols],
      the columns named by the attribute 'columns' (n0..n{B-1}, underflow, overflow,
      M0, meanMass, geometricMeanMass, gsd, medianMass, d10, d32, d43), 'binEdges',
      'binType' (integer | log), 'regions', 'regionVolumes', 'timeStart', ...
  postProcessing/NAME/<time>/{sizeDistribution,derived,regions}.csv   the solver's
      time averages at each write time (coag::correlatedMean) and the regions (the
      bounding box of each probe's cell).

average() recomputes the averages from the samples with
statistics.correlated_interval_masked (the same estimator the solver uses, with a
least window of the residence time upstream of each probe as the moment report).
figures() plots each region's number density per bin against the mass;
diameter_figure() every region of a run on one figure as aerosol users read it,
dN/dlog10 d against d [nm] with the count median and geometric mean diameters and
sigma_g (size_statistics) in the legend.
"""

import csv
import glob
import os

import numpy as np

from . import analytic, statistics
from .samples import InputError

DERIVED = ("M0", "meanMass", "geometricMeanMass", "gsd", "medianMass", "d10", "d32", "d43")


def _attr(v):
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.size == 1:
        v = v.reshape(-1)[0]
        if isinstance(v, bytes):
            return v.decode()
    try:
        return float(v)
    except (TypeError, ValueError):
        return str(v)


def function_names(case):
    """Names of the sizeDistribution functions with samples in case."""
    hits = glob.glob(os.path.join(case, "postProcessing", "*", "*", "sizeDistribution.h5"))
    return sorted({os.path.basename(os.path.dirname(os.path.dirname(h))) for h in hits})


def _time_dirs(folder):
    out = []
    for d in os.listdir(folder):
        try:
            out.append((float(d), d))
        except ValueError:
            pass
    return [d for _, d in sorted(out)]


def read(case, name):
    """The samples of function `name` of a case, the run starts concatenated in time
    (a restart's file continues the series).  Returns a dict: time [N], data
    [N][regions][cols], columns, edges, binType, regions, volumes, centres, attrs,
    box (regions.csv of the latest write time: lo, hi [regions][3]; None without)."""
    import h5py

    folder = os.path.join(case, "postProcessing", name)
    if not os.path.isdir(folder):
        raise InputError("no size distribution '%s' in %s" % (name, case))
    times, data, attrs, centres = [], [], None, None
    for d in _time_dirs(folder):
        f = os.path.join(folder, d, "sizeDistribution.h5")
        if not os.path.exists(f):
            continue
        with h5py.File(f, "r") as h:
            a = {k: _attr(v) for k, v in h.attrs.items()}
            t = h["time"][:]
            m = h["moments"][:]
            centres = h["cellCentres"][:]
        if attrs is None:
            attrs = a
        if times:        # a restart: its samples replace the later ones of earlier files
            keep = np.concatenate(times) < (t[0] if t.size else np.inf)
            times = [np.concatenate(times)[keep]]
            data = [np.concatenate(data)[keep]]
        times.append(t)
        data.append(m)
    if attrs is None:
        raise InputError("no sizeDistribution.h5 under %s" % folder)
    time = np.concatenate(times)
    data = np.concatenate(data)
    columns = str(attrs["columns"]).split()
    edges = np.array([float(v) for v in str(attrs["binEdges"]).split()])
    regions = str(attrs["regions"]).split()
    volumes = np.array([float(v) for v in str(attrs["regionVolumes"]).split()])
    box = None
    writes = [d for d in _time_dirs(folder)
              if os.path.exists(os.path.join(folder, d, "regions.csv"))]
    if writes:
        with open(os.path.join(folder, writes[-1], "regions.csv")) as f:
            rows = list(csv.DictReader(f))
        lo = np.array([[float(r["xMin"]), float(r["yMin"]), float(r["zMin"])] for r in rows])
        hi = np.array([[float(r["xMax"]), float(r["yMax"]), float(r["zMax"])] for r in rows])
        box = (lo, hi)
    return {"case": case, "name": name, "time": time, "data": data, "columns": columns,
            "edges": edges, "binType": str(attrs.get("binType", "log")),
            "regions": regions, "volumes": volumes, "centres": centres, "attrs": attrs,
            "box": box, "nBins": len(edges) - 1}


def read_csv(case, name, time=None):
    """The solver's averages of the write time `time` (default: the latest):
    (psd rows, derived rows) as lists of dicts of floats (name strings kept)."""
    folder = os.path.join(case, "postProcessing", name)
    writes = [d for d in _time_dirs(folder)
              if os.path.exists(os.path.join(folder, d, "sizeDistribution.csv"))]
    if not writes:
        raise InputError("no sizeDistribution.csv under %s" % folder)
    d = os.path.join(folder, writes[-1] if time is None else time)

    def load(fname):
        with open(os.path.join(d, fname)) as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        out = []
        for r in rows:
            out.append({k: (v if k == "quantity" else float(v)) for k, v in r.items()})
        return out
    return load("sizeDistribution.csv"), load("derived.csv")


def average(psd, t_min=None, u=1.0, x_inlet=0.0, correlation_time=None):
    """Time averages of every region and column over samples t >= t_min (default
    the attribute timeStart): (mean, n_eff, ci95, tau_int), each [regions][cols],
    from statistics.correlated_interval_masked (NaN samples, the derived sizes of an
    empty region, left out).  Least window: correlation_time seconds, or None: the
    residence time (x - x_inlet)/u upstream of each region."""
    t0 = psd["attrs"].get("timeStart", 0.0) if t_min is None else t_min
    sel = psd["time"] >= float(t0) - 1e-12
    data = psd["data"][sel]
    dt = float(psd["attrs"].get("sampleInterval", 0) or 0)
    if correlation_time is None:
        t = np.maximum(psd["centres"][:, 0] - x_inlet, 0.0) / abs(u)
    else:
        t = np.full(len(psd["regions"]), float(correlation_time))
    mw = np.ceil(t / dt - 1e-9).astype(int)[:, None] if dt > 0 else 0
    mw = np.broadcast_to(mw, data.shape[1:]) if dt > 0 else 0
    return statistics.correlated_interval_masked(data, min_window=mw)


def exact(psd, u=1.0, x_inlet=0.0, K=None):
    """The exact number density per bin at each region, or None without one: the
    homogeneous Smoluchowski solution with inception (analytic.smoluchowski_sizes)
    at t = (x - x_inlet)/u averaged over the region's x extent (its cells' bounding
    box; the point itself without regions.csv), for the constant and additive
    kernels.  Integer bins: n_k; log bins: the sum of n_k over the integer sizes in
    the bin, NaN for bins above the largest size computed (K, default the bins'
    top, at most 4096), None where no bin holds an integer size (bins far below one
    mass unit, masses in kg; bins between two sizes).  Returns [regions][bins].
    Whether the case is the paper's duct, which the distribution assumes, is the
    caller's to decide (analytic.not_the_papers_duct)."""
    kernel = str(psd["attrs"].get("kernel", "")).lower()
    if kernel not in ("constant", "additive"):
        return None
    I = float(psd["attrs"]["inceptionRate"])
    K0 = float(psd["attrs"]["K0"])
    edges = psd["edges"]
    if psd["box"] is not None:
        lo, hi = psd["box"][0][:, 0], psd["box"][1][:, 0]
    else:
        lo = hi = psd["centres"][:, 0]
    if psd["binType"] == "integer":
        K = psd["nBins"]
        return analytic.duct_sizes(kernel, lo, hi, K, I, K0, u, x_inlet)
    Kmax = int(min(np.floor(edges[-1]), 4096)) if K is None else int(K)
    sizes = np.arange(1, max(Kmax, 0) + 1)
    # the integer sizes in each bin below the largest size computed
    inside = {b: (sizes >= edges[b]) & (sizes < edges[b + 1])
              for b in range(len(edges) - 1) if edges[b + 1] <= Kmax + 1}
    if not any(v.any() for v in inside.values()):
        return None
    n = analytic.duct_sizes(kernel, lo, hi, Kmax, I, K0, u, x_inlet)
    out = np.full((len(lo), len(edges) - 1), np.nan)
    for b, v in inside.items():
        out[:, b] = n[:, v].sum(axis=1)
    return out


def check(psd, ref, bins, mean, ci, z_max=4.0, frac_min=0.85):
    """Bin by bin against the exact ref [regions][bins] over the bins `bins` (indices):
    z = (mean - ref)/(ci/1.96).  Passes when at least frac_min of the region-bins have
    |z| <= 1.96 and none |z| > z_max.  Returns (ok, z [regions][len(bins)], lines)."""
    m = mean[:, bins]
    half = ci[:, bins]
    r = ref[:, bins]
    with np.errstate(invalid="ignore", divide="ignore"):
        z = (m - r) / (half / statistics.Z95)
    inside = np.abs(z) <= statistics.Z95
    frac = float(np.mean(inside))
    lines = []
    for i, name in enumerate(psd["regions"]):
        lines.append("%s x=%.4g: |z| <= 1.96 in %d of %d bins, max |z| %.2f (bin %d)"
                     % (name, psd["centres"][i, 0], int(inside[i].sum()), len(bins),
                        np.nanmax(np.abs(z[i])), bins[int(np.nanargmax(np.abs(z[i])))]))
    ok = bool(frac >= frac_min and np.all(np.abs(z) <= z_max) and np.all(np.isfinite(z)))
    lines.append("inside 95 %% intervals: %.1f %% of %d region-bins (need >= %.0f %%), "
                 "max |z| %.2f (need <= %.1f): %s"
                 % (100 * frac, z.size, 100 * frac_min, np.nanmax(np.abs(z)), z_max,
                    "PASS" if ok else "FAIL"))
    return ok, z, lines


def figures(runs, out, u=1.0, x_inlet=0.0, labels=None, reference=True):
    """PSD at every region of each run, one column per run (two runs side by side),
    one row per region: time-averaged number density per bin with its 95 % interval
    against the exact distribution where there is one (none without `reference`).  PNG
    files in out; returns their paths."""
    from .plots import _pyplot
    plt = _pyplot()
    os.makedirs(out, exist_ok=True)
    nreg = max(len(p["regions"]) for p in runs)
    fig, axes = plt.subplots(nreg, len(runs), figsize=(5.0 * len(runs), 3.2 * nreg),
                             squeeze=False, sharey="row")
    for j, p in enumerate(runs):
        mean, _, ci, _ = average(p, u=u, x_inlet=x_inlet)
        ref = exact(p, u, x_inlet) if reference else None
        B = p["nBins"]
        e = p["edges"]
        centre = np.arange(1, B + 1) if p["binType"] == "integer" else np.sqrt(e[1:] * e[:-1])
        for i in range(len(p["regions"])):
            ax = axes[i, j]
            ok = mean[i, :B] > 0
            ax.errorbar(centre[ok], mean[i, :B][ok], yerr=ci[i, :B][ok], fmt="o", ms=3,
                        capsize=2, label="time average, 95 % interval")
            if ref is not None:
                # bins without an integer size (exactly 0) and the round-off of the FFT
                # convolutions far below the peak are not drawn
                r = np.where(ref[i] > 1e-12 * np.nanmax(ref[i]), ref[i], np.nan)
                ax.plot(centre, r, "r-", lw=1, zorder=3, label="exact n_k(t = x/u)")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title("%s: %s x = %.4g" % (labels[j] if labels else p["case"],
                                              p["regions"][i], p["centres"][i, 0]),
                         fontsize=8)
            ax.set_xlabel("mass (monomer units)" if p["binType"] == "integer"
                          else "mass (bin centre)")
            ax.set_ylabel("number density per bin (1/m^3)")
            ax.legend(fontsize=6)
    fig.tight_layout()
    path = os.path.join(out, "sizeDistribution.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def check_m0(psd, case, rel_tol=1e-9):
    """The PSD's sum (bins, underflow and overflow) against M0 of the same cells from
    the moment samples (postProcessing/coagulationSamples, the momentFields path),
    averaged over the sample times both have: for a probe the cell whose centre is
    nearest the probe point; for a zone the mean M0 of the cells whose centres lie in
    the zone's bounding box (regions.csv), which is the zone's M0 for a box-shaped zone
    of cells of equal volume (the samples hold no volumes).  Returns (ok, lines)."""
    import h5py

    files = sorted(glob.glob(os.path.join(case, "postProcessing", "coagulationSamples",
                                          "samples_*.h5")))
    if not files:
        raise InputError("no moment samples in %s" % case)
    with h5py.File(files[0], "r") as h:
        t = h["time"][:]
        cc = h["cellCentres"][:]
        m = h["moments"][:, :, 0]
    B = psd["nBins"]
    total = psd["data"][:, :, :B + 2].sum(axis=2)           # [samples][regions]
    ok, lines = True, []
    common, ia, ib = np.intersect1d(np.round(psd["time"], 9), np.round(t, 9),
                                    return_indices=True)
    if common.size == 0:
        raise InputError("no common sample time of the PSD and the moments")
    for r, name in enumerate(psd["regions"]):
        if name.startswith("probe"):
            cells = [int(np.argmin(((cc - psd["centres"][r]) ** 2).sum(axis=1)))]
        elif psd["box"] is not None:
            lo, hi = psd["box"][0][r], psd["box"][1][r]
            cells = list(np.nonzero(np.all((cc > lo) & (cc < hi), axis=1))[0])
        else:
            continue
        a = total[ia, r].mean()
        b = m[ib][:, cells].mean(axis=1).mean()
        rel = abs(a - b) / max(abs(b), 1e-300)
        good = rel <= rel_tol
        ok = ok and good
        lines.append("%s: sum of the PSD %.10g, M0 of cell(s) %s %.10g over %d samples: "
                     "relative difference %.2e (tol %.0e) %s"
                     % (name, a, ",".join(str(c) for c in cells), b, common.size, rel,
                        rel_tol, "ok" if good else "FAIL"))
    return ok, lines


def check_csv(psd, case, rel_tol=1e-3):
    """The solver's averages at the last write time (sizeDistribution.csv, its C++
    coag::correlatedMean with the function's correlationTime) against average() of
    the samples with the same least window: means to 1e-9, n_eff, tau_int and the
    half-widths to rel_tol (the Student t quantiles differ by an approximation).
    Returns (ok, lines)."""
    rows, _ = read_csv(case, psd["name"])
    B = psd["nBins"]
    tc = float(psd["attrs"].get("correlationTime", 0.0) or 0.0)
    mean, neff, ci, tau = average(psd, correlation_time=tc)
    worst = {"mean": 0.0, "ci95": 0.0, "neff": 0.0, "tauInt": 0.0}
    for r in rows:
        i, b = int(r["region"]), int(r["bin"])
        j = B if b < 0 else (B + 1 if b == B else b)
        for key, ref, tol in (("mean", mean, 1e-9), ("ci95", ci, rel_tol),
                              ("neff", neff, rel_tol), ("tauInt", tau, rel_tol)):
            a, e = r[key], ref[i, j]
            if np.isnan(a) and np.isnan(e):
                continue
            d = abs(a - e) / max(abs(e), 1e-300) if e != 0 else abs(a)
            worst[key] = max(worst[key], d / tol)
    ok = all(v <= 1 for v in worst.values())
    return ok, ["solver CSV against the samples: largest difference / tolerance: "
                + ", ".join("%s %.3g" % kv for kv in worst.items())
                + (" ok" if ok else " FAIL")]


def diameter_bins(psd, density, mass_unit):
    """The bins as diameters of spheres of the density (masses in mass_unit kg): (centre,
    lower, upper) in m, and the width of each bin in log10 d.  Integer bins hold one size k
    each, their edges taken half way, k -/+ 1/2; log bins their mass edges."""
    B = psd["nBins"]
    e = np.asarray(psd["edges"], float)
    if psd["binType"] == "integer":
        k = np.arange(1, B + 1, dtype=float)
        centre, lower, upper = k, k - 0.5, k + 0.5
    else:
        centre, lower, upper = np.sqrt(e[1:B + 1] * e[:B]), e[:B], e[1:B + 1]

    def d(m):
        return sphere_diameter(m, density, mass_unit)
    return d(centre), d(lower), d(upper), np.log10(upper / lower) / 3.0


def sphere_diameter(mass, density, mass_unit):
    """The diameter [m] of spheres of mass [mass units of mass_unit kg] and density
    [kg/m3]: (6 m / (pi rho))^(1/3)."""
    return np.cbrt(6.0 * np.asarray(mass, float) * mass_unit / (np.pi * density))


def size_statistics(d, n, lower=None, upper=None):
    """The count median diameter, the geometric mean diameter and the geometric standard
    deviation of the numbers n in bins of centre diameters d (edges lower, upper: the
    median interpolated in log d within its bin; without edges, at the centres)."""
    n = np.where(np.isfinite(n) & (np.asarray(n) > 0), n, 0.0)
    total = n.sum()
    if not total > 0:
        return np.nan, np.nan, np.nan
    ln = np.log(d)
    gmd = np.exp(np.dot(n, ln) / total)
    sg = np.exp(np.sqrt(np.dot(n, (ln - np.log(gmd)) ** 2) / total))
    cum = np.cumsum(n) / total
    b = int(np.searchsorted(cum, 0.5))
    if lower is None:
        return d[b], gmd, sg
    before = cum[b - 1] if b > 0 else 0.0
    f = (0.5 - before) / (cum[b] - before)
    cmd = np.exp(np.log(lower[b]) + f * (np.log(upper[b]) - np.log(lower[b])))
    return cmd, gmd, sg


def diameter_figure(runs, out, u=1.0, x_inlet=0.0, labels=None, density=None, mass_unit=None,
                    reference=True):
    """dN/dlog10 d against d [nm] of every region of each run on one figure per run (side by
    side), 95 % intervals as bands, the exact distribution as lines where there is one (none
    without `reference`), the count median and geometric mean diameters and sigma_g of each
    region in the legend.
    The density and mass unit: the arguments, else the run's ('particles'); a run without
    either is left out.  Writes sizeDistributionDiameter.png and the plotted arrays as
    sizeDistributionDiameter.csv (run, region, x, bin, d_nm, dNdlog10d, ci95, exact);
    returns the paths (none when no run has a density)."""
    from .plots import _pyplot
    shown = []
    for j, p in enumerate(runs):
        # the values given win over the run's; a run without 'particles' has density 0
        rho = density if density is not None else float(p["attrs"].get("density", 0) or 0)
        unit = mass_unit if mass_unit is not None else float(p["attrs"].get("massUnit", 1) or 1)
        if rho > 0:
            shown.append((j, p, rho, unit))
    if not shown:
        return []
    plt = _pyplot()
    os.makedirs(out, exist_ok=True)
    fig, axes = plt.subplots(1, len(shown), figsize=(6.5 * len(shown), 4.8), squeeze=False)
    rows = []
    for a, (j, p, rho, unit) in enumerate(shown):
        ax = axes[0, a]
        mean, _, ci, _ = average(p, u=u, x_inlet=x_inlet)
        ref = exact(p, u, x_inlet) if reference else None
        B = p["nBins"]
        d, lo, hi, dlog = diameter_bins(p, rho, unit)
        nm = 1e9 * d
        # micrometres for particles of a micrometre and more
        scale, unit_name = (1e-3, "µm") if np.nanmin(nm) >= 1000 else (1.0, "nm")
        colours = _pyplot().cm.viridis(np.linspace(0, 0.85, len(p["regions"])))
        for i in range(len(p["regions"])):
            y, dy = mean[i, :B] / dlog, ci[i, :B] / dlog
            cmd, gmd, sg = size_statistics(d, mean[i, :B], lo, hi)
            show = y > 0
            ax.plot(scale * nm[show], y[show], "-", lw=1, color=colours[i],
                    label="%s x = %.4g m: CMD %.3g %s, GMD %.3g %s, σg %.3f"
                    % (p["regions"][i], p["centres"][i, 0], 1e9 * scale * cmd, unit_name,
                       1e9 * scale * gmd, unit_name, sg))
            # the band where the interval stays above zero; a bin whose interval reaches
            # zero (a log axis has no zero) as an open marker without a band
            firm = show & (y - dy > 0)
            ax.plot(scale * nm[firm], y[firm], "o", ms=3, color=colours[i])
            ax.plot(scale * nm[show & ~firm], y[show & ~firm], "o", ms=3.5, mfc="none",
                    color=colours[i])
            ax.fill_between(scale * nm, np.where(firm, y - dy, np.nan),
                            np.where(firm, y + dy, np.nan), color=colours[i], alpha=0.2, lw=0)
            ex = ref[i] / dlog if ref is not None else np.full(B, np.nan)
            if ref is not None:
                r = np.where(ex > 1e-12 * np.nanmax(ex), ex, np.nan)
                ax.plot(scale * nm, r, "-", color="k", lw=0.8, zorder=3,
                        label="exact n(d, t = x/u)" if i == 0 else None)
            for b in range(B):
                rows.append("%d,%s,%.8g,%d,%.10g,%.10g,%.10g,%.10g"
                            % (j, p["regions"][i], p["centres"][i, 0], b, nm[b], y[b], dy[b],
                               ex[b]))
        ax.set_xscale("log")
        ax.set_yscale("log")
        # diameters as plain numbers at 1, 2 and 5 of each decade (not powers of ten), more
        # where the sizes span less than a decade and a half
        from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
        span = np.log10(np.nanmax(nm) / np.nanmin(nm))
        subs = (1.0, 2.0, 5.0) if span > 1.5 else (1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0)
        ax.xaxis.set_major_locator(LogLocator(base=10, subs=subs))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: "%g" % v))
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel("d [%s] (spheres of %g kg/m³)" % (unit_name, rho))
        ax.set_ylabel("dN/dlog₁₀d [m⁻³]")
        ax.set_title("%s: size distribution, 95 %% intervals shaded (open: reaching 0)"
                     % (labels[j] if labels else p["case"]), fontsize=9)
        ax.legend(fontsize=6)
    fig.tight_layout()
    path = os.path.join(out, "sizeDistributionDiameter.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    csv_path = os.path.join(out, "sizeDistributionDiameter.csv")
    with open(csv_path, "w") as f:
        f.write("run,region,x,bin,d_nm,dNdlog10d,ci95,exact\n")
        f.write("\n".join(rows) + "\n")
    return [path, csv_path]
