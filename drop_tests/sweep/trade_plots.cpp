// The trade study's figures (trade.h): plots/trade (three panels against impact speed) and
// plots/pareto (peak force against final penetration, one panel per soil), drawn to read from a
// grid of a few speeds to a random sweep of thousands of drops (docs/figures.md, "At size").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/sweep/trade.h"
#include "drop_tests/util/percentile.h"
#include "rft/units.h"

namespace touchdown::sweep {

namespace fs = std::filesystem;

namespace {
// A (pad, soil) series of more rows than this (a random-speed sweep holds one row per drop) is
// drawn as its rows' points and a line through the medians of speed bins: a line joining every
// row zigzags between the drops' other drawn parameters (mass, gravity) and hides the trend.
constexpr size_t kMaxJoinedRows = 30;
// A speed bin's median is drawn from this many rows or more.
constexpr size_t kMinBinRows = 3;
// Fronts drawn (dashed, named by their speed) in a soil's panel, at most: past that the dashes
// cover the points they join (a random-speed sweep has a condition per drop).
constexpr size_t kMaxDrawnFronts = 12;
// Tics on the speed axis of a panel a third of the figure wide: more run their labels together.
constexpr int kMaxSpeedTics = 5;

struct Series {
  std::string pad, soil, colour;  // colour: the pad's in this trade (io::PadColours)
  std::vector<const TradeRow*> rows;  // by speed
  std::string file;                   // speed, penetration, force, conversion rate, feasible
  std::string medians;                // "" unless dense: speed, penetration, force, conversion rate
  bool dense() const { return rows.size() > kMaxJoinedRows; }
};

// A speed with 3 significant digits, as a label shows it ("1.75"; a random draw would show 17).
std::string SpeedText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// The medians of a dense series over equal speed bins (a bin per 25 rows, 5 to 20 of them), each
// bin of kMinBinRows rows or more one row: median speed, penetration, force, conversion rate.
void WriteMedians(Series& s, const fs::path& dir) {
  const double lo = s.rows.front()->impact_speed_m_s, hi = s.rows.back()->impact_speed_m_s;
  const size_t bins = std::clamp<size_t>(s.rows.size() / 25, 5, 20);
  std::vector<std::vector<const TradeRow*>> in(bins);
  for (const TradeRow* r : s.rows) {
    const double f = hi > lo ? (r->impact_speed_m_s - lo) / (hi - lo) : 0.0;
    in[std::min(bins - 1, static_cast<size_t>(f * static_cast<double>(bins)))].push_back(r);
  }
  s.medians = "plots/data/" + s.pad + "__" + s.soil + "__medians.csv";
  io::WriteFileAtomically((dir / s.medians).string(), [&](std::ostream& out) {
    for (const auto& bin : in) {
      if (bin.size() < kMinBinRows) continue;
      std::vector<double> v[4];
      for (const TradeRow* r : bin)
        for (const auto& [k, x] : {std::pair{0, r->impact_speed_m_s}, std::pair{1, r->final_penetration_m},
                                   std::pair{2, r->peak_force_N}, std::pair{3, r->mean_conversion_rate_W}})
          v[k].push_back(x);
      out << io::FormatNumber(io::Percentile(v[0], 50)) << ',' << io::FormatNumber(io::Percentile(v[1], 50)) << ','
          << io::FormatNumber(io::Percentile(v[2], 50)) << ',' << io::FormatNumber(io::Percentile(v[3], 50)) << '\n';
    }
  });
}

// One data file per (pad, soil) series against speed (and its medians when dense).
std::vector<Series> WriteSeries(const std::vector<TradeRow>& rows, const fs::path& dir) {
  std::map<std::pair<std::string, std::string>, std::vector<const TradeRow*>> by_key;
  for (const TradeRow& r : rows)
    if (r.drops != r.failed) by_key[{r.pad, r.soil}].push_back(&r);
  std::vector<std::string> pads;
  for (const auto& [key, list] : by_key)
    if (std::find(pads.begin(), pads.end(), key.first) == pads.end()) pads.push_back(key.first);
  const std::vector<std::string> colours = io::PadColours(pads);
  std::vector<Series> series;
  for (auto& [key, list] : by_key) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->impact_speed_m_s < b->impact_speed_m_s; });
    const std::string colour = colours[std::find(pads.begin(), pads.end(), key.first) - pads.begin()];
    Series s{key.first, key.second, colour, list, "plots/data/" + key.first + "__" + key.second + ".csv", ""};
    io::WriteFileAtomically((dir / s.file).string(), [&](std::ostream& out) {
      for (const TradeRow* r : s.rows)
        out << io::FormatNumber(r->impact_speed_m_s) << ',' << io::FormatNumber(r->final_penetration_m) << ','
            << io::FormatNumber(r->peak_force_N) << ',' << io::FormatNumber(r->mean_conversion_rate_W) << ','
            << (r->feasible ? 1 : 0) << '\n';
    });
    if (s.dense()) WriteMedians(s, dir);
    series.push_back(s);
  }
  return series;
}

std::string Title(const Series& s) { return s.pad + ", " + io::SoilDisplayName(s.soil); }
std::string Point(const Series& s) { return "pt " + std::to_string(io::SoilPoint(s.soil)) + " ps 1.2"; }
std::string Line(const Series& s) { return io::ColourSoilLine(s.colour, s.soil); }
std::string Colour(const Series& s) { return " lc rgb '" + s.colour + "'"; }
// A dense series' drops: small dots in its pad's colour, under its median line.
std::string Dots(const Series& s) { return "pt 7 ps 0.35" + Colour(s); }

// One speed panel: each series as a line through its rows, or its drops' dots and its medians'
// line; `limit` (file units) a dotted design limit.
std::string SpeedPanel(const std::vector<Series>& series, int column, const std::string& scale, double limit) {
  const std::string y = "($" + std::to_string(column) + scale + ")";
  std::string s = "plot ";
  for (size_t i = 0; i < series.size(); ++i) {
    const Series& x = series[i];
    s += (i ? ", \\\n     " : "");
    if (x.dense())
      s += io::GnuplotQuote(x.file) + " using 1:" + y + " with points " + Dots(x) + " notitle, \\\n     " +
           io::GnuplotQuote(x.medians) + " using 1:" + y + " with lines " + Line(x) + " notitle";
    else
      s += io::GnuplotQuote(x.file) + " using 1:" + y + " with linespoints " + Line(x) + " " + Point(x) + " notitle";
  }
  if (std::isfinite(limit)) s += ", \\\n     " + io::FormatNumber(limit) + " with lines " + io::kPaperBandLine + " notitle";
  return s + "\n";
}

// The speed figure's layout in pixels: its panels and title as they always were, over a strip for
// the key that grows by a row of entries per kKeyColumns series (a trade of many pads).
constexpr int kPanelPx = 444, kTitlePx = 36, kKeyColumns = 4, kKeyRowPx = 30;
int KeyStripPx(size_t entries) {
  const int rows = static_cast<int>((entries + kKeyColumns - 1) / kKeyColumns);
  return 60 + kKeyRowPx * std::max(rows, 2);
}

// The speed figure's key, in a strip of its own under the panels (every series at NaN).
std::string SpeedKey(const std::vector<Series>& series, bool limits, double strip_fraction) {
  std::string key = "set origin 0, 0\nset size 1, " + io::FormatNumber(strip_fraction) +
                    "\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nset xrange [0:1]\nset yrange [0:1]\n"
                    "set key center center horizontal Left reverse samplen 3 width 2 maxcols " +
                    std::to_string(kKeyColumns) + "\nplot ";
  for (size_t i = 0; i < series.size(); ++i)
    key += (i ? ", " : "") + std::string("NaN with ") +
           (series[i].dense() ? "lines " + Line(series[i]) : "linespoints " + Line(series[i]) + " " + Point(series[i])) +
           " title " + io::GnuplotQuote(Title(series[i]));
  if (limits) key += ", NaN with lines " + std::string(io::kPaperBandLine) + " title 'design limit'";
  return key + "\n";
}

// `set xtics` for the speeds of `series`: at most kMaxSpeedTics steps of 1, 2 or 5.
std::string SpeedTics(const std::vector<Series>& series) {
  double lo = INFINITY, hi = -INFINITY;
  for (const Series& s : series) {
    lo = std::min(lo, s.rows.front()->impact_speed_m_s);
    hi = std::max(hi, s.rows.back()->impact_speed_m_s);
  }
  return hi > lo ? "set xtics " + io::FormatNumber(io::TicStep(hi - lo, kMaxSpeedTics)) + "\n" : "";
}

// The speed figure's size: kFigureStrip, taller by the key's extra rows.
io::FigureSize SpeedFigureSize(const std::vector<Series>& series, const TradeLimits& limits) {
  return {io::kFigureStrip.width, kPanelPx + kTitlePx + KeyStripPx(series.size() + (limits.any() ? 1 : 0))};
}

std::string SpeedFigure(const std::vector<Series>& series, const TradeLimits& limits, const std::string& nothing) {
  const io::FigureSize size = SpeedFigureSize(series, limits);
  const double strip = static_cast<double>(KeyStripPx(series.size() + (limits.any() ? 1 : 0))) / size.height;
  const std::string panel_size = "set size 0.333, " + io::FormatNumber(static_cast<double>(kPanelPx) / size.height) + "\n";
  const auto origin = [&](const char* x) { return "set origin " + std::string(x) + ", " + io::FormatNumber(strip) + "\n"; };
  const bool any_dense = std::any_of(series.begin(), series.end(), [](const Series& s) { return s.dense(); });
  const std::string title = any_dense ? "Footpad trade study against impact speed (dots: every drop; lines: medians "
                                        "over speed bins, where a series has more than " +
                                            std::to_string(kMaxJoinedRows) + " speeds)"
                                      : "Footpad trade study against impact speed";
  const auto panel = [&](int column, const std::string& scale, double limit) {
    return series.empty() ? nothing : SpeedPanel(series, column, scale, limit);
  };
  // The three panels side by side over a strip that holds the key alone (no key covers a panel's
  // tics or label).
  return "set multiplot title " + io::GnuplotQuote(title) + "\nset xlabel 'impact speed [m/s]'\nunset key\n" +
         SpeedTics(series) + panel_size + origin("0") + "set ylabel 'final penetration [mm]'\n" +
         panel(2, "*1000", limits.max_final_penetration_m * units::kMmPerM) + origin("0.333") + "set ylabel 'peak force [N]'\n" +
         panel(3, "", limits.max_peak_force_N) + origin("0.666") + "set ylabel 'energy-conversion rate [W]'\n" +
         panel(4, "", INFINITY) + (series.empty() ? std::string() : SpeedKey(series, limits.any(), strip)) +
         "unset multiplot\n";
}

struct Front {
  std::string file;  // penetration, force, pad, sorted along the front
  std::string label; // its speed: "1.75 m/s" (its panel names the soil)
  double end_mm = 0.0, end_N = 0.0;  // its last point, where the label goes
};

// The fronts of one soil's conditions, one data file each; none past kMaxDrawnFronts (`count`
// says how many there are).
std::vector<Front> WriteFronts(const std::vector<TradeRow>& rows, const std::string& soil, size_t panel,
                               const fs::path& dir, size_t& count) {
  std::map<double, std::vector<const TradeRow*>> fronts;
  for (const TradeRow& r : rows)
    if (r.pareto && r.soil == soil) fronts[r.impact_speed_m_s].push_back(&r);
  count = fronts.size();
  std::vector<Front> files;
  if (count > kMaxDrawnFronts) return files;
  for (auto& [speed, list] : fronts) {
    std::sort(list.begin(), list.end(), [](auto a, auto b) { return a->final_penetration_m < b->final_penetration_m; });
    const std::string file = "plots/data/front_" + std::to_string(panel) + "_" + std::to_string(files.size()) + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&, &list = list](std::ostream& out) {
      for (const TradeRow* r : list)
        out << io::FormatNumber(r->final_penetration_m) << ',' << io::FormatNumber(r->peak_force_N) << ',' << r->pad << '\n';
    });
    files.push_back({file, SpeedText(speed) + " m/s", list.back()->final_penetration_m * units::kMmPerM, list.back()->peak_force_N});
  }
  return files;
}

// The panel of one soil: its pads' rows (filled within the limits, open outside), its fronts and
// their speeds; the key, under the panel, names its pads.
std::string ParetoPanel(const std::vector<Series>& series, const std::vector<TradeRow>& rows, const std::string& soil,
                        size_t panel, const fs::path& dir) {
  size_t conditions = 0;
  const std::vector<Front> fronts = WriteFronts(rows, soil, panel, dir, conditions);
  std::string title = io::SoilDisplayName(soil);
  if (conditions > kMaxDrawnFronts)
    title += ": " + std::to_string(conditions) + " conditions, fronts not drawn (drawn up to " +
             std::to_string(kMaxDrawnFronts) + ")";
  std::string labels, plot;
  for (const Series& s : series) {
    if (s.soil != soil) continue;
    const std::string file = io::GnuplotQuote(s.file), size = s.dense() ? " ps 0.6" : " ps 1.6";
    plot += (plot.empty() ? "plot " : ", \\\n     ") + file + " using ($2*1000):($5 > 0 ? $3 : 1/0) with points pt " +
            std::to_string(io::SoilPoint(soil)) + size + Colour(s) + " title " + io::GnuplotQuote(s.pad) + ", \\\n     " +
            file + " using ($2*1000):($5 > 0 ? 1/0 : $3) with points pt " + std::to_string(io::SoilPoint(soil, false)) +
            size + Colour(s) + " notitle";
  }
  for (size_t i = 0; i < fronts.size(); ++i) {
    plot += ", \\\n     " + io::GnuplotQuote(fronts[i].file) + " using ($1*1000):2 with lines lw 1.2 dt 2 lc rgb '#000000' notitle";
    labels += "set label " + std::to_string(10 + i) + " " + io::GnuplotQuote(fronts[i].label) + " at first " +
              io::FormatNumber(fronts[i].end_mm) + ", first " + io::FormatNumber(fronts[i].end_N) +
              " offset 1,0.6 left front font ',12'\n";
  }
  return "set title " + io::GnuplotQuote(title) + "\n" + labels + plot + "\nunset label\n";
}

// The ranges every soil's panel shares, from 0 a little past the largest value, so the soils
// compare by eye; the limits are on the scale.
std::string ParetoRanges(const std::vector<TradeRow>& rows, const TradeLimits& limits) {
  double mm = 0.0, newton = 0.0;
  for (const TradeRow& r : rows)
    if (r.drops != r.failed) {
      mm = std::max(mm, r.final_penetration_m * units::kMmPerM);
      newton = std::max(newton, r.peak_force_N);
    }
  if (std::isfinite(limits.max_final_penetration_m)) mm = std::max(mm, limits.max_final_penetration_m * units::kMmPerM);
  if (std::isfinite(limits.max_peak_force_N)) newton = std::max(newton, limits.max_peak_force_N);
  return (mm > 0.0 ? "set xrange [0:" + io::FormatNumber(io::AxisTopPast(mm)) + "]\n" : "") +
         (newton > 0.0 ? "set yrange [0:" + io::FormatNumber(io::AxisTopPast(newton)) + "]\n" : "");
}

// Room under a Pareto panel for its key's rows (io::kKeyBelow's margin holds one), at about four
// pads a row.
std::string ParetoKeyMargin(const std::vector<Series>& series, const std::string& soil) {
  const auto pads = std::count_if(series.begin(), series.end(), [&](const Series& s) { return s.soil == soil; });
  const int rows = static_cast<int>((pads + kKeyColumns - 1) / kKeyColumns);
  return rows > 1 ? "set bmargin " + std::to_string(5 + (3 * rows + 1) / 2) + "\n" : "";
}

std::string ParetoFigure(const std::vector<Series>& series, const std::vector<TradeRow>& rows, const TradeLimits& limits,
                         const fs::path& dir, const std::string& nothing) {
  const std::string title =
      limits.any() ? "Peak force against penetration per soil (shaded: within the limits; filled: feasible; dashed: "
                     "fronts, by impact speed)"
                   : "Peak force against final penetration per soil (no limits given: every pad is feasible); dashed: "
                     "fronts, by impact speed";
  std::string body = "set xlabel 'final penetration [mm]'\nset ylabel 'peak force [N]'\n";
  // The allowable region (lower left, inside the limits) shaded in every panel.
  if (std::isfinite(limits.max_final_penetration_m) || std::isfinite(limits.max_peak_force_N))
    body += "set object 1 rect from graph 0, graph 0 to " +
            (std::isfinite(limits.max_final_penetration_m) ? "first " + io::FormatNumber(limits.max_final_penetration_m * units::kMmPerM)
                                                           : std::string("graph 1")) +
            ", " +
            (std::isfinite(limits.max_peak_force_N) ? "first " + io::FormatNumber(limits.max_peak_force_N)
                                                    : std::string("graph 1")) +
            " behind fc rgb '#e8f4e8' fs solid 1 noborder\n";
  std::vector<std::string> soils;
  for (const Series& s : series)
    if (std::find(soils.begin(), soils.end(), s.soil) == soils.end()) soils.push_back(s.soil);
  if (soils.empty()) return "set title " + io::GnuplotQuote(title) + "\n" + body + nothing;
  body = "set multiplot layout 1," + std::to_string(soils.size()) + " title " + io::GnuplotQuote(title) + "\n" + body +
         ParetoRanges(rows, limits) + io::kKeyBelow + ParetoKeyMargin(series, soils.front());
  for (size_t k = 0; k < soils.size(); ++k) body += ParetoPanel(series, rows, soils[k], k, dir);
  return body + "unset multiplot\n";
}
}  // namespace

void WriteTradePlots(const std::vector<TradeRow>& rows, const std::string& dir, const TradeLimits& limits) {
  fs::create_directories(fs::path(dir) / "plots" / "data");
  const std::vector<Series> series = WriteSeries(rows, dir);
  // A sweep whose drops all failed has no series: each panel says so instead (a `plot` of
  // nothing is a gnuplot error).
  const std::string nothing = io::PlaceholderPlot("no completed drops: nothing to plot");
  const std::string gp = io::Figure("plots/trade", SpeedFigure(series, limits, nothing), SpeedFigureSize(series, limits)) +
                         io::Figure("plots/pareto", ParetoFigure(series, rows, limits, dir, nothing), io::kFigureWide);
  io::RenderPlots(dir, {"plots/trade.gp", gp, {io::FigurePng("plots/trade"), io::FigurePng("plots/pareto")}});
}

}  // namespace touchdown::sweep
