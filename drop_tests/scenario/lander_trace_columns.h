#pragma once
// The columns of a lander run's trace (trace.csv), named and in order: the one definition the CSV
// writer and the Python module's arrays read, so both hold the same numbers under the same names.
#include <functional>
#include <string>
#include <vector>

#include "lander/multibody/lander_run.h"

namespace touchdown::scenario {

struct LanderTraceColumn {
  std::string name;  // with its unit suffix, e.g. "depth1_m"
  std::function<double(const lander::LanderSample&)> value;
};

const std::vector<LanderTraceColumn>& LanderTraceColumns();

}  // namespace touchdown::scenario
