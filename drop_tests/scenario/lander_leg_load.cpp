#include "drop_tests/scenario/lander_leg_load.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace touchdown::scenario {

double LegAxialForce(const LanderSpec& lander, const lander::LanderSample& s, int leg) {
  const LanderLegSpec& spec = lander.legs[leg];
  if (spec.absorber) return s.leg_force_N[leg];
  // R_WB from the sample's attitude: Rz(yaw) Ry(-pitch) Rx(roll) (lander::BodyAttitude).
  const Eigen::Matrix3d R_WB = (Eigen::AngleAxisd(s.attitude.yaw_rad, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(-s.attitude.pitch_rad, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(s.attitude.roll_rad, Eigen::Vector3d::UnitX()))
                                   .toRotationMatrix();
  const Eigen::Vector3d axis_W = R_WB * (spec.joint_B - spec.hip_B).normalized();
  return -s.pad_force_W[leg].dot(axis_W);
}

std::array<LegLoadSummary, lander::kNumLegs> LegLoadSummaries(const LanderSpec& lander,
                                                              const std::vector<lander::LanderSample>& trace) {
  std::array<LegLoadSummary, lander::kNumLegs> legs;
  for (int i = 0; i < lander::kNumLegs; ++i) {
    const std::optional<lander::ShockAbsorber>& absorber = lander.legs[i].absorber;
    double peak = 0.0, stroke = 0.0;
    for (const lander::LanderSample& s : trace) {
      const double load = LegAxialForce(lander, s, i);
      peak = std::max(peak, load);
      stroke = std::max(stroke, std::abs(s.stroke_m[i]));
      if (!legs[i].over_limit_s && std::abs(load) > lander.legs[i].load_limit_N) legs[i].over_limit_s = s.t_s;
    }
    legs[i].peak_axial_force_N = peak;
    if (!absorber) continue;
    legs[i].max_stroke_m = stroke;
    if (absorber->kind == lander::ShockAbsorber::Kind::kCrushable)
      legs[i].stroke_left_m = std::max(absorber->stroke_limit_m - stroke, 0.0);
  }
  return legs;
}

}  // namespace touchdown::scenario
