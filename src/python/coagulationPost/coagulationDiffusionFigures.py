# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Plots and summaries of Sabelfeld-Kolodko's Figs 2-10 from the CSV files written by
build/applications/studies/coagulationDiffusionFigures.

    python3 -m coagulationPost.coagulationDiffusionFigures fig2      fig2.csv      OUTDIR
        -> Fig2.png
    python3 -m coagulationPost.coagulationDiffusionFigures figs3to8  figs3to8.csv  OUTDIR [column.csv]
        -> Fig3..Fig8.png; column.csv: the third column, coagulationFoam's n_l at t' = 1, 5, 10
        (tests/benchmarks/coagulationDiffusionColumn.sh, coagulationPost.coagulationDiffusionColumn),
        shown at x = 0 (divided by its f)
    python3 -m coagulationPost.coagulationDiffusionFigures figs9to10 figs9to10.csv OUTDIR
        -> Fig9.png, Fig10.png

Each prints the numbers the README quotes. Exit status 1 if a check fails: fig2, the Monte
Carlo F above F_R; figs3to8, more of the estimator's 95 % intervals (monomers, one per time: the
sizes share their paths) miss the closed-form n^L than a binomial(n, 0.05) allows at the 0.5 %
level; figs9to10, the same for N^D and N^CD, or
N^D/N^CD - 1 above 5 % at b = 0.01 (any t'), or (N^D - N^CD)/N^CD not above 1 (interval) at b = 1, t' = 1.
Exit status 2: bad arguments.
"""
import csv
import os
import sys

from .statistics import Z95


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def read(path):
    """The rows of a CSV file as dicts of strings."""
    with open(path) as f:
        return list(csv.DictReader(f))


def allowed(n, p=0.05, level=0.005):
    """The misses allowed among n intervals of coverage 1 - p: the smallest k with
    P(Bin(n, p) > k) < level (more than k misses has probability below level; the
    binomial's quantile at 1 - level, scipy.stats.binom.ppf(1 - level, n, p), but for ties)."""
    pk = (1 - p) ** n
    cdf = pk
    k = 0
    while 1 - cdf >= level and k < n:
        pk *= (n - k) / (k + 1.0) * p / (1 - p)
        cdf += pk
        k += 1
    return k


def fig2(rows, out):
    plt = _pyplot()
    ok = True
    plt.figure(figsize=(6, 4))
    for D in sorted({r["D"] for r in rows}, key=float):
        rs = [r for r in rows if r["D"] == D]
        t = [float(r["t"]) for r in rs]
        FR = [float(r["FR"]) for r in rs]
        plt.plot(t, FR, label="F_R, D = %s R$^2$" % D)
        imax = max(range(len(FR)), key=lambda i: FR[i])
        print("D/R^2 = %s: max F_R = %.4f at t' = %g" % (D, FR[imax], t[imax]))
        mc = [r for r in rs if r["F"]]
        if mc:
            plt.errorbar([float(r["t"]) for r in mc], [float(r["F"]) for r in mc],
                         yerr=[float(r["F_hw"]) for r in mc], fmt="o", ms=3,
                         color=plt.gca().lines[-1].get_color())
        for r in mc:
            F, hw, fr = float(r["F"]), float(r["F_hw"]), float(r["FR"])
            print("    t' = %s: F = %.5f +- %.2g, F_R = %.5f, F/F_R = %.3f"
                  % (r["t"], F, hw, fr, F / fr if fr > 0 else float("nan")))
            if F - hw > fr:
                ok = False
                print("    FAIL: F above F_R")
    plt.xlabel("t' = t K11 n0")
    plt.ylabel("F_R(t', 0) (lines), Monte Carlo F (K = 1, points)")
    plt.title("Fig 2: effective source bound at x = 0, plane")
    plt.legend(fontsize=7)
    plt.tight_layout()
    plt.savefig(os.path.join(out, "Fig2.png"), dpi=110)
    plt.close()
    return ok


def foam_rows(path):
    """coagulationFoam's column (coagulationDiffusionColumn compare's CSV, '#' lines
    skipped), rescaled to x = 0: tuples (t', l, n/f, Z95 se/f, z_E, z_L); [] without a path."""
    if not path:
        return []
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    rows = []
    for r in csv.DictReader(lines):
        f = float(r["f"])
        rows.append((float(r["t'"]), int(r["l"]), float(r["n_coagulationFoam"]) / f,
                     Z95 * float(r["se"]) / f, float(r["z_E"]), float(r["z_L"])))
    return rows


def monomer_misses(rows):
    """(misses, intervals): the monomer rows (l = 1) whose 95 % interval nL +- nL_hw misses
    the closed form nLexact; the sizes of one time share their paths, so one check per time.
    A zero half-width (every path ended in G, early times: the Wald interval degenerates)
    misses when nL is off by more than 1e-4 relative."""
    misses, n = 0, 0
    for r in rows:
        if r["l"] != "1":
            continue
        diff, hw = abs(float(r["nL"]) - float(r["nLexact"])), float(r["nL_hw"])
        n += 1
        misses += diff > hw if hw > 0 else diff > 1e-4 * float(r["nLexact"])
    return misses, n


def figs3to8(rows, out, column=None):
    plt = _pyplot()
    ok = True
    foam = foam_rows(column)
    haveE = bool(rows[0]["nE"])
    misses, n = monomer_misses(rows)
    print("n^L estimator against its closed form u_l(t') N^D: %d of %d monomer intervals miss "
          "(allowed %d)" % (misses, n, allowed(n)))
    if misses > allowed(n):
        ok = False
        print("FAIL: too many misses")
    times = sorted({float(r["t"]) for r in rows})
    # Figs 3-5: against size at t' = 1, 5, 10
    for fig, tt in ((3, 1.0), (4, 5.0), (5, 10.0)):
        rs = [r for r in rows if abs(float(r["t"]) - tt) < 1e-9]
        if not rs:
            continue
        l = [int(r["l"]) for r in rs]
        plt.figure(figsize=(6, 4))
        plt.errorbar(l, [float(r["nL"]) for r in rs], yerr=[float(r["nL_hw"]) for r in rs],
                     fmt="o", ms=3, label="n^L, adjoint estimator (95 %)")
        plt.plot(l, [float(r["nLexact"]) for r in rs], "-", lw=0.8, label="n^L closed form")
        if haveE:
            plt.plot(l, [float(r["nE"]) for r in rs], "s-", ms=3, label="n^E Eulerian reference")
        fr = [x for x in foam if x[0] == tt and x[2] > 0]
        if fr:
            plt.errorbar([x[1] for x in fr], [x[2] for x in fr], yerr=[x[3] for x in fr], fmt="^",
                         ms=4, mfc="none", label="coagulationFoam (95 %)")
        plt.yscale("log")
        plt.xlabel("size l")
        plt.ylabel("n_l(t', 0)")
        plt.title("Fig %d: t' = %g, D = 8.88e-2 R$^2$, K = 1" % (fig, tt))
        plt.legend(fontsize=7)
        plt.tight_layout()
        plt.savefig(os.path.join(out, "Fig%d.png" % fig), dpi=110)
        plt.close()
        if haveE:
            for size in (1, 5, 10, 15, 20):
                m = [r for r in rs if int(r["l"]) == size]
                if m:
                    r = m[0]
                    print("t' = %g, l = %d: n^E = %.4g, n^L = %.4g +- %.2g, n^E/n^L = %.3f"
                          % (tt, size, float(r["nE"]), float(r["nL"]), float(r["nL_hw"]),
                             float(r["nE"]) / float(r["nL"])))
    # Figs 6-8: sizes 1, 5, 10 against t'
    for fig, size in ((6, 1), (7, 5), (8, 10)):
        rs = [r for r in rows if int(r["l"]) == size]
        t = [float(r["t"]) for r in rs]
        plt.figure(figsize=(6, 4))
        plt.errorbar(t, [float(r["nL"]) for r in rs], yerr=[float(r["nL_hw"]) for r in rs],
                     fmt="o", ms=3, label="n^L, adjoint estimator (95 %)")
        plt.plot(t, [float(r["nLexact"]) for r in rs], "-", lw=0.8, label="n^L closed form")
        if haveE:
            plt.plot(t, [float(r["nE"]) for r in rs], "s-", ms=3, label="n^E Eulerian reference")
        fr = [x for x in foam if x[1] == size]
        if fr:
            plt.errorbar([x[0] for x in fr], [x[2] for x in fr], yerr=[x[3] for x in fr], fmt="^",
                         ms=5, mfc="none", label="coagulationFoam (95 %)")
        plt.xlabel("t'")
        plt.ylabel("n_%d(t', 0)" % size)
        plt.title("Fig %d: size %d at x = 0, D = 8.88e-2 R$^2$, K = 1" % (fig, size))
        plt.legend(fontsize=7)
        plt.tight_layout()
        plt.savefig(os.path.join(out, "Fig%d.png" % fig), dpi=110)
        plt.close()
    print("times: %d from t' = %g to %g" % (len(times), times[0], times[-1]))
    for tt in sorted({x[0] for x in foam}):
        fr = [x for x in foam if x[0] == tt and x[3] > 0]
        zE = max(abs(x[4]) for x in fr)
        zL = max(abs(x[5]) for x in fr)
        print("coagulationFoam at t' = %g, sizes %d..%d with particles: |z| against n^E at most "
              "%.2f, against n^L at most %.2f; monomers %.4g +- %.2g (at x = 0)"
              % (tt, fr[0][1], fr[-1][1], zE, zL, fr[0][2], fr[0][3]))
    return ok


def estimator_misses(rows):
    """(misses, intervals): the 95 % intervals of N^D and N^CD (ND_est +- ND_hw,
    NCD_est +- NCD_hw) that miss the formulas ND, NCD; every estimate has its own paths."""
    misses, n = 0, 0
    for r in rows:
        n += 2
        misses += abs(float(r["ND_est"]) - float(r["ND"])) > float(r["ND_hw"])
        misses += abs(float(r["NCD_est"]) - float(r["NCD"])) > float(r["NCD_hw"])
    return misses, n


def excess_interval(r):
    """Bounds of (N^D - N^CD)/N^CD from the two estimators' intervals of row r:
    (ND_est - ND_hw)/(NCD_est + NCD_hw) - 1 and (ND_est + ND_hw)/(NCD_est - NCD_hw) - 1."""
    lo = (float(r["ND_est"]) - float(r["ND_hw"])) / (float(r["NCD_est"]) + float(r["NCD_hw"])) - 1
    hi = (float(r["ND_est"]) + float(r["ND_hw"])) / (float(r["NCD_est"]) - float(r["NCD_hw"])) - 1
    return lo, hi


def figs9to10(rows, out):
    plt = _pyplot()
    ok = True
    misses, n = estimator_misses(rows)
    print("N^D, N^CD estimators against (29), (30): %d of %d intervals miss (allowed %d)"
          % (misses, n, allowed(n)))
    if misses > allowed(n):
        ok = False
        print("FAIL: too many misses")
    for fig, x in ((9, "0"), (10, "1.5")):
        plt.figure(figsize=(6, 4))
        rs = [r for r in rows if r["x"] == x]
        t = [float(r["t"]) for r in rs if r["b"] == "0.01"]
        plt.plot(t, [float(r["ND"]) for r in rs if r["b"] == "0.01"], "k-", label="N^D (29)")
        for b in ("0.01", "0.1", "1"):
            rb = [r for r in rs if r["b"] == b]
            line, = plt.plot(t, [float(r["NCD"]) for r in rb], "-", label="N^CD (30), b = %s" % b)
            plt.errorbar(t, [float(r["NCD_est"]) for r in rb],
                         yerr=[float(r["NCD_hw"]) for r in rb], fmt="o", ms=2,
                         color=line.get_color())
            worst = max(float(r["ND"]) / float(r["NCD"]) - 1 for r in rb)
            r1 = [r for r in rb if abs(float(r["t"]) - 1.0) < 1e-9]
            msg = "x' = (%s, 0), b = %s: sup_t' (N^D - N^CD)/N^CD = %.4f (formula)" % (x, b, worst)
            if r1:
                r = r1[0]
                lo, hi = excess_interval(r)
                rel = float(r["ND"]) / float(r["NCD"]) - 1
                msg += "; at t' = 1: formula %.4f, estimator [%.4f, %.4f]" % (rel, lo, hi)
                if b == "1" and not (rel > 1 and lo > 1):
                    ok = False
                    msg += "  FAIL (not > 100 %)"
            if b == "0.01" and worst > 0.05:
                ok = False
                msg += "  FAIL (not within 5 %)"
            print(msg)
        plt.xlabel("t' = t D / R$^2$")
        plt.ylabel("monomers / n0")
        plt.title("Fig %d: x' = (%s, 0), Saffman-Turner, K11 = 1" % (fig, x))
        plt.legend(fontsize=7)
        plt.tight_layout()
        plt.savefig(os.path.join(out, "Fig%d.png" % fig), dpi=110)
        plt.close()
    return ok


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) not in (3, 4) or argv[0] not in ("fig2", "figs3to8", "figs9to10") or (
            len(argv) == 4 and argv[0] != "figs3to8"):
        print(__doc__)
        return 2
    os.makedirs(argv[2], exist_ok=True)
    if argv[0] == "figs3to8":
        ok = figs3to8(read(argv[1]), argv[2], argv[3] if len(argv) == 4 else None)
    else:
        ok = {"fig2": fig2, "figs9to10": figs9to10}[argv[0]](read(argv[1]), argv[2])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
