#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationReport: time-averaged moment statistics of coagulationFoam runs.

Reads the HDF5 moment samples written by the solver,
<case>/postProcessing/coagulationSamples/*.h5 (also in sub-folders), merging the
files of processors and restarts by cell centre and time, and reports for every
cell and moment k, over the samples with t_relax <= t <= t_end (pooled over the
realisations given with --realisations), the sample mean, sd, count, 95 %
half-width of the mean and the normalised sd sqrt(n var(M_k)) / m_k,
against the analytic duct reference of the kernel (Patterson & Wagner eqs 39-45,
50) where the samples describe the paper's duct case (--analytic auto: a constant
or additive kernel, inception, masses in units of the incepted particle's, no
growth; else none, and a line says why).  A thin command line over the package
coagulationPost in <repo>/src/python (samples, statistics, analytic, report,
plots, checks), whose documentation gives the file layout and the merging rules.

Outputs in --out (resolved against --case when relative):
  moments.csv        x, Mk_mean, Mk_ci95 for k = 0..3
  moments_full.csv   x, y, z, and per k: mean, sd, count, ci95, analytic cell
                     average, analytic value at the centre, relative error,
                     normalised standard deviation, neff (effective sample size),
                     tauInt (integrated autocorrelation time, samples), ci95_iid
                     (1.96 sd / sqrt(count), as if the samples were independent)

The 95 % half-width ci95 allows for the correlation of successive samples: for one
run, t_{0.975,nu} sqrt(var(mean)) from the run's integrated autocorrelation time
(effective sample size n_eff = sd^2 / var(mean)); for several --realisations,
t_{0.975,R-1} sd(realisation means) / sqrt(R).  See coagulationPost.statistics.
  moments.png        m_k(x): means with 95 % CI bars and the analytic curve (1-D meshes)
  relativeError.png  (mean - analytic cell average) / analytic, with CI bars
  normalisedStdDev.png  sqrt(n var)/m_k against x, eq. (47) line for k = 1
  maps.png, maps.csv (2-D meshes), slice_<axis><value>.png, .csv (--slice; 3-D meshes:
                     the middle plane by default)
                     M0, M1 and the mean mass M1/M0 (with the particles' material: the
                     diameter of the mean mass, nm) per cell, and their relative 95 %
                     half-widths (<q>_relCI95)
  line<k>.png, .csv  (--line) the same along a segment, a step per cell with its
                     interval, each cell's entry and exit
  summary.json       run attributes, time window, files, realisations

Exit status: 0 success, 1 a --check / --check-value failed, 2 bad input
(no sample files, missing dataset, inconsistent files, bad options: also a
number that makes no sense, such as a density that is not positive and finite).

Examples:
  coagulationReport.py --case tutorials/constantDuct --check \\
      --check-rel-tol 0.03 --check-skip-cells 3 --check-moments 0,1,2,3
  coagulationReport.py --case tutorials/additiveDuct \\
      --check-cell-index -1 --check-moment 1 --check-value 9.90e3 \\
      --check-value-rel-tol 0.003
  coagulationReport.py --out pooled --realisations run_seed1 run_seed2 run_seed3
"""

import argparse
import math
import os
import re
import sys

# the post-processing package, <repo>/src/python/coagulationPost (PYTHONPATH: etc/bashrc)
from coagulationPost import analytic, checks, maps, plots, psd, report
from coagulationPost.samples import InputError

EXIT_OK, EXIT_CHECK_FAILED, EXIT_INPUT = 0, 1, 2


# argparse types of the options' numbers: a value that makes no sense (NaN, infinite, a density
# or a speed not above zero, ...) is refused by argparse, one line naming the option, the value
# and what is expected, exit status 2

def number(expected, low=None, strict=True):
    """A finite float, greater than low (strict) or at least low; otherwise refused with
    '<text> is not <expected>'."""
    def parse(text):
        try:
            v = float(text)
        except ValueError:
            v = math.nan
        if not math.isfinite(v) or (low is not None and (v <= low if strict else v < low)):
            raise argparse.ArgumentTypeError("%s is not %s" % (text, expected))
        return v
    return parse


def positive(expected):
    return number("a positive finite " + expected, 0.0)


def whole_number(text):
    """An integer >= 0 (a count, a moment order)."""
    try:
        v = int(text)
    except ValueError:
        v = -1
    if v < 0:
        raise argparse.ArgumentTypeError("%s is not a whole number >= 0" % text)
    return v


def moment_list(text):
    """'0,1,3' -> [0, 1, 3]."""
    try:
        orders = [int(t) for t in text.split(",") if t.strip()]
    except ValueError:
        orders = [-1]
    if not orders or min(orders) < 0:
        raise argparse.ArgumentTypeError(
            "%s is not a comma-separated list of moment orders >= 0 (0,1,2,3)" % text)
    return orders


def bin_range(text):
    """'A:B' -> (A, B), 1 <= A <= B."""
    try:
        a, b = (int(v) for v in text.split(":"))
    except ValueError:
        a, b = 0, 0
    if not 1 <= a <= b:
        raise argparse.ArgumentTypeError(
            "%s is not A:B with 1 <= A <= B (the first and last bins, 1-based)" % text)
    return a, b


def analytic_kind(text):
    """--analytic: auto, none, a reference's name, or the name of its kernel (constant,
    additive)."""
    return analytic.kind_for_kernel(text) or text


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
    p.add_argument("--t-relax", type=number("a finite time [s]"), default=None,
                   help="first sample time used (default: the files' tRelax attribute)")
    p.add_argument("--t-end", type=number("a finite time [s]"), default=None,
                   help="last sample time used (default: all)")
    p.add_argument("--u", type=positive("speed [m/s]"), default=None,
                   help="advection speed of the analytic duct (default: attribute u, else 1.0)")
    p.add_argument("--x-inlet", type=number("a finite position [m]"), default=0.0,
                   help="x of the duct inlet, where the analytic moments vanish (default 0)")
    p.add_argument("--out", default="results",
                   help="output folder; a relative path is taken inside --case (default: results)")
    p.add_argument("--analytic", default="auto", type=analytic_kind,
                   choices=("auto",) + analytic.KINDS + ("none",),
                   help="analytic reference: auto (default) the duct reference of the kernel "
                        "where the samples describe the paper's duct case (a constant or "
                        "additive kernel, inception, masses in units of the incepted "
                        "particle's, no growth), else none and why; none; or a reference "
                        "(constantDuct or constant, additiveDuct or additive) whatever the "
                        "case")
    p.add_argument("--correlation-time", type=number("a finite time >= 0 [s]", 0.0, False),
                   default=None, metavar="T",
                   help="one run's interval: the autocorrelation sum spans at least T seconds "
                        "(default: the residence time (x - x_inlet)/u upstream of the cell; "
                        "0: Sokal's automatic window alone)")
    p.add_argument("--no-plots", action="store_true",
                   help="skip the pictures (the PNG files and the maps' CSV files)")
    p.add_argument("--slice", action="append", metavar="AXIS=VALUE", default=[],
                   help="maps of the moments on the plane AXIS = VALUE (x, y or z) of the "
                        "case's mesh: slice_<AXIS><VALUE>.png and .csv; repeatable. A 3-D "
                        "mesh without --slice or --line: the plane through its middle "
                        "across its thinnest extent")
    p.add_argument("--line", nargs=2, action="append", metavar=("P0", "P1"), default=[],
                   help="the moments along the segment from P0 to P1, each '(x y z)' or "
                        "x,y,z: line<k>.png and .csv (k = 1, 2, ... in the order given); "
                        "repeatable")
    p.add_argument("--psd", nargs="*", metavar="NAME", default=None,
                   help="size distribution functions (cloudFunctions) to report: their "
                        "time-averaged PSD at every probe/zone against the exact "
                        "distribution (sizeDistribution.png, sizeDistribution.csv); "
                        "no NAME: every one found")
    p.add_argument("--psd-compare", metavar="DIR", default=None,
                   help="a second case whose PSD of the same NAME is plotted beside")
    p.add_argument("--density", type=positive("density in kg/m3"), default=None,
                   metavar="RHO",
                   help="the particles' density [kg/m3] for the diameters: the PSD's plot in "
                        "diameter (sizeDistributionDiameter.png), the maps' and lines' "
                        "diameter of the mean mass (default: the case's 'particles')")
    p.add_argument("--mass-unit", type=positive("mass unit in kg"), default=None,
                   metavar="KG",
                   help="kg per unit of the particles' masses (default: the case's "
                        "'particles' massUnit, else 1)")
    g = p.add_argument_group("checks (exit 1 on failure)")
    g.add_argument("--check", action="store_true",
                   help="compare every cell mean with the analytic cell average")
    g.add_argument("--check-rel-tol", type=positive("relative tolerance"), default=0.03,
                   help="--check: largest allowed |mean - analytic|/analytic (default 0.03)")
    g.add_argument("--check-sigma", type=positive("number of standard errors"), default=None,
                   metavar="Z",
                   help="--check: a cell moment outside --check-rel-tol fails only if it is also "
                        "more than Z standard errors (ci95/1.96) off (default: the tolerance "
                        "alone)")
    g.add_argument("--check-skip-cells", type=whole_number, default=0,
                   help="--check: ignore this many cells at the inlet (default 0)")
    g.add_argument("--check-moments", type=moment_list, default=None,
                   help="--check: comma-separated moment orders (default: all)")
    g.add_argument("--check-cell-index", type=int, action="append", metavar="I",
                   help="cell index (sorted by x; negative counts from the outlet) of a "
                        "--check-value; once for all values or once per value")
    g.add_argument("--check-moment", type=whole_number, action="append", metavar="K",
                   help="moment order of a --check-value; once for all or once per value")
    g.add_argument("--check-value", type=number("a finite number"), action="append",
                   metavar="V",
                   help="expected cell mean; repeatable")
    g.add_argument("--check-value-rel-tol", type=positive("relative tolerance"),
                   action="append", metavar="TOL",
                   help="relative tolerance of a --check-value; once for all or once per value "
                        "(default 0.01)")
    g.add_argument("--check-psd-bins", type=bin_range, metavar="A:B", default=None,
                   help="check the PSD bins A..B (1-based, inclusive) at every region against "
                        "the exact distribution: at least 85 %% inside the 95 %% intervals, "
                        "none beyond 4 half-widths/1.96")
    g.add_argument("--check-psd-m0", action="store_true",
                   help="check the PSD's sum against M0 of the probe's cell (moment samples), and "
                        "the solver's CSV averages against the samples")
    # a point of --line (or of an abbreviation of it) that starts with a minus (-0.1,0,0)
    # is a value, not an option
    argv = list(argv)
    for i, token in enumerate(argv):
        if len(token) > 3 and "--line".startswith(token):
            for j in (i + 1, i + 2):
                if j < len(argv) and re.match(r"-[\d.]", argv[j]):
                    argv[j] = " " + argv[j]
    args = p.parse_args(argv)
    try:
        args.slices = [parse_slice(t) for t in args.slice]
        args.lines = [(parse_point(a), parse_point(b)) for a, b in args.line]
    except ValueError as e:
        p.error(str(e))
    if args.no_plots and (args.slices or args.lines):
        p.error("--slice and --line draw pictures: not with --no-plots")
    stems = ["%s%g" % ("xyz"[a], v) for a, v in args.slices]
    if len(set(stems)) != len(stems):
        p.error("--slice: a plane given twice (%s)" % ", ".join(stems))
    for a, b in args.lines:
        if a == b:
            p.error("--line: the two points are the same (%g %g %g)" % tuple(a))

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


def parse_slice(text):
    """'z=0.025' -> (2, 0.025)"""
    axis, _, value = text.partition("=")
    if axis.strip() not in ("x", "y", "z") or not value.strip():
        raise ValueError("--slice %s: give AXIS=VALUE with AXIS x, y or z (z=0.025)" % text)
    try:
        v = float(value)
    except ValueError:
        raise ValueError("--slice %s: %s is not a number" % (text, value)) from None
    if not math.isfinite(v):
        raise ValueError("--slice %s: %s is not a finite number" % (text, value))
    return "xyz".index(axis.strip()), v


def parse_point(text):
    """'(0 0.1 0)' or '0,0.1,0' -> [0, 0.1, 0]"""
    parts = text.replace("(", " ").replace(")", " ").replace(",", " ").split()
    try:
        point = [float(v) for v in parts]
    except ValueError:
        point = []
    if len(point) != 3 or not all(math.isfinite(v) for v in point):
        raise ValueError("--line %s: a point is three numbers, '(x y z)' or x,y,z, each "
                         "finite" % text.strip())
    return point


def material(args, res):
    """(density, kg per mass unit) for the maps' and lines' diameters: --density and
    --mass-unit, else the samples' attributes (the case's 'particles'); None without a
    density. The options' values are positive (parse_args) and never replaced."""
    density = args.density if args.density is not None else res["meta"].get("density")
    unit = args.mass_unit if args.mass_unit is not None else res["meta"].get("massUnit") or 1.0
    return (density, unit) if density else None


def report_sections(args, res, out, dims):
    """The slices and lines of a mesh: those asked for, or on a 3-D mesh the plane through
    its middle across its thinnest extent; their files."""
    import numpy as np
    from coagulationPost import sections

    slices, lines = args.slices, args.lines
    asked = bool(slices or lines)
    centres = np.asarray(res["centres"], float)
    if not asked:
        if dims < 3:
            return []
        lo, hi = centres.min(axis=0), centres.max(axis=0)
        # of extents equal to round-off the last axis (z before y: a square channel along x
        # is cut in its x-y plane)
        extent = np.round((hi - lo) / max((hi - lo).max(), 1e-300), 6)
        axis = int(max(range(3), key=lambda k: (-extent[k], k)))
        slices = [(axis, 0.5 * (lo[axis] + hi[axis]))]
    case = args.realisations[0] if args.realisations else args.case
    try:
        mesh = sections.read_mesh(case)
    except ValueError as e:
        if asked:
            raise InputError("--slice/--line need the case's mesh: %s" % e) from None
        print("a three-dimensional mesh without a readable constant/polyMesh (%s): no maps "
              "(moments_full.csv has every cell's)" % e)
        return []
    cell_of_row = sections.match_cells(mesh, centres)
    if cell_of_row is None:
        msg = ("the cells of %s/constant/polyMesh (%d) do not match the samples' %d cell "
               "centres" % (case, mesh["nCells"], len(centres)))
        if asked:
            raise InputError(msg)
        print("%s: no maps (moments_full.csv has every cell's)" % msg)
        return []
    title = os.path.basename(os.path.abspath(case))
    written = []
    try:
        for axis, value in slices:
            written += maps.slice_figure(res, out, mesh, cell_of_row, axis, value, title,
                                         material(args, res))
        for k, (p0, p1) in enumerate(lines):
            written += maps.line_figure(res, out, mesh, cell_of_row, p0, p1,
                                        "line%d" % (k + 1), title, material(args, res))
    except ValueError as e:
        raise InputError(str(e)) from None
    return written


def report_psd(args, res, out, u, written):
    """The size distributions of --psd: CSV of the averages, plots, checks. The exact
    distribution as --analytic says: auto where the moment report has a reference and the
    distribution's attributes describe the paper's duct too (else a line says why), none
    with none, wherever there is one with a reference named."""
    names = args.psd or psd.function_names(args.case)
    if not names:
        raise InputError("--psd: no size distribution under %s/postProcessing" % args.case)
    ok = True
    for name in names:
        p = psd.read(args.case, name)
        mean, neff, ci, tau = psd.average(p, u=u, x_inlet=args.x_inlet,
                                          correlation_time=args.correlation_time)
        why = None
        if args.analytic == "none":
            why = "--analytic none"
        elif args.analytic == "auto":
            why = res["meta"].get("analyticMismatch") or analytic.not_the_papers_duct(p["attrs"])
            if why:
                print("PSD %s: no exact distribution: %s" % (name, why))
        reference = why is None
        ref = psd.exact(p, u, args.x_inlet) if reference else None
        path = os.path.join(out, "sizeDistribution_%s.csv" % name)
        with open(path, "w") as f:
            f.write("region,name,x,column,mean,neff,tauInt,ci95,exact\n")
            for r, rn in enumerate(p["regions"]):
                for j, col in enumerate(p["columns"]):
                    ex = ref[r, j] if (ref is not None and j < p["nBins"]) else float("nan")
                    f.write("%d,%s,%.8g,%s,%.10g,%.6g,%.6g,%.6g,%.10g\n"
                            % (r, rn, p["centres"][r, 0], col, mean[r, j], neff[r, j],
                               tau[r, j], ci[r, j], ex))
        written.append(path)
        if not args.no_plots:
            runs, labels = [p], [os.path.basename(os.path.abspath(args.case))]
            if args.psd_compare:
                runs.append(psd.read(args.psd_compare, name))
                labels.append(os.path.basename(os.path.abspath(args.psd_compare)))
            d = os.path.join(out, name)
            written += psd.figures(runs, d, u, args.x_inlet, labels, reference)
            more = psd.diameter_figure(runs, d, u, args.x_inlet, labels, args.density,
                                       args.mass_unit, reference)
            if not more:
                print("PSD %s: no particle density (give the case 'particles { density ...; }'"
                      " or --density): no plot in diameter" % name)
            written += more
        if args.check_psd_bins:
            a, b = args.check_psd_bins
            if ref is None:
                raise InputError("--check-psd-bins: no exact distribution (%s)"
                                 % (why or "kernel %s, bins %s of %g to %g"
                                    % (p["attrs"].get("kernel"), p["binType"], p["edges"][0],
                                       p["edges"][-1])))
            if b > p["nBins"]:
                raise InputError("--check-psd-bins %d:%d: %s has %d bins"
                                 % (a, b, name, p["nBins"]))
            good, _, lines = psd.check(p, ref, list(range(a - 1, b)), mean, ci)
            print("\n".join("PSD %s: %s" % (name, l) for l in lines))
            ok = ok and good
        if args.check_psd_m0:
            good, lines = psd.check_m0(p, args.case)
            more_ok, more = psd.check_csv(p, args.case)
            good, lines = good and more_ok, lines + more
            print("\n".join("PSD %s: %s" % (name, l) for l in lines))
            ok = ok and good
    return ok


def main(argv=None):
    try:  # behave like a normal filter under `| head`
        import signal
        signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    except (ImportError, AttributeError, ValueError):
        pass
    args = parse_args(sys.argv[1:] if argv is None else argv)
    try:
        res = report.compute(args.realisations if args.realisations else [args.case],
                             t_relax=args.t_relax, t_end=args.t_end, u=args.u,
                             x_inlet=args.x_inlet, analytic_kind=args.analytic,
                             correlation_time=args.correlation_time)
        out = args.out if os.path.isabs(args.out) else os.path.join(args.case, args.out)
        os.makedirs(out, exist_ok=True)
        report.print_table(res, args.t_end)
        written = report.write_csv(res, out)
        written.append(report.write_summary(res, out, args.t_end))
        dims = maps.dimension(res["centres"])
        if args.no_plots:
            pass
        elif dims <= 1:
            # along the duct (or a single cell): the moments against x
            written += plots.report_figures(res, out, args.x_inlet, args.t_end,
                                            args.check_rel_tol if args.check else None)
        elif dims == 2:
            written += maps.map_figure(res, out, os.path.basename(os.path.abspath(args.case)),
                                       args.case, material(args, res))
        if not args.no_plots:
            written += report_sections(args, res, out, dims)
        ok = True
        if args.check:
            ok = checks.check_analytic(res, args.check_rel_tol, args.check_skip_cells,
                                       args.check_moments, args.analytic, args.check_sigma)
        ok = checks.check_values(res, args.value_checks) and ok
        if args.psd is not None:
            ok = report_psd(args, res, out, res["meta"]["u"], written) and ok
    except InputError as e:
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
