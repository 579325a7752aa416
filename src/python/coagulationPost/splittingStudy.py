# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Tables and plots of tests/benchmarks/splittingStudy.sh's runs.

    python3 -m coagulationPost.splittingStudy OUT

Writes OUT/splittingStudy.md (tables; also printed) and OUT/splittingOrder.png (error
against dt).  Errors are relative to the analytic cell averages the report writes (eqs
39-45, 50); the 95 % intervals of parts A and B are the report's (successive samples taken
as independent, as in the paper); parts C, D and F's are Student-t intervals over
independent realisations (statistics.standard_error_from_realisations).

Parts (each only if OUT holds its runs):
  A  OUT/A_<scheme>_<dt>/       M1 without coagulation, additive-duct geometry
  B  OUT/B_<scheme>_<dt>/       constant-kernel duct, M0..M3
  C  OUT/C_<scheme>_<dt>_r<k>/  additive-kernel duct, realisations pooled
  E  OUT/E_<scheme>_<dt>/       cost at equal accuracy (and the first C run of each scheme)
  D  OUT/D_<scheme>_<dt>_r<k>.txt   ductReference --cells, no coagulation, seeds pooled
  F  OUT/F_<scheme>_<dt>_r<k>.txt   the same with coagulation
a run folder holding results/moments_full.csv (coagulationReport) and wallTime.
"""
import glob
import math
import os
import re
import sys

import numpy as np

from .statistics import Z95, fit_exponent, standard_error_from_realisations

DX = 2e-3           # cells of the additive-duct geometry (A, C, E)
DX_REFERENCE = 4e-3  # cells of the constant-duct geometry (D)
SCHEMES = ("Lie", "Strang", "StrangSAS")
# each scheme's incepted staircase I dt (floor(x/h + shift) + offset) (case_splitting)
STAIRCASE = {"Lie": (0.0, 0.0), "Strang": (0.5, 0.0), "StrangSAS": (0.0, 0.5)}
_trapz = getattr(np, "trapezoid", None) or np.trapz


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def load(out, name):
    """moments_full.csv of run OUT/NAME (named columns) and the run's wall time."""
    d = os.path.join(out, name)
    f = np.genfromtxt(d + "/results/moments_full.csv", delimiter=",", names=True)
    wall = float(open(d + "/wallTime").read())
    return f, wall


def predicted_m1(scheme, dt, lo, hi, rate=1e5, u=1.0):
    """Exact expectation of the incepted M1 of a scheme without coagulation (case_splitting):
    the cell average of I dt (floor(x/h + s) + o), h = u dt, s = 0 (Lie, StrangSAS) or 1/2
    (Strang), o = 1/2 (StrangSAS) or 0."""
    h = u * dt
    s, o = STAIRCASE[scheme]
    x = np.linspace(lo, hi, 200001)
    return rate * dt * _trapz(np.floor(x / h + s) + o, x) / (hi - lo)


def slope(dts, errs):
    """least-squares slope of log|err| against log dt"""
    return fit_exponent(dts, np.abs(errs))


def pooled(a):
    """mean over the seeds (axis 0), the Student-t 95 % half-width and the count R"""
    a = np.array(a)
    with np.errstate(invalid="ignore"):  # M0 is infinite without coagulation: unused
        return a.mean(0), standard_error_from_realisations(a)[1], len(a)


def weighted_log_slope(dts, errs, half_widths):
    """Slope of log|err| against log dt, each point weighted by (err/se)^2 (the delta
    method: se of log|err| = se/|err|), se = half-width/Z95: (slope, its standard error)."""
    se = np.asarray(half_widths) / Z95
    wts = (np.asarray(errs) / se) ** 2
    X = np.vstack([np.log(dts), np.ones(len(dts))]).T
    cov = np.linalg.inv(X.T @ (wts[:, None] * X))
    b = cov @ X.T @ (wts * np.log(np.abs(errs)))
    return b[0], math.sqrt(cov[0, 0])


def reference_lines(lines, ncells=50):
    """Relative errors [cell][k] of one ductReference --cells output: its lines
    'cell I Mk VALUE%' (others skipped)."""
    rel = np.zeros((ncells, 4))
    for line in lines:
        t = line.split()
        if t[0] == "cell":
            rel[int(t[1]), int(t[2][1])] = float(t[3].rstrip("%")) / 100
    return rel


def reference_runs(out, part):
    """{(scheme, dt): [relative errors [cell][k] of one seed]} of ductReference --cells files"""
    runs = {}
    for path in glob.glob(out + "/%s_*_r*.txt" % part):
        m = re.match(part + r"_(Lie|StrangSAS|Strang)_([0-9.e-]+)_r(\d+)\.txt", os.path.basename(path))
        with open(path) as f:
            rel = reference_lines(f)
        runs.setdefault((m.group(1), float(m.group(2))), []).append(rel)
    return runs


def _by_dt(paths):
    return sorted(paths, key=lambda p: float(p.split("_")[-1]))


def runs_of(out, part, scheme):
    """The run folders OUT/PART_SCHEME_<dt>[_r<k>] of one scheme (not of a scheme whose name
    starts with this one's)"""
    return glob.glob(out + "/%s_%s_[0-9]*" % (part, scheme))


def part_a(out, md, fig_data):
    """A: M1 without coagulation, additive-duct geometry."""
    if not sorted(glob.glob(out + "/A_*")):
        return
    md += ["## A. M1 near the inlet and at the outlet (additive-duct geometry, no coagulation)", "",
           "Relative error of the time-averaged M1 against I x/u (eq 50), measured ± 95 % "
           "(predicted: the scheme's exact expectation). Wall: the run's seconds.", "",
           "| scheme | dt | dx/h | cell 0 | cell 1 | cell 2 | cell 49 (outlet) | wall |",
           "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for scheme in SCHEMES:
        if not runs_of(out, "A", scheme):
            continue
        dts, pe, me, mc = [], [], [], []
        for d in _by_dt(runs_of(out, "A", scheme)):
            dt = float(d.split("_")[-1])
            f, wall = load(out, os.path.basename(d))
            cells = []
            for i in (0, 1, 2, 49):
                lo, hi = i * DX, (i + 1) * DX
                exact = f["M1_analytic"][i]
                p = predicted_m1(scheme, dt, lo, hi) / exact - 1
                m = f["M1_mean"][i] / exact - 1
                c = f["M1_ci95"][i] / exact
                cells.append("%+.2f ± %.2f %% (%+.2f %%)" % (100 * m, 100 * c, 100 * p))
                if i == 0:
                    dts.append(dt); pe.append(p); me.append(m); mc.append(c)
            md.append("| %s | %g | %.3g | %s | %.0f s |" % (scheme, dt, DX / dt, " | ".join(cells), wall))
        fig_data[("A", scheme)] = (np.array(dts), np.array(pe), np.array(me), np.array(mc))
    md.append("")
    for scheme in (sc for sc in SCHEMES if ("A", sc) in fig_data):
        dts, pe, me, mc = fig_data[("A", scheme)]
        ok = np.abs(me) > 2 * mc
        txt = "%s: order of the predicted cell-0 error %.2f" % (scheme, slope(dts, pe))
        if ok.sum() >= 2:
            txt += "; of the measured errors resolved beyond 2 CI (%d of %d dt): %.2f" % (
                ok.sum(), len(dts), slope(dts[ok], me[ok]))
        else:
            txt += "; measured errors resolved beyond 2 CI at %d of %d dt: too few for a fit" % (
                ok.sum(), len(dts))
        md.append("- " + txt)
    md.append("")


def part_b(out, md, fig_data):
    """B: constant-kernel duct, M0..M3 against eqs 39-45."""
    if not glob.glob(out + "/B_*"):
        return
    md += ["## B. Constant-kernel duct (SWA, n = 256): M0..M3 against eqs 39-45", "",
           "Relative error, measured ± 95 %, in the first cell and over cells 45..49 (outlet).", "",
           "| scheme | dt | M0 cell 0 | M1 cell 0 | M2 cell 0 | M3 cell 0 | M0 outlet | M2 outlet | M3 outlet | wall |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for scheme in SCHEMES:
        if not runs_of(out, "B", scheme):
            continue
        dts, e0 = [], []
        for d in _by_dt(runs_of(out, "B", scheme)):
            dt = float(d.split("_")[-1])
            f, wall = load(out, os.path.basename(d))
            cells = []
            for k in range(4):
                e = f["M%d_mean" % k][0] / f["M%d_analytic" % k][0] - 1
                c = f["M%d_ci95" % k][0] / f["M%d_analytic" % k][0]
                cells.append("%+.2f ± %.2f %%" % (100 * e, 100 * c))
                if k == 0:
                    dts.append(dt); e0.append((e, c))
            for k in (0, 2, 3):
                s = slice(45, 50)
                m = f["M%d_mean" % k][s].sum() / f["M%d_analytic" % k][s].sum() - 1
                c = np.sqrt((f["M%d_ci95" % k][s] ** 2).sum()) / f["M%d_analytic" % k][s].sum()
                cells.append("%+.2f ± %.2f %%" % (100 * m, 100 * c))
            md.append("| %s | %g | %s | %.0f s |" % (scheme, dt, " | ".join(cells), wall))
        fig_data[("B", scheme)] = (np.array(dts), np.array([e for e, _ in e0]), np.array([c for _, c in e0]))
    md.append("")
    for scheme in (sc for sc in SCHEMES if ("B", sc) in fig_data):
        dts, e, c = fig_data[("B", scheme)]
        ok = np.abs(e) > 2 * c
        if ok.sum() >= 2:
            md.append("- %s: order of the M0 cell-0 error from the %d dt resolved beyond 2 CI: %.2f"
                      % (scheme, ok.sum(), slope(dts[ok], e[ok])))
        else:
            md.append("- %s: the M0 cell-0 error is resolved beyond 2 CI at %d of %d dt: no fit"
                      % (scheme, ok.sum(), len(dts)))
    md.append("")


def part_c(out, md):
    """C: additive-kernel duct (the tutorial), realisations pooled."""
    if not glob.glob(out + "/C_*"):
        return
    md += ["## C. Additive-kernel duct (tutorial: SWA, n = 2048, dt = 4e-4), independent realisations", "",
           "Mean of the realisations' time averages over [0.2, 0.4], ± Student-t 95 % over R.", "",
           "| scheme | R | M1 cell 1 (x = 0.003) | M1 cell 2 | M1 last cell (9.90e3 exact) | M2 last cell | cells 1..49 with M1 off I x/u beyond the interval | wall per run |",
           "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for scheme in SCHEMES:
        runs = sorted(runs_of(out, "C", scheme))
        if not runs:
            continue
        fs = [load(out, os.path.basename(r)) for r in runs]
        R = len(fs)
        exact = fs[0][0]["M1_analytic"]
        mm1, c1, _ = pooled([f["M1_mean"] for f, _ in fs])
        mm2, c2, _ = pooled([f["M2_mean"] for f, _ in fs])
        off = int(np.sum(np.abs(mm1[1:] - exact[1:]) > c1[1:]))
        cells = ["%+.2f ± %.2f %%" % (100 * (mm1[i] / exact[i] - 1), 100 * c1[i] / exact[i]) for i in (1, 2)]
        md.append("| %s | %d | %s | %.4g ± %.2g | %.4g ± %.2g | %d of 49 | %.0f s |"
                  % (scheme, R, " | ".join(cells), mm1[-1], c1[-1], mm2[-1], c2[-1], off,
                     np.mean([w for _, w in fs])))
    md.append("")


def part_e(out, md):
    """E: cost at equal accuracy (additive duct with coagulation, one seed each)."""
    E = sorted(glob.glob(out + "/E_*"))
    if not E:
        return
    C_ = {sc: sorted(runs_of(out, "C", sc)) for sc in SCHEMES}
    md += ["## E. Cost at equal accuracy: additive-kernel duct (SWA, n = 2048, t = 0..0.4)", "",
           "Expected outlet-cell M1 error of the scheme (its exact expectation; the measured one "
           "is below one run's resolution), and the run's wall time.", "",
           "| scheme | dt | Courant | expected M1 error, outlet cell | expected M1 error, cell 1 | wall |",
           "| --- | --- | --- | --- | --- | --- |"]
    entries = [(os.path.basename(e), e) for e in E] + [(os.path.basename(C_[sc][0]), C_[sc][0]) for sc in C_ if C_[sc]]
    for name, path in sorted(entries, key=lambda e: (e[0].split("_")[1], -float(e[0].split("_")[2]))):
        scheme, dt = name.split("_")[1], float(name.split("_")[2])
        f, wall = load(out, name)
        out49 = predicted_m1(scheme, dt, 49 * DX, 50 * DX) / (1e5 * 49.5 * DX) - 1
        out1 = predicted_m1(scheme, dt, DX, 2 * DX) / (1e5 * 1.5 * DX) - 1
        md.append("| %s | %g | %.2g | %+.3f %% | %+.2f %% | %.0f s |" % (scheme, dt, dt / DX, 100 * out49, 100 * out1, wall))
    md.append("")


def part_d(out, md, fig_data):
    """D: the OpenFOAM-free reference, constant-duct geometry without coagulation."""
    if not glob.glob(out + "/D_*_r*.txt"):
        return
    dxD = DX_REFERENCE
    runs = reference_runs(out, "D")
    md += ["## D. Constant-duct geometry without coagulation, OpenFOAM-free reference (SWA, n = 4096, t = 4)", "",
           "Relative error of M1 against eq 41, mean over R seeds ± Student-t 95 %, the "
           "scheme's exact expectation in brackets; cells 45..49 (outlet) averaged.", "",
           "| scheme | dt | dx/h | R | M1 cell 0 | M1 cell 1 | M1 outlet (45..49) |",
           "| --- | --- | --- | --- | --- | --- | --- |"]
    for scheme in SCHEMES:
        dts = sorted(dt for (sc, dt) in runs if sc == scheme)
        if not dts:
            continue
        pts = []
        for dt in dts:
            mean, ci, R = pooled(runs[(scheme, dt)])
            pred = [predicted_m1(scheme, dt, i * dxD, (i + 1) * dxD, rate=3e8) /
                    (3e8 * (i + 0.5) * dxD) - 1 for i in (0, 1)]
            cells = ["%+.2f ± %.2f %% (%+.2f %%)" % (100 * mean[i, 1], 100 * ci[i, 1], 100 * pred[i]) for i in (0, 1)]
            a = np.array(runs[(scheme, dt)])[:, 45:50, 1].mean(1)
            mo, co, _ = pooled(a)
            cells.append("%+.3f ± %.3f %%" % (100 * mo, 100 * co))
            md.append("| %s | %g | %.3g | %d | %s |" % (scheme, dt, dxD / dt, R, " | ".join(cells)))
            pts.append((dt, mean[0, 1], ci[0, 1], pred[0], mean[0, 0], ci[0, 0]))
        fig_data[("D", scheme)] = np.array(pts)
    md.append("")
    for scheme in (sc for sc in SCHEMES if ("D", sc) in fig_data):
        p = fig_data[("D", scheme)]
        ok = np.abs(p[:, 1]) > 2 * p[:, 2]
        txt = "%s: order of the exact expected M1 cell-0 error %.2f" % (scheme, slope(p[:, 0], p[:, 3]))
        if ok.sum() >= 2:
            w = slope(p[ok, 0], p[ok, 1])
            txt += "; of the measured errors resolved beyond 2 CI (dt = %s): %.2f" % (
                ", ".join("%g" % d for d in p[ok, 0]), w)
        else:
            txt += "; measured errors resolved beyond 2 CI at %d dt: no fit" % ok.sum()
        # all dt, log errors weighted by (error/SE)^2 (delta method), with the slope's SE
        b, b_se = weighted_log_slope(p[:, 0], p[:, 1], p[:, 2])
        txt += "; weighted fit over all %d dt: %.2f ± %.2f (1 SE)" % (len(p), b, b_se)
        z = (p[:, 1] - p[:, 3]) / (p[:, 2] / Z95)
        txt += "; measured minus expected, in standard errors: %s" % " ".join("%+.1f" % v for v in z)
        md.append("- " + txt)
    md.append("")


def part_f(out, md):
    """F: the reference with coagulation (constant kernel), M0, M2, M3."""
    if not glob.glob(out + "/F_*_r*.txt"):
        return
    runs = reference_runs(out, "F")
    md += ["## F. Constant-kernel duct with coagulation, OpenFOAM-free reference (SWA, n = 1024, t = 4)", "",
           "Relative errors against eqs 39, 43, 45, mean over R seeds ± Student-t 95 %; "
           "outlet: cells 45..49 averaged.", "",
           "| scheme | dt | R | M0 cell 0 | M2 cell 0 | M3 cell 0 | M0 outlet | M2 outlet | M3 outlet |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    fits = {}
    for scheme in SCHEMES:
        for dt in sorted(dt for (sc, dt) in runs if sc == scheme):
            a = np.array(runs[(scheme, dt)])
            mean, ci, R = pooled(a)
            cells = ["%+.2f ± %.2f %%" % (100 * mean[0, k], 100 * ci[0, k]) for k in (0, 2, 3)]
            for k in (0, 2, 3):
                mo, co, _ = pooled(a[:, 45:50, k].mean(1))
                cells.append("%+.3f ± %.3f %%" % (100 * mo, 100 * co))
                fits.setdefault((scheme, k), []).append((dt, mo, co))
            md.append("| %s | %g | %d | %s |" % (scheme, dt, R, " | ".join(cells)))
    md.append("")
    for (scheme, k), pts in sorted(fits.items()):
        p = np.array(pts)
        ok = np.abs(p[:, 1]) > 2 * p[:, 2]
        if ok.sum() >= 2:
            md.append("- %s M%d outlet: order from the %d dt resolved beyond 2 CI: %.2f"
                      % (scheme, k, ok.sum(), slope(p[ok, 0], p[ok, 1])))
        else:
            md.append("- %s M%d outlet: resolved beyond 2 CI at %d of %d dt" % (scheme, k, ok.sum(), len(p)))
    md.append("")


def plot(out, fig_data):
    """splittingOrder.png: |error| against dt of parts A, B and D."""
    plt = _pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4))
    for scheme, col in (("Lie", "C0"), ("Strang", "C1"), ("StrangSAS", "C2")):
        if ("A", scheme) in fig_data:
            dts, pe, me, mc = fig_data[("A", scheme)]
            axes[0].loglog(dts, np.abs(pe), "-", color=col, label="%s, exact expectation" % scheme)
            axes[0].errorbar(dts, np.abs(me), yerr=mc, fmt="o", color=col, label="%s, measured" % scheme)
        if ("B", scheme) in fig_data:
            dts, e, c = fig_data[("B", scheme)]
            axes[1].errorbar(dts, np.abs(e), yerr=c, fmt="o-", color=col, label=scheme)
        if ("D", scheme) in fig_data:
            p = fig_data[("D", scheme)]
            axes[2].loglog(p[:, 0], np.abs(p[:, 3]), "-", color=col, label="%s, exact expectation" % scheme)
            axes[2].errorbar(p[:, 0], np.abs(p[:, 1]), yerr=p[:, 2], fmt="o", color=col, label="%s, measured" % scheme)
    axes[0].set_title("A: |M1 error|, cell 0 (no coagulation)")
    axes[2].set_title("D: |M1 error|, cell 0 (reference, no coagulation)")
    axes[1].set_title("B: |M0 error|, cell 0 (constant kernel)")
    for ax in axes:
        ax.set_xscale("log"); ax.set_yscale("log"); ax.set_xlabel("dt"); ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "splittingOrder.png"), dpi=110)
    plt.close(fig)


def study(out):
    """The tables (markdown lines) of the runs in OUT, in the order A, B, C, E, D, F, and
    the data of the plot."""
    md = ["# Splitting study (tests/benchmarks/splittingStudy.sh)", ""]
    fig_data = {}
    part_a(out, md, fig_data)
    part_b(out, md, fig_data)
    part_c(out, md)
    part_e(out, md)
    part_d(out, md, fig_data)
    part_f(out, md)
    return md, fig_data


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    out = argv[0]
    md, fig_data = study(out)
    open(os.path.join(out, "splittingStudy.md"), "w").write("\n".join(md) + "\n")
    print("\n".join(md))
    try:
        plot(out, fig_data)
    except ImportError:   # no matplotlib: the tables only
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())
