// The lander's equations of motion on their own: free flight conserves energy and momentum
// (checks the mass matrix, the Jacobians and the velocity-product terms), joints stay exact.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_simulation.h"
#include "fixtures/paper_lander.h"

namespace touchdown::lander {
namespace {

struct Momenta {
  Eigen::Vector3d linear, angular_about_com;
};

Momenta ComputeMomenta(const LanderModel& m, const StateLayout& L, const Eigen::VectorXd& y) {
  const LanderPose p = ComputePose(m, L, y);
  struct Body {
    double mass;
    Eigen::Vector3d x, v, w;
    Eigen::Matrix3d I;
  };
  std::vector<Body> bodies{{m.body_mass_kg, p.p_WB, p.v_WB_W, p.w_WB_W, p.R_WB * m.body_inertia_B * p.R_WB.transpose()}};
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = p.pads[i];
    bodies.push_back({m.legs[i].pad->mass_kg, f.p_WJ + f.c_JC_W, f.v_WJ_W + f.w_WP_W.cross(f.c_JC_W), f.w_WP_W,
                      f.R_WP * m.legs[i].pad->inertia_com_B * f.R_WP.transpose()});
  }
  Eigen::Vector3d com = Eigen::Vector3d::Zero(), vcom = Eigen::Vector3d::Zero();
  for (const Body& b : bodies) com += b.mass * b.x, vcom += b.mass * b.v;
  com /= m.TotalMass();
  vcom /= m.TotalMass();
  Momenta out{m.TotalMass() * vcom, Eigen::Vector3d::Zero()};
  for (const Body& b : bodies) out.angular_about_com += b.I * b.w + b.mass * (b.x - com).cross(b.v - vcom);
  return out;
}

TEST(LanderDynamics, FreeFlightConservesEnergyAndMomentum) {
  test::PaperLander setup = test::MakePaperLander('A');
  // High above the ground, tumbling, pads spinning about their own joints.
  setup.initial.p_WB.z() = 100.0;
  setup.initial.w_WB_W = Eigen::Vector3d(1.5, -2.0, 3.0);
  setup.initial.v_WB_W = Eigen::Vector3d(0.3, 0.0, -1.0);
  LanderRunOptions& options = setup.options;
  options.duration_s = 0.3;
  // Conservation is a property of the equations: check it at a tolerance far below the default's.
  options.integrator.rtol = 1e-10;
  const StateLayout L(setup.model);
  const LanderRunResult r = SimulateLander(setup);
  ASSERT_FALSE(r.first_touchdown_s);
  const double E0 = r.initial_energy_J;
  EXPECT_NEAR(r.final_kinetic_J + r.final_potential_J, E0, 1e-8 * std::abs(E0));
  EXPECT_NEAR(r.dissipated_J, 0.0, 1e-12);

  // Linear momentum changes by M g t; angular momentum about the CoM is conserved.
  Eigen::VectorXd y0 = r.final_state;  // rebuild the initial state through a zero-length run
  LanderSetup zero = setup;
  zero.options.duration_s = 1e-9;
  const Eigen::VectorXd y_start = SimulateLander(zero).final_state;
  const Momenta a = ComputeMomenta(setup.model, L, y_start), b = ComputeMomenta(setup.model, L, y0);
  const double M = setup.model.TotalMass(), g = setup.model.gravity_m_s2;
  EXPECT_NEAR((b.linear - a.linear - Eigen::Vector3d(0, 0, -M * g * (options.duration_s - zero.options.duration_s))).norm(),
              0.0, 1e-7);
  EXPECT_LT((b.angular_about_com - a.angular_about_com).norm(), 1e-8 * a.angular_about_com.norm());
  EXPECT_GT(a.angular_about_com.norm(), 0.01);  // the check is not vacuous
}

// An evaluation that reuses the position terms (mass matrix factor, the holds' constraint
// decomposition) of one at the same positions gives what forming them again gives, bit for bit:
// case B rocking in the soil with every pad free, and case A at rest with two pads held and its
// speeds set going, each at speeds other than the kept evaluation's.
TEST(LanderDynamics, ReusedPositionTermsGiveTheSameEvaluationBitForBit) {
  struct Case {
    const char* name;
    test::PaperLander setup;
    Eigen::VectorXd y;
    LanderModes modes;
  };
  std::vector<Case> cases;
  {
    Case rocking{"case B rocking, pads free", test::MakePaperLander('B'), {}, {}};
    rocking.y = test::StateAfterFirstTouchdown(rocking.setup, 0.004);
    cases.push_back(rocking);
    Case held{"case A, pads 1 and 3 held", test::MakePaperLander('A'), {}, {}};
    held.setup.options.duration_s = 0.4;
    held.y = SimulateLander(held.setup).final_state;
    held.modes.pad[0] = held.modes.pad[2] = PadMode::kHeld;
    cases.push_back(held);
  }
  for (const Case& c : cases) {
    const StateLayout L(c.setup.model);
    LanderData kept;
    LanderEvaluation e;
    EvaluateLander(c.setup.model, L, c.setup.terrain, c.modes, c.y, &e, &kept, nullptr, PositionTerms::kKeep);
    for (int k = 0; k < 5; ++k) {
      Eigen::VectorXd moved = c.y;
      for (int j = 0; j < L.nu; ++j) moved[L.nq + j] += 0.01 * std::sin(1.0 + 7.0 * k + 3.0 * j);
      LanderEvaluation reused, formed;
      LanderData scratch;
      EvaluateLander(c.setup.model, L, c.setup.terrain, c.modes, moved, &reused, &kept, nullptr, PositionTerms::kReuse);
      EvaluateLander(c.setup.model, L, c.setup.terrain, c.modes, moved, &formed, &scratch);
      EXPECT_EQ(reused.u_dot, formed.u_dot) << c.name << ", speeds " << k;
      EXPECT_GT((formed.u_dot - e.u_dot).norm(), 0.0) << c.name;  // the speeds did change the evaluation
      for (int i = 0; i < kNumLegs; ++i) {
        EXPECT_EQ(reused.soil[i].force_W, formed.soil[i].force_W) << c.name;
        EXPECT_EQ(reused.soil[i].moment_W, formed.soil[i].moment_W) << c.name;
      }
      EXPECT_EQ(reused.dissipation_W, formed.dissipation_W) << c.name;
    }
  }
}

// A held pad's capacity from its integrals (HeldPadCapacity) is QuasiStaticWrench's force at the
// pose they were formed in, bit for bit, in every direction of load: case A at rest in the soil.
// Forming counts one contact; the probes after it none, until the integrals are formed again.
TEST(LanderDynamics, HeldPadCapacityIsTheQuasiStaticForceAtItsPose) {
  test::PaperLander setup = test::MakePaperLander('A');
  setup.options.duration_s = 0.4;
  const Eigen::VectorXd y = SimulateLander(setup).final_state;
  const StateLayout L(setup.model);
  const LanderPose pose = ComputePose(setup.model, L, y);
  for (int i = 0; i < kNumLegs; ++i) {
    ASSERT_GT(PadDepth(setup.model, setup.terrain, i, pose.pads[i]), 0.0) << "pad " << i + 1;
    HeldPadCapacity held;
    long contacts = 0;
    for (int k = 0; k < 36; ++k) {
      const double a = k * M_PI / 18.0;
      const Eigen::Vector3d d(std::cos(a), std::sin(a), 0.0);
      const Eigen::Vector3d fast = HeldPadCapacityForce(setup.model, setup.terrain, i, pose.pads[i], d, &held, &contacts);
      EXPECT_EQ(fast, QuasiStaticWrench(setup.model, setup.terrain, i, pose.pads[i], d).force_W)
          << "pad " << i + 1 << " direction " << k;
      EXPECT_GT(-fast.dot(d), 0.0) << "pad " << i + 1 << " direction " << k;  // it resists the push
    }
    EXPECT_EQ(contacts, 1) << "pad " << i + 1;
    held.formed = false;  // as after an event
    HeldPadCapacityForce(setup.model, setup.terrain, i, pose.pads[i], Eigen::Vector3d::UnitX(), &held, &contacts);
    EXPECT_EQ(contacts, 2) << "pad " << i + 1;
  }
}

TEST(LanderDynamics, AttitudeAnglesFollowAerospaceSigns) {
  // Right side (negative y) down: roll > 0. Nose (positive x) up: pitch > 0.
  const Eigen::Matrix3d roll = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_GT((roll * Eigen::Vector3d(0, 1, 0)).z(), 0.0);  // left side up
  EXPECT_NEAR(BodyAttitude(roll).roll_rad, 0.1, 1e-15);
  const Eigen::Matrix3d pitch = Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_GT((pitch * Eigen::Vector3d(1, 0, 0)).z(), 0.0);  // nose up
  EXPECT_NEAR(BodyAttitude(pitch).pitch_rad, 0.1, 1e-15);
  EXPECT_NEAR(BodyAttitude(pitch).tilt_rad, 0.1, 1e-15);
}

TEST(LanderSoilMap, PatchesSelectTheSoil) {
  rft::Terrain t;
  t.soils.resize(2);
  t.patches.push_back({"square", rft::RectanglePolygon(0.0, 0.0, 1.0, 1.0), 1});
  t.patches.push_back({"triangle", {{2.0, 0.0}, {3.0, 0.0}, {2.0, 1.0}}, 1});
  EXPECT_EQ(t.SoilAt(0.5, 0.5), 1);
  EXPECT_EQ(t.SoilAt(1.5, 0.5), 0);
  EXPECT_EQ(t.SoilAt(2.2, 0.2), 1);
  EXPECT_EQ(t.SoilAt(2.8, 0.8), 0);
}

}  // namespace
}  // namespace touchdown::lander
