# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""Maps of the report's time-averaged cell moments: on a two-dimensional mesh (one cell
thick, or any mesh whose cell centres lie in a plane), on a plane through any mesh, and
along a line.

dimension(centres)        how many axes the cell centres spread along: 1, 2 or 3
plane(centres)            the two axes of a two-dimensional mesh's plane
triangulation(u, v)       the Delaunay triangles of the centres, without those that bridge a
                          gap of the domain (a step, an obstacle): triangles with an edge
                          longer than 2.5 times the longer of its vertices' nearest-neighbour
                          distances are masked
cell_polygons(case, c)    each cell's polygon on the mesh's plane, from constant/polyMesh
                          (ASCII or binary): its face on the 'empty' patch of the smaller
                          coordinate
map_figure(res, out)      maps.png: the means of M0, M1 and the mean mass M1/M0 (top row) and
                          their relative 95 % half-widths (ci95 over the mean; bottom row),
                          each cell's polygon in its colour (or, without the mesh, the values
                          at the centres, linear in the triangles between them), the domain's
                          outline; maps.csv beside it holds every cell's plotted values and
                          each panel's colour range
slice_figure(res, out, mesh, cell_of_row, axis, value)
                          the same maps on the cells the plane x[axis] = value cuts, each
                          drawn as its cut: slice_<axis><value>.png and .csv
line_figure(res, out, mesh, cell_of_row, p0, p1, name)
                          M0, M1 and M1/M0 of the cells the segment p0 p1 crosses against
                          the distance along it, a step per cell with its 95 % interval as
                          a band: <name>.png and .csv

The values are each cell's own time averages and intervals, not interpolated between
cells: a picture shows what the report's statistics say, cell by cell.
"""

import os
import re

import numpy as np

QUANTITIES = ("M0", "M1", "meanMass", "M0_relCI95", "M1_relCI95", "meanMass_relCI95")
# with the particles' material: the diameter of the mean mass
DIAMETER = ("meanDiameter", "meanDiameter_relCI95")


def dimension(centres, rel_tol=1e-9):
    """The number of axes along which the cell centres spread beyond rel_tol of the
    mesh's extent."""
    c = np.asarray(centres, float).reshape(-1, 3)
    if len(c) < 2:
        return 0
    span = np.ptp(c, axis=0)
    return int(np.sum(span > rel_tol * span.max()))


def plane(centres, rel_tol=1e-9):
    """The two axes (indices) a two-dimensional mesh's centres spread along."""
    c = np.asarray(centres, float).reshape(-1, 3)
    span = np.ptp(c, axis=0)
    axes = [a for a in range(3) if span[a] > rel_tol * span.max()]
    if len(axes) != 2:
        raise ValueError("the cell centres spread along %d axes, not 2" % len(axes))
    return axes


def triangulation(u, v):
    """matplotlib's Delaunay triangulation of the points (u, v) with the triangles masked
    that bridge a gap of the domain (an edge longer than 2.5 times the longer of its two
    vertices' nearest-neighbour distances)."""
    import matplotlib.tri as mtri
    from scipy.spatial import cKDTree

    tri = mtri.Triangulation(u, v)
    pts = np.column_stack([u, v])
    dist, _ = cKDTree(pts).query(pts, k=2)
    near = dist[:, 1]
    t = tri.triangles
    mask = np.zeros(len(t), dtype=bool)
    for a, b in ((0, 1), (1, 2), (2, 0)):
        edge = np.hypot(u[t[:, a]] - u[t[:, b]], v[t[:, a]] - v[t[:, b]])
        mask |= edge > 2.5 * np.maximum(near[t[:, a]], near[t[:, b]])
    tri.set_mask(mask)
    return tri


def outline(tri):
    """The edges of the unmasked triangles that belong to one of them only: the outline
    of the domain (and of its holes), as [(u0, v0), (u1, v1)] segments."""
    t = tri.triangles[~tri.mask] if tri.mask is not None else tri.triangles
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    uniq, count = np.unique(edges, axis=0, return_counts=True)
    once = uniq[count == 1]
    return [((tri.x[a], tri.y[a]), (tri.x[b], tri.y[b])) for a, b in once]


def _read_list(path):
    """The list(s) of an OpenFOAM polyMesh file, ASCII or binary: points as an [N][3]
    array, labels as an [N] array, faces as a list of index arrays (faceList in ASCII,
    faceCompactList's offsets and indices in binary)."""
    with open(path, "rb") as f:
        data = f.read()
    head_end = data.index(b"}", data.index(b"FoamFile")) + 1
    header = data[:head_end].decode("latin-1")
    binary = re.search(r"format\s+binary", header) is not None
    m = re.search(r"label\s*=\s*(\d+)", header)
    label = np.int64 if m and m.group(1) == "64" else np.int32
    m = re.search(r"scalar\s*=\s*(\d+)", header)
    scalar = np.float32 if m and m.group(1) == "32" else np.float64
    cls = re.search(r"class\s+(\w+)", header).group(1)
    body = data[head_end:]

    def count_at(pos):
        """The count of the list whose count starts at or after pos (past comments), and
        the position just after its '('"""
        m = re.compile(rb"(?:^|\n)\s*(\d+)\s*\(", re.S).search(body, pos)
        return int(m.group(1)), m.end()

    n, pos = count_at(0)
    if binary:
        if cls == "vectorField":
            return np.frombuffer(body, scalar, 3 * n, pos).reshape(n, 3)
        if cls == "labelList":
            return np.frombuffer(body, label, n, pos)
        if cls == "faceCompactList":
            offsets = np.frombuffer(body, label, n, pos)
            m2, pos2 = count_at(pos + n * np.dtype(label).itemsize + 1)
            idx = np.frombuffer(body, label, m2, pos2)
            return [idx[offsets[i]:offsets[i + 1]] for i in range(n - 1)]
        raise ValueError("%s: binary %s is not read here" % (path, cls))
    text = body[pos:].decode("latin-1")
    if cls == "vectorField":
        return np.array(text.replace("(", " ").replace(")", " ").split()[:3 * n],
                        dtype=float).reshape(n, 3)
    if cls == "labelList":
        return np.array(text.replace(")", " ").split()[:n], dtype=int)
    if cls in ("faceList", "faceCompactList"):
        faces = re.findall(r"\d+\s*\(([^)]*)\)", text)[:n]
        return [np.array(f.split(), dtype=int) for f in faces]
    raise ValueError("%s: %s is not read here" % (path, cls))


def patches(case):
    """(name, type, nFaces, startFace) of each patch of constant/polyMesh/boundary."""
    with open(os.path.join(case, "constant", "polyMesh", "boundary")) as f:
        text = f.read()
    # after the header's dictionary (no braces inside it), each patch's dictionary
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    out = []
    for name, entries in re.findall(r"(\w+)\s*\{([^}]*)\}", body):
        def get(key):
            m = re.search(r"\b%s\s+(\w+)\s*;" % key, entries)
            return m.group(1) if m else None
        out.append((name, get("type"), int(get("nFaces") or 0), int(get("startFace") or 0)))
    return out


def cell_polygons(case, centres):
    """Each cell's polygon in the plane of a two-dimensional mesh (one cell thick between
    two 'empty' patches): the cell's face on the patch side of the smaller coordinate,
    from constant/polyMesh (ASCII or binary, sections.read_mesh), its points' two in-plane
    coordinates; the cells matched to centres (the report's order: a decomposed run's
    differs from the mesh's) by sections.match_cells. None where the mesh cannot be read so
    or does not match the centres."""
    from . import sections

    try:
        mesh = sections.read_mesh(case)
    except ValueError:
        return None
    points, faces, owner = mesh["points"], mesh["faces"], mesh["owner"]
    # the normal of the plane: an axis the centres do not spread along (of two such, the
    # mesh's thinner)
    c = np.asarray(centres, float)
    spread = np.ptp(c, axis=0)
    flat = [k for k in range(3) if spread[k] <= 1e-9 * max(spread.max(), 1e-300)]
    if not flat:
        return None
    normal = min(flat, key=lambda k: np.ptp(points[:, k]))
    a, b = [k for k in range(3) if k != normal]
    front = points[:, normal].min()
    tol = 1e-9 * max(np.ptp(points, axis=0).max(), 1e-300)
    poly = {}
    for _, kind, n, start in mesh["patches"]:
        if kind != "empty":
            continue
        for fi in range(start, start + n):
            pts = points[faces[fi]]
            if np.all(np.abs(pts[:, normal] - front) <= tol):
                poly[int(owner[fi])] = pts[:, [a, b]]
    cell_of_row = sections.match_cells(mesh, c)
    if len(poly) != mesh["nCells"] or cell_of_row is None:
        return None
    return [poly[k] for k in cell_of_row]


def values(res, material=None):
    """Every cell's plotted values: {quantity: array} of QUANTITIES. The mean mass where
    M0 > 0; the relative 95 % half-widths, the report's intervals over the means (one run's
    from its correlated samples, or the realisations'), the mean mass's its own
    (report.compute's meanMassCi: with the covariance of M0 and M1). With material =
    (density [kg/m3], kg per mass unit) also DIAMETER: the diameter of a sphere of the mean
    mass [nm] and its relative half-width, a third of the mass's (to first order)."""
    from .psd import sphere_diameter

    mean, ci = res["mean"], res["ci"]
    with np.errstate(invalid="ignore", divide="ignore"):
        out = {
            "M0": mean[:, 0],
            "M1": mean[:, 1],
            "meanMass": res["meanMass"],
            "M0_relCI95": ci[:, 0] / mean[:, 0],
            "M1_relCI95": ci[:, 1] / mean[:, 1],
            "meanMass_relCI95": res["meanMassCi"] / res["meanMass"],
        }
    if material:
        out["meanDiameter"] = 1e9 * sphere_diameter(out["meanMass"], *material)
        out["meanDiameter_relCI95"] = out["meanMass_relCI95"] / 3.0
    return out


def split_invalid(tri, finite):
    """The triangulation with the triangles at a cell without a value (finite False) masked
    too, and those triangles as polygons [k][3][2] (drawn grey)."""
    from matplotlib.tri import Triangulation

    t = Triangulation(tri.x, tri.y, tri.triangles, tri.mask)
    shown = np.ones(len(t.triangles), dtype=bool) if t.mask is None else ~t.mask
    bad = ~np.asarray(finite)[t.triangles].all(axis=1) & shown
    t.set_mask(~shown | bad)
    tb = t.triangles[bad]
    return t, np.stack([t.x[tb], t.y[tb]], axis=-1)


def cell_collection(polygons, z, cmap, vmin, vmax):
    """The cells' polygons coloured by z on cmap over [vmin, vmax], the cells without a
    value (not finite) in the colour map's 'bad' colour; edges in the cells' colours (no
    seams between them)."""
    from matplotlib.collections import PolyCollection

    pc = PolyCollection(polygons, array=np.ma.masked_invalid(z), cmap=cmap,
                        edgecolors="face", linewidths=0.3)
    pc.set_clim(vmin, vmax)
    return pc


def polygon_outline(polygons):
    """The edges that belong to one polygon only: the outline of the domain (its patches)."""
    edges = {}
    for p in polygons:
        for i in range(len(p)):
            e = tuple(sorted((tuple(np.round(p[i], 12)), tuple(np.round(p[i - 1], 12)))))
            edges[e] = edges.get(e, 0) + 1
    return [e for e, n in edges.items() if n == 1]


LABELS = {"M0": "M0 [1/m³]", "M1": "M1 [mass unit/m³]", "meanMass": "M1/M0 [mass unit]",
          "M0_relCI95": "M0's 95 % half-width / M0",
          "M1_relCI95": "M1's 95 % half-width / M1",
          "meanMass_relCI95": "M1/M0's 95 % half-width / M1/M0",
          "meanDiameter": "diameter of the mean mass [nm]",
          "meanDiameter_relCI95": "its 95 % half-width / diameter"}


def _draw(vals, a, b, polygons, tri, title, png):
    """The six panels of vals (each cell's polygon in its colour, or with tri the values at
    the centres, linear in its triangles) on the plane of axes a and b, the domain's
    outline, saved as png; returns each quantity's colour range."""
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.ticker import MaxNLocator
    from .plots import _pyplot

    if tri is not None:
        u, v = tri.x, tri.y
    else:
        corners = np.concatenate(polygons)
        u, v = corners[:, 0], corners[:, 1]
    names = "xyz"
    plt = _pyplot()
    span = np.ptp(u) / max(np.ptp(v), 1e-300)
    # the third quantity: the mean particle's diameter where the material is known
    third = "meanDiameter" if "meanDiameter" in vals else "meanMass"
    if span > 6:
        # a very long domain (a channel): one panel a row, the quantity above its error
        order = ("M0", "M0_relCI95", "M1", "M1_relCI95", third, third + "_relCI95")
        fig, axes = plt.subplots(6, 1, figsize=(14, 6 * (11.0 / span + 0.9) + 0.6),
                                 squeeze=False)
    elif span > 3:
        # a long domain (a channel, a step): a quantity and its error side by side, in rows
        order = ("M0", "M0_relCI95", "M1", "M1_relCI95", third, third + "_relCI95")
        fig, axes = plt.subplots(3, 2, figsize=(15, 3 * max(1.6, 7.0 / span) + 1.5),
                                 squeeze=False)
    else:
        order = ("M0", "M1", third, "M0_relCI95", "M1_relCI95", third + "_relCI95")
        fig, axes = plt.subplots(2, 3, figsize=(15, 2 * max(2.2, min(5.0, 4.6 / span)) + 1.2),
                                 squeeze=False)
    ranges = {}
    segments = outline(tri) if tri is not None else polygon_outline(polygons)
    for q, ax in zip(order, axes.ravel()):
        z = vals[q]
        finite = np.isfinite(z)
        lo, hi = (float(np.min(z[finite])), float(np.max(z[finite]))) if finite.any() \
            else (0.0, 1.0)
        ranges[q] = (lo, hi)
        # a field that is the same in every cell (to round-off) gets a colour bar around it
        pad = 0.0 if hi - lo > 1e-9 * max(abs(hi), abs(lo)) else max(1e-6 * abs(hi), 1e-300)
        # cells without a value (the mean mass and the errors of an empty cell) in grey
        cmap = plt.get_cmap("viridis").copy()
        cmap.set_bad("lightgrey")
        if tri is not None:
            # gouraud shading takes no masked values: the triangles at such a cell are
            # drawn grey beneath, and left out of the map
            t, grey = split_invalid(tri, finite)
            ax.add_collection(PolyCollection(grey, facecolors="lightgrey", edgecolors="none"))
            pc = ax.tripcolor(t, np.where(finite, z, lo), shading="gouraud", vmin=lo - pad,
                              vmax=hi + pad, cmap=cmap)
        else:
            pc = cell_collection(polygons, z, cmap, lo - pad, hi + pad)
            ax.add_collection(pc)
            ax.autoscale_view()
        ax.add_collection(LineCollection(segments, colors="k", linewidths=0.8))
        fig.colorbar(pc, ax=ax, shrink=0.85)
        ax.set_aspect("equal")
        ax.xaxis.set_major_locator(MaxNLocator(4))
        ax.yaxis.set_major_locator(MaxNLocator(4))
        ax.set_title(LABELS[q], fontsize=9)
        ax.set_xlabel("%s [m]" % names[a])
        ax.set_ylabel("%s [m]" % names[b])
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    return ranges


def _write_cells(path, notes, rows, centres, vals):
    """The CSV of a map: the notes as '# ' lines, then each row's cell (the report's index),
    centre and values (QUANTITIES, and DIAMETER where there are)."""
    names = [q for q in QUANTITIES + DIAMETER if q in vals]
    with open(path, "w") as f:
        for note in notes:
            f.write("# %s\n" % note)
        f.write("cell,x,y,z," + ",".join(names) + "\n")
        for i in rows:
            f.write("%d,%.12g,%.12g,%.12g," % (i, *centres[i])
                    + ",".join("%.12g" % vals[q][i] for q in names) + "\n")


def _ranges_note(ranges):
    return "colour ranges: %s" % ", ".join("%s %.12g %.12g" % (q, *r) for q, r in ranges.items())


def map_figure(res, out, title="", case=None, material=None):
    """maps.png and maps.csv of a two-dimensional report (see the module's text): each
    cell's polygon in its colour where the case's mesh gives them (cell_polygons), else the
    values at the centres, linear in the triangles between them; with material (density,
    kg per mass unit) the diameter of the mean mass in place of the mean mass; returns
    their paths."""
    centres = np.asarray(res["centres"], float)
    a, b = plane(centres)
    polygons = cell_polygons(case, centres) if case else None
    tri = None if polygons is not None else triangulation(centres[:, a], centres[:, b])
    vals = values(res, material)
    os.makedirs(out, exist_ok=True)
    png = os.path.join(out, "maps.png")
    ranges = _draw(vals, a, b, polygons, tri, "Time-averaged moments per cell%s"
                   % (": " + title if title else ""), png)
    path = os.path.join(out, "maps.csv")
    _write_cells(path, [_ranges_note(ranges),
                        "cells drawn as %s" % ("the mesh's polygons" if tri is None
                                               else "triangles between the centres")],
                 range(len(centres)), centres, vals)
    return [png, path]


def _rows(mesh, cell_of_row, cells):
    """The report's rows of the mesh's cells."""
    row_of_cell = np.full(mesh["nCells"], -1, dtype=np.int64)
    row_of_cell[cell_of_row] = np.arange(len(cell_of_row))
    return row_of_cell[cells]


def slice_figure(res, out, mesh, cell_of_row, axis, value, title="", material=None):
    """slice_<axis><value>.png and .csv: the maps of map_figure on the cells the plane
    x[axis] = value cuts, each drawn as its cut (sections.slice_polygons); cell_of_row the
    mesh cell of each of the report's rows (sections.match_cells). ValueError where the
    plane misses the mesh."""
    from . import sections

    cells, polygons = sections.slice_polygons(mesh, axis, value)
    name = "xyz"[axis]
    if not len(cells):
        lo, hi = mesh["points"][:, axis].min(), mesh["points"][:, axis].max()
        raise ValueError("the plane %s = %g does not cut the mesh (%s from %g to %g)"
                         % (name, value, name, lo, hi))
    rows = _rows(mesh, cell_of_row, cells)
    vals = values(res, material)
    sub = {q: v[rows] for q, v in vals.items()}
    a, b = [k for k in range(3) if k != axis]
    os.makedirs(out, exist_ok=True)
    stem = os.path.join(out, "slice_%s%g" % (name, value))
    ranges = _draw(sub, a, b, polygons, None, "Time-averaged moments per cell on the plane "
                   "%s = %g%s" % (name, value, ": " + title if title else ""), stem + ".png")
    _write_cells(stem + ".csv", [_ranges_note(ranges),
                                 "cells cut by the plane %s = %g, drawn as their cuts"
                                 % (name, value)],
                 rows, np.asarray(res["centres"], float), vals)
    return [stem + ".png", stem + ".csv"]


def steps(s_in, s_out, *values):
    """The arrays that draw each cell's values as a step from its entry to its exit: x and
    each of values, three points a cell (entry, exit, and NaN after a cell the next does not
    start at: a break where the segment leaves the mesh and comes back)."""
    s_in, s_out = np.asarray(s_in, float), np.asarray(s_out, float)
    tol = 1e-9 * max(float(np.max(s_out)) if len(s_out) else 0.0, 1e-300)
    gap = np.append(s_in[1:] > s_out[:-1] + tol, False)

    def three(a, b):
        return np.column_stack([a, b, np.where(gap, np.nan, b)]).ravel()
    return (three(s_in, s_out),) + tuple(three(v, v) for v in values)


def line_figure(res, out, mesh, cell_of_row, p0, p1, name, title="", material=None):
    """<name>.png and <name>.csv: the time-averaged M0, M1 and M1/M0 of each cell the
    segment p0 p1 crosses (sections.line_cells), against the distance along it from p0: a
    step per cell from its entry to its exit, with the 95 % interval as a band; with
    material (density, kg per mass unit) the diameter of the mean mass [nm] in place of the
    mean mass, its interval a third of the mass's relative one. ValueError where the segment
    misses the mesh."""
    from . import sections
    from .plots import _pyplot

    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    cells, t_in, t_out = sections.line_cells(mesh, p0, p1)
    where = "(%g %g %g) to (%g %g %g)" % (*p0, *p1)
    if not len(cells):
        raise ValueError("the line %s does not cross the mesh" % where)
    rows = _rows(mesh, cell_of_row, cells)
    length = np.linalg.norm(p1 - p0)
    s_in, s_out = t_in * length, t_out * length
    mean, ci = res["mean"][rows], res["ci"][rows]
    third = ("meanMass", res["meanMass"][rows], res["meanMassCi"][rows])
    if material:
        from .psd import sphere_diameter
        d = 1e9 * sphere_diameter(third[1], *material)
        third = ("meanDiameter", d, d * third[2] / (3.0 * third[1]))
    columns = (("M0", mean[:, 0], ci[:, 0]), ("M1", mean[:, 1], ci[:, 1]), third)
    plt = _pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(15, 4), squeeze=False)
    for (q, m, c), ax in zip(columns, axes.ravel()):
        x, y, e = steps(s_in, s_out, m, c)
        ax.fill_between(x, y - e, y + e, color="C0", alpha=0.25, linewidth=0,
                        label="95 % interval")
        ax.plot(x, y, color="C0", lw=1.2, label="cell mean")
        ax.set_xlabel("distance from (%g %g %g) [m]" % tuple(p0))
        ax.set_ylabel(LABELS[q])
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("Time-averaged moments along %s, %d cells%s"
                 % (where, len(cells), ": " + title if title else ""), fontsize=10)
    fig.tight_layout()
    os.makedirs(out, exist_ok=True)
    png, path = os.path.join(out, name + ".png"), os.path.join(out, name + ".csv")
    fig.savefig(png, dpi=110)
    plt.close(fig)
    centres = np.asarray(res["centres"], float)
    with open(path, "w") as f:
        f.write("# the cells along the line %s, from where it enters each to where it "
                "leaves, distances from its start [m]\n" % where)
        f.write("s_in,s_out,cell,x,y,z," + ",".join("%s,%s_ci95" % (q, q) for q, _, _ in columns)
                + "\n")
        for k, r in enumerate(rows):
            f.write("%.12g,%.12g,%d,%.12g,%.12g,%.12g," % (s_in[k], s_out[k], r, *centres[r])
                    + ",".join("%.12g,%.12g" % (m[k], c[k]) for _, m, c in columns) + "\n")
    return [png, path]
