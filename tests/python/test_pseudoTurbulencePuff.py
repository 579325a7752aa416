# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.pseudoTurbulencePuff: the cells in a ball, the sums over them and the
comparison table's puff."""

import math

import numpy as np
import pytest

from coagulationPost import pseudoTurbulencePuff as puff


def test_centre_radius2_of_small_blocks():
    # 2^3 cells of [-12, 12]^3: centres at +-6, |x|^2 = 108 everywhere
    assert puff.centre_radius2(2).tolist() == [108.0] * 8
    # 3^3 cells: centres -8, 0, 8; the middle cell (1, 1, 1) is number 13
    r2 = puff.centre_radius2(3)
    assert r2[13] == 0.0
    assert r2[0] == r2[26] == 192.0
    assert r2[1] == r2[3] == r2[9] == 128.0
    assert sorted(r2).count(64.0) == 6


def test_ball_sums():
    r2 = np.array([0.0, 4.0, 9.0])
    cells = np.array([0, 1, 2, 2])
    mass = np.array([1.0, 2.0, 3.0, 4.0])
    weight = np.array([1.0, 2.0, 3.0, 4.0])
    n, se, m = puff.ball_sums(r2, cells, mass, weight, 2.0)   # |x| <= 2: cells 0 and 1
    assert (n, m) == (3.0, 5.0)
    assert se == pytest.approx(math.sqrt(5.0))
    assert puff.ball_sums(r2, cells, mass, weight, 3.0) == pytest.approx((10.0, math.sqrt(30.0), 30.0))


def test_z_score_combines_the_standard_errors():
    assert puff.z_score(10.0, 3.0, 6.0, 4.0) == pytest.approx(0.8)


def test_cells_per_side(monkeypatch):
    monkeypatch.delenv("PUFF_NX", raising=False)
    assert puff.cells_per_side() == 48
    monkeypatch.setenv("PUFF_NX", "4")
    assert puff.cells_per_side() == 4


def test_compare_with_two_cells_a_side(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("PUFF_NX", "2")
    d = tmp_path / "2" / "lagrangian" / "coagulationCloud"
    d.mkdir(parents=True)
    head = "FoamFile\n{\n}\n2\n(\n"
    (d / "coordinates").write_text(head + "(0.25 0.25 0.25 0.25) 0 1 1\n(0.25 0.25 0.25 0.25) 7 1 1\n)\n")
    (d / "mass").write_text(head + "1\n2\n)\n")
    (d / "weight").write_text(head + "3\n4\n)\n")
    ref = tmp_path / "ref.csv"
    ref.write_text("r,In,In_se,In_v0,mass\n10,1,1,2,3\n11,4,3,6,10\n")
    assert puff.compare(str(tmp_path), str(ref), "2")
    out = capsys.readouterr().out.splitlines()
    # every centre at sqrt(108) = 10.39: none within r = 10, both within 11
    assert out[1] == "10,0,0,1,1,2,-1.00,0,3"
    assert out[2] == "11,7,5,4,3,6,%+.2f,11,10" % (3 / math.hypot(5, 3))


def test_setup_writes_the_case(tmp_path, monkeypatch):
    monkeypatch.setenv("PUFF_NX", "8")
    for d in ("system", "constant", "0"):
        (tmp_path / d).mkdir()
    puff.setup(str(tmp_path), 16, 3)
    assert "(8 8 8)" in (tmp_path / "system" / "blockMeshDict").read_text()
    assert "seed 3;" in (tmp_path / "system" / "pseudoTurbulenceDict").read_text()
    assert "statisticalWeight { n 16; V1 1; }" in (tmp_path / "constant" / "coagulationProperties").read_text()


def test_main_usage():
    assert puff.main(["compare", "case"]) == 2
