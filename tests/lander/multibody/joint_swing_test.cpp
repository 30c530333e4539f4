// The pads' swing on their ball joints: JointSwingAngle against its closed form, the largest swing a
// run records (LanderRunResult::max_joint_swing_rad) against its own trace, and the cone limit that
// bounds it, on a sliding landing of the paper's lander (fixtures/paper_lander.h):
// with free joints its pads turn past edge-on; a cone stop holds them near its half angle, and the
// energy balance still closes with the stop's potential energy.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "lander/multibody/lander_simulation.h"
#include "rft/units.h"
#include "fixtures/paper_lander.h"

namespace touchdown::lander {
namespace {

using units::kDeg;

TEST(JointSwing, IsTheAngleOfThePadAxisFromTheBodyAxis) {
  // Any body attitude; the pad turned by `a` about an axis normal to the body's z axis, then spun
  // about its own axis (a spin is no swing).
  const Eigen::Matrix3d R_WB = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()) *
                                Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  const Eigen::Vector3d swing_axis_B = Eigen::Vector3d(0.6, 0.8, 0.0);
  for (double a : {0.0, 1e-6, 0.3, M_PI / 2, 2.5, M_PI - 1e-6}) {
    const Eigen::Matrix3d R_WP =
        R_WB * Eigen::AngleAxisd(a, swing_axis_B).toRotationMatrix() * Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(JointSwingAngle(R_WB, R_WP), a, 1e-14) << "swing " << a;
  }
}

// The bench's attitude landing (bench/lander_bench.cpp, BM_LanderCaseA_Attitude_1s) at the tests'
// 16 segments: rolled and pitched 5 deg at release, 0.5 m/s forward, LP under every pad, the soils
// as shipped (their dynamic term), 1 s.
LanderRunResult SlidingLanding(const std::optional<ConeLimit>& cone) {
  test::PaperLander setup = test::MakePaperLander('A', test::kTestAngularSegments, 0.10, /*shipped_soils=*/true);
  for (Leg& leg : setup.model.legs) leg.cone = cone;
  LanderInitialState& s = setup.initial;
  s.R_WB = (Eigen::AngleAxisd(5.0 * kDeg, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(5.0 * kDeg, Eigen::Vector3d::UnitY()))
               .toRotationMatrix();
  for (Eigen::Matrix3d& R_WP : s.R_WP) R_WP = s.R_WB;
  s.v_WB_W = Eigen::Vector3d(0.5, 0.0, 0.0);
  s.p_WB.z() = BodyHeightForClearance(setup.model, setup.terrain, s, setup.drop_height_m);
  setup.options.duration_s = 1.0;
  return SimulateLander(setup);
}

Eigen::Matrix3d Rotation(const Eigen::Vector4d& q_wxyz) {
  return Eigen::Quaterniond(q_wxyz[0], q_wxyz[1], q_wxyz[2], q_wxyz[3]).toRotationMatrix();
}

// The largest swing over the trace's samples, from their quaternions.
double LargestSampledSwing(const LanderRunResult& r) {
  double largest = 0.0;
  for (const LanderSample& x : r.trace)
    for (int i = 0; i < kNumLegs; ++i) largest = std::max(largest, JointSwingAngle(Rotation(x.q_WB), Rotation(x.q_WP[i])));
  return largest;
}

double EnergyBalanceError(const LanderRunResult& r) {
  return r.final_kinetic_J + r.final_potential_J + r.dissipated_J - r.initial_energy_J;
}

TEST(JointSwing, FreePadsOfASlidingLandingTurnPastEdgeOnAndAConeStopHoldsThem) {
  const LanderRunResult free_joints = SlidingLanding(std::nullopt);
  constexpr double kHalfAngle = 30.0 * kDeg, kStiffness = 20.0, kDamping = 0.02;
  const LanderRunResult stopped = SlidingLanding(ConeLimit{kHalfAngle, kStiffness, kDamping});
  for (const LanderRunResult* r : {&free_joints, &stopped}) {
    // The run's record is the largest swing at its samples and events, which the trace holds (the
    // sample's attitude from the normalised quaternion, the record's from the pose: rounding apart).
    EXPECT_NEAR(r->max_joint_swing_rad, LargestSampledSwing(*r), 1e-9);
    EXPECT_FALSE(r->tipped_over);
    const double turned_over = r->initial_energy_J - r->final_potential_J;
    EXPECT_NEAR(EnergyBalanceError(*r), 0.0, 1e-5 * turned_over);
  }
  std::printf("[ swing    ] free joints %.1f deg, 30 deg stop %.1f deg; energy balance %.2g / %.2g J\n",
              free_joints.max_joint_swing_rad / kDeg, stopped.max_joint_swing_rad / kDeg,
              EnergyBalanceError(free_joints), EnergyBalanceError(stopped));
  EXPECT_GT(free_joints.max_joint_swing_rad, 90.0 * kDeg);
  // Over-travel: the soil moment on a pad (about 1 N m) over the stop stiffness, a few degrees.
  EXPECT_LT(stopped.max_joint_swing_rad, kHalfAngle + 5.0 * kDeg);
  EXPECT_GT(stopped.max_joint_swing_rad, kHalfAngle);
}

}  // namespace
}  // namespace touchdown::lander
