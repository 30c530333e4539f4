// The lander's structured Jacobian (lander_jacobian.h) against central difference quotients of the
// whole right-hand side, on case B a few milliseconds into the contact (every pad free and
// rocking in the soil), and what it costs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "lander/multibody/lander_jacobian.h"
#include "lander/multibody/lander_simulation.h"
#include "rft/ground.h"
#include "fixtures/paper_lander.h"
#include "tests/malloc_counter.h"

namespace touchdown::lander {
namespace {

struct RockingState {
  test::PaperLander setup = test::MakePaperLander('B');
  StateLayout layout{setup.model};
  Eigen::VectorXd y;
  Eigen::VectorXd f;  // the right-hand side at y
};

// Case B 4 ms after the first touchdown: all four pads in the soil, none held yet.
const RockingState& Rocking() {
  static const RockingState state = [] {
    RockingState s;
    s.y = test::StateAfterFirstTouchdown(s.setup, 0.004);
    s.f = test::FreeModesRhs(s.setup, s.layout, s.y);
    return s;
  }();
  return state;
}

// The same on a 10 deg slope falling along +y, 60 ms after the first touchdown: the contacts see the
// joints' positions through their depths below an inclined plane (every pad in the soil, checked below).
const RockingState& RockingOnASlope() {
  static const RockingState state = [] {
    RockingState s;
    s.setup.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, 0.0, -std::tan(10.0 * M_PI / 180.0));
    s.setup.initial.p_WB.z() =
        BodyHeightForClearance(s.setup.model, s.setup.terrain, s.setup.initial, s.setup.drop_height_m);
    s.y = test::StateAfterFirstTouchdown(s.setup, 0.06);
    s.f = test::FreeModesRhs(s.setup, s.layout, s.y);
    return s;
  }();
  return state;
}

Eigen::VectorXd Rhs(const RockingState& s, const Eigen::VectorXd& y) { return test::FreeModesRhs(s.setup, s.layout, y); }

// Central differences of the whole right-hand side, every contact evaluated again, step 1e-7 in SI
// units.
Eigen::MatrixXd CentralDifferences(const RockingState& s) {
  const int n = s.layout.size;
  Eigen::MatrixXd reference(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd plus = s.y, minus = s.y;
    plus[j] += 1e-7, minus[j] -= 1e-7;
    reference.col(j) = (Rhs(s, plus) - Rhs(s, minus)) / 2e-7;
  }
  return reference;
}

// The Jacobian at the rocking state; `attitude`: LanderJacobianData::attitude_sensitivity.
Eigen::MatrixXd RockingJacobian(const RockingState& s, bool attitude, long* contacts) {
  const int n = s.layout.size;
  LanderData data;
  LanderJacobianData work;
  work.attitude_sensitivity = attitude;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  LanderJacobian(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, Eigen::VectorXd::Ones(n), &data, &work,
                 J);
  *contacts = work.contact_evaluations;
  return J;
}

// Worst error of column j of J against the reference, relative to the column's size, beyond the
// rounding of J's own one-sided quotient: an evaluation rounds every row at a few ulps of the
// largest terms it sums (the pads' moments, 1e3 in the pads' rows), and the quotient divides that
// by its step h_j = sqrt(eps) max(|y_j|, 1) (LanderJacobian's step at unit scales): 1.5e-5 for one
// ulp of 1e3, whatever the column. Columns whose reference is below 1e-3 (in their rows' units: the
// body's x and y change nothing on a level bed, exactly 0) are compared absolutely.
double ColumnError(const RockingState& s, const Eigen::MatrixXd& J, const Eigen::MatrixXd& reference, int j) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double h = std::sqrt(eps) * std::max(std::abs(s.y[j]), 1.0);
  const double rounding = 4.0 * eps * s.f.cwiseAbs().maxCoeff() / h;
  const Eigen::ArrayXd beyond = ((J.col(j) - reference.col(j)).cwiseAbs().array() - rounding).max(0.0);
  return beyond.matrix().norm() / std::max(reference.col(j).norm(), 1e-3);
}

// Worst column error of the Jacobian at `s` against central differences; asserts every pad is in the soil.
double WorstColumnError(const RockingState& s, bool attitude, long* contacts) {
  for (int i = 0; i < kNumLegs; ++i)
    EXPECT_GT(PadDepth(s.setup.model, s.setup.terrain, i, ComputePose(s.setup.model, s.layout, s.y).pads[i]), 0.0) << i;
  const Eigen::MatrixXd J = RockingJacobian(s, attitude, contacts);
  const Eigen::MatrixXd reference = CentralDifferences(s);
  double worst = 0.0;
  for (int j = 0; j < s.layout.size; ++j) worst = std::max(worst, ColumnError(s, J, reference, j));
  return worst;
}

// On level ground and on a slope, where the joint's horizontal position changes its depth (the x and y
// columns of a pad's sensitivity are then its depth column times the plane's slope, exact as the
// level bed's zeros are).
TEST(LanderJacobian, MatchesCentralDifferencesOfTheWholeRightHandSide) {
  for (const bool slope : {false, true}) {
    long contacts = 0;
    // The chain rule through each pad's motion (joint position and velocity, attitude, spin) and the
    // frozen wrenches of the other pads are first-order exact, so what is left is the difference
    // quotients' own error (one-sided, sqrt(eps) steps).
    const double worst = WorstColumnError(slope ? RockingOnASlope() : Rocking(), true, &contacts);
    std::printf("[ jacobian ] %s: worst column error %.2e relative\n", slope ? "10 deg slope" : "level", worst);
    EXPECT_LT(worst, 3e-5) << slope;  // measured 1.7e-5 level, 1.3e-6 on the slope
    // One evaluation of all four (the base point), then ten per pad for its motion (over a plane the
    // joint's position counts only through its depth: one quotient, not three): 44, where difference
    // quotients of the whole right-hand side would evaluate 4 x 42 = 168.
    EXPECT_EQ(contacts, kNumLegs + kNumLegs * 10) << slope;
  }
}

// SimulateLander's Jacobian leaves out the contact's derivatives with respect to the pads'
// attitudes: seven contacts per pad (nine off a plane). Every column but the pads' quaternions' is
// the same as above; those lose the soil's moment gradient (not stiff at the steps taken,
// lander_jacobian.h).
TEST(LanderJacobian, WithoutAttitudeSensitivityCostsSevenContactsPerPad) {
  const RockingState& s = Rocking();
  long contacts = 0;
  const Eigen::MatrixXd J = RockingJacobian(s, false, &contacts);
  EXPECT_EQ(contacts, kNumLegs + kNumLegs * 7);
  const Eigen::MatrixXd reference = CentralDifferences(s);
  double worst = 0.0, worst_attitude = 0.0;
  for (int j = 0; j < s.layout.size; ++j) {
    bool pad_attitude = false;
    for (int i = 0; i < kNumLegs; ++i) pad_attitude |= j >= s.layout.quat_WP(i) && j < s.layout.quat_WP(i) + 4;
    (pad_attitude ? worst_attitude : worst) = std::max(pad_attitude ? worst_attitude : worst, ColumnError(s, J, reference, j));
  }
  EXPECT_LT(worst, 3e-5);
  EXPECT_GT(worst_attitude, 0.1);  // what is left out is not small: it is not stiff
}

// House style: nothing allocates in a Jacobian once its scratch exists (the first call sizes it),
// with and without the evaluation at y given.
TEST(LanderJacobian, DoesNotAllocateOnceItsScratchExists) {
  if (!testing_alloc::kCountsMalloc) GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
  const RockingState& s = Rocking();
  const int n = s.layout.size;
  LanderData data;
  LanderJacobianData work;
  LanderEvaluation at_y;
  EvaluateLander(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, &at_y, &data);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd scale = Eigen::VectorXd::Ones(n);
  auto jacobian = [&](const LanderEvaluation* given) {
    LanderJacobian(s.setup.model, s.layout, s.setup.terrain, LanderModes{}, s.y, scale, &data, &work, J, given);
  };
  jacobian(nullptr);
  EXPECT_EQ(testing_alloc::CountAllocations([&] {
              jacobian(nullptr);
              jacobian(&at_y);
            }),
            0);
  // Given the evaluation at y, the same Jacobian without its four base contacts.
  const Eigen::MatrixXd evaluated = J;
  const long before = work.contact_evaluations;
  J.setZero();
  jacobian(&at_y);
  EXPECT_EQ(work.contact_evaluations - before, kNumLegs * 10);
  EXPECT_EQ(J, evaluated);
}

}  // namespace
}  // namespace touchdown::lander
