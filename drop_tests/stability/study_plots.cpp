// The study's figures (drop_tests/formats/plot_runner.h: one script, gnuplot in the output directory,
// every path relative to it): the tip-over map (probability on a scale fitted to the cells, the
// study's contours, each cell's interval width beside it), exceedance curves, histograms; each as
// PNG and SVG. Data files under plots/data/. What each shows: docs/stability_studies.md, "Outputs".
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
  std::string file;   // relative to the output directory; "": `style` is the whole series (a key entry: "NaN with ...")
  std::string style;  // gnuplot `using ... with ...` part
  std::string title;  // "": no key entry
};

// `plot` of the series that have data, or the placeholder saying there is nothing to show.
std::string PlotCommand(const std::vector<Series>& series, const std::string& nothing) {
  if (series.empty()) return io::PlaceholderPlot(nothing);
  std::string s = "plot ";
  for (size_t i = 0; i < series.size(); ++i)
    s += (i ? ", \\\n     " : "") + (series[i].file.empty() ? "" : io::GnuplotQuote(series[i].file) + " ") +
         series[i].style + (series[i].title.empty() ? " notitle" : " title " + io::GnuplotQuote(series[i].title));
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

// A cell whose 95 % interval is wider than this says nothing its colour could show: +-0.1, as
// wide as the whole colour scale of the shipped lunar study's map (0 to 0.2), and wide enough to
// hold both 0 and the upper default contour, 0.1 (0 of 17 landings: [0, 0.195]; 0 of 18: 0.185;
// at P = 0.5 up to 103 landings). Such cells are hatched (docs/stability_studies.md).
constexpr double kUnreadableIntervalWidth = 0.2;
// The colour scale turns logarithmic when the cells' positive probabilities span this factor.
constexpr double kLogScaleSpan = 100.0;
// Cells are labelled with their counts when the map has at most this many bins on each axis: a
// label "12/104" needs about 50 pixels, a tenth of a panel.
constexpr int kMaxLabelledBins = 12;

// How the map's colour carries the probability (docs/stability_studies.md, "Outputs"): linear from
// 0 to a round number at or above the highest cell; logarithmic over whole decades when the
// positive cells span kLogScaleSpan or more, cells at P = 0 then drawn apart in their own colour.
struct ColourScale {
  bool log = false;
  double low = 0.0, high = 1.0;
};

ColourScale FitColourScale(const std::vector<MapCell>& cells) {
  double lowest = INFINITY, highest = 0.0;
  for (const MapCell& c : cells)
    if (c.landings > 0 && c.probability > 0.0) {
      lowest = std::min(lowest, c.probability);
      highest = std::max(highest, c.probability);
    }
  if (highest == 0.0) return {};  // no tip-over in any cell: nothing to fit, the full [0, 1]
  if (highest / lowest >= kLogScaleSpan)
    return {true, io::PowerOfTen(static_cast<int>(std::floor(std::log10(lowest) + 1e-9))),
            std::min(1.0, io::PowerOfTen(static_cast<int>(std::ceil(std::log10(highest) - 1e-9))))};
  return {false, 0.0, std::min(1.0, io::RoundScaleTop(highest))};
}

// The cells `keep` selects, as boxes centred on them: x, y, half widths, `value`; "" (and no
// file) when it selects none.
std::string CellFile(DataWriter& data, const std::string& name, const std::vector<MapCell>& cells,
                     const std::function<bool(const MapCell&)>& keep, const std::function<double(const MapCell&)>& value) {
  if (std::none_of(cells.begin(), cells.end(), keep)) return "";
  return data.Write(name, [&](std::ostream& out) {
    for (const MapCell& c : cells)
      if (keep(c))
        out << io::FormatNumber(0.5 * (c.x_low + c.x_high)) << ',' << io::FormatNumber(0.5 * (c.y_low + c.y_high)) << ','
            << io::FormatNumber(0.5 * (c.x_high - c.x_low)) << ',' << io::FormatNumber(0.5 * (c.y_high - c.y_low)) << ','
            << io::FormatNumber(value(c)) << '\n';
  });
}

// The cells `keep` selects hatched: in each, five parallel segments across it (u - v = -2/3 ...
// 2/3 in the cell's unit square), one block per segment; "" (and no file) when it selects none.
// Drawn as lines: gnuplot's pattern fill took a second per figure for a hundred cells.
std::string HatchFile(DataWriter& data, const std::string& name, const std::vector<MapCell>& cells,
                      const std::function<bool(const MapCell&)>& keep) {
  if (std::none_of(cells.begin(), cells.end(), keep)) return "";
  return data.Write(name, [&](std::ostream& out) {
    for (const MapCell& c : cells) {
      if (!keep(c)) continue;
      const auto point = [&](double u, double v) {
        out << io::FormatNumber(c.x_low + u * (c.x_high - c.x_low)) << ','
            << io::FormatNumber(c.y_low + v * (c.y_high - c.y_low)) << '\n';
      };
      for (const double k : {-2.0, -1.0, 0.0, 1.0, 2.0}) {
        const double offset = k / 3.0;
        point(std::max(offset, 0.0), std::max(-offset, 0.0));
        point(std::min(1.0 + offset, 1.0), std::min(1.0 - offset, 1.0));
        out << '\n';
      }
    }
  });
}

double IntervalWidth(const MapCell& c) { return c.interval.high - c.interval.low; }
bool Unreadable(const MapCell& c) { return c.landings > 0 && IntervalWidth(c) > kUnreadableIntervalWidth; }

// Cells as boxes (CellFile's columns), plain or coloured by their value on the palette.
const std::string kBoxes = "using 1:2:3:4 with boxxyerror ";
const std::string kColouredBoxes = "using 1:2:3:4:5 with boxxyerror fillstyle solid 1.0 noborder linecolor palette";

// Contour k of `levels` (increasing): black, the highest level solid and widest, each lower one
// dashed and narrower, so the lines stay apart where they run close.
std::string ContourLine(size_t k, size_t levels) {
  return "lw " + io::FormatNumber(2.0 + 0.75 * static_cast<double>(k)) + " dt " + std::to_string(levels - k) +
         " lc rgb '#000000'";
}
// Under each contour a white casing, so a black line reads on the darkest cells too.
std::string ContourCasing(size_t k) {
  return "lw " + io::FormatNumber(5.0 + 0.75 * static_cast<double>(k)) + " lc rgb '#ffffff'";
}

std::string LevelName(double level) { return "P = " + io::FormatNumber(level); }

// The `level` contour: marching squares over the cells' centres (cells without landings break it);
// "" when the map never crosses it.
std::string ContourFile(const StudyMap& m, const StudySummary& s, size_t k, DataWriter& data) {
  std::vector<double> p, xc, yc;
  for (const MapCell& c : s.map) p.push_back(c.probability);
  for (int i = 0; i < m.x.bins; ++i) xc.push_back(m.x.low + (i + 0.5) * (m.x.high - m.x.low) / m.x.bins);
  for (int i = 0; i < m.y.bins; ++i) yc.push_back(m.y.low + (i + 0.5) * (m.y.high - m.y.low) / m.y.bins);
  const auto segments = ContourSegments(p, m.x.bins, m.y.bins, xc, yc, m.contours[k]);
  if (segments.empty()) return "";
  return data.Write("map_contour_" + std::to_string(k + 1), [&](std::ostream& out) {
    for (const auto& seg : segments)
      out << io::FormatNumber(seg[0].x) << ',' << io::FormatNumber(seg[0].y) << '\n'
          << io::FormatNumber(seg[1].x) << ',' << io::FormatNumber(seg[1].y) << "\n\n";
  });
}

// The completed landings that tipped over (or stayed up) at their drawn coordinates, as marks;
// "" when there are none or more than the map's max_drawn_landings (`total`: the count that
// decides, the study's landings for the circles, its tip-overs for the crosses).
std::string LandingFile(const Study& study, const std::vector<DropRecord>& records, bool tipped, int64_t total,
                        DataWriter& data) {
  const StudyMap& m = *study.map;
  if (total == 0 || total > m.max_drawn_landings) return "";
  return data.Write(tipped ? "map_tipped" : "map_landed", [&](std::ostream& out) {
    for (const DropRecord& r : records)
      if (r.ok && Tipped(r) == tipped)
        out << io::FormatNumber(MapCoordinate(study, m.x, r.index)) << ','
            << io::FormatNumber(MapCoordinate(study, m.y, r.index)) << '\n';
  });
}

// Tip-overs as black crosses, landings that stayed up as black circles: on top of every colour.
constexpr const char* kTippedMarks = "pointtype 2 pointsize 2 linewidth 3 linecolor rgb '#000000'";
constexpr const char* kLandedMarks = "pointtype 6 pointsize 1.2 linewidth 1.5 linecolor rgb '#000000'";

// Everything the map figure draws, written once: the left panel's cells and lines, the right
// panel's widths and labels, the marks, and what the key and note say about them.
struct MapParts {
  ColourScale scale;
  std::string cells, zero_cells, empty_cells, unreadable_cells, widths, labels, landed, tipped;
  std::vector<std::string> contours;  // per level; "" where the map does not cross it
  double widest = 0.0;                // the widest interval of a cell with landings
};

MapParts WriteMapParts(const Study& study, const StudySummary& s, const std::vector<DropRecord>& records,
                       DataWriter& data) {
  const StudyMap& m = *study.map;
  MapParts p;
  p.scale = FitColourScale(s.map);
  const auto probability = [](const MapCell& c) { return c.probability; };
  const auto positive_on_scale = [&](const MapCell& c) { return c.landings > 0 && (!p.scale.log || c.probability > 0.0); };
  p.cells = CellFile(data, "map_cells", s.map, positive_on_scale, probability);
  if (p.scale.log)
    p.zero_cells = CellFile(data, "map_zero_cells", s.map, [](const MapCell& c) { return c.landings > 0 && c.probability == 0.0; },
                            probability);
  p.empty_cells = CellFile(data, "map_empty_cells", s.map, [](const MapCell& c) { return c.landings == 0; }, probability);
  p.unreadable_cells = HatchFile(data, "map_unreadable_cells", s.map, Unreadable);
  p.widths = CellFile(data, "map_interval_widths", s.map, [](const MapCell& c) { return c.landings > 0; }, IntervalWidth);
  for (const MapCell& c : s.map)
    if (c.landings > 0) p.widest = std::max(p.widest, IntervalWidth(c));
  if (m.x.bins <= kMaxLabelledBins && m.y.bins <= kMaxLabelledBins)
    p.labels = data.Write("map_cell_counts", [&](std::ostream& out) {
      for (const MapCell& c : s.map)
        if (c.landings > 0)
          out << io::FormatNumber(0.5 * (c.x_low + c.x_high)) << ',' << io::FormatNumber(0.5 * (c.y_low + c.y_high)) << ','
              << c.tipped << '/' << c.landings << '\n';
    });
  for (size_t k = 0; k < m.contours.size(); ++k) p.contours.push_back(ContourFile(m, s, k, data));
  p.landed = LandingFile(study, records, false, s.landings, data);
  p.tipped = LandingFile(study, records, true, s.tipped, data);
  return p;
}

// The looks of the cells that show no probability: empty (grey hatching, both panels), at P = 0 on
// a log scale (pale), too thin to read (thin black hatching across the other diagonal, over the
// colour, which shows between its lines; its key entry a pattern of the same look).
const std::string kEmptyFill = std::string("fillstyle pattern 4 border lc rgb '") + io::kEmptyCellColour + "' lc rgb '" +
                               io::kEmptyCellColour + "'";
const std::string kZeroFill = std::string("fillstyle solid 1.0 noborder lc rgb '") + io::kZeroCellColour + "'";
const std::string kUnreadableHatch = "using 1:2 with lines lw 1 lc rgb '#000000'";
const std::string kUnreadableKey = "fillstyle transparent pattern 5 noborder lc rgb '#000000'";

// The layers both panels draw over their colour: the empty cells and the cells too thin to read.
void AddSharedLayers(const MapParts& p, std::vector<Series>& series) {
  if (!p.empty_cells.empty()) series.push_back({p.empty_cells, kBoxes + kEmptyFill, ""});
  if (!p.unreadable_cells.empty()) series.push_back({p.unreadable_cells, kUnreadableHatch, ""});
}

// A map panel's frame, between screen fractions `left` and `right`: both panels the same height,
// room between them for the left one's colour box and its label.
std::string MapFrame(double left, double right) {
  return "set lmargin at screen " + io::FormatNumber(left) + "\nset rmargin at screen " + io::FormatNumber(right) +
         "\nset bmargin at screen 0.28\nset tmargin at screen 0.88\n";
}

// The left panel: the probability in colour, the contours, the tip-overs and (few) landings on top.
std::string ProbabilityPanel(const MapParts& p) {
  std::vector<Series> series;
  if (!p.cells.empty()) series.push_back({p.cells, kColouredBoxes, ""});
  if (!p.zero_cells.empty()) series.push_back({p.zero_cells, kBoxes + kZeroFill, ""});
  AddSharedLayers(p, series);
  for (size_t k = 0; k < p.contours.size(); ++k)
    if (!p.contours[k].empty()) {
      series.push_back({p.contours[k], "using 1:2 with lines " + ContourCasing(k), ""});
      series.push_back({p.contours[k], "using 1:2 with lines " + ContourLine(k, p.contours.size()), ""});
    }
  if (!p.landed.empty()) series.push_back({p.landed, std::string("using 1:2 with points ") + kLandedMarks, ""});
  if (!p.tipped.empty()) series.push_back({p.tipped, std::string("using 1:2 with points ") + kTippedMarks, ""});
  const ColourScale& c = p.scale;
  const std::string scale = c.log ? "set logscale cb\nset cbrange [" + io::FormatNumber(c.low) + ":" + io::FormatNumber(c.high) +
                                        "]\nset format cb '%g'\n"
                                  : "unset logscale cb\nset format cb '% h'\nset cbrange [0:" + io::FormatNumber(c.high) + "]\n";
  const std::string title = std::string("tip-over probability (") + (c.log ? "logarithmic" : "linear") + " colour scale)";
  return MapFrame(0.07, 0.39) + "set title " + io::GnuplotQuote(title) + "\n" + scale +
         "set cblabel 'tip-over probability'\n"
         // Blue through yellow to red: no probability is white or grey, so an empty cell (hatched
         // grey) or a cell at P = 0 on a log scale (pale) never passes for a probability.
         "set palette defined (0 '#4575b4', 0.25 '#91bfdb', 0.5 '#fee090', 0.75 '#fc8d59', 1 '#d73027')\n" +
         PlotCommand(series, "no completed landings: nothing to map");
}

// The right panel: how far each cell's probability can be trusted (its 95 % interval's width,
// white for none) and, on maps of few cells, its counts.
std::string IntervalPanel(const MapParts& p) {
  std::vector<Series> series;
  if (!p.widths.empty()) series.push_back({p.widths, kColouredBoxes, ""});
  AddSharedLayers(p, series);
  if (!p.labels.empty()) series.push_back({p.labels, "using 1:2:3 with labels font ',10' textcolor rgb '#000000'", ""});
  const double top = p.widest > 0.0 ? std::min(1.0, io::RoundScaleTop(p.widest)) : 1.0;
  return MapFrame(0.58, 0.9) + "set title " +
         io::GnuplotQuote(p.labels.empty() ? "width of each cell's 95 % interval"
                                           : "width of each cell's 95 % interval; labels: tip-overs/landings") +
         "\nunset logscale cb\nset format cb '% h'\nset cbrange [0:" + io::FormatNumber(top) +
         "]\nset cblabel '95 % interval width'\n"
         // White to mid grey: black labels and hatching read on every cell.
         "set palette defined (0 '#ffffff', 1 '#8c8c8c')\n" +
         PlotCommand(series, "no completed landings: nothing to map");
}

// Which landings the left panel draws one by one, in words (a line under the key).
std::string DrawnLandingsNote(const StudyMap& m, const StudySummary& s, const MapParts& p) {
  const std::string limit = std::to_string(m.max_drawn_landings);
  if (!p.landed.empty()) return "every landing drawn: a study of at most " + limit + " landings (study.map.max_drawn_landings)";
  if (!p.tipped.empty())
    return "the " + std::to_string(s.tipped) + " tip-overs drawn; landings that stayed up are drawn one by one only in a study of at most " +
           limit + " landings (study.map.max_drawn_landings)";
  if (s.landings > 0)
    return "no landing drawn one by one: landings, and tip-overs, are drawn when at most " + limit +
           " (study.map.max_drawn_landings)";
  return "";
}

// The key of both panels in a strip of its own under them (every look at NaN, so it covers no
// cell), and the note saying which landings are drawn.
std::string MapKeyStrip(const StudyMap& m, const StudySummary& s, const MapParts& p) {
  std::vector<Series> entries;
  const auto entry = [&](const std::string& style, const std::string& title) { entries.push_back({"", "NaN " + style, title}); };
  if (!p.zero_cells.empty()) entry("with boxes " + kZeroFill, "no tip-over in the cell (P = 0)");
  if (!p.empty_cells.empty()) entry("with boxes " + kEmptyFill, "no landing in the cell");
  if (!p.unreadable_cells.empty())
    entry("with boxes " + kUnreadableKey,
          "too few landings: interval > " + io::FormatNumber(kUnreadableIntervalWidth));
  for (size_t k = 0; k < m.contours.size(); ++k)  // a level never crossed is named all the same: it was looked for
    entry("with lines " + ContourLine(k, m.contours.size()),
          LevelName(m.contours[k]) + (p.contours[k].empty() ? ": not crossed" : " contour"));
  if (!p.tipped.empty()) entry(std::string("with points ") + kTippedMarks, "landing that tipped over");
  if (!p.landed.empty()) entry(std::string("with points ") + kLandedMarks, "landing that stayed up");
  const std::string note = DrawnLandingsNote(m, s, p);
  return "set lmargin at screen 0.02\nset rmargin at screen 0.98\nset bmargin at screen 0.06\nset tmargin at screen 0.19\n"
         "unset title\nunset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nunset colorbox\nunset logscale cb\n"
         "set xrange [0:1]\nset yrange [0:1]\nset key center center horizontal Left reverse samplen 3 width 2 maxcols 3\n" +
         (note.empty() ? "" : "set label 1 " + io::GnuplotQuote(note) + " at screen 0.5, screen 0.03 center font ',13'\n") +
         (entries.empty() ? std::string("plot NaN notitle\n") : PlotCommand(entries, "")) + "unset label 1\n";
}

std::string MapFigure(const Study& study, const StudySummary& s, const std::vector<DropRecord>& records,
                      DataWriter& data) {
  const StudyMap& m = *study.map;
  const MapParts parts = WriteMapParts(study, s, records, data);
  const std::string title = "Tip-over map: " + std::to_string(s.landings) + " landings, " + std::to_string(s.tipped) +
                            " tipped over, " + std::to_string(m.x.bins) + " x " + std::to_string(m.y.bins) + " cells";
  const std::string axes = "set xlabel " + io::GnuplotQuote(AxisLabel(m.x.param)) + "\nset ylabel " +
                           io::GnuplotQuote(AxisLabel(m.y.param)) + "\nset xrange [" + io::FormatNumber(m.x.low) + ":" +
                           io::FormatNumber(m.x.high) + "]\nset yrange [" + io::FormatNumber(m.y.low) + ":" +
                           io::FormatNumber(m.y.high) + "]\nunset key\n";
  const std::string body = "set multiplot title " + io::GnuplotQuote(title) + "\n" + axes + ProbabilityPanel(parts) +
                           IntervalPanel(parts) + MapKeyStrip(m, s, parts) + "unset multiplot\n";
  return Figure("plots/tip_over_map", 1000, 625, body);
}

// The exceedance curve of `values` (scaled), points with P > 0 only (log axis), closed by the
// largest value at the last positive P (so the last step reaches it); "" when none.
std::string ExceedanceFile(DataWriter& data, const std::string& name, const std::vector<double>& values, double scale) {
  std::vector<ExceedancePoint> curve = Exceedance(values);
  if (curve.size() < 2) return "";
  const double largest = curve.back().x;
  curve.pop_back();  // P = 0: below every log axis
  curve.push_back({largest, curve.back().probability});
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

// A pad's final penetrations over the landings that stayed up, split: loaded pads (above 0) are
// the depths a soil bearing is checked against; a pad at or above the surface (<= 0: lifted, its
// negative "penetration" a height, up to a metre on a slope's uphill side) or without a value
// (NaN) is counted apart, since its height would stretch the depth axis past the depths.
struct LoadedPads {
  std::vector<double> depths_m;
  int64_t lifted = 0;
};

LoadedPads Loaded(const std::vector<double>& penetrations_m) {
  LoadedPads out;
  for (const double v : penetrations_m)
    if (v > 0.0)
      out.depths_m.push_back(v);
    else
      ++out.lifted;
  return out;
}

// `set xrange` from 0 a little past the largest of `values` (file units), or autoscaled for none.
std::string XRangeFrom0(const std::vector<double>& values, double scale) {
  double largest = 0.0;
  for (const double v : values)
    if (std::isfinite(v)) largest = std::max(largest, v * scale);
  return largest > 0.0 ? "set xrange [0:" + io::FormatNumber(io::AxisTopPast(largest)) + "]\n" : "set xrange [*:*]\n";
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
  if (series.empty()) return "unset logscale y\nset yrange [*:*]\nset format y '% h'\n" + PlotCommand(series, nothing);
  // '%g': 1, 0.1, ... 0.0001, 1e-05 (gnuplot's own format writes every decade with six decimals
  // once the axis reaches 1e-5, at 20,000 landings).
  return "set logscale y\nset yrange [*:1]\nset format y '%g'\n" + PlotCommand(series, nothing);
}

// The curves fall from the upper left to the lower right: the key sits in the empty lower left.
// The deepest pad, drawn first, wide and grey, lies under the pad it equals. Penetration is over
// each pad's loaded landings, its lifted ones counted in its key entry.
std::string ExceedanceFigure(const StudySummary& s, const std::vector<DropRecord>& records, DataWriter& data) {
  const std::string style = "using 1:2 with steps linewidth 2";
  const std::vector<double> tilts = Values(records, [](const DropRecord& r) { return r.max_tilt_deg; });
  std::vector<Series> tilt;
  if (const std::string f = ExceedanceFile(data, "exceedance_max_tilt", tilts, 1.0); !f.empty())
    tilt.push_back({f, style + " lc rgb '#000000'", "max tilt"});
  std::vector<Series> depth;
  int64_t lifted = 0, pads = 0;
  const auto add = [&](const std::string& name, const LoadedPads& loaded, const std::string& line, const std::string& title) {
    if (const std::string f = ExceedanceFile(data, name, loaded.depths_m, 1e3); !f.empty())
      depth.push_back({f, "using 1:2 with steps " + line,
                       title + ": " + std::to_string(loaded.depths_m.size()) + " loaded, " + std::to_string(loaded.lifted) +
                           " lifted"});
  };
  const LoadedPads deepest = Loaded(Values(records, [](const DropRecord& r) { return r.final_penetration_m; }));
  add("exceedance_deepest_pad", deepest, "linewidth 7 linecolor rgb '#b0b0b0'", "deepest pad");
  for (int pad = 0; pad < 4; ++pad) {
    const LoadedPads loaded = Loaded(Values(records, [pad](const DropRecord& r) { return r.pad_final_penetration_m[pad]; }));
    lifted += loaded.lifted;
    pads += static_cast<int64_t>(loaded.depths_m.size()) + loaded.lifted;
    // Pad i in the colour and dash it has in the lander's own figures (lander_plots.cpp).
    add("exceedance_pad" + std::to_string(pad + 1), loaded, io::LanderPadLine(pad), "pad " + std::to_string(pad + 1));
  }
  const std::string nothing = "fewer than two distinct values: no exceedance curve";
  const std::string body =
      "set multiplot layout 1,2 title " +
      io::GnuplotQuote("Exceedance probability P[X > x] over the " + std::to_string(s.landings - s.tipped) +
                       " landings that stayed up") +
      "\nset grid\nset key inside bottom left opaque Left reverse\nset ylabel 'P[X > x]'\n"
      "set title 'max tilt'\nset xlabel 'max tilt from the vertical [deg]'\n" + XRangeFrom0(tilts, 1.0) +
      LogPanel(tilt, nothing) +
      "set title " +
      io::GnuplotQuote("final penetration of the loaded pads (lifted, <= 0, counted apart: " + std::to_string(lifted) +
                       " of " + std::to_string(pads) + ")") +
      "\nset xlabel 'final penetration of a loaded pad [mm]'\nset ylabel 'P[X > x] among the loaded pads'\n" +
      XRangeFrom0(deepest.depths_m, 1e3) + LogPanel(depth, nothing) + "unset multiplot\n";
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
