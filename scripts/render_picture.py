#!/usr/bin/env python3
"""Render the last ParaView frame of a gapfem run to a PNG (VTK, offscreen).

    xvfb-run -a /usr/bin/python3 scripts/render_picture.py RESULTS.pvd OUT.png [--compare REF.png]

Draws the deformed mesh (displacements magnified so the largest is 8 % of the model's size) coloured
by the displacement magnitude, with beams and trusses as tubes and each gap element as a ball at
its first node coloured by its status (open, closed, sticking, slipping). The README's picture is
made by this script from examples/01_pipe_on_supports (tests/cli/readme_picture_test.cpp remakes it
and compares, so it never goes stale). With --compare, exits 1 when OUT.png differs from REF.png by
more than a few grey levels on average.

Debian packages: python3-vtk9 (use /usr/bin/python3) and, without a display, xvfb.
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk

STATUS = {0: ("open", (0.6, 0.6, 0.6)), 1: ("closed", (0.85, 0.1, 0.1)),
          2: ("sticking", (0.1, 0.35, 0.9)), 3: ("slipping", (1.0, 0.6, 0.0))}


def last_frame(path):
    if not path.endswith(".pvd"):
        return path
    sets = ET.parse(path).getroot().iter("DataSet")
    last = sorted(sets, key=lambda d: float(d.get("timestep", "0")))[-1]
    return os.path.join(os.path.dirname(path), last.get("file"))


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def warped(grid):
    """The grid moved by U magnified to 8 % of the bounding-box diagonal; also that factor."""
    b = grid.GetBounds()
    diag = math.sqrt(sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3))) or 1.0
    u = grid.GetPointData().GetArray("U")
    umax = u.GetMaxNorm() if u else 0.0
    if not u or umax == 0.0:
        return grid, 1.0, diag
    grid.GetPointData().SetActiveVectors("U")
    scale = 0.08 * diag / umax
    w = vtk.vtkWarpVector()
    w.SetInputData(grid)
    w.SetScaleFactor(scale)
    w.Update()
    return w.GetOutput(), scale, diag


def magnitude_lut(grid):
    u = grid.GetPointData().GetArray("U")
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetRange(0.0, u.GetMaxNorm() if u and u.GetMaxNorm() > 0 else 1.0)
    lut.SetVectorModeToMagnitude()
    lut.Build()
    return lut


def mesh_actors(grid, lut, diag):
    """Surfaces of solids and shells as they are, lines (beams, trusses) as tubes."""
    actors = []
    status = grid.GetCellData().GetArray("gap_status")
    keep = vtk.vtkIdTypeArray()
    for i in range(grid.GetNumberOfCells()):
        if status is None or status.GetValue(i) < 0:
            keep.InsertNextValue(i)
    sel = vtk.vtkSelectionNode()
    sel.SetFieldType(vtk.vtkSelectionNode.CELL)
    sel.SetContentType(vtk.vtkSelectionNode.INDICES)
    sel.SetSelectionList(keep)
    selection = vtk.vtkSelection()
    selection.AddNode(sel)
    extract = vtk.vtkExtractSelection()
    extract.SetInputData(0, grid)
    extract.SetInputData(1, selection)
    surface = vtk.vtkDataSetSurfaceFilter()
    surface.SetInputConnection(extract.GetOutputPort())
    tubes = vtk.vtkTubeFilter()
    tubes.SetInputConnection(surface.GetOutputPort())
    tubes.SetRadius(0.006 * diag)
    tubes.SetNumberOfSides(16)
    for source in (surface, tubes):
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(source.GetOutputPort())
        m.SetLookupTable(lut)
        m.SetScalarModeToUsePointFieldData()
        m.SelectColorArray("U")
        m.SetUseLookupTableScalarRange(True)
        a = vtk.vtkActor()
        a.SetMapper(m)
        actors.append(a)
    return actors


def gap_actors(grid, diag):
    status = grid.GetCellData().GetArray("gap_status")
    if status is None:
        return [], set()
    actors, seen = [], set()
    # several gaps at one node (a rest and a guide): stacked upwards, one ball each
    stacked, place = {}, {}
    for i in range(grid.GetNumberOfCells()):
        if status.GetValue(i) >= 0:
            n = grid.GetCell(i).GetPointId(0)
            x = grid.GetPoint(n)
            k = stacked.get(n, 0)
            stacked[n] = k + 1
            place[i] = (x[0], x[1], x[2] + 2.4 * 0.014 * diag * k)
    for code, (name, colour) in STATUS.items():
        pts = vtk.vtkPoints()
        for i in range(grid.GetNumberOfCells()):
            if status.GetValue(i) == code:
                pts.InsertNextPoint(place[i])
        if pts.GetNumberOfPoints() == 0:
            continue
        seen.add(code)
        poly = vtk.vtkPolyData()
        poly.SetPoints(pts)
        ball = vtk.vtkSphereSource()
        ball.SetRadius(0.014 * diag)
        ball.SetThetaResolution(24)
        ball.SetPhiResolution(16)
        glyph = vtk.vtkGlyph3D()
        glyph.SetInputData(poly)
        glyph.SetSourceConnection(ball.GetOutputPort())
        glyph.SetScaleModeToDataScalingOff()
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(glyph.GetOutputPort())
        m.ScalarVisibilityOff()
        a = vtk.vtkActor()
        a.SetMapper(m)
        a.GetProperty().SetColor(colour)
        actors.append(a)
    return actors, seen


def text(renderer, s, x, y, size, colour=(0.1, 0.1, 0.1)):
    t = vtk.vtkTextActor()
    t.SetInput(s)
    t.GetTextProperty().SetFontSize(size)
    t.GetTextProperty().SetColor(colour)
    t.GetTextProperty().SetFontFamilyToArial()
    t.SetPosition(x, y)
    renderer.AddActor2D(t)


def render(frame, out, width, height, title):
    grid = read(frame)
    lut = magnitude_lut(grid)
    moved, scale, diag = warped(grid)
    ren = vtk.vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    for a in mesh_actors(moved, lut, diag):
        ren.AddActor(a)
    gaps, seen = gap_actors(moved, diag)
    for a in gaps:
        ren.AddActor(a)
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("|U|")
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.3g")
    bar.SetOrientationToHorizontal()
    bar.SetPosition(0.62, 0.04)
    bar.SetWidth(0.34)
    bar.SetHeight(0.13)
    for p in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        p.SetColor(0.1, 0.1, 0.1)
        p.SetFontFamilyToArial()
        p.ItalicOff()
        p.ShadowOff()
    ren.AddActor2D(bar)
    text(ren, f"{title}   (displacements x {scale:.3g})", 12, height - 34, 20)
    x = 12
    for code in sorted(seen):
        name, colour = STATUS[code]
        text(ren, "gap " + name, x, 14, 18, colour)
        x += 170
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(0, 0, 0)
    cam.SetPosition(0.35, -1.0, 0.55)
    cam.SetViewUp(0, 0, 1)
    ren.ResetCamera()
    # the camera fits the bounding sphere into the height: a long, slender model (a pipe run)
    # can be brought closer in a wide picture
    b = moved.GetBounds()
    ext = sorted((b[2 * k + 1] - b[2 * k] for k in range(3)), reverse=True)
    slender = ext[0] > 4.0 * max(ext[1], 1e-30)
    cam.Zoom(0.8 * width / height if slender else 1.3)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(width, height)
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(out)
    png.SetInputConnection(grab.GetOutputPort())
    png.Write()


def mean_difference(a, b):
    """Mean absolute difference per pixel and channel (0-255), or None when sizes differ."""
    imgs = []
    for path in (a, b):
        r = vtk.vtkPNGReader()
        r.SetFileName(path)
        r.Update()
        imgs.append(r.GetOutput())
    if imgs[0].GetDimensions() != imgs[1].GetDimensions():
        return None
    pa, pb = (i.GetPointData().GetScalars() for i in imgs)
    if pa.GetNumberOfComponents() != pb.GetNumberOfComponents():
        return None
    n = pa.GetNumberOfTuples() * pa.GetNumberOfComponents()
    total = 0
    for k in range(n):
        total += abs(pa.GetValue(k) - pb.GetValue(k))
    return total / n


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("results", help="job.pvd (its last frame) or a .vtu frame")
    p.add_argument("out", help="PNG to write")
    p.add_argument("--size", default="1400x480", help="WIDTHxHEIGHT in pixels")
    p.add_argument("--title", default=None)
    p.add_argument("--compare", metavar="REF.png", help="exit 1 when OUT.png differs from it")
    p.add_argument("--tolerance", type=float, default=2.0,
                   help="mean absolute difference (grey levels) --compare accepts")
    a = p.parse_args()
    width, height = (int(v) for v in a.size.split("x"))
    frame = last_frame(a.results)
    title = a.title or os.path.splitext(os.path.basename(a.results))[0]
    render(frame, a.out, width, height, title)
    if a.compare:
        d = mean_difference(a.out, a.compare)
        if d is None or d > a.tolerance:
            print(f"{a.out} differs from {a.compare}: mean difference "
                  f"{'(size)' if d is None else f'{d:.2f}'} > {a.tolerance}; if the change is "
                  f"intended, remake it: scripts/render_picture.py ... {a.compare}")
            return 1
        print(f"{a.out} matches {a.compare} (mean difference {d:.3f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
