# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationPost.maps: the dimension of a mesh, the triangulation of its centres without the
gaps of the domain, and the maps' values and colour ranges."""
import os

import numpy as np
import pytest

from coagulationPost import maps


def _step_centres(n=12):
    """Cell centres of a backward-facing step in the x-y plane at z = 0.005: a 2n x n grid
    of unit squares without its lower-left n/2 x n/2 block."""
    c = [((i + 0.5) / n, (j + 0.5) / n, 0.005) for i in range(2 * n) for j in range(n)
         if not (i < n // 2 and j < n // 2)]
    return np.array(c)


def test_dimension_and_plane():
    c = _step_centres()
    assert maps.dimension(c) == 2 and maps.plane(c) == [0, 1]
    assert maps.dimension(np.column_stack([np.arange(5.0), np.zeros(5), np.zeros(5)])) == 1
    rng = np.random.default_rng(1)
    assert maps.dimension(rng.random((20, 3))) == 3


def test_triangulation_leaves_out_the_step():
    c = _step_centres()
    tri = maps.triangulation(c[:, 0], c[:, 1])
    t = tri.triangles[~tri.mask]
    centroid = np.column_stack([tri.x[t].mean(axis=1), tri.y[t].mean(axis=1)])
    # no unmasked triangle covers the step's corner block [0, 0.5) x [0, 0.5) (less the half
    # cell the centres stand in from its edges)
    inside = (centroid[:, 0] < 0.5 - 0.5 / 12) & (centroid[:, 1] < 0.5 - 0.5 / 12)
    assert not inside.any()
    # and every cell centre is a vertex of an unmasked triangle
    assert np.unique(t).size == len(c)
    # the outline runs along the step: segments at y = 0.5 + 0.5/12 for x < 0.5
    seg = np.array(maps.outline(tri))
    step = np.isclose(seg[:, 0, 1], 0.5 + 0.5 / 12) & np.isclose(seg[:, 1, 1], 0.5 + 0.5 / 12)
    assert step.any()


def test_map_figure_writes_the_cells_values_and_ranges(tmp_path):
    c = _step_centres()
    n = len(c)
    mean = np.column_stack([1e12 * (1 + c[:, 0]), 3e12 * (1 + c[:, 1]), np.ones(n), np.ones(n)])
    ci = 0.02 * mean
    ratio = mean[:, 1] / mean[:, 0]
    res = {"centres": c, "mean": mean, "ci": ci, "meanMass": ratio, "meanMassCi": 0.01 * ratio}
    png, csv = maps.map_figure(res, str(tmp_path), "step")
    assert os.path.getsize(png) > 10000
    head = open(csv).readline()
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=2)
    assert "triangles between the centres" in open(csv).readlines()[1]
    assert np.allclose(rows["M0"], mean[:, 0]) and np.allclose(rows["M1"], mean[:, 1])
    assert np.allclose(rows["meanMass"], mean[:, 1] / mean[:, 0])
    assert np.allclose(rows["M0_relCI95"], 0.02)
    assert np.allclose(rows["meanMass_relCI95"], 0.01)
    # the colour range of each panel is its values' range
    ranges = dict((q, (float(a), float(b))) for q, a, b in
                  (part.split() for part in head.split(":", 1)[1].split(",")))
    assert np.isclose(ranges["M0"][0], mean[:, 0].min()) and np.isclose(ranges["M0"][1],
                                                                        mean[:, 0].max())


def _mesh_file(path, cls, body, binary):
    head = ("FoamFile\n{\n    version 2.0;\n    format %s;\n    arch \"LSB;label=32;scalar=64\";\n"
            "    class %s;\n    object x;\n}\n\n" % ("binary" if binary else "ascii", cls))
    with open(path, "wb") as f:
        f.write(head.encode() + body)


def _two_cells(tmp_path, binary):
    """Two hexahedra side by side in x, one cell thick in z: the 'empty' front (z = 0) and
    back faces, a wall around"""
    d = tmp_path / "constant" / "polyMesh"
    d.mkdir(parents=True)
    pts = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], float)
    pts = np.vstack([pts, pts + [0, 0, 0.1]])
    faces = [[1, 4, 10, 7],                                  # internal
             [0, 3, 4, 1], [1, 4, 5, 2],                     # front (z = 0): cells 0, 1
             [6, 7, 10, 9], [7, 8, 11, 10],                  # back
             [0, 6, 9, 3], [2, 5, 11, 8], [0, 1, 7, 6], [1, 2, 8, 7], [3, 9, 10, 4],
             [4, 10, 11, 5]]
    owner = [0, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1]
    neighbour = [1]
    if binary:
        offsets = np.cumsum([0] + [len(f) for f in faces]).astype(np.int32)
        idx = np.concatenate(faces).astype(np.int32)
        _mesh_file(d / "points", "vectorField",
                   b"%d\n(" % len(pts) + pts.astype(np.float64).tobytes() + b")\n", True)
        _mesh_file(d / "faces", "faceCompactList",
                   b"%d\n(" % len(offsets) + offsets.tobytes() + b")\n\n"
                   + b"%d\n(" % len(idx) + idx.tobytes() + b")\n", True)
        _mesh_file(d / "owner", "labelList",
                   b"%d\n(" % len(owner) + np.array(owner, np.int32).tobytes() + b")\n", True)
        _mesh_file(d / "neighbour", "labelList",
                   b"%d\n(" % len(neighbour) + np.array(neighbour, np.int32).tobytes()
                   + b")\n", True)
    else:
        _mesh_file(d / "points", "vectorField", ("%d\n(\n%s\n)\n" % (len(pts), "\n".join(
            "(%g %g %g)" % tuple(p) for p in pts))).encode(), False)
        _mesh_file(d / "faces", "faceList", ("%d\n(\n%s\n)\n" % (len(faces), "\n".join(
            "4(%s)" % " ".join(map(str, f)) for f in faces))).encode(), False)
        _mesh_file(d / "owner", "labelList", ("%d\n(\n%s\n)\n" % (len(owner), "\n".join(
            map(str, owner)))).encode(), False)
        _mesh_file(d / "neighbour", "labelList", ("%d\n(\n%s\n)\n" % (len(neighbour),
                   "\n".join(map(str, neighbour)))).encode(), False)
    (d / "boundary").write_text(
        "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class polyBoundaryMesh;\n"
        "    object boundary;\n}\n2\n(\n    frontAndBack\n    {\n        type empty;\n"
        "        nFaces 4;\n        startFace 1;\n    }\n    walls\n    {\n"
        "        type wall;\n        nFaces 6;\n        startFace 5;\n    }\n)\n")


@pytest.mark.parametrize("binary", [False, True])
def test_cell_polygons_from_the_mesh(tmp_path, binary):
    _two_cells(tmp_path, binary)
    # the report's centres, in another order than the mesh's cells
    centres = np.array([[1.5, 0.5, 0.05], [0.5, 0.5, 0.05]])
    polys = maps.cell_polygons(str(tmp_path), centres)
    assert polys is not None and len(polys) == 2
    assert np.allclose(polys[0].mean(axis=0), [1.5, 0.5])
    assert np.allclose(polys[1].mean(axis=0), [0.5, 0.5])
    # the outline: the six outer edges, not the shared one at x = 1
    out = maps.polygon_outline(polys)
    assert len(out) == 6
    assert not any(np.allclose([e[0][0], e[1][0]], 1.0) for e in out)
    # centres of another mesh (three cells): no polygons
    other = np.array([[0.5, 0.5, 0.05], [1.5, 0.5, 0.05], [1.0, 0.2, 0.05]])
    assert maps.cell_polygons(str(tmp_path), other) is None


def test_an_empty_cell_is_drawn_without_a_value(tmp_path):
    c = _step_centres()
    mean = np.column_stack([np.full(len(c), 1e12), np.full(len(c), 2e12), np.ones(len(c)),
                            np.ones(len(c))])
    mean[5, :] = 0.0                                 # an empty cell
    with np.errstate(invalid="ignore"):
        ratio = mean[:, 1] / mean[:, 0]
    res = {"centres": c, "mean": mean, "ci": 0.02 * mean, "meanMass": ratio,
           "meanMassCi": 0.01 * ratio}
    png, csv = maps.map_figure(res, str(tmp_path))
    rows = np.genfromtxt(csv, delimiter=",", names=True, skip_header=2)
    assert np.isnan(rows["meanMass"][5]) and np.isfinite(rows["meanMass"][4])
    assert os.path.getsize(png) > 10000
    # without the mesh: the triangles at the empty cell are out of the map and drawn grey
    tri = maps.triangulation(c[:, 0], c[:, 1])
    finite = np.isfinite(rows["meanMass"])
    t, grey = maps.split_invalid(tri, finite)
    at5 = (t.triangles == 5).any(axis=1)
    assert t.mask[at5].all() and len(grey) == np.count_nonzero(at5 & ~tri.mask)
    assert not t.mask[~at5 & ~tri.mask].any()
    # with the mesh's polygons: the empty cell in the colour map's 'bad' colour
    import matplotlib
    cmap = matplotlib.colormaps["viridis"].copy()
    cmap.set_bad("lightgrey")
    squares = [np.array([[x - 0.04, y - 0.04], [x + 0.04, y - 0.04], [x + 0.04, y + 0.04],
                         [x - 0.04, y + 0.04]]) for x, y in c[:, :2]]
    pc = maps.cell_collection(squares, rows["meanMass"], cmap, 0.5, 1.5)
    pc.update_scalarmappable()
    colours = pc.get_facecolors()
    assert np.allclose(colours[5], matplotlib.colors.to_rgba("lightgrey"))
    assert not np.allclose(colours[4], matplotlib.colors.to_rgba("lightgrey"))
