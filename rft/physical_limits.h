#pragma once
// The physically meaningful range of every magnitude a user gives, in one place, so the command
// line and the YAML files refuse the same values with the same message. The bounds are generous
// (far beyond any lander) but keep every product the contact sums form finite: a 1e308 m/s
// impact or a 1e30 mm pad would otherwise reach the solver or print NaN.
#include <cmath>
#include <cstdio>
#include <string>

#include "rft/input_error.h"

namespace touchdown::limits {

struct Range {
  const char* unit;
  double low, high;
  bool low_open;  // low itself excluded (a positive quantity)
};

inline constexpr Range kSpeed_m_s{"m/s", 0.0, 100.0, false};            // impact speed, |velocity|
inline constexpr Range kAbsSpeed_m_s{"m/s", -100.0, 100.0, false};      // a signed horizontal speed
inline constexpr Range kAngularSpeed_rad_s{"rad/s", 0.0, 1000.0, false};  // |omega|, ~160 rev/s
inline constexpr Range kForceTilt_deg{"deg", -180.0, 180.0, false};     // `force` poses any attitude
inline constexpr Range kDepth_m{"m", -10.0, 10.0, false};               // below (+) / above (-) the surface
inline constexpr Range kZeta_N_cm3{"N/cm^3", 0.0, 1e4, true};           // RFT scaling factor
inline constexpr Range kPadSize_m{"m", 0.0, 10.0, true};                // pad radius, thickness, mesh extent
inline constexpr Range kPadSize_mm{"mm", 0.0, kPadSize_m.high * 1e3, true};  // the same, as pad YAML gives it
// Worker threads a run may start (--threads, the Python module's `threads`; 0: every core). Far
// beyond any machine's cores, and checked before a thread starts: a process that cannot start the
// threads it asked for ends in std::terminate, not in an error message.
inline constexpr int kMaxThreads = 4096;
inline constexpr Range kThreads{"threads", 0.0, double(kMaxThreads), false};

inline bool Within(const Range& r, double v) {
  return std::isfinite(v) && (r.low_open ? v > r.low : v >= r.low) && v <= r.high;
}

// "must be between 0 and 100 m/s, got 1e+308"
inline std::string Describe(const Range& r, double v) {
  char text[160];
  std::snprintf(text, sizeof text, "must be %s %g and %g %s, got %.6g", r.low_open ? "above" : "between", r.low,
                r.high, r.unit, v);
  std::string s = text;
  if (r.low_open) s.replace(s.find(" and "), 5, " and at most ");
  return s;
}

// Throws InputError(file, field, Describe(...)) unless v is in r.
inline void Require(const Range& r, double v, const std::string& file, const std::string& field) {
  if (!Within(r, v)) throw MakeInputError(file, field, Describe(r, v));
}

}  // namespace touchdown::limits
