# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Sections of a three-dimensional OpenFOAM mesh for the report's plots: the cells an
axis-aligned plane cuts and their polygons, the cells a straight segment crosses.

read_mesh(case)             constant/polyMesh (ASCII or binary): points, faces, owner,
                            neighbour, the number of cells and the boundary's patches
cell_centres(mesh)          each cell's centre: the mean of its faces' centres (each the
                            mean of its points); exact for parallelepipeds, close enough
                            elsewhere to match cells
match_cells(mesh, centres)  the mesh cell of each of the report's cell centres (which come
                            in another order: merged from decomposed runs), by the nearest
                            cell centre; None unless the map is one-to-one
slice_polygons(mesh, a, v)  the cells the plane x[a] = v cuts and each cut's polygon in the
                            two other coordinates (in increasing axis order)
line_cells(mesh, p0, p1)    the cells the segment p0 + t (p1 - p0), 0 <= t <= 1, crosses,
                            in order, with the t of its entry and of its exit

The sections are exact for convex cells with planar faces (blockMesh's hexahedra, most of
snappyHexMesh's cells) and approximations for others.
"""

import os

import numpy as np

from .maps import _read_list, patches


def read_mesh(case):
    """{points [N][3], faces (index arrays), owner, neighbour (of the internal faces, which
    come first), nCells, patches ((name, type, nFaces, startFace) each)} of case's
    constant/polyMesh; ValueError naming the file where one cannot be read."""
    folder = os.path.join(case, "constant", "polyMesh")
    mesh = {}
    for name in ("points", "faces", "owner", "neighbour", "boundary"):
        path = os.path.join(folder, name)
        try:
            mesh[name] = patches(case) if name == "boundary" else _read_list(path)
        except (OSError, ValueError, IndexError, AttributeError) as e:
            raise ValueError("%s cannot be read: %s" % (path, e)) from e
    mesh["patches"] = mesh.pop("boundary")
    mesh["points"] = np.asarray(mesh["points"], float).reshape(-1, 3)
    mesh["owner"] = np.asarray(mesh["owner"], np.int64)
    mesh["neighbour"] = np.asarray(mesh["neighbour"], np.int64)
    if len(mesh["owner"]) != len(mesh["faces"]) or len(mesh["neighbour"]) > len(mesh["faces"]):
        raise ValueError("%s: %d faces, %d owners, %d neighbours" % (
            folder, len(mesh["faces"]), len(mesh["owner"]), len(mesh["neighbour"])))
    mesh["nCells"] = int(max(mesh["owner"].max(initial=-1),
                             mesh["neighbour"].max(initial=-1))) + 1
    return mesh


def _edges(mesh):
    """The faces' points as flat arrays: the face of each (face), the point (a), the next
    point around its face (b), and each face's number of points (size)."""
    faces = mesh["faces"]
    size = np.array([len(f) for f in faces], dtype=np.int64)
    a = np.concatenate(faces).astype(np.int64) if len(faces) else np.zeros(0, np.int64)
    face = np.repeat(np.arange(len(faces)), size)
    start = np.cumsum(size) - size
    nxt = np.arange(len(a)) + 1
    nxt[start + size - 1] = start
    return face, a, a[nxt], size


def _sum_by(index, values, n):
    """The sums of the rows of values [k][3] with the same index, for index 0 ... n-1."""
    return np.column_stack([np.bincount(index, values[:, j], n) for j in range(3)])


def _face_centres(mesh, face, a, size):
    return _sum_by(face, mesh["points"][a], len(size)) / size[:, None]


def _both_sides(mesh, values):
    """The cell on each side of every face (the owner's, then the internal faces'
    neighbour's), and values [nFaces] repeated for the internal faces."""
    n_int = len(mesh["neighbour"])
    cells = np.concatenate([mesh["owner"], mesh["neighbour"]])
    return cells, np.concatenate([values, values[:n_int]])


def cell_centres(mesh):
    """[nCells][3]: each cell's mean of its faces' centres (a face's centre: the mean of its
    points)."""
    face, a, _, size = _edges(mesh)
    cells, fc = _both_sides(mesh, _face_centres(mesh, face, a, size))
    n = mesh["nCells"]
    return _sum_by(cells, fc, n) / np.bincount(cells, minlength=n)[:, None]


def match_cells(mesh, centres):
    """cell[i]: the mesh cell whose centre is nearest to centres[i]; None where the counts
    differ or two centres fall to one cell."""
    from scipy.spatial import cKDTree

    c = np.asarray(centres, float).reshape(-1, 3)
    if len(c) != mesh["nCells"]:
        return None
    _, cell = cKDTree(cell_centres(mesh)).query(c)
    if len(np.unique(cell)) != len(c):
        return None
    return cell.astype(np.int64)


def slice_polygons(mesh, axis, value):
    """(cells, polygons): the cells (ascending) the plane x[axis] = value cuts and each cut
    as an [n][2] array of the two other coordinates, its vertices in order around it.

    The vertices are the points where the cell's faces' edges cross the plane. A point
    with x[axis] - value >= 0 counts as above it, so that a plane on a layer of faces cuts
    the cells below them (their top faces) only, neither losing nor doubling them, and a
    plane on the mesh's lowest boundary cuts the cells above it; a point within 1e-9 of the
    mesh's size of the plane is on it."""
    if axis not in (0, 1, 2):
        raise ValueError("axis %r is not 0, 1 or 2" % (axis,))
    pts = mesh["points"]
    face, a, b, _ = _edges(mesh)
    # each edge taken the same way round in every face: the same crossing bit for bit
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    # a point within round-off of the plane is on it: blockMesh's points on a layer of
    # faces scatter by an ulp about the value given
    tol = 1e-9 * max(np.ptp(pts, axis=0).max() if len(pts) else 0.0, 1e-300)
    if len(pts) and abs(value - pts[:, axis].min()) <= tol:
        # the mesh's lowest boundary: the cells above it (none lies below)
        value = pts[:, axis].min() + 2.0 * tol
    s = pts[:, axis] - value
    s[np.abs(s) <= tol] = 0.0
    above = s >= 0
    cut = above[lo] != above[hi]
    lo, hi, face = lo[cut], hi[cut], face[cut]
    uv = [k for k in range(3) if k != axis]
    t = (s[lo] / (s[lo] - s[hi]))[:, None]
    x = pts[lo][:, uv] + t * (pts[hi][:, uv] - pts[lo][:, uv])
    # each crossing a point of the face's owner and (internal faces) of its neighbour
    internal = face < len(mesh["neighbour"])
    x = np.concatenate([x, x[internal]])
    cells = np.concatenate([mesh["owner"][face], mesh["neighbour"][face[internal]]])
    # each cell's distinct points: the crossings of an edge seen from several faces, and of
    # several edges at a vertex on the plane, as one
    key = np.round((x - pts[:, uv].min(axis=0)) / tol).astype(np.int64)
    _, first = np.unique(np.column_stack([cells, key]), axis=0, return_index=True)
    cells, x = cells[first], x[first]
    out_cells, polygons = [], []
    uniq, start, count = np.unique(cells, return_index=True, return_counts=True)
    for cell, i, n in zip(uniq, start, count):
        p = x[i:i + n]
        m = p.mean(axis=0)
        p = p[np.argsort(np.arctan2(p[:, 1] - m[1], p[:, 0] - m[0]))]
        # one of two points within tol of each other that rounded to neighbouring keys
        p = p[np.hypot(*(p - np.roll(p, 1, axis=0)).T) > tol]
        if len(p) >= 3:
            out_cells.append(cell)
            polygons.append(p)
    return np.array(out_cells, dtype=np.int64), polygons


def line_cells(mesh, p0, p1):
    """(cells, t_in, t_out): the cells the segment p(t) = p0 + t (p1 - p0), 0 <= t <= 1,
    crosses, by t_in, each with the t of its entry and exit; only those with
    t_out - t_in > 1e-12.

    Each cell clips the segment by its faces' half-spaces (Cyrus-Beck): a face's normal n
    (Newell's: about its centre fc) points out of its owner, which holds
    n.(p(t) - fc) <= 0, and into its neighbour. A segment in the plane of an internal face
    belongs to the owner only, as a slice's plane on a layer of faces to one side."""
    p0 = np.asarray(p0, float)
    d = np.asarray(p1, float) - p0
    pts = mesh["points"]
    face, a, b, size = _edges(mesh)
    fc = _face_centres(mesh, face, a, size)
    normal = _sum_by(face, np.cross(pts[a] - fc[face], pts[b] - fc[face]), len(size))
    num = np.einsum("ij,ij->i", normal, p0 - fc)
    # a start within round-off of a face's plane is on it: the points of a layer of faces
    # scatter by an ulp, which would hand a segment along the layer to either side
    tol = 1e-9 * max(np.ptp(pts, axis=0).max() if len(pts) else 0.0, 1e-300)
    num[np.abs(num) <= tol * np.linalg.norm(normal, axis=1)] = 0.0
    den = normal @ d
    scale = np.linalg.norm(normal, axis=1) * np.linalg.norm(d)
    n_faces, n_int = len(size), len(mesh["neighbour"])
    cells, num = _both_sides(mesh, num)
    num[n_faces:] *= -1
    den = np.concatenate([den, -den[:n_int]])
    scale = np.concatenate([scale, scale[:n_int]])
    parallel = np.abs(den) <= 1e-12 * scale
    # parallel to a face and on its far side (or on it, for the neighbour): out
    outside = parallel & np.concatenate([num[:n_faces] > 0, num[n_faces:] >= 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -num / den
    t_in, t_out = np.zeros(mesh["nCells"]), np.ones(mesh["nCells"])
    entry, leave = ~parallel & (den < 0), ~parallel & (den > 0)
    np.maximum.at(t_in, cells[entry], t[entry])
    np.minimum.at(t_out, cells[leave], t[leave])
    t_out[cells[outside]] = -np.inf
    keep = np.flatnonzero(t_out - t_in > 1e-12)
    keep = keep[np.argsort(t_in[keep], kind="stable")]
    return keep, t_in[keep], t_out[keep]
