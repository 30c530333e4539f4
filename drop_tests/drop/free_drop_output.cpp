#include "drop_tests/drop/free_drop_output.h"

#include <iomanip>
#include <nlohmann/json.hpp>

#include "drop_tests/drop/drop_columns.h"

namespace touchdown::drop {

nlohmann::json FreeDropJson(const pad::FreeDropResult& r) {
  nlohmann::json j{{"mode", "free"}};
  for (const ResultNumber<pad::FreeDropResult>& n : FreeMetrics()) j[n.name] = r.*n.member;
  j["solver_steps"] = r.solver.steps;
  return j;
}

void WriteFreeDropTraceCsv(const pad::FreeDropResult& r, std::ostream& out) {
  const std::vector<TraceColumn<pad::FreeDropSample>>& columns = FreeTraceColumns();
  for (size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
  out << '\n' << std::setprecision(10);
  for (const pad::FreeDropSample& s : r.trace) {
    for (size_t c = 0; c < columns.size(); ++c) {
      if (c) out << ',';
      out << columns[c].value(s);
    }
    out << '\n';
  }
}

}  // namespace touchdown::drop
