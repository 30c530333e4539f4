// The study's figures (drop_tests/formats/plot_runner.h: one script, gnuplot in the output directory,
// every path relative to it): the tip-over map with its p = 0.5 boundary, exceedance curves,
// histograms; each as PNG and SVG. Data files under plots/data/.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <ostream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/stability/study_outputs.h"

namespace touchdown::stability {

namespace {
namespace fs = std::filesystem;
using sweep::DropRecord;

struct Series {
  std::string file;   // relative to the output directory
  std::string style;  // gnuplot `using ... with ...` part
  std::string title;
};

// `plot` of the series that have data, or the placeholder saying there is nothing to show.
std::string PlotCommand(const std::vector<Series>& series, const std::string& nothing) {
  if (series.empty()) return io::PlaceholderPlot(nothing);
  std::string s = "plot ";
  for (size_t i = 0; i < series.size(); ++i)
    s += (i ? ", \\\n     " : "") + io::GnuplotQuote(series[i].file) + " " + series[i].style + " title " +
         io::GnuplotQuote(series[i].title);
  return s + "\n";
}

// The figure `body` in the one style (io::Figure: PNG, checked by the plot runner, and SVG), at
// 1.6 times the given size: the style's fonts are drawn for slides.
std::string Figure(const std::string& base, int width, int height, const std::string& body) {
  return io::Figure(base, body, {width * 8 / 5, height * 8 / 5});
}

class DataWriter {
 public:
  explicit DataWriter(fs::path dir) : dir_(std::move(dir)) {}
  // Writes plots/data/NAME.csv with `rows` lines; returns its path relative to the directory.
  std::string Write(const std::string& name, const std::function<void(std::ostream&)>& rows) {
    const std::string file = "plots/data/" + name + ".csv";
    io::WriteFileAtomically((dir_ / file).string(), rows);
    return file;
  }

 private:
  fs::path dir_;
};

void WriteCell(std::ostream& out, const MapCell& c) {
  out << io::FormatNumber(0.5 * (c.x_low + c.x_high)) << ',' << io::FormatNumber(0.5 * (c.y_low + c.y_high)) << ','
      << io::FormatNumber(0.5 * (c.x_high - c.x_low)) << ',' << io::FormatNumber(0.5 * (c.y_high - c.y_low)) << ','
      << io::FormatNumber(c.probability) << '\n';
}

// The map's cells (boxes centred on the cells): those that hold landings coloured by their
// probability, the empty ones hatched grey, a look no probability has.
void AddCellSeries(const StudySummary& s, DataWriter& data, std::vector<Series>& series) {
  bool any_cell = false, any_empty = false;
  for (const MapCell& c : s.map) (c.landings > 0 ? any_cell : any_empty) = true;
  if (any_cell)
    series.push_back({data.Write("map_cells",
                                 [&](std::ostream& out) {
                                   for (const MapCell& c : s.map)
                                     if (c.landings > 0) WriteCell(out, c);
                                 }),
                      "using 1:2:3:4:5 with boxxyerror fillstyle solid 1.0 noborder linecolor palette", "tip-over probability"});
  if (any_empty)
    series.push_back({data.Write("map_empty_cells",
                                 [&](std::ostream& out) {
                                   for (const MapCell& c : s.map)
                                     if (c.landings == 0) WriteCell(out, c);
                                 }),
                      std::string("using 1:2:3:4 with boxxyerror fillstyle pattern 4 border lc rgb '") + io::kEmptyCellColour +
                          "' lc rgb '" + io::kEmptyCellColour + "'",
                      "no landing in the cell"});
}

// The p = 0.5 boundary: marching squares over the cells' centres (cells without landings break
// it); false when the map never crosses 0.5.
bool AddBoundarySeries(const StudyMap& m, const StudySummary& s, DataWriter& data, std::vector<Series>& series) {
  std::vector<double> p, xc, yc;
  for (const MapCell& c : s.map) p.push_back(c.probability);
  for (int i = 0; i < m.x.bins; ++i) xc.push_back(m.x.low + (i + 0.5) * (m.x.high - m.x.low) / m.x.bins);
  for (int i = 0; i < m.y.bins; ++i) yc.push_back(m.y.low + (i + 0.5) * (m.y.high - m.y.low) / m.y.bins);
  const auto segments = ContourSegments(p, m.x.bins, m.y.bins, xc, yc, 0.5);
  if (segments.empty()) return false;
  series.push_back({data.Write("map_boundary",
                               [&](std::ostream& out) {
                                 for (const auto& seg : segments)
                                   out << io::FormatNumber(seg[0].x) << ',' << io::FormatNumber(seg[0].y) << '\n'
                                       << io::FormatNumber(seg[1].x) << ',' << io::FormatNumber(seg[1].y) << "\n\n";
                               }),
                    "using 1:2 with lines linewidth 3 linecolor rgb 'black'", "p = 0.5 boundary"});
  return true;
}

// Every completed landing at its drawn coordinates: circles stayed up, crosses tipped over.
void AddLandingSeries(const Study& study, const std::vector<DropRecord>& records, DataWriter& data,
                      std::vector<Series>& series) {
  const StudyMap& m = *study.map;
  for (const bool tipped : {false, true}) {
    int64_t n = 0;
    const std::string file = data.Write(tipped ? "map_tipped" : "map_landed", [&](std::ostream& out) {
      for (const DropRecord& r : records)
        if (r.ok && (r.tipped_over == 1.0) == tipped) {
          out << io::FormatNumber(MapCoordinate(study, m.x, r.index)) << ','
              << io::FormatNumber(MapCoordinate(study, m.y, r.index)) << '\n';
          ++n;
        }
    });
    if (n > 0)
      series.push_back({file,
                        tipped ? "using 1:2 with points pointtype 2 pointsize 2 linewidth 3 linecolor rgb 'black'"
                               : "using 1:2 with points pointtype 6 pointsize 1.5 linewidth 2 linecolor rgb 'black'",
                        tipped ? "landing that tipped over" : "landing that stayed up"});
  }
}

std::string MapFigure(const Study& study, const StudySummary& s, const std::vector<DropRecord>& records,
                      DataWriter& data) {
  const StudyMap& m = *study.map;
  std::vector<Series> series;
  AddCellSeries(s, data, series);
  const bool crossing = AddBoundarySeries(m, s, data, series);
  AddLandingSeries(study, records, data, series);
  const std::string title = "Tip-over probability, " + std::to_string(s.landings) + " landings, " +
                            std::to_string(m.x.bins) + " x " + std::to_string(m.y.bins) + " cells" +
                            (crossing ? "" : " (no p = 0.5 crossing)");
  const std::string body =
      "set title " + io::GnuplotQuote(title) + "\nset xlabel " + io::GnuplotQuote(AxisLabel(m.x.param)) +
      "\nset ylabel " + io::GnuplotQuote(AxisLabel(m.y.param)) + "\nset xrange [" + io::FormatNumber(m.x.low) + ":" +
      io::FormatNumber(m.x.high) + "]\nset yrange [" + io::FormatNumber(m.y.low) + ":" + io::FormatNumber(m.y.high) +
      "]\nset cbrange [0:1]\nset cblabel 'tip-over probability'\n"
      // Blue through yellow to red: no probability is white or grey, so an empty cell (hatched
      // grey) never passes for p = 0.5, and the black marks stand out on every colour.
      "set palette defined (0 '#4575b4', 0.25 '#91bfdb', 0.5 '#fee090', 0.75 '#fc8d59', 1 '#d73027')\n" +
      io::kKeyBelow + "set key maxrows 2\n" +
      PlotCommand(series, "no completed landings: nothing to map");
  return Figure("plots/tip_over_map", 900, 750, body);
}

// The exceedance curve of `values` (scaled), points with P > 0 only (log axis); "" when none.
std::string ExceedanceFile(DataWriter& data, const std::string& name, const std::vector<double>& values, double scale) {
  std::vector<ExceedancePoint> curve = Exceedance(values);
  curve.erase(std::remove_if(curve.begin(), curve.end(), [](const ExceedancePoint& e) { return e.probability <= 0; }),
              curve.end());
  if (curve.empty()) return "";
  return data.Write(name, [&](std::ostream& out) {
    for (const ExceedancePoint& e : curve)
      out << io::FormatNumber(e.x * scale) << ',' << io::FormatNumber(e.probability) << '\n';
  });
}

std::vector<double> Values(const std::vector<DropRecord>& records, const std::function<double(const DropRecord&)>& f) {
  std::vector<double> v;
  for (const DropRecord& r : records)
    if (StayedUp(r)) v.push_back(f(r));
  return v;
}

// `set ytics` at whole numbers for a count axis up to `max_count`: a step of 1, 2 or 5 times a
// power of ten giving at most about 8 tics (gnuplot's own choice can be 0.5 landings).
std::string IntegerTics(int64_t max_count) {
  int64_t step = 1;
  for (int64_t decade = 1;; decade *= 10) {
    for (int64_t m : {1, 2, 5})
      if (max_count / (m * decade) <= 8) {
        step = m * decade;
        return "set ytics 0, " + std::to_string(step) + "\nset format y '%.0f'\nset mytics 1\n";
      }
  }
}

// A panel with a logarithmic probability axis; its placeholder (no data) on linear axes, which
// gnuplot needs for an empty frame.
std::string LogPanel(const std::vector<Series>& series, const std::string& nothing) {
  if (series.empty()) return "unset logscale y\nset yrange [*:*]\n" + PlotCommand(series, nothing);
  return "set logscale y\nset yrange [*:1]\n" + PlotCommand(series, nothing);
}

// The curves fall from the upper left to the lower right: the key sits in the empty lower left.
// The deepest pad, drawn first, wide and grey, lies under the pad it equals.
std::string ExceedanceFigure(const StudySummary& s, const std::vector<DropRecord>& records, DataWriter& data) {
  const std::string style = "using 1:2 with steps linewidth 2";
  std::vector<Series> tilt;
  if (const std::string f = ExceedanceFile(data, "exceedance_max_tilt",
                                           Values(records, [](const DropRecord& r) { return r.max_tilt_deg; }), 1.0);
      !f.empty())
    tilt.push_back({f, style + " lc rgb '#000000'", "max tilt"});
  std::vector<Series> depth;
  for (int pad = 0; pad < 4; ++pad) {
    const std::string f =
        ExceedanceFile(data, "exceedance_pad" + std::to_string(pad + 1),
                       Values(records, [pad](const DropRecord& r) { return r.pad_final_penetration_m[pad]; }), 1e3);
    // Pad i in the colour and dash it has in the lander's own figures (lander_plots.cpp).
    if (!f.empty()) depth.push_back({f, "using 1:2 with steps " + io::LanderPadLine(pad), "pad " + std::to_string(pad + 1)});
  }
  if (const std::string f = ExceedanceFile(
          data, "exceedance_deepest_pad", Values(records, [](const DropRecord& r) { return r.final_penetration_m; }), 1e3);
      !f.empty())
    depth.insert(depth.begin(), {f, "using 1:2 with steps linewidth 7 linecolor rgb '#b0b0b0'", "deepest pad"});
  const std::string nothing = "fewer than two distinct values: no exceedance curve";
  const std::string body =
      "set multiplot layout 1,2 title " +
      io::GnuplotQuote("Exceedance probability P[X > x] over the " + std::to_string(s.landings - s.tipped) +
                       " landings that stayed up") +
      "\nset grid\nset key inside bottom left opaque Left reverse\nset ylabel 'P[X > x]'\n"
      "set title 'max tilt'\nset xlabel 'max tilt from the vertical [deg]'\n" + LogPanel(tilt, nothing) +
      "set title 'final pad penetration'\nset xlabel 'final penetration [mm]'\n" + LogPanel(depth, nothing) +
      "unset multiplot\n";
  return Figure("plots/exceedance", 1300, 560, body);
}

std::string HistogramFigure(const StudySummary& s, const std::vector<DropRecord>& records, DataWriter& data) {
  struct Panel {
    std::string name, title, xlabel;
    double scale;
    std::function<double(const DropRecord&)> value;
  };
  const std::vector<Panel> panels = {
      {"hist_max_tilt", "max tilt", "max tilt from the vertical [deg]", 1.0,
       [](const DropRecord& r) { return r.max_tilt_deg; }},
      {"hist_final_tilt", "final tilt", "final tilt from the vertical [deg]", 1.0,
       [](const DropRecord& r) { return r.final_tilt_deg; }},
      {"hist_deepest_pad", "deepest pad's final penetration", "final penetration [mm]", 1e3,
       [](const DropRecord& r) { return r.final_penetration_m; }},
      {"hist_leg_load", "peak axial leg load", "peak leg load (compression) [N]", 1.0,
       [](const DropRecord& r) { return r.peak_leg_force_N; }}};
  const int bins =
      std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(s.landings - s.tipped)))), 5, 50);
  std::string body = "set multiplot layout 2,2 title " +
                     io::GnuplotQuote("Distributions over the " + std::to_string(s.landings - s.tipped) +
                                      " landings that stayed up") +
                     "\nset grid\nset key off\nset ylabel 'landings'\n"
                     "set style fill solid 0.6 border lc rgb '#224466'\n";
  for (const Panel& panel : panels) {
    std::vector<double> v = Values(records, panel.value);
    for (double& x : v) x *= panel.scale;
    const Histogram h = MakeHistogram(v, bins);
    std::vector<Series> series;
    if (!h.counts.empty())
      series.push_back({data.Write(panel.name,
                                   [&](std::ostream& out) {
                                     for (size_t k = 0; k < h.counts.size(); ++k)
                                       out << io::FormatNumber(h.low + (k + 0.5) * h.width) << ',' << h.counts[k]
                                           << ',' << io::FormatNumber(h.width) << '\n';
                                   }),
                        "using 1:2:3 with boxes linecolor rgb '#4477aa'", panel.title});
    const int64_t top = h.counts.empty() ? 1 : std::max<int64_t>(1, *std::max_element(h.counts.begin(), h.counts.end()));
    body += "set title " + io::GnuplotQuote(panel.title) + "\nset xlabel " + io::GnuplotQuote(panel.xlabel) + "\n" +
            (h.counts.empty() ? "set ytics autofreq\nset format y '% h'\nset yrange [*:*]\n"
                              : IntegerTics(top) + "set yrange [0:" + std::to_string(top + std::max<int64_t>(1, top / 10)) + "]\n") +
            PlotCommand(series, "no values");
  }
  return Figure("plots/histograms", 1200, 900, body + "unset multiplot\n");
}
}  // namespace

void WriteStudyPlots(const Study& study, const StudySummary& s, const std::vector<DropRecord>& records,
                     const std::string& dir) {
  fs::create_directories(fs::path(dir) / "plots" / "data");
  DataWriter data(dir);
  std::string script;
  std::vector<std::string> pngs;
  if (study.map) {
    script += MapFigure(study, s, records, data);
    pngs.push_back("plots/tip_over_map.png");
  }
  script += ExceedanceFigure(s, records, data);
  script += HistogramFigure(s, records, data);
  pngs.push_back("plots/exceedance.png");
  pngs.push_back("plots/histograms.png");
  io::RenderPlots(dir, {"plots/study.gp", script, pngs});
}

}  // namespace touchdown::stability
