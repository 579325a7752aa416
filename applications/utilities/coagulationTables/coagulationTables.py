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

A thin command line over the package coagulationPost in <repo>/src/python
(samples, statistics, analytic, tables, plots, checks).
"""

import argparse
import dataclasses
import os
import sys

# the post-processing package, <repo>/src/python/coagulationPost (PYTHONPATH: etc/bashrc)
from coagulationPost import checks, plots, tables
from coagulationPost.samples import InputError


def parse_args(argv):
    A = checks.Acceptance
    p = argparse.ArgumentParser(prog="coagulationTables.py",
                                description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter,
                                epilog="See the module documentation (head of this file).")
    p.add_argument("--rows", nargs="+", required=True, metavar="DIR",
                   help="ensemble folders (coagulationEnsemble -out), one per method and n; "
                        "DIR1+DIR2 pools the realisations of several folders into one row")
    p.add_argument("--out", default="results", help="output folder (default: results)")
    p.add_argument("--table-x", type=float, default=A.table_x,
                   help="x inside the table cell (default 0.099: the cell [0.098, 0.1])")
    p.add_argument("--t-end", type=float, default=None, help="last sample time (default: all)")
    p.add_argument("--no-plots", action="store_true")
    g = p.add_argument_group("checks (exit 1 on failure)")
    g.add_argument("--check", action="store_true")
    g.add_argument("--swa-m1-ref", type=float, default=A.swa_m1_ref)
    g.add_argument("--swa-m1-tol", type=float, default=A.swa_m1_tol)
    g.add_argument("--swa-m2-ref", type=float, default=A.swa_m2_ref)
    g.add_argument("--swa-m2-tol", type=float, default=A.swa_m2_tol)
    g.add_argument("--m1-exact", type=float, default=A.m1_exact, help="eq. (50) at the cell centre")
    g.add_argument("--z-ci", type=float, default=A.z_ci,
                   help="widen the SWA tolerances by this many standard errors (default 0)")
    g.add_argument("--z", type=float, default=A.z,
                   help="significance (standard errors) of the DSA2 trend check (default 3)")
    g.add_argument("--z-dsa1", type=float, default=None,
                   help="significance of the DSA1 bias check (default: --z)")
    g.add_argument("--sd-exponent-tol", type=float, default=A.sd_exponent_tol)
    g.add_argument("--nsd-tol", type=float, default=A.nsd_tol)
    g.add_argument("--nsd-skip-cells", type=int, default=A.nsd_skip_cells)
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
        rows = tables.load_rows(args.rows, args.t_end)
        os.makedirs(args.out, exist_ok=True)
        add = [r for r in rows if r["kernel"] == "additive"]
        written = tables.write_tables(rows, add if add else rows, args.table_x, args.out)
        if not args.no_plots:
            written += plots.table_figures(rows, args.out)
    except InputError as e:
        print("coagulationTables: error: %s" % e, file=sys.stderr)
        return 2
    for k in (1, 2):
        with open(os.path.join(args.out, "table%d.md" % k)) as f:
            print(f.read())
    ok = True
    if args.check:
        acc = checks.Acceptance(**{f.name: getattr(args, f.name)
                                   for f in dataclasses.fields(checks.Acceptance)})
        try:
            chk = checks.table_checks(rows, acc)
        except InputError as e:
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
