// The lander's right-hand side allocates nothing while pads are held (house style: no allocation
// in a right-hand side): EvaluateLander with its LanderData, then StateDerivative, through the
// constraint solve of four held pads. malloc itself is counted, so Eigen's heap buffers count as
// well as operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>

#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_simulation.h"
#include "tests/lander/multibody/paper_lander.h"

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

// AddressSanitizer replaces malloc itself; the count is then left to the plain build.
#if !defined(__SANITIZE_ADDRESS__)
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) {
  if (counting.load()) ++allocations;
  return __libc_malloc(size);
}
#define TOUCHDOWN_COUNTS_MALLOC 1
#endif

namespace touchdown::lander {
namespace {

TEST(LanderRightHandSide, DoesNotAllocate) {
#if !defined(TOUCHDOWN_COUNTS_MALLOC)
  GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
#else
  {  // the counter works, for Eigen's buffers too
    allocations = 0;
    counting = true;
    Eigen::VectorXd probe(64);
    counting = false;
    probe.setZero();
    ASSERT_GE(allocations.load(), 1);
  }
  const test::PaperLander setup = test::MakePaperLander('A');
  const StateLayout L(setup.model);
  LanderRunOptions options;
  options.duration_s = 0.4;
  // At rest on the soil: every pad submerged.
  const Eigen::VectorXd y = SimulateLander(setup.model, setup.terrain, setup.initial, options).final_state;
  LanderData data;
  LanderEvaluation e;
  e.u_dot = Eigen::VectorXd::Zero(L.nu);
  Eigen::VectorXd ydot(L.size);
  LanderModes modes;
  for (int i = 0; i < kNumLegs; ++i) modes.pad[i] = PadMode::kHeld;
  EvaluateLander(setup.model, L, setup.terrain, modes, y, &e, &data);
  allocations = 0;
  counting = true;
  for (int k = 0; k < 3; ++k) {
    EvaluateLander(setup.model, L, setup.terrain, modes, y, &e, &data);
    StateDerivative(L, y, e, ydot);
  }
  counting = false;
  EXPECT_EQ(allocations.load(), 0);
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
#endif
}

}  // namespace
}  // namespace touchdown::lander
