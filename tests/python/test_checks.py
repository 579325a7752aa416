# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.checks on hand-made results: each check passes on the reference
values, fails just outside its tolerance, and says so."""

import math

import numpy as np
import pytest

from coagulationPost import analytic, checks
from coagulationPost.samples import InputError


def report_result(rel_errors):
    """A coagulationPost.report result of 3 cells x 2 moments with the given relative errors."""
    a = np.array([[1.0, 10.0], [2.0, 20.0], [3.0, 30.0]])
    rel = np.asarray(rel_errors, dtype=float)
    return {"x": np.array([0.1, 0.2, 0.3]), "mean": a * (1 + rel), "analytic": a, "rel": rel,
            "ci": 0.01 * a, "meta": {"analytic": "constantDuct", "kernel": "constant"}}


def test_check_analytic(capsys):
    res = report_result([[0.0, 0.029], [-0.029, 0.0], [0.0, 0.0]])
    assert checks.check_analytic(res, rel_tol=0.03)
    assert "check passed: 6 cell moments (cells 0..2, moments 0,1)" in capsys.readouterr().out
    res = report_result([[0.0, 0.031], [0.0, 0.0], [0.0, np.nan]])
    assert not checks.check_analytic(res, rel_tol=0.03)
    out = capsys.readouterr().out
    assert "CHECK FAILED cell 0 x=0.1 M1" in out and "CHECK FAILED cell 2" in out
    assert "check: 2 of 6 cell moments outside" in out
    assert checks.check_analytic(res, rel_tol=0.03, moments=[0])        # M1 not checked
    res = report_result([[0.5, 0.031], [0.0, 0.0], [0.0, 0.0]])          # bad inlet cell
    assert not checks.check_analytic(res, rel_tol=0.03)
    assert checks.check_analytic(res, rel_tol=0.03, skip_cells=1)
    assert "(cells 1..2, moments 0,1)" in capsys.readouterr().out
    with pytest.raises(InputError, match="no moment 2"):
        checks.check_analytic(res, moments=[2])
    res["meta"]["analytic"] = None
    with pytest.raises(InputError, match="needs an analytic reference"):
        checks.check_analytic(res)


def test_check_analytic_sigma(capsys):
    # ci95 = 1 % of the value: standard error 0.51 %; 3.1 % off is 6.1 standard errors
    res = report_result([[0.0, 0.031], [0.0, 0.0], [0.0, 0.0]])
    assert not checks.check_analytic(res, rel_tol=0.03, sigma=4.0)
    assert checks.check_analytic(res, rel_tol=0.03, sigma=6.5)
    assert "check passed: 5 cell moments (cells 0..2, moments 0,1) within relative tolerance " \
        "0.03 of the analytic cell averages; 1 more outside it but within 6.5 standard errors" \
        in capsys.readouterr().out
    res["ci"] = 0.1 * res["analytic"]                     # 3.1 % off, 0.6 standard errors
    assert checks.check_analytic(res, rel_tol=0.03, sigma=4.0)
    res["mean"][2, 0] = np.nan                            # not finite: fails whatever sigma
    res["rel"][2, 0] = np.nan
    assert not checks.check_analytic(res, rel_tol=0.03, sigma=4.0)
    with pytest.raises(InputError, match="check-sigma must be > 0"):
        checks.check_analytic(res, sigma=0.0)


def test_check_values(capsys):
    res = report_result(np.zeros((3, 2)))
    assert checks.check_values(res, [(-1, 1, 30.0 * 1.0099, 0.01), (0, 0, 1.0, 0.0)])
    assert not checks.check_values(res, [(2, 1, 30.0 * 1.0102, 0.01)])
    assert "CHECK FAILED cell 2 x=0.3 M1" in capsys.readouterr().out
    with pytest.raises(InputError, match="only 3 cells"):
        checks.check_values(res, [(3, 0, 1.0, 0.1)])
    with pytest.raises(InputError, match="moments 0..1"):
        checks.check_values(res, [(0, 2, 1.0, 0.1)])


NC, DX, I, V1 = 50, 2e-3, 1e5, 7.8125e-5


def table_row(method, n, m1=9.877e3, m2=9.1e7, R=3, nsd_factor=1.0, count=153):
    """A coagulationPost.tables row of the additive duct: sds falling like n^-1/2,
    normalised sd of M1 nsd_factor times eq. (47), realisation SEs = sample SEs."""
    x = (np.arange(NC) + 0.5) * DX
    mean = np.tile([1e3, 0.0, 0.0, 1e12], (NC, 1))
    mean[:, 1], mean[:, 2] = I * x, 9.1e7 * (x / 0.099) ** 3
    mean[-1, 1], mean[-1, 2] = m1, m2
    sd = np.empty((NC, 4))
    sd[:] = 0.1 * mean * math.sqrt(2048 / n)
    sd[:, 1] = nsd_factor * analytic.normalised_sd_m1(x, I, V1) * I * x / math.sqrt(n)
    nsd = np.sqrt(n) * sd / mean
    cnt = np.full((NC, 4), float(count))
    return {"method": method, "n": n, "kernel": "additive", "R": R, "x": x, "I": I, "V1": V1,
            "u": 1.0, "edges": (x - DX / 2, x + DX / 2), "mean": mean, "sd": sd, "nsd": nsd,
            "count": cnt, "seR": sd / np.sqrt(cnt), "sdSE": sd / np.sqrt(2 * cnt)}


def test_table_checks_pass_and_fail():
    good = [table_row("SWA", 2048), table_row("SWA", 8192),
            table_row("DSA1", 2048, m1=10.5e3), table_row("DSA2", 2048, m2=3e7),
            table_row("DSA2", 8192, m2=5.5e7)]
    chk = checks.table_checks(good, checks.Acceptance())
    assert (chk.run, chk.failed) == (11, 0), "\n".join(chk.lines)
    assert not any(line.startswith("check skipped") for line in chk.lines)

    # SWA M1 +0.3 % (tolerance 0.2 %), DSA1 on the exact value, DSA2 falling with n
    bad = [table_row("SWA", 2048, m1=9.877e3 * 1.003), table_row("DSA1", 2048, m1=9.9e3),
           table_row("DSA2", 2048, m2=5.5e7), table_row("DSA2", 8192, m2=3e7)]
    chk = checks.table_checks(bad, checks.Acceptance())
    failed = [line for line in chk.lines if line.startswith("CHECK FAILED")]
    assert len(failed) == 4, "\n".join(chk.lines)
    assert failed[0].startswith("CHECK FAILED: Table 1 SWA n=2048 M1 mean 9906.63 vs 9877: +0.300%")
    assert "DSA1 n=2048 M1 mean 9900 above 9900 by 0.00 SE" in failed[1]
    assert "check skipped: sd ~ n^-1/2 needs two SWA rows" in chk.lines
    # --z-ci widens the SWA tolerance by standard errors: 0.1 % more is 3.3 SE here
    chk = checks.table_checks(bad[:1], checks.Acceptance(z_ci=4))
    assert chk.failed == 0, "\n".join(chk.lines)


def test_table_checks_sd_scaling_and_eq47():
    """sd of M2 not falling with n fails the n^-1/2 check; an M1 sd 20 % above
    eq. (47) fails the normalised-sd check (tolerance 10 %)."""
    flat = table_row("SWA", 8192)
    flat["sd"][:, 2] *= 2.0
    chk = checks.table_checks([table_row("SWA", 2048), flat], checks.Acceptance())
    failed = [line for line in chk.lines if line.startswith("CHECK FAILED")]
    assert len(failed) == 1 and failed[0].startswith("CHECK FAILED: SWA sd of M2 ~ n^0.000")
    chk = checks.table_checks([table_row("SWA", 2048, nsd_factor=1.2)], checks.Acceptance())
    failed = [line for line in chk.lines if line.startswith("CHECK FAILED")]
    assert len(failed) == 1 and "normalised sd of M1 vs eq. (47)" in failed[0] and "+20.0%" in failed[0]
    with pytest.raises(InputError, match="leaves no cell"):
        checks.table_checks([table_row("SWA", 2048)], checks.Acceptance(nsd_skip_cells=NC))


def test_dsa1_significance_defaults_to_z():
    """The DSA1 bias check needs z_dsa1 standard errors, z_dsa1 = z unless given."""
    row = table_row("DSA1", 2048)
    row["mean"][-1, 1] = 9.9e3 + 3.5 * row["seR"][-1, 1]          # 3.5 SE above eq. (50)
    assert checks.table_checks([row], checks.Acceptance()).failed == 0          # z = 3
    assert checks.table_checks([row], checks.Acceptance(z=4)).failed == 1       # z_dsa1 = z
    assert checks.table_checks([row], checks.Acceptance(z=4, z_dsa1=3)).failed == 0
