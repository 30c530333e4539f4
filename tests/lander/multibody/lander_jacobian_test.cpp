// The lander's structured Jacobian (lander_jacobian.h) against central difference quotients of the
// whole right-hand side, on case B a few milliseconds into the contact (every pad free and
// rocking in the soil), and what it costs.
#include <gtest/gtest.h>

#include "lander/multibody/lander_jacobian.h"
#include "tests/lander/multibody/paper_lander.h"

namespace touchdown::lander {
namespace {

struct RockingState {
  test::PaperLander setup = test::MakePaperLander('B');
  StateLayout layout{setup.model};
  Eigen::VectorXd y;
};

// Case B 4 ms after the first touchdown: all four pads in the soil, none held yet.
const RockingState& Rocking() {
  static const RockingState state = [] {
    RockingState s;
    s.y = test::StateAfterFirstTouchdown(s.setup, 0.004);
    return s;
  }();
  return state;
}

Eigen::VectorXd Rhs(const RockingState& s, const Eigen::VectorXd& y) { return test::FreeModesRhs(s.setup, s.layout, y); }

TEST(LanderJacobian, MatchesCentralDifferencesOfTheWholeRightHandSide) {
  const RockingState& s = Rocking();
  const int n = s.layout.size;
  for (int i = 0; i < kNumLegs; ++i)
    ASSERT_GT(PadDepth(s.setup.model, s.setup.terrain, i, ComputePose(s.setup.model, s.layout, s.y).pads[i]), 0.0);
  LanderData data;
  LanderJacobianData work;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  LanderJacobian(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, Eigen::VectorXd::Ones(n), &data, &work,
                 J);
  // Reference: central differences, every contact evaluated again, step 1e-7 in SI units.
  Eigen::MatrixXd reference(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd plus = s.y, minus = s.y;
    plus[j] += 1e-7, minus[j] -= 1e-7;
    reference.col(j) = (Rhs(s, plus) - Rhs(s, minus)) / 2e-7;
  }
  // Column by column, relative to the column's size: the chain rule through the joints' motion
  // and the frozen wrenches of the other pads are first-order exact, so what is left is the
  // difference quotients' own error (one-sided, sqrt(eps) steps).
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {
    const double size = std::max(reference.col(j).norm(), 1e-6);
    worst = std::max(worst, (J.col(j) - reference.col(j)).norm() / size);
  }
  std::printf("[ jacobian ] worst column error %.2e relative\n", worst);
  EXPECT_LT(worst, 3e-5);  // measured 5.9e-6
}

TEST(LanderJacobian, CostsThirteenContactsPerPadInTheSoil) {
  const RockingState& s = Rocking();
  const int n = s.layout.size;
  LanderData data;
  LanderJacobianData work;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  LanderJacobian(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, Eigen::VectorXd::Ones(n), &data, &work,
                 J);
  // One evaluation of all four (the base point), then per pad six for the joint's motion and
  // seven for its own attitude and spin: 56, where difference quotients of the whole right-hand
  // side would evaluate 4 x 42 = 168.
  EXPECT_EQ(work.contact_evaluations, kNumLegs + kNumLegs * (6 + 7));
}

}  // namespace
}  // namespace touchdown::lander
