// Janosi's shear displacement j as a state of the lander's pads (lander_dynamics.h, StateLayout's
// shear states): only on a terrain with a Bekker soil with shear; a sideways landing on one
// balances its energy and comes to rest with j grown by the pads' slip; the structured Jacobian
// still matches central differences with the j rows and columns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lander/multibody/lander_jacobian.h"
#include "lander/multibody/lander_simulation.h"
#include "rft/bekker_law.h"
#include "rft/units.h"
#include "fixtures/paper_lander.h"

namespace touchdown::lander {
namespace {

// data/soils/lunar_nominal_bekker.yaml (n = 1, k_c = 1.4 kN/m^2, k_phi = 820 kN/m^3, c = 0.17 kPa,
// phi = 35 deg, K = 18 mm), for the paper lander's pad.
test::PaperLander JanosiLander(double sideways_m_s) {
  test::PaperLander setup = test::MakePaperLander('A');
  rft::SoilParameters s;
  s.name = "lunar_nominal_bekker";
  s.rft_law_3d = rft::LawKind::kBekker;
  s.bekker = {1.0, 1.4e3, 820e3, 170.0, 35.0 * units::kDeg, 0.018};
  setup.terrain.soils = {{s.name, rft::MakeSoilContactModel(rft::LawKind::kBekker, s, 9.81, {}, &setup.model.legs[0].pad->surface)}};
  setup.initial.v_WB_W.x() = sideways_m_s;
  return setup;
}

TEST(LanderJanosi, PadsCarryJOnlyOnABekkerSoilWithShear) {
  const test::PaperLander rft_lander = test::MakePaperLander('B');
  EXPECT_FALSE(HasJanosiShear(rft_lander.terrain));
  const test::PaperLander bekker = JanosiLander(0.0);
  ASSERT_TRUE(HasJanosiShear(bekker.terrain));
  const StateLayout plain(bekker.model), with_j(bekker.model, true);
  EXPECT_EQ(with_j.size, plain.size + kNumLegs);
  EXPECT_EQ(with_j.shear(0), plain.work() + 1);
}

TEST(LanderJanosi, SidewaysLandingBalancesEnergyAndAccumulatesSlip) {
  test::PaperLander setup = JanosiLander(0.3);
  setup.options.duration_s = 1.0;
  const LanderRunResult r = SimulateLander(setup);
  const StateLayout L(setup.model, true);
  ASSERT_EQ(r.final_state.size(), L.size);
  EXPECT_FALSE(r.tipped_over);
  const double turned_over = r.initial_energy_J - r.final_potential_J;
  EXPECT_NEAR(r.final_kinetic_J + r.final_potential_J + r.dissipated_J, r.initial_energy_J, 1e-5 * turned_over);
  // Every pad slid in the soil before its capture: j > 0, and no more than the body's travel.
  for (int i = 0; i < kNumLegs; ++i) {
    const double j = r.final_state[L.shear(i)];
    EXPECT_GT(j, 1e-4) << "pad " << i + 1;
    EXPECT_LT(j, 0.3 * 1.0) << "pad " << i + 1;  // at most the body's sideways speed times the run
  }
}

// A sideways landing 4 ms after the first touchdown: every pad free and sliding in the soil.
struct JanosiSlidingState {
  test::PaperLander setup = JanosiLander(0.3);
  StateLayout layout{setup.model, true};
  Eigen::VectorXd y;
};

const JanosiSlidingState& JanosiSliding() {
  static const JanosiSlidingState state = [] {
    JanosiSlidingState s;
    s.y = test::StateAfterFirstTouchdown(s.setup, 0.004);
    return s;
  }();
  return state;
}

Eigen::VectorXd JanosiRhs(const JanosiSlidingState& s, const Eigen::VectorXd& y) {
  return test::FreeModesRhs(s.setup, s.layout, y);
}

TEST(LanderJanosi, JacobianMatchesCentralDifferencesWithTheShearStates) {
  const JanosiSlidingState& s = JanosiSliding();
  const int n = s.layout.size;
  ASSERT_EQ(s.y.size(), n);
  const LanderPose pose = ComputePose(s.setup.model, s.layout, s.y);
  for (int i = 0; i < kNumLegs; ++i) {
    ASSERT_GT(PadDepth(s.setup.model, s.setup.terrain, i, pose.pads[i]), 0.0);
    // Mid-ramp: the shear is still mobilising (j of the order of K), so the j columns matter.
    ASSERT_GT(s.y[s.layout.shear(i)], 0.0);
    ASSERT_LT(s.y[s.layout.shear(i)], 0.018 * 3.0);
  }
  LanderData data;
  LanderJacobianData work;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  LanderJacobian(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, Eigen::VectorXd::Ones(n), &data, &work,
                 J);
  Eigen::MatrixXd reference(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd plus = s.y, minus = s.y;
    plus[j] += 1e-7, minus[j] -= 1e-7;
    reference.col(j) = (JanosiRhs(s, plus) - JanosiRhs(s, minus)) / 2e-7;
  }
  // Column by column, relative to the column's size (as tests/lander/multibody/lander_jacobian_test.cpp).
  auto column_error = [&](int j) {
    return (J.col(j) - reference.col(j)).norm() / std::max(reference.col(j).norm(), 1e-6);
  };
  double worst = 0.0, worst_j = 0.0;
  int worst_column = -1;
  for (int j = 0; j < n; ++j)
    if (column_error(j) > worst) worst = column_error(j), worst_column = j;
  for (int i = 0; i < kNumLegs; ++i) worst_j = std::max(worst_j, column_error(s.layout.shear(i)));
  // The j rows: dj/dt = |horizontal joint velocity| against every state.
  double worst_row = 0.0;
  for (int i = 0; i < kNumLegs; ++i) {
    const int r = s.layout.shear(i);
    worst_row = std::max(worst_row, (J.row(r) - reference.row(r)).norm() / std::max(reference.row(r).norm(), 1e-6));
  }
  std::printf("[ jacobian ] sliding with j: worst column %.2e (state %d), j columns %.2e, j rows %.2e relative\n", worst,
              worst_column, worst_j, worst_row);
  // Measured in a body attitude column (a quaternion component): 4.7e-4 with gcc, 1.0e-3 with clang
  // (the sanitizer build). It is the one-sided difference quotients of each pad's contact with
  // respect to its motion that the chain rule builds on (lander_jacobian.h), in a sliding contact
  // where the shear's direction turns with the slip; 2.0e-4 before the chain rule. A missing
  // coupling would be of order 1. The j rows and columns 4e-7 and below.
  EXPECT_LT(worst, 3e-3);
  EXPECT_LT(worst_j, 3e-5);
  EXPECT_LT(worst_row, 3e-5);
  // The j columns are not empty: a pad's j moves its own shear force.
  for (int i = 0; i < kNumLegs; ++i) EXPECT_GT(reference.col(s.layout.shear(i)).norm(), 1.0) << "pad " << i + 1;
}

}  // namespace
}  // namespace touchdown::lander
