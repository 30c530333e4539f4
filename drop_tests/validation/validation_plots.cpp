// validate's figures (measured points against the simulated curves, per source) and the whole
// output directory.
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/figure_style.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/plot_runner.h"
#include "drop_tests/validation/validate.h"

namespace touchdown::validation {

namespace {

// A simulated variant's line: its law's colour, dashed and narrower when zeta is fixed, so a
// variant that gives the same values as another is drawn inside it rather than hidden under it.
std::string VariantLine(const Variant& v) {
  return std::string(v.zeta_fixed ? "lw 2 dt 2" : "lw 4.5 dt 1") + " lc rgb '" + io::LawColour(v.Name()) + "'";
}
// Its marks: filled circles, open squares when zeta is fixed.
std::string VariantPoints(const Variant& v) { return v.zeta_fixed ? "pt 4 ps 2" : "pt 7 ps 1.4"; }

// `set xrange`/`set yrange` on a log axis holding `values` (the positive ones) with a margin of
// a fifth of a decade-ish each side: the data fill the frame instead of a few decades of axis.
std::string LogRange(const char* axis, const std::vector<double>& values) {
  double lo = INFINITY, hi = 0.0;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) return std::string("set ") + axis + "range [*:*]\n";
  const double margin = std::max(1.15, std::pow(hi / lo, 0.08));
  lo /= margin;
  hi *= margin;
  std::ostringstream s;
  s << std::setprecision(6) << "set " << axis << "range [" << lo << ":" << hi << "]\n";
  // Tics at 1, 2, 5 times the powers of ten (every digit when the range is narrower): gnuplot's
  // own log tics are the decades only, none or one of which falls inside a fitted range.
  for (const std::vector<int>& digits : {std::vector<int>{1, 2, 5}, std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}}) {
    std::vector<double> tics;
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10.0)
      for (int d : digits)
        if (d * decade >= lo && d * decade <= hi) tics.push_back(d * decade);
    if (tics.size() < 3 && digits.size() == 3) continue;
    s << "set " << axis << "tics (";
    for (size_t i = 0; i < tics.size(); ++i) s << (i ? ", " : "") << io::FormatNumber(tics[i]);
    s << ")\n";
    break;
  }
  return s.str();
}

void WriteTable(const std::string& path, const std::function<void(std::ostream&)>& rows) {
  io::WriteFileAtomically(path, [&](std::ostream& out) {
    out << std::setprecision(10);
    rows(out);
  });
}

// quantity against impact speed: the measured points (with their uncertainty) and each variant.
std::string CurveFigure(const std::string& dir, const SourceResult& r, const Curve& c) {
  const std::string base = "plots/" + r.source->id + "_" + QuantityName(c.quantity);
  const double f = QuantityToReport(c.quantity);
  WriteTable(dir + "/" + base + ".csv", [&](std::ostream& out) {
    for (size_t i = 0; i < c.speed_m_s.size(); ++i) {
      out << c.speed_m_s[i];
      for (const std::vector<double>& sim : c.simulated) out << "," << sim[i] * f;
      out << "\n";
    }
  });
  WriteTable(dir + "/" + base + "_measured.csv", [&](std::ostream& out) {
    for (const PointResult& p : r.points)
      if (p.point->quantity == c.quantity)
        out << p.point->impact_speed_m_s << "," << p.point->value * f << "," << p.point->uncertainty * f << "\n";
  });
  const std::string file = r.source->id + "_" + QuantityName(c.quantity);
  std::string body = "set title " + io::GnuplotQuote(r.source->id + ": " + io::Words(QuantityName(c.quantity)) + " against impact speed") +
                     "\nset xlabel 'impact speed [m/s]'\nset ylabel " +
                     io::GnuplotQuote(io::Words(QuantityName(c.quantity)) + " [" + QuantityUnit(c.quantity) + "]") +
                     "\nset key top left\nplot " + io::GnuplotQuote("plots/" + file + "_measured.csv") +
                     " using 1:2:3 with yerrorbars " + io::kMeasuredPoints + " title 'measured'";
  for (size_t k = 0; k < r.variants.size(); ++k)
    body += ", " + io::GnuplotQuote("plots/" + file + ".csv") + " using 1:" + std::to_string(k + 2) + " with lines " +
            VariantLine(r.variants[k]) + " title " + io::GnuplotQuote(io::Words(r.variants[k].Name()));
  return base + "|" + body + "\n";
}

// A trend on log-log axes: each variant's simulated values (its fitted exponent and whether it
// reproduces the measurement in the key), and what was measured: for an exponent, its slope
// through the first variant's middle value with the tolerance's slopes as a black dotted wedge;
// for a direction, the direction in a note (the source gives no value to draw).
std::string TrendFigure(const std::string& dir, const SourceResult& r, const TrendResult& t) {
  const MeasuredTrend& m = *t.trend;
  const std::string base = "plots/" + r.source->id + "_" + m.id;
  const double f = QuantityToReport(m.quantity);
  const size_t mid = m.values.size() / 2;
  const bool exponent = m.direction == Direction::kExponent;
  auto anchored = [&](size_t i, double slope) { return t.simulated[0][mid] * f * std::pow(t.x[0][i] / t.x[0][mid], slope); };
  std::vector<double> xs, ys;
  // Columns: per variant its abscissa and value, then the measured slope's line and its
  // tolerance's two edges (on variant 0's x).
  WriteTable(dir + "/" + base + ".csv", [&](std::ostream& out) {
    for (size_t i = 0; i < m.values.size(); ++i) {
      for (size_t k = 0; k < t.simulated.size(); ++k) {
        out << (k ? "," : "") << t.x[k][i] << "," << t.simulated[k][i] * f;
        xs.push_back(t.x[k][i]);
        ys.push_back(t.simulated[k][i] * f);
      }
      out << "," << t.x[0][i];
      for (double slope : {m.exponent, m.exponent - m.tolerance, m.exponent + m.tolerance}) {
        out << "," << (exponent ? anchored(i, slope) : NAN);
        if (exponent) ys.push_back(anchored(i, slope));
      }
      out << "\n";
    }
  });
  const std::string file = io::GnuplotQuote("plots/" + r.source->id + "_" + m.id + ".csv");
  const std::string x_label = m.vary == Variable::kImpactSpeed         ? "impact speed [m/s]"
                              : m.vary == Variable::kGravity           ? "gravity [m/s^2]"
                              : m.vary == Variable::kTotalDropDistance ? "total drop distance h + d [m]"
                                                                       : "projectile density [kg/m^3]";
  std::string body = "set title " + io::GnuplotQuote(r.source->id + ": " + io::Words(m.id)) + "\nset logscale xy\nset xlabel " +
                     io::GnuplotQuote(x_label) + "\nset ylabel " +
                     io::GnuplotQuote(io::Words(QuantityName(m.quantity)) + " [" + QuantityUnit(m.quantity) + "]") + "\n" +
                     LogRange("x", xs) + LogRange("y", ys) + io::kKeyBelow + "set key maxrows 3\nset bmargin 10\n";
  if (!exponent)
    body += "set label 3 " +
            io::GnuplotQuote(std::string("measured: ") + io::Words(QuantityName(m.quantity)) +
                             (m.direction == Direction::kIncreasing ? " increases" : " decreases") +
                             " (the source gives a direction, no exponent)") +
            " at graph 0.98, graph 0.05 right front boxed\nset style textbox opaque noborder\n";
  body += "plot ";
  std::vector<std::string> items;
  for (size_t k = 0; k < r.variants.size(); ++k) {
    std::ostringstream title;
    title << io::Words(r.variants[k].Name()) << ": slope " << std::setprecision(3) << t.exponent[k]
          << (t.reproduced[k] ? " (reproduced)" : " (not reproduced)");
    items.push_back(file + " using " + std::to_string(2 * k + 1) + ":" + std::to_string(2 * k + 2) + " with linespoints " +
                    VariantLine(r.variants[k]) + " " + VariantPoints(r.variants[k]) + " title " + io::GnuplotQuote(title.str()));
  }
  if (exponent) {
    const size_t x = 2 * r.variants.size() + 1;
    std::ostringstream title;
    title << "measured exponent " << std::setprecision(3) << m.exponent << " +- " << m.tolerance
          << (m.tolerance_assumed ? " (tolerance assumed)" : "") << " (anchored)";
    items.push_back(file + " using " + std::to_string(x) + ":" + std::to_string(x + 1) + " with lines lw 2.5 lc rgb '#000000' title " +
                    io::GnuplotQuote(title.str()));
    for (size_t edge : {x + 2, x + 3})
      items.push_back(file + " using " + std::to_string(x) + ":" + std::to_string(edge) + " with lines " + io::kPaperBandLine +
                      (edge == x + 2 ? " title 'measured: tolerance'" : " notitle"));
  }
  for (size_t i = 0; i < items.size(); ++i) body += (i ? ", \\\n     " : "") + items[i];
  return base + "|" + body + "\nunset logscale xy\nunset label 3\nset xtics autofreq\nset ytics autofreq\n";
}

void WritePlots(const std::string& dir, const ValidationResult& result) {
  std::filesystem::create_directories(dir + "/plots");
  std::string script;
  std::vector<std::string> pngs;
  const auto add = [&](const std::string& base_and_body) {
    const size_t bar = base_and_body.find('|');
    const std::string base = base_and_body.substr(0, bar);
    script += io::Figure(base, base_and_body.substr(bar + 1));
    pngs.push_back(io::FigurePng(base));
  };
  for (const SourceResult& r : result.sources) {
    for (const Curve& c : r.curves) add(CurveFigure(dir, r, c));
    for (const TrendResult& t : r.trends) add(TrendFigure(dir, r, t));
  }
  if (pngs.empty()) return;
  io::RenderPlots(dir, {"plots/validation.gp", script, pngs});
}

}  // namespace

void WriteValidationOutputs(const ValidationResult& result, const std::string& out_dir) {
  std::vector<std::string> inputs;
  for (const ValidationSource& s : result.set->sources) inputs.push_back(s.file);
  io::WriteOutputDirectory({out_dir, inputs}, io::OutputKind::kValidation, [&](const std::string& dir) {
    io::WriteFileAtomically(dir + "/validation.json",
                            [&](std::ostream& out) { out << ValidationJson(result).dump(2) << "\n"; });
    io::WriteFileAtomically(dir + "/validation.md", [&](std::ostream& out) {
      out << "# touchdown validate\n\n" << ValidationMarkdown(result);
    });
    WritePlots(dir, result);
  });
}

ValidationResult ValidateSources(const std::string& sources_dir, const std::string& out_dir) {
  const auto set = std::make_shared<const ValidationSet>(
      LoadValidationSet(sources_dir.empty() ? io::DataDirectory() + "/validation" : sources_dir));
  std::vector<std::string> inputs;
  for (const ValidationSource& s : set->sources) inputs.push_back(s.file);
  if (!out_dir.empty()) io::CheckOutputDirectory({out_dir, inputs}, io::OutputKind::kValidation);
  ValidationResult result = RunValidation(*set);
  result.owned_set = set;
  if (!out_dir.empty()) WriteValidationOutputs(result, out_dir);
  return result;
}

}  // namespace touchdown::validation
