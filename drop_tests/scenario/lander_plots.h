#pragma once
// PNG plots of a lander drop, drawn by gnuplot (RenderPlots, plot_runner.h):
//   plots/penetration.png  depth of each pad's lowest point against time
//   plots/attitude.png     roll, pitch and tilt of the body against time
// from plots/data/trace.csv, the plotted columns of trace.csv decimated to a few thousand rows
// (plot_decimation.h). The gnuplot script stays in plots/; a plotting failure throws.
#include <string>

namespace touchdown::scenario {

struct LanderRun;

void WriteLanderPlots(const LanderRun& run, const std::string& out_dir);

}  // namespace touchdown::scenario
