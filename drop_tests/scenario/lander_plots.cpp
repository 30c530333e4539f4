#include "drop_tests/scenario/lander_plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "drop_tests/io/dataset_csv.h"
#include "drop_tests/io/figure_style.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/io/plot_decimation.h"
#include "drop_tests/io/plot_runner.h"
#include "drop_tests/scenario/lander_leg_load.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
using units::kDeg;
constexpr int kLegs = lander::kNumLegs;
// plots/data/trace.csv: 1 t [ms], 2-4 roll, pitch, tilt [deg], then per pad depth [mm], soil
// force [N], leg axial force [N] (compression +), and last the body's vertical acceleration [m/s^2].
constexpr size_t kColumns = 4 + 3 * kLegs + 1;
constexpr int kDepthColumn = 5, kForceColumn = 5 + kLegs, kLegColumn = 5 + 2 * kLegs, kAccelColumn = 5 + 3 * kLegs;

double PlottedValue(const LanderSpec& lander, const lander::LanderSample& s, size_t column) {
  if (column == 0) return s.t_s * 1e3;
  if (column == 1) return s.attitude.roll_rad / kDeg;
  if (column == 2) return s.attitude.pitch_rad / kDeg;
  if (column == 3) return s.attitude.tilt_rad / kDeg;
  if (column == kColumns - 1) return s.a_WB_W.z();
  const size_t k = column - 4, leg = k % kLegs;
  if (k < kLegs) return s.pad_depth_m[leg] * 1e3;
  if (k < 2 * kLegs) return s.pad_force_W[leg].norm();
  return LegAxialForce(lander, s, static_cast<int>(leg));
}

struct Window {
  double from_ms = 0.0, to_ms = 0.0;
};

// First touchdown to rest, tip-over or the end of the run, with a margin each side: where the
// landing happens (before it the pads are in the air, after it nothing moves).
Window ContactWindow(const lander::LanderRunResult& r) {
  double first = NAN, last = r.trace.empty() ? 0.0 : r.trace.back().t_s;
  for (const lander::LanderEvent& e : r.events) {
    if (e.kind == lander::LanderEventKind::kTouchdown && !(e.t_s >= first)) first = e.t_s;
    if (e.kind == lander::LanderEventKind::kRest || e.kind == lander::LanderEventKind::kTipOver) last = e.t_s;
  }
  if (!std::isfinite(first)) return {0.0, last * 1e3};  // never touched down: the whole run
  const double span = std::max(last - first, 1e-3);
  const double end = r.trace.empty() ? last : r.trace.back().t_s;
  return {std::max(0.0, first - 0.1 * span) * 1e3, std::min(end, last + 0.25 * span) * 1e3};
}

// [lo:hi] of the given columns' values inside the window, widened to at least `min_span` about
// its middle (so rounding noise on a quantity that stays zero does not fill the frame).
std::string Range(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace, const Window& w, size_t first_column,
                  size_t count, double min_span, double pad_fraction = 0.08) {
  double lo = INFINITY, hi = -INFINITY;
  for (const lander::LanderSample& s : trace) {
    const double t = s.t_s * 1e3;
    if (t < w.from_ms || t > w.to_ms) continue;
    for (size_t c = first_column; c < first_column + count; ++c) {
      lo = std::min(lo, PlottedValue(lander, s, c));
      hi = std::max(hi, PlottedValue(lander, s, c));
    }
  }
  if (!(lo <= hi)) lo = hi = 0.0;
  const double mid = 0.5 * (lo + hi), half = std::max(0.5 * (hi - lo) * (1.0 + pad_fraction), 0.5 * min_span);
  std::ostringstream s;
  s << std::setprecision(6) << "[" << mid - half << ":" << mid + half << "]";
  return s.str();
}

std::string PerPad(int column, const std::string& unit_title, const LanderRun& run) {
  std::ostringstream s;
  s << "plot ";
  for (int i = 0; i < kLegs; ++i)
    s << (i ? ", \\\n     " : "") << "'plots/data/trace.csv' skip 1 using 1:" << column + i << " with lines lw 2.5 lc rgb '"
      << io::SeriesColour(i) << "' dt " << io::SoilDash(run.soil_under_pad[i]) << " title "
      << io::GnuplotQuote("pad " + std::to_string(i + 1) + " (" + run.soil_under_pad[i] + ")" + unit_title);
  return s.str() + "\n";
}

std::string PenetrationFigure(const LanderRun& run, const Window& w, const std::string& xrange) {
  std::ostringstream body;
  body << "set title " << io::GnuplotQuote(run.scenario.name + ": penetration of each pad (lowest point below the surface)")
       << "\nset xlabel 't [ms] (release at 0)'\nset ylabel 'penetration [mm]'\nset key outside right top\n"
       << "set xrange " << xrange << "\nset yrange " << Range(run.scenario.lander, run.result.trace, w, 4, kLegs, 1.0) << "\n"
       << PerPad(kDepthColumn, "", run);
  return io::Figure("plots/penetration", body.str(), io::kFigureStrip);
}

std::string AttitudeFigure(const LanderRun& run, const Window& w, const std::string& xrange) {
  const double band = run.scenario.paper ? run.scenario.paper->roll_pitch_within_deg : 0.0;
  std::ostringstream body;
  body << "set title " << io::GnuplotQuote(run.scenario.name + ": body attitude (roll > 0 right side down, pitch > 0 nose up)")
       << "\nset xlabel 't [ms] (release at 0)'\nset ylabel 'angle [deg]'\nset key outside right top\n"
       << "set xrange " << xrange << "\nset yrange " << Range(run.scenario.lander, run.result.trace, w, 1, 3, std::max(2.0, 3.0 * band))
       << "\nplot 'plots/data/trace.csv' skip 1 using 1:2 with lines lw 2.5 lc rgb '" << io::SeriesColour(0)
       << "' title 'roll', \\\n     '' skip 1 using 1:3 with lines lw 2.5 lc rgb '" << io::SeriesColour(1)
       << "' title 'pitch', \\\n     '' skip 1 using 1:4 with lines lw 2 dt 2 lc rgb '" << io::SeriesColour(2)
       << "' title 'tilt from vertical'";
  if (band > 0.0)
    body << ", \\\n     " << band << " with lines " << io::kPaperBandLine << " title "
         << io::GnuplotQuote("paper: roll and pitch within +-" + io::FormatNumber(band) + " deg") << ", \\\n     "
         << -band << " with lines " << io::kPaperBandLine << " notitle";
  body << "\n";
  return io::Figure("plots/attitude", body.str(), io::kFigureStrip);
}

std::string LoadsFigure(const LanderRun& run, const Window& w, const std::string& xrange) {
  std::ostringstream body;
  body << "set multiplot layout 3,1 title " << io::GnuplotQuote(run.scenario.name + ": loads during the landing")
       << "\nset xrange " << xrange << "\nset key outside right top\nunset xlabel\n"
       << "set lmargin 12\nset rmargin 34\n"  // the panels' frames aligned whatever their labels and keys
       << "set ylabel 'soil force on pad [N]'\nset yrange " << Range(run.scenario.lander, run.result.trace, w, 4 + kLegs, kLegs, 1.0, 0.15)
       << "\n" << PerPad(kForceColumn, "", run) << "set ylabel 'leg force [N]'\nset key title 'axial, compression +'\nset yrange "
       << Range(run.scenario.lander, run.result.trace, w, 4 + 2 * kLegs, kLegs, 1.0, 0.15) << "\n" << PerPad(kLegColumn, "", run)
       << "set xlabel 't [ms] (release at 0)'\nset ylabel 'a_z [m/s^2]'\nset key notitle\nset yrange "
       << Range(run.scenario.lander, run.result.trace, w, kColumns - 1, 1, 1.0, 0.15) << "\nplot 'plots/data/trace.csv' skip 1 using 1:"
       << kAccelColumn << " with lines lw 2.5 lc rgb '#000000' title 'body CoM, vertical (+ up)'\nunset multiplot\n";
  return io::Figure("plots/loads", body.str(), io::kFigureWide);
}
}  // namespace

void WriteLanderPlots(const LanderRun& run, const std::string& out_dir) {
  const fs::path dir = out_dir;
  fs::create_directories(dir / "plots" / "data");
  const std::vector<lander::LanderSample>& trace = run.result.trace;
  auto value = [&](size_t row, size_t column) { return PlottedValue(run.scenario.lander, trace[row], column); };
  const std::vector<size_t> rows = io::PlotRowsToKeep(trace.size(), kColumns, value);
  io::WriteFileAtomically((dir / "plots" / "data" / "trace.csv").string(), [&](std::ostream& out) {
    out << "t_ms,roll_deg,pitch_deg,tilt_deg";
    for (const char* what : {"depth_mm", "soil_force_N", "leg_force_N"})
      for (int i = 1; i <= kLegs; ++i) out << ",pad" << i << "_" << what;
    out << ",body_az_m_s2\n";
    for (const size_t k : rows) {
      for (size_t c = 0; c < kColumns; ++c) out << (c ? "," : "") << io::FormatNumber(value(k, c));
      out << '\n';
    }
  });
  const Window w = ContactWindow(run.result);
  std::ostringstream xrange;
  xrange << std::setprecision(6) << "[" << w.from_ms << ":" << w.to_ms << "]";
  const std::string gp = PenetrationFigure(run, w, xrange.str()) + AttitudeFigure(run, w, xrange.str()) +
                         LoadsFigure(run, w, xrange.str());
  io::RenderPlots(dir, {"plots/lander.gp", gp,
                        {io::FigurePng("plots/penetration"), io::FigurePng("plots/attitude"),
                         io::FigurePng("plots/loads")}});
}

}  // namespace touchdown::scenario
