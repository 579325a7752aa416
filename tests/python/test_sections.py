# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.sections: the cells of a three-dimensional polyMesh cut by an axis-aligned
plane and crossed by a segment, on blocks of hexahedra (graded, and sheared into
parallelepipeds), against the blocks' own geometry."""
import numpy as np
import pytest

from coagulationPost import sections

X = np.array([0.0, 0.1, 0.25, 0.45, 0.7])          # graded
Y = np.array([-0.2, 0.0, 0.05, 0.3])
Z = np.array([1.0, 1.1, 1.3, 1.35, 1.6, 2.0])


def _write(path, cls, n, lines):
    path.write_text("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n"
                    "    object %s;\n}\n\n%d\n(\n%s\n)\n" % (cls, path.name, n, "\n".join(lines)))


def _block(tmp_path, x=X, y=Y, z=Z, shear=0.0):
    """An ASCII polyMesh of the hexahedra between the nodes x, y, z (cell (i, j, k) is
    i + nx (j + ny k)), its points moved by x += shear z; internal faces first in OpenFOAM's
    order (by owner, then neighbour; normals from owner to neighbour), then the boundary
    faces (normals outwards), all of one patch 'walls'. Returns the case."""
    nx, ny, nz = len(x) - 1, len(y) - 1, len(z) - 1
    node = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    cell = lambda i, j, k: i + nx * (j + ny * k)
    pts = [(x[i] + shear * z[k], y[j], z[k]) for k in range(nz + 1) for j in range(ny + 1)
           for i in range(nx + 1)]
    # the face at the node plane i (j, k) of the cell (i, j, k), normal +x (+y, +z)
    fx = lambda i, j, k: [node(i, j, k), node(i, j + 1, k), node(i, j + 1, k + 1), node(i, j, k + 1)]
    fy = lambda i, j, k: [node(i, j, k), node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j, k)]
    fz = lambda i, j, k: [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k)]
    faces, owner, neighbour = [], [], []
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                for ok, f, nb in ((i + 1 < nx, fx(i + 1, j, k), cell(i + 1, j, k)),
                                  (j + 1 < ny, fy(i, j + 1, k), cell(i, j + 1, k)),
                                  (k + 1 < nz, fz(i, j, k + 1), cell(i, j, k + 1))):
                    if ok:
                        faces.append(f), owner.append(cell(i, j, k)), neighbour.append(nb)
    n_int = len(faces)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = cell(i, j, k)
                for on, f in ((i == 0, fx(i, j, k)[::-1]), (i == nx - 1, fx(i + 1, j, k)),
                              (j == 0, fy(i, j, k)[::-1]), (j == ny - 1, fy(i, j + 1, k)),
                              (k == 0, fz(i, j, k)[::-1]), (k == nz - 1, fz(i, j, k + 1))):
                    if on:
                        faces.append(f), owner.append(c)
    d = tmp_path / "constant" / "polyMesh"
    d.mkdir(parents=True)
    _write(d / "points", "vectorField", len(pts), ["(%.17g %.17g %.17g)" % p for p in pts])
    _write(d / "faces", "faceList", len(faces), ["4(%d %d %d %d)" % tuple(f) for f in faces])
    _write(d / "owner", "labelList", len(owner), map(str, owner))
    _write(d / "neighbour", "labelList", len(neighbour), map(str, neighbour))
    _write(d / "boundary", "polyBoundaryMesh", 1, [
        "walls\n{\n    type wall;\n    nFaces %d;\n    startFace %d;\n}"
        % (len(faces) - n_int, n_int)])
    return str(tmp_path)


def _ijk(c, x=X, y=Y):
    nx, ny = len(x) - 1, len(y) - 1
    return c % nx, (c // nx) % ny, c // (nx * ny)


def _area(p):
    """The signed (shoelace) area of the polygon p [n][2]."""
    return 0.5 * np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])


def test_read_mesh_and_the_cell_centres(tmp_path):
    mesh = sections.read_mesh(_block(tmp_path, shear=0.3))
    nc = 4 * 3 * 5
    assert mesh["nCells"] == nc and len(mesh["points"]) == 5 * 4 * 6
    n_int = 3 * 3 * 5 + 4 * 2 * 5 + 4 * 3 * 4
    assert len(mesh["neighbour"]) == n_int and len(mesh["faces"]) == n_int + 2 * (12 + 20 + 15)
    assert mesh["patches"] == [("walls", "wall", 2 * (12 + 20 + 15), n_int)]
    i, j, k = _ijk(np.arange(nc))
    zc = (Z[k] + Z[k + 1]) / 2
    exact = np.column_stack([(X[i] + X[i + 1]) / 2 + 0.3 * zc, (Y[j] + Y[j + 1]) / 2, zc])
    assert np.allclose(sections.cell_centres(mesh), exact, rtol=0, atol=1e-12)


def test_read_mesh_names_the_file(tmp_path):
    case = _block(tmp_path)
    (tmp_path / "constant" / "polyMesh" / "neighbour").unlink()
    with pytest.raises(ValueError, match="neighbour"):
        sections.read_mesh(case)


def test_match_cells(tmp_path):
    mesh = sections.read_mesh(_block(tmp_path, shear=0.3))
    perm = np.random.default_rng(3).permutation(mesh["nCells"])
    i, j, k = _ijk(perm)
    zc = (Z[k] + Z[k + 1]) / 2
    centres = np.column_stack([(X[i] + X[i + 1]) / 2 + 0.3 * zc, (Y[j] + Y[j + 1]) / 2, zc])
    assert np.array_equal(sections.match_cells(mesh, centres + 1e-6), perm)
    assert sections.match_cells(mesh, centres[1:]) is None
    assert sections.match_cells(mesh, np.vstack([centres[:1], centres[:-1]])) is None


def test_slice_across_a_layer(tmp_path):
    s = 0.3
    mesh = sections.read_mesh(_block(tmp_path, shear=s))
    z = 1.4                                        # in layer k = 3
    cells, polys = sections.slice_polygons(mesh, 2, z)
    assert np.array_equal(cells, np.arange(3 * 12, 4 * 12))
    areas = np.array([_area(p) for p in polys])
    assert np.all(areas > 0)
    assert abs(areas.sum() / (np.ptp(X) * np.ptp(Y)) - 1) < 1e-12
    i, j, _ = _ijk(cells)
    assert np.allclose(areas, (X[i + 1] - X[i]) * (Y[j + 1] - Y[j]), rtol=1e-12, atol=0)
    # cell (2, 1, 3): the rectangle [x_2, x_3] x [y_1, y_2] moved by s z
    p = polys[list(cells).index(2 + 4 * (1 + 3 * 3))]
    rect = [(X[2] + s * z, Y[1]), (X[3] + s * z, Y[1]), (X[3] + s * z, Y[2]), (X[2] + s * z, Y[2])]
    assert len(p) == 4 and np.allclose(sorted(map(tuple, p)), sorted(rect), rtol=0, atol=1e-12)


def test_slice_on_a_node_plane_and_outside(tmp_path):
    mesh = sections.read_mesh(_block(tmp_path, shear=0.3))
    cells, polys = sections.slice_polygons(mesh, 2, Z[2])
    # the layer below the plane, each column once
    assert np.array_equal(cells, np.arange(12, 24))
    assert abs(sum(_area(p) for p in polys) / (np.ptp(X) * np.ptp(Y)) - 1) < 1e-12
    for value in (Z[0] - 0.1, Z[-1] + 0.1):
        cells, polys = sections.slice_polygons(mesh, 2, value)
        assert len(cells) == 0 and polys == []
    # on the lowest boundary: the lowest layer, each column once
    cells, polys = sections.slice_polygons(mesh, 2, Z[0])
    assert np.array_equal(cells, np.arange(12))
    assert abs(sum(_area(p) for p in polys) / (np.ptp(X) * np.ptp(Y)) - 1) < 1e-12


@pytest.mark.parametrize("axis, value, shear, area", [
    (0, 0.3, 0.0, np.ptp(Y) * np.ptp(Z)),
    (0, X[2], 0.0, np.ptp(Y) * np.ptp(Z)),
    (1, 0.1, 0.3, np.ptp(X) * np.ptp(Z)),         # a parallelogram in (x, z)
    (1, Y[1], 0.3, np.ptp(X) * np.ptp(Z))])
def test_slice_normal_to_x_and_y(tmp_path, axis, value, shear, area):
    mesh = sections.read_mesh(_block(tmp_path, shear=shear))
    cells, polys = sections.slice_polygons(mesh, axis, value)
    nodes = X if axis == 0 else Y
    layer = np.searchsorted(nodes, value, side="left") - 1    # on a node: the cells below
    assert np.all(np.array(_ijk(cells))[axis] == layer)
    assert len(cells) == 5 * (3 if axis == 0 else 4)
    areas = np.array([_area(p) for p in polys])
    assert np.all(areas > 0) and abs(areas.sum() / area - 1) < 1e-12


def test_slice_of_the_sheared_block_normal_to_x(tmp_path):
    s = 0.3
    mesh = sections.read_mesh(_block(tmp_path, shear=s))
    # through the edges at x - s z = X[2], z = Z[1]: cells (1, j, 0) touch it along an edge only
    v = X[2] + s * Z[1]
    cells, polys = sections.slice_polygons(mesh, 0, v)
    # each cell's section, unsheared: y in [Y_j, Y_j+1], z in [Z_k, Z_k+1] with
    # X_i <= v - s z <= X_i+1
    i, j, k = np.meshgrid(np.arange(4), np.arange(3), np.arange(5), indexing="ij")
    i, j, k = i.ravel(), j.ravel(), k.ravel()
    dz = (np.minimum(Z[k + 1], (v - X[i]) / s) - np.maximum(Z[k], (v - X[i + 1]) / s))
    area = (Y[j + 1] - Y[j]) * np.maximum(dz, 0)
    cut = area > 1e-9
    expected = np.sort(i[cut] + 4 * (j[cut] + 3 * k[cut]))
    assert np.array_equal(cells, expected)
    areas = np.array([_area(p) for p in polys])
    assert np.allclose(areas, area[cut][np.argsort(i[cut] + 4 * (j[cut] + 3 * k[cut]))],
                       rtol=1e-12, atol=0)


def test_line_along_a_column(tmp_path):
    mesh = sections.read_mesh(_block(tmp_path))
    p0, p1 = np.array([0.3, 0.1, 0.5]), np.array([0.3, 0.1, 1.8])    # column (2, 2)
    cells, t_in, t_out = sections.line_cells(mesh, p0, p1)
    assert np.array_equal(cells, [2 + 4 * (2 + 3 * k) for k in range(5)])
    assert np.allclose(t_in, (Z[:5] - 0.5) / 1.3, rtol=0, atol=1e-12)
    assert np.allclose(t_out, np.append((Z[1:5] - 0.5) / 1.3, 1.0), rtol=0, atol=1e-12)
    assert abs(np.sum(t_out - t_in) * 1.3 - (1.8 - Z[0])) < 1e-12
    # diagonally through the edge at (X[2], Y[1]) in layer 1: the two cells either side of
    # it, not the two it only touches
    cells, t_in, t_out = sections.line_cells(mesh, [X[2] - 0.04, Y[1] - 0.04, 1.2],
                                             [X[2] + 0.04, Y[1] + 0.04, 1.2])
    assert np.array_equal(cells, [1 + 4 * (0 + 3 * 1), 2 + 4 * (1 + 3 * 1)])
    assert np.allclose(np.column_stack([t_in, t_out]), [[0, 0.5], [0.5, 1]], rtol=0, atol=1e-12)
    # outside the block
    assert len(sections.line_cells(mesh, [0.8, 0, 1.2], [0.9, 0.1, 1.9])[0]) == 0


def test_line_in_a_plane_of_faces_is_claimed_once(tmp_path):
    mesh = sections.read_mesh(_block(tmp_path))
    cells, t_in, t_out = sections.line_cells(mesh, [X[2], 0.1, 0.0], [X[2], 0.1, 3.0])
    i, j, k = _ijk(cells)
    assert np.array_equal(k, np.arange(5)) and np.all(j == 2) and np.all(np.isin(i, [1, 2]))
    assert np.allclose(t_out[:-1], t_in[1:], rtol=0, atol=1e-12)


def test_diagonal_line_through_the_sheared_block(tmp_path):
    s = 0.3
    mesh = sections.read_mesh(_block(tmp_path, shear=s))
    # towards -x: the cells' numbers are not in the order of the line's crossing
    p0, p1 = np.array([1.5, -0.5, 0.7]), np.array([-0.2, 0.5, 2.3])
    cells, t_in, t_out = sections.line_cells(mesh, p0, p1)
    # unsheared (x - s z), the block is a box: its entry and exit by the slab method
    unshear = lambda p: p - [s * p[2], 0, 0]
    q0, qd = unshear(p0), unshear(p1) - unshear(p0)
    lo = np.array([X[0], Y[0], Z[0]])
    hi = np.array([X[-1], Y[-1], Z[-1]])
    ta, tb = (lo - q0) / qd, (hi - q0) / qd
    t_enter, t_exit = max(0, np.minimum(ta, tb).max()), min(1, np.maximum(ta, tb).min())
    assert t_exit - t_enter > 0.1 and len(cells) > 5 and len(set(cells)) == len(cells)
    assert abs(t_in[0] - t_enter) < 1e-12 and abs(t_out[-1] - t_exit) < 1e-12
    assert np.all(np.abs(t_out[:-1] - t_in[1:]) < 1e-12) and np.all(t_out > t_in)
    # each cell's midpoint, unsheared, is in its box
    for c, a, b in zip(cells, t_in, t_out):
        q = unshear(p0 + (a + b) / 2 * (p1 - p0))
        i, j, k = _ijk(c)
        assert X[i] <= q[0] <= X[i + 1] and Y[j] <= q[1] <= Y[j + 1] and Z[k] <= q[2] <= Z[k + 1]


def _report(tmp_path, shear=0.0, seed=3):
    """A case with the block's mesh and a report's statistics on it: the rows in a shuffled
    order of the cells, M0 = 1 + x, M1 = 2 + y (the cell's exact centroid), ci 5 % and 10 %;
    returns case, mesh, res, the mesh cell of each row."""
    case = _block(tmp_path, shear=shear)
    mesh = sections.read_mesh(case)
    rng = np.random.default_rng(seed)
    cell_of_row = rng.permutation(mesh["nCells"])
    nx, ny = len(X) - 1, len(Y) - 1
    i, j, k = (cell_of_row % nx, (cell_of_row // nx) % ny, cell_of_row // (nx * ny))
    zc = 0.5 * (Z[k] + Z[k + 1])
    c = np.column_stack([0.5 * (X[i] + X[i + 1]) + shear * zc, 0.5 * (Y[j] + Y[j + 1]), zc])
    mean = np.column_stack([1 + c[:, 0], 2 + c[:, 1], np.ones(len(c)), np.ones(len(c))])
    res = {"centres": c, "mean": mean, "ci": mean * [0.05, 0.1, 0.05, 0.05],
           "meanMass": mean[:, 1] / mean[:, 0], "meanMassCi": 0.07 * mean[:, 1] / mean[:, 0]}
    return case, mesh, res, cell_of_row


def test_slice_figure_writes_the_cut_cells_values(tmp_path):
    from coagulationPost import maps

    case, mesh, res, cell_of_row = _report(tmp_path, shear=0.2)
    assert np.array_equal(sections.match_cells(mesh, res["centres"]), cell_of_row)
    png, csv = maps.slice_figure(res, str(tmp_path / "out"), mesh, cell_of_row, 2, 1.2)
    assert png.endswith("slice_z1.2.png") and csv.endswith("slice_z1.2.csv")
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=2)
    # the layer 1.1 < z < 1.3: its 4 x 3 cells, each with its own row's values
    assert len(rows) == 12 and np.allclose(rows["z"], 1.2)
    r = rows["cell"].astype(int)
    assert np.allclose(rows["x"], res["centres"][r, 0])
    assert np.allclose(rows["M0"], res["mean"][r, 0]) and np.allclose(rows["M1"], res["mean"][r, 1])
    assert np.allclose(rows["M1_relCI95"], 0.1)
    # the colour ranges are those of the slice's cells only
    head = open(csv).readline()
    ranges = dict((q, (float(a), float(b))) for q, a, b in
                  (part.split() for part in head.split(":", 1)[1].split(",")))
    assert np.isclose(ranges["M0"][0], rows["M0"].min())
    assert np.isclose(ranges["M0"][1], rows["M0"].max())
    with pytest.raises(ValueError, match="does not cut the mesh"):
        maps.slice_figure(res, str(tmp_path / "out"), mesh, cell_of_row, 2, 5.0)


def test_line_figure_writes_the_crossed_cells_in_order(tmp_path):
    from coagulationPost import maps

    case, mesh, res, cell_of_row = _report(tmp_path)
    p0, p1 = [-0.1, 0.02, 1.2], [0.8, 0.02, 1.2]
    png, csv = maps.line_figure(res, str(tmp_path / "out"), mesh, cell_of_row, p0, p1, "line1")
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=1)
    # the row j = 1 (0 < y < 0.05), layer k = 1: the 4 cells along x, entered at x = X[i]
    assert len(rows) == 4
    assert np.allclose(rows["s_in"], X[:-1] + 0.1) and np.allclose(rows["s_out"], X[1:] + 0.1)
    r = rows["cell"].astype(int)
    assert np.allclose(rows["x"], 0.5 * (X[:-1] + X[1:]))
    assert np.allclose(rows["M0"], res["mean"][r, 0])
    assert np.allclose(rows["M0_ci95"], 0.05 * res["mean"][r, 0])
    assert np.allclose(rows["meanMass"], res["mean"][r, 1] / res["mean"][r, 0])
    assert np.allclose(rows["meanMass_ci95"], 0.07 * rows["meanMass"])
    with pytest.raises(ValueError, match="does not cross the mesh"):
        maps.line_figure(res, str(tmp_path / "out"), mesh, cell_of_row, [5, 5, 5], [6, 6, 6],
                         "line2")


def test_round_off_on_a_layer_of_faces(tmp_path):
    """The points of a layer of faces as blockMesh writes them: a few ulps off the value.
    A slice on the layer still cuts each column once, and a line along an edge where four
    cells meet still crosses one cell at each place."""
    mesh = sections.read_mesh(_block(tmp_path))
    rng = np.random.default_rng(7)
    pts = mesh["points"]
    mesh["points"] = pts + rng.choice([-1, 0, 1], size=pts.shape) * 4e-16 * np.abs(pts)
    cells, polys = sections.slice_polygons(mesh, 2, Z[2])
    assert len(cells) == 12 and len(np.unique(cells)) == 12
    assert abs(sum(_area(p) for p in polys) / (np.ptp(X) * np.ptp(Y)) - 1) < 1e-9
    cells, t_in, t_out = sections.line_cells(mesh, [X[0], Y[1], Z[2]], [X[-1], Y[1], Z[2]])
    i, j, k = _ijk(cells)
    assert np.array_equal(i, np.arange(4)) and len(np.unique(j)) == 1 and len(np.unique(k)) == 1
    assert np.allclose(t_out[:-1], t_in[1:], rtol=0, atol=1e-9)


def test_figures_in_diameter_with_a_material(tmp_path):
    """With a density and a mass unit, the maps and the line show the diameter of the mean
    mass, d = (6 m u / (pi rho))^(1/3) in nm, and its interval a third of the mass's
    relative one."""
    from coagulationPost import maps

    case, mesh, res, cell_of_row = _report(tmp_path)
    material = (1800.0, 9.42e-22)                       # 1 unit: a 10 nm sphere
    png, csv = maps.slice_figure(res, str(tmp_path / "out"), mesh, cell_of_row, 2, 1.2,
                                 material=material)
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=2)
    m = rows["meanMass"]
    d = 1e9 * (6 * m * 9.42e-22 / (np.pi * 1800.0)) ** (1 / 3)
    assert np.allclose(rows["meanDiameter"], d) and np.all((d > 10) & (d < 20))
    assert np.allclose(rows["meanDiameter_relCI95"], 0.07 / 3)
    assert "meanDiameter" in open(csv).readline()            # drawn: in the colour ranges
    png, csv = maps.line_figure(res, str(tmp_path / "out"), mesh, cell_of_row,
                                [-0.1, 0.02, 1.2], [0.8, 0.02, 1.2], "line1", material=material)
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=1)
    r = rows["cell"].astype(int)
    d = 1e9 * (6 * res["meanMass"][r] * 9.42e-22 / (np.pi * 1800.0)) ** (1 / 3)
    assert np.allclose(rows["meanDiameter"], d)
    assert np.allclose(rows["meanDiameter_ci95"], d * 0.07 / 3)


def test_steps_break_where_the_line_leaves_the_mesh():
    """A step per cell; where the next cell starts after this one ends (the segment left the
    mesh and came back), a break (NaN), and none between cells that touch."""
    from coagulationPost import maps

    x, y = maps.steps([0.0, 1.0, 3.0], [1.0, 2.0, 4.0], [5.0, 6.0, 7.0])
    assert np.array_equal(x[[0, 1, 3, 4, 6, 7]], [0, 1, 1, 2, 3, 4])
    assert np.array_equal(y[[0, 1, 3, 4, 6, 7]], [5, 5, 6, 6, 7, 7])
    assert x[2] == 1.0 and y[2] == 5.0                  # cells 0 and 1 touch: joined
    assert np.isnan(x[5]) and np.isnan(y[5])            # 2 .. 3: no cell, a break
