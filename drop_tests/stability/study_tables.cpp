// The study's CSV tables: percentiles of every metric, and the tip-over map's cells.
#include <cmath>
#include <filesystem>
#include <ostream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/stability/study_outputs.h"

namespace touchdown::stability {

namespace {
std::string Cell(double v) { return std::isfinite(v) ? io::FormatNumber(v) : ""; }

// Every landing's drawn soil parameters (a pure function of its index: soil_uncertainty.h), keyed
// as the database's landings are, so a reader joins them with the outcomes.
void WriteSoilParameters(const Study& study, const std::filesystem::path& path) {
  const SoilUncertainty& u = *study.soil_uncertainty;
  io::WriteFileAtomically(path.string(), [&](std::ostream& out) {
    out << "drop_id,drop_index";
    for (const UncertainParameter& p : u.parameters) out << ',' << p.column;
    out << '\n';
    for (int64_t i = 0; i < study.plan.size(); ++i) {
      out << study.plan.DropId(i) << ',' << i;
      for (const double v : DrawSoilParameters(u, i)) out << ',' << Cell(v);
      out << '\n';
    }
  });
}
}  // namespace

void WriteStudyTables(const Study& study, const StudySummary& s, const std::string& dir) {
  const std::filesystem::path d = dir;
  io::WriteFileAtomically((d / "percentiles.csv").string(), [&](std::ostream& out) {
    out << "metric,unit,landings,p50,p95,p99,max\n";
    for (const MetricPercentiles& m : s.metrics)
      out << m.metric->name << ',' << m.metric->unit << ',' << m.count << ',' << Cell(m.p50) << ',' << Cell(m.p95)
          << ',' << Cell(m.p99) << ',' << Cell(m.max) << '\n';
  });
  if (study.soil_uncertainty) WriteSoilParameters(study, d / "soil_parameters.csv");
  if (!study.map) return;
  io::WriteFileAtomically((d / "tip_over_map.csv").string(), [&](std::ostream& out) {
    const std::string x = sweep::SweepParamKey(study.map->x.param), y = sweep::SweepParamKey(study.map->y.param);
    out << x << "_low," << x << "_high," << y << "_low," << y << "_high,landings,tipped_over,tip_over_probability,"
        << "interval_95_low,interval_95_high\n";
    for (const MapCell& c : s.map)
      out << Cell(c.x_low) << ',' << Cell(c.x_high) << ',' << Cell(c.y_low) << ',' << Cell(c.y_high) << ','
          << c.landings << ',' << c.tipped << ',' << Cell(c.probability) << ',' << Cell(c.interval.low) << ','
          << Cell(c.interval.high) << '\n';
  });
}

}  // namespace touchdown::stability
