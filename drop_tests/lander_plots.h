#pragma once
// PNG plots of a lander drop, drawn by gnuplot from trace.csv (as campaign_plots does):
//   plots/penetration.png  depth of each pad's lowest point against time
//   plots/attitude.png     roll, pitch and tilt of the body against time
// The gnuplot script stays in plots/; without gnuplot on the PATH it is still written and a
// warning goes to stderr.
#include <string>

namespace touchdown::drop {

struct LanderRun;

void WriteLanderPlots(const LanderRun& run, const std::string& out_dir);

}  // namespace touchdown::drop
