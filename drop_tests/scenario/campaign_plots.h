#pragma once
// PNG plots of a campaign like the paper's figures, drawn by gnuplot from the traces:
//   fig3_time_histories.png  force and penetration against time at the reference speed (Fig. 3)
//   fig4_peaks.png           peak force and final penetration per case and speed (Fig. 4)
//   fig6_force_penetration.png  force against penetration: pads on one soil, one pad on each soil (Fig. 6)
// The gnuplot script stays in plots/ so a user can restyle and re-render it. Rendered by
// RenderPlots (plot_runner.h): without gnuplot, or when a PNG cannot be written whole, it throws.
#include <string>

namespace touchdown::scenario {

struct CampaignResult;

void WriteCampaignPlots(const CampaignResult& result, const std::string& out_dir);

}  // namespace touchdown::scenario
