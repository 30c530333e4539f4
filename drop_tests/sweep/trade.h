#pragma once
// The footpad shape trade study (`touchdown trade SWEEP.yaml --out DIR`): runs the sweep into
// DIR/results.sqlite (restartable like `sweep`), then, for each pad, final penetration, peak
// force and the paper's energy-conversion rate (impact energy / time to rest, dE/dt of Sutoh
// et al. 2017) against impact speed and soil.
//
// Rows are (pad, soil, impact speed); when other parameters vary too (mass, gravity, random
// samples) a row holds the means over its drops. Design limits (the sweep file's optional
// `trade:` block: allowable_final_penetration_mm, allowable_peak_force_N, max_pad_mass_kg) make
// a row feasible or not. Pareto front: within each (soil, speed) condition, the feasible pads
// that no other feasible pad beats on both final penetration and peak force (lower is better for
// both: a shallow, gentle landing); ties count as not beaten. Without limits every pad is
// feasible and three pads that trade depth for force are all on the front: the limits are what
// makes the front say something. Within each condition the feasible pad with the largest margin
// to the limits is marked best: the design a review would pick when the front holds several.
//
// Outputs in DIR: trade.csv (rows, with feasible and pareto columns), summary.json, plots/trade
// (three panels against speed), plots/pareto (peak force against penetration, a panel per soil:
// the allowable region, feasible pads filled, infeasible open, the fronts per condition), PNG and
// SVG, and their gnuplot script plots/trade.gp.
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::sweep {

struct TradeRow {
  std::string pad, soil;
  double impact_speed_m_s = 0.0;
  int drops = 0, failed = 0;
  double final_penetration_m = 0.0, peak_force_N = 0.0, mean_conversion_rate_W = 0.0;  // means over ok drops
  double pad_mass_kg = 0.0;                                                               // mean over ok drops
  bool feasible = true;  // within the limits (a row with no completed drop is not)
  // The smallest relative margin to the limits given, min(1 - value / limit): 0.2 means every
  // limited quantity is at least 20 % below its limit; negative: out; NaN without limits.
  double margin = NAN;
  bool pareto = false;
  bool best = false;  // the feasible row of its condition with the largest margin
};

// The design limits of a trade study, SI; infinite: none.
struct TradeLimits {
  double max_final_penetration_m = INFINITY;
  double max_peak_force_N = INFINITY;
  double max_pad_mass_kg = INFINITY;
  bool any() const;
};

// The sweep file's `trade:` block (absent: no limits); InputError naming file and field.
TradeLimits LoadTradeLimits(const std::string& sweep_file);
// The reference of the `trade:` block's keys (schema_doc.h; `touchdown schema`, docs/reference.md).
std::vector<io::BlockDoc> TradeSchema();

// A trade study compares footpads dropped on their own; a lander sweep (one pad design on four
// legs, whole-lander summaries) is refused with an InputError naming the sweep file and field.
void CheckTradePlan(const SweepPlan& plan);

// Rows sorted by soil, speed, pad, with the Pareto flags set. Lander records (drop_kind lander)
// are refused (InputError).
std::vector<TradeRow> TradeTable(const std::vector<DropRecord>& records, const TradeLimits& limits = {});
// Marks rows[i].pareto for the feasible rows of one condition (indices), by the rule above.
void MarkParetoFront(std::vector<TradeRow>& rows, const std::vector<size_t>& condition);
nlohmann::json TradeJson(const std::vector<TradeRow>& rows, const TradeLimits& limits = {});
// plots/trade and plots/pareto (PNG and SVG) and their script plots/trade.gp in `dir`
// (trade_plots.cpp): a series of more than 30 speeds (a random-speed sweep) drawn as its drops'
// dots and its speed bins' medians, the Pareto panels one per soil, fronts drawn up to 12 a soil.
void WriteTradePlots(const std::vector<TradeRow>& rows, const std::string& dir, const TradeLimits& limits = {});
// trade.csv, summary.json and plots/ in a sweep output, replacing an earlier trade analysis as one
// whole (io::ReplaceDerivedOutputs).
void WriteTradeOutputs(const std::vector<TradeRow>& rows, const std::string& out_dir, const TradeLimits& limits = {});

}  // namespace touchdown::sweep
