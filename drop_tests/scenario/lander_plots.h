#pragma once
// PNG plots of a lander drop, drawn by gnuplot (RenderPlots, plot_runner.h):
//   plots/penetration.png  depth of each pad's lowest point against time
//   plots/attitude.png     roll, pitch and tilt of the body against time
// from plots/data/trace.csv, the plotted columns of trace.csv decimated to a few thousand rows
// (plot_decimation.h). The gnuplot script stays in plots/; a plotting failure throws.
#include <array>
#include <string>
#include <vector>

#include "lander/multibody/lander_simulation.h"

namespace touchdown::scenario {

// `name`: the scenario's, in the titles; `soil_under_pad`: in the legend of each pad's depth.
void WriteLanderPlots(const std::string& name, const std::vector<lander::LanderSample>& trace,
                      const std::array<std::string, lander::kNumLegs>& soil_under_pad, const std::string& out_dir);

}  // namespace touchdown::scenario
