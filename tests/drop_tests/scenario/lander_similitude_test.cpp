// The paper's similitude (Sutoh et al., RA-L 2017, Sec. IV-A): the 1/6-scale model at the laboratory's
// gravity and the full-scale lander at that gravity / 6 land alike, with lengths x6, masses x216, speeds
// equal, times x6 and forces x36 (docs/lander_dynamics.md, "Similitude"). In RFT with lithostatic zeta
// (zeta proportional to g) and the dynamic term (lambda rho v^2) the stresses are equal at homologous
// points, so the whole landing is homologous: this test lands the shipped laboratory twin and the
// shipped full-scale lander (data/studies/lab_paper_lander_scenario.yaml, lunar_paper_lander_scenario.yaml)
// on the same asymmetric landing and compares.
//
// The full-scale lander runs at exactly 9.81 / 6 = 1.635 m/s^2, not the Moon's 1.62: the similitude is
// exact only at g_lab / 6, and the 0.9 % of gravity the real Moon takes off is a difference of the
// landing, not an error of the scaling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "tests/drop_tests/scenario/lander_test_support.h"
#include "rft/units.h"

namespace touchdown::lander::similitude_test {
namespace {

using units::kDeg;
constexpr double kLength = 6.0, kMass = kLength * kLength * kLength, kTime = kLength, kForce = kLength * kLength;

// Homologous quantities agree to these bounds. Nothing in the simulation breaks the similitude:
// scaled by 4 (a power of two, exact in binary) the right-hand side is the model's to the last bit
// (RightHandSideOfTheModelScaledByFourIsTheModelsToTheLastBit). What remains is rounding where
// quantities of different units meet in one pivoted factorisation (CVODE's dense LU, the
// constraint projection), which the step-size control amplifies into different step sequences
// (1975 and 1723 steps at rtol 1e-6) and so into the integration error: the disagreement falls
// with rtol (pad depths 3e-4, 5.6e-7, 2.5e-8, 1e-9 relative at rtol 1e-6, 1e-9, 1e-10, 1e-12;
// roll 1.4e-4, 8.7e-8, 3.4e-9, 2.3e-10 deg). So the landing is compared at rtol 1e-9, where it
// agrees to (measured) depths 5.6e-7, roll 8.7e-8 deg; pitch 1.06e-6 deg with Newton's convergence
// coefficient 0.03 (LanderRunOptions::integrator), hence the angles' 2e-6. A pad left hanging
// (negative depth) is where the rest event stops it and is not compared.
constexpr double kRtol = 1e-9;
constexpr double kDepth = 5e-6, kRelative = 2e-6;
constexpr double kAngle_deg = 2e-6;

std::string StudyScenario(const std::string& name) {
  return std::string(TOUCHDOWN_SOURCE_DIR) + "/data/studies/" + name + ".yaml";
}

// An asymmetric landing (the same speeds and angles at both scales): a 12 deg slope, 0.6 m/s across
// it, roll and pitch, a heading off the slope, and closely packed soil under pad 1 in a square of
// half width `patch_m`.
void Asymmetric(scenario::LanderScenario& s, double patch_m) {
  s.ground.slope_rad = 12.0 * kDeg;
  s.ground.downhill_azimuth_rad = 0.0;
  s.initial.horizontal_velocity_m_s = Eigen::Vector2d(0.5, -0.35);
  s.initial.roll_rad = 3.0 * kDeg;
  s.initial.pitch_rad = -2.0 * kDeg;
  s.initial.yaw_relative_to_slope_rad = 20.0 * kDeg;
  s.ground.patches = {{"cp_under_pad_1", "fjs1_cp", scenario::UnderPadSquare{1, patch_m}}};
  test::CoarsenPad(s);
}

TEST(LanderSimilitude, ShippedFullScaleLanderIsTheModelScaledBySixInLengthAndTwoHundredSixteenInMass) {
  const scenario::LanderScenario lab = scenario::LoadLanderScenario(StudyScenario("lab_paper_lander_scenario"));
  const scenario::LanderScenario full = scenario::LoadLanderScenario(StudyScenario("lunar_paper_lander_scenario"));
  const scenario::LanderSpec &a = lab.lander, &b = full.lander;
  EXPECT_NEAR(b.total_mass_kg / a.total_mass_kg, kMass, 1e-12 * kMass);
  EXPECT_NEAR(b.cog_height_m / a.cog_height_m, kLength, 1e-12 * kLength);
  const double inertia = kMass * kLength * kLength;
  EXPECT_LT((b.body_inertia_B - inertia * a.body_inertia_B).norm(), 1e-12 * b.body_inertia_B.norm());
  EXPECT_NEAR(b.pad.body.mass_kg / a.pad.body.mass_kg, kMass, 1e-12 * kMass);
  EXPECT_NEAR(b.pad.body.lowest_z_B / a.pad.body.lowest_z_B, kLength, 1e-12 * kLength);
  EXPECT_LT((b.pad.body.inertia_com_B - inertia * a.pad.body.inertia_com_B).norm(), 1e-9 * b.pad.body.inertia_com_B.norm());
  for (int i = 0; i < kNumLegs; ++i) {
    EXPECT_LT((b.legs[i].joint_B - kLength * a.legs[i].joint_B).norm(), 1e-12 * b.legs[i].joint_B.norm());
    EXPECT_LT((b.legs[i].hip_B - kLength * a.legs[i].hip_B).norm(), 1e-12 * b.legs[i].joint_B.norm());
    ASSERT_TRUE(a.legs[i].cone && b.legs[i].cone);
    EXPECT_EQ(b.legs[i].cone->half_angle_rad, a.legs[i].cone->half_angle_rad);
    // Torque per radian: force x length; per radian per second: times time.
    EXPECT_NEAR(b.legs[i].cone->stiffness_N_m_rad / a.legs[i].cone->stiffness_N_m_rad, kForce * kLength, 1e-9);
    EXPECT_NEAR(b.legs[i].cone->damping_N_m_s_rad / a.legs[i].cone->damping_N_m_s_rad, kForce * kLength * kTime, 1e-9);
  }
  EXPECT_DOUBLE_EQ(full.options.duration_s, kTime * lab.options.duration_s);
  EXPECT_DOUBLE_EQ(lab.options.sample_rate_hz, kTime * full.options.sample_rate_hz);
  EXPECT_EQ(full.initial.touchdown_speed_m_s, lab.initial.touchdown_speed_m_s);
  EXPECT_EQ(full.options.integrator.rtol, lab.options.integrator.rtol);
}

// The laboratory model scaled by `k` by the similitude: lengths x k, masses x k^3, inertia x k^5,
// cone-stop stiffness x k^3 (torque per radian) and damping x k^4; gravity / k, times x k.
scenario::LanderScenario Scaled(scenario::LanderScenario s, double k) {
  scenario::LanderSpec& l = s.lander;
  const double mass = k * k * k;
  l.total_mass_kg *= mass;
  l.body_mass_kg *= mass;
  l.body_inertia_B *= mass * k * k;
  l.cog_height_m *= k;
  for (scenario::LanderLegSpec& leg : l.legs) {
    leg.hip_B *= k;
    leg.joint_B *= k;
    if (leg.cone) {
      leg.cone->stiffness_N_m_rad *= mass;
      leg.cone->damping_N_m_s_rad *= mass * k;
    }
  }
  for (geom::ProfilePoint& p : l.pad.profile.points) p.x_m *= k, p.u_m *= k;
  l.pad.mass_kg *= mass;
  l.pad.body.mass_kg *= mass;
  l.pad.body.lowest_z_B *= k;  // CoarsenPad re-meshes the scaled profile about it
  s.gravity_m_s2 /= k;
  s.options.duration_s *= k;
  s.options.sample_rate_hz /= k;
  return s;
}

// Scaling by a power of two is exact in binary floating point, and by 4 even the square roots of
// masses (the mass matrix's Cholesky factor) stay exact: a threshold in fixed metres, newtons or
// seconds anywhere in the body, joint, pad or soil equations would show as a last-bit difference.
// A homologous state with pad 4 in the soil (the soil patch under pad 1, LP under the others).
TEST(LanderSimilitude, RightHandSideOfTheModelScaledByFourIsTheModelsToTheLastBit) {
  constexpr double k = 4.0;
  scenario::LanderScenario lab = scenario::LoadLanderScenario(StudyScenario("lab_paper_lander_scenario"));
  scenario::LanderScenario big = Scaled(lab, k);
  Asymmetric(lab, 0.08);
  Asymmetric(big, k * 0.08);
  const lander::LanderSetup A = scenario::ResolveLander(lab), B = scenario::ResolveLander(big);
  const StateLayout L(A.model);
  ASSERT_EQ(L.size, StateLayout(B.model).size);
  // Lowered 12 mm (x k) from release, turning (rad/s / k), pads tilted on their joints.
  const auto state = [&](const lander::LanderSetup& S, double scale) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(L.size);
    const Eigen::Quaterniond q(S.initial.R_WB);
    y.segment<3>(L.p_WB()) = S.initial.p_WB - Eigen::Vector3d(0.0, 0.0, 0.012 * scale);
    y.segment<4>(L.quat_WB()) << q.w(), q.x(), q.y(), q.z();
    y.segment<3>(L.v_WB_W()) = S.initial.v_WB_W;
    y.segment<3>(L.w_WB_W()) = Eigen::Vector3d(0.3, -0.2, 0.1) / scale;
    for (int i = 0; i < kNumLegs; ++i) {
      const Eigen::Quaterniond p(Eigen::AngleAxisd(0.05 * i, Eigen::Vector3d::UnitX()) * S.initial.R_WB);
      y.segment<4>(L.quat_WP(i)) << p.w(), p.x(), p.y(), p.z();
      y.segment<3>(L.w_WP_W(i)) = Eigen::Vector3d(0.1 * i, 0.2, -0.3) / scale;
    }
    return y;
  };
  const Eigen::VectorXd ya = state(A, 1.0), yb = state(B, k);
  const LanderModes free_pads;
  LanderEvaluation ea, eb;
  EvaluateLander(A.model, L, A.terrain, free_pads, ya, &ea);
  EvaluateLander(B.model, L, B.terrain, free_pads, yb, &eb);
  ASSERT_GT(ea.soil[3].force_W.z(), 1.0);  // pad 4 in the soil
  for (int i = 0; i < kNumLegs; ++i) EXPECT_EQ(eb.soil[i].force_W, k * k * ea.soil[i].force_W) << "pad " << i + 1;
  Eigen::VectorXd da(L.size), db(L.size);
  StateDerivative(L, ya, ea, da);
  StateDerivative(L, yb, eb, db);
  // Per state: d/dt of positions is a speed (x 1), of quaternions a rate (/ k); accelerations / k,
  // angular accelerations / k^2; power (the work state) force x speed, x k^2.
  Eigen::VectorXd unit = Eigen::VectorXd::Constant(L.size, 1.0 / k);
  unit.segment<3>(L.p_WB()).setConstant(1.0);
  unit.segment<3>(L.w_WB_W()).setConstant(1.0 / (k * k));
  for (int i = 0; i < kNumLegs; ++i) unit.segment<3>(L.w_WP_W(i)).setConstant(1.0 / (k * k));
  unit[L.work()] = k * k;
  for (int j = 0; j < L.size; ++j) EXPECT_EQ(db[j], unit[j] * da[j]) << "state " << j;
}

TEST(LanderSimilitude, FullScaleAtASixthOfTheGravityLandsAsTheModelWithDepthsAndTimesTimesSix) {
  scenario::LanderScenario lab = scenario::LoadLanderScenario(StudyScenario("lab_paper_lander_scenario"));
  scenario::LanderScenario full = scenario::LoadLanderScenario(StudyScenario("lunar_paper_lander_scenario"));
  full.gravity_m_s2 = lab.gravity_m_s2 / kLength;  // 1.635, the similitude's exact gravity (not the Moon's 1.62)
  Asymmetric(lab, 0.08);
  Asymmetric(full, kLength * 0.08);
  lab.options.integrator.rtol = full.options.integrator.rtol = kRtol;
  // Every state at its own scale: the studies' looser pad spins (a resolution like rtol) would leave
  // the two runs 3e-6 deg apart instead of at the tolerance's 1e-6.
  lab.options.pad_spin_tolerance_factor = full.options.pad_spin_tolerance_factor = 1.0;
  const LanderRunResult a = scenario::RunLanderScenario(lab).result;
  const LanderRunResult b = scenario::RunLanderScenario(full).result;

  double depth = 0.0, force = 0.0;
  for (int i = 0; i < kNumLegs; ++i) {
    std::printf("[ similitude ] pad %d: depth %.9f mm x6 = %.9f mm full scale; peak force %.6f N x36 = %.6f N\n", i + 1,
                a.final_penetration_m[i] * 1e3, b.final_penetration_m[i] * 1e3, a.peak_pad_force_N[i],
                b.peak_pad_force_N[i] / kForce);
    if (a.final_penetration_m[i] > 0.0)
      depth = std::max(depth, std::abs(b.final_penetration_m[i] / (kLength * a.final_penetration_m[i]) - 1.0));
    force = std::max(force, std::abs(b.peak_pad_force_N[i] / (kForce * a.peak_pad_force_N[i]) - 1.0));
    ASSERT_EQ(a.touchdown_time_s[i].has_value(), b.touchdown_time_s[i].has_value());
    if (a.touchdown_time_s[i]) {
      EXPECT_NEAR(*b.touchdown_time_s[i] / (kTime * *a.touchdown_time_s[i]), 1.0, kRelative);
    }
  }
  const auto deg = [](double rad) { return rad / kDeg; };
  std::printf("[ similitude ] roll %.9f / %.9f deg, pitch %.9f / %.9f deg, max tilt %.9f / %.9f deg, "
              "max swing %.6f / %.6f deg\n",
              deg(a.final_attitude.roll_rad), deg(b.final_attitude.roll_rad), deg(a.final_attitude.pitch_rad),
              deg(b.final_attitude.pitch_rad), deg(a.max_tilt_rad), deg(b.max_tilt_rad), deg(a.max_joint_swing_rad),
              deg(b.max_joint_swing_rad));
  std::printf("[ similitude ] rest %.9f s x6 = %.9f s; steps %ld / %ld; depth ratio off by %.2e, peak force by %.2e\n",
              a.rest_time_s.value_or(-1.0), b.rest_time_s.value_or(-1.0) / kTime, long(a.solver.steps),
              long(b.solver.steps), depth, force);

  EXPECT_EQ(a.tipped_over, b.tipped_over);
  EXPECT_LT(depth, kDepth);
  EXPECT_LT(force, kRelative);
  EXPECT_NEAR(deg(b.final_attitude.roll_rad), deg(a.final_attitude.roll_rad), kAngle_deg);
  EXPECT_NEAR(deg(b.final_attitude.pitch_rad), deg(a.final_attitude.pitch_rad), kAngle_deg);
  EXPECT_NEAR(deg(b.final_attitude.yaw_rad), deg(a.final_attitude.yaw_rad), kAngle_deg);
  EXPECT_NEAR(deg(b.max_tilt_rad), deg(a.max_tilt_rad), kAngle_deg);
  EXPECT_NEAR(deg(b.max_joint_swing_rad), deg(a.max_joint_swing_rad), kAngle_deg);
  // Not a trivial landing: it ends tilted and a pad swings several degrees on its joint.
  EXPECT_GT(std::abs(deg(a.final_attitude.roll_rad)) + std::abs(deg(a.final_attitude.pitch_rad)), 1.0);
  EXPECT_GT(deg(a.max_joint_swing_rad), 5.0);
  ASSERT_EQ(a.rest_time_s.has_value(), b.rest_time_s.has_value());
  if (a.rest_time_s) {
    EXPECT_NEAR(*b.rest_time_s / (kTime * *a.rest_time_s), 1.0, kRelative);
  }
  EXPECT_NEAR(b.dissipated_J / (kMass * a.dissipated_J), 1.0, kRelative);
}

}  // namespace
}  // namespace touchdown::lander::similitude_test
