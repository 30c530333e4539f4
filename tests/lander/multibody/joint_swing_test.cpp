// The pads' swing on their ball joints: JointSwingAngle against its closed form, the largest swing a
// run records (LanderRunResult::max_joint_swing_rad) against its own trace, and the cone limit that
// bounds it, on a sliding landing of the paper's lander (fixtures/paper_lander.h):
// with free joints its pads turn past edge-on; a cone stop holds them near its half angle, and the
// energy balance still closes with the stop's potential energy.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
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
LanderRunResult SlidingLanding(const std::optional<ConeLimit>& cone, bool stops_as_modes = true) {
  test::PaperLander setup = test::MakePaperLander('A', test::kTestAngularSegments, 0.10, /*shipped_soils=*/true);
  for (Leg& leg : setup.model.legs) leg.cone = cone;
  setup.options.joint_stops_as_modes = stops_as_modes;
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

// The stops as modes of the hybrid run (LanderRunOptions::joint_stops_as_modes): each pad reaches its
// cone at an event where its swing is the half angle to the root's location, and leaves it at one
// 100 rtol inside, alternately; the landing is the one with the torque switched on by the angle inside
// the steps (the same model up to that band) to the integration tolerance (rtol 1e-7; measured
// 1.6e-6 of a depth, 1.7e-6 deg of pitch, 4e-6 deg of the largest swing), in fewer steps (1,350
// against 1,452: the stop's damping no longer switches on inside a step).
TEST(JointSwing, AStopAsAModeIsReachedAndLeftAtItsHalfAngle) {
  constexpr double kHalfAngle = 30.0 * kDeg, kStiffness = 20.0, kDamping = 0.02;
  const ConeLimit cone{kHalfAngle, kStiffness, kDamping};
  const LanderRunResult modes = SlidingLanding(cone), by_angle = SlidingLanding(cone, /*stops_as_modes=*/false);
  std::array<int, kNumLegs> reached{}, left{};
  for (const LanderEvent& e : modes.events) {
    if (e.kind != LanderEventKind::kStopReached && e.kind != LanderEventKind::kStopLeft) continue;
    const bool reaching = e.kind == LanderEventKind::kStopReached;
    // Alternately reached and left, starting clear of the stop.
    EXPECT_EQ(reached[e.leg], left[e.leg] + (reaching ? 0 : 1)) << "pad " << e.leg << " at " << e.t_s;
    ++(reaching ? reached : left)[e.leg];
    // The sample the run records at the event (before its modes change).
    const auto at = std::find_if(modes.trace.begin(), modes.trace.end(), [&](const LanderSample& x) { return x.t_s == e.t_s; });
    ASSERT_NE(at, modes.trace.end());
    // Reached at the rim; left 100 rtol inside it (StopHysteresis, lander_hybrid.cpp; rtol 1e-7 here).
    const double where = reaching ? kHalfAngle : kHalfAngle - 100.0 * LanderRunOptions{}.integrator.rtol;
    EXPECT_NEAR(JointSwingAngle(Rotation(at->q_WB), Rotation(at->q_WP[e.leg])), where, 1e-8) << e.t_s;
  }
  int stops = 0;
  for (int i = 0; i < kNumLegs; ++i) stops += reached[i];
  EXPECT_GT(stops, 0);
  for (const LanderEvent& e : by_angle.events)
    EXPECT_TRUE(e.kind != LanderEventKind::kStopReached && e.kind != LanderEventKind::kStopLeft);
  std::printf("[ stops    ] %d stops reached; steps as modes %ld, by angle %ld\n", stops, modes.solver.steps,
              by_angle.solver.steps);
  ASSERT_EQ(modes.tipped_over, by_angle.tipped_over);
  for (int i = 0; i < kNumLegs; ++i)
    EXPECT_NEAR(modes.final_penetration_m[i], by_angle.final_penetration_m[i], 1e-5 * by_angle.final_penetration_m[i]) << i;
  EXPECT_NEAR(modes.final_attitude.roll_rad, by_angle.final_attitude.roll_rad, 1e-5 * kDeg);
  EXPECT_NEAR(modes.final_attitude.pitch_rad, by_angle.final_attitude.pitch_rad, 1e-5 * kDeg);
  EXPECT_NEAR(modes.max_joint_swing_rad, by_angle.max_joint_swing_rad, 1e-4 * kDeg);
  EXPECT_LT(modes.solver.steps, by_angle.solver.steps);
}

}  // namespace
}  // namespace touchdown::lander
