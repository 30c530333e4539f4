#pragma once
// Figures of a campaign like the paper's (PNG and SVG, io::Figure's style: a pad keeps its colour
// and a soil its dash in every figure), drawn by gnuplot:
//   fig3_time_histories      force and penetration against time at the reference speed (Fig. 3),
//                            from touchdown to a little after the last stop
//   fig4_peaks               peak force and final penetration per case and speed (Fig. 4): bars in
//                            the case's pad colour, darker for faster drops
//   fig6_force_penetration   force against penetration over the stroke: pads on one soil, one pad
//                            on each soil (Fig. 6)
//   fig7_paper_checks        each paper check's ratio as simulated beside the paper's experiment
//                            and RFT values (black)
// The strokes of fig3 and fig6 are drawn from the reference-speed drops run again sampled at
// 10 kHz (the traces keep the rig's 1 kHz, a dozen points per stroke): the same drops through
// the same path, only the output grid is finer. The gnuplot script stays in plots/ so a user can
// restyle and re-render it; RenderPlots (plot_runner.h) throws when a figure cannot be written.
#include <string>

#include "drop_tests/scenario/campaign.h"

namespace touchdown::scenario {

void WriteCampaignPlots(const CampaignResult& result, const std::string& out_dir);

}  // namespace touchdown::scenario
