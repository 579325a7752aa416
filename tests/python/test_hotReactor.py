# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.hotReactor: the plug flow's discrete sizes put into the solver's mass bins."""
import numpy as np

from coagulationPost import hotReactor, maps


def test_bin_sizes_puts_each_mass_in_the_bin_below_its_upper_edge():
    upper = np.array([2.0, 4.0, 8.0])
    masses = [1, 2, 3, 4, 7, 8, 20]
    numbers = [1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6]
    # 1 -> bin 0; 2, 3 -> bin 1 (an edge belongs to the bin above); 4, 7 -> bin 2; 8, 20 dropped
    assert hotReactor.bin_sizes(masses, numbers, upper).tolist() == [1.0, 110.0, 11000.0]


def test_bin_sizes_keeps_the_number_in_range():
    rng = np.random.default_rng(3)
    masses = rng.integers(1, 100, 500)
    numbers = rng.random(500)
    upper = np.geomspace(1.5, 200.0, 12)
    assert np.isclose(hotReactor.bin_sizes(masses, numbers, upper).sum(), numbers.sum())


BOUNDARY = """FoamFile
{
    version     2.0;
    format      ascii;
    class       polyBoundaryMesh;
    object      boundary;
}

3
(
    inlet
    {
        type            patch;
        nFaces          15;
        startFace       4395;
    }
    lowerWall
    {
        type            wall;
        inGroups        1(wall);
        nFaces          150;
        startFace       4425;
    }
    frontAndBack
    {
        type            empty;
        inGroups        1(empty);
        nFaces          4500;
        startFace       4725;
    }
)
"""

T_FIELD = """FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    object      T;
}
dimensions      [0 0 0 1 0 0 0];
internalField   nonuniform List<scalar> 3
(
400
800
1200
)
;
boundaryField
{
    inlet { type fixedValue; value uniform 1200; }
}
"""


def test_surface_rate_field_is_the_arrhenius_rate_of_each_cell(tmp_path):
    (tmp_path / "constant" / "polyMesh").mkdir(parents=True)
    (tmp_path / "constant" / "polyMesh" / "boundary").write_text(BOUNDARY)
    (tmp_path / "0").mkdir()
    (tmp_path / "0" / "T").write_text(T_FIELD)
    assert maps.patches(str(tmp_path)) == [
        ("inlet", "patch", 15, 4395), ("lowerWall", "wall", 150, 4425),
        ("frontAndBack", "empty", 4500, 4725)]
    k = hotReactor.surface_rate_field(str(tmp_path), "0", 1.25, 1e5)
    exact = 1.25 * np.exp(-1e5 / (8.314462618 * np.array([400.0, 800.0, 1200.0])))
    assert np.allclose(k, exact, rtol=1e-15)
    text = (tmp_path / "0" / "kSurface").read_text()
    assert np.allclose(hotReactor.internal_field(text), exact, rtol=1e-15)
    assert "dimensions [1 -2 -1 0 0 0 0];" in text
    assert "frontAndBack { type empty; }" in text and "lowerWall { type zeroGradient; }" in text
