#pragma once
// A number for a JSON output: JSON has no NaN or infinity, so a value that is not finite (a
// quantity with no data, a ratio over zero) is written as null.
#include <cmath>

#include <nlohmann/json.hpp>

namespace touchdown::io {

inline nlohmann::json FiniteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace touchdown::io
