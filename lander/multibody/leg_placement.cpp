#include "lander/multibody/leg_placement.h"

#include <algorithm>
#include <cmath>

#include "rft/units.h"

namespace touchdown::lander {

namespace {
// Pads clockwise seen from above, pad 1 front-left (x forward, y left).
constexpr double kPadAzimuthDeg[kNumLegs] = {45.0, -45.0, -135.0, 135.0};
}  // namespace

double MaxStopStiffness(const geom::PadBody& pad) {
  const Eigen::Vector3d& d = pad.com_B;  // the joint is the pad frame's origin
  const Eigen::Matrix3d I_joint =
      pad.inertia_com_B + pad.mass_kg * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  const double omega = 2.0 * M_PI * kMaxStopRingingHz;
  return std::min(I_joint(0, 0), I_joint(1, 1)) * omega * omega;
}

std::variant<LegPlacement, LegPlacementError> PlaceLegs(const geom::PadBody& pad, double total_mass_kg,
                                                        double cog_height_m, const LegLayout& layout) {
  using Field = LegPlacementError::Field;
  LegPlacement out;
  out.body_mass_kg = total_mass_kg - kNumLegs * pad.mass_kg;
  if (!(out.body_mass_kg > 0.0)) return LegPlacementError{Field::kTotalMass, "must exceed the four pads' mass"};
  // Standing level on the pad bottoms: the joint centre is -lowest_z_B above the bottom, the pad
  // CoM com_B.z above the joint; the body CoM height follows from the whole lander's CoG height.
  const double joint_height = -pad.lowest_z_B;
  const double pad_com_height = joint_height + pad.com_B.z();
  const double body_com_height =
      (total_mass_kg * cog_height_m - kNumLegs * pad.mass_kg * pad_com_height) / out.body_mass_kg;
  if (!(body_com_height > joint_height))
    return LegPlacementError{Field::kCogHeight, "puts the body's centre of mass below the joints"};
  if (!(layout.hip_height_m > joint_height))
    return LegPlacementError{Field::kHipHeight, "must be above the ball-joint centres"};
  for (int i = 0; i < kNumLegs; ++i) {
    const double az = kPadAzimuthDeg[i] * units::kDeg;
    const Eigen::Vector3d dir(std::cos(az), std::sin(az), 0.0);
    out.joint_B[i] = layout.joint_radius_m * dir + Eigen::Vector3d(0, 0, joint_height - body_com_height);
    out.hip_B[i] = layout.hip_radius_m * dir + Eigen::Vector3d(0, 0, layout.hip_height_m - body_com_height);
  }
  return out;
}

}  // namespace touchdown::lander
