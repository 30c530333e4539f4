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
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"

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

TradeLimits LoadTradeLimits(const std::string& sweep_file) {
  const io::YamlFields f = io::YamlFields::LoadFile(sweep_file);
  TradeLimits limits;
  if (!f.Has("trade")) return limits;
  const io::YamlFields t = f.Child("trade");
  t.RequireOnly({"allowable_final_penetration_mm", "allowable_peak_force_N", "max_pad_mass_kg"});
  if (t.Has("allowable_final_penetration_mm")) limits.max_final_penetration_m = t.Positive("allowable_final_penetration_mm") * 1e-3;
  if (t.Has("allowable_peak_force_N")) limits.max_peak_force_N = t.Positive("allowable_peak_force_N");
  if (t.Has("max_pad_mass_kg")) limits.max_pad_mass_kg = t.Positive("max_pad_mass_kg");
  return limits;
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
// One data file per (pad, soil) series against speed: speed, penetration, force, conversion rate,
// feasible (1/0).
std::vector<std::pair<std::string, std::string>> WriteSeries(const std::vector<TradeRow>& rows, const fs::path& dir) {
  std::map<std::pair<std::string, std::string>, std::vector<const TradeRow*>> series;
  for (const TradeRow& r : rows)
    if (r.drops != r.failed) series[{r.pad, r.soil}].push_back(&r);
  std::vector<std::pair<std::string, std::string>> files;  // file, "pad|soil"
  for (auto& [key, list] : series) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->impact_speed_m_s < b->impact_speed_m_s; });
    const std::string file = "plots/data/" + key.first + "__" + key.second + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&, &list = list](std::ostream& out) {
      for (const TradeRow* r : list)
        out << io::FormatNumber(r->impact_speed_m_s) << ',' << io::FormatNumber(r->final_penetration_m) << ','
            << io::FormatNumber(r->peak_force_N) << ',' << io::FormatNumber(r->mean_conversion_rate_W) << ','
            << (r->feasible ? 1 : 0) << '\n';
    });
    files.push_back({file, key.first + "|" + key.second});
  }
  return files;
}

struct Front {
  std::string file;   // penetration, force, pad, sorted along the front
  std::string label;  // its condition: "1 m/s, FJS-1 LP"
  double end_mm = 0.0, end_N = 0.0;  // its last point, where the label goes
};

// One data file per condition's front.
std::vector<Front> WriteFronts(const std::vector<TradeRow>& rows, const fs::path& dir) {
  std::map<std::pair<std::string, double>, std::vector<const TradeRow*>> fronts;
  for (const TradeRow& r : rows)
    if (r.pareto) fronts[{r.soil, r.impact_speed_m_s}].push_back(&r);
  std::vector<Front> files;
  for (auto& [key, list] : fronts) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->final_penetration_m < b->final_penetration_m; });
    const std::string file = "plots/data/front_" + std::to_string(files.size()) + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&, &list = list](std::ostream& out) {
      for (const TradeRow* r : list)
        out << io::FormatNumber(r->final_penetration_m) << ',' << io::FormatNumber(r->peak_force_N) << ',' << r->pad << '\n';
    });
    files.push_back({file, io::FormatNumber(key.second) + " m/s, " + io::SoilDisplayName(key.first),
                     list.back()->final_penetration_m * 1e3, list.back()->peak_force_N});
  }
  return files;
}

std::string SeriesTitle(const std::string& key) {
  return key.substr(0, key.find('|')) + ", " + io::SoilDisplayName(key.substr(key.find('|') + 1));
}

// Marks of a series: its soil's shape (circles LP, squares CP).
std::string SeriesPoint(const std::string& key) {
  return "pt " + std::to_string(io::SoilPoint(key.substr(key.find('|') + 1))) + " ps 1.2";
}
std::string SeriesLine(const std::string& key) { return io::PadSoilLine(key.substr(0, key.find('|')), key.substr(key.find('|') + 1)); }
std::string SeriesColourOf(const std::string& key) { return io::PadColour(key.substr(0, key.find('|'))); }
}  // namespace

namespace {
void WriteTradeFiles(const std::vector<TradeRow>& rows, const fs::path& dir, const TradeLimits& limits) {
  fs::create_directories(dir / "plots" / "data");
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

  const std::vector<std::pair<std::string, std::string>> series = WriteSeries(rows, dir);
  const std::vector<Front> fronts = WriteFronts(rows, dir);
  // A sweep whose drops all failed has no series: each panel says so instead (a `plot` of
  // nothing is a gnuplot error).
  const std::string nothing = io::PlaceholderPlot("no completed drops: nothing to plot");
  // The three panels side by side over a strip that holds the key alone (no key covers a panel's
  // tics or label); the strip's "plot" draws nothing but the key, every series at NaN.
  auto plot = [&](const std::string& columns, double limit) {
    if (series.empty()) return nothing;
    std::string s = "plot ";
    for (size_t i = 0; i < series.size(); ++i)
      s += (i ? ", \\\n     " : "") + io::GnuplotQuote(series[i].first) + " using " + columns + " with linespoints " +
           SeriesLine(series[i].second) + " " + SeriesPoint(series[i].second) + " notitle";
    if (std::isfinite(limit)) s += ", \\\n     " + io::FormatNumber(limit) + " with lines " + io::kPaperBandLine + " notitle";
    return s + "\n";
  };
  std::string key = "set origin 0, 0\nset size 1, 0.2\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\n"
                    "set xrange [0:1]\nset yrange [0:1]\nset key center center horizontal Left reverse samplen 3 width 2\nplot ";
  for (size_t i = 0; i < series.size(); ++i)
    key += (i ? ", " : "") + std::string("NaN with linespoints ") + SeriesLine(series[i].second) + " " + SeriesPoint(series[i].second) +
           " title " + io::GnuplotQuote(SeriesTitle(series[i].second));
  if (limits.any()) key += ", NaN with lines " + std::string(io::kPaperBandLine) + " title 'design limit'";
  const bool any_key = !series.empty();  // no series: the panels say so, and there is nothing to key
  const std::string speeds =
      "set multiplot title 'Footpad trade study against impact speed'\nset xlabel 'impact speed [m/s]'\nunset key\n"
      "set size 0.333, 0.74\nset origin 0, 0.2\nset ylabel 'final penetration [mm]'\n" +
      plot("1:($2*1000)", limits.max_final_penetration_m * 1e3) + "set origin 0.333, 0.2\nset ylabel 'peak force [N]'\n" +
      plot("1:3", limits.max_peak_force_N) + "set origin 0.666, 0.2\nset ylabel 'energy-conversion rate [W]'\n" +
      plot("1:4", INFINITY) + (any_key ? key + "\n" : std::string()) + "unset multiplot\n";
  // The allowable region (lower left, inside the limits) shaded; feasible rows filled, the others open.
  std::string pareto = "set title " +
                       io::GnuplotQuote(limits.any() ? "Peak force against penetration (shaded: within the limits; filled: feasible; "
                                                       "dashed: fronts)"
                                                     : "Peak force against final penetration (no limits given: every pad is "
                                                       "feasible); dashed: fronts") +
                       "\nset xlabel 'final penetration [mm]'\nset ylabel 'peak force [N]'\nset key outside right top\n";
  if (std::isfinite(limits.max_final_penetration_m) || std::isfinite(limits.max_peak_force_N))
    pareto += "set object 1 rect from graph 0, graph 0 to " +
              (std::isfinite(limits.max_final_penetration_m) ? "first " + io::FormatNumber(limits.max_final_penetration_m * 1e3)
                                                               : std::string("graph 1")) +
              ", " + (std::isfinite(limits.max_peak_force_N) ? "first " + io::FormatNumber(limits.max_peak_force_N) : std::string("graph 1")) +
              " behind fc rgb '#e8f4e8' fs solid 1 noborder\n";
  if (series.empty()) {
    pareto += nothing;
  } else {
    pareto += "plot ";
    for (size_t i = 0; i < series.size(); ++i) {
      // Circles on loosely packed soil, squares on others; filled within the limits, open outside.
      const std::string soil = series[i].second.substr(series[i].second.find('|') + 1);
      const std::string file = io::GnuplotQuote(series[i].first), colour = " lc rgb '" + SeriesColourOf(series[i].second) + "'";
      pareto += (i ? ", \\\n     " : "") + file + " using ($2*1000):($5 > 0 ? $3 : 1/0) with points pt " +
                std::to_string(io::SoilPoint(soil)) + " ps 1.6" + colour + " title " +
                io::GnuplotQuote(SeriesTitle(series[i].second)) + ", \\\n     " + file +
                " using ($2*1000):($5 > 0 ? 1/0 : $3) with points pt " + std::to_string(io::SoilPoint(soil, false)) + " ps 1.6" +
                colour + " notitle";
    }
    for (const Front& f : fronts)
      pareto += ", \\\n     " + io::GnuplotQuote(f.file) + " using ($1*1000):2 with lines lw 1.2 dt 2 lc rgb '#000000' notitle";
    pareto += "\n";
    // Each front named by its condition at its far end.
    std::string labels;
    for (size_t i = 0; i < fronts.size(); ++i)
      labels += "set label " + std::to_string(10 + i) + " " + io::GnuplotQuote(fronts[i].label) + " at first " +
                io::FormatNumber(fronts[i].end_mm) + ", first " + io::FormatNumber(fronts[i].end_N) +
                " offset 1,0.6 left front font ',12'\n";
    pareto = labels + pareto;
  }
  const std::string gp = io::Figure("plots/trade", speeds, io::kFigureStrip) + io::Figure("plots/pareto", pareto, io::kFigureWide);
  io::RenderPlots(dir, {"plots/trade.gp", gp, {io::FigurePng("plots/trade"), io::FigurePng("plots/pareto")}});
}
}  // namespace

void WriteTradeOutputs(const std::vector<TradeRow>& rows, const std::string& out_dir, const TradeLimits& limits) {
  io::ReplaceDerivedOutputs(out_dir, io::OutputKind::kSweep, "summary.json",
                            [&](const std::string& staging) { WriteTradeFiles(rows, staging, limits); });
}

}  // namespace touchdown::sweep
