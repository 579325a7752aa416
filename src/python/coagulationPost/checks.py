# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Acceptance checks of coagulationReport and coagulationTables.

Report (one case or pooled realisations, coagulationPost.report.compute):
  check_analytic   every cell mean within a relative tolerance of the analytic
                   cell average (prints one CHECK FAILED line per failure)
  check_values     single cell means against given values
Tables (rows of coagulationPost.tables), the paper's acceptance statements:
  Acceptance       their references and tolerances (the command line's defaults)
  table_checks     SWA M1/M2 means, sd ~ n^-1/2, normalised sd against eq. (47),
                   the DSA1 bias and the DSA2 trend
"""

import dataclasses
import math

import numpy as np

from . import analytic, statistics
from .samples import InputError
from .tables import se_of, table_cell


# --------------------------------------------------------------------------- report

def check_analytic(res, rel_tol=0.03, skip_cells=0, moments=None, analytic_option="auto",
                   sigma=None):
    """Every cell from skip_cells on, each of `moments` (default: all with a
    reference): |mean - analytic| / analytic <= rel_tol.  With sigma, a cell moment
    outside the tolerance fails only if it is also more than sigma standard errors off
    (standard error ci95/1.96 from the run's own interval; its half-width carries the
    Student t quantile, so with few degrees of freedom this is a little larger than the
    standard error, 5 % at 25): many cells and moments checked
    at a fixed tolerance near the noise of the noisiest one (M3 near the inlet) fail for
    some random streams, not for a bias.  Returns True when all pass."""
    nm = res["mean"].shape[1]
    ncell = len(res["x"])
    if res["meta"]["analytic"] is None:
        why = res["meta"].get("analyticMismatch")
        raise InputError("--check needs an analytic reference (kernel '%s', --analytic %s)%s"
                         % (res["meta"]["kernel"], analytic_option,
                            ": %s; --analytic KIND draws one whatever the case" % why
                            if why and analytic_option == "auto" else ""))
    if moments is None:
        moments = list(range(min(nm, analytic.N_MOMENTS)))
    for k in moments:
        if k < 0 or k >= min(nm, analytic.N_MOMENTS):
            raise InputError("--check-moments: no moment %d" % k)
    if sigma is not None and not sigma > 0:
        raise InputError("--check-sigma must be > 0")
    nfail = ntested = nsignificance = 0
    for i in range(skip_cells, ncell):
        for k in moments:
            ntested += 1
            m, a, r, c = res["mean"][i, k], res["analytic"][i, k], res["rel"][i, k], res["ci"][i, k]
            within = np.isfinite(r) and abs(r) <= rel_tol
            if not within and sigma is not None and np.isfinite(m) and np.isfinite(c) \
                    and abs(m - a) <= sigma * c / 1.96:
                nsignificance += 1
                continue
            if not within:
                nfail += 1
                print("CHECK FAILED cell %d x=%.6g M%d: mean %.6e analytic %.6e rel.err %+.3f%% "
                      "(tol %.3g%%) ci95 %.3e" % (i, res["x"][i], k, m, a, 100 * r,
                                                 100 * rel_tol, c))
    if nfail:
        print("check: %d of %d cell moments outside the relative tolerance %g"
              % (nfail, ntested, rel_tol))
        return False
    print("check passed: %d cell moments (cells %d..%d, moments %s) within relative "
          "tolerance %g of the analytic cell averages"
          % (ntested - nsignificance, skip_cells, ncell - 1, ",".join(map(str, moments)), rel_tol)
          + ("; %d more outside it but within %g standard errors" % (nsignificance, sigma)
             if nsignificance else ""))
    return True


def check_values(res, value_checks):
    """value_checks: (cell index, moment, expected mean, relative tolerance) tuples;
    negative cell indices count from the outlet.  Returns True when all pass."""
    ok = True
    nm = res["mean"].shape[1]
    ncell = len(res["x"])
    for ci_, k, v, tol in value_checks:
        if not (-ncell <= ci_ < ncell):
            raise InputError("--check-cell-index %d: only %d cells" % (ci_, ncell))
        if not (0 <= k < nm):
            raise InputError("--check-moment %d: the files hold moments 0..%d" % (k, nm - 1))
        i = ci_ % ncell
        m, c = res["mean"][i, k], res["ci"][i, k]
        r = (m - v) / abs(v) if v != 0 else (m - v)
        good = bool(np.isfinite(r) and abs(r) <= tol)
        print("%s cell %d x=%.6g M%d: mean %.6e ± %.3e expected %.6e rel.err %+.3f%% (tol %.3g%%)"
              % ("check passed:" if good else "CHECK FAILED", i, res["x"][i], k, m, c, v,
                 100 * r, 100 * tol))
        ok = ok and good
    return ok


# --------------------------------------------------------------------------- tables

@dataclasses.dataclass
class Acceptance:
    """References and tolerances of table_checks (see coagulationTables.py --help)."""
    table_x: float = 0.099          # x inside the table cell [0.098, 0.1]
    swa_m1_ref: float = 9.877e3
    swa_m1_tol: float = 0.002
    swa_m2_ref: float = 9.1e7
    swa_m2_tol: float = 0.03
    m1_exact: float = 9.90e3        # eq. (50) at the cell centre
    z_ci: float = 0.0
    z: float = 3.0
    z_dsa1: float | None = None     # None: z
    sd_exponent_tol: float = 0.1
    nsd_tol: float = 0.10
    nsd_skip_cells: int = 3


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


def table_checks(rows, acc):
    """The paper's acceptance statements on the additive-kernel rows present; acc an
    Acceptance.  Returns a Checks (lines, run, failed)."""
    chk = Checks()
    add = [r for r in rows if r["kernel"] == "additive"]
    by = {m: sorted([r for r in add if r["method"] == m], key=lambda r: r["n"])
          for m in ("SWA", "DSA1", "DSA2")}
    swa, dsa1, dsa2 = by["SWA"], by["DSA1"], by["DSA2"]
    x = acc.table_x

    if not swa:
        chk.skip("no additive-kernel SWA row")
    for r in swa:
        i = table_cell(r, x)
        mean_check(chk, r, i, 1, acc.swa_m1_ref, acc.swa_m1_tol, acc.z_ci, "Table 1")
        mean_check(chk, r, i, 2, acc.swa_m2_ref, acc.swa_m2_tol, acc.z_ci, "Table 2")
    if len(swa) >= 2:
        ns = [r["n"] for r in swa]
        for k in (1, 2):
            sds = [r["sd"][table_cell(r, x), k] for r in swa]
            rel_se = [r["sdSE"][table_cell(r, x), k] / r["sd"][table_cell(r, x), k] for r in swa]
            e = statistics.fit_exponent(ns, sds)
            # standard error of the fitted exponent from the sds' relative errors
            lx = np.log(np.asarray(ns, float))
            e_se = math.sqrt(sum((w * q) ** 2 for w, q in
                                 zip((lx - lx.mean()) / ((lx - lx.mean()) ** 2).sum(), rel_se)))
            allowed = acc.sd_exponent_tol + acc.z_ci * e_se
            chk.result(abs(e + 0.5) <= allowed,
                       "SWA sd of M%d ~ n^%.3f over n = %s (expected -0.5, allowed ± %.3g = %g + %g"
                       " SE, SE %.3g); sd = %s" % (k, e, ns, allowed, acc.sd_exponent_tol, acc.z_ci,
                                                  e_se, ", ".join("%.4g" % s for s in sds)))
    elif swa:
        chk.skip("sd ~ n^-1/2 needs two SWA rows")
    for r in swa:
        cells = np.arange(acc.nsd_skip_cells, len(r["x"]))
        if cells.size == 0:
            raise InputError("--nsd-skip-cells %d leaves no cell of %d" % (acc.nsd_skip_cells,
                                                                           len(r["x"])))
        ref = analytic.normalised_sd_m1(r["x"][cells], r["I"], r["V1"], r["u"])
        rel = r["nsd"][cells, 1] / ref - 1
        allowed = acc.nsd_tol + acc.z_ci * r["sdSE"][cells, 1] / r["sd"][cells, 1]
        worst = int(np.argmax(np.abs(rel) / allowed))
        chk.result(bool(np.all(np.abs(rel) <= allowed)),
                   "SWA n=%d normalised sd of M1 vs eq. (47) in cells %d..%d: worst %+.1f%% at x=%.4g"
                   " (allowed %.1f%% = %g%% + %g SE of the sd), mean over cells %+.1f%%"
                   % (r["n"], cells[0], cells[-1], 100 * rel[worst], r["x"][cells[worst]],
                      100 * allowed[worst], 100 * acc.nsd_tol, acc.z_ci, 100 * float(np.mean(rel))))

    if not dsa1:
        chk.skip("no additive-kernel DSA1 row")
    for r in dsa1:
        i = table_cell(r, x)
        se, src = se_of(r, i, 1)
        z = (r["mean"][i, 1] - acc.m1_exact) / se
        z_dsa1 = acc.z if acc.z_dsa1 is None else acc.z_dsa1
        chk.result(z > z_dsa1, "DSA1 n=%d M1 mean %.6g above %.6g by %.2f SE (SE %.3g from %s,"
                   " R=%d; need > %g)" % (r["n"], r["mean"][i, 1], acc.m1_exact, z, se, src, r["R"],
                                          z_dsa1))

    if len(dsa2) >= 2:
        lo, hi = dsa2[0], dsa2[-1]
        il, ih = table_cell(lo, x), table_cell(hi, x)
        sl, _ = se_of(lo, il, 2)
        sh, _ = se_of(hi, ih, 2)
        z = (hi["mean"][ih, 2] - lo["mean"][il, 2]) / math.hypot(sl, sh)
        chk.result(z > acc.z, "DSA2 M2 mean rises from %.4g (n=%d) to %.4g (n=%d): %.2f combined SE"
                   " (need > %g)" % (lo["mean"][il, 2], lo["n"], hi["mean"][ih, 2], hi["n"], z, acc.z))
        target = swa[-1]["mean"][table_cell(swa[-1], x), 2] if swa else acc.swa_m2_ref
        chk.result(abs(hi["mean"][ih, 2] - target) < abs(lo["mean"][il, 2] - target),
                   "DSA2 M2 at n=%d is closer than at n=%d to the SWA value %.4g"
                   % (hi["n"], lo["n"], target))
    else:
        chk.skip("the DSA2 trend needs two DSA2 rows")
    return chk
