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
  WriteTraceCsv(FreeTraceColumns(), r.trace, out);
}

}  // namespace touchdown::drop
