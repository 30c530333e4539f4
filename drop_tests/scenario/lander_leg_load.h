#pragma once
// The axial force in a lander's leg at one sample (compression positive): the absorber's force
// where the leg has one; on a rigid leg (a massless link) the soil's force on the pad along the
// leg's axis, which is what the link carries. One definition for the study's peak leg load
// (sweep), the lander's load plot and its per-leg summary.
#include <array>
#include <optional>
#include <vector>

#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

double LegAxialForce(const LanderSpec& lander, const lander::LanderSample& sample, int leg);

// What an inspection of one leg after the landing reads, over a run's samples: the largest axial
// compression it carried, the largest stroke of its absorber, what is left of a crushable
// absorber's stroke (a crushed core stays crushed, so the stroke used is the largest reached), and
// when its load first passed its stated limit (LanderLegSpec::load_limit_N), in compression or
// tension. Sampled: a peak between two samples is not seen.
struct LegLoadSummary {
  double peak_axial_force_N = 0.0;      // largest LegAxialForce, 0 if it only ever pulled
  std::optional<double> max_stroke_m;   // absorber legs: largest |stroke|
  std::optional<double> stroke_left_m;  // crushable absorbers: stroke_limit_m less max_stroke_m
  std::optional<double> over_limit_s;   // the first sample time (since release) at which |load| > limit
};
std::array<LegLoadSummary, lander::kNumLegs> LegLoadSummaries(const LanderSpec& lander,
                                                              const std::vector<lander::LanderSample>& trace);

}  // namespace touchdown::scenario
