#pragma once
// The axial force in a lander's leg at one sample (compression positive): the absorber's force
// where the leg has one; on a rigid leg (a massless link) the soil's force on the pad along the
// leg's axis, which is what the link carries. One definition for the study's peak leg load
// (sweep) and the lander's load plot.
#include "drop_tests/scenario/lander_scenario_types.h"

namespace touchdown::scenario {

double LegAxialForce(const LanderSpec& lander, const lander::LanderSample& sample, int leg);

}  // namespace touchdown::scenario
