# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.splittingStudy: the schemes' exact expectations, the fits, the pooling
over seeds and the reference runs' tables."""

import math
import warnings

import numpy as np
import pytest

from coagulationPost import splittingStudy as ss

T975_1 = math.tan(0.475 * math.pi)   # Student t with 1 dof is Cauchy: 12.706...


def test_predicted_m1_of_the_two_schemes():
    # cell [0, 2h], h = u dt: Lie's staircase floor(x/h) averages 1/2, Strang's
    # floor(x/h + 1/2) averages 1, which is x/h's own average
    assert ss.predicted_m1("Lie", 1e-3, 0.0, 2e-3, rate=1.0) == pytest.approx(0.5e-3, rel=1e-4)
    assert ss.predicted_m1("Strang", 1e-3, 0.0, 2e-3, rate=1.0) == pytest.approx(1e-3, rel=1e-4)
    # the first cell of Lie with h = the cell: nothing incepted (but for the trapezoidal
    # rule's half step at the cell's end), against I x/u = 100 on average
    assert ss.predicted_m1("Lie", 2e-3, 0.0, 2e-3) == pytest.approx(0.0, abs=1e-3)


def test_predicted_m1_of_strang_sas():
    # S(dt/2) A(dt) S(dt/2): half a step's cohort moves h in its own step, half does not,
    # floor(x/h) + 1/2; on [0, 5h/3] it averages (1/2 + 3/2 (2/3))/(5/3) = 0.9, Strang's
    # floor(x/h + 1/2) 0.8 and x/h itself 5/6
    h = 1e-3
    assert ss.predicted_m1("StrangSAS", h, 0.0, 5 * h / 3, rate=1.0) == pytest.approx(0.9e-3, rel=1e-4)
    assert ss.predicted_m1("Strang", h, 0.0, 5 * h / 3, rate=1.0) == pytest.approx(0.8e-3, rel=1e-4)
    # on whole multiples of h it is x/h's own average (second order)
    assert ss.predicted_m1("StrangSAS", h, 0.0, 4 * h, rate=1.0) == pytest.approx(2e-3, rel=1e-4)


def test_runs_of_one_scheme_only(tmp_path):
    for name in ("A_Strang_3e-4", "A_StrangSAS_3e-4", "A_Lie_3e-4", "C_Strang_4e-4_r1"):
        (tmp_path / name).mkdir()
    names = lambda part, sc: sorted(p.rsplit("/", 1)[1] for p in ss.runs_of(str(tmp_path), part, sc))
    assert names("A", "Strang") == ["A_Strang_3e-4"]
    assert names("A", "StrangSAS") == ["A_StrangSAS_3e-4"]
    assert names("C", "Strang") == ["C_Strang_4e-4_r1"]


def test_slope_of_the_absolute_errors():
    assert ss.slope([1.0, 2.0, 4.0], [-1.0, -4.0, -16.0]) == pytest.approx(2.0)


def test_pooled_student_interval():
    mean, hw, R = ss.pooled([[1.0, 2.0], [3.0, 6.0]])
    assert R == 2
    assert mean.tolist() == [2.0, 4.0]
    # sd of (1, 3) = sqrt 2, se = 1; of (2, 6): se = 2
    assert hw == pytest.approx([T975_1, 2 * T975_1])
    mean, hw, R = ss.pooled([[1.0, 2.0]])
    assert R == 1 and np.isnan(hw).all()


def test_pooled_infinite_errors_quietly():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mean, hw, R = ss.pooled([[np.inf, 1.0], [np.inf, 3.0]])
    assert mean[0] == np.inf and np.isnan(hw[0])
    assert hw[1] == pytest.approx(T975_1)


def test_weighted_log_slope():
    # two points at log dt = 0, 1 with errors exp(2 log dt) and se = |err| (weights 1):
    # slope 2, covariance (X'X)^-1 = [[2, -1], [-1, 1]]: standard error sqrt 2
    dts = np.array([1.0, math.e])
    errs = dts ** 2
    b, se = ss.weighted_log_slope(dts, errs, 1.96 * errs)
    assert b == pytest.approx(2.0)
    assert se == pytest.approx(math.sqrt(2.0))


def test_reference_lines():
    rel = ss.reference_lines(["ductReference SWA n = 4096", "cell 0 M1 +1.5%",
                              "cell 2 M3 -0.25%", "cell 1 M0 inf%"], ncells=3)
    assert rel[0, 1] == pytest.approx(0.015)
    assert rel[2, 3] == pytest.approx(-0.0025)
    assert rel[1, 0] == np.inf
    assert np.count_nonzero(rel) == 3


def test_part_d_table(tmp_path):
    # seeds 1 and 2 of the M1 cell-0 error: 1 % and 3 %: +2.00 +- t(1) 1 %
    for scheme in ("Lie", "Strang"):
        for dt in ("2e-3", "4e-3"):
            for r, e in ((1, 1.0), (2, 3.0)):
                lines = ["cell %d M%d %s%%" % (i, k, (("%+.4f" % e) if (i, k) == (0, 1) else "+0"))
                         for i in range(50) for k in range(4)]
                (tmp_path / ("D_%s_%s_r%d.txt" % (scheme, dt, r))).write_text("\n".join(lines) + "\n")
    assert ss.main([str(tmp_path)]) == 0
    md = (tmp_path / "splittingStudy.md").read_text().splitlines()
    lie = [l for l in md if l.startswith("| Lie |")]
    # dx/h = 2 and 1; cell 0 = [0, 2h] (Lie expects -50 %) and [0, h] (-100 %)
    assert lie[0].startswith("| Lie | 0.002 | 2 | 2 | +2.00 ± %.2f %% (-50.00 %%) |" % T975_1)
    assert lie[1].startswith("| Lie | 0.004 | 1 | 2 | +2.00 ± %.2f %% (-100.00 %%) |" % T975_1)
    assert (tmp_path / "splittingOrder.png").stat().st_size > 0


def test_main_usage():
    assert ss.main([]) == 2
