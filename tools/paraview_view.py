"""Opens a lander's or a free drop's ParaView series ready to watch, with ParaView itself (pvbatch or
pvpython), and saves a picture of one frame and/or a ParaView state file for the GUI.

    touchdown lander data/scenarios/lander_case_B.yaml --out case_B
    xvfb-run -a -s "-screen 0 1920x1200x24" pvbatch tools/paraview_view.py case_B/vtk/lander.pvd \\
        --png case_B.png --state case_B.pvsm
    paraview --state=case_B.pvsm                # the same view, animated, in the GUI

What it shows (docs/paraview.md lists the fields): the pads coloured by the soil's normal stress
on each element (normal_stress_Pa); the soil's force on the loaded elements (leading = 1, one in
--stride) as arrows (element_force_N, glyphs whose tips touch the element, so that they push on the
pad from the soil's side, the longest --arrow-length long); the legs coloured by their axial load (leg_force_N) and the body in grey; the
soil's surface pressed in by the pads (the `crater` part, coloured by crater_depth_m) and the soil's
square with its patches, half transparent; the camera on the pads, from below the surface (--view
below, where the pads' bottoms carry the stress) or from above (--view above, where the craters and
furrows show once a pad has moved on). The frame shown: --time T, else that of the largest total
pad load while no pad is held (trace.csv beside a lander's vtk/), else that of the largest normal
stress.

The state file names the .pvd by its absolute path: write it for your own series (it is not portable
between machines). Needs ParaView 5.11 (Debian `paraview` and `python3-paraview`; `tools/install_deps.sh
docs`), not part of the build or the tests. Debian's pvbatch needs an X display, hence xvfb-run.
"""
import argparse
import csv
import math
import os

from paraview.simple import (Calculator, CellCenters, ColorBy, ExtractBlock, GetActiveViewOrCreate,
                             GetAnimationScene, GetColorTransferFunction, GetScalarBar, Glyph, PVDReader, Render,
                             SaveScreenshot, SaveState, Show, Threshold, UpdatePipeline)

BELOW = (0.4, -0.5, -0.75)  # from below the surface, in front of pad 1 (front-left, x forward)
ABOVE = (-0.55, -0.75, 0.75)  # from above, behind and to the right


def peak_load_time(pvd):
    """A lander's trace time with the largest total pad force while no pad is held (a held pad's
    load is a constraint force, not RFT stress: docs/paraview.md), from trace.csv beside vtk/; None
    without a trace."""
    trace = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(pvd))), "trace.csv")
    if not os.path.exists(trace):
        return None
    best_t, best = None, -1.0
    with open(trace, newline="") as f:
        for row in csv.DictReader(f):
            if "held1" not in row or any(float(row[f"held{i}"]) for i in range(1, 5)):
                continue
            total = sum(float(row[f"force{i}_N"]) for i in range(1, 5))
            if total > best:
                best_t, best = float(row["t_s"]), total
    return best_t


def peak_stress_time(pads, times):
    """The frame with the largest normal stress on any element (reads every frame of the pads)."""
    best_t, best = times[0], -math.inf
    for t in times:
        UpdatePipeline(time=t, proxy=pads)
        top = pads.CellData["normal_stress_Pa"].GetRange(0)[1]
        if top > best:
            best_t, best = t, top
    return best_t


def block(reader, name):
    return ExtractBlock(Input=reader, Selectors=[f"/Root/{name}"])


def colour(display, view, array, association, preset, title, bar=True):
    ColorBy(display, (association, array))
    lut = GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    display.RescaleTransferFunctionToDataRange(False, True)
    display.SetScalarBarVisibility(view, bar)
    if bar:
        scalar_bar = GetScalarBar(lut, view)
        scalar_bar.Title = title
        scalar_bar.ComponentTitle = ""
        scalar_bar.TitleColor = scalar_bar.LabelColor = [0.1, 0.1, 0.1]
    return lut


def force_arrows(pads, view, t, arrow_length_m, stride):
    """element_force_N as arrows ending on the centres of the elements that lead the motion (the
    soil pushes from outside): cell centres moved back along the force by the arrow's length, then
    glyphs along the force, one element in `stride`. Returns the scale [m/N]."""
    UpdatePipeline(time=t, proxy=pads)
    largest = pads.CellData["element_force_N"].GetRange(-1)[1]
    scale = arrow_length_m / largest if largest > 0.0 else 0.0
    loaded = Threshold(Input=pads, Scalars=["CELLS", "leading"], LowerThreshold=0.5, UpperThreshold=1.0)
    centres = CellCenters(Input=loaded)
    centres.VertexCells = 1
    tails = Calculator(Input=centres)
    tails.CoordinateResults = 1
    tails.Function = f"coords - {scale!r} * element_force_N"
    tails.ResultArrayName = "tail"
    arrows = Glyph(Input=tails, GlyphType="Arrow")
    arrows.OrientationArray = ["POINTS", "element_force_N"]
    arrows.ScaleArray = ["POINTS", "element_force_N"]
    arrows.ScaleFactor = scale
    arrows.GlyphMode = "Every Nth Point"
    arrows.Stride = stride
    arrows.GlyphType.TipResolution = 12
    arrows.GlyphType.ShaftResolution = 12
    display = Show(arrows, view)
    display.ColorArrayName = [None, ""]
    display.AmbientColor = display.DiffuseColor = [0.0, 0.6, 0.3]
    return scale


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd", help="a lander's vtk/lander.pvd or a free drop's drop.pvd")
    parser.add_argument("--png", help="write a picture of the frame")
    parser.add_argument("--state", help="write a ParaView state (.pvsm) to open with paraview --state=FILE")
    parser.add_argument("--time", type=float, help="the time [s] to show (default: the peak load)")
    parser.add_argument("--view", choices=("below", "above"), default="below", help="where the camera is")
    parser.add_argument("--arrow-length", type=float, default=0.015,
                        help="length [m] of the arrow of the largest element force (default 0.015)")
    parser.add_argument("--stride", type=int, default=6, help="an arrow on one loaded element in N (default 6)")
    parser.add_argument("--zoom", type=float, default=1.1, help="closer than the pads' framing by this (default 1.1)")
    parser.add_argument("--size", default="1600x1000", help="picture size in pixels (default 1600x1000)")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))

    reader = PVDReader(FileName=os.path.abspath(args.pvd))
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    with open(args.pvd, encoding="utf-8") as f:
        collection = f.read()
    parts = [b for b in ("pads", "pad", "body", "legs", "crater", "soil") if f'name="{b}"' in collection]
    pad_part = "pads" if "pads" in parts else "pad"
    pads = block(reader, pad_part)
    wanted = args.time if args.time is not None else peak_load_time(args.pvd)
    if wanted is None:
        wanted = peak_stress_time(pads, times)
    t = min(times, key=lambda x: abs(x - wanted))
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = t

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = t
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1

    pads_display = Show(pads, view)
    colour(pads_display, view, "normal_stress_Pa", "CELLS", "Inferno (matplotlib)",
           "soil normal stress on the pads [Pa]")
    scale = force_arrows(pads, view, t, args.arrow_length, args.stride)

    for name in ("body", "legs"):
        if name not in parts:
            continue
        display = Show(block(reader, name), view)
        display.LineWidth = 5.0
        if name == "legs":
            colour(display, view, "leg_force_N", "CELLS", "Viridis (matplotlib)", "leg load [N]")
        else:
            display.ColorArrayName = [None, ""]
            display.AmbientColor = display.DiffuseColor = [0.55, 0.55, 0.6]
    if "crater" in parts:
        crater_display = Show(block(reader, "crater"), view)
        colour(crater_display, view, "crater_depth_m", "POINTS", "Blues", "crater depth [m]", bar=False)
        crater_display.Opacity = 0.6
    if "soil" in parts:
        soil_display = Show(block(reader, "soil"), view)
        soil_lut = colour(soil_display, view, "soil", "CELLS", "Greens", "", bar=False)
        soil_lut.RescaleTransferFunction(-1.0, 3.0)
        soil_display.Opacity = 0.2

    # The camera on the pads: looking at their bounding box from the chosen side, framed on it, then
    # moved in (--zoom).
    UpdatePipeline(time=t, proxy=pads)
    x0, x1, y0, y1, z0, z1 = pads.GetDataInformation().GetBounds()
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    direction = BELOW if args.view == "below" else ABOVE
    Render(view)  # the first render places the camera on everything; ours replaces it
    view.CameraFocalPoint = centre
    view.CameraPosition = [c + d for c, d in zip(centre, direction)]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    view.ResetCamera(x0, x1, y0, y1, z0, z1)
    view.GetActiveCamera().Dolly(args.zoom)
    Render(view)
    if args.png:
        SaveScreenshot(args.png, view, ImageResolution=[width, height])
        print(f"wrote {args.png} (t = {t:.4f} s, arrows {scale:.3g} m/N)")
    if args.state:
        SaveState(args.state)
        print(f"wrote {args.state}")


if __name__ == "__main__":
    main()
