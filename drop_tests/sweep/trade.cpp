#include "drop_tests/sweep/trade.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "drop_tests/formats/json_number.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::sweep {

namespace fs = std::filesystem;

void CheckTradePlan(const SweepPlan& plan) {
  if (plan.lander)
    throw MakeInputError(plan.source, "lander",
                         "trade compares footpads dropped on their own (pad: [...]); a lander sweep runs one pad "
                         "design on four legs. Run it with `touchdown sweep` and read its summaries with "
                         "`touchdown export`");
}

bool TradeLimits::any() const {
  return std::isfinite(max_final_penetration_m) || std::isfinite(max_peak_force_N) || std::isfinite(max_pad_mass_kg);
}

namespace {
// The sweep file's `trade:` block: each limit optional (absent: none).
const io::FieldTable<TradeLimits>& TradeLimitFields() {
  using L = TradeLimits;
  static const io::FieldTable<L> fields{
      {"allowable_final_penetration_mm", &L::max_final_penetration_m, units::kMm, io::Sign::kPositive, true, false,
       nullptr, "none"},
      {"allowable_peak_force_N", &L::max_peak_force_N, 1.0, io::Sign::kPositive, true, false, nullptr, "none"},
      {"max_pad_mass_kg", &L::max_pad_mass_kg, 1.0, io::Sign::kPositive, true, false, nullptr, "none"},
  };
  return fields;
}
}  // namespace

TradeLimits LoadTradeLimits(const std::string& sweep_file) {
  const io::YamlFields f = io::YamlFields::LoadFile(sweep_file);
  TradeLimits limits;
  if (!f.Has("trade")) return limits;
  const io::YamlFields t = f.Child("trade");
  t.RequireOnly(io::FieldKeys(TradeLimitFields()));
  io::ReadFields(t, TradeLimitFields(), limits);
  return limits;
}

std::vector<io::BlockDoc> TradeSchema() {
  return {io::MakeBlock("sweep.trade", "drop_tests/sweep/trade.cpp", io::DocsOf(TradeLimitFields()))};
}

std::vector<TradeRow> TradeTable(const std::vector<DropRecord>& records, const TradeLimits& limits) {
  for (const DropRecord& r : records)
    if (r.kind == DropKind::kLander)
      throw MakeInputError("drop " + r.drop_id, "drop_kind",
                           "a lander drop; trade tabulates single-pad drops only");
  std::map<std::tuple<std::string, double, std::string>, TradeRow> rows;  // (soil, speed, pad)
  for (const DropRecord& r : records) {
    TradeRow& row = rows[{r.soil, r.impact_speed_m_s, r.pad}];
    row.pad = r.pad;
    row.soil = r.soil;
    row.impact_speed_m_s = r.impact_speed_m_s;
    ++row.drops;
    if (!r.ok) {
      ++row.failed;
      continue;
    }
    row.final_penetration_m += r.final_penetration_m;
    row.peak_force_N += r.peak_force_N;
    row.mean_conversion_rate_W += r.mean_conversion_rate_W;
    row.pad_mass_kg += r.pad_mass_kg;
  }
  std::vector<TradeRow> out;
  for (auto& [key, row] : rows) {
    const int ok = row.drops - row.failed;
    for (double* v : {&row.final_penetration_m, &row.peak_force_N, &row.mean_conversion_rate_W, &row.pad_mass_kg})
      *v = ok > 0 ? *v / ok : std::nan("");
    row.feasible = ok > 0 && row.final_penetration_m <= limits.max_final_penetration_m &&
                   row.peak_force_N <= limits.max_peak_force_N && row.pad_mass_kg <= limits.max_pad_mass_kg;
    if (limits.any() && ok > 0) {
      row.margin = INFINITY;
      for (const auto& [value, limit] : {std::pair{row.final_penetration_m, limits.max_final_penetration_m},
                                         std::pair{row.peak_force_N, limits.max_peak_force_N},
                                         std::pair{row.pad_mass_kg, limits.max_pad_mass_kg}})
        if (std::isfinite(limit)) row.margin = std::min(row.margin, 1.0 - value / limit);
    }
    out.push_back(row);
  }
  std::map<std::pair<std::string, double>, std::vector<size_t>> conditions;
  for (size_t i = 0; i < out.size(); ++i) conditions[{out[i].soil, out[i].impact_speed_m_s}].push_back(i);
  for (const auto& [key, members] : conditions) {
    MarkParetoFront(out, members);
    int best = -1;
    for (size_t i : members)
      if (out[i].feasible && std::isfinite(out[i].margin) && (best < 0 || out[i].margin > out[best].margin))
        best = static_cast<int>(i);
    if (best >= 0) out[best].best = true;
  }
  return out;
}

void MarkParetoFront(std::vector<TradeRow>& rows, const std::vector<size_t>& condition) {
  for (size_t i : condition) {
    const TradeRow& a = rows[i];
    if (a.drops == a.failed || !a.feasible) continue;  // nothing to rank, or out of the limits
    bool beaten = false;
    for (size_t j : condition) {
      const TradeRow& b = rows[j];
      if (j == i || b.drops == b.failed || !b.feasible) continue;
      beaten |= b.final_penetration_m <= a.final_penetration_m && b.peak_force_N <= a.peak_force_N &&
                (b.final_penetration_m < a.final_penetration_m || b.peak_force_N < a.peak_force_N);
    }
    rows[i].pareto = !beaten;
  }
}

nlohmann::json TradeJson(const std::vector<TradeRow>& rows, const TradeLimits& limits) {
  nlohmann::json list = nlohmann::json::array();
  for (const TradeRow& r : rows)
    list.push_back({{"pad", r.pad},
                    {"soil", r.soil},
                    {"impact_speed_m_s", r.impact_speed_m_s},
                    {"drops", r.drops},
                    {"failed", r.failed},
                    {"final_penetration_m", io::FiniteOrNull(r.final_penetration_m)},
                    {"peak_force_N", io::FiniteOrNull(r.peak_force_N)},
                    {"mean_conversion_rate_W", io::FiniteOrNull(r.mean_conversion_rate_W)},
                    {"pad_mass_kg", io::FiniteOrNull(r.pad_mass_kg)},
                    {"feasible", r.feasible},
                    {"margin", io::FiniteOrNull(r.margin)},
                    {"pareto", r.pareto},
                    {"best", r.best}});
  int feasible = 0, front = 0;
  for (const TradeRow& r : rows) feasible += r.feasible, front += r.pareto;
  return {{"rows", list},
          {"limits", {{"allowable_final_penetration_m", io::FiniteOrNull(limits.max_final_penetration_m)},
                      {"allowable_peak_force_N", io::FiniteOrNull(limits.max_peak_force_N)},
                      {"max_pad_mass_kg", io::FiniteOrNull(limits.max_pad_mass_kg)}}},
          {"rows_feasible", feasible},
          {"rows_on_front", front},
          {"pareto_rule", "within each (soil, impact speed): the feasible pads (within the limits; null: none) no "
                          "other feasible pad beats on both final penetration and peak force (lower is better)"},
          {"best_rule", "within each (soil, impact speed): the feasible pad with the largest margin, "
                        "min over the limits given of 1 - value / limit"},
          {"conversion_rate", "impact energy / time to rest (Sutoh et al. 2017, dE/dt)"}};
}

namespace {
void WriteTradeFiles(const std::vector<TradeRow>& rows, const fs::path& dir, const TradeLimits& limits) {
  io::WriteFileAtomically((dir / "trade.csv").string(), [&](std::ostream& out) {
    out << "pad,soil,impact_speed_m_s,drops,failed,final_penetration_m,peak_force_N,mean_conversion_rate_W,pad_mass_kg,"
           "feasible,margin,pareto,best\n";
    for (const TradeRow& r : rows)
      out << r.pad << ',' << r.soil << ',' << io::FormatNumber(r.impact_speed_m_s) << ',' << r.drops << ',' << r.failed
          << ',' << io::FormatNumber(r.final_penetration_m) << ',' << io::FormatNumber(r.peak_force_N) << ','
          << io::FormatNumber(r.mean_conversion_rate_W) << ',' << io::FormatNumber(r.pad_mass_kg) << ','
          << (r.feasible ? 1 : 0) << ',' << io::FormatNumber(r.margin) << ',' << (r.pareto ? 1 : 0) << ','
          << (r.best ? 1 : 0) << '\n';
  });
  io::WriteFileAtomically((dir / "summary.json").string(), [&](std::ostream& out) { out << TradeJson(rows, limits).dump(2) << '\n'; });
  WriteTradePlots(rows, dir.string(), limits);
}
}  // namespace

void WriteTradeOutputs(const std::vector<TradeRow>& rows, const std::string& out_dir, const TradeLimits& limits) {
  io::ReplaceDerivedOutputs(out_dir, io::OutputKind::kSweep, "summary.json",
                            [&](const std::string& staging) { WriteTradeFiles(rows, staging, limits); });
}

}  // namespace touchdown::sweep
