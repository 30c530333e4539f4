#include "drop_tests/scenario/lander_plots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_decimation.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/scenario/lander_leg_load.h"
#include "drop_tests/scenario/lander_trace_columns.h"
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

// A plotted column: a column of trace.csv (LanderTraceColumns, the one definition of the trace) in
// the figure's unit, or a leg's axial force, which is no trace column (it needs the lander's
// geometry, lander_leg_load.h).
struct PlottedColumn {
  const LanderTraceColumn* trace = nullptr;
  double scale = 1.0;  // trace unit -> figure unit
  int leg = -1;        // >= 0: that leg's axial force
};

const LanderTraceColumn* TraceColumn(const std::string& name) {
  for (const LanderTraceColumn& c : LanderTraceColumns())
    if (c.name == name) return &c;
  throw std::logic_error("lander plots: no trace column '" + name + "'");
}

const std::vector<PlottedColumn>& PlottedColumns() {
  static const std::vector<PlottedColumn> columns = [] {
    std::vector<PlottedColumn> c = {
        {TraceColumn("t_s"), units::kMsPerS}, {TraceColumn("roll_deg")}, {TraceColumn("pitch_deg")}, {TraceColumn("tilt_deg")}};
    for (int i = 1; i <= kLegs; ++i) c.push_back({TraceColumn("depth" + std::to_string(i) + "_m"), units::kMmPerM});
    for (int i = 1; i <= kLegs; ++i) c.push_back({TraceColumn("force" + std::to_string(i) + "_N")});
    for (int i = 0; i < kLegs; ++i) c.push_back({nullptr, 1.0, i});
    c.push_back({TraceColumn("az_m_s2")});
    if (c.size() != kColumns) throw std::logic_error("lander plots: the column list and kColumns disagree");
    return c;
  }();
  return columns;
}

double RawPlottedValue(const LanderSpec& lander, const lander::LanderSample& s, size_t column) {
  const PlottedColumn& c = PlottedColumns()[column];
  if (c.leg >= 0) return LegAxialForce(lander, s, c.leg);
  return c.scale == 1.0 ? c.trace->value(s) : c.trace->value(s) * c.scale;
}

// Values within rounding of zero (1e-9 of the plotted unit: a body at rest shows a_z ~ 4e-14)
// drawn as zero, so they do not read as a signal of either sign.
double Snap(double v) { return std::abs(v) < 1e-9 ? 0.0 : v; }

double PlottedValue(const LanderSpec& lander, const lander::LanderSample& s, size_t column) {
  return column == 0 ? RawPlottedValue(lander, s, column) : Snap(RawPlottedValue(lander, s, column));
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
  if (!std::isfinite(first)) return {0.0, last * units::kMsPerS};  // never touched down: the whole run
  const double span = std::max(last - first, 1e-3);
  const double end = r.trace.empty() ? last : r.trace.back().t_s;
  return {std::max(0.0, first - 0.1 * span) * units::kMsPerS, std::min(end, last + 0.25 * span) * units::kMsPerS};
}

// The columns' values inside the window, per column (row order).
std::vector<std::vector<double>> InWindow(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace,
                                          const Window& w, size_t first_column, size_t count) {
  std::vector<std::vector<double>> v(count);
  for (const lander::LanderSample& s : trace) {
    const double t = s.t_s * units::kMsPerS;
    if (t < w.from_ms || t > w.to_ms) continue;
    for (size_t c = 0; c < count; ++c) v[c].push_back(PlottedValue(lander, s, first_column + c));
  }
  return v;
}

// [lo:hi] of the given columns' values inside the window and of `include` (a paper's band edge
// must be on the scale), widened to at least `min_span` about its middle (so rounding noise on a
// quantity that stays zero does not fill the frame).
std::string Range(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace, const Window& w, size_t first_column,
                  size_t count, double min_span, double pad_fraction = 0.08, const std::vector<double>& include = {}) {
  double lo = INFINITY, hi = -INFINITY;
  for (const std::vector<double>& column : InWindow(lander, trace, w, first_column, count))
    for (double v : column) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  for (double v : include) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) lo = hi = 0.0;
  const double mid = 0.5 * (lo + hi), half = std::max(0.5 * (hi - lo) * (1.0 + pad_fraction), 0.5 * min_span);
  std::ostringstream s;
  s << std::setprecision(6) << "[" << mid - half << ":" << mid + half << "]";
  return s.str();
}

// "pads 1 and 3 coincide; pads 2 and 4 coincide" for the pads whose traces (columns first_column
// .. +kLegs) stay within 1 % of the largest value of any pad of each other over the window, ""
// when none do: a pad drawn exactly over another would otherwise look missing.
std::string CoincidentPads(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace, const Window& w,
                           size_t first_column) {
  const std::vector<std::vector<double>> v = InWindow(lander, trace, w, first_column, kLegs);
  double scale = 0.0;
  for (const std::vector<double>& column : v)
    for (double x : column) scale = std::max(scale, std::abs(x));
  const double tolerance = 1e-2 * scale;
  auto same = [&](int a, int b) {
    for (size_t k = 0; k < v[a].size(); ++k)
      if (std::abs(v[a][k] - v[b][k]) > tolerance) return false;
    return !v[a].empty();
  };
  std::array<bool, kLegs> grouped{};
  std::string note;
  for (int a = 0; a < kLegs; ++a) {
    if (grouped[a]) continue;
    std::vector<int> group{a};
    for (int b = a + 1; b < kLegs; ++b)
      if (!grouped[b] && same(a, b)) group.push_back(b);
    if (group.size() < 2) continue;
    std::string names;
    for (size_t k = 0; k < group.size(); ++k) {
      grouped[group[k]] = true;
      names += (k == 0 ? "" : k + 1 == group.size() ? " and " : ", ") + std::to_string(group[k] + 1);
    }
    note += (note.empty() ? "" : "; ") + std::string("pads ") + names + " coincide";
  }
  return note;
}

// Every `mark_every` rows, a little more for each later series, so two series that coincide
// show their marks at different places.
int MarkInterval(int mark_every, int series) { return mark_every + series * std::max(1, mark_every / 3); }

// "roll and pitch coincide" (and the like) for the attitude angles that stay within 0.5 % of the
// largest angle of each other over the window.
std::string CoincidentAngles(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace, const Window& w) {
  const std::vector<std::vector<double>> v = InWindow(lander, trace, w, 1, 3);
  double scale = 0.0;
  for (const std::vector<double>& column : v)
    for (double x : column) scale = std::max(scale, std::abs(x));
  auto same = [&](int a, int b) {
    for (size_t k = 0; k < v[a].size(); ++k)
      if (std::abs(v[a][k] - v[b][k]) > 5e-3 * scale) return false;
    return !v[a].empty() && scale > 0.0;
  };
  if (same(0, 1)) return same(1, 2) ? "roll, pitch and tilt coincide" : "roll and pitch coincide";
  if (same(1, 2)) return "pitch and tilt coincide (no roll)";
  if (same(0, 2)) return "roll and tilt coincide (no pitch)";
  return "";
}

// The pads in order, pad 1 widest and each later one narrower and differently dashed, with its
// own marks every `mark_every` rows: pads that coincide show as nested lines, not as one.
std::string PerPad(int column, const LanderRun& run, int mark_every) {
  std::ostringstream s;
  s << "plot ";
  for (int i = 0; i < kLegs; ++i)
    s << (i ? ", \\\n     " : "") << "'plots/data/trace.csv' skip 1 using 1:" << column + i << " with linespoints "
      << io::LanderPadLine(i) << " pt " << io::LanderPadPoint(i) << " ps 1.4 pi " << MarkInterval(mark_every, i) << " title "
      << io::GnuplotQuote("pad " + std::to_string(i + 1) + " (" + io::SoilDisplayName(run.soil_under_pad[i]) + ")");
  return s.str() + "\n";
}

// A dotted vertical line at the rest event, when there is one, named by `rest_label` (a gnuplot
// string literal): the traces break there (plots/data/trace.csv), the state after it being the one
// at rest, not a continuation of the landing. With `captures`, one more at each pad's capture
// before the rest, named in the free space after the rest line: from a capture the pad's force is
// the hold's reaction, and the other pads' speeds, on which their soil forces depend, jump with
// it; at the rest every pad is held and the holds' reactions carry the weight (split by the
// minimum-norm solution of a statically indeterminate support). The jumps at these lines are the
// switches, not a stretch of signal.
std::string EventMarkers(const lander::LanderRunResult& r, const std::string& rest_label = "'at rest'", bool captures = false) {
  const lander::LanderEvent* rest = nullptr;
  for (const lander::LanderEvent& e : r.events)
    if (e.kind == lander::LanderEventKind::kRest) rest = &e;
  if (!rest) return "";
  auto line = [](int id, const std::string& t) {
    return "set arrow " + std::to_string(id) + " from first " + t + ", graph 0 to first " + t +
           ", graph 1 nohead dt 3 lw 1.5 lc rgb '#808080' back\n";
  };
  // The captures before the rest, those at one instant together: one line and one label each,
  // stacked down from the top of the free space after the rest line, the rest's label under them.
  std::vector<std::pair<double, std::vector<int>>> captures_at;
  for (const lander::LanderEvent& e : r.events)
    if (captures && e.kind == lander::LanderEventKind::kCapture && e.t_s < rest->t_s) {
      if (captures_at.empty() || captures_at.back().first != e.t_s) captures_at.push_back({e.t_s, {}});
      captures_at.back().second.push_back(e.leg);
    }
  const std::string t = io::FormatNumber(rest->t_s * units::kMsPerS);
  std::string s;
  double y = 0.9;
  for (const auto& [t_s, legs] : captures_at) {
    std::string pads = legs.size() == 1 ? "pad " : "pads ";
    for (size_t k = 0; k < legs.size(); ++k)
      pads += (k == 0 ? "" : k + 1 == legs.size() ? " and " : ", ") + std::to_string(legs[k] + 1);
    std::ostringstream at;
    at << std::setprecision(5) << t_s * units::kMsPerS;
    const std::string id = std::to_string(10 + legs.front());
    s += line(10 + legs.front(), io::FormatNumber(t_s * units::kMsPerS)) + "set label " + id + " \"" + pads + " held\\nat " + at.str() +
         " ms\" at first " + t + ", graph " + io::FormatNumber(y) + " left offset 0.5,0 textcolor rgb '#606060' front\n";
    y -= 0.22;
  }
  s += line(1, t) + "set label 1 " + rest_label + " at first " + t + ", graph " + io::FormatNumber(std::min(0.5, y - 0.1)) +
       " left offset 0.5,0 textcolor rgb '#606060' front\n";
  return s;
}

// True when a leg pulls (axial force below zero beyond rounding) inside the window.
bool AnyTension(const LanderSpec& lander, const std::vector<lander::LanderSample>& trace, const Window& w) {
  for (const std::vector<double>& column : InWindow(lander, trace, w, 4 + 2 * kLegs, kLegs))
    for (double v : column)
      if (v < 0.0) return true;
  return false;
}

// A note on the panel (which pads coincide), in an opaque box at the upper left, or nothing.
std::string Note(const std::string& note) {
  if (note.empty()) return "unset label 2\n";
  return "set label 2 " + io::GnuplotQuote(note) + " at graph 0.01, graph 0.93 left front boxed\n";
}

struct PlotFrame {
  const LanderRun& run;
  const Window& w;
  std::string xrange;
  int mark_every;
};

std::string PenetrationFigure(const PlotFrame& f) {
  const LanderRun& run = f.run;
  std::ostringstream body;
  body << "set title " << io::GnuplotQuote(run.scenario.name + ": penetration of each pad (lowest point below the surface)")
       << "\nset xlabel 't [ms] (release at 0)'\nset ylabel 'penetration [mm]'\n" << io::kKeyBelow
       << "set style textbox opaque noborder\n" << EventMarkers(run.result)
       << Note(CoincidentPads(run.scenario.lander, run.result.trace, f.w, 4))
       << "set xrange " << f.xrange << "\nset yrange " << Range(run.scenario.lander, run.result.trace, f.w, 4, kLegs, 1.0) << "\n"
       << PerPad(kDepthColumn, run, f.mark_every);
  return io::Figure("plots/penetration", body.str(), io::kFigureStrip);
}

std::string AttitudeFigure(const PlotFrame& f) {
  const LanderRun& run = f.run;
  const double band = run.scenario.paper ? run.scenario.paper->roll_pitch_within_deg : 0.0;
  std::vector<double> include;
  if (band > 0.0) include = {-band, band};
  std::ostringstream body;
  // Tilt first and widest, pitch dashed over it, roll thin with marks on top: where they
  // coincide (a pure pitch makes tilt = |pitch|) each still shows.
  body << "set title " << io::GnuplotQuote(run.scenario.name + ": body attitude (roll > 0 right side down, pitch > 0 nose up)")
       << "\nset xlabel 't [ms] (release at 0)'\nset ylabel 'angle [deg]'\n" << io::kKeyBelow << EventMarkers(run.result)
       << "set style textbox opaque noborder\n" << Note(CoincidentAngles(run.scenario.lander, run.result.trace, f.w)) << "set xrange " << f.xrange
       << "\nset yrange " << Range(run.scenario.lander, run.result.trace, f.w, 1, 3, std::max(2.0, 3.0 * band), 0.15, include)
       << "\nplot 'plots/data/trace.csv' skip 1 using 1:4 with lines lw 7 lc rgb '#b0b0b0' title 'tilt from vertical', \\\n"
       << "     '' skip 1 using 1:3 with linespoints lw 3.5 dt 2 lc rgb '" << io::SeriesColour(1) << "' pt 5 ps 1.3 pi "
       << MarkInterval(f.mark_every, 0) << " title 'pitch', \\\n     '' skip 1 using 1:2 with linespoints lw 1.8 lc rgb '"
       << io::SeriesColour(0) << "' pt 7 ps 1.1 pi " << MarkInterval(f.mark_every, 1) << " title 'roll'";
  if (band > 0.0)
    body << ", \\\n     " << band << " with lines " << io::kPaperBandLine << " title "
         << io::GnuplotQuote("paper: |roll|, |pitch| <= " + io::FormatNumber(band) + " deg") << ", \\\n     "
         << -band << " with lines " << io::kPaperBandLine << " notitle";
  body << "\n";
  return io::Figure("plots/attitude", body.str(), io::kFigureStrip);
}

std::string LoadsFigure(const PlotFrame& f) {
  const LanderRun& run = f.run;
  const LanderSpec& lander = run.scenario.lander;
  const auto& trace = run.result.trace;
  std::ostringstream body;
  // One key for the pads, above the first panel; the panels below share its styles.
  body << "set multiplot layout 3,1 margins 0.09, 0.98, 0.1, 0.87 spacing 0, 0.06 title "
       << io::GnuplotQuote(run.scenario.name + ": loads during the landing (leg force along the leg, compression +)") << "\nset xrange " << f.xrange
       << "\nset key at screen 0.5, screen 0.935 center top horizontal maxrows 1 Left reverse samplen 2 width -2\n"
       << "unset xlabel\nset style textbox opaque noborder\n" << EventMarkers(run.result, "\"at rest:\\nthe holds carry\\nthe weight\"", true)
       << "set ylabel 'soil force [N]'\nset yrange " << Range(lander, trace, f.w, 4 + kLegs, kLegs, 1.0, 0.15) << "\n"
       << Note(CoincidentPads(lander, trace, f.w, 4 + kLegs)) << PerPad(kForceColumn, run, f.mark_every) << "unset key\n";
  // A leg in tension is the model's answer, not noise: the soil resists a pad's withdrawal as the
  // body rebounds (RFT resists motion in any direction, at any speed), so the zero line is drawn
  // and the label says which side is which.
  if (AnyTension(lander, trace, f.w))
    body << "set ylabel \"leg axial force [N]\\n(< 0: tension)\"\nset xzeroaxis lt 1 lw 1 dt 2 lc rgb '#404040'\n";
  else
    body << "set ylabel 'leg axial force [N]'\n";
  body << "set yrange " << Range(lander, trace, f.w, 4 + 2 * kLegs, kLegs, 1.0, 0.15) << "\n"
       << Note(CoincidentPads(lander, trace, f.w, 4 + 2 * kLegs)) << PerPad(kLegColumn, run, f.mark_every)
       << "unset xzeroaxis\nunset label 2\nset xlabel 't [ms] (release at 0)'\nset ylabel \"body a_z [m/s^2]\\n(CoM, vertical, + up)\"\nset yrange "
       << Range(lander, trace, f.w, kColumns - 1, 1, 1.0, 0.15) << "\nplot 'plots/data/trace.csv' skip 1 using 1:"
       << kAccelColumn << " with lines lw 2.5 lc rgb '#000000' notitle\nunset multiplot\n";
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
    // A sample repeated at an event's instant holds the state after the event (a pad captured or
    // released, the lander at rest): a blank line before it breaks the lines there, so the jump
    // is not drawn as a steep stretch of signal.
    double previous_t = NAN;
    for (const size_t k : rows) {
      if (trace[k].t_s == previous_t) out << '\n';
      previous_t = trace[k].t_s;
      for (size_t c = 0; c < kColumns; ++c) out << (c ? "," : "") << io::FormatNumber(value(k, c));
      out << '\n';
    }
  });
  const Window w = ContactWindow(run.result);
  std::ostringstream xrange;
  xrange << std::setprecision(6) << "[" << w.from_ms << ":" << w.to_ms << "]";
  // About a dozen marks per trace across the window, whatever the decimation kept.
  const auto in_window = std::count_if(rows.begin(), rows.end(), [&](size_t k) {
    const double t = trace[k].t_s * units::kMsPerS;
    return t >= w.from_ms && t <= w.to_ms;
  });
  const PlotFrame frame{run, w, xrange.str(), std::max(1, static_cast<int>(in_window / 12))};
  const std::string gp = PenetrationFigure(frame) + AttitudeFigure(frame) + LoadsFigure(frame);
  io::RenderPlots(dir, {"plots/lander.gp", gp,
                        {io::FigurePng("plots/penetration"), io::FigurePng("plots/attitude"),
                         io::FigurePng("plots/loads")}});
}

}  // namespace touchdown::scenario
