// The generic CVODE wrapper: accuracy on closed forms, root-finding, option checks, and
// exceptions carried across the C callbacks.
#include "lander/integ/cvode_integrator.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include "tests/malloc_counter.h"

namespace touchdown::integ {
namespace {

TEST(CvodeIntegrator, HarmonicOscillatorMatchesClosedForm) {
  for (bool stiff : {false, true}) {
    IntegratorOptions options;
    options.stiff = stiff;
    CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
      d[0] = y[1];
      d[1] = -4.0 * y[0];
    }, options);
    integ.Reset(0.0, Eigen::Vector2d(1.0, 0.0));
    integ.AdvanceTo(3.0);
    EXPECT_NEAR(integ.state()[0], std::cos(6.0), 1e-8) << "stiff " << stiff;
    EXPECT_NEAR(integ.state()[1], -2.0 * std::sin(6.0), 1e-8);
    EXPECT_GT(integ.summary().steps, 0);
  }
}

TEST(CvodeIntegrator, FindsRootOfFreeFallExactly) {
  // Fall from 1 m: the ground is reached at t = sqrt(2 / g).
  RootSpec roots{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = y[0]; },
                 {-1}};
  CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = y[1];
    d[1] = -9.81;
  }, IntegratorOptions{}, roots);
  integ.Reset(0.0, Eigen::Vector2d(1.0, 0.0));
  const AdvanceResult r = integ.AdvanceTo(10.0);
  ASSERT_EQ(r.status, AdvanceStatus::kFoundRoot);
  EXPECT_EQ(r.roots_found[0], -1);
  EXPECT_NEAR(r.t, std::sqrt(2.0 / 9.81), 1e-9);
  EXPECT_NEAR(integ.time(), r.t, 0.0);
}

TEST(CvodeIntegrator, RootDirectionFilters) {
  // sin(t) rises through 0 at 2 pi, falls at pi; only the rising crossing is asked for.
  RootSpec roots{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = y[0]; },
                 {+1}};
  CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = y[1];
    d[1] = -y[0];
  }, IntegratorOptions{}, roots);
  integ.Reset(0.0, Eigen::Vector2d(0.0, 1.0));
  const AdvanceResult r = integ.AdvanceTo(10.0);
  ASSERT_EQ(r.status, AdvanceStatus::kFoundRoot);
  EXPECT_NEAR(r.t, 2 * M_PI, 1e-7);
}

TEST(CvodeIntegrator, ExceptionInRightHandSideIsRethrownAfterCvodeReturns) {
  CvodeIntegrator integ(1, [](double t, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) {
    if (t > 0.5) throw std::domain_error("model refused");
    d[0] = 1.0;
  }, IntegratorOptions{});
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  EXPECT_THROW(integ.AdvanceTo(1.0), std::domain_error);
}

TEST(CvodeIntegrator, SolverFailureComesBackWithReason) {
  IntegratorOptions options;
  options.max_num_steps = 5;
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = -1000.0 * y[0] + std::sin(1000.0 * y[0]);
  }, options);
  integ.Reset(0.0, Eigen::VectorXd::Ones(1));
  try {
    integ.AdvanceTo(100.0);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("CV_TOO_MUCH_WORK"), std::string::npos) << e.what();
  }
}

TEST(CvodeIntegrator, WallClockLimitFailsTheAdvanceWithItsReason) {
  // A right-hand side that costs 2 ms per evaluation and a 50 ms budget: the advance must stop
  // with an IntegrationFailure naming the limit, well before the 10^4 s it was asked for.
  IntegratorOptions options;
  options.max_wall_time_s = 0.05;
  options.max_num_steps = 100000000;
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    d[0] = std::cos(y[0]);
  }, options);
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  const auto start = std::chrono::steady_clock::now();
  try {
    integ.AdvanceTo(1e4);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("wall-clock limit exceeded"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(CvodeIntegrator, WallClockLimitIsCheckedInRootFunctionsToo) {
  // A cheap right-hand side, a slow root function, and steps capped at 1 ms so that reaching
  // t = 1000 s takes a million root evaluations.
  IntegratorOptions options;
  options.max_wall_time_s = 0.05;
  options.max_num_steps = 100000000;
  options.max_step = 1e-3;
  RootSpec roots;
  roots.count = 1;
  roots.function = [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    g[0] = y[0] + 1.0;  // never crosses
  };
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = 1.0;
  }, options, roots);
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  try {
    integ.AdvanceTo(1e3);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("wall-clock limit exceeded"), std::string::npos) << e.what();
  }
}

// The deterministic work limit. It counts every right-hand side over the
// integrator's life (across Resets, whose CVODE counters restart), so the same model fails at
// the same evaluation on any machine; the failure names the limit and its value.
TEST(CvodeIntegrator, EvaluationLimitFailsAtTheSameEvaluationAcrossResets) {
  IntegratorOptions options;
  EXPECT_EQ(options.max_rhs_evaluations, 0);  // none by default
  options.max_rhs_evaluations = 300;
  options.max_step = 1e-2;
  long calls = 0;
  auto run = [&] {
    calls = 0;
    CvodeIntegrator integ(1, [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
      ++calls;
      d[0] = std::cos(y[0]);
    }, options);
    for (int k = 0;; ++k) {  // restarts every 0.5 s: the budget is not renewed
      integ.Reset(0.5 * k, Eigen::VectorXd::Zero(1));
      integ.AdvanceTo(0.5 * (k + 1));
    }
  };
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      run();
      FAIL() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
      EXPECT_EQ(e.limit(), "max_rhs_evaluations");
      EXPECT_EQ(e.value(), 300.0);
      EXPECT_NE(std::string(e.what()).find("more than 300 right-hand-side evaluations"), std::string::npos) << e.what();
      EXPECT_EQ(calls, 300);  // the 301st evaluation is refused before the model runs
    }
  }
  options.max_rhs_evaluations = -1;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
}

TEST(CvodeIntegrator, NoWallClockLimitByDefault) {
  IntegratorOptions options;
  EXPECT_EQ(options.max_wall_time_s, 0.0);
  options.max_wall_time_s = -1.0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("max_wall_time_s"), std::string::npos);
  options.max_wall_time_s = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(options.IsValid(&why));
}

// A stiff linear system of the lander's size, y' = A y with A = V D V^T (V orthogonal, D from -1 to
// -1e6: a stiffness ratio of a million, and a Newton matrix that needs row pivoting), against its
// closed form V exp(D t) V^T y0, with each of the two dense LU solvers of the Newton matrix.
TEST(CvodeIntegrator, StiffSystemMatchesClosedFormWithEitherDenseSolver) {
  constexpr int n = 44;
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
  Eigen::VectorXd d(n);
  for (int k = 0; k < n; ++k) d[k] = -std::pow(10.0, 6.0 * k / (n - 1));
  const Eigen::MatrixXd A = V * d.asDiagonal() * V.transpose();
  Eigen::VectorXd y0 = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const double t = 0.5;
  const Eigen::VectorXd exact = V * (d * t).array().exp().matrix().asDiagonal() * (V.transpose() * y0);
  for (DenseSolver solver : {DenseSolver::kEigen, DenseSolver::kSundials}) {
    IntegratorOptions options;
    options.stiff = true;
    options.rtol = 1e-9;
    options.atol = 1e-12;
    options.dense_solver = solver;
    CvodeIntegrator integ(n, [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> dy) {
      dy.noalias() = A * y;
    }, options);
    integ.SetJacobian([&](double, auto, auto, Eigen::Ref<Eigen::MatrixXd> J) { J = A; });
    integ.Reset(0.0, y0);
    integ.AdvanceTo(t);
    EXPECT_LT((integ.state() - exact).norm(), 1e-7 * exact.norm()) << static_cast<int>(solver);
    EXPECT_GT(integ.summary().jacobian_evaluations, 0);
  }
  EXPECT_TRUE(IntegratorOptions{}.dense_solver == DenseSolver::kEigen);
}

// House style: once the integrator exists, stepping allocates nothing, the Newton matrix's
// factorisations and solves included (Eigen's LU works in the storage it was given at construction).
TEST(CvodeIntegrator, StiffStepsAllocateNothing) {
  if (!testing_alloc::kCountsMalloc) GTEST_SKIP() << "malloc is not counted under AddressSanitizer";
  ASSERT_GT(testing_alloc::AllocationsOfAnEigenBuffer(), 0);
  constexpr int n = 20;
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
  Eigen::VectorXd d(n);
  for (int k = 0; k < n; ++k) d[k] = -std::pow(10.0, 5.0 * k / (n - 1));
  const Eigen::MatrixXd A = V * d.asDiagonal() * V.transpose();
  IntegratorOptions options;
  options.stiff = true;
  options.rtol = 1e-8;
  options.atol = 1e-12;
  CvodeIntegrator integ(n, [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> dy) {
    dy.noalias() = A * y;
  }, options);
  integ.SetJacobian([&](double, auto, auto, Eigen::Ref<Eigen::MatrixXd> J) { J = A; });
  integ.Reset(0.0, Eigen::VectorXd::Ones(n));
  integ.AdvanceTo(1e-3);
  const long before = integ.summary().jacobian_evaluations;
  EXPECT_EQ(testing_alloc::CountAllocations([&] { integ.AdvanceTo(1.0); }), 0);
  EXPECT_GT(integ.summary().jacobian_evaluations, before);  // factorisations happened while counting
}

// A Newton matrix that cannot be factored (here not finite) fails the setup as recoverable, as
// SUNDIALS' own solver does for a zero pivot: CVODE counts it as a convergence failure, retries with
// smaller steps and gives up, and the advance fails with CVODE's reason.
TEST(CvodeIntegrator, NewtonMatrixThatCannotBeFactoredFailsTheAdvance) {
  IntegratorOptions options;
  options.stiff = true;
  CvodeIntegrator integ(3, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> dy) {
    dy = -y;
  }, options);
  integ.SetJacobian([](double, auto, auto, Eigen::Ref<Eigen::MatrixXd> J) {
    J.setConstant(std::numeric_limits<double>::quiet_NaN());
  });
  integ.Reset(0.0, Eigen::Vector3d(1.0, 2.0, 3.0));
  try {
    integ.AdvanceTo(1.0);
    FAIL() << "the advance should fail";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("CV_CONV_FAILURE"), std::string::npos) << e.what();
  }
}

TEST(CvodeIntegrator, OptionsAreValidated) {
  std::string why;
  IntegratorOptions bad;
  bad.rtol = 0.0;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_NE(why.find("rtol"), std::string::npos);
  bad = {};
  bad.atol = -1;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_TRUE(IntegratorOptions{}.IsValid(&why));
  EXPECT_THROW(CvodeIntegrator(1, [](double, auto, auto) {}, bad), std::invalid_argument);
  // Newton's convergence coefficient: 0 keeps CVODE's 0.1; a value of 1 or more, or negative, or
  // not a number, is refused.
  for (double c : {-0.01, 1.0, std::nan("")}) {
    bad = {};
    bad.nonlinear_convergence_coefficient = c;
    EXPECT_FALSE(bad.IsValid(&why)) << c;
    EXPECT_NE(why.find("nonlinear_convergence_coefficient"), std::string::npos);
  }
  IntegratorOptions tight;
  tight.nonlinear_convergence_coefficient = 0.03;
  EXPECT_TRUE(tight.IsValid(&why));
}

}  // namespace
}  // namespace touchdown::integ
