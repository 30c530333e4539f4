// The lander's right-hand side allocates nothing while pads are held (house style: no allocation
// in a right-hand side): EvaluateLander with its LanderData, then StateDerivative, through the
// constraint solve of four held pads. malloc itself is counted, so Eigen's heap buffers count as
// well as operator new.
#include <gtest/gtest.h>

#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_simulation.h"
#include "fixtures/paper_lander.h"
#include "tests/malloc_counter.h"

namespace touchdown::lander {
namespace {

TEST(LanderRightHandSide, DoesNotAllocate) {
  if (!testing_alloc::kCountsMalloc) GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
  ASSERT_GE(testing_alloc::AllocationsOfAnEigenBuffer(), 1);  // the counter works, for Eigen's buffers too
  test::PaperLander setup = test::MakePaperLander('A');
  const StateLayout L(setup.model);
  setup.options.duration_s = 0.4;
  // At rest on the soil: every pad submerged.
  const Eigen::VectorXd y = SimulateLander(setup).final_state;
  LanderData data;
  data.evaluation.u_dot = Eigen::VectorXd::Zero(L.nu);
  const LanderEvaluation& e = data.evaluation;
  Eigen::VectorXd ydot(L.size);
  LanderModes modes;
  for (int i = 0; i < kNumLegs; ++i) modes.pad[i] = PadMode::kHeld;
  const LanderSystem system{setup.model, L, setup.terrain, modes};
  Derivative(system, data, y, ydot);
  EXPECT_EQ(testing_alloc::CountAllocations([&] {
              for (int k = 0; k < 3; ++k) Derivative(system, data, y, ydot);
            }),
            0);
  EXPECT_TRUE(e.constrained);
  // The held pads carry the lander at rest: their reactions balance its weight.
  double lift = 0.0;
  for (int i = 0; i < kNumLegs; ++i) lift += e.soil[i].force_W.z();
  EXPECT_NEAR(lift, setup.model.TotalMass() * setup.model.gravity_m_s2, 1e-6 * lift);
  EXPECT_LT(e.u_dot.norm(), 1e-6);
  // The same evaluation as with scratch of its own.
  LanderEvaluation fresh;
  EvaluateLander(setup.model, L, setup.terrain, modes, y, &fresh);
  EXPECT_EQ(fresh.u_dot, e.u_dot);
  for (int i = 0; i < kNumLegs; ++i) EXPECT_EQ(fresh.soil[i].force_W, e.soil[i].force_W);
}

}  // namespace
}  // namespace touchdown::lander
