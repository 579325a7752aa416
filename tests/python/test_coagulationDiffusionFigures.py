# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.coagulationDiffusionFigures: the misses allowed, the interval checks and
the third column's figures."""

import pytest
from scipy.stats import binom

from coagulationPost import coagulationDiffusionFigures as cdf


def test_allowed_misses_by_hand():
    # n = 4: P(X > 1) = 1 - 0.95^4 - 4 0.05 0.95^3 = 0.0140 >= 0.5 %,
    #        P(X > 2) = 4 0.05^3 0.95 + 0.05^4 = 4.8e-4 < 0.5 %
    assert cdf.allowed(4) == 2
    assert cdf.allowed(1) == 1          # P(X > 0) = 0.05
    assert cdf.allowed(0) == 0


def test_allowed_is_the_binomial_quantile():
    for n in range(1, 201):
        assert cdf.allowed(n) == int(binom.ppf(0.995, n, 0.05)), n


def rows3to8(cases):
    return [dict(l=l, nL=str(nL), nL_hw=str(hw), nLexact=str(ex)) for l, nL, hw, ex in cases]


def test_monomer_misses():
    rows = rows3to8([("1", 1.0, 0.1, 1.2),        # misses
                     ("1", 1.0, 0.5, 1.2),        # covers
                     ("1", 1.0, 0.0, 1.00005),    # no width: within 1e-4 relative
                     ("1", 1.0, 0.0, 1.001),      # no width: off
                     ("2", 1.0, 0.1, 5.0)])       # not a monomer
    assert cdf.monomer_misses(rows) == (2, 4)


def row9to10(ND, ND_est, ND_hw, NCD, NCD_est, NCD_hw):
    return dict(ND=str(ND), ND_est=str(ND_est), ND_hw=str(ND_hw),
                NCD=str(NCD), NCD_est=str(NCD_est), NCD_hw=str(NCD_hw))


def test_estimator_misses_counts_both_estimators():
    rows = [row9to10(1.2, 1.0, 0.1, 1.0, 1.05, 0.1), row9to10(1.0, 1.0, 0.1, 2.0, 1.0, 0.5)]
    assert cdf.estimator_misses(rows) == (2, 4)


def test_excess_interval():
    lo, hi = cdf.excess_interval(row9to10(0, 3.0, 1.0, 0, 1.0, 0.5))
    assert lo == pytest.approx(2.0 / 1.5 - 1)
    assert hi == pytest.approx(7.0)


def test_foam_rows_rescale_to_the_centre(tmp_path):
    p = tmp_path / "column.csv"
    p.write_text("t',l,n_coagulationFoam,se,nE,nL,z_E,z_L,f\n1,1,2,0.5,1,1,+1.50,-2.00,0.5\n"
                 "# t' = 1: |z| ...\n")
    assert cdf.foam_rows(str(p)) == [(1.0, 1, 4.0, pytest.approx(1.96), 1.5, -2.0)]
    assert cdf.foam_rows(None) == []


def test_fig2_fails_when_the_monte_carlo_is_above_the_bound(tmp_path, capsys):
    rows = [dict(D="0.1", t="1", FR="0.3", F="0.25", F_hw="0.01"),
            dict(D="0.1", t="2", FR="0.4", F="", F_hw=""),
            dict(D="0.1", t="4", FR="0.35", F="0.4", F_hw="0.01")]
    assert not cdf.fig2(rows, str(tmp_path))
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "D/R^2 = 0.1: max F_R = 0.4000 at t' = 2"
    assert out[-1] == "    FAIL: F above F_R"
    assert (tmp_path / "Fig2.png").stat().st_size > 0
    rows[2]["F"] = "0.355"                 # within its interval of F_R
    assert cdf.fig2(rows, str(tmp_path))


def test_main_usage():
    assert cdf.main(["fig2", "a.csv", "out", "column.csv"]) == 2
