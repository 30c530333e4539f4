#include "drop_tests/gap/diagnose_plots.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/util/percentile.h"
#include "rft/units.h"

namespace touchdown::gap {

namespace fs = std::filesystem;

namespace {

struct ConditionGroup {
  std::string label;
  std::vector<size_t> rows;
};

// Conditions in the order their first drop appears (the dataset's order).
std::vector<ConditionGroup> GroupByCondition(const std::vector<GapRow>& rows) {
  std::vector<ConditionGroup> groups;
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto [it, added] = index.try_emplace(rows[i].condition_key, groups.size());
    if (added) groups.push_back({rows[i].condition_label, {}});
    groups[it->second].rows.push_back(i);
  }
  return groups;
}

std::array<double, 3> Percentiles(const std::vector<double>& v) {
  return {io::Percentile(v, 5), io::Percentile(v, 50), io::Percentile(v, 95)};
}

}  // namespace

GapLayout ChooseGapLayout(const std::vector<GapRow>& rows) {
  if (rows.size() <= kMaxBarsPerPanel) return GapLayout::kPerDrop;
  return GroupByCondition(rows).size() <= kMaxBarsPerPanel ? GapLayout::kByCondition : GapLayout::kScatter;
}

std::optional<GapLayout> WriteGapPanelData(const std::vector<GapRow>& rows, const std::string& atmosphere,
                                           const fs::path& dir) {
  if (rows.empty()) return std::nullopt;
  const GapLayout layout = ChooseGapLayout(rows);
  std::ostringstream out;
  if (layout == GapLayout::kPerDrop) {
    out << "k,drop,force_nrmse_before,force_nrmse_after,noise_floor\n";
    for (size_t k = 0; k < rows.size(); ++k)
      out << k << ',' << rows[k].drop_label << (rows[k].held_out ? "*" : "") << ',' << io::FormatNumber(rows[k].before)
          << ',' << io::FormatNumber(rows[k].after) << ',' << io::FormatNumber(rows[k].floor) << '\n';
  } else if (layout == GapLayout::kByCondition) {
    // The tic names the condition, its drops and how many of them are held out: "(4; 1*)" (no
    // comma: the file's separator).
    out << "k,condition,before_mean,before_min,before_max,after_mean,after_min,after_max,noise_floor,drops,held_out\n";
    const std::vector<ConditionGroup> groups = GroupByCondition(rows);
    for (size_t k = 0; k < groups.size(); ++k) {
      double sum[3] = {0, 0, 0}, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
      int held = 0;
      for (size_t i : groups[k].rows) {
        const double v[2] = {rows[i].before, rows[i].after};
        for (int m = 0; m < 2; ++m) sum[m] += v[m], lo[m] = std::min(lo[m], v[m]), hi[m] = std::max(hi[m], v[m]);
        sum[2] += rows[i].floor;
        held += rows[i].held_out ? 1 : 0;
      }
      const double n = static_cast<double>(groups[k].rows.size());
      out << k << ',' << groups[k].label << " (" << groups[k].rows.size() << (held > 0 ? "; " + std::to_string(held) + "*" : "")
          << ")," << io::FormatNumber(sum[0] / n) << ',' << io::FormatNumber(lo[0]) << ',' << io::FormatNumber(hi[0]) << ','
          << io::FormatNumber(sum[1] / n) << ',' << io::FormatNumber(lo[1]) << ',' << io::FormatNumber(hi[1]) << ','
          << io::FormatNumber(sum[2] / n) << ',' << groups[k].rows.size() << ',' << held << '\n';
    }
  } else {
    // The drops the effect leaves worst are named beside their points.
    std::vector<size_t> order(rows.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return rows[a].after > rows[b].after; });
    std::vector<bool> named(rows.size(), false);
    for (size_t j = 0; j < std::min(kNamedWorstDrops, order.size()); ++j) named[order[j]] = true;
    out << "drop,held_out,force_nrmse_before,force_nrmse_after,noise_floor,named\n";
    for (size_t i = 0; i < rows.size(); ++i)
      out << rows[i].drop_label << ',' << (rows[i].held_out ? 1 : 0) << ',' << io::FormatNumber(rows[i].before) << ','
          << io::FormatNumber(rows[i].after) << ',' << io::FormatNumber(rows[i].floor) << ','
          << (named[i] ? rows[i].drop_label : "") << '\n';
  }
  io::WriteFileAtomically((dir / "data" / ("gap_" + atmosphere + ".csv")).string(), [&](std::ostream& o) { o << out.str(); });
  return layout;
}

// A whisker from a condition's lowest drop to its highest, capped at both ends.
constexpr const char* kWhisker = "with vectors heads size screen 0.006,90 lw 1.5 lc rgb '#000000' notitle, ";

std::string GapPerDropFigure(const std::string& aug_title, const std::array<std::optional<GapLayout>, 2>& panels,
                             bool any_worse) {
  std::ostringstream body;
  // Tic names upright and small, held-out ones starred; a drop or condition the effect made worse
  // carries a down-pointing mark above its bars.
  body << "set multiplot layout 2,1 margins 0.08, 0.98, 0.14, 0.83 spacing 0, 0.2 title "
       << io::GnuplotQuote("Force NRMSE per drop: base and " + aug_title + " (* held out)")
       << "\nset style fill solid 1 border lc rgb '#303030'\nset boxwidth 0.38\n"
          "set key at screen 0.5, screen 0.955 center top horizontal maxrows 1 Left reverse samplen 2\n";
  const std::string accent = std::string("lc rgb '") + io::kAugmentedColour + "'";
  const char* atmospheres[2] = {"vacuum", "air"};
  for (int panel = 0; panel < 2; ++panel) {
    const std::string atmosphere = atmospheres[panel];
    body << (panel > 0 ? "unset key\n" : "") << "unset arrow\nunset label\n";
    if (!panels[panel]) {
      body << "set title 'drops in " << atmosphere << "'\n" << io::PlaceholderPlot("no drop in " + atmosphere);
      continue;
    }
    const std::string file = "'data/gap_" + atmosphere + ".csv'";
    switch (*panels[panel]) {
      case GapLayout::kPerDrop:
        body << "set title 'drops in " << atmosphere << "'\nset xtics rotate by 30 right font ',11'\n"
             << "set xlabel ''\nset ylabel 'force NRMSE'\nset xrange [*:*]\nset yrange [0:*]\nset offsets 0, 0, graph 0.12, 0\n"
             << "plot " << file << " skip 1 using ($1-0.2):3:xtic(2) with boxes lc rgb '#9e9e9e' title 'base', " << file
             << " skip 1 using ($1+0.2):4 with boxes " << accent << " title 'with effect', " << file
             << " skip 1 using 1:5 with points pt 5 ps 1 lc rgb '#000000' title 'sensor-noise floor', " << file
             << " skip 1 using 1:($4 > $3 ? ($4 > $5 ? $4 : $5) * 1.08 : 1/0) with points pt 11 ps 1.8 " << accent << ' '
             << (any_worse ? "title 'made worse by the effect'" : "notitle") << "\n";
        break;
      case GapLayout::kByCondition:
        // Bars: the mean of a condition's drops; whiskers: their range.
        body << "set title 'drops in " << atmosphere
             << ", by condition: mean of its drops, whiskers their range (drops, held out*)'\n"
             << "set xtics rotate by 30 right font ',10'\nset xlabel ''\nset ylabel 'force NRMSE'\nset xrange [*:*]\n"
             << "set yrange [0:*]\nset offsets 0, 0, graph 0.12, 0\n"
             << "plot " << file << " skip 1 using ($1-0.2):3:xtic(2) with boxes lc rgb '#9e9e9e' title 'base', " << file
             << " skip 1 using ($1+0.2):6 with boxes " << accent << " title 'with effect', " << file
             << " skip 1 using ($1-0.2):4:(0):($5-$4) " << kWhisker << file
             << " skip 1 using ($1+0.2):7:(0):($8-$7) " << kWhisker << file
             << " skip 1 using 1:9 with points pt 5 ps 1 lc rgb '#000000' title 'sensor-noise floor', " << file
             << " skip 1 using 1:($6 > $3 ? ($8 > $9 ? $8 : $9) * 1.08 : 1/0) with points pt 11 ps 1.8 " << accent << ' '
             << (any_worse ? "title 'made worse by the effect'" : "notitle") << "\n";
        break;
      case GapLayout::kScatter:
        // Too many conditions for bars: each drop a point, the diagonal marks no change.
        body << "set title 'drops in " << atmosphere << ": each drop (held out filled), the "
             << kNamedWorstDrops << " worst with the effect named'\nset xtics norotate font ',11'\n"
             << "set xlabel 'force NRMSE, base'\nset ylabel 'force NRMSE, with effect'\nset offsets 0, 0, 0, 0\n"
             << "set key inside top left vertical maxrows 4 Left reverse samplen 2 font ',11'\n"
             << "stats " << file << " skip 1 using 3:4 nooutput name 'G'\nstats " << file
             << " skip 1 using 5 nooutput name 'F'\ng_top = 1.08 * (G_max_x > G_max_y ? G_max_x : G_max_y) + 1e-9\n"
             << "set xrange [0:g_top]\nset yrange [0:g_top]\n"
             << "plot x with lines lw 1 lc rgb '#000000' title 'no change (above: made worse)', F_median with lines dt 2 lw 1.5 "
             << "lc rgb '#000000' title 'sensor-noise floor (median)', " << file
             << " skip 1 using 3:($2 == 0 ? $4 : 1/0) with points pt 6 ps 1 " << accent << " title 'training drop', " << file
             << " skip 1 using 3:($2 == 1 ? $4 : 1/0) with points pt 7 ps 1 " << accent << " title 'held-out drop', " << file
             << " skip 1 using 3:4:6 with labels left offset 0.6, 0.3 font ',10' notitle\n";
        break;
    }
  }
  body << "unset multiplot\n";
  return io::Figure("plots/gap_per_drop", body.str(), io::kFigureWide);
}

std::vector<ResidualBand> ResidualBands(const std::vector<ResidualSample>& samples, int bins) {
  std::vector<ResidualBand> out;
  if (samples.empty() || bins < 1) return out;
  double t_lo = samples.front().t_s, t_hi = t_lo;
  for (const ResidualSample& s : samples) t_lo = std::min(t_lo, s.t_s), t_hi = std::max(t_hi, s.t_s);
  const double width = (t_hi - t_lo) / bins;
  std::vector<std::vector<double>> base(bins), aug(bins);
  for (const ResidualSample& s : samples) {
    const int b = width > 0 ? std::min(bins - 1, static_cast<int>((s.t_s - t_lo) / width)) : 0;
    base[b].push_back(s.base);
    aug[b].push_back(s.augmented);
  }
  for (int b = 0; b < bins; ++b) {
    if (base[b].size() < 5) continue;
    out.push_back({(t_lo + (b + 0.5) * width) * units::kMsPerS, Percentiles(base[b]), Percentiles(aug[b]), base[b].size()});
  }
  return out;
}

void WriteResidualBands(const std::vector<ResidualBand>& bands, const std::string& atmosphere, const fs::path& dir) {
  io::WriteFileAtomically((dir / "data" / ("residual_bands_" + atmosphere + ".csv")).string(), [&](std::ostream& out) {
    out << "t_ms,base_p05,base_p50,base_p95,augmented_p05,augmented_p50,augmented_p95,samples\n";
    for (const ResidualBand& b : bands) {
      out << io::FormatNumber(b.t_ms);
      for (double v : b.base) out << ',' << io::FormatNumber(v);
      for (double v : b.augmented) out << ',' << io::FormatNumber(v);
      out << ',' << b.samples << '\n';
    }
  });
}

std::string ResidualFigure(const std::string& aug_title, const ResidualPanels& panels) {
  std::ostringstream body;
  body << "set xlabel 't [ms]'\nset ylabel 'normalised residual'\n";
  const double pad = 0.05 * (panels.r_hi - panels.r_lo) + 1e-3;
  body << "set yrange [" << io::FormatNumber(panels.r_lo - pad) << ':' << io::FormatNumber(panels.r_hi + pad) << "]\nset xrange ["
       << io::FormatNumber(panels.t_lo_ms) << ':' << io::FormatNumber(panels.t_hi_ms) << "]\n";
  body << "set multiplot layout 2,2 title 'Held-out force residual (simulated - measured) / measured peak force; "
          "one scale on every panel'\n";
  const char* atmospheres[2] = {"vacuum", "air"};
  for (int panel = 0; panel < 2; ++panel) {
    const std::string atmosphere = atmospheres[panel];
    for (int model = 0; model < 2; ++model) {
      const std::string name = model == 0 ? "base" : aug_title;
      const std::string colour = model == 0 ? "#6e6e6e" : io::kAugmentedColour;
      switch (panels.layout[panel]) {
        case ResidualLayout::kNone:
          body << "unset key\nset title " << io::GnuplotQuote(name + ", " + atmosphere) << "\n"
               << io::PlaceholderPlot("no held-out drop in " + atmosphere + " could be simulated");
          break;
        case ResidualLayout::kSamples:
          // Residuals are noisy samples: points, not lines joining the noise.
          body << "unset key\nset title "
               << io::GnuplotQuote(name + ", " + atmosphere + " (" + std::to_string(panels.drops[panel]) +
                                   " held-out drops)")
               << "\nplot 'data/residuals_held_out.csv' skip 1 using ($1*1000):(strcol(4) eq '" << atmosphere << "' ? $"
               << (model == 0 ? 2 : 3) << " : 1/0) with points pt 7 ps 0.6 lc rgb '" << colour
               << "' notitle, 0 with lines lw 1 lc rgb '#000000' notitle\n";
          break;
        case ResidualLayout::kBands: {
          // Past kMaxResidualDropsDrawn drops every sample overlaid is a solid band: the median
          // and the 5-95 % band over time bins say where the model is off and by how much.
          const std::string file = "'data/residual_bands_" + atmosphere + ".csv'";
          const int c = model == 0 ? 2 : 5;
          body << "set key top right samplen 2\nset title "
               << io::GnuplotQuote(name + ", " + atmosphere + " (" + std::to_string(panels.drops[panel]) +
                                   " held-out drops, binned)")
               << "\nplot " << file << " skip 1 using 1:" << c << ':' << c + 2 << " with filledcurves fs transparent solid 0.3 "
               << "noborder lc rgb '" << colour << "' title '5-95 %', " << file << " skip 1 using 1:" << c + 1
               << " with lines lw 2.5 lc rgb '" << colour << "' title 'median', 0 with lines lw 1 lc rgb '#000000' notitle\n";
          break;
        }
      }
    }
  }
  body << "unset multiplot\n";
  return io::Figure("plots/residuals", body.str());
}

}  // namespace touchdown::gap
