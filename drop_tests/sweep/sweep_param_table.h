#pragma once
// Internal to drop_tests/sweep (not a public header): the sweep parameters' tables the plan
// (sweep_plan.cpp) and its file reader (sweep_plan_file.cpp) share: keys, units, which parameters
// are names, lander-only or single-pad-only, and the paper's Table II ground cases.
#include <array>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "drop_tests/sweep/sweep_plan.h"
#include "drop_tests/sweep/sweep_file_keys.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::sweep::param_table {
using namespace file_keys;
using units::kDeg;
using limits::kMaxGridCount;  // rft/physical_limits.h
using limits::kMaxSweepDrops;
constexpr SweepParam kAll[kSweepParamCount] = {SweepParam::kPad,     SweepParam::kSoil, SweepParam::kImpactSpeed,
                                               SweepParam::kMass,    SweepParam::kGravity, SweepParam::kTilt,
                                               SweepParam::kHorizontalSpeed, SweepParam::kZeta, SweepParam::kRoll,
                                               SweepParam::kPitch, SweepParam::kPadSoils, SweepParam::kSlope,
                                               SweepParam::kDownhillAzimuth, SweepParam::kYawToSlope,
                                               SweepParam::kHorizontalAzimuth, SweepParam::kRateX, SweepParam::kRateY,
                                               SweepParam::kRateZ};
// Random streams of the per-pad soil draws: above every parameter's own stream (its enum value).
constexpr uint64_t kPerPadStream = 0x100;

inline std::optional<SweepParam> ParamFromKey(const std::string& key) {
  for (SweepParam p : kAll)
    if (key == SweepParamKey(p)) return p;
  return std::nullopt;
}

inline bool IsName(SweepParam p) { return p == SweepParam::kPad || p == SweepParam::kSoil || p == SweepParam::kPadSoils; }

// Table II of Sutoh et al. 2017: the packing under pads 1..4 (clockwise from front-left).
struct PaperCase {
  const char* label;
  std::array<const char*, 4> soils;
};
constexpr PaperCase kPaperCases[] = {{"A", {"fjs1_lp", "fjs1_lp", "fjs1_lp", "fjs1_lp"}},
                                     {"B", {"fjs1_cp", "fjs1_lp", "fjs1_lp", "fjs1_lp"}},
                                     {"C", {"fjs1_cp", "fjs1_cp", "fjs1_lp", "fjs1_lp"}}};

// Parameters given in degrees (angles) or degrees per second (rates) in the file, radians inside.
inline bool InDegrees(SweepParam p) {
  switch (p) {
    case SweepParam::kTilt: case SweepParam::kRoll: case SweepParam::kPitch: case SweepParam::kSlope:
    case SweepParam::kDownhillAzimuth: case SweepParam::kYawToSlope: case SweepParam::kHorizontalAzimuth:
    case SweepParam::kRateX: case SweepParam::kRateY: case SweepParam::kRateZ:
      return true;
    default:
      return false;
  }
}

inline double ToSi(SweepParam p, double v) {
  if (InDegrees(p)) return v * kDeg;
  if (p == SweepParam::kZeta) return units::ZetaFromN_cm3(v);
  return v;
}

inline double FromSi(SweepParam p, double v) {
  if (InDegrees(p)) return v / kDeg;
  if (p == SweepParam::kZeta) return units::ZetaToN_cm3(v);
  return v;
}

inline std::string FileText(const std::string& path) {
  if (path.empty()) return "";
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline bool IsLanderParam(SweepParam p) {
  return p == SweepParam::kRoll || p == SweepParam::kPitch || p == SweepParam::kPadSoils ||
         static_cast<int>(p) >= static_cast<int>(SweepParam::kSlope);
}
inline bool IsSinglePadOnly(SweepParam p) {
  return p == SweepParam::kPad || p == SweepParam::kMass || p == SweepParam::kTilt || p == SweepParam::kZeta;
}

}  // namespace touchdown::sweep::param_table
