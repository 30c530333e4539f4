#include "apps/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace touchdown::app {

CLI::Validator NumberIn(double low, double high) {
  std::ostringstream range;
  range << low << " to " << high;
  const std::string text = range.str();
  return CLI::Validator(
      [low, high, text](std::string& value) -> std::string {
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(value.c_str(), &end);
        const bool number = !value.empty() && end == value.c_str() + value.size() && errno != ERANGE;
        if (!number || std::isnan(v)) return "must be a number from " + text + ", got '" + value + "'";
        if (v < low || v > high) return "must be from " + text + ", got " + value;
        return "";
      },
      "NUMBER in [" + text + "]", "NumberIn");
}

CLI::Validator NonEmptyPath() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        return value.empty() ? "an empty path: give a file or directory (or leave the option out)" : "";
      },
      "PATH", "NonEmptyPath");
}

}  // namespace touchdown::app
