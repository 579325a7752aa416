# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.coagulationDiffusionColumn: the central cells, the densities of sizes,
the diffusion factor and the comparison table's coagulationFoam column."""

import math

import numpy as np
import pytest
from scipy.special import erf

from coagulationPost import coagulationDiffusionColumn as col


def exact_factor(t, half, D=0.0888):
    """The diffusion factor in closed form: int erf(u) du = u erf(u) + exp(-u^2)/sqrt(pi)."""
    s = 2 * math.sqrt(D * t)

    def G(u):
        return u * erf(u) + math.exp(-u * u) / math.sqrt(math.pi)
    mean = s * (G((1 + half) / s) - G((1 - half) / s)) / (2 * half)
    return (mean / erf(1 / s)) ** 2


@pytest.mark.parametrize("t, half", [(1.0, 0.3), (5.0, 0.8), (10.0, 0.3)])
def test_diffusion_factor_is_the_gaussian_average(t, half):
    # the trapezoidal rule on 201 points is within 1e-5 of the closed form
    assert col.diffusion_factor(t, half) == pytest.approx(exact_factor(t, half), rel=2e-5)


def test_diffusion_factor_is_one_before_the_edges_move():
    assert col.diffusion_factor(1e-6, 0.3) == pytest.approx(1.0, abs=1e-12)


def test_central_cells_of_a_coarse_mesh():
    # nx = 10 on [-4, 4]: h = 0.8, centres +-0.4 inside |x| < 0.9: 2 x 2 cells
    mask, vol, half = col.central_cells(10, 0.9)
    assert np.flatnonzero(mask).tolist() == [44, 45, 54, 55]
    assert vol == pytest.approx(4 * 0.8 * 0.8 * 0.1)
    assert half == pytest.approx(0.8)


def test_size_density_rounds_the_mass_and_sums_the_weights():
    # the masses are sums of unit monomers, up to round-off: 1.2 is 1, 1.9999999999 is 2
    inside = np.array([True, True, False, True, True])
    mass = np.array([1.0, 1.2, 1.0, 2.0, 1.9999999999])
    weight = np.array([2.0, 3.0, 5.0, 7.0, 1.0])
    n, se = col.size_density(inside, mass, weight, 1, 2.0)
    assert n == pytest.approx(2.5)
    assert se == pytest.approx(math.sqrt(13) / 2)
    assert col.size_density(inside, mass, weight, 2, 2.0) == pytest.approx((4.0, math.sqrt(50) / 2))


def test_z_score():
    assert col.z_score(3.0, 1.0, 0.5) == 4.0
    assert math.isnan(col.z_score(3.0, 1.0, 0.0))


def write_particles(case, time, cells, mass, weight):
    d = case / time / "lagrangian" / "coagulationCloud"
    d.mkdir(parents=True)
    head = "FoamFile\n{\n    object x;\n}\n\n%d\n(\n" % len(cells)
    (d / "coordinates").write_text(
        head + "".join("(0.25 0.25 0.25 0.25) %d 1 1\n" % c for c in cells) + ")\n")
    (d / "mass").write_text(head + "".join("%g\n" % m for m in mass) + ")\n")
    (d / "weight").write_text(head + "".join("%.17g\n" % w for w in weight) + ")\n")


def test_compare_prints_the_table_and_checks(tmp_path, capsys):
    # one monomer of weight vol in a central cell: n = 1, se = 1; a dimer outside
    vol = 4 * 0.8 * 0.8 * 0.1
    write_particles(tmp_path, "1", [44, 0], [1, 2], [vol, 1.0])
    ref = tmp_path / "ref.csv"
    ref.write_text("t,l,nE,nL\n1,1,2,1\n1,2,0.5,0.25\n")
    ok = col.compare(str(tmp_path), str(ref), nx=10, times=("1",), sizes=2, half=0.9)
    f = exact_factor(1.0, 0.8)
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "t',l,n_coagulationFoam,se,nE,nL,z_E,z_L,f"
    t, l, n, se, nE, nL, zE, zL, ff = lines[1].split(",")
    assert (t, l, float(n), float(se)) == ("1", "1", 1.0, 1.0)
    assert float(nE) == pytest.approx(2 * f, rel=2e-5)
    assert float(nL) == pytest.approx(f, rel=2e-5)
    assert float(zE) == pytest.approx(1 - 2 * f, abs=0.006)
    assert float(ff) == pytest.approx(f, rel=2e-5)
    assert lines[2].split(",")[2:4] == ["0", "0"] and lines[2].split(",")[6:8] == ["+nan", "+nan"]
    # |z_E| < 4, but n^L is nowhere off by 5 standard errors: the check fails
    assert not ok


def test_setup_writes_the_mesh_and_the_particles(tmp_path):
    for d in ("system", "constant", "0"):
        (tmp_path / d).mkdir()
    col.setup(str(tmp_path), 150, 20)
    assert "(20 20 1)" in (tmp_path / "system" / "blockMeshDict").read_text()
    props = (tmp_path / "constant" / "coagulationProperties").read_text()
    assert "statisticalWeight { n 150; V1 1; }" in props and "D 0.0888;" in props
    assert "boxToCell" in (tmp_path / "system" / "topoSetDict").read_text()


def test_main_usage():
    assert col.main([]) == 2
    assert col.main(["compare", "a", "b", "80"]) == 2
