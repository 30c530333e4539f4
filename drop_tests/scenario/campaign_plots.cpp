#include "drop_tests/scenario/campaign_plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_runner.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
constexpr double kPlotSampleRateHz = 10000.0;  // 80-210 points per stroke at 1 m/s

bool SameSpeed(double a, double b) { return std::abs(a - b) < 1e-9; }

struct Stroke {  // one reference-speed drop, densely sampled: plots/data/<drop_id>.csv
  std::string file, pad, soil;
  double t_stop_s = 0.0;
};

std::string Label(const std::string& pad, const std::string& soil) { return pad + ", " + io::SoilDisplayName(soil); }

// The reference-speed drops again at the plot's sampling, written up to kStrokeWindow times the
// last stop (the time histories' range); columns: t [ms], penetration [mm], force [N].
constexpr double kStrokeWindow = 1.15;

std::vector<Stroke> DenseStrokes(const CampaignResult& r, const fs::path& dir) {
  pad::RigDropOptions dense;
  dense.sample_rate_hz = kPlotSampleRateHz;
  std::vector<std::pair<const CampaignCase*, drop::PadDrop>> runs;
  double t_stop_max = 0.0;
  for (const CampaignCase& c : r.scenario.cases) {
    if (!SameSpeed(c.conditions.impact_speed_m_s, r.scenario.reference_speed_m_s)) continue;
    runs.emplace_back(&c, drop::RunDrop(drop::ResolveDrop(*c.pad, c.soil, c.conditions, {.rig = dense})));
    t_stop_max = std::max(t_stop_max, runs.back().second.result.time_to_rest_s);
  }
  std::vector<Stroke> strokes;
  for (const auto& run : runs) {
    const CampaignCase* c = run.first;
    const drop::PadDrop& d = run.second;  // named, not a structured binding: clang 14 cannot capture those
    const std::string file = "plots/data/" + c->drop_id + ".csv";
    io::WriteFileAtomically((dir / file).string(), [&](std::ostream& out) {
      out << "t_ms,penetration_mm,force_N\n" << std::setprecision(6);  // a figure's resolution
      for (const pad::DropSample& s : d.result.trace) {
        if (s.t_s > kStrokeWindow * t_stop_max) break;
        out << s.t_s * units::kMsPerS << ',' << s.penetration_m * units::kMmPerM << ',' << s.force_N << '\n';
      }
    });
    strokes.push_back({file, c->pad->name, c->soil.name, d.result.time_to_rest_s});
  }
  return strokes;
}

std::string StrokePlot(const std::vector<Stroke>& strokes, const std::string& columns, bool stroke_only) {
  if (strokes.empty()) return io::PlaceholderPlot("no drop at the reference speed");
  std::ostringstream s;
  s << std::setprecision(10) << "plot ";
  for (size_t i = 0; i < strokes.size(); ++i) {
    const Stroke& k = strokes[i];
    s << (i ? ", \\\n     " : "") << io::GnuplotQuote(k.file) << " skip 1 using ";
    if (stroke_only) s << "($1 <= " << k.t_stop_s * units::kMsPerS << " ? $2 : 1/0):3";  // force on penetration up to the stop
    else s << columns;
    s << " with lines " << io::PadSoilLine(k.pad, k.soil) << " title " << io::GnuplotQuote(Label(k.pad, k.soil));
  }
  return s.str() + "\n";
}

std::string TimeHistories(const std::vector<Stroke>& strokes, const std::string& speed) {
  double t_stop_max = 0.0;
  for (const Stroke& k : strokes) t_stop_max = std::max(t_stop_max, k.t_stop_s);
  std::ostringstream body;
  // One key, in a row above the upper panel: both panels draw the same cases in the same styles.
  body << "set multiplot layout 2,1 margins 0.08, 0.98, 0.1, 0.87 spacing 0, 0.1 title 'Time histories at " << speed
       << " m/s (t = 0 at touchdown)'\n"
       << "set key at screen 0.5, screen 0.935 center top horizontal Left reverse samplen 3 width -1\nset xrange [0:"
       << std::max(kStrokeWindow * t_stop_max * units::kMsPerS, 1.0) << "]\nset xlabel 't [ms]'\nset ylabel 'force on pad [N]'\n"
       << "set yrange [0:*]\n" << StrokePlot(strokes, "1:3", false)
       << "unset key\nset ylabel 'penetration [mm] (down)'\nset yrange [0:*] reverse\n" << StrokePlot(strokes, "1:2", false)
       << "unset multiplot\n";
  return io::Figure("plots/fig3_time_histories", body.str());
}

std::string ForcePenetration(const CampaignResult& r, const std::vector<Stroke>& strokes, const std::string& speed) {
  std::map<std::string, int> soil_count;
  for (const Stroke& k : strokes) ++soil_count[k.soil];
  std::string main_soil;
  for (const auto& [soil, n] : soil_count)
    if (main_soil.empty() || n > soil_count[main_soil]) main_soil = soil;
  const std::string first_pad = r.scenario.cases.empty() ? "" : r.scenario.cases.front().pad->name;
  std::vector<Stroke> by_pad, by_soil;
  for (const Stroke& k : strokes) {
    if (k.soil == main_soil) by_pad.push_back(k);
    if (k.pad == first_pad &&
        std::none_of(by_soil.begin(), by_soil.end(), [&](const Stroke& s) { return s.soil == k.soil; }))
      by_soil.push_back(k);
  }
  std::ostringstream body;
  body << "set multiplot layout 1,2 title 'Force against penetration over the stroke at " << speed << " m/s'\n"
       << "set key bottom right\nset xlabel 'penetration [mm]'\nset ylabel 'force [N]'\nset xrange [0:*]\nset yrange [0:*]\n"
       << "set title " << io::GnuplotQuote("(a) footpad shape, " + io::SoilDisplayName(main_soil)) << "\n" << StrokePlot(by_pad, "", true)
       << "set title " << io::GnuplotQuote("(b) ground condition, " + first_pad + " pad") << "\n"
       << StrokePlot(by_soil, "", true) << "unset multiplot\n";
  return io::Figure("plots/fig6_force_penetration", body.str(), io::kFigureStrip);
}

// `colour` ("#rrggbb") mixed with white: weight 1 keeps it, 0 is white.
int Shade(const std::string& colour, double weight) {
  const int rgb = std::stoi(colour.substr(1), nullptr, 16);
  int out = 0;
  for (int shift : {16, 8, 0}) {
    const int c = (rgb >> shift) & 0xff;
    out |= static_cast<int>(std::lround(255 - weight * (255 - c))) << shift;
  }
  return out;
}

// Soils drawn hatched in Fig. 4: all but the loosely packed (io::SoilDash's solid line).
bool Hatched(const std::string& soil) { return io::SoilDash(soil) != 1; }

// Fig. 4: a bar per case and speed, grouped by case, in the pad's colour (lighter for slower
// drops); plots/data/peaks.csv holds x, peak force, final penetration and the bar's colour.
std::string Peaks(const CampaignResult& r, const fs::path& dir) {
  std::vector<double> speeds;
  std::vector<std::pair<std::string, std::string>> cases;  // (pad, soil)
  for (const CampaignCase& c : r.scenario.cases) {
    if (std::none_of(speeds.begin(), speeds.end(), [&](double v) { return SameSpeed(v, c.conditions.impact_speed_m_s); }))
      speeds.push_back(c.conditions.impact_speed_m_s);
    const std::pair<std::string, std::string> key{c.pad->name, c.soil.name};
    if (std::find(cases.begin(), cases.end(), key) == cases.end()) cases.push_back(key);
  }
  std::sort(speeds.begin(), speeds.end());
  if (cases.empty()) return io::Figure("plots/fig4_peaks", io::PlaceholderPlot("no drop to plot"));
  const double width = 0.8 / static_cast<double>(speeds.size());
  auto weight = [&](size_t k) { return speeds.size() == 1 ? 1.0 : 0.35 + 0.65 * k / (speeds.size() - 1.0); };
  io::WriteFileAtomically((dir / "plots" / "data" / "peaks.csv").string(), [&](std::ostream& out) {
    out << "x,case,speed_m_s,peak_force_N,final_penetration_mm,colour,hatched\n";
    for (size_t i = 0; i < cases.size(); ++i)
      for (size_t k = 0; k < speeds.size(); ++k)
        for (size_t j = 0; j < r.scenario.cases.size(); ++j) {
          const CampaignCase& c = r.scenario.cases[j];
          if (c.pad->name != cases[i].first || c.soil.name != cases[i].second ||
              !SameSpeed(c.conditions.impact_speed_m_s, speeds[k]))
            continue;
          out << io::FormatNumber(i + (k - 0.5 * (speeds.size() - 1.0)) * width) << ',' << c.drop_id << ','
              << io::FormatNumber(speeds[k]) << ',' << io::FormatNumber(r.drops[j].result.peak_force_N) << ','
              << io::FormatNumber(r.drops[j].result.final_penetration_m * units::kMmPerM) << ','
              << Shade(io::PadColour(c.pad->name), weight(k)) << ',' << (Hatched(c.soil.name) ? 1 : 0) << '\n';
        }
  });
  std::ostringstream tics, key;
  tics << "set xtics (";
  for (size_t i = 0; i < cases.size(); ++i)
    tics << (i ? ", " : "") << io::GnuplotQuote(cases[i].first + " / " + io::SoilDisplayName(cases[i].second)) << " " << i;
  tics << ")\n";
  // The key names what the hatching means (the soils); colour (the pad) is in the tics, and each
  // bar carries its own speed, so no swatch stands for a colour no bar has.
  std::vector<std::string> soils;
  for (const auto& c : cases)
    if (std::find(soils.begin(), soils.end(), c.second) == soils.end()) soils.push_back(c.second);
  if (soils.size() > 1)
    for (const std::string& soil : soils)
      key << ", \\\n     NaN with boxes " << (Hatched(soil) ? "fs transparent pattern 4 lc rgb '#000000'" : "fs empty lc rgb '#303030'")
          << " title " << io::GnuplotQuote(io::SoilDisplayName(soil) + (Hatched(soil) ? " (hatched)" : ""));
  auto panel = [&](int column) {
    std::ostringstream p;
    p << "plot 'plots/data/peaks.csv' skip 1 using 1:" << column << ":6 with boxes lc rgb variable notitle, \\\n"
      << "     '' skip 1 using 1:($7 > 0 ? $" << column << " : 1/0) with boxes fs transparent pattern 4 lc rgb '#000000' notitle, \\\n"
      << "     '' skip 1 using 1:" << column << ":(sprintf('%g', $3)) with labels offset 0,0.8 font ',12' notitle" << key.str() << "\n";
    return p.str();
  };
  std::ostringstream body;
  body << "set multiplot layout 2,1 title 'Peak force and final penetration per case (colour: the pad; lighter and "
          "labelled on top: impact speed [m/s])'\n"
       << "set lmargin 12\nset rmargin 4\nset style fill solid 1 border lc rgb '#303030'\nset boxwidth " << width * 0.95
       << "\nset key inside left top opaque Left reverse\n" << tics.str() << "set xrange [-0.6:" << cases.size() - 0.4
       << "]\nset yrange [0:*]\nset offsets 0, 0, graph 0.15, 0\nset ylabel 'peak force [N]'\n" << panel(4)
       << "unset key\nset ylabel 'final penetration [mm]'\n" << panel(5) << "unset multiplot\n";
  return io::Figure("plots/fig4_peaks", body.str());
}

// Each paper check: the simulated ratio (bar) beside the paper's experiment (filled circle) and
// its RFT (open triangle) where the paper gives them.
std::string PaperChecks(const CampaignResult& r, const fs::path& dir) {
  const std::vector<CheckOutcome> checks = EvaluateChecks(r);
  if (checks.empty()) return io::Figure("plots/fig7_paper_checks", io::PlaceholderPlot("the scenario has no paper check"));
  io::WriteFileAtomically((dir / "plots" / "data" / "paper_checks.csv").string(), [&](std::ostream& out) {
    out << "x,check,simulated,paper_experiment,paper_rft\n";
    for (size_t i = 0; i < checks.size(); ++i) {
      const PaperCheck& c = checks[i].check;
      auto number = [](double v) { return v > 0.0 ? io::FormatNumber(v) : std::string("NaN"); };
      out << i << ',' << c.name << ',' << io::FormatNumber(checks[i].simulated) << ',' << number(c.paper_experiment)
          << ',' << number(c.paper_rft) << '\n';
    }
  });
  double top = 0.0;  // the frame holds every bar and mark
  for (const CheckOutcome& c : checks)
    for (double v : {c.simulated, c.check.paper_experiment, c.check.paper_rft}) top = std::max(top, std::isfinite(v) ? v : 0.0);
  std::ostringstream tics;
  tics << "set xtics (";
  for (size_t i = 0; i < checks.size(); ++i)
    tics << (i ? ", " : "") << io::GnuplotQuote(io::Words(checks[i].check.name)) << " " << i;
  tics << ")\n";
  std::ostringstream body;
  body << "set title 'Paper checks: ratios of final penetration, simulated and published'\n" << tics.str()
       << "set xrange [-0.6:" << checks.size() - 0.4 << "]\nset yrange [0:" << 1.3 * top << "]\nset ylabel 'ratio'\n"
       << "set style fill solid 1 border lc rgb '#303030'\nset boxwidth 0.5\n" << io::kKeyBelow
       << "set bars 3\n"
       // The experiment's marks carry +-10 % bars: the band the parity plots draw, so a reader
       // sees whether a bar is within it without a table.
       << "plot 'plots/data/paper_checks.csv' skip 1 using 1:3 with boxes lc rgb '" << io::kSimulatedColour
       << "' title 'touchdown (simulated)', \\\n     '' skip 1 using 1:4:($4*0.9):($4*1.1) with yerrorbars lw 2 pt 7 ps 3 lc rgb '#000000'"
       << " title 'paper: experiment, +-10 %', \\\n     '' skip 1 using 1:5 with points pt 8 ps 3.5 lw 2.5 lc rgb '#000000' title 'paper: RFT'\n";
  return io::Figure("plots/fig7_paper_checks", body.str(), io::kFigureStrip);
}
}  // namespace

void WriteCampaignPlots(const CampaignResult& r, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots" / "data");
  std::ostringstream speed;
  speed << std::setprecision(3) << r.scenario.reference_speed_m_s;
  const std::vector<Stroke> strokes = DenseStrokes(r, dir);
  const std::string gp = TimeHistories(strokes, speed.str()) + Peaks(r, dir) +
                         ForcePenetration(r, strokes, speed.str()) + PaperChecks(r, dir);
  io::RenderPlots(dir, {"plots/campaign.gp", gp,
                        {io::FigurePng("plots/fig3_time_histories"), io::FigurePng("plots/fig4_peaks"),
                         io::FigurePng("plots/fig6_force_penetration"), io::FigurePng("plots/fig7_paper_checks")}});
}

}  // namespace touchdown::scenario
