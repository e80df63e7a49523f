"""ParaView's own readers on what `miniaster convert` writes (tests/cli/user_walk.cpp), run by pvpython:

  pvpython paraview_check.py FILE.vtu|FILE.pvd [--screenshot OUT.png --colour ARRAY[:COMPONENT] --scale S]

Prints, one per line: the time steps (`times 0 1`), every point and cell array of the last step
(`point RES_XFEMDEPL 3 DX,DY,DZ min,max per component`), the vectors ParaView's Warp By Vector takes
by default (`warp RES_XFEMDEPL`) and the largest difference between the warped points and
points + vectors (`warp_error 4.4e-16`). With --screenshot: the result warped by its vectors times S,
coloured by ARRAY (or one component), rendered offscreen (Debian's ParaView renders through X: run
under `xvfb-run -a`).
"""
import argparse

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, OpenDataFile, Render, ResetCamera,
                             SaveScreenshot, Show, UpdatePipeline, WarpByVector)
from vtkmodules.util.numpy_support import vtk_to_numpy


def arrays(data, kind):
    out = []
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        if a is None:
            continue
        n = a.GetNumberOfComponents()
        names = ",".join(a.GetComponentName(c) or str(c) for c in range(n)) if n > 1 else "-"
        ranges = " ".join("%.17g,%.17g" % a.GetRange(c) for c in range(n))
        out.append(f"{kind} {a.GetName()} {n} {names} {ranges}")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--screenshot", default=None)
    ap.add_argument("--colour", default=None)
    ap.add_argument("--scale", type=float, default=1.0)
    args = ap.parse_args()
    reader = OpenDataFile(args.file)
    times = list(getattr(reader, "TimestepValues", []) or [])
    print("reader", reader.GetXMLName())
    print("times", " ".join("%g" % t for t in times) if times else "none")
    last = times[-1] if times else None
    UpdatePipeline(time=last, proxy=reader)
    grid = servermanager.Fetch(reader)
    print("points", grid.GetNumberOfPoints(), "cells", grid.GetNumberOfCells())
    for line in arrays(grid.GetPointData(), "point") + arrays(grid.GetCellData(), "cell"):
        print(line)
    warp = WarpByVector(Input=reader)  # as a user applies it: its default vectors
    print("warp", warp.Vectors[1])
    UpdatePipeline(time=last, proxy=warp)
    warped = servermanager.Fetch(warp)
    moved = vtk_to_numpy(warped.GetPoints().GetData())
    start = vtk_to_numpy(grid.GetPoints().GetData())
    vectors = vtk_to_numpy(grid.GetPointData().GetArray(warp.Vectors[1]))
    print("warp_error %.3g" % abs(moved - start - vectors).max())
    print("warp_largest_move %.17g" % abs(moved - start).max())
    if args.screenshot:
        if times:
            GetAnimationScene().AnimationTime = last
        view = GetActiveViewOrCreate("RenderView")
        warp.ScaleFactor = args.scale
        display = Show(warp, view)
        name, _, component = args.colour.partition(":")
        where = "POINTS" if grid.GetPointData().GetArray(name) else "CELLS"
        ColorBy(display, (where, name, component) if component else (where, name))
        display.SetScalarBarVisibility(view, True)
        display.RescaleTransferFunctionToDataRange(True, False)
        display.SetRepresentationType("Surface With Edges")
        view.CameraPosition = [0.0, 0.0, 1.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        ResetCamera(view)
        Render(view)
        SaveScreenshot(args.screenshot, view, ImageResolution=[800, 600])
        print("screenshot", args.screenshot)


if __name__ == "__main__":
    main()
