#pragma once
// The footpad shape trade study (`touchdown trade SWEEP.yaml --out DIR`): runs the sweep into
// DIR/results.sqlite (restartable like `sweep`), then, for each pad, final penetration, peak
// force and the paper's energy-conversion rate (impact energy / time to rest, dE/dt of Sutoh
// et al. 2017) against impact speed and soil.
//
// Rows are (pad, soil, impact speed); when other parameters vary too (mass, gravity, random
// samples) a row holds the means over its drops. Pareto front: within each (soil, speed)
// condition, the pads that no other pad beats on both final penetration and peak force (lower
// is better for both: a shallow, gentle landing); ties count as not beaten.
//
// Outputs in DIR: trade.csv (rows, with a pareto column), summary.json, plots/trade.png
// (three panels against speed), plots/pareto.png (peak force against penetration, the fronts
// drawn per condition) and their gnuplot script plots/trade.gp.
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep_spec.h"

namespace touchdown::sweep {

struct TradeRow {
  std::string pad, soil;
  double impact_speed_m_s = 0.0;
  int drops = 0, failed = 0;
  double final_penetration_m = 0.0, peak_force_N = 0.0, mean_conversion_rate_W = 0.0;  // means over ok drops
  bool pareto = false;
};

// A trade study compares footpads dropped on their own; a lander sweep (one pad design on four
// legs, whole-lander summaries) is refused with an InputError naming the sweep file and field.
void CheckTradePlan(const SweepPlan& plan);

// Rows sorted by soil, speed, pad, with the Pareto flags set. Lander records (drop_kind lander)
// are refused (InputError).
std::vector<TradeRow> TradeTable(const std::vector<DropRecord>& records);
// Marks rows[i].pareto for rows of one condition (indices), by the rule above.
void MarkParetoFront(std::vector<TradeRow>& rows, const std::vector<size_t>& condition);
nlohmann::json TradeJson(const std::vector<TradeRow>& rows);
void WriteTradeOutputs(const std::vector<TradeRow>& rows, const std::string& out_dir);

}  // namespace touchdown::sweep
