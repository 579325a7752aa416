# SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
"""coagulationView: a ParaView view of a coagulationFoam case written by foamToVTK.

Opens the case's VTK series (VTK/<case>.vtm.series and the cloud's
VTK/lagrangian/<cloud>/<cloud>.vtp.series) at the latest time: the cells coloured by a
moment field (M0 by default) and the particles as Point Gaussian splats coloured by their
mass on a log scale.  A two-dimensional mesh (one cell thick) is seen face on; a
three-dimensional one as a slice through the middle of the domain across its thinnest
extent (--slice: across that axis, on any mesh), with the particles around it.

  pvbatch coagulationView.py [--case DIR] [--png FILE] [--field M0] [--cloud NAME]
                             [--size 1600x900 | 1600] [--slice x|y|z]
      renders FILE (no display: run it under virtualDisplay from etc/functions, or
      xvfb-run -s "-screen 0 1280x1024x24 -noreset"; Debian's pvbatch has no
      off-screen rendering without X)
  paraview --script=coagulationView.py
      the same view in ParaView's window, for the case in the current folder

Exit status 0, or 2 when the case has no VTK series (run foamToVTK first) or the field
is not in it.
"""

import argparse
import glob
import json
import math
import os
import sys

import paraview.simple
from paraview.simple import (ColorBy, CreateLayout, CreateView, ExtractBlock,
                             GetAnimationScene, GetColorTransferFunction, GetScalarBar,
                             OpenDataFile, SaveScreenshot, Show, Slice)


BAR = 200  # the pixels below each picture for its colour bar
MIN_PICTURE = 80  # the fewest pixels of a picture across and above its bar


def fail(msg):
    print("coagulationView: error: %s" % msg, file=sys.stderr)
    sys.exit(2)


def series(pattern):
    """The first file that matches pattern, and its latest time."""
    found = sorted(glob.glob(pattern))
    if not found:
        return None, None
    with open(found[0]) as f:
        times = [entry["time"] for entry in json.load(f)["files"]]
    return found[0], max(times)


def parse(argv):
    p = argparse.ArgumentParser(prog="coagulationView.py")
    p.add_argument("--case", default=".")
    p.add_argument("--png", default=None, help="render to this file and exit")
    p.add_argument("--field", default="M0", help="the cell field coloured (default M0)")
    p.add_argument("--cloud", default=None, help="the cloud (default: the first found)")
    p.add_argument("--size", default=None,
                   help="the picture's pixels, WxH, or W alone (default: 1600 wide; the "
                        "height the domain needs)")
    p.add_argument("--slice", choices=("x", "y", "z"), default=None,
                   help="the slice's normal (default: a 3-D mesh's thinnest axis; a 2-D "
                        "mesh is seen face on unless this is given)")
    # in ParaView's window the arguments are ParaView's own: ignore what is not ours
    return p.parse_known_args(argv)[0]


def main(argv):
    args = parse(argv)
    # the camera is set below: no reset to the data's bounds at the first render
    paraview.simple._DisableFirstRenderCameraReset()
    vtk = os.path.join(os.path.abspath(args.case), "VTK")
    mesh_file, t_mesh = series(os.path.join(vtk, "*.vtm.series"))
    if mesh_file is None:
        fail("no VTK/*.vtm.series in %s: run foamToVTK first" % args.case)
    cloud = args.cloud or "*"
    cloud_file, t_cloud = series(os.path.join(vtk, "lagrangian", cloud, "*.vtp.series"))

    time = max(t for t in (t_mesh, t_cloud) if t is not None)

    # the cells: the internal mesh only (the patches would hide a 3-D interior)
    reader = OpenDataFile(mesh_file)
    cells = ExtractBlock(Input=reader, Selectors=["/Root/internal"])
    cells.UpdatePipeline(time)
    if args.field not in cells.CellData.keys():
        fail("no cell field %s in %s (fields: %s)"
             % (args.field, mesh_file, ", ".join(cells.CellData.keys())))
    bounds = cells.GetDataInformation().GetBounds()
    extent = [bounds[2 * k + 1] - bounds[2 * k] for k in range(3)]
    centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    # of extents equal to round-off the last axis, as coagulationReport's default slice
    thin = max(range(3), key=lambda k: (-round(extent[k] / max(max(extent), 1e-300), 6), k))
    if args.slice or extent[thin] >= 0.05 * max(extent):
        # three-dimensional (or a slice asked for): a slice through the middle (on a layer of
        # faces, VTK's cut takes one layer's cells: the test counts them)
        thin = "xyz".index(args.slice) if args.slice else thin
        cut = Slice(Input=cells)
        cut.SliceType = "Plane"
        cut.SliceType.Origin = centre
        cut.SliceType.Normal = [1.0 if k == thin else 0.0 for k in range(3)]
        cut.Triangulatetheslice = 0      # a polygon a cell
        cut.UpdatePipeline(time)
        print("coagulationView: the slice %s = %.6g through %d cells"
              % ("xyz"[thin], centre[thin], cut.GetDataInformation().GetNumberOfCells()))
        cells = cut
    # the picture's axes: the slice's two others, the vertical one z unless it is the normal
    up = 2 if thin != 2 else 1
    across = [k for k in range(3) if k not in (thin, up)][0]
    # two views, the cells and the particles: stacked for a long domain, else side by
    # side; each the domain's picture above its colour bar (BAR pixels)
    stacked = extent[across] > 2.0 * extent[up]
    if args.size and "x" in args.size.lower():
        w, h = (int(v) for v in args.size.lower().split("x"))
    else:
        w = int(args.size) if args.size else 1600
        pw = w if stacked else w / 2
        view_h = int(min(max(0.9 * pw * extent[up] / extent[across], 80), 900)) + BAR
        h = 2 * view_h if stacked else view_h
    pw, ph = (w, h / 2.0) if stacked else (w / 2.0, h)
    # each view needs room for a picture above its colour bar
    if pw < MIN_PICTURE or ph - BAR < MIN_PICTURE:
        fail("--size %s leaves each of the two views (%s) %dx%d pixels: too small for a picture "
             "of at least %d pixels above its %d-pixel colour bar; give at least %dx%d"
             % (args.size, "stacked" if stacked else "side by side", pw, ph, MIN_PICTURE, BAR,
                MIN_PICTURE * (1 if stacked else 2),
                (MIN_PICTURE + BAR) * (2 if stacked else 1)))
    # the domain fills its view above the bar: k pixels a metre
    k = min(0.9 * pw / extent[across], 0.9 * (ph - BAR) / extent[up])
    layout = CreateLayout("coagulationView")
    layout.SplitVertical(0, 0.5) if stacked else layout.SplitHorizontal(0, 0.5)
    views = []
    for cell in (1, 2):
        view = CreateView("RenderView")
        view.ViewTime = time
        view.OrientationAxesVisibility = 1
        layout.AssignView(cell, view)
        views.append(view)

    shown = Show(cells, views[0])
    # unlit: each cell in its colour bar's colour
    shown.Ambient, shown.Diffuse = 1.0, 0.0
    ColorBy(shown, ("CELLS", args.field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    field_lut = GetColorTransferFunction(args.field)
    field_lut.ApplyPreset("Viridis (matplotlib)", True)
    bar(field_lut, views[0], args.field, cells.CellData[args.field].GetRange())

    # the particles: Point Gaussian splats, coloured by mass on a log scale, over the
    # mesh's outline
    if cloud_file is not None:
        outline = Show(cells, views[1])
        outline.SetRepresentationType("Feature Edges")
        outline.ColorArrayName = ["POINTS", ""]
        outline.AmbientColor = outline.DiffuseColor = [0.1, 0.1, 0.1]
        particles = OpenDataFile(cloud_file)
        particles.UpdatePipeline(time)
        dots = Show(particles, views[1])
        dots.SetRepresentationType("Point Gaussian")
        dots.GaussianRadius = 2.5 / k  # pixels
        # flat discs in the colour bar's colours
        dots.ShaderPreset = "Plain circle"
        ColorBy(dots, ("POINTS", "mass"))
        mass_lut = GetColorTransferFunction("mass")
        mass_lut.ApplyPreset("Inferno (matplotlib)", True)
        dots.RescaleTransferFunctionToDataRange(True, False)
        lo_m, hi_m = particles.PointData["mass"].GetRange()
        if lo_m > 0 and hi_m > lo_m:
            mass_lut.MapControlPointsToLogSpace()
            mass_lut.UseLogScale = 1
        bar(mass_lut, views[1], "particle mass")

    # the camera: face on to the 2-D mesh or the slice, parallel projection
    # from the side that puts the picture's other axis to the right, the domain's centre
    # BAR/2 pixels above the view's
    focus = list(centre)
    focus[up] -= 0.5 * BAR / k
    position = list(focus)
    position[thin] += (-2.0 if thin == 1 else 2.0) * max(extent)
    for view in views:
        view.CameraPosition = position
        view.CameraFocalPoint = focus
        view.CameraViewUp = [1.0 if j == up else 0.0 for j in range(3)]
        view.CameraParallelProjection = 1
        view.CameraParallelScale = 0.5 * ph / k
    # the time shown, also in ParaView's window (its time controls follow the scene)
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = time
    if args.png:
        os.makedirs(os.path.dirname(os.path.abspath(args.png)), exist_ok=True)
        SaveScreenshot(args.png, layout, SaveAllViews=1, ImageResolution=[w, h],
                       SeparatorWidth=0)
        print("coagulationView: %s (t = %g)" % (args.png, time))


def nice_ticks(lo, hi, count=4):
    """About count round values inside [lo, hi], none within 12 % of the range of its ends
    (where the range's own labels are)."""
    if not hi > lo:
        return []
    raw = (hi - lo) / count
    step = 10.0 ** math.floor(math.log10(raw))
    step *= min((m for m in (1, 2, 2.5, 5, 10) if m * step >= raw), default=10)
    first = math.ceil(lo / step) * step
    ticks = [first + i * step for i in range(int((hi - first) / step) + 1)]
    margin = 0.12 * (hi - lo)
    return [t for t in ticks if lo + margin < t < hi - margin]


def bar(lut, view, title, linear_range=None):
    """The colour bar of lut in view: horizontal, below the picture; on a linear scale
    (linear_range given) labels at a few round values besides the range's ends (ParaView's
    own crowd on a short bar)."""
    b = GetScalarBar(lut, view)
    if linear_range is not None:
        b.UseCustomLabels = 1
        b.CustomLabels = nice_ticks(*linear_range)
        b.AddRangeLabels = 1
    b.Title = title
    b.ComponentTitle = ""
    b.Orientation = "Horizontal"
    b.WindowLocation = "Lower Center"
    b.ScalarBarLength = 0.5
    b.ScalarBarThickness = 12
    b.TitleFontSize = 9
    b.LabelFontSize = 8
    b.Visibility = 1


if __name__ == "__main__":
    main(sys.argv[1:])
