#pragma once
// Figures of a lander drop (PNG and SVG, io::Figure's style), drawn by gnuplot (RenderPlots):
//   plots/penetration  depth of each pad's lowest point against time
//   plots/attitude     roll, pitch and tilt of the body, with the paper's band when the scenario
//                      has a paper check
//   plots/loads        soil force on each pad, axial force in each leg, the body's vertical
//                      acceleration
// over the contact window (first touchdown to rest, tip-over or the end, with margins), from
// plots/data/trace.csv: the plotted columns of trace.csv decimated to a few thousand rows
// (plot_decimation.h). The gnuplot script stays in plots/; a plotting failure throws.
#include <string>

#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

void WriteLanderPlots(const LanderRun& run, const std::string& out_dir);

}  // namespace touchdown::scenario
