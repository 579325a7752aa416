# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.lagrangianStudy: the times of the files, the summaries and the figures of
the Kolodko-Sabelfeld-Wagner studies."""

import numpy as np

from coagulationPost import lagrangianStudy as ls


def test_times_sorted_by_value_once_each():
    names = ["functionals_t55.csv", "functionals_t1.25.csv", "functionals_t9.csv",
             "functionals_t10.csv", "functionals_t10_r5.csv", "spectrum_t3_r10.csv", "timing.csv"]
    assert ls.times_of(names, "functionals_t") == ["1.25", "9", "10", "55"]
    assert ls.times_of(names, "spectrum_t") == ["3"]


def test_half_radius_is_the_first_radius_at_half():
    r = np.array([10.0, 20.0, 30.0, 40.0])
    assert ls.half_radius(r, np.array([0.1, 0.3, 0.6, 0.9]), 1.0) == 30.0
    assert ls.half_radius(r, np.array([0.1, 0.5, 0.6, 0.9]), 1.0) == 20.0


def test_interval_sizes():
    below, within = ls.interval_sizes(np.array([1.0, 2.0, 3.0]), np.array([1.0, 2.0, 3.0]),
                                      np.array([0.5, 0.5, 0.5]), np.array([2.0, 2.4, 3.6]))
    assert below == [1, 3] and within == [2]


def write(path, header, rows):
    path.write_text(",".join(header) + "\n" + "".join(",".join(map(str, r)) + "\n" for r in rows))


def test_uniform_summary_and_figure(tmp_path, capsys):
    write(tmp_path / "functionals_t2.csv",
          ["r", "In", "In_hw", "In_det", "Ms", "Ms_hw", "Ms_det", "ratio_realisations"],
          [(50, 0.2, 0.01, 0.25, 1.0, 0.01, 1.0, 0), (100, 0.6, 0.01, 0.5, 1.1, 0.01, 1.0, 5),
           (200, 0.8, 0.01, 1.0, 1.2, 0.01, 1.25, 5)])
    ls.uniform(str(tmp_path), 100.0)
    assert capsys.readouterr().out == (
        "t' = 2: In(R')/S = 0.6 +- 0.01, deterministic 0.5 (ratio 0.833); half the clusters "
        "within r' = 100; max |<Ms> - Ms-bar| = 0.1 over the 2 radii with clusters\n")
    assert (tmp_path / "fig1_In_t2.png").stat().st_size > 0


def test_linear_summary_and_figures(tmp_path, capsys):
    write(tmp_path / "functionals_t2.csv",
          ["r", "In", "In_hw", "In_det", "Ms", "Ms_hw", "Ms_det", "ratio_realisations"],
          [(10, 0.2, 0.01, 0.25, 1.5, 0.01, 1.25, 3)])
    l = np.arange(1, 11)
    write(tmp_path / "spectrum_t2_r10.csv", ["l", "Sp", "Sp_hw", "Sp_det"],
          [(k, 2.0 ** -k, 0.1 * 2.0 ** -k, 2.0 ** -k * (1.5 if k == 5 else 1.0)) for k in l])
    ls.linear(str(tmp_path), 100.0)
    out = capsys.readouterr().out.splitlines()
    assert out[0] == ("t' = 2, r' = 10: <Sp_l> + interval below Sp-bar for l = [5]; Sp-bar inside "
                      "the interval for l = [1, 2, 3, 4, 6, 7, 8, 9, 10]; Sp_5/Sp-bar = 0.667 +- "
                      "0.067, Sp_10/Sp-bar = 1.000 +- 0.100")
    assert out[1] == ("t' = 2, r' = 10: <Ms> - 1 = 0.50000 +- 1.0e-02, Ms-bar - 1 = 0.25000 "
                      "(3 realisations with clusters)")
    assert sorted(p.name for p in tmp_path.glob("*.png")) == ["fig3_Sp_t2_r10.png", "fig4_Ms_t2.png"]


def test_main_usage():
    assert ls.main(["both", "d", "100"]) == 1
