"""A picture of a lander landing from its ParaView series, made with ParaView itself (headless).

    touchdown lander data/scenarios/lander_case_B.yaml --out case_B
    pvbatch tools/paraview_snapshot.py case_B/vtk/lander.pvd docs/figures/paraview_lander_case_B.png

Loads the .pvd time series with ParaView's PVD reader, goes to the frame where the pads carry the
most load (the largest sum of force<i>_N in the run's trace.csv, beside vtk/; or --time T), and
draws the pads coloured by the soil's normal stress on each element, the legs and body in grey and
the soil's surface coloured by its patches, seen from below and mostly transparent, so that the
pads' bottoms, which carry the stress, show. Saves a
PNG (1600 x 1000). Needs ParaView's pvbatch (Debian `paraview`); not part of the build, the tests
or tools/install_deps.sh (docs/paraview.md).
"""
import argparse
import csv
import os

from paraview.simple import (ColorBy, ExtractBlock, GetActiveViewOrCreate, GetAnimationScene,
                             GetColorTransferFunction, GetScalarBar, PVDReader, Render, SaveScreenshot, Show,
                             UpdatePipeline)


def peak_load_time(pvd):
    """The trace time with the largest total pad force while no pad is held (a held pad's load is a
    constraint force, not RFT stress: docs/paraview.md), from trace.csv beside vtk/."""
    trace = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(pvd))), "trace.csv")
    best_t, best = 0.0, -1.0
    with open(trace, newline="") as f:
        for row in csv.DictReader(f):
            if any(float(row[f"held{i}"]) for i in range(1, 5)):
                continue
            total = sum(float(row[f"force{i}_N"]) for i in range(1, 5))
            if total > best:
                best_t, best = float(row["t_s"]), total
    return best_t


def show_block(reader, name, view):
    block = ExtractBlock(Input=reader, Selectors=[f"/Root/{name}"])
    return block, Show(block, view)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pvd", help="a lander's vtk/lander.pvd")
    parser.add_argument("png", help="the picture to write")
    parser.add_argument("--time", type=float, help="the time [s] to show (default: the peak load)")
    args = parser.parse_args()

    reader = PVDReader(FileName=args.pvd)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    wanted = args.time if args.time is not None else peak_load_time(args.pvd)
    t = min(times, key=lambda x: abs(x - wanted))
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = t

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1600, 1000]
    view.ViewTime = t
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1

    pads, pads_display = show_block(reader, "pads", view)
    UpdatePipeline(time=t, proxy=pads)
    ColorBy(pads_display, ("CELLS", "normal_stress_Pa"))
    stress = GetColorTransferFunction("normal_stress_Pa")
    stress.ApplyPreset("Inferno (matplotlib)", True)
    pads_display.RescaleTransferFunctionToDataRange(False, True)
    bar = GetScalarBar(stress, view)
    bar.Title = "soil normal stress on the pads [Pa]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.Visibility = 1

    for name in ("body", "legs"):
        _, display = show_block(reader, name, view)
        display.ColorArrayName = [None, ""]
        display.AmbientColor = display.DiffuseColor = [0.55, 0.55, 0.6]
        display.LineWidth = 4.0
    _, soil_display = show_block(reader, "soil", view)
    ColorBy(soil_display, ("CELLS", "soil"))
    soil_lut = GetColorTransferFunction("soil")
    soil_lut.ApplyPreset("Greens", True)
    soil_lut.RescaleTransferFunction(-1.0, 3.0)
    soil_display.Opacity = 0.3
    soil_display.SetScalarBarVisibility(view, False)

    Render(view)  # the first render places the camera on everything; ours replaces it below
    # From below the surface, where the pads' bottoms carry the stress (pad 1 front-left, x forward).
    view.CameraPosition = [0.55, -0.68, -0.62]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    Render(view)
    SaveScreenshot(args.png, view, ImageResolution=[1600, 1000])
    print(f"wrote {args.png} (t = {t:.4f} s)")


if __name__ == "__main__":
    main()
