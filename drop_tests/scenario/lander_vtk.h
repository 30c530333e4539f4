#pragma once
// `touchdown lander SCENARIO --out DIR` also writes DIR/vtk/: the landing as a ParaView time series
// (docs/paraview.md). vtk/lander.pvd lists, at each frame, the four pads with their per-element soil
// stresses and forces (pads_NNNNNN.vtp), the body as the polygon of its hips (body_NNNNNN.vtp), the
// legs as lines from hip to ball joint with their loads (legs_NNNNNN.vtp), the soil's surface under
// each pad pressed in by it so far (crater_NNNNNN.vtp, io::CraterSurface; a frame that did not change
// it lists the previous file) and the soil's surface with its patches (soil.vtp).
#include <string>

#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

// Frames: every trace sample while a pad moves in the soil (the stroke: 18 ms of the paper's case A,
// where all that matters happens), else samples at least kLanderVtkFrameInterval_s apart (the fall),
// and after the rest event only the last (nothing moves). A frame of the paper's lander is about
// 1.6 MB (four pads of ~2,000 triangles in ASCII, with their stresses and force vectors): every
// 1 kHz sample of case A's simulated second would write some 1.6 GB; these 36 frames write 58 MB.
inline constexpr double kLanderVtkFrameInterval_s = 0.01;

// Writes the series into `directory` (inside the staging directory of WriteLanderOutputs; created).
void WriteLanderVtk(const LanderRun& run, const std::string& directory);

}  // namespace touchdown::scenario
