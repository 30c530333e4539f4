#include "drop_tests/scenario/campaign_plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "drop_tests/io/output_path.h"
#include "drop_tests/io/plot_runner.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
struct Line {
  std::string trace;  // path relative to the output directory
  std::string title;
  double t_stop_s;
};

// One gnuplot `plot` command over traces; `columns` gives the using-clause of a line.
std::string PlotLines(const std::vector<Line>& lines, const std::function<std::string(const Line&)>& columns) {
  if (lines.empty()) return io::PlaceholderPlot("no drop to plot");
  std::ostringstream s;
  s << "plot ";
  for (size_t i = 0; i < lines.size(); ++i)
    s << (i ? ", \\\n     " : "") << io::GnuplotQuote(lines[i].trace) << " using " << columns(lines[i])
      << " with lines lw 2 title " << io::GnuplotQuote(lines[i].title);
  return s.str() + "\n";
}

std::string Header(const std::string& png, int width, int height) {
  std::ostringstream s;
  s << "set terminal pngcairo size " << width << "," << height << " font 'sans,10'\n"
    << "set output 'plots/" << png << "'\nset termoption noenhanced\nset grid\nset key top right\n"
    << "set datafile separator ','\nset autoscale\nunset xlabel\nunset ylabel\nunset title\n";
  return s.str();
}

bool SameSpeed(double a, double b) { return std::abs(a - b) < 1e-9; }

// Fig. 3: force and penetration against time of every case at the reference speed.
std::string TimeHistories(const std::vector<Line>& reference, const std::string& speed) {
  double t_stop_max = 0.0;
  for (const Line& l : reference) t_stop_max = std::max(t_stop_max, l.t_stop_s);
  std::ostringstream gp;
  gp << Header("fig3_time_histories.png", 1000, 800) << "set multiplot layout 2,1 title 'Time histories at "
     << speed << " m/s (t = 0 at touchdown)'\n"
     << "set xrange [0:" << 1.6 * t_stop_max * 1000 << "]\nset xlabel 't [ms]'\nset ylabel 'force on pad [N]'\n"
     << PlotLines(reference, [](const Line&) { return std::string("($1*1000):4"); })
     << "set ylabel 'penetration [mm]'\nset yrange [*:*] reverse\n"
     << PlotLines(reference, [](const Line&) { return std::string("($1*1000):($2*1000)"); })
     << "set yrange [*:*] noreverse\nunset multiplot\n";
  return gp.str();
}

// Fig. 4: peak force and final penetration per case (rows) and speed (columns), from
// plots/peaks.csv, which it writes.
std::string Peaks(const std::vector<drop::PadDrop>& drops, const fs::path& dir) {
  std::vector<double> speeds;
  std::vector<std::string> cases;
  for (const drop::PadDrop& d : drops) {
    bool seen = false;
    for (double v : speeds) seen |= SameSpeed(v, d.conditions.impact_speed_m_s);
    if (!seen) speeds.push_back(d.conditions.impact_speed_m_s);
    const std::string c = d.pad.name + "/" + d.soil.name;
    if (std::find(cases.begin(), cases.end(), c) == cases.end()) cases.push_back(c);
  }
  io::WriteFileAtomically((dir / "plots" / "peaks.csv").string(), [&](std::ostream& out) {
    out << std::setprecision(10) << "case";
    for (double v : speeds) out << ",peak_force_N@" << v << ",final_penetration_mm@" << v;
    out << '\n';
    for (const std::string& c : cases) {
      out << c;
      for (double v : speeds) {
        double force = NAN, depth = NAN;
        for (const drop::PadDrop& d : drops)
          if (d.pad.name + "/" + d.soil.name == c && SameSpeed(d.conditions.impact_speed_m_s, v))
            force = d.result.peak_force_N, depth = d.result.final_penetration_m * 1000;
        out << ',' << force << ',' << depth;
      }
      out << '\n';
    }
  });
  std::ostringstream gp;
  gp << Header("fig4_peaks.png", 1000, 800)
     << "set multiplot layout 2,1 title 'Peak force and final penetration per case'\n"
     << "set style data histograms\nset style histogram clustered gap 1\nset style fill solid 0.8 border -1\n"
     << "set key top left\nset xtics rotate by -20\nset yrange [0:*]\nset xrange [-0.6:" << cases.size() - 0.4
     << "]\nset ylabel 'peak force [N]'\n";
  for (const int column : {2, 3}) {  // peak force, final penetration
    if (column == 3) gp << "set ylabel 'final penetration [mm]'\n";
    if (speeds.empty()) {
      gp << io::PlaceholderPlot("no drop to plot");
      continue;
    }
    gp << "plot ";
    for (size_t k = 0; k < speeds.size(); ++k)
      gp << (k ? ", " : "") << "'plots/peaks.csv' skip 1 using " << column + 2 * k << (k ? "" : ":xtic(1)")
         << " title '" << speeds[k] << " m/s'";
    gp << "\n";
  }
  gp << "unset multiplot\nunset style\nset xtics norotate\nset yrange [*:*]\n";
  return gp.str();
}

// Fig. 6: force against penetration at the reference speed: (a) the pads on the most used soil,
// (b) the first pad on each soil. `reference` holds the drops at that speed, in order.
std::string ForcePenetration(const std::vector<drop::PadDrop>& drops, double reference_speed_m_s,
                             const std::vector<Line>& reference, const std::string& speed) {
  std::map<std::string, int> soil_count;
  for (const drop::PadDrop& d : drops)
    if (SameSpeed(d.conditions.impact_speed_m_s, reference_speed_m_s)) ++soil_count[d.soil.name];
  std::string main_soil;
  for (const auto& [soil, n] : soil_count)
    if (main_soil.empty() || n > soil_count[main_soil]) main_soil = soil;
  std::vector<Line> by_pad, by_soil;
  std::map<std::string, bool> soil_seen;
  const std::string first_pad = drops.empty() ? "" : drops.front().pad.name;
  for (size_t i = 0, k = 0; i < drops.size(); ++i) {
    const drop::PadDrop& d = drops[i];
    if (!SameSpeed(d.conditions.impact_speed_m_s, reference_speed_m_s)) continue;
    const Line& line = reference[k++];
    if (d.soil.name == main_soil) by_pad.push_back(line);
    if (d.pad.name == first_pad && !soil_seen[d.soil.name]) by_soil.push_back(line), soil_seen[d.soil.name] = true;
  }
  auto stroke_only = [](const Line& l) {  // force against penetration up to the stop
    std::ostringstream s;
    s << std::setprecision(10) << "($1 <= " << l.t_stop_s << " ? $2*1000 : 1/0):4";
    return s.str();
  };
  std::ostringstream gp;
  gp << Header("fig6_force_penetration.png", 1000, 800)
     << "set multiplot layout 2,1 title 'Force against penetration (RFT stroke at " << speed << " m/s)'\n"
     << "set key top left\nset xlabel 'penetration [mm]'\nset ylabel 'force [N]'\n"
     << "set title " << io::GnuplotQuote("(a) influence of footpad shape, " + main_soil) << "\n"
     << PlotLines(by_pad, stroke_only) << "set title "
     << io::GnuplotQuote("(b) influence of ground condition, " + first_pad + " pad") << "\n"
     << PlotLines(by_soil, stroke_only) << "unset multiplot\n";
  return gp.str();
}
}  // namespace

void WriteCampaignPlots(const std::vector<drop::PadDrop>& drops, const std::vector<std::string>& drop_ids,
                        double reference_speed_m_s, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots");
  std::vector<Line> reference;  // every case at the reference speed
  for (size_t i = 0; i < drops.size(); ++i) {
    const drop::PadDrop& d = drops[i];
    if (!SameSpeed(d.conditions.impact_speed_m_s, reference_speed_m_s)) continue;
    reference.push_back({"traces/" + drop_ids[i] + ".csv", d.pad.name + ", " + d.soil.name, d.result.time_to_rest_s});
  }
  std::ostringstream speed;
  speed << std::setprecision(3) << reference_speed_m_s;
  const std::string gp = TimeHistories(reference, speed.str()) + Peaks(drops, dir) +
                         ForcePenetration(drops, reference_speed_m_s, reference, speed.str());
  io::RenderPlots(dir, {"plots/campaign.gp", gp,
                    {"plots/fig3_time_histories.png", "plots/fig4_peaks.png", "plots/fig6_force_penetration.png"}});
}

}  // namespace touchdown::scenario
