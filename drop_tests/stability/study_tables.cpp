// The study's CSV tables: percentiles of every metric, and the tip-over map's cells.
#include <cmath>
#include <filesystem>
#include <ostream>

#include "drop_tests/io/dataset_csv.h"
#include "drop_tests/io/output_path.h"
#include "drop_tests/stability/study_outputs.h"

namespace touchdown::stability {

namespace {
std::string Cell(double v) { return std::isfinite(v) ? io::FormatNumber(v) : ""; }
}  // namespace

void WriteStudyTables(const Study& study, const StudySummary& s, const std::string& dir) {
  const std::filesystem::path d = dir;
  io::WriteFileAtomically((d / "percentiles.csv").string(), [&](std::ostream& out) {
    out << "metric,unit,landings,p50,p95,p99,max\n";
    for (const MetricPercentiles& m : s.metrics)
      out << m.metric->name << ',' << m.metric->unit << ',' << m.count << ',' << Cell(m.p50) << ',' << Cell(m.p95)
          << ',' << Cell(m.p99) << ',' << Cell(m.max) << '\n';
  });
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
