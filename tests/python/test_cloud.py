# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.cloud: the particles' cells and fields from ASCII lagrangian files."""

import numpy as np

from coagulationPost import cloud

HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    location    "1/lagrangian/coagulationCloud";
    object      %s;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""

COORDINATES = HEADER % ("Cloud<coagulationParcel>", "coordinates") + """3
(
(0.25 0.25 0.25 0.25) 12 40 2
(0.1 0.2 0.3 0.4) 0 3 1
(0.7 0.1 0.1 0.1) 7 21 3
)


// ************************************************************************* //
"""

MASS = HEADER % ("scalarField", "mass") + """3
(
1.5
2
3e-1
)


// ************************************************************************* //
"""


def test_cells_are_the_first_integer_after_the_coordinates():
    assert cloud.cells_of_coordinates(COORDINATES).tolist() == [12, 0, 7]


def test_scalar_values_are_the_list_after_the_header():
    v = cloud.scalar_values(MASS)
    assert v.dtype == float
    assert v.tolist() == [1.5, 2.0, 0.3]


def test_files_of_a_case(tmp_path):
    d = tmp_path / "1" / "lagrangian" / "coagulationCloud"
    d.mkdir(parents=True)
    (d / "coordinates").write_text(COORDINATES)
    (d / "mass").write_text(MASS)
    assert cloud.cell_of(str(tmp_path), "1").tolist() == [12, 0, 7]
    assert np.array_equal(cloud.field(str(tmp_path), "1", "mass"), [1.5, 2.0, 0.3])
