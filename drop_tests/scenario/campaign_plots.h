#pragma once
// PNG plots of a campaign like the paper's figures, drawn by gnuplot from the traces:
//   fig3_time_histories.png  force and penetration against time at the reference speed (Fig. 3)
//   fig4_peaks.png           peak force and final penetration per case and speed (Fig. 4)
//   fig6_force_penetration.png  force against penetration: pads on one soil, one pad on each soil (Fig. 6)
// The gnuplot script stays in plots/ so a user can restyle and re-render it. Rendered by
// RenderPlots (plot_runner.h): without gnuplot, or when a PNG cannot be written whole, it throws.
#include <string>
#include <vector>

#include "drop_tests/drop/pad_drop.h"

namespace touchdown::scenario {

// `drops[i]`'s trace is traces/<drop_ids[i]>.csv in `out_dir`; the time histories and the force
// against penetration show the drops at `reference_speed_m_s`.
void WriteCampaignPlots(const std::vector<drop::PadDrop>& drops, const std::vector<std::string>& drop_ids,
                        double reference_speed_m_s, const std::string& out_dir);

}  // namespace touchdown::scenario
