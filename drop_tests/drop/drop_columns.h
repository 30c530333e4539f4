#pragma once
// The numbers of a single drop's outputs, each described once: the name its outputs give it
// (unit-suffixed) beside where the result keeps it. The summaries (JSON), the traces (CSV header
// and rows) and a sweep's records (drop_tests/sweep: the database column of the same name) are
// written from these tables, so a name and its value cannot drift apart.
#include <iomanip>
#include <ostream>
#include <vector>

#include "lander/pad/free_drop.h"
#include "lander/pad/rig_drop.h"

namespace touchdown::drop {

template <typename Result>
struct ResultNumber {
  const char* name;
  double Result::*member;
};

// The rig drop's metrics (final_penetration_m .. rest_creep_m), in the order of its summary and a
// sweep's records; solver_steps, an integer, follows them in both.
const std::vector<ResultNumber<pad::RigDropResult>>& RigMetrics();
// The free drop's summary numbers: its metrics (those of the rig it has), then the pad's tilt at
// touchdown and at rest and its horizontal travel.
const std::vector<ResultNumber<pad::FreeDropResult>>& FreeMetrics();

// A column of a trace: its name in the CSV header and its value in a sample.
template <typename Sample>
struct TraceColumn {
  const char* name;
  double (*value)(const Sample&);
};

// The rig's trace: t_s,penetration_m,velocity_m_s,force_N.
const std::vector<TraceColumn<pad::DropSample>>& RigTraceColumns();
// A free drop's trace: the rig's columns first (the dataset tools read them), then force_x_N,
// horizontal_m, tilt_deg and the pose (free_drop_output.h).
const std::vector<TraceColumn<pad::FreeDropSample>>& FreeTraceColumns();

// A trace as CSV: the columns' names, then one row per sample (10 significant digits).
template <typename Sample>
void WriteTraceCsv(const std::vector<TraceColumn<Sample>>& columns, const std::vector<Sample>& samples,
                   std::ostream& out) {
  for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
  out << '\n' << std::setprecision(10);
  for (const Sample& s : samples) {
    for (size_t c = 0; c < columns.size(); ++c) {
      if (c) out << ',';
      out << columns[c].value(s);
    }
    out << '\n';
  }
}

}  // namespace touchdown::drop
