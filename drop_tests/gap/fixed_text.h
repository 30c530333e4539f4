#pragma once
// A number as text with a fixed count of decimals, for diagnose's sentences and reasons.
#include <iomanip>
#include <sstream>
#include <string>

namespace touchdown::gap {

inline std::string Fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

}  // namespace touchdown::gap
