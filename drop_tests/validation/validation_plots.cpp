// validate's figures (measured points against the simulated curves, per source) and the whole
// output directory.
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>

#include <nlohmann/json.hpp>

#include "drop_tests/io/catalog.h"
#include "drop_tests/io/figure_style.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/io/plot_runner.h"
#include "drop_tests/validation/validate.h"

namespace touchdown::validation {

namespace {

// A simulated variant's line: its colour, dashed when zeta is fixed.
std::string VariantLine(const Variant& v, size_t k) {
  return "lw 2.5 lc rgb '" + io::SeriesColour(static_cast<int>(k) + 1) + "' dt " + (v.zeta_fixed ? "2" : "1");
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
  std::string body = "set title " + io::GnuplotQuote(r.source->id + ": " + QuantityName(c.quantity) + " against impact speed") +
                     "\nset xlabel 'impact speed [m/s]'\nset ylabel " +
                     io::GnuplotQuote(std::string(QuantityName(c.quantity)) + " [" + QuantityUnit(c.quantity) + "]") +
                     "\nset key top left\nplot " + io::GnuplotQuote("plots/" + file + "_measured.csv") +
                     " using 1:2:3 with yerrorbars " + io::kMeasuredPoints + " title 'measured'";
  for (size_t k = 0; k < r.variants.size(); ++k)
    body += ", " + io::GnuplotQuote("plots/" + file + ".csv") + " using 1:" + std::to_string(k + 2) + " with lines " +
            VariantLine(r.variants[k], k) + " title " + io::GnuplotQuote(r.variants[k].Name());
  return base + "|" + body + "\n";
}

// A trend on log-log axes: each variant's simulated values, and the measured exponent as a black
// dashed line through the first variant's middle value (its slope is what is measured).
std::string TrendFigure(const std::string& dir, const SourceResult& r, const TrendResult& t) {
  const MeasuredTrend& m = *t.trend;
  const std::string base = "plots/" + r.source->id + "_" + m.id;
  const double f = QuantityToReport(m.quantity);
  const size_t mid = m.values.size() / 2;
  // Columns: per variant its abscissa and value, then the measured slope's line (on variant 0's x).
  WriteTable(dir + "/" + base + ".csv", [&](std::ostream& out) {
    for (size_t i = 0; i < m.values.size(); ++i) {
      for (size_t k = 0; k < t.simulated.size(); ++k) out << (k ? "," : "") << t.x[k][i] << "," << t.simulated[k][i] * f;
      const double slope = m.direction == Direction::kExponent ? m.exponent : 0.0;
      out << "," << t.x[0][i] << "," << t.simulated[0][mid] * f * std::pow(t.x[0][i] / t.x[0][mid], slope) << "\n";
    }
  });
  const std::string file = r.source->id + "_" + m.id;
  const std::string x_label = m.vary == Variable::kImpactSpeed         ? "impact speed [m/s]"
                              : m.vary == Variable::kGravity           ? "gravity [m/s^2]"
                              : m.vary == Variable::kTotalDropDistance ? "total drop distance h + d [m]"
                                                                       : "projectile density [kg/m^3]";
  const std::string measured = m.direction == Direction::kExponent
                                   ? "measured exponent " + std::to_string(m.exponent).substr(0, 5)
                                   : std::string("measured: ") + (m.direction == Direction::kIncreasing ? "increasing" : "decreasing");
  std::string body = "set title " + io::GnuplotQuote(r.source->id + ": " + m.id) + "\nset logscale xy\nset xlabel " +
                     io::GnuplotQuote(x_label) + "\nset ylabel " +
                     io::GnuplotQuote(std::string(QuantityName(m.quantity)) + " [" + QuantityUnit(m.quantity) + "]") +
                     "\nset key top left\nplot ";
  std::vector<std::string> items;
  for (size_t k = 0; k < r.variants.size(); ++k)
    items.push_back(io::GnuplotQuote("plots/" + file + ".csv") + " using " + std::to_string(2 * k + 1) + ":" +
                    std::to_string(2 * k + 2) +
                    " with linespoints " + VariantLine(r.variants[k], k) + " pt 7 title " +
                    io::GnuplotQuote(r.variants[k].Name()));
  // A direction has no slope to draw: the key says what was measured.
  items.push_back(io::GnuplotQuote("plots/" + file + ".csv") + " using " + std::to_string(2 * r.variants.size() + 1) +
                  ":" + std::to_string(2 * r.variants.size() + 2) +
                  " with lines " + std::string(m.direction == Direction::kExponent ? io::kPaperBandLine : "lw 0 lc rgb '#ffffff'") +
                  " title " + io::GnuplotQuote(m.direction == Direction::kExponent ? measured + " (slope; anchored)" : measured));
  for (size_t i = 0; i < items.size(); ++i) body += (i ? ", " : "") + items[i];
  return base + "|" + body + "\nunset logscale xy\n";
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
