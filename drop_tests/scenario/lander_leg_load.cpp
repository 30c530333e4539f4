#include "drop_tests/scenario/lander_leg_load.h"

#include <Eigen/Geometry>

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

}  // namespace touchdown::scenario
