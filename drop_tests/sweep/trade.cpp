#include "drop_tests/sweep/trade.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "drop_tests/io/json_number.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/io/dataset_csv.h"
#include "drop_tests/io/plot_runner.h"
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

std::vector<TradeRow> TradeTable(const std::vector<DropRecord>& records) {
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
  }
  std::vector<TradeRow> out;
  for (auto& [key, row] : rows) {
    const int ok = row.drops - row.failed;
    for (double* v : {&row.final_penetration_m, &row.peak_force_N, &row.mean_conversion_rate_W})
      *v = ok > 0 ? *v / ok : std::nan("");
    out.push_back(row);
  }
  std::map<std::pair<std::string, double>, std::vector<size_t>> conditions;
  for (size_t i = 0; i < out.size(); ++i) conditions[{out[i].soil, out[i].impact_speed_m_s}].push_back(i);
  for (const auto& [key, members] : conditions) MarkParetoFront(out, members);
  return out;
}

void MarkParetoFront(std::vector<TradeRow>& rows, const std::vector<size_t>& condition) {
  for (size_t i : condition) {
    const TradeRow& a = rows[i];
    if (a.drops == a.failed) continue;  // nothing to rank
    bool beaten = false;
    for (size_t j : condition) {
      const TradeRow& b = rows[j];
      if (j == i || b.drops == b.failed) continue;
      beaten |= b.final_penetration_m <= a.final_penetration_m && b.peak_force_N <= a.peak_force_N &&
                (b.final_penetration_m < a.final_penetration_m || b.peak_force_N < a.peak_force_N);
    }
    rows[i].pareto = !beaten;
  }
}

nlohmann::json TradeJson(const std::vector<TradeRow>& rows) {
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
                    {"pareto", r.pareto}});
  return {{"rows", list},
          {"pareto_rule", "within each (soil, impact speed): pads no other pad beats on both final penetration "
                          "and peak force (lower is better)"},
          {"conversion_rate", "impact energy / time to rest (Sutoh et al. 2017, dE/dt)"}};
}

void WriteTradeOutputs(const std::vector<TradeRow>& rows, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots" / "data");
  io::WriteFileAtomically((dir / "trade.csv").string(), [&](std::ostream& out) {
    out << "pad,soil,impact_speed_m_s,drops,failed,final_penetration_m,peak_force_N,mean_conversion_rate_W,pareto\n";
    for (const TradeRow& r : rows)
      out << r.pad << ',' << r.soil << ',' << io::FormatNumber(r.impact_speed_m_s) << ',' << r.drops << ',' << r.failed
          << ',' << io::FormatNumber(r.final_penetration_m) << ',' << io::FormatNumber(r.peak_force_N) << ','
          << io::FormatNumber(r.mean_conversion_rate_W) << ',' << (r.pareto ? 1 : 0) << '\n';
  });
  io::WriteFileAtomically((dir / "summary.json").string(), [&](std::ostream& out) { out << TradeJson(rows).dump(2) << '\n'; });

  // One data file per (pad, soil) series against speed and one per condition's Pareto front.
  std::map<std::pair<std::string, std::string>, std::vector<const TradeRow*>> series;
  std::map<std::pair<std::string, double>, std::vector<const TradeRow*>> fronts;
  for (const TradeRow& r : rows) {
    if (r.drops == r.failed) continue;
    series[{r.pad, r.soil}].push_back(&r);
    if (r.pareto) fronts[{r.soil, r.impact_speed_m_s}].push_back(&r);
  }
  std::vector<std::pair<std::string, std::string>> series_files;  // file, title
  for (auto& [key, list] : series) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->impact_speed_m_s < b->impact_speed_m_s; });
    const std::string file = "plots/data/" + key.first + "__" + key.second + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&, &list = list](std::ostream& out) {
      for (const TradeRow* r : list)
        out << io::FormatNumber(r->impact_speed_m_s) << ',' << io::FormatNumber(r->final_penetration_m) << ','
            << io::FormatNumber(r->peak_force_N) << ',' << io::FormatNumber(r->mean_conversion_rate_W) << '\n';
    });
    series_files.push_back({file, key.first + ", " + key.second});
  }
  std::vector<std::pair<std::string, std::string>> front_files;
  int k = 0;
  for (auto& [key, list] : fronts) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->final_penetration_m < b->final_penetration_m; });
    const std::string file = "plots/data/front_" + std::to_string(k++) + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&, &list = list](std::ostream& out) {
      for (const TradeRow* r : list)
        out << io::FormatNumber(r->final_penetration_m) << ',' << io::FormatNumber(r->peak_force_N) << ',' << r->pad << '\n';
    });
    front_files.push_back({file, "front: " + key.first + ", " + io::FormatNumber(key.second) + " m/s"});
  }
  // A sweep whose drops all failed has no series: each panel says so instead (a `plot` of
  // nothing is a gnuplot error).
  const std::string nothing = io::PlaceholderPlot("no completed drops: nothing to plot");
  auto plot = [&](const std::string& columns) {
    if (series_files.empty()) return nothing;
    std::string s = "plot ";
    for (size_t i = 0; i < series_files.size(); ++i)
      s += (i ? ", \\\n     " : "") + io::GnuplotQuote(series_files[i].first) + " using " + columns +
           " with linespoints lw 2 pt 7 title " + io::GnuplotQuote(series_files[i].second);
    return s + "\n";
  };
  std::string gp =
      "set datafile separator ','\nset termoption noenhanced\nset grid\nset key outside right\n"
      "set terminal pngcairo noenhanced size 1500,450 font 'sans,10'\nset output 'plots/trade.png'\n"
      "set multiplot layout 1,3 title 'Footpad trade study against impact speed'\nset xlabel 'impact speed [m/s]'\n"
      "set key off\nset ylabel 'final penetration [mm]'\n" + plot("1:($2*1000)") +
      "set ylabel 'peak force [N]'\n" + plot("1:3") + "set key outside right\nset ylabel 'energy-conversion rate [W]'\n" +
      plot("1:4") + "unset multiplot\n";
  gp += "set terminal pngcairo noenhanced size 900,650 font 'sans,10'\nset output 'plots/pareto.png'\n"
        "set title 'Peak force against final penetration (lower-left is better); fronts per soil and speed'\n"
        "set xlabel 'final penetration [mm]'\nset ylabel 'peak force [N]'\nset key outside right\n";
  if (series_files.empty()) {
    gp += nothing;
  } else {
    gp += "plot ";
    for (size_t i = 0; i < series_files.size(); ++i)
      gp += (i ? ", \\\n     " : "") + io::GnuplotQuote(series_files[i].first) + " using ($2*1000):3 with points pt 7 title " +
            io::GnuplotQuote(series_files[i].second);
    for (const auto& [file, title] : front_files)
      gp += ", \\\n     " + io::GnuplotQuote(file) + " using ($1*1000):2 with lines lw 1 dt 2 lc rgb 'black' notitle";
    gp += "\n";
  }
  io::RenderPlots(dir, {"plots/trade.gp", gp, {"plots/trade.png", "plots/pareto.png"}});
}

}  // namespace touchdown::sweep
